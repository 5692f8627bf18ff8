"""Whose side a crossing walker or rider comes from, when the side is said of something else too:

* a crossing whose side is only said of the parked vehicles it comes out from keeps that side when
  other parked vehicles are named with no side ("parked cars both sides ... from behind a parked van
  on the left": from the left);
* a bare "nearside" or "far side" names the writer's near or far kerb, and a writer who drives on the
  left has the nearside on the left (a test line with metric speeds keeps the right-hand convention);
* a kerb a road user is said to come off ("off the pavement on the right") is where it starts, not
  the kerb it is said to be going to afterwards ("to reach the shop on the other side");
* "from the left" after the vehicle a walker crosses in front of is where the walker comes from.

The guards keep the readings that were already right."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _crosser(text: str) -> dict:
    layers = layers_from_text(text, 0)
    crossers = [a for a in layers["adversaries"] if a["behaviour"]["behaviour"] == "cross_in_front"]
    assert len(crossers) == 1, layers["adversaries"]
    return crossers[0]


NEW = [
    (
        "Cyclist emerging between parked cars. Ego at 40 km/h. A cyclist emerges from a gap between parked "
        "cars on the ego's left and crosses at 15 km/h.",
        "roadside_left",
    ),
    (
        "Driving through the village at 25 mph, a boy ran out from between parked cars, nearside, and I braked.",
        "roadside_left",
    ),
    (
        "I was doing 20 mph behind a bus. A lad on a scooter came off the footway on the left and shot across "
        "in front of me to get to his friends on the other side.",
        "roadside_left",
    ),
    (
        "Our bus was leaving the stop at 15 km/h when an old man crossed in front of the bus from the left.",
        "roadside_left",
    ),
    ("A man crossed in front of the lorry from the left.", "roadside_left"),
]


@pytest.mark.parametrize(("text", "relation"), NEW)
def test_the_crossing_starts_from_the_side_said_of_it(text, relation):
    assert _crosser(text)["spawn"]["relation"] == relation


GUARDS = [
    (
        "A cyclist came off the pavement on the right and rode across in front of me to reach the shop on the "
        "other side.",
        "roadside_right",
    ),
    ("A pedestrian stepped off the kerb on the left and crossed.", "roadside_left"),
    ("A dog ran off to the left, across in front of me.", "roadside_right"),
    ("Test 4: a child target runs out from behind parked cars, nearside, ego at 40 km/h.", "roadside_right"),
    ("A woman stepped out from between two parked cars on the right and walked across.", "roadside_right"),
    ("A jogger crossed in front of me from the left.", "roadside_left"),
    ("A man crossed in front of the lorry from the right.", "roadside_right"),
    (
        "Child stepping out between parked cars. Ego at 30 km/h in a quiet street. A child steps out from "
        "behind a parked pickup on the left side and runs across.",
        "roadside_left",
    ),
]


@pytest.mark.parametrize(("text", "relation"), GUARDS)
def test_sides_already_read_keep_their_reading(text, relation):
    assert _crosser(text)["spawn"]["relation"] == relation


def test_an_overtaker_from_a_side_keeps_its_own_reading():
    # (no crossing: "from the left" stays with the one who passes)
    layers = layers_from_text("A cyclist overtook the bus from the left.", 0)
    assert [a["behaviour"]["behaviour"] for a in layers["adversaries"]][:1] == ["overtake"]
