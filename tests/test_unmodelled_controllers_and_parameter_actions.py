# ruff: noqa: E501  (the hand-written scenarios keep their XML lines whole)
"""Scenarios written for other tools: a controller that names no model (the ASAM example scenarios
give each car a driver description, ``HAF_Driver`` with weight, age and eye distance), overrides that
are switched off, and parameters modified by a ParameterAction (OpenSCENARIO 1.0/1.1).

esmini plays a controller type it does not know as its default controller; vei does the same and says
so in a warning (the file, the line, the name), where it used to refuse the whole scenario. esmini's
own models that vei lacks are refused once an action activates one (esmini would then drive the car by
it); never activated, they change nothing, in esmini as in vei."""

from __future__ import annotations

import itertools
import json
import subprocess
import sys

import numpy as np
import pytest

from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter import run_scenario

DT = 0.01


def _road(path) -> None:
    """(Its folder made.) A straight 2 km motorway cross-section after the ASAM examples' AB_RQ31_Straight road: border,
    two driving lanes and a hard shoulder each way."""
    lanes = [(5, "border", 1.5), (4, "stop", 3.6), (3, "driving", 3.9), (2, "driving", 3.9), (1, "border", 2.6)]

    def lane(i: int, kind: str, w: float) -> str:
        return (
            f'<lane id="{i}" type="{kind}" level="false"><link/><width sOffset="0" a="{w}" b="0" c="0" d="0"/></lane>'
        )

    path.parent.mkdir(parents=True, exist_ok=True)
    left = "".join(lane(i, k, w) for i, k, w in lanes)
    right = "".join(lane(-i, k, w) for i, k, w in reversed(lanes))
    path.write_text(
        '<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6" name="r" version="1"/>'
        '<road name="r" length="2000" id="1" junction="-1"><link/><planView><geometry s="0" x="0" y="0" hdg="0" '
        f'length="2000"><line/></geometry></planView><lanes><laneSection s="0"><left>{left}</left>'
        f'<center><lane id="0" type="driving" level="false"/></center><right>{right}</right></laneSection></lanes>'
        "</road></OpenDRIVE>"
    )


def _car(name: str, driver: str | None) -> str:
    ctrl = (
        f'<ObjectController><Controller name="{driver}"><Properties><Property name="weight" value="80.0"/>'
        '<Property name="age" value="32"/><Property name="eyeDistance" value="0.07"/></Properties></Controller>'
        "</ObjectController>"
        if driver
        else ""
    )
    return (
        f'<ScenarioObject name="{name}"><Vehicle name="{name}_car" vehicleCategory="car">'
        '<Performance maxSpeed="69.444" maxAcceleration="200" maxDeceleration="10.0"/>'
        '<BoundingBox><Center x="1.4" y="0" z="0.8"/><Dimensions width="2.0" length="4.2" height="1.6"/></BoundingBox>'
        '<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.5" trackWidth="1.75" positionX="2.8" positionZ="0.25"/>'
        '<RearAxle maxSteering="0" wheelDiameter="0.5" trackWidth="1.75" positionX="0" positionZ="0.25"/></Axles>'
        f"<Properties/></Vehicle>{ctrl}</ScenarioObject>"
    )


def _speed(entity: str, v: float) -> str:
    return (
        '<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" '
        f'dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="{v}"/></SpeedActionTarget>'
        "</SpeedAction></LongitudinalAction></PrivateAction>"
    )


def _cut_in(
    tmp_path, driver: str | None = "Default_Driver", ego_extra: str = "", init_extra: str = "", a1_extra: str = ""
) -> object:
    """A cut-in as the ASAM example writes it: a faster car from behind in the next lane changes into
    the ego's lane once 20 m ahead of it (road coordinates), a slower car ahead in the ego's lane."""
    _road(tmp_path / "rq31.xodr")
    xosc = f"""<?xml version="1.0" encoding="utf-8"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2020-02-21T10:00:00" description="cut-in" author="t"/>
<ParameterDeclarations><ParameterDeclaration parameterType="string" name="owner" value="A2"/></ParameterDeclarations>
<CatalogLocations/><RoadNetwork><LogicFile filepath="rq31.xodr"/></RoadNetwork>
<Entities>
{_car("Ego", driver and "HAF_Driver")}
{_car("A1", driver)}
{_car("A2", driver)}
</Entities>
<Storyboard><Init><Actions>{init_extra}
<Private entityRef="Ego">{_speed("Ego", 27.778)}<PrivateAction><TeleportAction><Position>
<LanePosition roadId="1" laneId="-3" offset="0.5" s="100"/></Position></TeleportAction></PrivateAction>{ego_extra}</Private>
<Private entityRef="A1">{_speed("A1", 25.0)}<PrivateAction><TeleportAction><Position>
<RelativeLanePosition entityRef="Ego" dLane="0" ds="84.0"/></Position></TeleportAction></PrivateAction>{a1_extra}</Private>
<Private entityRef="A2">{_speed("A2", 30.556)}<PrivateAction><TeleportAction><Position>
<RelativeLanePosition entityRef="Ego" dLane="1" ds="-30.0"/></Position></TeleportAction></PrivateAction></Private>
</Actions></Init>
<Story name="S"><Act name="A"><ManeuverGroup maximumExecutionCount="1" name="G">
<Actors selectTriggeringEntities="false"><EntityRef entityRef="$owner"/></Actors><Maneuver name="M">
<Event name="E" priority="override"><Action name="cut"><PrivateAction><LateralAction>
<LaneChangeAction targetLaneOffset="-0.036"><LaneChangeActionDynamics dynamicsDimension="distance" dynamicsShape="cubic" value="54.8"/>
<LaneChangeTarget><RelativeTargetLane entityRef="Ego" value="0"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction></Action>
<StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="rising"><ByEntityCondition>
<TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="$owner"/></TriggeringEntities><EntityCondition>
<DistanceCondition value="20.0" freespace="false" coordinateSystem="road" rule="greaterThan"><Position>
<RelativeObjectPosition entityRef="Ego" dx="0" dy="0"/></Position></DistanceCondition></EntityCondition></ByEntityCondition>
</Condition></ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>
<StartTrigger><ConditionGroup><Condition name="go" delay="0" conditionEdge="rising"><ByValueCondition>
<SimulationTimeCondition value="0" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising"><ByValueCondition>
<SimulationTimeCondition value="30" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""
    path = tmp_path / "cut_in.xosc"
    path.write_text(xosc)
    return path


def _vei(*args: str, check: bool = False) -> subprocess.CompletedProcess:
    """``vei ARGS`` in a process of its own, as a user runs it (its output captured as text)."""
    return subprocess.run([sys.executable, "-m", "vei_scenario", *args], capture_output=True, text=True, check=check)


def _same_motion(a, b) -> None:
    assert a.t.shape == b.t.shape
    for name in a.traces:
        for attr in ("x", "y", "yaw", "speed"):
            np.testing.assert_array_equal(getattr(a.traces[name], attr), getattr(b.traces[name], attr))


# --- a controller that names no model --------------------------------------------------------------


def test_a_driver_description_plays_as_the_default_controller_and_says_so(tmp_path):
    with_drivers = run_scenario(_cut_in(tmp_path / "a"), {}, DT)
    without = run_scenario(_cut_in(tmp_path / "b", driver=None), {}, DT)
    _same_motion(with_drivers, without)
    assert without.warnings == ()
    assert len(with_drivers.warnings) == 3  # one per controller element, each naming its file and line
    first = with_drivers.warnings[0]
    assert "cut_in.xosc: line " in first and "'HAF_Driver'" in first and "default controller" in first
    assert "\n" not in first
    # the lane change happened (A2 ends in the ego's lane) and A2 runs into A1, as nobody brakes
    a2 = with_drivers.traces["A2"]
    ego = with_drivers.traces["Ego"]
    assert abs(a2.y[-1] - ego.y[-1]) < 0.6 and abs(a2.y[0] - ego.y[0]) > 3.0  # (offsets 0.5 and -0.036)


def test_activating_a_controller_without_a_model_changes_nothing(tmp_path):
    activate = (
        '<PrivateAction><ControllerAction><ActivateControllerAction controllerRef="HAF_Driver" lateral="true" '
        'longitudinal="true"/></ControllerAction></PrivateAction>'
    )
    activated = run_scenario(_cut_in(tmp_path / "a", ego_extra=activate), {}, DT)
    plain = run_scenario(_cut_in(tmp_path / "b", driver=None), {}, DT)
    _same_motion(activated, plain)


#: esmini's own models that vei lacks (a few of controllers.ESMINI_ONLY).
ESMINI_MODELS = ["FollowGhostController", "InteractiveController", "ExternalController", "SloppyDriverController"]
_ACTIVATE = (
    '<PrivateAction><ControllerAction><ActivateControllerAction lateral="true" longitudinal="true"/>'
    "</ControllerAction></PrivateAction>"
)


@pytest.mark.parametrize("kind", ESMINI_MODELS)
def test_esminis_own_models_never_activated_change_nothing_and_are_named(tmp_path, kind):
    """esmini 3.6 plays a scenario whose entities are given one of its models that no action activates
    as if they had none (measured: pedestrian_traj_synch.xosc, its Ego's InteractiveController never
    activated, plays the same without it); vei plays it so too, with a warning naming the model."""
    assigned = run_scenario(_cut_in(tmp_path / "a", driver=kind), {}, DT)
    plain = run_scenario(_cut_in(tmp_path / "b", driver=None), {}, DT)
    _same_motion(assigned, plain)
    named = [w for w in assigned.warnings if f"'{kind}' (an esmini model" in w]
    assert len(named) == 2 and all("stops if it is activated" in w and "cut_in.xosc: line " in w for w in named)


@pytest.mark.parametrize("kind", ESMINI_MODELS)
def test_esminis_own_models_activated_are_refused_in_one_line(tmp_path, kind):
    """Activated, esmini would drive the entity by its model: the run stops, naming the model, the
    entity and when (in Init, or by the event that changes lanes once A2 is 20 m ahead)."""
    with pytest.raises(VeiInputError) as err:
        run_scenario(_cut_in(tmp_path / "init", driver=kind, a1_extra=_ACTIVATE), {}, DT)
    msg = str(err.value)
    assert f"'{kind}' (an esmini model) is not supported" in msg and "A1's is activated at t = 0.00 s" in msg
    assert "cut_in.xosc: line " in msg and "\n" not in msg
    path = _cut_in(tmp_path / "event", driver=kind)
    path.write_text(
        path.read_text().replace('<Action name="cut">', f'<Action name="on">{_ACTIVATE}</Action><Action name="cut">')
    )
    with pytest.raises(VeiInputError, match=r"A2's is activated at t = [1-9][0-9]*\.[0-9]{2} s"):
        run_scenario(path, {}, DT)


def test_a_sumo_controller_is_refused_unactivated(tmp_path):
    """esmini's SUMO controller adds and drives the vehicles of a SUMO simulation without being activated."""
    with pytest.raises(VeiInputError, match=r"'SumoController' \(an esmini model\) is not supported"):
        run_scenario(_cut_in(tmp_path, driver="SumoController"), {}, DT)


def test_vei_run_refusing_an_activated_model_writes_nothing(tmp_path):
    out = tmp_path / "run"
    path = _cut_in(tmp_path, driver="InteractiveController", a1_extra=_ACTIVATE)
    proc = _vei("run", str(path), "-o", str(out), "--no-plots")
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("vei: error: ")]
    assert proc.returncode != 0 and len(errors) == 1 and "Traceback" not in proc.stderr
    assert "'InteractiveController'" in errors[0] and not (out.exists() and any(out.iterdir()))


def test_vei_run_prints_the_warning_and_writes_it_to_the_metrics(tmp_path):
    out = tmp_path / "run"
    proc = _vei("run", str(_cut_in(tmp_path)), "-o", str(out), "--no-plots")
    assert proc.returncode == 0, proc.stderr
    warned = [ln for ln in proc.stderr.splitlines() if ln.startswith("vei: warning: ")]
    assert len(warned) == 3 and "Traceback" not in proc.stderr
    doc = json.loads((out / "metrics.json").read_text())
    assert len(doc["warnings"]) == 3 and "'Default_Driver'" in doc["warnings"][1]
    # a run without anything to say writes the document it always wrote: no warnings key
    quiet = tmp_path / "quiet"
    path = _cut_in(tmp_path / "q", driver=None)
    _vei("run", str(path), "-o", str(quiet), "--no-plots", check=True)
    assert "warnings" not in json.loads((quiet / "metrics.json").read_text())


def test_the_asam_style_cut_in_plays_as_in_esmini(tmp_path, esmini):
    """The driver descriptions as esmini plays them (its default controller): within 5 cm, with the
    same collision at the same time."""
    from vei_scenario.conformance.esmini import compare_runs, run_esmini

    path = _cut_in(tmp_path)
    c = compare_runs(run_scenario(path, {}, DT), run_esmini(esmini, path, DT))
    assert max(e.max_deviation_m for e in c.entities) < 0.05, c
    assert [(round(t, 1), {a, b}) for t, a, b in c.vei_collisions] == [
        (round(t, 1), {a, b}) for t, a, b in c.esmini_collisions
    ]
    assert c.vei_collisions  # (A2 runs into A1: the check compares something)


# --- overrides switched off --------------------------------------------------------------------------

OVERRIDES = (
    "<PrivateAction><ControllerAction><OverrideControllerValueAction>"
    '<Throttle value="0" active="false"/><Brake value="BRAKE" active="ACTIVE"/><Clutch value="0" active="false"/>'
    '<ParkingBrake value="0" active="false"/><SteeringWheel value="0" active="false"/><Gear number="0" active="false"/>'
    "</OverrideControllerValueAction></ControllerAction></PrivateAction>"
)


def test_overrides_switched_off_change_nothing(tmp_path):
    off = OVERRIDES.replace("BRAKE", "0").replace("ACTIVE", "false")
    with_off = run_scenario(_cut_in(tmp_path / "a", driver=None, ego_extra=off), {}, DT)
    _same_motion(with_off, run_scenario(_cut_in(tmp_path / "b", driver=None), {}, DT))


def test_an_active_override_is_refused_naming_it(tmp_path):
    on = OVERRIDES.replace("BRAKE", "0.8").replace("ACTIVE", "true")
    with pytest.raises(
        VeiInputError, match=r"cut_in\.xosc: line \d+: OverrideControllerValueAction: an active <Brake>"
    ):
        run_scenario(_cut_in(tmp_path, driver=None, ego_extra=on), {}, DT)


# --- ParameterAction: set and modify --------------------------------------------------------------


def _counting(tmp_path, declarations: str, actions: str, condition: str) -> object:
    """One car at 10 m/s; ``actions`` (global actions) run as an event at 1 s; the car speeds up to
    20 m/s when ``condition`` (a ParameterCondition) holds."""
    _road(tmp_path / "rq31.xodr")
    go = (
        '<Event name="go" priority="parallel"><Action name="fast">'
        f"{_speed('Ego', 20.0)}</Action><StartTrigger><ConditionGroup><Condition name='p' delay='0' "
        f"conditionEdge='none'><ByValueCondition>{condition}</ByValueCondition></Condition></ConditionGroup>"
        "</StartTrigger></Event>"
    )
    change = (
        f'<Event name="change" priority="parallel">{actions}<StartTrigger><ConditionGroup><Condition name="t" '
        'delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1" rule="greaterOrEqual"/>'
        "</ByValueCondition></Condition></ConditionGroup></StartTrigger></Event>"
    )
    xosc = f"""<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="0" date="2021-02-11T12:00:00" description="p" author="t"/>
<ParameterDeclarations>{declarations}</ParameterDeclarations><CatalogLocations/>
<RoadNetwork><LogicFile filepath="rq31.xodr"/></RoadNetwork><Entities>{_car("Ego", None)}</Entities>
<Storyboard><Init><Actions><Private entityRef="Ego">{_speed("Ego", 10.0)}<PrivateAction><TeleportAction><Position>
<LanePosition roadId="1" laneId="-3" offset="0" s="10"/></Position></TeleportAction></PrivateAction></Private></Actions></Init>
<Story name="S"><Act name="A"><ManeuverGroup maximumExecutionCount="1" name="G"><Actors selectTriggeringEntities="false">
<EntityRef entityRef="Ego"/></Actors><Maneuver name="M">{change}{go}</Maneuver></ManeuverGroup>
<StartTrigger><ConditionGroup><Condition name="s" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising"><ByValueCondition>
<SimulationTimeCondition value="3" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""
    path = tmp_path / "p.xosc"
    path.write_text(xosc)
    return path


_NAMES = itertools.count()


def _action(name: str, rule: str) -> str:
    return f'<Action name="{name}{next(_NAMES)}"><GlobalAction><ParameterAction parameterRef="{name}">{rule}</ParameterAction></GlobalAction></Action>'


def _speeds_up_at(result) -> float | None:
    tr = result.traces["Ego"]
    fast = np.nonzero(tr.speed > 15.0)[0]
    return float(result.t[fast[0]]) if fast.size else None


def test_modify_actions_add_and_multiply_in_order(tmp_path):
    decls = (
        '<ParameterDeclaration name="Gain" parameterType="double" value="2.0"/>'
        '<ParameterDeclaration name="Count" parameterType="integer" value="1"/>'
    )
    actions = (
        _action("Gain", '<ModifyAction><Rule><MultiplyByValue value="0.277778"/></Rule></ModifyAction>')
        + _action("Gain", '<ModifyAction><Rule><AddValue value="1.0"/></Rule></ModifyAction>')
        + _action("Count", '<ModifyAction><Rule><MultiplyByValue value="3"/></Rule></ModifyAction>')
    )
    # 2 x 0.277778 + 1 = 1.555556 and 1 x 3 = 3: both conditions hold from 1 s on
    cond = (
        '<ParameterCondition parameterRef="Gain" value="1.5555" rule="greaterThan"/></ByValueCondition></Condition>'
        '<Condition name="q" delay="0" conditionEdge="none"><ByValueCondition>'
        '<ParameterCondition parameterRef="Count" value="3" rule="equalTo"/>'
    )
    result = run_scenario(_counting(tmp_path, decls, actions, cond), {}, DT)
    assert result.parameters["Gain"] == repr(2.0 * 0.277778 + 1.0) and result.parameters["Count"] == "3"
    assert _speeds_up_at(result) == pytest.approx(1.01, abs=1e-9)  # (the step after the condition held)
    # without the multiplication the sum stays below the threshold: the car never speeds up
    only_add = _action("Gain", '<ModifyAction><Rule><AddValue value="-0.5"/></Rule></ModifyAction>')
    assert _speeds_up_at(run_scenario(_counting(tmp_path / "b", decls, only_add, cond), {}, DT)) is None


def test_set_then_modify_a_parameter(tmp_path):
    decls = '<ParameterDeclaration name="finalSpeed" parameterType="double" value="5.0"/>'
    actions = _action("finalSpeed", '<SetAction value="2.5"/>') + _action(
        "finalSpeed", '<ModifyAction><Rule><AddValue value="8.0"/></Rule></ModifyAction>'
    )
    cond = '<ParameterCondition parameterRef="finalSpeed" value="10.5" rule="equalTo"/>'
    assert _speeds_up_at(run_scenario(_counting(tmp_path, decls, actions, cond), {}, DT)) == pytest.approx(1.01)


@pytest.mark.parametrize(
    "decl, rule, why",
    [
        ('parameterType="integer" value="1"', '<MultiplyByValue value="1.5"/>', "parameter N = '1.5' is not"),
        ('parameterType="string" value="abc"', '<AddValue value="1"/>', "parameter 'N' = 'abc' is not a number"),
        ('parameterType="double" value="1e300"', '<MultiplyByValue value="1e12"/>', "parameter 'N' would become inf"),
        ('parameterType="unsignedInt" value="1"', '<AddValue value="-2"/>', "parameter N = '-1' must not be negative"),
    ],
)
def test_a_modification_that_breaks_the_type_is_refused_in_one_line(tmp_path, decl, rule, why):
    decls = f'<ParameterDeclaration name="N" {decl}/>'
    actions = _action("N", f"<ModifyAction><Rule>{rule}</Rule></ModifyAction>")
    cond = '<ParameterCondition parameterRef="N" value="0" rule="greaterThan"/>'
    with pytest.raises(VeiInputError) as err:
        run_scenario(_counting(tmp_path, decls, actions, cond), {}, DT)
    msg = str(err.value)
    assert why in msg and "p.xosc: line " in msg and "\n" not in msg


def test_modifying_an_undeclared_parameter_is_refused(tmp_path):
    decls = '<ParameterDeclaration name="N" parameterType="double" value="1"/>'
    actions = _action("Nope", '<ModifyAction><Rule><AddValue value="1"/></Rule></ModifyAction>')
    cond = '<ParameterCondition parameterRef="N" value="0" rule="greaterThan"/>'
    with pytest.raises(VeiInputError, match="ParameterAction on undeclared parameter 'Nope'"):
        run_scenario(_counting(tmp_path, decls, actions, cond), {}, DT)


def _with_gap(path):
    """The cut-in with the car ahead's distance as a parameter ``Gap`` (84 m), for a sweep to vary."""
    decl = '<ParameterDeclaration parameterType="double" name="Gap" value="84"/>'
    text = path.read_text().replace("<ParameterDeclarations>", "<ParameterDeclarations>" + decl, 1)
    path.write_text(text.replace('ds="84.0"', 'ds="$Gap"'))
    return path


def test_vei_sweep_says_so_once_and_writes_it_to_the_catalog(tmp_path):
    """A sweep plays every variant with the default controller: the warning is said once (not per
    variant) and kept in catalog.json; a sweep with nothing to say writes the catalog it always wrote."""
    path = _with_gap(_cut_in(tmp_path))
    out = tmp_path / "sweep"
    proc = _vei("sweep", str(path), "--vary", "Gap=60,84,100", "-o", str(out), "--quiet")
    assert proc.returncode == 0, proc.stderr
    warned = [ln for ln in proc.stderr.splitlines() if ln.startswith("vei: warning: ")]
    assert len(warned) == 3 and all("default controller" in w for w in warned)
    doc = json.loads((out / "catalog.json").read_text())
    assert len(doc["warnings"]) == 3 and len(doc["variants"]) == 3
    quiet = tmp_path / "quiet"
    plain = _with_gap(_cut_in(tmp_path / "q", driver=None))
    _vei("sweep", str(plain), "--vary", "Gap=60,84", "-o", str(quiet), "--quiet", check=True)
    assert "warnings" not in json.loads((quiet / "catalog.json").read_text())
