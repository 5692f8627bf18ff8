"""A distance said of a walker or rider going along the road that is too short to hold the two bodies
(the room the ego gave passing it, how far short it stopped behind it) is how near the ego came, kept
in the behaviour, and the road user starts where one going along starts; a distance that leaves room
between them is still where it starts."""

import pytest

from vei_scenario.language.closest_approach import is_closest_approach
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text
from vei_scenario.language.scenario_writer import TYPES


def _along(text: str, seed: int = 0) -> dict:
    layers = layers_from_text(text, seed)
    along = [a for a in layers["adversaries"] if _first(a)["behaviour"] == "along_road"]
    assert along, layers["adversaries"]
    return along[0]


def _first(adv: dict) -> dict:
    return next(node for _, node in behaviour_nodes(adv["behaviour"]))


def _gap(adv: dict) -> float | None:
    return _first(adv)["config"].get("gap_m")


def _clear_of_the_ego(adv: dict) -> bool:
    """Whether it starts with room between its body and the ego's (a car)."""
    half = (TYPES["car"][0][0] + TYPES[adv["type"]][0][0]) / 2
    return abs(float(adv["spawn"]["longitudinal_m"])) > half


@pytest.mark.parametrize(
    ("text", "near"),
    [
        # a driver's account: the room given going round a rider
        (
            "We were doing 40 km/h. A cyclist was riding along the kerb ahead of us and we went round him "
            "giving about 1.5 m.",
            1.5,
        ),
        # a participle opening, the clearance said as what was to spare
        (
            "Driving at 50 km/h, I passed a jogger running along the edge of the road in my direction with "
            "only half a metre to spare.",
            0.5,
        ),
        # a rider's speed first, then the ego held back and passed
        (
            "A cyclist was riding along the road in front of me at 15 km/h. I stayed behind him, then passed "
            "him leaving 2 metres.",
            2.0,
        ),
    ],
)
def test_a_distance_too_short_to_start_at_is_how_near_the_ego_came(text: str, near: float) -> None:
    for seed in (0, 1, 2):
        adv = _along(text, seed)
        assert _clear_of_the_ego(adv), adv
        assert _gap(adv) == pytest.approx(near), adv


@pytest.mark.parametrize(
    ("text", "start"),
    [
        # guard: a start said in metres with room between them stays where it starts
        ("The ego drives at 50 km/h. A cyclist rides along the kerb 30 m ahead in the same direction.", 30.0),
        ("At 30 km/h I came up behind a jogger running along the road about 12 metres ahead of me.", 12.0),
    ],
)
def test_a_distance_with_room_between_is_where_it_starts(text: str, start: float) -> None:
    adv = _along(text)
    assert float(adv["spawn"]["longitudinal_m"]) == pytest.approx(start)
    assert _gap(adv) is None


def test_the_room_a_start_needs_is_the_two_bodies_and_some_space() -> None:
    car, bike = TYPES["car"][0][0], TYPES["bicycle"][0][0]
    assert is_closest_approach(2.0, car, bike)
    assert is_closest_approach(-0.5, car, bike)  # (behind the ego: the same bodies)
    assert not is_closest_approach(10.0, car, bike)
