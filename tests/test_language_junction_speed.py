"""A road user that waits at a junction and then turns across the ego's path or pulls into its road
keeps the speed the text states as its speed in the layers (the speed it moves at): it rolls up to
its stop line at that speed, stands until its timing says go, and goes at it. Built from readings,
not sentences, so no wording is favoured."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.reading import ActorSpec, Reading
from vei_scenario.language.rules_backend import sample_layers

sys.path.insert(0, str(Path(__file__).parent))
from play_layers import play_layers  # noqa: E402


def _reading(kind, relation, behaviour, speed_mps, ego_speed_mps, intent):
    spec = ActorSpec(kind, relation, None, speed_mps, [(behaviour, {}, None, "sequence")])
    return Reading(map_kind="crossroad", ego_speed_mps=ego_speed_mps, intent=intent, actors=[spec])


CASES = [
    # an oncoming car turning across the ego's path at 30 km/h, the ego at 50 km/h
    ("car", "junction_opposite", "turn_across", 30 / 3.6, 50 / 3.6, "near_miss"),
    # a lorry pulling out of a side road on the left at 15 mph, the ego at 50 mph
    ("truck", "junction_left", "turn_into", 15 * 0.44704, 50 * 0.44704, "near_miss"),
    # a van pulling out from the right at 20 km/h, the ego slow
    ("van", "junction_right", "turn_into", 20 / 3.6, 30 / 3.6, "safe"),
    # a car turning across at 40 km/h in front of a fast ego
    ("car", "junction_opposite", "turn_across", 40 / 3.6, 70 / 3.6, "collision"),
]


@pytest.mark.parametrize("kind, relation, behaviour, speed, ego_speed, intent", CASES)
def test_a_stated_speed_of_a_road_user_at_a_junction_is_its_speed_and_it_still_plays(
    kind, relation, behaviour, speed, ego_speed, intent, tmp_path
):
    layers = sample_layers(_reading(kind, relation, behaviour, speed, ego_speed, intent), "built by a test", 3)
    (adv,) = layers["adversaries"]
    assert adv["speed_mps"] == pytest.approx(speed, abs=0.01)
    assert played_problems(play_layers(layers, tmp_path), layers) == []


@pytest.mark.parametrize("behaviour", ["turn_across", "turn_into"])
def test_no_stated_speed_it_still_stands_at_its_line(behaviour):
    # near miss: a road user at a junction with no speed said waits there standing
    relation = "junction_opposite" if behaviour == "turn_across" else "junction_left"
    layers = sample_layers(_reading("car", relation, behaviour, None, 12.0, "near_miss"), "built by a test", 3)
    assert layers["adversaries"][0]["speed_mps"] == 0.0


def test_a_road_user_said_to_stand_at_its_line_stays_standing():
    # near miss: "waiting at the line" read as speed 0 stays at 0
    layers = sample_layers(_reading("car", "junction_left", "turn_into", 0.0, 12.0, "safe"), "built by a test", 3)
    assert layers["adversaries"][0]["speed_mps"] == 0.0
