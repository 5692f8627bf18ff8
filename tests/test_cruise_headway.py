"""A TimeHeadwayCondition as a guard of quiet stretches: whether its target is ahead of the road user
(along its heading) and, while the road user's speed holds, its distance against ``value`` times that
speed are worked out by the core every step; the core stops before the step that would change either.
Before, the condition held no quiet step at all, and a cut-in watched by one ran step by step.

Checked as tests/test_cruise_distances.py checks the distance guards: the run equals the stepped
interpreter's bit for bit while the core takes most steps in few stretches, on the arc road (frames that
turn); and the event fires on the step after the headway, worked out here from the recorded trace, first
falls below its value, including where it falls there because the target comes out ahead.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_cruise import _entity, assert_identical
from test_cruise_distances import _run_both, assert_guarded_run, scenario

from vei_scenario.interpreter import run_scenario


def _headway(target: str, value: float, rule: str, extra: str = "", who: str = "Ego") -> str:
    return _entity(
        f'<TimeHeadwayCondition entityRef="{target}" value="{value}" freespace="false" rule="{rule}" {extra}/>', who
    )


CASES = {
    # (the Ego at 13 m/s closing on the Lead at 8 m/s, 55 m ahead at first)
    "lead_euclidean": _headway("Lead", 2.0, "lessThan"),
    "lead_euclidean_alongRoute_1_0": _headway("Lead", 2.0, "lessThan", 'alongRoute="true"'),
    "lead_boxes": _headway("Lead", 1.5, "lessOrEqual").replace('freespace="false"', 'freespace="true"'),
    "lead_longitudinal_entity": _headway(
        "Lead", 1.2, "lessThan", 'coordinateSystem="entity" relativeDistanceType="longitudinal"'
    ),
    # (along the road: a distance the core does not work out; bounded by how fast it can change)
    "lead_along_road": _headway("Lead", 1.8, "lessThan", 'coordinateSystem="road" relativeDistanceType="longitudinal"'),
    "lead_greater_falling": (_headway("Lead", 2.5, "greaterThan"), "falling"),
    # (Other, on lane -2 at 11 m/s, 15 m ahead of the Ego at first: the Ego comes out ahead of it at about
    # 7.5 s, and from then on Other has a headway to the Ego, some 3.5 m across at 11 m/s)
    "other_sees_ego_come_ahead": _headway("Ego", 1.0, "lessThan", who="Other"),
}
#: The same between the boxes: a headway of 0 as soon as they overlap along the way, before the Ego's
#: reference point is ahead (stepped while the Ego is behind, so that it fires on its step).
BOXES_ALONGSIDE = _headway(
    "Ego", 1.0, "lessThan", 'coordinateSystem="entity" relativeDistanceType="longitudinal"', who="Other"
).replace('freespace="false"', 'freespace="true"')


@pytest.mark.parametrize("case", sorted(CASES))
def test_headway_guards_equal_the_stepped_run_in_few_stretches(tmp_path, monkeypatch, case):
    # (along the road the stretches shorten as the gap closes: a few dozen, not one per step)
    assert_guarded_run(tmp_path, monkeypatch, case, CASES[case], 40 if case == "lead_along_road" else 15)


def _headway_from_trace(a, b, k: int) -> float:
    """TimeHeadwayCondition's quantity at sample k, worked out here from the trace: the distance between
    the reference points over a's speed; infinite where b is not ahead of a along a's heading."""
    c, s = math.cos(a.yaw[k]), math.sin(a.yaw[k])
    dx, dy = b.x[k] - a.x[k], b.y[k] - a.y[k]
    if c * dx + s * dy <= 0 or a.speed[k] <= 1e-9:
        return math.inf
    return math.hypot(dx, dy) / a.speed[k]


FIRINGS = [("lead_euclidean", "Ego", "Lead", 2.0), ("other_sees_ego_come_ahead", "Other", "Ego", 1.0)]


def test_between_boxes_a_target_alongside_has_a_headway_of_zero(tmp_path, monkeypatch):
    """esmini 3.6's signed free-space distance: a target whose box is behind with a gap has no headway,
    one whose box overlaps along the way has a headway of 0. The event fires on the step after the
    Ego's box (coming from behind on the next lane) first reaches Other's, worked out here from the
    trace; before, vei waited until the Ego's reference point was ahead (about 1.4 s later; measured
    against esmini on a scenariogeneration cut-in, 11.6 m apart, now within 0.4 mm)."""
    r, _, _, stepped = _run_both(scenario(tmp_path, BOXES_ALONGSIDE), monkeypatch)
    assert_identical(r, stepped)
    other, ego = r.traces["Other"], r.traces["Ego"]
    c, s = np.cos(other.yaw), np.sin(other.yaw)
    along = c * (ego.x - other.x) + s * (ego.y - other.y)  # (same boxes: centre offsets cancel)
    turn = ego.yaw - other.yaw
    half = 0.5 * (4.5 + 4.5 * np.abs(np.cos(turn)) + 1.8 * np.abs(np.sin(turn)))
    reached = int(np.argmax(along > -half))  # (behind with a gap until then)
    slowed = int(np.argmax(np.isclose(ego.speed, 5.0)))
    assert along[reached - 1] <= -half[reached - 1] and slowed == reached + 1, (reached, slowed)
    assert along[reached] < 0  # (its reference point still behind: before, no headway yet)


@pytest.mark.parametrize(("case", "who", "target", "value"), FIRINGS)
def test_the_event_fires_on_the_step_after_the_headway_falls_below(tmp_path, case, who, target, value):
    r = run_scenario(scenario(tmp_path, CASES[case]))
    a, b, ego = r.traces[who], r.traces[target], r.traces["Ego"]
    headway = np.array([_headway_from_trace(a, b, k) for k in range(len(r.t))])
    first = int(np.argmax(headway < value))
    slowed = int(np.argmax(np.isclose(ego.speed, 5.0)))
    assert headway[first - 1] >= value > headway[first] and slowed == first + 1, (first, slowed)
    if who == "Other":  # (it fell below because the Ego came out ahead: an instant before, no headway)
        assert math.isinf(headway[first - 1]) and headway[first] < 0.5
