"""A road user named by what they ride: South Asian English's "bike wala", and a shared e-scooter's
operator name typed in lower case after what someone is on ("a lad on a lime")."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    "text",
    [
        "One bike wala came from the wrong side straight towards me on the flyover.",
        "A bikewala was coming opposite direction in my lane, I went to the left side.",
        "Sir, one bike-wallah cut in front of me from the left near the signal.",
        "Some scooty wali came wrong side on the service road, straight at my cab.",
        "one motorcycle wala overtook me from left side and cut in front.",
    ],
)
def test_a_bike_wala_is_a_motorcyclist(text: str) -> None:
    """ "bike" in that English is a motorbike: its rider is typed as a motor two-wheeler, a car."""
    assert kinds(text) == ["car"]


@pytest.mark.parametrize(
    "text, kind",
    [
        ("One cycle wala, no light, was going on the left edge of the road in front of me.", "bicycle"),
        ("A cyclewala suddenly turned right across my lane.", "bicycle"),
        ("One auto wala suddenly cut in front of me from the left.", "car"),
        ("the autowala cut in front of me from the left.", "car"),
        ("A truck-wala came on the wrong side towards me.", "truck"),
        ("One tempo wala reversed out of the lane into my path.", "van"),
    ],
)
def test_a_wala_is_the_road_user_of_their_vehicle(text: str, kind: str) -> None:
    """The agent suffix makes the vehicle's word its rider or driver, typed by the vehicle."""
    assert kinds(text) == [kind]


def test_a_wala_of_no_vehicle_is_no_vehicle() -> None:
    """A trade named with the suffix ("the chai wallah") is a person, never a vehicle."""
    assert "car" not in kinds("The chai wallah was standing at the corner and a cyclist pulled out in front of me.")


@pytest.mark.parametrize(
    "text",
    [
        "two guys doubled up on one lime came out of the alley straight into my lane",
        "a lad on a lime shot out of the side street in front of me",
        "some kid riding a bird came off the pavement in front of me",
        "a girl on a bird, no helmet, swerved into my lane",
        "this guy on a voi zoomed across in front of me at the lights",
    ],
)
def test_what_someone_is_on_in_lower_case_is_a_shared_scooter(text: str) -> None:
    """An operator's name typed in lower case names the e-scooter where a person is on it."""
    assert kinds(text) == ["e-scooter"]


@pytest.mark.parametrize(
    "text, kind",
    [
        ("a kid on a lime green bike came out of the alley in front of me", "bicycle"),
        ("a pigeon sat on a bird table while a man stepped out in front of me", "pedestrian"),
        ("there was a bird on a lime tree and a cyclist pulled out in front of me", "bicycle"),
    ],
)
def test_a_lower_case_operator_word_that_goes_on_a_noun_stays_a_word(text: str, kind: str) -> None:
    """ "lime green", "a bird table", "a lime tree": the word describes the next noun, no scooter."""
    assert kinds(text) == [kind]


@pytest.mark.parametrize(
    "text, kind",
    [
        ("Ego goes straight at 40 mph.\nNPC car: oncoming, turns left across ego path late.", "car"),
        ("Bot car: oncoming, turns left across the ego's path.", "car"),
        ("Sim car: oncoming, turns right across the ego's path at the junction.", "car"),
        ("Ego at 50 km/h.\nNPC truck: oncoming, turns left across ego path.", "truck"),
        ("Ego at 30 km/h.\nSim cyclist: oncoming, turns right across ego path.", "bicycle"),
    ],
)
def test_a_field_named_by_a_road_user_with_a_word_before_it(text: str, kind: str) -> None:
    """ "NPC car: oncoming, turns left": a line's field named by a road user's noun with one word before
    it is that road user, doing what the field says."""
    assert kinds(text) == [kind]


def test_a_field_named_with_an_article_is_no_such_field() -> None:
    """ "The car: it turned left": an article before the noun is a sentence's, read as it is."""
    assert kinds("The car: it turned left across my path at the junction.") == ["car"]


def test_an_operator_word_one_is_otherwise_on_stays_a_word() -> None:
    """ "went on a spin, then a cyclist ...": "spin", "beam", "bolt" and "tier" are things one is on."""
    assert kinds("We went on a spin, and a cyclist pulled out in front of me.") == ["bicycle"]
