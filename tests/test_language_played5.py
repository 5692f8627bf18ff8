"""A road user running the red from the arm opposite the ego: straight on it would only pass the ego
side by side (the ego going straight on, or turning right), so it turns left through the junction,
across the ego's way or into the road the ego turns into, and comes within 3 m of the ego's path.

Each scenario is written, played with vei run's interpreter and checked with
:func:`~vei_scenario.language.corpus_check.played_problems`; the guards keep the runners from the side
arms, and from the opposite arm when the ego turns left across it, going straight on."""

from __future__ import annotations

import math

import pytest
from built_layers import junction_context, layers_of
from play_layers import play_layers

from vei_scenario.language.behaviours import run_red_light
from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.rules_backend import layers_from_text


def _runner(relation: str, ego_route: str, lanes: int = 2, kind: str = "bicycle", speed: float = 5.0) -> dict:
    ego = {"placement": "before_junction", "lane": 1, "agent": "cap", "speed_mps": 10.0, "distance_m": 60.0}
    adversary = {
        "name": "Adversary1",
        "type": kind,
        "spawn": {"relation": relation},
        "speed_mps": speed,
        "behaviour": {"behaviour": "run_red_light", "config": {}},
    }
    return layers_of("crossroad", ego | {"route": ego_route}, [adversary], lanes=lanes, signals=True)


def _turned(result) -> float:
    """How far the runner's heading has turned from its start by the end of the run (rad)."""
    yaw = result.traces["Adversary1"].yaw
    return abs((float(yaw[-1]) - float(yaw[0]) + math.pi) % (2 * math.pi) - math.pi)


@pytest.mark.parametrize(("ego_route", "lanes"), [("straight", 2), ("straight", 1), ("right", 2)])
def test_a_runner_from_the_opposite_arm_turns_across_the_ego_s_way(ego_route, lanes, tmp_path):
    layers = _runner("junction_opposite", ego_route, lanes)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert _turned(result) > 1.2  # (a quarter turn, to its left)


def test_a_runner_the_ego_turns_left_across_still_goes_straight_on(tmp_path):
    """Guard: the ego turning left crosses the opposite arm's straight way already."""
    layers = _runner("junction_opposite", "left")
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert _turned(result) < 0.2


@pytest.mark.parametrize("relation", ["junction_left", "junction_right"])
def test_a_runner_from_a_side_arm_still_goes_straight_over(relation, tmp_path):
    """Guard: from the ego's left or right, straight on crosses the ego's way."""
    layers = _runner(relation, "straight", kind="car", speed=10.0)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert _turned(result) < 0.2


def test_the_way_through_is_chosen_on_the_crossroad_only():
    """Guard: on a roundabout every way goes round the ring: the runner keeps its straight exit."""
    ctx = junction_context(map_kind="roundabout")
    assert run_red_light.way_through(ctx) == "straight"
    ctx.map_kind = "crossroad"
    assert run_red_light.way_through(ctx) == "left"
    ctx.ego_route = "left"
    assert run_red_light.way_through(ctx) == "straight"


@pytest.mark.parametrize(
    "text",
    [
        "Driving straight over the crossroads at 30 km/h on a green light, an oncoming cyclist ran the red light.",
        "Going straight across the junction at 30 km/h on green, a van coming the other way ran the red light.",
    ],
)
def test_a_described_runner_coming_the_other_way_plays_through_the_ego_s_way(text, tmp_path):
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert adv["spawn"]["relation"] == "junction_opposite"
    assert adv["behaviour"]["behaviour"] == "run_red_light"
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
