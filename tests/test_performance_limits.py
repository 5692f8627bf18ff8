"""A vehicle's Performance bounds what the speed actions ask of it, as esmini 3.6 plays it (each case
measured there first, and compared with it here when esmini is beside the checkout):

* a SpeedAction's target speed is held within maxSpeed, either way (a MiscObject, which esmini gives
  no performance, is not moved by one; a pedestrian, which has no Performance, is not held);
* a continuous RelativeTargetSpeed, once its transition is over, follows its reference at no more
  than maxAcceleration/maxDeceleration; one at a rate keeps that rate while the reference changes;
* a SpeedProfileAction's limits are the constraints' within the Performance, and a target its time
  would reach faster than they allow is reached as fast as they allow;
* an untimed FollowTrajectoryAction started during the run starts where the trajectory starts.
"""

from __future__ import annotations

import numpy as np
import pytest
from roads import straight_500m
from test_cruise import assert_identical, run_both
from test_cruise_lateral import _event as event_when
from test_cruise_lateral import _time as time_passed
from xosc_parts import speed_action, speed_to

from vei_scenario.interpreter import run_scenario

ROAD = straight_500m()
DT = 0.01
LANE_Y = -1.535  # (lane -1's centre on the straight road)


def _relative(ref: str, delta: float, **kw) -> str:
    return speed_to(
        f'<RelativeTargetSpeed entityRef="{ref}" value="{delta}" speedTargetValueType="delta" continuous="true"/>',
        **kw,
    )


def _object(name: str, kind: str = "car", perf: str = 'maxSpeed="10" maxAcceleration="5" maxDeceleration="8"') -> str:
    box = '<BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="2" length="4.5" height="1.5"/></BoundingBox>'
    if kind == "pedestrian":
        body = f'<Pedestrian name="p" mass="80" pedestrianCategory="pedestrian">{box}<Properties/></Pedestrian>'
    elif kind == "misc":
        body = f'<MiscObject name="m" mass="80" miscObjectCategory="obstacle">{box}<Properties/></MiscObject>'
    else:
        body = (
            f'<Vehicle name="v" vehicleCategory="car"><Performance {perf}/>{box}<Axles>'
            '<FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.8" positionX="2.8" positionZ="0.3"/>'
            '<RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.8" positionX="0" positionZ="0.3"/>'
            "</Axles><Properties/></Vehicle>"
        )
    return f'<ScenarioObject name="{name}">{body}</ScenarioObject>'


def _event(name: str, actor: str, action: str, at: float) -> str:
    """A maneuver group of its own whose event starts ``action`` on ``actor`` once ``at`` s have passed."""
    return event_when(name, actor, action, time_passed(at))


def _scenario(tmp_path, objects: str, init: dict[str, tuple[float, float, str]], events: str, end: float) -> object:
    """``init``: entity -> (x, speed, more Init actions) on lane -1 of the 500 m straight road."""
    network = f'<LogicFile filepath="{ROAD}"/>'
    privates = "".join(
        f'<Private entityRef="{n}"><PrivateAction><TeleportAction><Position><WorldPosition x="{x}" y="{LANE_Y}" '
        f'h="0"/></Position></TeleportAction></PrivateAction>{speed_action(v)}{more}</Private>'
        for n, (x, v, more) in init.items()
    )
    text = f"""<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="limits" author="vei"/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork>{network}</RoadNetwork><Entities>{objects}</Entities>
<Storyboard><Init><Actions>{privates}</Actions></Init><Story name="s"><Act name="a">{events}<StartTrigger>
<ConditionGroup><Condition name="go" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition
value="0" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="{end}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup>
</StopTrigger></Storyboard></OpenSCENARIO>
"""
    path = tmp_path / "limits.xosc"
    path.write_text(text)
    return path


def _agrees_with_esmini(esmini_or_none, path, within_m: float) -> None:
    """Where esmini is here, every entity within ``within_m`` of esmini's (same collisions)."""
    if esmini_or_none is None:
        return
    from vei_scenario.conformance.esmini import cross_check

    c = cross_check(esmini_or_none, path, dt=DT)
    assert c.max_deviation_m < within_m, [(e.entity, e.max_deviation_m, e.at_time_s) for e in c.entities]


@pytest.mark.parametrize("target", [15.0, -15.0])
@pytest.mark.parametrize("where", ["init", "event"])
def test_a_speed_action_holds_a_vehicle_within_its_max_speed(tmp_path, esmini_if_here, target, where):
    """maxSpeed 10: a step to ±15 m/s, in Init or at 1 s, gives ±10 m/s, and the car covers 10 m/s' distance."""
    init = {"A": (200.0, target if where == "init" else 5.0, "")}
    events = _event("go", "A", speed_action(target), 1.0) if where == "event" else ""
    path = _scenario(tmp_path, _object("A"), init, events, 4.0)
    a = run_scenario(path, {}, DT).traces["A"]
    late = a.t > 1.05
    assert np.all(a.speed[late] == np.sign(target) * 10.0)
    assert np.max(np.abs(a.speed)) == 10.0
    assert abs(a.x[-1] - a.x[np.argmax(late)]) == pytest.approx(10.0 * (a.t[-1] - a.t[np.argmax(late)]), abs=1e-9)
    _agrees_with_esmini(esmini_if_here, path, 0.01)


def test_a_speed_action_leaves_a_misc_object_standing_and_a_pedestrian_unheld(tmp_path, esmini_if_here):
    """A MiscObject has no Performance and esmini gives it none to move by; a pedestrian has no maxSpeed to keep."""
    objects = _object("Box", "misc") + _object("Walker", "pedestrian")
    init = {"Box": (100.0, 5.0, ""), "Walker": (150.0, 1.0, "")}
    events = _event("push", "Box", speed_action(15.0), 1.0) + _event("run", "Walker", speed_action(15.0), 1.0)
    path = _scenario(tmp_path, objects, init, events, 3.0)
    run = run_scenario(path, {}, DT).traces
    assert np.ptp(run["Box"].x) < 1e-6 and np.all(run["Box"].speed == 0.0)
    assert run["Walker"].speed[-1] == 15.0
    _agrees_with_esmini(esmini_if_here, path, 0.01)


def _follower(tmp_path, follow: str, lead_events: str, perf: str, end: float = 9.0):
    objects = _object("A", perf=perf) + _object("B", perf='maxSpeed="50" maxAcceleration="50" maxDeceleration="50"')
    init = {"A": (20.0, 5.0, ""), "B": (100.0, 10.0, "")}
    return _scenario(tmp_path, objects, init, _event("follow", "A", follow, 1.0) + lead_events, end)


def test_a_continuous_relative_speed_follows_its_reference_within_the_limits(tmp_path, esmini_if_here):
    """A keeps B's speed + 2 m/s: B jumps 10 → 20 m/s at 2 s and 20 → 4 at 5 s; A (maxAcceleration 5,
    maxDeceleration 8, maxSpeed 19) gets there at 5 and 8 m/s², held at 19 m/s meanwhile."""
    lead = _event("up", "B", speed_action(20.0), 2.0) + _event("down", "B", speed_action(4.0), 5.0)
    path = _follower(tmp_path, _relative("B", 2.0), lead, 'maxSpeed="19" maxAcceleration="5" maxDeceleration="8"')
    fast, cruised, slow = run_both(path, pytest.MonkeyPatch())
    assert_identical(fast, slow)  # (the core's quiet steps keep it the same way)
    a, t = fast.traces["A"], fast.t
    dv = np.diff(a.speed[t > 1.05])
    assert dv.max() == pytest.approx(5.0 * DT, abs=1e-9) and dv.min() == pytest.approx(-8.0 * DT, abs=1e-9)
    assert a.speed.max() == 19.0
    assert a.speed[(t > 1.05) & (t < 2.0)] == pytest.approx(12.0)  # (a step transition: at once)
    assert a.speed[-1] == 6.0
    rising = (t > 2.1) & (t < 3.3)
    assert np.diff(a.speed[rising]) == pytest.approx(5.0 * DT, abs=1e-9)  # (12 → 19 takes 1.4 s at 5 m/s²)
    assert cruised > 0.3 * len(t)
    _agrees_with_esmini(esmini_if_here, path, 0.15)  # (esmini's A reacts one step sooner to B's jumps)


def test_a_continuous_relative_speed_at_a_rate_keeps_its_rate(tmp_path, esmini_if_here):
    """A linear transition at 1 m/s² towards B's speed + 2 goes on at 1 m/s² when B's speed jumps midway."""
    lead = _event("up", "B", speed_action(20.0), 2.0)
    follow = _relative("B", 2.0, shape="linear", value=1.0, dimension="rate")
    path = _follower(tmp_path, follow, lead, 'maxSpeed="50" maxAcceleration="5" maxDeceleration="8"')
    a = run_scenario(path, {}, DT).traces["A"]
    t = a.t
    assert np.diff(a.speed[(t > 1.05) & (t < 8.9)]) == pytest.approx(1.0 * DT, abs=1e-9)
    _agrees_with_esmini(esmini_if_here, path, 0.05)


def test_a_kept_distance_with_constraints_keeps_within_the_performance(tmp_path, esmini_if_here):
    """A keeps 20 m behind B with constraints of 10 m/s² and 50 m/s, its Performance 2 m/s² and 12
    m/s: it closes the 80 m gap at 2 m/s², no faster than 12 m/s (placed at the gap without
    constraints, the Performance has no say)."""
    keep = (
        '<PrivateAction><LongitudinalAction><LongitudinalDistanceAction entityRef="B" continuous="true" '
        'distance="20" freespace="false" coordinateSystem="entity" displacement="trailingReferencedEntity">'
        '<DynamicConstraints maxAcceleration="10" maxDeceleration="10" maxSpeed="50"/>'
        "</LongitudinalDistanceAction></LongitudinalAction></PrivateAction>"
    )
    path = _follower(tmp_path, keep, "", 'maxSpeed="12" maxAcceleration="2" maxDeceleration="3"')
    fast, _cruised, slow = run_both(path, pytest.MonkeyPatch())
    assert_identical(fast, slow)
    a = fast.traces["A"]
    late = a.t > 1.05
    assert np.diff(a.speed[late]).max() == pytest.approx(2.0 * DT, abs=1e-9)
    assert a.speed.max() == 12.0
    _agrees_with_esmini(esmini_if_here, path, 0.02)


@pytest.mark.parametrize("limited_by", ["constraints", "performance"])
def test_a_speed_profile_target_beyond_the_limits_is_reached_as_fast_as_they_allow(
    tmp_path, esmini_if_here, limited_by
):
    """15 m/s 1 s after 5 m/s, 18 1 s later, 6 2 s after that, at 3 m/s² up and 4 down (the constraints'
    or the Performance's, whichever is smaller): 15 is reached 10/3 s after the start, 18 1 s later, 6
    3 s after that."""
    small, large = 'maxAcceleration="3" maxDeceleration="4"', 'maxAcceleration="30" maxDeceleration="30"'
    constraints, perf = (small, large) if limited_by == "constraints" else (large, small)
    profile = (
        '<PrivateAction><LongitudinalAction><SpeedProfileAction followingMode="position"><DynamicConstraints '
        f'{constraints} maxSpeed="50"/><SpeedProfileEntry speed="15" time="1"/><SpeedProfileEntry speed="18" '
        'time="1"/><SpeedProfileEntry speed="6" time="2"/></SpeedProfileAction></LongitudinalAction></PrivateAction>'
    )
    objects = _object("A", perf=f'maxSpeed="50" {perf}')
    path = _scenario(tmp_path, objects, {"A": (20.0, 5.0, "")}, _event("p", "A", profile, 1.0), 9.5)
    a = run_scenario(path, {}, DT).traces["A"]
    t0 = 1.01  # (the action starts on the step after 1 s)
    for at, want in ((t0 + 10 / 3, 15.0), (t0 + 10 / 3 + 1, 18.0), (t0 + 10 / 3 + 4, 6.0)):
        assert np.interp(at, a.t, a.speed) == pytest.approx(want, abs=0.02)
    assert np.diff(a.speed).max() <= 3.0 * DT + 1e-9 and np.diff(a.speed).min() >= -4.0 * DT - 1e-9
    _agrees_with_esmini(esmini_if_here, path, 0.05)


def test_an_untimed_trajectory_started_during_the_run_starts_where_it_starts(tmp_path, esmini_if_here):
    """A at 28 m when a trajectory from 10 m starts: A is at 10 m on the next step, then on along it."""
    trajectory = (
        '<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="t" closed="false">'
        "<Shape><Polyline>"
        + "".join(
            f'<Vertex><Position><WorldPosition x="{x}" y="{LANE_Y}" h="0"/></Position></Vertex>' for x in (10, 55, 85)
        )
        + "</Polyline></Shape></Trajectory></TrajectoryRef><TimeReference><None/></TimeReference>"
        '<TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction></RoutingAction></PrivateAction>'
    )
    path = _scenario(tmp_path, _object("A"), {"A": (20.0, 8.0, "")}, _event("t", "A", trajectory, 1.0), 4.0)
    a = run_scenario(path, {}, DT).traces["A"]
    jump = int(np.argmax(np.diff(a.x) < 0)) + 1
    assert a.t[jump] == pytest.approx(1.02) and a.x[jump] == pytest.approx(10.0 + 8.0 * DT, abs=1e-9)
    assert a.x[-1] == pytest.approx(10.0 + 8.0 * (a.t[-1] - a.t[jump - 1]), abs=1e-9)
    _agrees_with_esmini(esmini_if_here, path, 0.01)


def test_limits_of_zero_leave_the_speed_as_it_is(tmp_path, esmini_if_here):
    """maxAcceleration and maxDeceleration 0: a linear SpeedAction never gets going (esmini 3.6), nor
    does a continuous relative one; a kept distance with maxSpeed 0 stands, written as 0, never -0."""
    from vei_scenario.runner import trajectories_csv

    perf = 'maxSpeed="10" maxAcceleration="0" maxDeceleration="0"'
    path = _follower(tmp_path, speed_action(3.0, "linear", 1.0), "", perf)
    a = run_scenario(path, {}, DT).traces["A"]
    assert np.all(a.speed == 5.0)
    _agrees_with_esmini(esmini_if_here, path, 0.01)
    lead = _event("up", "B", speed_action(20.0), 2.0)
    path = _follower(tmp_path, _relative("B", 2.0, shape="linear", value=2.0, dimension="rate"), lead, perf)
    assert np.all(run_scenario(path, {}, DT).traces["A"].speed == 5.0)
    keep = (
        '<PrivateAction><LongitudinalAction><LongitudinalDistanceAction entityRef="B" continuous="true" '
        'distance="20" freespace="false" coordinateSystem="entity" displacement="trailingReferencedEntity">'
        '<DynamicConstraints maxAcceleration="10" maxDeceleration="10" maxSpeed="50"/>'
        "</LongitudinalDistanceAction></LongitudinalAction></PrivateAction>"
    )
    objects = _object("A", perf='maxSpeed="0" maxAcceleration="0" maxDeceleration="0"') + _object("B")
    path = _scenario(
        tmp_path, objects, {"A": (20.0, 0.0, ""), "B": (100.0, 10.0, "")}, _event("k", "A", keep, 1.0), 3.0
    )
    result = run_scenario(path, {}, DT)
    assert np.all(result.traces["A"].speed == 0.0)
    assert "-0.000000" not in trajectories_csv(result)
