"""One person on one vehicle is one road user: the rider.

A person said to be on or riding a vehicle is its rider, also where a hedge or a part stands between
("on one of those hire bikes", "on what looked like a rented e-scooter", "riding some sort of electric
scooter"); a person said back with "the" (and a word or two that only describe them: "the young man",
"the poor kid") after a rider was named, with no one on foot named before, is that rider said again.
A person brought in new ("a young man"), placed elsewhere ("the man on the kerb") or told apart ("the
other lad") is someone else.
"""

from __future__ import annotations

import pytest

from tests.reading_of import kinds

#: A person on a vehicle said past a hedge or a part: one road user, the vehicle, as writers in many
#: places and registers say it.
ON_IT_PAST_A_HEDGE = [
    ("At 30 km/h a man on what looked like a rented e-scooter crossed in front of me from the right.", "e-scooter"),
    ("A woman riding what appeared to be an electric bicycle came off the pavement in front of me.", "bicycle"),
    ("doing 25 mph and a teenager on some sort of electric scooter cut across my lane", "e-scooter"),
    ("A boy on one of the shared scooters came off the kerb in front of me while I was doing 20 mph.", "e-scooter"),
    ("Subject vehicle at 40 km/h. Male on one of them hire bikes crossed from the nearside kerb.", "bicycle"),
    ("abeg this guy on one of those rental bikes just crossed in front of me at the junction", "bicycle"),
    ("Young chap on what seemed to be a borrowed bicycle wobbled out in front of me, I was at 20 mph.", "bicycle"),
]


@pytest.mark.parametrize("text,kind", ON_IT_PAST_A_HEDGE)
def test_a_person_on_a_vehicle_past_a_hedge_is_its_rider(text: str, kind: str) -> None:
    assert kinds(text) == [kind]


#: "One" that stands for the ridden vehicles named before, after "on" or "riding": the person rides one.
ON_ONE = [
    ("E-scooters are everywhere now. Last week a teenager on one came flying out of an alley.", "e-scooter"),
    ("Them Lime bikes are a menace. A kid on one shot out in front of me from the left.", "bicycle"),
    ("Cyclists use this road a lot. A man on one of them swerved into my lane.", "bicycle"),
    ("Bikes everywhere on this road. This morning a woman on one of those pulled out in front of me.", "bicycle"),
    ("Hire bikes are all over town. Yesterday a boy on one swerved into my lane.", "bicycle"),
]


@pytest.mark.parametrize("text,kind", ON_ONE)
def test_a_person_on_one_of_the_vehicles_named_rides_one(text: str, kind: str) -> None:
    assert kinds(text) == [kind]


def test_riding_one_said_of_no_one_is_no_road_user() -> None:
    """Riding in general ("it's mad riding one of those in the snow") names no one on it."""
    text = "I followed an e-scooter for a while at 10 mph. It's mad riding one of those in the snow."
    assert kinds(text) == ["e-scooter"]


def test_one_that_counts_a_noun_is_no_vehicle() -> None:
    """ "On one side", "on one of the crossings": a count of a noun, not the vehicle said again."""
    assert "pedestrian" in kinds("A cyclist came past and a pedestrian on one of the crossings stepped out.")
    assert "pedestrian" in kinds("A cyclist was riding on one side of the road when a pedestrian stepped out.")


#: The rider said back by who they are, with a word or two that describe them, after the vehicle or
#: rider was named and no one on foot was.
SAID_BACK = [
    ("A cyclist rode across in front of me. The young man then carried on without looking.", "bicycle"),
    ("An e-scooter rider came off the kerb in front of me. The student kept going.", "e-scooter"),
    ("An e-scooter shot out from the right in front of me and the poor kid went over my bonnet.", "e-scooter"),
    ("a bike came out of the side street on my left, the little boy didn't even look", "bicycle"),
    ("Pedal cyclist entered the carriageway from the offside. The male continued on.", "bicycle"),
    ("A cyclist swerved across my lane at 30 km/h. The victim was taken to hospital.", "bicycle"),
]


@pytest.mark.parametrize("text,kind", SAID_BACK)
def test_a_person_said_back_after_a_rider_is_that_rider(text: str, kind: str) -> None:
    assert kinds(text) == [kind]


#: Near misses: a person and a rider who are two road users.
TWO = [
    "A cyclist passed me. A young man then stepped out in front of me.",  # (brought in new)
    "A cyclist passed me on the right. The young man on the kerb then stepped out in front of me.",  # (placed)
    "A pedestrian and a cyclist crossed in front of me.",
    "A man on the pavement next to one of those scooters stepped out in front of me. A cyclist passed me.",
    "A woman on the phone to one of the cyclists stepped out in front of me as a cyclist came past.",
    "A boy on a bike came past me on the right, then the other boy stepped out in front of me.",  # (told apart)
]


@pytest.mark.parametrize("text", TWO)
def test_a_walker_beside_a_rider_stays_a_walker(text: str) -> None:
    assert "pedestrian" in kinds(text)


def test_a_walker_named_before_keeps_the_person_said_back() -> None:
    """With someone on foot named before, "the young man" may be either: nothing is folded."""
    text = "A pedestrian crossed in front of me, then a cyclist came past. The young man waved."
    assert sorted(kinds(text)) == ["bicycle", "pedestrian"]


#: One road user named again by its make or operator between commas, after a phrase with words of its
#: own ("a rental scooter, a Bird,", "a silver car, a Toyota,"): one road user, as after a bare noun.
NAMED_AGAIN_BY_ITS_MAKE = [
    ("I was doing 40 when a man on a rental scooter, a Bird, came towards me in my lane.", ["e-scooter"]),
    ("I was doing 40 when a silver car, a Toyota, pulled out in front of me.", ["car"]),
    ("I was doing 40 when a big white van, a Transit, pulled out in front of me.", ["van"]),
    ("I was doing 40 when a car, a Toyota, pulled out in front of me.", ["car"]),
]


@pytest.mark.parametrize("text,expected", NAMED_AGAIN_BY_ITS_MAKE)
def test_a_make_between_commas_names_the_one_before(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


def test_a_list_of_two_stays_two() -> None:
    """A list ("a silver car, a van and a bus") names each one of its own."""
    assert len(kinds("I was doing 40 when a silver car, a white van and a bus pulled out in front of me.")) >= 2
