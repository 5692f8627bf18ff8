"""The ego of a third-person text (a news item, a court report, an incident log): the vehicle the
text follows is the ego, never also listed as another road user, and its speed is the ego's."""

from __future__ import annotations

import pytest
from reading_of import ego_kph as _ego_kph
from reading_of import kinds as _kinds

from vei_scenario.language.reader import read


# A news report that opens on a driver and goes on with "his"/"her" vehicle and "he"/"she": that
# driver's vehicle is the ego, and a speed said of the driver's pronoun is the ego's.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("A bus driver has been praised after a girl on a bike rode out of a side road into the path of "
         "his bus. He was going at 15 mph and stopped in time.", ["bicycle"], 24.1),
        ("A lorry driver has been banned after a cyclist was hit by his lorry at a junction. The court "
         "heard he was travelling at 30 mph.", ["bicycle"], 48.3),
        ("A delivery driver escaped injury when a pedestrian walked out in front of her van. She was "
         "doing about 25 mph and braked hard.", ["pedestrian"], 40.2),
        ("A minicab driver was cleared after a girl on an e-scooter swerved across the front of his "
         "taxi. He had been driving at 20 mph.", ["e-scooter"], 32.2),
    ],
)  # fmt: skip
def test_a_driver_a_news_report_follows_through_his_or_her_vehicle_is_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# "him"/"her" placed by another road user is the driver the report opens on: the taxi, not the van.
def test_a_driver_another_road_user_is_placed_by_is_the_ego():
    assert _kinds("A taxi driver was hurt when a van pulled out in front of him on the ring road.") == ["van"]
    assert _kinds("A coach driver was shaken after a lorry came across into her lane near Leeds.") == ["truck"]


# Near misses: a watcher who is no party; a speed said of someone of the other gender; a driver the
# report does not open on.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("A taxi driver watched as a van doing 40 mph hit a cyclist who came out from the left.",
         ["bicycle"], 64.4),
        ("A bus driver stopped in time when a woman stepped out in front of his bus. She was running at "
         "9 km/h.", ["pedestrian"], None),
        ("A cyclist was hurt when a van driver opened his door into her path. She was riding at 12 mph.",
         ["van"], None),
    ],
)  # fmt: skip
def test_a_driver_the_report_does_not_follow_is_not_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# A log that names one vehicle by its label and then a bare "Driver" speaks of that vehicle's driver:
# the labelled vehicle is the ego and the driver's speed is the ego's.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("Unit 7. Driver was doing 40 mph on the bypass when a cyclist pulled out of a lay-by on the "
         "left. Driver braked hard.", ["bicycle"], 64.4),
        ("Bus 31 on Mill Road. Driver was at 20 mph when a pedestrian stepped off the kerb on the right. "
         "Driver stopped short.", ["pedestrian"], 32.2),
        ("Van 5, 07:40, London Road. Driver was turning left at 10 mph when an e-scooter came up on the "
         "inside.", ["e-scooter"], 16.1),
    ],
)  # fmt: skip
def test_a_bare_driver_after_one_labelled_vehicle_is_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# Near misses: two labels (whose driver is open); a driver named with another vehicle.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("Car 1 was doing 30 mph when Car 2 pulled out of a side road on the left. Driver of car 2 was "
         "hurt.", ["car"], 48.3),
        ("Van 5 stopped at the lights. A bus driver behind sounded his horn and pulled out round it at "
         "20 mph.", ["truck"], None),
    ],
)  # fmt: skip
def test_a_driver_of_another_vehicle_is_not_the_labelled_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# A spaced dash after a time or a number and before a word breaks the sentence as a comma does: the
# road user after it is the subject of what follows ("22:16 - lead vehicle sudden stop"); between
# two numbers it is a range.
@pytest.mark.parametrize(
    "text, kind, behaviour",
    [
        ("Unit 3 AEB fired 14:05 - lead vehicle (van) sudden stop, unit speed 40 mph.", "van", "sudden_stop"),
        ("Tram 2 logged 11:20 - lead vehicle (bus) sudden stop, tram speed 30 km/h.", "truck", "sudden_stop"),
        ("Event 41 at 8 - lead vehicle (car) sudden stop, ego speed 45 km/h.", "car", "sudden_stop"),
    ],
)  # fmt: skip
def test_a_spaced_dash_after_a_number_breaks_the_sentence(text, kind, behaviour):
    actors = read(text).actors
    assert [a.kind for a in actors] == [kind]
    assert behaviour in [b[0] for b in actors[0].behaviours]


def test_a_dash_between_two_numbers_is_still_a_range():
    assert _ego_kph("The ego drives at 30 - 40 km/h and a cyclist ahead brakes hard.") == 35.0


# A person named by a noun of a person who is the subject of driving (in their own clause or their
# relative clause) is at a wheel: the ego, no walker, with the speed they drove at.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("A Leeds woman who struck a cyclist while driving at 45mph has been fined.", ["bicycle"], 72.4),
        ("A pensioner was driving his Volvo at 30 mph when a jogger ran into the road from the right.",
         ["pedestrian"], 48.3),
        ("A Bristol man who knocked down a girl on a zebra crossing while driving at 35 mph was jailed.",
         ["pedestrian"], 56.3),
    ],
)  # fmt: skip
def test_a_person_who_drives_is_the_ego_not_a_walker(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# Near misses: the person is no subject of driving, or walks.
@pytest.mark.parametrize(
    "text, kinds",
    [
        ("A man walking his dog was struck by a car doing 30 mph.", ["pedestrian"]),
        ("A woman who was crossing the road was hit by a van driving at 40 mph.", ["pedestrian"]),
    ],
)  # fmt: skip
def test_a_person_who_does_not_drive_stays_a_road_user(text, kinds):
    assert _kinds(text) == kinds


# A report whose only first-person word is an operator's "our" before its scooters or bikes ("one of
# our scooters") is told in the third person: the party driving is the ego, not one more vehicle.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("Complainant was driving a minibus at 20 mph when one of our scooters came off the kerb on the "
         "left.", ["e-scooter"], 32.2),
        ("Complainant was driving a lorry at 15 mph when one of our bikes came out of a side road on the "
         "left.", ["bicycle"], 24.1),
        ("Claimant was driving a taxi at 20 mph when one of our e-scooters pulled out of a side street on "
         "the right.", ["e-scooter"], 32.2),
    ],
)  # fmt: skip
def test_an_operators_own_scooters_leave_the_report_in_the_third_person(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# Near misses: "our van", "our driver" put the writer's own vehicle in the scene.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("Our van was doing 20 mph when a cyclist pulled out of a side road on the left.", ["bicycle"], 32.2),
        ("Our driver says a cyclist pulled out in front of the pool car at 20 mph.", ["bicycle"], 32.2),
    ],
)  # fmt: skip
def test_the_writers_own_vehicle_keeps_the_writer_in_the_scene(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph
