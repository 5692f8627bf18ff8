"""RelativeClearanceCondition (OpenSCENARIO 1.2) on test_cruise's road: Ego (15 m/s, lane -1, s = 10)
closes on Other (12 m/s, lane -2, s = 30) at 3 m/s; the lane to Ego's right is clear while Other is
more than ``distanceForward`` ahead along the road. The firing step is worked out from the speeds, not
from the code; lane ranges reaching past the road's lanes read as far as there are lanes (a range of a
million lanes found by a mutation fuzz took minutes a step before)."""

from __future__ import annotations

import time

import numpy as np
import pytest
from test_cruise import _entity, scenario

from vei_scenario.interpreter import run_scenario


def _clearance(lanes: str, forward: float = 5.5, extra: str = "") -> str:
    return _entity(
        f'<RelativeClearanceCondition distanceForward="{forward}" distanceBackward="5" freeSpace="false" '
        f'oppositeLanes="false" {extra}>{lanes}</RelativeClearanceCondition>'
    )


def _slowed_at(run) -> float | None:
    """When Ego's speed first drops below its 15 m/s (the event's step speed of 5 m/s)."""
    ego = run.traces["Ego"]
    below = np.nonzero(ego.speed < 14.0)[0]
    return float(run.t[below[0]]) if below.size else None


def test_the_lane_to_the_right_stops_being_clear_when_other_comes_within_reach(tmp_path):
    right = '<RelativeLaneRange from="-1" to="-1"/>'
    run = run_scenario(scenario(tmp_path, _clearance(right), edge="falling", end=8.0))
    # Other's gap along the road, 20 - 3 t, reaches 5.5 m at t = 4.8333 s: the first step at or past it
    # is 4.84 s, and the new speed shows on the step after
    assert _slowed_at(run) == pytest.approx(4.85, abs=1e-9)


@pytest.mark.parametrize(
    "lanes",
    [
        '<RelativeLaneRange from="-1000000" to="-1"/>',  # (every lane to the right, and a million more)
        '<RelativeLaneRange from="-1" to="-1"/><RelativeLaneRange from="-7" to="-3"/>',  # (lanes the road lacks)
    ],
)
def test_ranges_past_the_roads_lanes_read_the_lanes_there_are(tmp_path, lanes):
    reference = run_scenario(scenario(tmp_path, _clearance('<RelativeLaneRange from="-1" to="-1"/>'), edge="falling"))
    started = time.perf_counter()
    run = run_scenario(scenario(tmp_path, _clearance(lanes), edge="falling"))
    assert time.perf_counter() - started < 30.0  # (minutes before: a million lanes looked at every step)
    assert _slowed_at(run) == _slowed_at(reference) == pytest.approx(4.85, abs=1e-9)
    assert np.array_equal(run.traces["Ego"].x, reference.traces["Ego"].x)


def test_lanes_the_other_way_count_only_with_opposite_lanes(tmp_path):
    """Lane 1 (to Ego's left) runs the other way: without ``oppositeLanes`` there is no lane to be clear
    and the condition never holds; with it, Oncoming is 320 m ahead and the lane is clear at once."""
    left = '<RelativeLaneRange from="1" to="1"/>'
    never = run_scenario(scenario(tmp_path, _clearance(left), end=3.0))
    assert _slowed_at(never) is None
    opposite = _clearance(left).replace('oppositeLanes="false"', 'oppositeLanes="true"')
    at_once = run_scenario(scenario(tmp_path, opposite, end=3.0))
    assert _slowed_at(at_once) == 0.0  # (the storyboard is evaluated once before t = 0 is logged)
