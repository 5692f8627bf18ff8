"""Quiet steps taken by the core in one call (interpreter/cruise.py) give the run the interpreter gives
step by step, bit for bit: on a curved road, with every kind of condition that says how long it holds,
with delays and edges, and where the cruise must stop (a collision, a road's end, the time limit).

The reference is the same interpreter with the cruise switched off; each scenario also checks that
its event did fire (the comparison has something to compare) and, where the conditions allow it,
that most steps were cruised (the comparison is not vacuous)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from xosc_parts import CAR, step_speed

import vei_scenario.interpreter.engine as engine
from vei_scenario.interpreter import run_scenario
from vei_scenario.interpreter.conditions import STEADY, steps_before

K = 0.01  # the arc's curvature (a 100 m radius: a car at 15 m/s turns 0.15 rad/s)
ARC = 150.0
X2, Y2 = 100.0 + math.sin(K * ARC) / K, (1.0 - math.cos(K * ARC)) / K

ROAD = f"""<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="{100 + ARC + 120}" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry>
<geometry s="100" x="100" y="0" hdg="0" length="{ARC}"><arc curvature="{K}"/></geometry>
<geometry s="{100 + ARC}" x="{X2}" y="{Y2}" hdg="{K * ARC}" length="120"><line/></geometry></planView>
<lanes><laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
</left><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"""


def _lane(name: str, lane: int, s: float, speed: float) -> str:
    return (
        f'<Private entityRef="{name}"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" '
        f'laneId="{lane}" s="{s}" offset="0"/></Position></TeleportAction></PrivateAction>{step_speed(speed)}</Private>'
    )


def _entity(cond: str, who: str = "Ego") -> str:
    return (
        '<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any">'
        f'<EntityRef entityRef="{who}"/></TriggeringEntities><EntityCondition>{cond}</EntityCondition>'
        "</ByEntityCondition>"
    )


def _event(name: str, actor: str, speed: float, condition: str, delay: float, edge: str) -> str:
    return (
        f'<ManeuverGroup maximumExecutionCount="1" name="{name}g"><Actors selectTriggeringEntities="false">'
        f'<EntityRef entityRef="{actor}"/></Actors><Maneuver name="{name}m"><Event name="{name}" priority="override">'
        f'<Action name="{name}a">{step_speed(speed)}</Action><StartTrigger><ConditionGroup>'
        f'<Condition name="{name}c" delay="{delay}" conditionEdge="{edge}">{condition}</Condition>'
        "</ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>"
    )


def scenario(tmp_path, condition: str, delay: float = 0.0, edge: str = "none", end: float = 14.0, lead_speed=8.0):
    """Ego (15 m/s) behind Lead on lane -1 of a road with a 100 m radius arc, Other on lane -2 and
    Oncoming on lane 1; Lead stops at 4 s; Ego slows to 5 m/s when ``condition`` fires."""
    (tmp_path / "arc.xodr").write_text(ROAD)
    names = ("Ego", "Lead", "Other", "Oncoming")
    stop_lead = _event("LeadStops", "Lead", 0.0, '<ByValueCondition><SimulationTimeCondition value="4" '
                       'rule="greaterThan"/></ByValueCondition>', 0.0, "rising")  # fmt: skip
    init = f"{_lane('Ego', -1, 10, 15)}{_lane('Lead', -1, 70, lead_speed)}{_lane('Other', -2, 30, 12)}"
    init += _lane("Oncoming", 1, 330, 9)
    xosc = tmp_path / "s.xosc"
    xosc.write_text(on_arc(names, init, _event("Change", "Ego", 5.0, condition, delay, edge) + stop_lead, end))
    return xosc


def on_arc(names, init: str, events: str, end: float, others: str = "") -> str:
    """A scenario on arc.xodr: cars ``names`` (and the ScenarioObjects ``others``), the Init actions
    ``init``, one act of ``events`` started at once, stopped after ``end`` seconds."""
    return f"""<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork><LogicFile filepath="arc.xodr"/></RoadNetwork>
<Entities>{"".join(f'<ScenarioObject name="{n}">{CAR}</ScenarioObject>' for n in names)}{others}</Entities>
<Storyboard><Init><Actions>{init}</Actions></Init>
<Story name="s"><Act name="a">{events}
<StartTrigger><ConditionGroup><Condition name="go" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup>
</StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="{end}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup>
</StopTrigger></Storyboard></OpenSCENARIO>"""


def run_both(path, monkeypatch, **kw):
    """(run with quiet steps, steps the core took, run step by step)."""
    taken = []
    original = engine.cruise

    def counting(*args):
        n = original(*args)
        taken.append(n)
        return n

    monkeypatch.setattr(engine, "cruise", counting)
    fast = run_scenario(path, **kw)
    monkeypatch.setattr(engine, "cruise", lambda *args: 0)
    slow = run_scenario(path, **kw)
    monkeypatch.setattr(engine, "cruise", original)
    return fast, sum(taken), slow


def assert_identical(a, b) -> None:
    assert np.array_equal(a.t, b.t)
    assert a.collisions == b.collisions and a.end_reason == b.end_reason
    for name, ta in a.traces.items():
        tb = b.traces[name]
        for field in ("x", "y", "yaw", "speed", "accel"):
            assert np.array_equal(getattr(ta, field), getattr(tb, field)), (name, field)
        assert ta.status == tb.status, name


FIXED_POINT = '<Position><LanePosition roadId="1" laneId="-1" s="150" offset="0"/></Position>'
CASES = {
    "time": '<ByValueCondition><SimulationTimeCondition value="3.333" rule="greaterThan"/></ByValueCondition>',
    "time_equal": '<ByValueCondition><SimulationTimeCondition value="2.5" rule="equalTo"/></ByValueCondition>',
    "traveled": _entity('<TraveledDistanceCondition value="47.77"/>'),
    "reach": _entity(f'<ReachPositionCondition tolerance="1.5">{FIXED_POINT}</ReachPositionCondition>'),
    "distance_cartesian": _entity(
        f'<DistanceCondition value="6.5" freespace="false" rule="lessThan">{FIXED_POINT}</DistanceCondition>'
    ),
    "distance_road": _entity(
        '<DistanceCondition value="9" freespace="true" rule="lessThan" coordinateSystem="road" '
        f'relativeDistanceType="longitudinal">{FIXED_POINT}</DistanceCondition>'
    ),
    "relative_freespace": _entity(
        '<RelativeDistanceCondition entityRef="Lead" relativeDistanceType="cartesianDistance" value="12.3" '
        'freespace="true" rule="lessThan"/>'
    ),
    "relative_longitudinal": _entity(
        '<RelativeDistanceCondition entityRef="Lead" relativeDistanceType="longitudinal" value="20" '
        'freespace="false" rule="lessThan" coordinateSystem="entity"/>'
    ),
    "relative_lateral": _entity(
        '<RelativeDistanceCondition entityRef="Other" relativeDistanceType="lateral" value="3.2" '
        'freespace="false" rule="lessThan" coordinateSystem="entity"/>'
    ),
    "relative_along_road": _entity(
        '<RelativeDistanceCondition entityRef="Lead" relativeDistanceType="longitudinal" value="15" '
        'freespace="true" rule="lessOrEqual" coordinateSystem="road"/>'
    ),
    "standstill": _entity('<StandStillCondition duration="1.5"/>', who="Lead"),
    "heading": _entity(
        '<AngleCondition angleType="heading" angle="0.6" angleTolerance="0.05" coordinateSystem="entity"/>'
    ),
    "relative_heading": _entity(
        '<RelativeAngleCondition entityRef="Other" angleType="heading" angle="0.2" angleTolerance="0.01" '
        'coordinateSystem="entity"/>'
    ),
    "element_state": '<ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" '
    'storyboardElementRef="LeadStops" state="endTransition"/></ByValueCondition>',
    "speed_of_other": _entity('<SpeedCondition value="1" rule="lessThan"/>', who="Lead"),
    "headway": _entity(
        '<TimeHeadwayCondition entityRef="Lead" value="1.2" freespace="true" rule="lessThan" '
        'coordinateSystem="entity" relativeDistanceType="longitudinal"/>'
    ),
}
#: conditions that cannot tell how long they hold: the run is stepped, and must still be the same
UNTOLD = {"headway"}
#: a lateral distance to a road user far behind on a curve changes quickly (the frame turns): fewer
PARTLY = {"relative_lateral": 0.3}


TIMINGS = [(0.0, "none"), (0.37, "none"), (0.0, "rising"), (0.5, "risingOrFalling"), (1e-12, "none")]


@pytest.mark.parametrize("timing", TIMINGS)
@pytest.mark.parametrize("case", sorted(CASES))
def test_quiet_steps_equal_the_stepped_run(tmp_path, monkeypatch, case, timing):
    delay, edge = timing
    fast, cruised, slow = run_both(scenario(tmp_path, CASES[case], delay, edge), monkeypatch)
    assert_identical(fast, slow)
    ego = fast.traces["Ego"]
    fired = np.flatnonzero(np.isclose(ego.speed, 5.0))
    if edge == "none" or case not in ("time_equal",):  # (an equality holds one step: no edge to see)
        assert fired.size, f"{case}: the event never fired"
    if case not in UNTOLD:
        share = PARTLY.get(case, 0.5)
        assert cruised > share * len(fast.t), f"{case}: only {cruised} of {len(fast.t)} steps cruised"


def test_a_collision_ends_a_cruise_where_the_stepped_run_sees_it(tmp_path, monkeypatch):
    never = '<ByValueCondition><SimulationTimeCondition value="99" rule="greaterThan"/></ByValueCondition>'
    fast, cruised, slow = run_both(scenario(tmp_path, never, lead_speed=3.0), monkeypatch)
    assert_identical(fast, slow)
    assert fast.collisions and fast.collisions[0][1:] == ("Ego", "Lead")
    assert cruised > 0.5 * len(fast.t)
    contact = _entity('<CollisionCondition><EntityRef entityRef="Lead"/></CollisionCondition>')
    fast, _, slow = run_both(scenario(tmp_path, contact, 0.25, "none", lead_speed=3.0), monkeypatch)
    assert_identical(fast, slow)


def test_the_road_end_and_the_time_limit_end_cruises_as_steps_do(tmp_path, monkeypatch):
    never = '<ByValueCondition><SimulationTimeCondition value="99" rule="greaterThan"/></ByValueCondition>'
    path = scenario(tmp_path, never, end=60.0)  # everyone reaches an end of the road and stands there
    fast, cruised, slow = run_both(path, monkeypatch, max_time_s=31.234)
    assert_identical(fast, slow)
    assert fast.t[-1] == pytest.approx(31.24) and fast.traces["Ego"].speed[-1] == 0.0
    assert cruised > 0.5 * len(fast.t)


def test_steps_before_a_threshold():
    assert steps_before(1.0, 0.1) == 9  # ten steps could reach it: nine are certain
    assert steps_before(0.0, 0.1) == 0 and steps_before(-1.0, 0.1) == 0 and steps_before(math.nan, 0.1) == 0
    assert steps_before(1.0, 0.0) == STEADY and steps_before(math.inf, 0.1) == STEADY


@pytest.mark.parametrize("dt", [0.01, 0.005, 1 / 60, 0.033, 0.1, 0.0123456789])
def test_the_clock_gives_every_step_its_rounded_time(dt):
    from vei_scenario.interpreter import clock

    for first, stop in ((0, 10), (7, 5000), (4000, 9000), (clock.KEPT_STEPS - 3, clock.KEPT_STEPS + 4), (0, 0)):
        assert clock.step_times(first, stop, dt) == [round(k * dt, 9) for k in range(first, stop)]
    assert clock.step_time(123457, dt) == round(123457 * dt, 9)


def test_standing_lane_keepers_step_as_the_full_step_would(tmp_path, monkeypatch):
    """A road user standing in its lane skips the lane-keeping step once a step left it where it was
    (engine._move): the run equals the one without that shortcut, through standing, being teleported
    while standing, and driving off again."""
    time_at = '<ByValueCondition><SimulationTimeCondition value="{}" rule="greaterThan"/></ByValueCondition>'
    xosc = scenario(tmp_path, time_at.format(3.333), lead_speed=0.0)
    teleport = (
        '<ManeuverGroup maximumExecutionCount="1" name="tg"><Actors selectTriggeringEntities="false"><EntityRef '
        'entityRef="Other"/></Actors><Maneuver name="tm"><Event name="t" priority="override"><Action name="ta">'
        '<PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-2" s="190.5" offset="0.4"/>'
        '</Position></TeleportAction></PrivateAction></Action><StartTrigger><ConditionGroup><Condition name="tc" '
        f'delay="0" conditionEdge="none">{time_at.format(6)}</Condition></ConditionGroup></StartTrigger></Event>'
        "</Maneuver></ManeuverGroup>"
    )
    extra = _event("OtherStops", "Other", 0.0, time_at.format(2), 0.0, "rising")
    extra += _event("LeadGoes", "Lead", 6.0, time_at.format(9), 0.0, "rising")
    extra += _event("OtherGoes", "Other", 4.0, time_at.format(11), 0.0, "rising") + teleport
    go = '<StartTrigger><ConditionGroup><Condition name="go"'
    xosc.write_text(xosc.read_text().replace(go, extra + go, 1))
    parked = []
    original = engine._parked

    def counting(e):
        key = original(e)
        parked.append(key is not None and e.speed == 0.0)
        return key

    monkeypatch.setattr(engine, "cruise", lambda *args: 0)  # (quiet stretches would take most steps)
    monkeypatch.setattr(engine, "_parked", counting)
    fast = run_scenario(xosc)
    monkeypatch.setattr(engine, "_parked", lambda e: None)
    slow = run_scenario(xosc)
    assert_identical(fast, slow)
    assert sum(parked) > 300  # the shortcut was taken
    other, lead = fast.traces["Other"], fast.traces["Lead"]
    i = int(np.searchsorted(fast.t, 6.05))
    assert other.speed[i] == 0.0 and abs(other.x[i] - other.x[i - 10]) > 50  # teleported while standing
    assert lead.speed[-1] == 6.0 and lead.x[-1] > lead.x[int(np.searchsorted(fast.t, 9.0))] + 10


def test_quiet_stretches_run_on_after_a_road_user_is_deleted(tmp_path, monkeypatch):
    """A deleted road user neither moves nor has a transition in the core: the stretches go on (the
    Oncoming car deleted at 1 s, the Ego's change on a time condition)."""
    path = scenario(tmp_path, CASES["time"])
    delete = (
        '<ManeuverGroup maximumExecutionCount="1" name="dg"><Actors selectTriggeringEntities="false"/>'
        '<Maneuver name="dm"><Event name="del" priority="parallel"><Action name="da"><GlobalAction>'
        '<EntityAction entityRef="Oncoming"><DeleteEntityAction/></EntityAction></GlobalAction></Action>'
        '<StartTrigger><ConditionGroup><Condition name="dc" delay="0" conditionEdge="none"><ByValueCondition>'
        '<SimulationTimeCondition value="1" rule="greaterOrEqual"/></ByValueCondition></Condition>'
        "</ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>"
    )
    path.write_text(
        path.read_text().replace('<Story name="s"><Act name="a">', f'<Story name="s"><Act name="a">{delete}')
    )
    fast, cruised, slow = run_both(path, monkeypatch)
    assert_identical(fast, slow)
    assert fast.traces["Oncoming"].status[-1] == "deleted"
    after = int(np.searchsorted(fast.t, 1.5))
    assert cruised > 0.5 * (len(fast.t) - after), f"only {cruised} of {len(fast.t)} steps cruised"
