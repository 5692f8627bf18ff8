"""Two classes of scenario that were read but did not play as their layers say:

* a road user that overtakes an ego standing still (in a queue, at the lights), coming up faster than
  it from the start, and then stops: it starts far enough back to be out in the next lane before it
  draws level, so the pass, the cut back in and the stop all happen;
* a road user that cuts across the ego's lane to turn off on a map with no exit on that side (a bend,
  a straight road: the turn is into a drive or a car park the map does not hold): the scenario is
  written, and the cut across is played.

Each sentence is read, written, played with vei run's interpreter and checked with
:func:`~vei_scenario.language.corpus_check.played_problems`; the guards keep what already played."""

from __future__ import annotations

import pytest
from built_layers import layers_of
from play_layers import play_layers

from vei_scenario.language.behaviours import overtake
from vei_scenario.language.corpus_check import _ego_frame, played_problems
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text
from vei_scenario.language.scenario_writer import TYPES

PASSED_WHILE_STANDING = [
    "The ego car is stationary at a red signal at a crossroads; a cyclist overtakes it and then stops.",
    "The ego is standing still in queueing traffic on a straight road. A motorbike passes it and then stops.",
    "The ego has come to a halt in a queue on a straight road; a courier on a bicycle overtakes it and then stops.",
]


def _names(adv: dict) -> list[str]:
    return [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])]


@pytest.mark.parametrize("text", PASSED_WHILE_STANDING)
def test_a_faster_road_user_overtaking_a_standing_ego_passes_and_then_stops(text, tmp_path):
    layers = layers_from_text(text, 0)
    assert float(layers["ego"]["speed_mps"]) == 0.0
    [adv] = layers["adversaries"]
    assert _names(adv) == ["overtake", "stop"]
    assert float(adv["speed_mps"]) > 1.0
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert not any(adv["name"] in (a, b) for _, a, b in result.collisions)
    assert abs(float(result.traces[adv["name"]].speed[-1])) < 0.5


@pytest.mark.parametrize(("speed", "ego_speed"), [(10.0, 0.0), (16.0, 0.0), (5.0, 0.0)])
def test_an_overtaker_faster_than_the_ego_starts_back_by_what_it_closes_while_it_pulls_out(speed, ego_speed):
    cfg = {"lane_change_s": 3.0, "delay_s": 0.5}
    lon, _ = overtake.place(ego_speed, 6.4, cfg, speed)
    assert -lon >= 3.2 + (speed - ego_speed) * 3.5


def test_an_overtaker_at_the_ego_s_speed_starts_where_it_did():
    """Guard: one at the ego's speed (or one whose speed the text leaves open) starts 15 m behind,
    beyond half the lengths, as before."""
    assert overtake.place(12.0, 6.4, {}, 12.0) == (-(3.2 + 15.0), 12.0)
    assert overtake.place(12.0, 6.4, {}) == (-(3.2 + 15.0), 12.0)
    # past a moving ego, even a faster one (a motorbike at 150 km/h past an ego at 120): the pass is
    # timed from behind it, and from further back it would not be ahead before the scenario ends
    assert overtake.place(33.3, 6.4, {}, 41.7) == (-(3.2 + 15.0), 33.3)
    layers = layers_from_text("The ego car drives at 50 km/h on a straight road. A van overtakes it and stops.", 0)
    [adv] = layers["adversaries"]
    lengths = TYPES["car"][0][0] + TYPES[adv["type"]][0][0]
    assert float(adv["spawn"]["longitudinal_m"]) == pytest.approx(-(lengths / 2 + 15.0), abs=1e-3)


def _turning_off(map_kind: str, placement: str) -> dict:
    ego = {"placement": placement, "lane": 1, "agent": "cap", "speed_mps": 13.0}
    if map_kind != "straight":
        ego["distance_m"] = 70.0
    adversary = {
        "name": "Adversary1",
        "type": "van",
        "spawn": {"relation": "left", "longitudinal_m": 20.0},
        "speed_mps": 11.0,
        "behaviour": {"behaviour": "forced_turn", "config": {"gap_m": 8.0, "turn": "right"}},
    }
    return layers_of(map_kind, ego, [adversary])


@pytest.mark.parametrize(("map_kind", "placement"), [("curve", "on_curve"), ("straight", "straight")])
def test_a_turn_off_a_road_with_no_exit_on_that_side_is_played_as_the_cut_across(map_kind, placement, tmp_path):
    layers = _turning_off(map_kind, placement)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    lon, lat = _ego_frame(result, "Adversary1")
    assert lat[0] > 2.0  # (it starts in the lane beside the ego)
    assert ((lon > 0) & (abs(lat) < 1.2)).any()  # and cuts across in front of it


def test_a_turn_at_a_junction_still_turns_off_there(tmp_path):
    """Guard: where the map has the exit, the forced turn takes its route through it."""
    layers = _turning_off("crossroad", "before_junction")
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    trace, ego = result.traces["Adversary1"], result.traces[result.ego]
    assert abs(float(trace.yaw[-1]) - float(ego.yaw[0])) > 1.0  # it has turned off the ego's way
