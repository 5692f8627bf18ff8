"""Quiet stretches through a running SynchronizeAction and along untimed paths (the Euro NCAP VRU
scenarios' shape): the core sets the synchronised entity's speed each step as the action does and moves
it along its path or lane, and the run equals the interpreter's step by step, bit for bit.

Each case varies the synchronisation (final speed absolute, relative or none; steady state by distance
or time; tolerances; a start at t = 0 before the master moves; a target the entity must linger or rush
to) and adds a condition on the synchronised entity that an event reacts to. The reference is the same
interpreter with the cruise switched off (tests/test_cruise.py's ``run_both``): both take the speed
profile from one C function (core_module.c: sync_speed), the core with its distances along paths and
road programs, the interpreter with its own. The profile's modes the cases pass through are asserted,
and so is the share of steps the core took where the conditions let it."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_cruise import assert_identical, run_both
from xosc_parts import CAR, step_speed

from vei_scenario.interpreter import synchronize

ROAD = """<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="400" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="400"><line/></geometry></planView>
<lanes><laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
</left><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"""

PEDESTRIAN = """<Pedestrian name="p" mass="75" model="ped" pedestrianCategory="pedestrian"><BoundingBox>
<Center x="0" y="0" z="0.9"/><Dimensions width="0.6" length="0.5" height="1.8"/></BoundingBox><Properties/>
</Pedestrian>"""

CROSS_X = 150.0  # where the VRU's path crosses the road (lane -1's centre is at y = -1.75)


def _linked_road(rid: int, x0: float, link: str) -> str:
    """A straight 200 m road from (x0, 0) with ROAD's lanes, each linked to the same lane on either side."""

    def lane(i: int) -> str:
        return (
            f'<lane id="{i}" type="driving"><link><predecessor id="{i}"/><successor id="{i}"/></link>'
            '<width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>'
        )

    return (
        f'<road id="{rid}" length="200" junction="-1"><link>{link}</link><planView><geometry s="0" x="{x0}" y="0" '
        f'hdg="0" length="200"><line/></geometry></planView><lanes><laneSection s="0"><left>{lane(1)}</left>'
        f'<center><lane id="0" type="none"/></center><right>{lane(-1)}{lane(-2)}</right></laneSection></lanes></road>'
    )


#: The same 400 m as two roads of 200 m, the first's end linked to the second's start.
TWO_ROADS = (
    '<OpenDRIVE><header revMajor="1" revMinor="6"/>'
    + _linked_road(1, 0.0, '<successor elementType="road" elementId="2" contactPoint="start"/>')
    + _linked_road(2, 200.0, '<predecessor elementType="road" elementId="1" contactPoint="end"/>')
    + "</OpenDRIVE>"
)


def _lane(lane: int, x: float, split: bool = False) -> str:
    """The position on ``lane`` at ``x`` along the road (on two roads: the second from x = 200)."""
    road, s = (2, x - 200.0) if split and x >= 200.0 else (1, x)
    return f'<LanePosition roadId="{road}" laneId="{lane}" s="{s}" offset="0"/>'


def _follow(points: list[tuple[float, float]]) -> str:
    """Following an untimed polyline through ``points``."""
    vertices = "".join(f'<Vertex><Position><WorldPosition x="{x}" y="{y}"/></Position></Vertex>' for x, y in points)
    return (
        '<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="t" closed="false">'
        f"<Shape><Polyline>{vertices}</Polyline></Shape></Trajectory></TrajectoryRef><TimeReference><None/>"
        '</TimeReference><TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction>'
        "</RoutingAction></PrivateAction>"
    )


def _final(kind: str | None, value: float, steady: str = "") -> str:
    if kind is None:
        return ""
    if kind == "absolute":
        return f'<FinalSpeed><AbsoluteSpeed value="{value}">{steady}</AbsoluteSpeed></FinalSpeed>'
    return (
        f'<FinalSpeed><RelativeSpeedToMaster value="{value}" speedTargetValueType="{kind}">{steady}'
        "</RelativeSpeedToMaster></FinalSpeed>"
    )


def _watch(condition: str | None, who: str = "VRU") -> str:
    """An event slowing the Ego to 9 m/s once ``condition`` holds for ``who``."""
    if condition is None:
        return ""
    return (
        '<ManeuverGroup maximumExecutionCount="1" name="wg"><Actors selectTriggeringEntities="false">'
        '<EntityRef entityRef="Ego"/></Actors><Maneuver name="wm"><Event name="watch" priority="parallel">'
        f'<Action name="wa">{step_speed(9.0)}</Action><StartTrigger><ConditionGroup><Condition name="wc" delay="0" '
        f'conditionEdge="none"><ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef '
        f'entityRef="{who}"/></TriggeringEntities><EntityCondition>{condition}</EntityCondition></ByEntityCondition>'
        "</Condition></ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>"
    )


def scenario(tmp_path, c: dict):
    """Ego at ``ego_s`` on lane -1 at ``ego_v``; the VRU on an untimed path across the road (or, with
    ``vru_lane``, on that lane) synchronised from ``start`` s to reach the crossing as Ego reaches it."""
    (tmp_path / "straight.xodr").write_text(TWO_ROADS if c.get("two_roads") else ROAD)
    split, cross_x = c.get("two_roads", False), c.get("cross_x", CROSS_X)
    vru_lane = c.get("vru_lane")
    if vru_lane is None:
        vru_init = (
            f'<Private entityRef="VRU"><PrivateAction><TeleportAction><Position><WorldPosition x="{cross_x}" '
            f'y="{c["vru_y0"]}" h="1.5708"/></Position></TeleportAction></PrivateAction>{step_speed(c["vru_v"])}'
            # across the road, with a bend half way (so it turns once)
            f"{_follow([(cross_x, c['vru_y0']), (cross_x + 0.3, 0.0), (cross_x, -c['vru_y0'])])}</Private>"
        )
        target = f'<WorldPosition x="{cross_x}" y="-1.75"/>'
        vru = f'<ScenarioObject name="VRU">{PEDESTRIAN}</ScenarioObject>'
    else:
        vru_init = (
            f'<Private entityRef="VRU"><PrivateAction><TeleportAction><Position>{_lane(vru_lane, c["vru_s"], split)}'
            f"</Position></TeleportAction></PrivateAction>{step_speed(c['vru_v'])}</Private>"
        )
        target = _lane(vru_lane, cross_x, split)
        vru = f'<ScenarioObject name="VRU">{CAR}</ScenarioObject>'
    ego_path = _follow([(c["ego_s"], -1.75), (200.0, -1.6), (390.0, -1.75)])  # (a master following a path)
    ego_init = (
        f'<Private entityRef="Ego"><PrivateAction><TeleportAction><Position>{_lane(-1, c["ego_s"], split)}</Position>'
        f"</TeleportAction></PrivateAction>{step_speed(c['ego_v'])}{ego_path if c.get('ego_path') else ''}</Private>"
    )
    sync = (
        '<PrivateAction><SynchronizeAction masterEntityRef="Ego" '
        f'targetTolerance="{c.get("tol", 0)}" targetToleranceMaster="{c.get("tol_master", 0)}">'
        f"<TargetPositionMaster>{_lane(-1, cross_x - 3.0, split)}</TargetPositionMaster>"
        f"<TargetPosition>{target}</TargetPosition>"
        f"{_final(c.get('final'), c.get('final_v', 0.0), c.get('steady', ''))}</SynchronizeAction></PrivateAction>"
    )
    story = (
        '<ManeuverGroup maximumExecutionCount="1" name="sg"><Actors selectTriggeringEntities="false"><EntityRef '
        'entityRef="VRU"/></Actors><Maneuver name="sm"><Event name="sync" priority="override"><Action name="sa">'
        f'{sync}</Action><StartTrigger><ConditionGroup><Condition name="sc" delay="0" conditionEdge="none">'
        f'<ByValueCondition><SimulationTimeCondition value="{c.get("start", 0.5)}" rule="greaterOrEqual"/>'
        "</ByValueCondition></Condition></ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>"
        + _watch(c.get("watch"), c.get("watch_who", "VRU"))
    )
    xosc = tmp_path / "sync.xosc"
    xosc.write_text(
        f"""<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork><LogicFile filepath="straight.xodr"/></RoadNetwork>
<Entities><ScenarioObject name="Ego">{CAR}</ScenarioObject>{vru}</Entities>
<Storyboard><Init><Actions>{ego_init}{vru_init}</Actions></Init>
<Story name="s"><Act name="a">{story}<StartTrigger><ConditionGroup><Condition name="go" delay="0"
conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/>
</ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="{c.get("end", 12.0)}" rule="greaterThan"/></ByValueCondition></Condition>
</ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    )
    return xosc


STEADY_DISTANCE = '<TargetDistanceSteadyState distance="2.5"/>'
STEADY_TIME = '<TargetTimeSteadyState time="1.2"/>'
BASE = {"ego_s": 40.0, "ego_v": 12.0, "vru_y0": -9.0, "vru_v": 0.0, "final": "absolute", "final_v": 1.5}
CASES = {
    "ncap_like": {"steady": STEADY_DISTANCE},
    "moving_start": {"vru_v": 1.0, "final_v": 2.0},
    "no_final_speed": {"final": None, "vru_v": 0.2},
    "relative_delta": {"final": "delta", "final_v": -10.5, "steady": STEADY_TIME},
    "relative_factor": {"final": "factor", "final_v": 0.15, "vru_v": 0.5},
    "from_time_zero": {"start": 0.0, "steady": STEADY_DISTANCE},
    "linger": {"vru_y0": -4.5, "vru_v": 2.5, "final_v": 1.0, "ego_s": 20.0},
    "linger_stop_now": {"vru_y0": -3.2, "vru_v": 3.0, "final_v": 0.5, "ego_s": 10.0, "ego_v": 8.0},
    "rush": {"vru_y0": -14.0, "vru_v": 0.5, "final_v": 2.0, "ego_s": 90.0},
    "tolerances": {"tol": 0.4, "tol_master": 1.5, "steady": STEADY_DISTANCE},
    "on_a_lane": {"vru_lane": 1, "vru_s": 200.0, "vru_v": -4.0, "final": "absolute", "final_v": -3.0},
    "master_on_a_path": {"ego_path": True, "steady": STEADY_DISTANCE},
    # the master's target on the next road: its distance over the chain of roads, then along its road
    "target_on_the_next_road": {"two_roads": True, "cross_x": 260.0, "ego_v": 14.0, "steady": STEADY_DISTANCE},
    # both on lanes, both crossing from the first road to targets on the second
    "lanes_across_roads": {
        "two_roads": True,
        "vru_lane": -2,
        "vru_s": 120.0,
        "vru_v": 5.0,
        "final_v": 8.0,
        "cross_x": 260.0,
        "end": 20.0,
    },
    # conditions on the synchronised entity, watched while the core steps it
    "watch_speed": {"steady": STEADY_DISTANCE, "watch": '<SpeedCondition value="1.2" rule="greaterThan"/>'},
    "watch_accel": {"vru_v": 1.0, "watch": '<AccelerationCondition value="-0.2" rule="lessThan"/>'},
    "watch_traveled": {"steady": STEADY_DISTANCE, "watch": '<TraveledDistanceCondition value="3.3"/>'},
    "watch_reach": {
        "watch": '<ReachPositionCondition tolerance="0.8"><Position><WorldPosition x="150.15" y="-4.0"/>'
        "</Position></ReachPositionCondition>"
    },
    "watch_standstill": {
        "vru_y0": -4.5,
        "vru_v": 2.5,
        "final_v": 1.0,
        "ego_s": 20.0,
        "watch": '<StandStillCondition duration="0.3"/>',
    },
    "watch_relative_speed": {
        "watch": '<RelativeSpeedCondition entityRef="VRU" value="10.8" rule="lessThan"/>',
        "watch_who": "Ego",
    },
    "watch_master_distance": {
        "watch": '<RelativeDistanceCondition entityRef="VRU" relativeDistanceType="cartesianDistance" value="25" '
        'freespace="true" rule="lessThan"/>',
        "watch_who": "Ego",
    },
}
#: the watched condition counts how long the synchronised entity stands: the core stops at each
#: standstill's start and end, which this case is made of (conditions on its speed are guards in the core)
STEPPED = {"watch_standstill"}


def _with_modes(monkeypatch, seen: set):
    original = synchronize.Synchronize.step

    def recording(self, ctx):
        original(self, ctx)
        seen.add(self.mode)

    monkeypatch.setattr(synchronize.Synchronize, "step", recording)


@pytest.mark.parametrize("case", sorted(CASES))
def test_synchronised_stretches_equal_the_stepped_run(tmp_path, monkeypatch, case):
    c = {**BASE, **CASES[case]}
    fast, cruised, slow = run_both(scenario(tmp_path, c), monkeypatch)
    assert_identical(fast, slow)
    vru = slow.traces["VRU"]
    assert np.ptp(vru.speed) > 0.3, "the synchronisation did not change the VRU's speed"
    if "watch" in c:
        assert np.any(np.isclose(slow.traces["Ego"].speed, 9.0)), f"{case}: the watched condition never fired"
    if case not in STEPPED:
        assert cruised > 0.5 * len(fast.t), f"{case}: only {cruised} of {len(fast.t)} steps cruised"


def test_the_cases_pass_through_every_mode_of_the_profile(tmp_path, monkeypatch):
    """The comparison above covers the profile's branches: each mode is entered by some case."""
    seen: set = set()
    _with_modes(monkeypatch, seen)
    for case in CASES:
        scenario(tmp_path, {**BASE, **CASES[case]})
        from vei_scenario.interpreter import run_scenario

        run_scenario(tmp_path / "sync.xosc")
    assert {"WAITING", "STEADY", "LINEAR", "NON_LINEAR", "STOP_NOW", "STOPPED"} <= seen, seen


def test_a_synchronised_entity_reaches_its_target_as_the_master_reaches_its(tmp_path):
    """Not only equal to the stepped run: the synchronisation does what it says (an analytic check)."""
    from vei_scenario.interpreter import run_scenario

    c = {**BASE, **CASES["ncap_like"]}
    r = run_scenario(scenario(tmp_path, c))
    vru = r.traces["VRU"]
    # the Ego's reference point reaches s = CROSS_X - lead at constant speed from ego_s
    t_master = (CROSS_X - 3.0 - c["ego_s"]) / c["ego_v"]
    k = int(np.argmin(abs(r.t - t_master)))
    assert math.isclose(vru.y[k], -1.75, abs_tol=0.05), vru.y[k]
    assert math.isclose(vru.speed[k], 1.5, abs_tol=1e-9)


# --- SpeedAction transitions in the core --------------------------------------------------------------


def _shaped_speed(v: float, shape: str, dimension: str, value: float) -> str:
    return (
        f'<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="{shape}" '
        f'value="{value}" dynamicsDimension="{dimension}"/><SpeedActionTarget><AbsoluteTargetSpeed value="{v}"/>'
        "</SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"
    )


TRANSITIONS = [
    ("linear", "time", 2.5),
    ("cubic", "time", 3.3),
    ("sinusoidal", "rate", 1.7),
    ("linear", "distance", 30.0),
    ("cubic", "rate", 4.0),
]
#: conditions of tests/test_cruise.py's scenario that fire while (or after) the Ego's speed changes
WATCHED = ["time", "traveled", "reach", "relative_longitudinal", "speed_of_other", "element_state"]


@pytest.mark.parametrize("transition", TRANSITIONS, ids=lambda t: "-".join(map(str, t)))
@pytest.mark.parametrize("case", WATCHED)
def test_speed_transitions_in_quiet_stretches_equal_the_stepped_run(tmp_path, monkeypatch, case, transition):
    """tests/test_cruise.py's scenario with the Ego's slowing (15 -> 5 m/s) a transition of each shape
    and dimension, and the Lead's stop a 2 s linear slowing to 0.5 m/s (still moving: the step that ends
    it, which ends its event that element_state watches, is not one where a standstill begins)."""
    import test_cruise

    path = test_cruise.scenario(tmp_path, test_cruise.CASES[case])
    xml = path.read_text()
    xml = xml.replace(
        f'<Action name="Changea">{step_speed(5.0)}', f'<Action name="Changea">{_shaped_speed(5.0, *transition)}'
    )
    xml = xml.replace(f'<Action name="LeadStopsa">{step_speed(0.0)}',
                      f'<Action name="LeadStopsa">{_shaped_speed(0.5, "linear", "time", 2.0)}')  # fmt: skip
    assert xml.count("dynamicsShape") == xml.count('dynamicsShape="step"') + 2  # (both replaced)
    path.write_text(xml)
    fast, cruised, slow = run_both(path, monkeypatch)
    assert_identical(fast, slow)
    ego = slow.traces["Ego"].speed
    assert np.any((ego > 5.5) & (ego < 14.5)), "the Ego never was between its speeds"
    assert cruised > 0.5 * len(fast.t), f"only {cruised} of {len(fast.t)} steps cruised"


def test_a_condition_on_a_changing_speed_is_evaluated_every_step(tmp_path, monkeypatch):
    """A SpeedCondition on the entity whose transition runs is a guard in the core, which stops before
    the step that crosses it: it fires on the step the stepped run fires it, and the core takes the rest."""
    import test_cruise

    watched = test_cruise._entity('<SpeedCondition value="3.3" rule="lessThan"/>', who="Lead")
    path = test_cruise.scenario(tmp_path, watched)
    xml = path.read_text().replace(f'<Action name="LeadStopsa">{step_speed(0.0)}',
                                   f'<Action name="LeadStopsa">{_shaped_speed(0.0, "cubic", "time", 2.0)}')  # fmt: skip
    path.write_text(xml)
    fast, cruised, slow = run_both(path, monkeypatch)
    assert_identical(fast, slow)
    assert np.any(np.isclose(slow.traces["Ego"].speed, 5.0))
    assert cruised > 0.5 * len(fast.t), f"only {cruised} of {len(fast.t)} steps cruised"


def _stretches(tmp_path, monkeypatch, c: dict, quantity: str) -> list[tuple[int, float, float]]:
    """Each offer to the core in the run of case ``c`` (checked equal to the stepped run): the steps
    it took and the VRU's ``quantity`` before and after."""
    from vei_scenario.interpreter import engine

    stretches: list[tuple[int, float, float]] = []
    original = engine.cruise

    def watching(ctx, *args):
        before = getattr(ctx.entities["VRU"], quantity)
        n = original(ctx, *args)
        stretches.append((n, before, getattr(ctx.entities["VRU"], quantity)))
        return n

    monkeypatch.setattr(engine, "cruise", watching)
    fast, _, slow = run_both(scenario(tmp_path, c), monkeypatch)
    assert_identical(fast, slow)
    return stretches


def test_a_synchronised_entity_speeding_up_to_its_final_speed_stays_in_one_stretch(tmp_path, monkeypatch):
    """The quiet steps' bound on a synchronised entity's move reaches its final speed: from standstill
    to 6 m/s (three times the margin) the core carries it without stopping at each margin passed."""
    from vei_scenario.interpreter import cruise

    c = {**BASE, "vru_lane": -2, "vru_s": 100.0, "final_v": 6.0, "cross_x": 200.0, "ego_s": 20.0, "end": 14.0}
    stretches = _stretches(tmp_path, monkeypatch, c, "speed")
    gains = [v1 - v0 for n, v0, v1 in stretches if n > 0]
    assert max(gains) > 2 * cruise.SPEED_MARGIN_MPS, gains
    assert max(v1 for _, _, v1 in stretches) > 5.0


def test_a_traveled_distance_is_a_guard_the_core_stops_just_before(tmp_path, monkeypatch):
    """A TraveledDistanceCondition does not cut the stretch to the steps its distance could at most be
    covered in: the core compares the odometer each step and stops before the step that reaches it."""
    stretches = _stretches(tmp_path, monkeypatch, {**BASE, **CASES["watch_traveled"]}, "odometer")
    # one stretch carries the rider from where it stands to the step before its 3.3 m
    assert any(n > 100 and a < 0.5 and 3.3 - 0.05 < b < 3.3 for n, a, b in stretches), stretches
