"""Distance conditions as guards of quiet stretches: a RelativeDistanceCondition or a DistanceCondition
(cartesian, longitudinal or lateral; between reference points or boxes) is worked out by the core every
step, and the core stops before the step that would change its comparison, or leave the distance within
a micrometre of the threshold (where the core's arithmetic and the interpreter's could differ in the
last bits). Before, such a condition bounded a stretch by how fast the distance could change at most,
which cut an approach into dozens of ever shorter stretches.

Checked three ways: the run equals the stepped interpreter's bit for bit (tests/test_cruise.py's
``run_both``) while the stretches are few; the core alone stops where the analytic distance crosses its
threshold; and the event fires on the step after the distance, measured independently from the
recorded trace, first crosses it."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_cruise import ROAD, _entity, _event, _lane, assert_identical, on_arc
from test_cruise_sync import PEDESTRIAN

import vei_scenario.interpreter.engine as engine
from vei_scenario.core import _core, layout
from vei_scenario.interpreter import run_scenario

#: A walker crossing the road ahead of the Ego at an angle (its box turned against the Ego's), on a
#: trajectory timed so that it is still on the road when the Ego passes.
CROSSING = (
    '<Private entityRef="Walker"><PrivateAction><TeleportAction><Position><WorldPosition x="150" y="-14" '
    'h="1.2"/></Position></TeleportAction></PrivateAction><PrivateAction><RoutingAction><FollowTrajectoryAction>'
    '<TrajectoryRef><Trajectory name="cross" closed="false"><Shape><Polyline>'
    '<Vertex time="0"><Position><WorldPosition x="150" y="-14"/></Position></Vertex>'
    '<Vertex time="6"><Position><WorldPosition x="156" y="-2"/></Position></Vertex>'
    '<Vertex time="16"><Position><WorldPosition x="160" y="20"/></Position></Vertex>'
    '</Polyline></Shape></Trajectory></TrajectoryRef><TimeReference><Timing domainAbsoluteRelative="absolute" '
    'scale="1" offset="0"/></TimeReference><TrajectoryFollowingMode followingMode="position"/>'
    "</FollowTrajectoryAction></RoutingAction></PrivateAction></Private>"
)


def scenario(tmp_path, condition: str, edge: str = "none") -> object:
    """The Ego (13 m/s) on lane -1 of tests/test_cruise.py's road (a 100 m radius arc from 100 m),
    the Lead ahead of it at 8 m/s, Other on lane -2, the Walker crossing; the Ego slows to 5 m/s when
    ``condition`` holds."""
    (tmp_path / "arc.xodr").write_text(ROAD)
    xosc = tmp_path / "d.xosc"
    init = f"{_lane('Ego', -1, 5, 13)}{_lane('Lead', -1, 60, 8)}{_lane('Other', -2, 20, 11)}{CROSSING}"
    walker = f'<ScenarioObject name="Walker">{PEDESTRIAN}</ScenarioObject>'
    change = _event("Change", "Ego", 5.0, condition, 0.0, edge)
    xosc.write_text(on_arc(("Ego", "Lead", "Other"), init, change, 13, walker))
    return xosc


def _relative(target: str, kind: str, freespace: bool, value: float, rule: str) -> str:
    return _entity(
        f'<RelativeDistanceCondition entityRef="{target}" relativeDistanceType="{kind}" value="{value}" '
        f'freespace="{str(freespace).lower()}" rule="{rule}" coordinateSystem="entity"/>'
    )


def _to_point(kind: str, freespace: bool, value: float, rule: str) -> str:
    return _entity(
        f'<DistanceCondition value="{value}" freespace="{str(freespace).lower()}" rule="{rule}" '
        f'relativeDistanceType="{kind}" coordinateSystem="entity"><Position><WorldPosition x="175" y="30" h="0.7"/>'
        "</Position></DistanceCondition>"
    )


CASES = {
    "lead_longitudinal_boxes": _relative("Lead", "longitudinal", True, 7.5, "lessThan"),
    "lead_longitudinal_points": _relative("Lead", "longitudinal", False, 17.0, "lessOrEqual"),
    "lead_cartesian_boxes": _relative("Lead", "cartesianDistance", True, 11.0, "lessThan"),
    "lead_euclidian_points": _relative("Lead", "euclidianDistance", False, 19.0, "lessThan"),
    "other_lateral_boxes": _relative("Other", "lateral", True, 1.6, "lessOrEqual"),
    "other_lateral_points": _relative("Other", "lateral", False, 3.3, "lessThan"),
    "other_longitudinal_greater": (_relative("Other", "longitudinal", True, 6.0, "greaterOrEqual"), "rising"),
    "walker_cartesian_boxes": _relative("Walker", "cartesianDistance", True, 6.0, "lessThan"),
    "walker_lateral_boxes": _relative("Walker", "lateral", True, 3.0, "lessThan"),
    "point_cartesian": _to_point("cartesianDistance", False, 60.0, "lessThan"),
    "point_longitudinal_boxes": _to_point("longitudinal", True, 45.0, "lessOrEqual"),
    "point_lateral": _to_point("lateral", False, 30.0, "lessThan"),
}


def _run_both(path, monkeypatch):
    """(run with quiet stretches, steps the core took, its calls, run step by step)."""
    taken = []
    original = engine.cruise

    def counting(*args):
        n = original(*args)
        if n:
            taken.append(n)
        return n

    monkeypatch.setattr(engine, "cruise", counting)
    fast = run_scenario(path)
    monkeypatch.setattr(engine, "cruise", lambda *args: 0)
    slow = run_scenario(path)
    monkeypatch.setattr(engine, "cruise", original)
    return fast, sum(taken), len(taken), slow


def assert_guarded_run(tmp_path, monkeypatch, case: str, spec, max_calls: int) -> None:
    """The run of :func:`scenario` with ``spec`` (a condition, or (condition, edge)) equals the stepped one
    bit for bit, its condition fired, and the core took most steps in at most ``max_calls`` stretches."""
    condition, edge = spec if isinstance(spec, tuple) else (spec, "none")
    fast, cruised, calls, slow = _run_both(scenario(tmp_path, condition, edge), monkeypatch)
    assert_identical(fast, slow)
    ego = fast.traces["Ego"]
    assert np.any(np.isclose(ego.speed, 5.0)) and ego.speed[0] == 13.0, f"{case}: the condition never fired"
    assert cruised > 0.8 * len(fast.t), f"{case}: only {cruised} of {len(fast.t)} steps cruised"
    assert calls <= max_calls, f"{case}: {calls} stretches"


@pytest.mark.parametrize("case", sorted(CASES))
def test_distance_guards_equal_the_stepped_run_in_few_stretches(tmp_path, monkeypatch, case):
    # the walker's path (three segments), the Lead and Ego leaving the arc, the event: a handful (a distance
    # bounded by its rate cuts an approach in dozens)
    assert_guarded_run(tmp_path, monkeypatch, case, CASES[case], 15)


def _gap_longitudinal(ego, lead, k: int) -> float:
    """The freespace longitudinal distance at sample k, in the Ego's frame (the cars' boxes: 4.5 x 1.8,
    centred 1.4 m ahead of the reference point), worked out here from the trace."""
    c, s = math.cos(ego.yaw[k]), math.sin(ego.yaw[k])
    ax, ay = ego.x[k] + 1.4 * c, ego.y[k] + 1.4 * s
    bx, by = lead.x[k] + 1.4 * math.cos(lead.yaw[k]), lead.y[k] + 1.4 * math.sin(lead.yaw[k])
    d = c * (bx - ax) + s * (by - ay)
    turn = lead.yaw[k] - ego.yaw[k]
    half = 0.5 * (4.5 + 4.5 * abs(math.cos(turn)) + 1.8 * abs(math.sin(turn)))
    return max(abs(d) - half, 0.0)


def test_the_event_fires_on_the_step_after_the_distance_crosses(tmp_path):
    """Not only equal to the stepped run: the Ego slows on the step after the gap to the Lead, worked
    out from the recorded trace, first falls below 7.5 m (on the arc, both cars turning)."""
    from xosc_parts import CAR as car

    assert 'length="4.5"' in car and 'width="1.8"' in car and 'x="1.4"' in car  # (the boxes assumed above)
    r = run_scenario(scenario(tmp_path, CASES["lead_longitudinal_boxes"]))
    ego, lead = r.traces["Ego"], r.traces["Lead"]
    gaps = np.array([_gap_longitudinal(ego, lead, k) for k in range(len(r.t))])
    first = int(np.argmax(gaps < 7.5))
    slowed = int(np.argmax(np.isclose(ego.speed, 5.0)))
    assert gaps[first - 1] >= 7.5 > gaps[first] and slowed == first + 1, (first, slowed, gaps[first - 1 : first + 1])
    assert abs(ego.yaw[first] - ego.yaw[0]) > 0.05  # on the arc: the frame had turned


ROW, GUARD, QUANTITY = layout("road_user"), layout("guard"), layout("guard_quantity")


def _straight(x: float, y: float, yaw: float, speed: float) -> list[float]:
    row = [0.0] * len(ROW)
    values = {"MODE": 0.0, "X": x, "Y": y, "YAW": yaw, "SPEED": speed, "LENGTH": 4.0, "WIDTH": 2.0}
    values |= {"PROFILE": -1.0, "TOW": -1.0, "MAX_MOVE": 10.0, "MAX_DS": 10.0}
    for name, v in values.items():
        row[ROW[name]] = v
    return row


def _core_steps(quantity: str, rule: int, value: float, freespace: bool, n_max: int = 400, other=1) -> int:
    """Steps the core takes of A (8 m/s along x from 0, dt 1/8: a metre a step, exactly) towards B
    (standing at x = 50, y = 3) under one distance guard."""
    state = _straight(0.0, 0.0, 0.0, 8.0) + _straight(50.0, 3.0, 0.0, 0.0)
    guard = [0.0] * len(GUARD)
    values = {"ENTITY": 0.0, "OTHER": float(other), "QUANTITY": float(QUANTITY[quantity]), "RULE": float(rule)}
    values |= {"VALUE": value, "FREESPACE": 1.0 if freespace else 0.0, "POINT_X": 50.0, "POINT_Y": 3.0}
    for name, v in values.items():
        guard[GUARD[name]] = v
    pack = np.asarray
    clock = pack([k / 8 for k in range(n_max)], float).tobytes()
    n, *_ = _core.cruise((None, None), pack(state, float).tobytes(), b"", b"", b"", b"", pack(guard, float).tobytes(),
                         clock, math.inf, 0.125)  # fmt: skip
    return n


def test_the_core_stops_where_the_distance_crosses_and_before_the_margin():
    lt, le, gt = 1, 3, 0  # (conditions.RULE_CODES)
    # longitudinal between reference points: 50 - k after k steps; below 20.5 after step 30
    assert _core_steps("LONGITUDINAL", lt, 20.5, False) == 29
    # between boxes (4 m long): 46 - k; 20 exactly after step 26 is within the margin: stop before it
    assert _core_steps("LONGITUDINAL", le, 20.0, True) == 25
    # 20 after step 26 is above 20 - 5e-7, but within a micrometre of it: the interpreter decides that step
    assert _core_steps("LONGITUDINAL", le, 20.0 - 5e-7, True) == 25
    assert _core_steps("LONGITUDINAL", le, 19.99, True) == 26  # (clear of it: the step that reaches 20 is taken)
    # straight-line distance sqrt((50 - k)^2 + 9) < 10: (50 - k)^2 < 91, k > 40.46
    assert _core_steps("CARTESIAN", lt, 10.0, False) == 40
    # between boxes: the gap along x (50 - k - 4) with a 1 m lateral gap: sqrt((46 - k)^2 + 1) < 5 from k = 42
    assert _core_steps("CARTESIAN", lt, 5.0, True) == 41
    # lateral: 3 m between reference points, never changing; 1 m between the boxes
    assert _core_steps("LATERAL", gt, 2.9, False, n_max=100) == 100
    assert _core_steps("LATERAL", lt, 1.0 + 1e-3, True, n_max=100) == 100
    # to a point (no box) at (50, 3): the longitudinal gap of A's box (2 m half length) is 48 - k
    assert _core_steps("LONGITUDINAL", lt, 10.5, True, other=-1) == 37
    # already within the margin at the start: no step
    assert _core_steps("LONGITUDINAL", lt, 50.0, False) == 0


def test_the_core_refuses_guards_it_does_not_know():
    with pytest.raises(ValueError, match="guard"):
        _core_steps("LONGITUDINAL", 9, 20.0, False)


def _profiled(v0: float, v1: float, duration: float) -> list[float]:
    """A road user standing or driving along x whose speed goes linearly from v0 at t = 0 to v1."""
    row = _straight(0.0, 0.0, 0.0, v0)
    shape = layout("shape")["LINEAR"]
    for name, v in {"PROFILE": shape, "PROFILE_V0": v0, "PROFILE_V1": v1, "PROFILE_DURATION": duration}.items():
        row[ROW[name]] = float(v)
    return row


def _profiled_steps(v0: float, v1: float, start_step: int = 0) -> tuple[int, int]:
    """(steps the core takes, its edge) of one road user under a 2 s linear speed change, from ``start_step``."""
    clock = np.asarray([(start_step + k) / 8 for k in range(40)], float).tobytes()
    state = np.asarray(_profiled(v0, v1, 2.0), float).tobytes()
    n, *_, edge = _core.cruise((None,), state, b"", b"", b"", b"", b"", clock, math.inf, 0.125)
    return n, edge


def test_the_core_says_when_it_stops_before_a_road_user_starts_or_stops():
    """A road user setting off or coming to a standstill is the interpreter's step (it marks when the
    standstill began); the core stops before it and says why (``edge``), so that the engine offers the
    step after it at once (cruise.EDGE_RETRIES)."""
    assert _profiled_steps(0.0, 4.0) == (0, 1)  # (sets off in the first step)
    assert _profiled_steps(0.0, 4.0, start_step=3) == (0, 1)
    # (stands where its transition ends: the end of an action, the interpreter's for that; no edge)
    assert _profiled_steps(4.0, 0.0, start_step=1) == (14, 0)
    assert _profiled_steps(2.0, 4.0, start_step=1) == (14, 0)
