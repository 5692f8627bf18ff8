"""Scenarios whose road users change lanes near a junction or roundabout are written so that every lane
change runs on linked lanes: an overtake before the junction is over (the overtaker back in a lane ahead
of the ego) while both are still on the ego's road, and a forced turn by a road user on another arm of
the junction is its turn along its route, with no lane change towards the ego's lane (a lane of another
road). Each test writes the scenario of a sentence, plays it with vei run's interpreter and checks what
happened."""

from __future__ import annotations

import numpy as np
import pytest
from play_layers import play_layers

from vei_scenario.language.corpus_check import _ego_frame, _nearest_on_path, played_problems
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text
from vei_scenario.language.scenario_writer import write_scenario

OVERTAKES_BEFORE_A_JUNCTION = [
    "Coming up to the roundabout, a van behind me overtook me and cut in dangerously close in front of me.",
    "On the approach to the crossroads a lorry overtook us at speed and cut straight back in with barely a metre"
    " to spare.",
    "Approaching the crossroads, a van overtook me and cut in just in front of me.",
    "Just before the roundabout, a cyclist on my right overtook me and swerved in inches from my bumper.",
]


def _names(adv: dict) -> list[str]:
    return [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])]


def _travelled(trace) -> np.ndarray:
    return np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(trace.x), np.diff(trace.y)))])


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("text", OVERTAKES_BEFORE_A_JUNCTION)
def test_an_overtake_before_a_junction_is_over_before_the_junction(text, seed, tmp_path):
    """The overtaker is back in the ego's lane ahead of it while the ego is still on its own road, and
    the scenario plays (a cut back still under way at the junction ran into its roads' unlinked lanes)."""
    layers = layers_from_text(text, seed)
    assert layers["environment"]["map"]["kind"] in ("crossroad", "roundabout")
    [adv] = layers["adversaries"]
    assert "overtake" in _names(adv)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    on_own_road = _travelled(result.traces[result.ego]) < float(layers["ego"]["distance_m"])
    lon, lat = _ego_frame(result, adv["name"])
    assert ((lon > 0) & (np.abs(lat) < 1.2) & on_own_road).any()


def test_an_overtake_on_a_road_without_a_junction_keeps_the_ego_s_start():
    """Guard: on a straight road there is no junction for the overtake to finish before, and the ego
    has no distance to one."""
    layers = layers_from_text("A van overtook me on the open road and cut in just in front of me.", 0)
    assert layers["environment"]["map"]["kind"] == "straight"
    assert "distance_m" not in layers["ego"]


@pytest.mark.parametrize(
    "text",
    [
        "At the crossroads a car coming the other way turned left across my path.",
        "Approaching the crossroads at the lights, a bus waited on the right and then ran the red light.",
    ],
)
def test_with_no_one_overtaking_the_ego_starts_where_it_did(text):
    """Guard: where no road user overtakes, the ego's start before its junction is the sampler's own
    (70 m, give or take 10), not moved back."""
    layers = layers_from_text(text, 0)
    assert not any("overtake" in _names(a) for a in layers["adversaries"])
    assert 60.0 <= float(layers["ego"]["distance_m"]) <= 80.0


FORCED_TURNS_FROM_THE_OPPOSITE_ARM = [
    "At the crossroads a car coming the other way forced a right turn across my lane.",
    "At the roundabout, an oncoming hatchback forcefully turns right in front of me.",
]


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("text", FORCED_TURNS_FROM_THE_OPPOSITE_ARM)
def test_a_forced_turn_from_another_arm_is_written_without_a_lane_change_and_plays(text, seed, tmp_path):
    """A road user on the arm opposite the ego turns along its route; no lane change towards the ego's
    lane (whose id is another road's) is written for it, and the scenario plays."""
    layers = layers_from_text(text, seed)
    [adv] = layers["adversaries"]
    assert _names(adv) == ["forced_turn"] and adv["spawn"]["relation"] == "junction_opposite"
    assert b"LaneChangeAction" not in write_scenario(layers, "scenario").xosc
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []


def test_a_forced_turn_from_the_opposite_arm_of_a_crossroads_crosses_the_ego_s_path(tmp_path):
    """It turns at the junction (its route is its from the start), across the ego's path, not straight
    on past the ego (the gap it waited for closes only once they have passed each other)."""
    layers = layers_from_text(FORCED_TURNS_FROM_THE_OPPOSITE_ARM[0], 0)
    result = play_layers(layers, tmp_path)
    distance, _ = _nearest_on_path(result.traces["Adversary1"], result.traces[result.ego])
    assert float(distance.min()) < 1.0


def test_a_forced_turn_from_the_lane_beside_the_ego_still_cuts_across_its_lane():
    """Guard: from the lane beside the ego, on the ego's own road, the forced turn is still the cut
    across the ego's lane (a lane change to it) before the turn."""
    text = "Just before the crossroads, the car in the lane to my left forced a right turn across my lane."
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert _names(adv) == ["forced_turn"] and adv["spawn"]["relation"] == "left"
    assert b"RelativeTargetLane" in write_scenario(layers, "scenario").xosc


@pytest.mark.parametrize(
    "text",
    [
        "At the crossroads an oncoming car forced a right turn across my lane and ran the red light.",
        "At the lights a van coming the other way forcefully turned right in front of me, straight through the red"
        " light.",
    ],
)
def test_a_turn_from_another_arm_that_runs_the_red_runs_it_along_the_turn(text, tmp_path):
    """One that turns at the junction and runs the red doing so keeps its turn's route (the run takes no
    straight-on route of its own from where it started): its way crosses the ego's path."""
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert _names(adv) == ["forced_turn", "run_red_light"] and adv["spawn"]["relation"] == "junction_opposite"
    assert write_scenario(layers, "scenario").xosc.count(b"<AssignRouteAction>") == 2  # (the ego's and its turn)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []


# A road user whose first behaviour is itself a drive (head-on the wrong way, past the ego) moves when
# the scenario starts: a standing speed read for it ("... stopped right in front of me") is where it ends.
STANDING_DRIVES = [
    ("A farmer's pickup driving the wrong way down the lane stopped right in front of me.", "wrong_way"),
    ("Some idiot in a hatchback going the wrong way up the one-way street stopped nose to nose with me.", "wrong_way"),
    ("The delivery van overtook us and stopped outside the shop.", "overtake"),
]


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize(("text", "drive"), STANDING_DRIVES)
def test_a_drive_read_as_standing_goes_at_a_road_pace(text, drive, seed):
    """Its speed is a road pace, not the standstill the text ends it in."""
    [adv] = layers_from_text(text, seed)["adversaries"]
    assert _names(adv)[0] == drive
    assert float(adv["speed_mps"]) > 5.0


@pytest.mark.parametrize(("text", "drive"), STANDING_DRIVES)
def test_a_drive_read_as_standing_does_what_its_layers_say(text, drive, tmp_path):
    """Played, the wrong-way driver is head-on in the ego's lane and the overtaker gets ahead of the ego."""
    layers = layers_from_text(text, 0)
    assert played_problems(play_layers(layers, tmp_path), layers) == []


@pytest.mark.parametrize(
    ("text", "first"),
    [
        ("A car was parked on my side of the road facing me.", "stop"),
        ("A cyclist coming towards me on the wrong side of the road stopped and waited.", "stop"),
    ],
)
def test_a_road_user_that_only_stands_keeps_standing(text, first):
    """Guard: one whose first behaviour is standing (parked, stopped) still starts at a standstill."""
    [adv] = layers_from_text(text, 0)["adversaries"]
    assert _names(adv)[0] == first and float(adv["speed_mps"]) == 0.0


def test_a_wrong_way_driver_with_a_stated_speed_keeps_it():
    """Guard: a speed said of the wrong-way driver is its speed."""
    text = "A van doing about 30 km/h came at me on the wrong side of the road."
    [adv] = layers_from_text(text, 0)["adversaries"]
    assert _names(adv)[0] == "wrong_way" and abs(float(adv["speed_mps"]) * 3.6 - 30.0) < 1.0
