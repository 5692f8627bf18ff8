"""Where each road user starts relative to the ego: the writer's side of the road said outright, the
kerb a road user is at when no side is said, and what a side said of a road user's goal (not its
start) leaves open."""

import re

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.sides import drives_on_left


def relation(text: str) -> str | None:
    return read(text).actors[0].relation


def _side_started(text: str) -> str | None:
    a = read(text).actors[0]
    if a.relation in ("left", "right", "roadside_left", "roadside_right"):
        return a.relation.removeprefix("roadside_")
    if a.lateral_m:
        return "left" if a.lateral_m > 0 else "right"
    return None


def _tokens(text: str) -> list[str]:
    return re.findall(r"[a-z0-9/]+|[^\sa-z0-9]", text.lower())


@pytest.mark.parametrize(
    "text",
    [
        "We're in Dublin, 50 km/h, a courier on a bike rolls along on our inside.",
        "Setting: New Zealand, rural road at 80 km/h; a ute in the nearside lane drifts across.",
        "Sim for the Australian market (we drive on the left), ego 60 km/h.",
        "Left-hand traffic please. Ego at 40 km/h on a two-lane road.",
        "Based in Mumbai: ego at 30 km/h and an auto-rickshaw in the inside lane.",
        "Japan, city street, 30 km/h, cyclist on the nearside.",
    ],
)
def test_a_place_or_convention_of_left_hand_traffic_said_outright(text):
    """Metric speeds alone keep Euro NCAP's right-hand convention; a writer who says where the road
    is, or that traffic keeps left, is read as driving on the left whatever the unit."""
    assert drives_on_left(_tokens(text), text)


@pytest.mark.parametrize(
    "text",
    [
        "US city street, 25 mph, a cyclist on the inside.",
        "In Canada at 40 mph on the nearside.",
        "We drive on the right here: 30 mph, a van in the inside lane.",
        "On holiday in France, 50 mph, a cyclist on my inside.",
        # near misses: words that only look like a place or a convention
        "The van drove on the left lane at 60 km/h.",
        "My English is not good: ego 30 km/h, a bike on the inside.",
        "A Japanese hatchback in the nearside lane, ego 50 km/h.",
    ],
)
def test_a_place_or_convention_of_right_hand_traffic_or_none(text):
    assert not drives_on_left(_tokens(text), text)


def test_the_pronoun_us_is_no_country():
    text = "Let us know: 30 mph, a cyclist in the inside lane."
    assert drives_on_left(_tokens(text), text)  # (miles per hour, and "us" a pronoun, not the US)


def test_two_places_of_different_conventions_say_nothing_of_the_side():
    text = "A rental in Spain on holiday from Ireland, at 50 mph; a cyclist on the inside."
    assert drives_on_left(_tokens(text), text)  # (both said: the unit decides, miles per hour)


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Ireland, 50 km/h: a cyclist came up on our inside and rode on.", "left"),
        ("Ego at 40 km/h in Sydney, Australia; a scooter nips up the inside and keeps going.", "left"),
        ("It's a UK road, 60 km/h, I'm in lane 1 and a van in the outside lane drifts into mine.", "right"),
    ],
)
def test_a_left_hand_place_sets_the_inside(text, expected):
    assert _side_started(text) == expected
