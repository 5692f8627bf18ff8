"""What is not a road user: standing vehicles that only block or hide, and vehicles named only as the
place someone comes out from. The format lists the road users that act on the road; a vehicle that
stands and does nothing is scenery (the scenario may still hold it, parked, as the occluder it is).
Each construction is pinned by wordings of our own (none of them from a corpus), read through the
whole reader, with near misses that look alike and must read the other way."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read

#: What a standing vehicle may be given and still be scenery: it stays where it stands.
STANDING = {"stop", "keep_going", "keep_lane"}


def acting(text: str) -> list[str]:
    """The kinds of the road users ``text`` is read with that act: not standing still doing nothing."""
    out = []
    for a in read(text).actors:
        names = {b[0] for b in a.behaviours}
        if not (a.speed_mps == 0.0 and names <= STANDING):
            out.append(a.kind)
    return out


# --- a state word before a vehicle's noun says it stands, whatever modifiers come between -----------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "The ego drives at 50 km/h behind a lead car; the lead car swerves left and reveals a stationary "
            "foam target car in the ego lane.",
            ["car"],
        ),
        ("I was doing 30 mph behind a hatchback when it pulled out round a parked white van in my lane.", ["car"]),
        (
            "Driving at 40 km/h behind a taxi, the taxi swerved into the next lane and there was a stopped "
            "grey lorry in our lane.",
            ["car"],
        ),
    ],
    ids=["two-modifiers", "colour", "existential"],
)
def test_a_state_word_before_modifiers_and_a_vehicle_noun_makes_it_stand(text, expected):
    assert acting(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A parked white van pulled out in front of me while I was doing 30 km/h.", ["van"]),
        ("A stationary blue bus pulled away from the stop right in front of us while we drove at 40 km/h.", ["truck"]),
    ],
    ids=["parked-pulls-out", "stationary-pulls-away"],
)
def test_a_standing_vehicle_that_then_moves_is_a_road_user(text, expected):
    assert acting(text) == expected


# --- vehicles counted as the place someone comes out from between are scenery ------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was driving at 30 km/h when a girl stepped out from between two vans on the right.", ["pedestrian"]),
        ("At 25 mph a kid on a bike shot out between three lorries on my left.", ["bicycle"]),
        (
            "Doing 20 mph along a road with parked cars both sides, a jogger ran out from between two of the "
            "cars on the right.",
            ["pedestrian"],
        ),
    ],
    ids=["two-vans", "three-lorries", "two-of-the-cars"],
)
def test_counted_vehicles_someone_comes_out_from_between_are_scenery(text, expected):
    assert acting(text) == expected


def test_vehicles_that_come_out_from_between_something_are_road_users():
    text = "Two vans pulled out from between the houses right in front of me while I was doing 30 km/h."
    assert acting(text) == ["van", "van"]


# --- a standing vehicle named before a comma does not share the verb of the one named after it -------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("Doing 20 mph along a road with parked cars, a jogger ran out on the right.", ["pedestrian"]),
        ("At 30 km/h past a row of stationary vans, a cyclist darted out from the left.", ["bicycle"]),
        ("Doing 20 mph along a road with parked cars on both sides, a child ran out on the left.", ["pedestrian"]),
    ],
    ids=["parked-cars-comma", "stationary-vans-comma", "both-sides"],
)
def test_a_standing_vehicle_before_a_comma_does_not_share_the_next_verb(text, expected):
    assert acting(text) == expected


def test_two_road_users_said_before_one_verb_both_do_it():
    text = "While I was doing 30 km/h, a cyclist, a jogger and a dog all crossed from the left in front of me."
    assert sorted(acting(text)) == ["bicycle", "pedestrian", "pedestrian"]


# --- a singular vehicle noun before a plural noun modifies it: no road user ----------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("The estate roads were quiet at 30 km/h when a boy ran out from the right in front of me.", ["pedestrian"]),
        (
            "Two car crashes here this year already. At 40 mph a lorry pulled out of a side road on the left "
            "right in front of me.",
            ["truck"],
        ),
        (
            "Five van break-ins on this street lately; at 20 mph a jogger ran out from the left in front of me.",
            ["pedestrian"],
        ),
    ],
    ids=["estate-roads", "counted-agrees", "unknown-plural-counted"],
)
def test_a_vehicle_noun_modifying_a_plural_noun_is_no_road_user(text, expected):
    assert acting(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("At 30 km/h a scooter wobbles out from the left kerb in front of me.", ["e-scooter"]),
        ("Two scooter riders came off the pavement on my left in front of me at 20 mph.", ["e-scooter", "e-scooter"]),
        ("At 30 mph the car ahead brakes hard in front of me.", ["car"]),
    ],
    ids=["verb-after-singular", "riders-are-road-users", "known-verb"],
)
def test_a_vehicle_noun_before_its_verb_stays_a_road_user(text, expected):
    assert acting(text) == expected


def test_a_vehicle_noun_before_a_measure_stays_a_measure():
    text = "Doing about 10 mph, I stayed four car lengths behind a cyclist on the high street."
    assert [a.kind for a in read(text).actors] == ["bicycle"]


def test_a_figure_before_a_vehicle_noun_is_no_count_of_it():
    text = "08:15 ego at 30 km/h on the high street\n08:16 cyclist crosses from the right in front of the ego"
    assert acting(text) == ["bicycle"]


# --- a word right before an auxiliary is its subject, a noun: people of the aftermath do nothing --------
@pytest.mark.parametrize(
    "text",
    [
        "A car came the wrong way towards me in my lane at 50 mph. Police have arrested a 42-year-old man.",
        "A van cut in from the left in front of me at 40 mph. Police are questioning a local man.",
        "A lorry pulled out of a side road on my right at 30 mph. Police were called and spoke to a woman.",
    ],
    ids=["have", "are", "were"],
)
def test_a_noun_before_an_auxiliary_is_no_verb_of_the_person_after_it(text):
    assert len(acting(text)) == 1


def test_an_unknown_verb_before_no_auxiliary_is_still_a_verb():
    assert acting("At 40 mph a deer bounds across the road in front of me from the left.") == ["pedestrian"]


# --- a participle of stopping after what "there is" is its state: it stands ----------------------------
@pytest.mark.parametrize(
    "text",
    [
        "At 50 mph the van in front swerves out at the last second and there's a car stopped dead in our lane.",
        "Doing 70 km/h behind a bus, the bus swerved left and there was a lorry stopped suddenly in our lane.",
        "At 40 mph the taxi in front swerved out and there was a van stopped dead in lane 1 with its hazards on.",
    ],
    ids=["stopped-dead", "stopped-suddenly", "hazards"],
)
def test_a_stop_said_as_a_participle_of_what_is_there_is_standing(text):
    assert len(acting(text)) == 1


@pytest.mark.parametrize(
    "text",
    [
        "At 50 mph the van in front swerves out and a car stopped dead in our lane right in front of me.",
        "At 50 mph there was a car ahead that stopped dead in our lane right in front of me.",
    ],
    ids=["finite", "relative-clause"],
)
def test_a_finite_stop_is_the_stop_it_says(text):
    reading = read(text)
    assert any(b[0] == "sudden_stop" for a in reading.actors for b in a.behaviours)
