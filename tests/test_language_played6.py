"""Two classes of scenario that were read but did not play as their layers say:

* a cut-in by a road user that starts behind the ego in the ego's own lane (slower than it, or at
  its speed): it had no lane to change from and stayed behind; now it pulls out into the lane beside,
  comes past faster than the ego and changes in once it is its gap ahead;
* a slow walker crossing a wide road from the far kerb, timed to meet a slow ego far ahead: the run
  ended before the ego got there; now it lasts until the ego has reached the crossing.

Scenarios are built directly (:func:`built_layers.layers_of`) or read, written, played with vei run's
interpreter and checked with :func:`~vei_scenario.language.corpus_check.played_problems`; the guards
keep what already played."""

from __future__ import annotations

import numpy as np
import pytest
from built_layers import layers_of
from play_layers import play_layers

from vei_scenario.language.behaviours import cross_in_front, cut_in
from vei_scenario.language.behaviours.base import ActorContext
from vei_scenario.language.corpus_check import _ego_frame, played_problems
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text
from vei_scenario.language.scenario_writer import top_speed


def _cut_in_from(relation: str, lon: float, speed: float, kind: str = "car", lanes: int = 2) -> dict:
    lane = 2 if relation == "right" else 1  # (layers count lanes from the kerb)
    ego = {"placement": "straight", "lane": lane, "agent": "cap", "speed_mps": 14.0}
    adversary = {
        "name": "Adversary1",
        "type": kind,
        "spawn": {"relation": relation, "longitudinal_m": lon},
        "speed_mps": speed,
        "behaviour": {"behaviour": "cut_in", "config": {"gap_m": 6.0, "lane_change_s": 1.5, "lead_s": 2.5}},
    }
    return layers_of("straight", ego, [adversary], lanes=lanes, duration_s=20.0)


@pytest.mark.parametrize(
    ("lon", "speed", "kind", "lanes"),
    [(-20.0, 11.0, "car", 2), (-35.0, 14.0, "van", 3), (-15.0, 12.0, "car", 1), (-30.0, 13.0, "e-scooter", 2)],
)
def test_a_cut_in_from_behind_in_the_ego_s_lane_comes_past_and_gets_in_ahead(lon, speed, kind, lanes, tmp_path):
    layers = _cut_in_from("behind", lon, speed, kind, lanes)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    along, across = _ego_frame(result, "Adversary1")
    assert (np.abs(across) > 2.5).any()  # (out in the lane beside the ego's first)
    assert ((along > 0) & (np.abs(across) < 1.2)).any()


def test_a_rider_cutting_in_from_behind_may_go_faster_than_its_kind_usually_does():
    layers = _cut_in_from("behind", -30.0, 13.0, "e-scooter")
    ctx = _ctx(-2, 70.0)  # (where the writer places it: 30 m behind the ego in its lane)
    ctx.actor_type, ctx.actor_speed_mps = "e-scooter", 13.0
    assert top_speed(layers["adversaries"][0], 14.0, ctx) > 14.0 + cut_in.PASS_GAIN_MPS - 1e-6


def _ctx(actor_lane: int, actor_s: float, lanes: int = 2) -> ActorContext:
    return ActorContext(
        actor="Adversary1",
        actor_type="car",
        ego="Ego",
        ego_speed_mps=14.0,
        actor_speed_mps=12.0,
        ego_lane_id=-2 if lanes > 1 else -1,
        actor_lane_id=actor_lane,
        actor_road="1",
        actor_s_m=actor_s,
        lanes=lanes,
        friction=1.0,
        map_kind="straight",
        ego_s_m=100.0,
    )


def test_only_one_behind_in_the_ego_s_own_lane_comes_past_first():
    assert cut_in.behind_in_ego_lane(_ctx(-2, 80.0))
    assert not cut_in.behind_in_ego_lane(_ctx(-1, 80.0))  # (in the next lane: it changes lane as before)
    assert not cut_in.behind_in_ego_lane(_ctx(-2, 120.0))  # (ahead in the ego's lane)
    assert cut_in.passing_lane(_ctx(-2, 80.0, lanes=3)) == -1  # (the next lane of its direction)
    assert cut_in.passing_lane(_ctx(-1, 80.0, lanes=1)) == 1  # (one lane each way: over the centre line)


@pytest.mark.parametrize("relation", ["left", "right"])
def test_guard_a_cut_in_from_the_next_lane_ahead_still_plays(relation, tmp_path):
    layers = _cut_in_from(relation, 25.0, 11.0)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []


def test_guard_a_cut_in_read_from_the_next_lane_keeps_its_steps():
    layers = layers_from_text("On a two-lane road at 60 km/h, a van in the left lane cuts in front of the ego.", 0)
    [adv] = layers["adversaries"]
    assert adv["spawn"]["relation"] == "left"


def _kerb_crossing(ego_speed: float) -> dict:
    text = (
        f"The ego drives at {ego_speed:g} km/h on a road with three lanes each way; "
        "a pedestrian slowly walks across from the left kerb."
    )
    return layers_from_text(text, 0)


def test_a_slow_crossing_of_a_wide_road_lasts_until_the_ego_gets_there(tmp_path):
    layers = _kerb_crossing(20)
    [adv] = layers["adversaries"]
    assert adv["spawn"]["relation"] == "roadside_left"
    meet_s = float(adv["spawn"]["longitudinal_m"]) / float(layers["ego"]["speed_mps"])
    assert float(layers["duration_s"]) >= meet_s
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []


def test_guard_a_quick_crossing_keeps_its_run_length():
    layers = layers_from_text(
        "At 40 km/h on a straight road, a child runs out from the right kerb ahead of the ego.", 0
    )
    assert float(layers["duration_s"]) == 15.0


def test_a_van_behind_that_pulls_out_and_cuts_in_gets_in_ahead(tmp_path):
    layers = layers_from_text("The van behind us pulled out and cut in ahead of us.", 0)
    [adv] = layers["adversaries"]
    assert adv["spawn"]["relation"] == "behind"
    assert played_problems(play_layers(layers, tmp_path), layers) == []


def _stopped_short() -> dict:
    ego = {"placement": "straight", "lane": 1, "agent": "cap", "speed_mps": 10.0}
    lead = {
        "name": "Adversary1",
        "type": "car",
        "spawn": {"relation": "ahead", "longitudinal_m": 15.0},
        "speed_mps": 10.0,
        "behaviour": {"behaviour": "sudden_stop", "config": {"decel_mps2": 8.0, "delay_s": 0.5}},
    }
    walker = {
        "name": "Adversary2",
        "type": "pedestrian",
        "spawn": {"relation": "roadside_right", "longitudinal_m": 60.0},
        "speed_mps": 0.0,
        "behaviour": {"behaviour": "cross_in_front", "config": {"crossing_speed_mps": 1.5, "arrival_gap_s": 0.5}},
    }
    return layers_of("straight", ego, [lead, walker])


def test_a_kerb_crossing_is_made_even_when_the_ego_stops_short_of_it(tmp_path):
    layers = _stopped_short()
    result = play_layers(layers, tmp_path)
    along, _ = _ego_frame(result, "Adversary2")
    assert along.min() > 30.0  # (the ego never came near the walker)
    assert played_problems(result, layers) == []


def test_guard_a_kerb_crosser_still_sets_off_by_the_ego_s_distance_first():
    """The late start comes only after the ego, at its speed, would have set the crosser off."""
    ctx = _ctx(-2, 140.0)
    trigger_m = cross_in_front.trigger_distance_m(ctx, {"crossing_speed_mps": 1.5})
    late = cross_in_front.late_s(ctx, trigger_m)
    assert late == pytest.approx(max(0.0, 40.0 - trigger_m) / 14.0 + cross_in_front.LATE_S, abs=1e-3)
    standing = _ctx(-2, 140.0)
    standing.ego_speed_mps = 0.0
    assert cross_in_front.late_s(standing, trigger_m) is None


@pytest.mark.parametrize("seed", [0, 1])
def test_a_cut_in_after_an_overtake_cuts_in_from_beside_not_from_behind_again(seed, tmp_path):
    """An overtake then a cut-in: the cut-in starts where the overtake left the road user, already
    past the ego, so it does not pull out to come past a second time (on a road with one lane each way
    that second pass ran into the junction's unlinked lanes)."""
    layers = layers_from_text(
        "Nearing the roundabout, a pickup behind me overtook me and cut in sharply just in front of me.", seed
    )
    [adv] = layers["adversaries"]
    assert [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])] == ["overtake", "cut_in"]
    assert played_problems(play_layers(layers, tmp_path), layers) == []
