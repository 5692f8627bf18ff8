"""Safety engineers' shorthand and the English of writers of other languages: "HV" is the host vehicle
(the ego) unless said as a heavy vehicle ("a HV", "the HV in front of me"), a version number is no
party's code, an ego said to stand keeps standing when a vehicle near it has a speed, a number of
minutes to an hour is no speed, dates are no clock, a distance after "lane" is no lane number, and the
words for e-scooters, buses and bicycles of Latin America and Japan name them.

Every wording here is written for these tests (none is from a corpus). Each rule has wordings that must
read and near misses that look alike but must not."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read

MPH = 0.44704
KPH = 1 / 3.6


def _kinds(text: str) -> list[str]:
    return [a.kind for a in read(text).actors]


# --- "HV" names the host vehicle, the ego -------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("HE-12: HV 65 km/h on a rural road, a tractor 30 m ahead brakes hard.", 65),
        ("Field event: HV ~35 km/h, a cyclist rides out of a driveway on the right 15 m ahead.", 35),
        ("OS-7 | motorway | HV 120 km/h | lorry from the right lane cuts in 20 m ahead at 85 km/h", 120),
    ],
)
def test_hv_is_the_ego(text, kph):
    reading = read(text)
    assert reading.ego_speed_mps == pytest.approx(kph * KPH)
    assert len(reading.actors) == 1


@pytest.mark.parametrize(
    "text",
    [
        "A HV travelling south crossed the centre line and hit my car.",
        "The HV in front of me braked suddenly and I ran into it at 30 km/h.",
        "An HV overtook me on the highway and cut in close.",
    ],
)
def test_a_heavy_vehicle_said_as_hv_is_a_lorry(text):
    assert _kinds(text) == ["truck"]


def test_a_version_number_is_no_other_party():
    text = (
        "HV creeping forward in a queue at ~8 km/h. A cyclist rode across in front from the left pavement, "
        "~4 m ahead. FCW stayed silent (below its 10 km/h threshold - to check against spec v2.4 which says 5 km/h)."
    )
    assert _kinds(text) == ["bicycle"]


def test_a_partys_code_stays_a_party():
    text = "V1 was travelling at 30 mph when V2, a white van, pulled out of a side road on the left."
    assert _kinds(text) == ["van"]


# --- an ego said to stand stands ----------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "I was stopped at the lights when a lorry coming up behind me at 20 mph ran into the back of my car.",
        "We were stationary in the queue when a taxi hit the back of our car at 10 mph.",
        "My van was completely stopped when a cyclist riding the wrong way at 15 km/h clipped my mirror.",
        "I was fully stopped at the give way line and a scooter behind me at about 12 km/h hit my bumper.",
    ],
)
def test_an_ego_said_to_stand_keeps_standing(text):
    assert read(text).ego_speed_mps == 0.0


@pytest.mark.parametrize(
    "text, kph",
    [
        ("A car 12 m ahead of the ego at 50 km/h brakes hard.", 50),
        ("I stopped completely when a cyclist came past me at 20 km/h. I had been doing 40 km/h.", 40),
    ],
)
def test_an_ego_that_goes_keeps_its_speed(text, kph):
    assert read(text).ego_speed_mps == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text, mph",
    [
        ("I had stopped at the junction, then pulled out and a van tailgated me at 60 mph.", 60),
        (
            "I was stopped at the lights. When they turned green I pulled off and a car next to me at 30 mph "
            "swerved into my side.",
            30,
        ),
        ("I had not completely stopped when the car behind me at 20 mph hit me.", 20),
        ("I totally stopped concentrating for a second and a van beside me at 50 mph drifted into my lane.", 50),
        ("Debris hit the car beside me at 50 mph and it swerved into my lane.", 50),
    ],
)
def test_an_ego_that_stopped_once_or_was_not_said_to_stand_shares_the_speed(text, mph):
    assert read(text).ego_speed_mps == pytest.approx(mph * MPH)


def test_a_stop_of_doing_something_is_no_standstill():
    assert read("I completely stopped paying attention and rear-ended the car in front of me.").ego_speed_mps != 0.0


def test_the_striker_keeps_the_speed_it_strikes_at():
    reading = read("I was stationary at the lights when a van hit the back of my car at 15 mph.")
    assert reading.ego_speed_mps == 0.0
    assert [a.relation for a in reading.actors] == ["behind"]


# --- minutes to an hour are a clock, dates are none -----------------------------------------------------------
@pytest.mark.parametrize(
    "text, clock",
    [
        ("At twenty to seven in the evening a cyclist pulled out in front of me.", "18:40"),
        ("At ten past eight a van came out of a side road on my left.", "08:10"),
        ("I left at 25 to 9 and a bus pulled out in front of me.", "08:35"),
    ],
)
def test_minutes_to_an_hour_are_a_clock_and_no_speed(text, clock):
    reading = read(text)
    assert reading.time == clock
    assert reading.ego_speed_mps is None


@pytest.mark.parametrize(
    "text, clock",
    [
        ("At quarter past 8 2 cyclists rode out in front of me.", "08:15"),
        ("On the A406 ten to six a van pulled out in front of me.", "17:50"),
        ("Sat 12/05/24 quarter past 5 a van pulled out in front of me.", "17:15"),
    ],
)
def test_a_clock_beside_other_numbers_stays(text, clock):
    assert read(text).time == clock


def test_a_count_after_an_hour_word_keeps_the_speed():
    text = "I drove at 20 past two parked vans when a kid ran out between them."
    assert read(text).ego_speed_mps == pytest.approx(20 * KPH)


def test_a_range_of_speeds_stays_a_speed():
    assert read("I was doing 10 to 12 mph when a cyclist pulled out in front of me.").ego_speed_mps is not None


@pytest.mark.parametrize(
    "text",
    [
        "I hired the car from 4/10 to 4/15. On 4/12 a cyclist rode out in front of me.",
        "Booked 3/20 to 3/25 at the depot; on the second day a van pulled out of a side road on my right.",
    ],
)
def test_dates_are_no_clock(text):
    assert read(text).time is None


# --- a distance after "lane" is no lane number -------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A van cut into the ego lane 6 m ahead.",
        "A lorry pulls into my lane 5 metres in front.",
        "A car moved into our lane 4 m ahead of us.",
    ],
)
def test_a_distance_after_lane_is_no_lane_number(text):
    assert read(text).lanes != int(text.split("lane ")[1].split()[0])


def test_a_numbered_lane_stays():
    assert read("I was in lane 3 when a van pulled in front of me.").lanes == 3


# --- other languages' words for the road users -------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("I was behind a patineta at 25 km/h and he braked suddenly for a hole.", "e-scooter"),
        ("A boy on a monopatin eléctrico crossed the avenue in front of me.", "e-scooter"),
        ("The colectivo in front of me stopped suddenly to pick up a passenger.", "truck"),
        ("A pesero braked hard in front of me at the corner.", "truck"),
        ("An old man on a mamachari came out of a side street on my left.", "bicycle"),
    ],
)
def test_other_languages_words_name_road_users(text, kind):
    assert _kinds(text) == [kind]


# --- the runner's own red ---------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "I had green at 30 km/h. A Fiat came from the left passing his red light fast and hit my door.",
        "Going straight on green, a cyclist from the right ignored their red and crossed in front of me.",
        "On green at the crossroads a scooter from my left went through her red and I braked hard.",
        "Ego at 40 km/h. A car from the left ignores the red signal and shoots across in front of us.",
    ],
)
def test_a_runners_own_red_is_the_red_light(text):
    (actor,) = read(text).actors
    assert [b[0] for b in actor.behaviours] == ["run_red_light"]


def test_a_red_car_stays_a_car():
    (actor,) = read("A woman in her red car pulled out of a side road on my left.").actors
    assert actor.kind == "car" and [b[0] for b in actor.behaviours] == ["turn_into"]
