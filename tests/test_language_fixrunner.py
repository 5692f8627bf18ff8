"""A red-light runner whose way through the junction the text says ("carried straight on past me",
"went straight through") keeps that way: the reader puts it on the run as ``turn`` and the builder
drives it so. Only where the text says nothing of its way does the builder choose one that meets the
ego (from the arm opposite, a left turn across the ego's way, in right-hand traffic)."""

from __future__ import annotations

import math

import pytest
from built_layers import junction_context
from play_layers import play_layers

from vei_scenario.language.behaviours import run_red_light
from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text


def _run(text: str) -> dict:
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    runs = [n for _, n in behaviour_nodes(adv["behaviour"]) if n["behaviour"] == "run_red_light"]
    assert runs, adv["behaviour"]
    return runs[0]


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming car jumped the lights and carried straight on past me.",
        "A car ran the red light coming towards me and went straight through.",
        "An oncoming van ran the red light and drove straight on.",
        "A taxi coming the other way went straight through the red light.",
        "An oncoming lorry ignored the red light and kept going straight ahead.",
    ],
)
def test_a_runner_said_to_go_straight_on_is_told_so(text):
    assert _run(text).get("config", {}).get("turn") == "straight"


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming car ran the red light.",  # (its way not said: the builder chooses)
        "An oncoming car ran the red light and carried on.",
        "Going straight on at the crossroads, I saw an oncoming car run the red light.",  # (the ego's way)
        "An oncoming car ran the red light and came straight at me.",  # (at the ego: no way through said)
        "Heading straight over the junction on green, an oncoming van ran the red light.",  # (the ego's)
    ],
)
def test_a_runner_whose_way_is_not_said_is_left_to_the_builder(text):
    assert "turn" not in _run(text).get("config", {})


def test_the_way_said_is_the_way_taken():
    assert run_red_light.way_through(junction_context(), "straight") == "straight"
    assert run_red_light.way_through(junction_context("left"), "right") == "right"
    # (not said: from the opposite arm it turns across the ego's way)
    assert run_red_light.way_through(junction_context()) == "left"
    assert run_red_light.way_through(junction_context(), None) == "left"


def _turned(result) -> float:
    yaw = result.traces["Adversary1"].yaw
    return abs((float(yaw[-1]) - float(yaw[0]) + math.pi) % (2 * math.pi) - math.pi)


def test_a_runner_said_to_carry_straight_on_plays_straight_on(tmp_path):
    layers = layers_from_text("An oncoming car jumped the lights and carried straight on past me.", 0)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []  # (side by side, as the text says: no run across is asked)
    assert _turned(result) < 0.2


def test_a_runner_whose_way_is_not_said_still_turns_across(tmp_path):
    """Guard: the runner's way left to the builder still meets the ego."""
    layers = layers_from_text("An oncoming car ran the red light.", 0)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert _turned(result) > 1.2


def test_a_runner_sent_straight_on_across_an_ego_turning_left_must_still_meet_its_path():
    """Guard: only the side-by-side pass is spared the check that a run comes near the ego's path."""
    assert run_red_light.passes_by("junction_opposite", "straight", "straight")
    assert not run_red_light.passes_by("junction_opposite", "straight", "left")
    assert not run_red_light.passes_by("junction_left", "straight", "straight")
    assert not run_red_light.passes_by("junction_opposite", None, "straight")
