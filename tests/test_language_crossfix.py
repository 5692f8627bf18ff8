"""A walker's or rider's way "over the road" or "to the other side" (way_across.py): what it is not.

The review's sentences and variants of them: "road" only modifying a compound noun ("the road
bridge"); the other side of something that is not the road ("of the bus", "of the lane", "of the
field") or reached along or under a way; a move to the other side made to overtake or to let the ego
pass; a pronoun standing for a vehicle; the side a turn goes to with the subject left out or the
verb in the past tense. Guards: the crossings the rule was made for keep their reading.
"""

from __future__ import annotations

import pytest

from tests.reading_of import acts
from vei_scenario.language.rules_backend import layers_from_text


def _adversaries(text: str) -> list[tuple[str, str, list[str]]]:
    """(type, start relation, behaviour names) of each adversary read from ``text`` (seed 0)."""
    from tests.reading_of import _behaviour_names

    layers = layers_from_text(text, 0)
    return [(a["type"], a["spawn"]["relation"], _behaviour_names(a["behaviour"])) for a in layers["adversaries"]]


@pytest.mark.parametrize(
    "text",
    [
        "The cyclist went over the road bridge ahead of me.",
        "The cyclist went over the road hump in front of me.",
        "A man walked over the road works barrier ahead.",
        "A lad on a bike rode over the road bridge in front of me.",
        "The jogger went over the street markings near the school.",
    ],
)
def test_road_as_a_modifier_is_no_way_over_the_road(text: str) -> None:
    """F14: "the road bridge", "the road hump": "road" modifies the noun after it, nothing is crossed."""
    assert all("cross_in_front" not in names for _, names in acts(text))


@pytest.mark.parametrize(
    "text",
    [
        "The cyclist moved to the far side of the lane as I passed.",
        "The dog ran to the other side of the field.",
        "The kid cycled to the other side of the car park while I reversed.",
        "The walker moved to the opposite side of the path as the car came.",
        "The cyclist rode through the underpass to the other side of the road.",
        "A jogger ran along the pavement to the other side of the bridge.",
        "A cyclist rode under the flyover to the far side of the road.",
    ],
)
def test_the_other_side_of_what_is_not_the_road_is_no_crossing(text: str) -> None:
    """F15, C1: the far side of a lane, a field, a car park, or reached along or under a way, is no
    crossing of the ego's road."""
    assert all("cross_in_front" not in names for _, names in acts(text))


def test_the_other_side_of_a_bus_says_no_kerb() -> None:
    """F15: "the other side of the bus" is no far kerb: the walker keeps the kerb it is read at."""
    ((kind, relation, names),) = _adversaries("The pedestrian went to the other side of the bus and crossed.")
    assert (kind, relation, names) == ("pedestrian", "roadside_left", ["cross_in_front"])


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A kid ran to the other side of the road in front of me.", "pedestrian"),
        ("A lad on a bike rode to the other side of the dual carriageway right in front of me.", "bicycle"),
        ("An old woman walked through the traffic to the other side of the road.", "pedestrian"),
    ],
)
def test_the_other_side_of_the_road_still_crosses(text: str, kind: str) -> None:
    """Guard: the other side of the road (its head a carriageway word) is a crossing."""
    assert acts(text)[0] == (kind, ["cross_in_front"])


def test_to_the_other_side_to_overtake_keeps_the_overtake() -> None:
    """F16: a pull out to the other side of the road to overtake a bus is a move onto the wrong side,
    not a crossing; the bus overtaken stays in the reading."""
    got = _adversaries("A scooter rider pulled out to the other side of the road to overtake a bus.")
    assert [kind for kind, _, _ in got] == ["e-scooter", "truck"]
    assert all("cross_in_front" not in names for _, _, names in got)


def test_to_the_other_side_to_let_me_pass_keeps_the_give_way() -> None:
    """F16: the purpose after the goal ("to let me pass") is no word of the goal: it stays."""
    ((_, _, names),) = _adversaries("A horse rider moved over to the other side of the road to let me pass.")
    assert "give_way" in names


@pytest.mark.parametrize(
    "text",
    [
        "A car came round the bend too fast. It went over the road and hit the wall.",
        "A taxi did a U-turn. It went to the other side of the road and stopped.",
        "The van in front indicated right. It turned right to get to the other side of the dual carriageway.",
        "A motorbike came up behind me. It went over the road and into a side street.",
    ],
)
def test_a_pronoun_for_a_vehicle_does_not_cross(text: str) -> None:
    """F17: "it" standing for a car, a taxi, a van, a motorbike: no crossing, so no red run at an
    invented crossroads (a turn said may still place a junction)."""
    layers = layers_from_text(text, 0)
    assert "turned" in text or layers["environment"]["map"]["kind"] != "crossroad"
    assert all("run_red_light" not in names and "cross_in_front" not in names for _, names in acts(text))


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A cyclist was ahead of me. Then it turned right to get to the other side of the road.", "bicycle"),
        ("An old man stood at the kerb. Then he went over the road in front of me.", "pedestrian"),
    ],
)
def test_a_pronoun_for_a_walker_or_rider_crosses(text: str, kind: str) -> None:
    """Guard: a pronoun for the walker or rider named before it still crosses."""
    assert acts(text)[0] == (kind, ["cross_in_front"])


@pytest.mark.parametrize(
    ("text", "relation"),
    [
        ("A cyclist was ahead of me. Then turned right to get to the other side of the road.", "roadside_left"),
        ("A cyclist was ahead of me. Then it turned right to get to the other side of the road.", "roadside_left"),
        ("The cyclist turned right across me to get to the other side.", "roadside_left"),
        (
            "A cyclist was cruising in the gutter, then hooks a right across the front of me to get to the other side.",
            "roadside_left",
        ),
        ("A cyclist hooked a right across the front of me to get to the other side.", "roadside_left"),
        ("A kid on a scooter swung a left across my bonnet to get to the other side.", "roadside_right"),
    ],
)
def test_the_turns_side_says_the_kerb_it_starts_from(text: str, relation: str) -> None:
    """F18: a turn to the right to get to the other side starts on the left kerb (and the other way
    round), with the subject said or left out and the verb in the present or the past."""
    first = _adversaries(text)[0]
    assert (first[1], first[2]) == (relation, ["cross_in_front"])
