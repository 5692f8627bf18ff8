# ruff: noqa: E501  (the hand-written scenarios keep their XML lines whole)
"""The adaptive cruise of esmini's ACCController / ALKSController (the system-under-test placeholder
of ALKS test scenarios): its control law against analytic results, the interpreter's controller on
hand-written ALKS-style scenarios (against esmini where it is installed), its refusals, and the
one-off LongitudinalDistanceAction that such scenarios start with."""

from __future__ import annotations

import math

import numpy as np
import pytest

from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter import run_scenario
from vei_scenario.models.acc import AccParameters, acc_speed, box_gaps, bumper_gap, close_ahead

DT = 0.01
P = AccParameters()


# --- the control law ---------------------------------------------------------------------------------


@pytest.mark.parametrize("v0, v_set", [(0.0, 20.0), (30.0, 12.0), (12.0, 12.3)])
def test_without_a_leader_it_reaches_the_set_speed_without_passing_it(v0, v_set):
    v, speeds = v0, []
    for _ in range(3000):
        v = acc_speed(P, v, v_set, None, 3.0, 8.0, DT)
        speeds.append(v)
    speeds = np.array(speeds)
    assert speeds[-1] == pytest.approx(v_set, abs=1e-9)
    err = (speeds - v_set) * np.sign(v0 - v_set)
    assert np.all(err >= 0.0) and np.all(np.diff(err) <= 1e-12)  # a monotonic approach, never past it
    rate = np.abs(np.diff(np.concatenate([[v0], speeds]))) / DT
    assert rate.max() <= (0.7 * 3.0 if v0 < v_set else 8.0) + 1e-9


@pytest.mark.parametrize("v_lead, time_gap", [(10.0, 1.5), (20.0, 2.0), (5.0, 1.0)])
def test_behind_a_steady_leader_it_settles_at_the_time_gap(v_lead, time_gap):
    """The fixed point of the law: the leader's speed at gap = min_gap + time_gap·v (analytic)."""
    p = AccParameters(time_gap_s=time_gap)
    v, gap = v_lead + 8.0, 3.0 * (3.0 + time_gap * (v_lead + 8.0))
    for _ in range(60000):
        v_new = acc_speed(p, v, 40.0, (gap, v_lead), 4.0, 9.0, DT)
        gap += (v_lead - v_new) * DT
        v = v_new
    assert v == pytest.approx(v_lead, abs=1e-3)
    assert gap == pytest.approx(p.min_gap_m + time_gap * v_lead, abs=0.05)


def test_following_never_takes_it_above_the_set_speed_and_a_closed_gap_stops_it():
    assert acc_speed(P, 16.0, 16.0, (500.0, 30.0), 5.0, 9.0, DT) == 16.0  # far behind a faster leader
    assert acc_speed(P, 16.0, 16.0, (0.9, 16.0), 5.0, 9.0, DT) == 0.0  # under a metre: stands
    assert acc_speed(P, 16.0, 16.0, (10.0, 0.0), 5.0, 9.0, DT) == pytest.approx(16.0 - 9.0 * DT)


def test_box_gaps_and_the_close_ahead_rule():
    own = (0.0, 0.0, 0.0, 4.0, 2.0)
    assert box_gaps(own, (10.0, 0.0, 0.0, 4.0, 2.0)) == pytest.approx((6.0, 0.0))
    assert box_gaps(own, (-10.0, 3.0, 0.0, 4.0, 2.0)) == pytest.approx((-6.0, 1.0))
    assert box_gaps(own, (5.0, 0.0, math.pi / 2, 4.0, 2.0)) == pytest.approx((2.0, 0.0))  # turned across
    assert close_ahead(2.0, 0.0, 4.5, 0.0) and not close_ahead(2.0, 0.3, 4.5, 0.0)
    assert close_ahead(2.0, -0.4, 4.5, 0.0) and not close_ahead(6.0, 0.0, 4.5, 0.0)
    assert close_ahead(6.0, 0.0, 4.5, 2.0)  # closing at 2 m/s: a metre more
    # reference points 20 m apart along the lane, rear axles 1.4 m behind the box centres
    assert bumper_gap(20.0, 4.5, 1.4, 4.5, 1.4, True) == pytest.approx(20.0 - 3.65 - 0.85)
    assert bumper_gap(20.0, 4.5, 1.4, 4.5, 1.4, False) == pytest.approx(20.0 - 3.65 - 3.65)


# --- in the interpreter ------------------------------------------------------------------------------


def _road(path, lanes: int = 3, curvature: float = 0.0) -> None:
    def lane(i: int) -> str:
        return f'<lane id="{i}" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>'

    shape = f'<arc curvature="{curvature}"/>' if curvature else "<line/>"
    path.write_text(
        '<?xml version="1.0" encoding="UTF-8"?><OpenDRIVE><header revMajor="1" revMinor="6" name="r" version="1"/>'
        '<road name="r" length="3000" id="0" junction="-1"><link/><planView><geometry s="0" x="0" y="0" hdg="0" '
        f'length="3000">{shape}</geometry></planView><lanes><laneSection s="0">'
        f"<left>{''.join(lane(i) for i in range(lanes, 0, -1))}</left>"
        '<center><lane id="0" type="none" level="false"/></center>'
        f"<right>{''.join(lane(-i) for i in range(1, lanes + 1))}</right></laneSection></lanes></road></OpenDRIVE>"
    )


def _car(name: str, length: float = 5.0, cx: float = 1.4) -> str:
    return (
        f'<Vehicle name="{name}" vehicleCategory="car"><BoundingBox><Center x="{cx}" y="0" z="0.9"/>'
        f'<Dimensions width="2.0" length="{length}" height="1.8"/></BoundingBox>'
        '<Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/>'
        '<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/>'
        '<RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles>'
        "<Properties/></Vehicle>"
    )


def _speed(target: str, shape: str = "step", value: str = "0", dim: str = "time") -> str:
    return (
        f'<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="{shape}" value="{value}" '
        f'dynamicsDimension="{dim}"/><SpeedActionTarget>{target}</SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>'
    )


def _event(name: str, actor: str, private: str, when: str) -> str:
    return (
        f'<Story name="{name}S"><Act name="{name}A"><ManeuverGroup maximumExecutionCount="1" name="{name}G">'
        f'<Actors selectTriggeringEntities="false"><EntityRef entityRef="{actor}"/></Actors><Maneuver name="{name}M">'
        f'<Event name="{name}E" priority="override"><Action name="{name}">{private}</Action><StartTrigger><ConditionGroup>'
        f'<Condition name="{name}C" delay="0" conditionEdge="rising"><ByValueCondition><SimulationTimeCondition value="{when}" '
        'rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Event></Maneuver>'
        f'</ManeuverGroup><StartTrigger><ConditionGroup><Condition name="{name}go" delay="0" conditionEdge="none">'
        '<ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition>'
        "</ConditionGroup></StartTrigger></Act></Story>"
    )


def _scenario(
    tmp_path,
    controller: str | None,
    lead_brake: str,
    speed_kph: float = 60.0,
    ego_events: str = "",
    stop_s: float = 25.0,
    lane: int = -2,
    entry: str = "Sut",
    curvature: float = 0.0,
    offset: float = 0.0,
) -> object:
    """Ego and a lead car on a straight three-lane road; the lead starts 2 s ahead (bumper to bumper)
    by a one-off LongitudinalDistanceAction in Init and brakes to a stop at ``lead_brake`` m/s² at 8 s.
    ``controller``: the ego's controller, from a controller catalog (as the ALKS scenarios write it)."""
    _road(tmp_path / "road.xodr", curvature=curvature)
    (tmp_path / "controllers").mkdir(exist_ok=True)
    (tmp_path / "controllers" / "controller_catalog.xosc").write_text(
        '<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2024-01-01T00:00:00" '
        f'description="c" author="t"/><Catalog name="controller_catalog">{controller or ""}</Catalog></OpenSCENARIO>'
    )
    obj_ctrl = (
        f'<ObjectController><CatalogReference catalogName="controller_catalog" entryName="{entry}"/></ObjectController>'
        if controller
        else ""
    )
    activate = (
        _event(
            "on",
            "Ego",
            '<PrivateAction><ControllerAction><ActivateControllerAction lateral="true" longitudinal="true"/></ControllerAction></PrivateAction>',
            "1.0",
        )
        if controller
        else ""
    )
    v = speed_kph / 3.6
    xosc = f"""<?xml version="1.0" encoding="utf-8"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2024-01-01T00:00:00" description="alks-like" author="t"/>
<ParameterDeclarations/><CatalogLocations><ControllerCatalog><Directory path="./controllers"/></ControllerCatalog></CatalogLocations>
<RoadNetwork><LogicFile filepath="road.xodr"/></RoadNetwork>
<Entities><ScenarioObject name="Ego">{_car("ego")}{obj_ctrl}</ScenarioObject><ScenarioObject name="Lead">{_car("lead")}</ScenarioObject></Entities>
<Storyboard><Init><Actions>
<Private entityRef="Ego"><PrivateAction><TeleportAction><Position><LanePosition roadId="0" laneId="{lane}" offset="0" s="5"/></Position></TeleportAction></PrivateAction>{_speed(f'<AbsoluteTargetSpeed value="{v}"/>')}</Private>
<Private entityRef="Lead"><PrivateAction><TeleportAction><Position><RelativeLanePosition entityRef="Ego" dLane="0" ds="{2 * v + 5}" offset="{offset}"/></Position></TeleportAction></PrivateAction>
{_speed('<RelativeTargetSpeed entityRef="Ego" value="0" speedTargetValueType="delta" continuous="false"/>')}
<PrivateAction><LongitudinalAction><LongitudinalDistanceAction continuous="false" coordinateSystem="entity" displacement="leadingReferencedEntity" timeGap="2.0" entityRef="Ego" freespace="true"/></LongitudinalAction></PrivateAction></Private>
</Actions></Init>{activate}{ego_events}{_event("brake", "Lead", _speed('<AbsoluteTargetSpeed value="0"/>', "linear", lead_brake, "rate"), "8.0")}
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising"><ByValueCondition><SimulationTimeCondition value="{stop_s}" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""
    path = tmp_path / "s.xosc"
    path.write_text(xosc)
    return path


ALKS = '<Controller name="Sut"><Properties><Property name="esminiController" value="ALKSController"/></Properties></Controller>'


def _gap(result) -> np.ndarray:
    ego, lead = result.traces["Ego"], result.traces["Lead"]
    return (lead.x - ego.x) - (2.5 + 1.4) - (2.5 - 1.4)


def test_a_one_off_distance_set_in_init_lets_the_entity_go(tmp_path):
    """A LongitudinalDistanceAction with continuous="false" in Init places the lead once: braking
    later, it stops where the braking distance v²/(2a) puts it and stays there (it used to be put
    back at the gap behind the still moving ego every step)."""
    r = run_scenario(_scenario(tmp_path, None, "5"), {}, DT)
    lead, v = r.traces["Lead"], 60 / 3.6
    i8 = int(round(8.0 / DT))
    assert _gap(r)[0] == pytest.approx(2.0 * v, abs=1e-6)  # 2 s bumper to bumper
    stop_x = lead.x[i8] + v * v / (2 * 5.0)
    after = lead.t > 8.0 + v / 5.0 + 0.05
    assert np.all(lead.speed[after] == 0.0)
    assert lead.x[after] == pytest.approx(np.full(after.sum(), stop_x), abs=0.1)


@pytest.mark.parametrize("brake", ["9.81", "4"])
def test_the_alks_controller_stops_behind_a_braking_lead(tmp_path, brake):
    r = run_scenario(_scenario(tmp_path, ALKS, brake), {}, DT)
    ego, gap = r.traces["Ego"], _gap(r)
    assert not r.collisions
    assert ego.speed.max() <= 60 / 3.6 + 1e-9  # never above the set speed
    assert ego.speed[-1] == pytest.approx(0.0, abs=0.05)
    assert gap.min() >= P.stop_gap_m  # it kept clear of the stopped lead
    assert gap[-1] == pytest.approx(P.min_gap_m, abs=0.5)  # and closed up to the standstill distance
    assert ego.y == pytest.approx(np.full(len(ego.y), ego.y[0]))  # it keeps its lane


def test_without_the_controller_the_ego_runs_into_the_stopped_lead(tmp_path):
    r = run_scenario(_scenario(tmp_path, None, "9.81"), {}, DT)
    assert [c[1:] for c in r.collisions][:1] in ([("Ego", "Lead")], [("Lead", "Ego")])


def test_additive_mode_takes_a_later_speed_action_as_its_set_speed_override_ignores_it(tmp_path):
    slower = _event("slow", "Ego", _speed('<AbsoluteTargetSpeed value="8"/>'), "3.0")
    add = run_scenario(_scenario(tmp_path, ALKS, "4", ego_events=slower, stop_s=7.9), {}, DT)
    assert add.traces["Ego"].speed[-1] == pytest.approx(8.0)
    acc = '<Controller name="Sut"><Properties><Property name="esminiController" value="ACCController"/><Property name="mode" value="override"/><Property name="setSpeed" value="12"/></Properties></Controller>'
    over = run_scenario(_scenario(tmp_path, acc, "4", ego_events=slower, stop_s=7.9), {}, DT)
    sp = over.traces["Ego"].speed
    assert sp.min() > 11.9 and sp[-1] == pytest.approx(12.0)  # down to its own set speed, deaf to the action


@pytest.mark.parametrize(
    "brake, curvature, offset",
    [("9.81", 0.0, 0.0), ("4", 0.0, 0.0), ("6", 0.001, 1.75), ("6", -0.004, -1.0), ("9", 0.004, 1.75)],
)
def test_the_alks_controller_plays_as_in_esmini(tmp_path, esmini, brake, curvature, offset):
    """On straight and curved roads, with the lead off its lane centre up to the lane border (where it
    still counts as in the ego's lane: it was placed in it)."""
    from vei_scenario.conformance.esmini import compare_runs, run_esmini

    # named as the ALKS test scenarios name it, with no esminiController property: esmini goes by the name
    ctrl = '<Controller name="ALKSController"><Properties/></Controller>'
    path = _scenario(tmp_path, ctrl, brake, entry="ALKSController", curvature=curvature, offset=offset)
    c = compare_runs(run_scenario(path, {}, DT), run_esmini(esmini, path, DT))
    assert c.entities and c.max_deviation_m <= 0.10, c.entities
    assert not c.vei_collisions and not c.esmini_collisions


@pytest.mark.parametrize(
    "prop, why",
    [
        ('<Property name="timeGap" value="-1"/>', "timeGap must be a number in 0..60"),
        ('<Property name="timeGap" value="nan"/>', "timeGap must be a number in 0..60"),
        ('<Property name="setSpeed" value="fast"/>', "setSpeed must be a number"),
        ('<Property name="mode" value="sometimes"/>', "mode must be additive or override"),
        ('<Property name="virtual" value="true"/>', "virtual mode"),
    ],
)
def test_bad_controller_properties_are_refused_in_one_line(tmp_path, prop, why):
    ctrl = ALKS.replace("</Properties>", prop + "</Properties>")
    with pytest.raises(VeiInputError) as err:
        run_scenario(_scenario(tmp_path, ctrl, "4"), {}, DT)
    msg = str(err.value)
    assert why in msg and "controller_catalog.xosc" in msg and "\n" not in msg


def test_an_unknown_esmini_controller_is_named_in_the_refusal(tmp_path):
    ctrl = ALKS.replace("ALKSController", "SloppyDriverController")
    with pytest.raises(VeiInputError, match=r"'SloppyDriverController' \(an esmini model\) is not supported"):
        run_scenario(_scenario(tmp_path, ctrl, "4"), {}, DT)


def test_the_cruise_acts_from_the_step_after_its_activation(tmp_path):
    """esmini steps a controller from the step after the one it is activated in: activated with a set
    speed of 10 m/s (the Ego at 60 km/h), the cruise leaves that step to the default motion, at the
    speed the Ego had, and slows down from the next."""
    acc = (
        '<Controller name="Sut"><Properties><Property name="esminiController" value="ACCController"/>'
        '<Property name="mode" value="override"/><Property name="setSpeed" value="10"/></Properties></Controller>'
    )
    path = _scenario(tmp_path, acc, "4")
    # (activated by the evaluation at 0.01 s: the step to 0.02 s is the default motion's)
    path.write_text(
        path.read_text().replace('SimulationTimeCondition value="1.0"', 'SimulationTimeCondition value="0.005"', 1)
    )
    ego, v = run_scenario(path, {}, DT).traces["Ego"], 60 / 3.6
    assert list(ego.status[1:4]) == ["default", "default", "acc"]
    assert ego.speed[2] == pytest.approx(v) and ego.x[2] - ego.x[1] == pytest.approx(v * DT)
    assert ego.speed[3] < v - 0.01


def test_esminis_alks_example_follows_esmini_from_the_first_step(esmini):
    """esmini's alks-test (the ALKSController activated in Init, braking at once for a slower car): 0.07 m
    before the controller waited a step, now within a millimetre."""
    from vei_scenario.conformance.esmini import compare_runs, run_esmini

    path = esmini.parents[1] / "xosc" / "alks-test.xosc"
    if not path.is_file():
        pytest.skip(f"{path} not shipped beside esmini")
    c = compare_runs(run_scenario(path, {}, DT), run_esmini(esmini, path, DT))
    assert c.entities and c.max_deviation_m <= 1e-3, c.entities
