"""An overtake by a road user faster than a moving ego, played as its layers say:

* one that comes up behind the ego in its lane starts at the ego's speed and speeds up as it pulls
  out: closing in on the ego's tail it was, to the ego's planner, about to run into it, and the ego
  braked hard (and was run into, or passed before the pull-out was over, and the cut back in and a
  cut-in after it never came);
* the watch for the overtaker drawing level starts with its pull-out, so one that draws level while
  it is still pulling out (or speeding up in the next lane) still cuts back in ahead of the ego.

Each sentence is read, written, played with vei run's interpreter and checked with
:func:`~vei_scenario.language.corpus_check.played_problems`; the guards keep what already played."""

from __future__ import annotations

import numpy as np
import pytest
from play_layers import play_layers

from vei_scenario.language.behaviours import overtake
from vei_scenario.language.corpus_check import _ego_frame, played_problems
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text

FASTER_FROM_BEHIND = [
    "On a straight two-lane road the ego travels at 60 km/h; a car at 80 km/h overtakes it and then cuts in "
    "in front of it.",
    "The ego cruises at 90 km/h on a straight road. A car from behind overtakes it at 112 km/h and then cuts "
    "in sharply.",
    "The ego is driving at 50 km/h on a straight road. A sports car doing 75 km/h overtakes it from behind and pulls "
    "back in just ahead.",
]


def _names(adv: dict) -> list[str]:
    return [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])]


@pytest.mark.parametrize("text", FASTER_FROM_BEHIND)
def test_a_faster_overtaker_behind_a_moving_ego_passes_and_gets_back_in_ahead(text, tmp_path):
    layers = layers_from_text(text, 0)
    ego_speed = float(layers["ego"]["speed_mps"])
    [adv] = layers["adversaries"]
    assert _names(adv)[0] == "overtake"
    assert adv["spawn"]["relation"] == "behind"
    assert float(adv["speed_mps"]) > ego_speed + 1.0
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    lon, lat = _ego_frame(result, adv["name"])
    back_in = (lon > 0) & (np.abs(lat) < 1.2)
    assert back_in.any()
    # the ego does not brake for it as it comes up behind (nor is it run into before it is passed)
    ego = result.traces[result.ego]
    first = int(np.argmax(back_in))
    assert float(ego.speed[:first].min()) > 0.9 * ego_speed
    dt = 1.0 / float(layers["rate_hz"])
    assert not any(adv["name"] in (a, b) and t < first * dt for t, a, b in result.collisions)


def test_an_overtaker_that_draws_level_while_still_speeding_up_still_cuts_back_in(tmp_path):
    """One already in the next lane, close behind and much faster, is level before its speed change
    is over: it cuts back in ahead of the ego all the same."""
    layers = layers_from_text(
        "The ego drives at 30 km/h in the right lane of a straight road with two lanes each way. "
        "A car in the lane to its left, doing 70 km/h, overtakes it and cuts in ahead.",
        0,
    )
    [adv] = layers["adversaries"]
    assert _names(adv) == ["overtake"] and adv["spawn"]["relation"] == "left"
    adv["spawn"]["longitudinal_m"] = -8.0
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    lon, lat = _ego_frame(result, adv["name"])
    assert ((lon > 0) & (np.abs(lat) < 1.2)).any()


@pytest.mark.parametrize(
    ("ego_speed", "speed", "relation", "start"),
    [
        (20.0, 26.0, "behind", 20.0),  # behind a moving ego, faster: pulls out at the ego's speed first
        (20.0, 20.0, "behind", 20.0),  # guard: at the ego's speed, as before
        (20.0, 15.0, "behind", 15.0),  # guard: slower (it is the ego that comes up): its own
        (0.0, 6.0, "behind", 6.0),  # guard: past a standing ego it filters from far back at its speed
        (20.0, 26.0, "left", 26.0),  # guard: already in the next lane, it is in no one's way
        (20.0, 26.0, "oncoming", 26.0),  # guard: coming the other way
    ],
)
def test_start_speed(ego_speed, speed, relation, start):
    assert overtake.start_speed(ego_speed, speed, relation) == start


def test_an_overtaker_at_the_ego_s_speed_still_plays_as_before(tmp_path):
    layers = layers_from_text("The ego is driving at 60 km/h on a straight road. A van overtakes it.", 0)
    [adv] = layers["adversaries"]
    assert float(adv["speed_mps"]) == pytest.approx(float(layers["ego"]["speed_mps"]))
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert float(result.traces[adv["name"]].speed[0]) == pytest.approx(float(adv["speed_mps"]), abs=0.05)
    assert not result.collisions
