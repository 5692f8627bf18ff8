"""A roundabout whose approaches have two lanes each way: every lane of an arm reaches the ring.

The ring is one lane; of an arm's two lanes only the one next to the centre line was joined to it,
so a road user in the kerb lane (the ego in lane 1, a road user waiting at an entry, which stands in
its arm's kerb lane) came to the ring and stood there for the rest of the run: a turn in never
turned in, the ego never went round. Each lane driving in now merges onto the ring, and the ring
feeds each lane driving out.

The sentences are read, written, played with vei run's interpreter and checked with
:func:`~vei_scenario.language.corpus_check.played_problems`; the guards keep what already played."""

from __future__ import annotations

import math

import pytest
from play_layers import play_layers

from vei_scenario.language import maps
from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text

RING = {"11", "12", "13", "14"}


def _links(kind: str, lanes: int) -> tuple[set, set]:
    """(the (arm, lane) pairs that drive into the junctions, the (arm, lane) pairs the junctions drive
    out to) of a generated map with ``lanes`` lanes each way on its arms: the lanes of the arms that a
    connecting road's lanes link to (an arm's negative lanes drive in, its positive ones out)."""
    odr, _ = maps.build_map({"kind": kind, "lanes_per_direction": lanes})
    into, out = set(), set()
    for road in odr.get_element().iter("road"):
        link = road.find("link")
        if road.get("junction") in (None, "-1") or link is None:
            continue
        ends = {end.tag: end.get("elementId") for end in link}
        for lane in road.iter("lane"):
            for end in lane.iter():
                arm = ends.get(end.tag) if end.tag in ("predecessor", "successor") else None
                if arm is not None and arm not in RING:
                    lane_id = int(end.get("id"))
                    (into if lane_id < 0 else out).add((arm, lane_id))
    return into, out


ARMS = ("1", "2", "3", "4")


@pytest.mark.parametrize("lanes", [2, 3])
def test_every_lane_of_a_multi_lane_arm_drives_onto_and_off_the_ring(lanes):
    into, out = _links("roundabout", lanes)
    assert into == {(arm, -k) for arm in ARMS for k in range(1, lanes + 1)}
    assert out == {(arm, k) for arm in ARMS for k in range(1, lanes + 1)}


def test_a_one_lane_roundabout_is_joined_as_before():
    """Guard: one lane each way, one ring lane: one connection in and one out per arm, as before."""
    into, out = _links("roundabout", 1)
    assert into == {(arm, -1) for arm in ARMS}
    assert out == {(arm, 1) for arm in ARMS}


def test_the_crossroad_is_joined_as_before():
    """Guard: the crossroad's arms meet lane for lane, every lane in and out, as they did."""
    into, out = _links("crossroad", 2)
    assert into == {(arm, -k) for arm in ARMS for k in (1, 2)}
    assert out == {(arm, k) for arm in ARMS for k in (1, 2)}


def _names(adv: dict) -> list[str]:
    return [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])]


def _travelled_m(trace) -> float:
    return float(sum(math.hypot(dx, dy) for dx, dy in zip(trace.x[1:] - trace.x[:-1], trace.y[1:] - trace.y[:-1])))


KERB_LANE_AT_A_TWO_LANE_RING = [
    # the ego in the kerb lane, a van pulling out of the next entry on its right
    (
        "The ego approaches a two-lane roundabout at 40 km/h, keeping to the right-hand lane. "
        "A van pulls out of the entry on its right into its path.",
        "turn_into",
    ),
    # the guide's example: a taxi waiting at the entry before the ego's (on its left) pulls out
    (
        "I came up to a two-lane roundabout in the right-hand lane and a taxi pulled out of the next entry.",
        "turn_into",
    ),
    # the ego in the kerb lane, a cyclist at the entry on its right that lets it go by
    (
        "On a two-lane roundabout the ego drives at 35 km/h in the outer lane; a cyclist waiting at the "
        "entry on its right gives way to it.",
        "give_way",
    ),
]


@pytest.mark.parametrize(("text", "does"), KERB_LANE_AT_A_TWO_LANE_RING)
def test_the_ego_in_the_kerb_lane_goes_onto_the_ring_and_the_road_user_at_the_entry_does_its_part(text, does, tmp_path):
    layers = layers_from_text(text, 0)
    assert layers["environment"]["map"] == {"kind": "roundabout", "lanes_per_direction": 2}
    assert layers["ego"]["lane"] == 1
    [adv] = layers["adversaries"]
    assert _names(adv) == [does]
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    # the ego came to the ring and went on round it, past where its arm ends
    assert _travelled_m(result.traces[result.ego]) > float(layers["ego"]["distance_m"]) + 20.0
    if does == "turn_into":  # it left its entry (from the kerb lane it stands in)
        assert _travelled_m(result.traces[adv["name"]]) > 20.0


def test_a_road_user_giving_way_at_a_two_lane_entry_goes_on_once_the_ego_has_passed(tmp_path):
    """The ego in the lane next to the centre line went onto the ring before; the road user giving way
    stands in its arm's kerb lane, and it now goes on onto the ring after the ego, where it stood at
    the arm's end for the rest of the run. It still stands first and is not hit."""
    text = (
        "The ego drives at 30 km/h in the inner lane towards a two-lane roundabout. "
        "A car waiting at the entry on its right gives way to it."
    )
    layers = layers_from_text(text, 0)
    assert layers["environment"]["map"]["lanes_per_direction"] == 2
    assert layers["ego"]["lane"] == 2
    [adv] = layers["adversaries"]
    assert _names(adv) == ["give_way"]
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert _travelled_m(result.traces[adv["name"]]) > 10.0  # (it went on once the ego had passed)
