"""Every class of layers the reader can produce plays what it says, whatever the map, the speeds and
the other road users: each test builds layers directly (not from a sentence, so no wording is
favoured), writes and plays them with vei run's interpreter, and checks the trajectories with
:func:`~vei_scenario.language.corpus_check.played_problems`."""

from __future__ import annotations

from pathlib import Path

import pytest

from vei_scenario.interpreter import run_scenario
from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.scenario_writer import write_scenario


def _layers(kind: str, lanes: int, ego: dict, adversaries: list[dict], duration_s: float = 20.0) -> dict:
    """Layers of a scenario on a ``kind`` map with ``lanes`` lanes each way."""
    placement = {"straight": "straight", "curve": "on_curve", "crossroad": "before_junction"}[kind]
    ego = {"placement": placement, "lane": 1, "agent": "cap"} | ego
    if kind != "straight":
        ego.setdefault("distance_m", 60.0)
    return {
        "format": "vei-layers/1",
        "description": "built by a test",
        "seed": 0,
        "intent": "unspecified",
        "duration_s": duration_s,
        "rate_hz": 20,
        "environment": {
            "map": {"kind": kind, "lanes_per_direction": lanes},
            "weather": {"condition": "clear"},
            "time_of_day": "12:00",
            "traffic_density": "none",
        },
        "ego": ego,
        "adversaries": adversaries,
        "background": {"vehicles": []},
    }


def _play(layers: dict, tmp_path: Path) -> list[str]:
    written = write_scenario(layers, "scenario")
    (tmp_path / "scenario.xosc").write_bytes(written.xosc)
    (tmp_path / "scenario.xodr").write_bytes(written.xodr)
    result = run_scenario(tmp_path / "scenario.xosc", None, round(1.0 / float(layers["rate_hz"]), 6))
    return played_problems(result, layers)


@pytest.mark.parametrize("kind", ["straight", "curve"])
@pytest.mark.parametrize("speed", [6.0, 12.0, 20.0])
def test_a_lead_swerving_out_on_a_road_with_one_lane_each_way_goes_into_the_oncoming_lane(kind, speed, tmp_path):
    """With one lane each way a lead has no lane of its own direction to swerve into: it goes round
    what stands in its lane the way drivers do, over the centre line into the oncoming lane."""
    lead_gap = 4.6 + 1.5 * speed
    layers = _layers(
        kind,
        1,
        {"speed_mps": speed},
        [
            {
                "name": "Adversary1",
                "type": "car",
                "spawn": {"relation": "ahead", "longitudinal_m": lead_gap},
                "speed_mps": speed,
                "behaviour": {"behaviour": "cut_out", "config": {"obstacle": "Adversary2", "reveal_ttc_s": 4.0}},
            },
            {
                "name": "Adversary2",
                "type": "car",
                "spawn": {"relation": "ahead", "longitudinal_m": lead_gap + 5.0 * speed + 20.0},
                "speed_mps": 0.0,
                "behaviour": {"behaviour": "stop", "config": {}},
            },
        ],
    )
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_a_lane_change_to_a_side_with_no_lane_of_its_own_direction_is_refused_in_one_line(direction, tmp_path):
    """Near miss: a plain lane change told to go where its road has no lane in its direction is not
    turned into a swerve across the centre line (that is a cut-out's way round an obstacle, not a lane
    change): the writer says which road user and why."""
    layers = _layers(
        "straight",
        1,
        {"speed_mps": 12.0},
        [
            {
                "name": "Adversary1",
                "type": "car",
                "spawn": {"relation": "ahead", "longitudinal_m": 25.0},
                "speed_mps": 12.0,
                "behaviour": {"behaviour": "change_lane", "config": {"direction": direction}},
            }
        ],
    )
    with pytest.raises(ValueError, match="Adversary1 has no lane to the"):
        write_scenario(layers, "scenario")
