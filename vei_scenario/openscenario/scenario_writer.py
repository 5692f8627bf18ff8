"""ScenarioModel → ASAM OpenSCENARIO XML through scenariogeneration's object model.

Structure of a compiled scenario:

* ``ParameterDeclarations``: TimeShift, RiderType, CapEnabled, EgoCruiseSpeed, ConflictTimeShift.
* ``Entities``: ``Ego`` (car) with the ``CollisionAvoidancePlanner`` controller, one bicycle-category
  vehicle per scooter track; the threat scooter carries the ``SocialForceModel`` controller. Every
  other annotated road user is typed by its category (``Pedestrian``, a vehicle of its category, or a
  ``MiscObject``) and replays its track. Controller
  properties hold every model parameter (``$``-references where a scenario parameter decides).
* ``Init``: every entity teleported to its first pose; the ego at ``$EgoCruiseSpeed``, the scooters at
  their first recorded speed.
* Story ``Reconstruction``: every moving entity follows its reconstructed trajectory
  (``FollowTrajectoryAction``, Polyline with vertex times in scenario time). Scooters replay with
  absolute timing (the threat's ``offset`` is ``${-$TimeShift}``: see :func:`threat_offset`); the ego
  follows the path only
  (``TimeReference/None``), so it holds its cruise speed unless the planner takes over.
* Story ``Controllers``: the social force model is activated when ``RiderType`` is ``normal`` or
  ``aggressive`` and the planner when ``CapEnabled`` is true (``ParameterCondition`` triggers, which
  every OpenSCENARIO 1.x version has).
* Stop trigger at the end of the clip.

With ``resolved`` parameter values instead, the same structure is written with literal values, no
parameter declarations and the parameter conditions decided at compile time, for tools that do not
support parameters.
"""

from __future__ import annotations

import datetime as dt
import xml.etree.ElementTree as ET

from lxml import etree
from scenariogeneration import xosc
from scenariogeneration.xosc.exceptions import OpenSCENARIOVersionError

from vei_scenario.errors import VeiInputError
from vei_scenario.geometry.angles import wrap_pi
from vei_scenario.safe_xml import safe_parser
from vei_scenario.scenario.model import EntitySpec, ScenarioModel
from vei_scenario.scenario.parameters import MODEL_PARAMETERS, format_value

AUTHOR = "vei-scenario"
SFM_CONTROLLER = "SocialForceModel"
CAP_CONTROLLER = "CollisionAvoidancePlanner"


def header_date(model: ScenarioModel) -> dt.datetime:
    """The header date: the clip's recording time, never the wall clock (byte-for-byte output)."""
    if model.date:
        try:
            return dt.datetime.fromisoformat(model.date.replace("Z", "+00:00")).replace(tzinfo=None, microsecond=0)
        except ValueError:
            pass
    return dt.datetime(1970, 1, 1)


def _num(v: float, digits: int = 4) -> float:
    r = round(float(v), digits)
    return 0.0 if r == 0 else r


def _ref(name: str, resolved: dict | None, type_: str) -> str:
    """``$Name`` in a parametrised scenario, the literal value in a resolved one."""
    return format_value(type_, resolved[name]) if resolved is not None else f"${name}"


def _vehicle(e: EntitySpec) -> xosc.Vehicle:
    """The entity's vehicle. Reference-point convention: the position of a compiled entity is its
    recorded point (the ego's GPS fix, the annotated centre of a scooter), the centre of its bounding
    box (``Center x = 0``), and the rear axle is declared there (``positionX = 0``). esmini places the
    box at ``Center.x - RearAxle.positionX`` ahead of the position, vei at ``Center.x``: with the
    rear axle at 0 both put the box where the models, the metrics and the collision check have it."""
    category = getattr(xosc.VehicleCategory, e.category)
    box = _box(e)
    if e.name == "Ego":
        front = xosc.Axle(0.52, 0.65, 1.6, 0.3 * e.length_m, 0.325)
        rear = xosc.Axle(0.0, 0.65, 1.6, 0.0, 0.325)
        return xosc.Vehicle(e.name, category, box, front, rear, 50.0, 4.0, 9.0)
    if e.object_type == "e-scooter":
        front = xosc.Axle(0.6, 0.2, 0.1, 0.4, 0.1)
        rear = xosc.Axle(0.0, 0.2, 0.1, 0.0, 0.1)
        vehicle = xosc.Vehicle(e.name, category, box, front, rear, 7.0, 2.0, 3.5)
    else:  # a replayed road user: limits no recorded motion would reach (it follows its trajectory)
        wheel = min(0.7, 0.4 * e.height_m)
        front = xosc.Axle(0.5, wheel, 0.8 * e.width_m, 0.6 * e.length_m, wheel / 2)
        rear = xosc.Axle(0.0, wheel, 0.8 * e.width_m, 0.0, wheel / 2)
        vehicle = xosc.Vehicle(e.name, category, box, front, rear, 70.0, 10.0, 10.0, mass=e.mass_kg or None)
    _type_property(vehicle, e)
    return vehicle


def _box(e: EntitySpec) -> xosc.BoundingBox:
    """The box, centred on the recorded point (see :func:`_vehicle`)."""
    return xosc.BoundingBox(e.width_m, e.length_m, e.height_m, 0.0, 0.0, e.height_m / 2)


def _type_property(obj, e: EntitySpec) -> None:
    # OpenSCENARIO has no e-scooter category (it is a bicycle-category vehicle), nor one for every
    # annotated class: the property tells players that know better types, such as the OSI writer
    # (TYPE_STANDUP_SCOOTER), what it is
    if e.object_type:
        obj.add_property("objectType", e.object_type)


def _scenario_object(e: EntitySpec, minor_version: int):
    """The entity's Vehicle, Pedestrian or MiscObject (a road user is typed by its category). A 1.0
    Pedestrian must name a model (later versions dropped it): its category."""
    if e.kind == "pedestrian":
        model = e.category if minor_version == 0 else None
        obj = xosc.Pedestrian(e.name, e.mass_kg, getattr(xosc.PedestrianCategory, e.category), _box(e), model)
    elif e.kind == "misc":
        obj = xosc.MiscObject(e.name, e.mass_kg, getattr(xosc.MiscObjectCategory, e.category), _box(e))
    else:
        return _vehicle(e)
    _type_property(obj, e)
    return obj


def _properties(values: dict[str, object]) -> xosc.Properties:
    props = xosc.Properties()
    for k, v in values.items():
        props.add_property(k, v if isinstance(v, str) else format_value("double", v))
    return props


def _exposed(model: ScenarioModel, which: str, resolved: dict | None) -> dict[str, str]:
    """The controller properties that read a declared model parameter: ``$Name`` (or its value)."""
    declared = {p.name for p in model.parameters}
    return {
        prop: _ref(name, resolved, "double")
        for name, (ctrl, prop, _) in MODEL_PARAMETERS.items()
        if ctrl == which and name in declared
    }


def _sfm_controller(model: ScenarioModel, resolved: dict | None) -> xosc.Controller:
    values: dict[str, object] = {"riderType": _ref("RiderType", resolved, "string"), "route": f"{model.threat}_route"}
    values.update(model.sfm.properties())
    values.update(_exposed(model, "sfm", resolved))
    return xosc.Controller(SFM_CONTROLLER, _properties(values))


def _cap_controller(model: ScenarioModel, resolved: dict | None) -> xosc.Controller:
    values: dict[str, object] = {
        "enabled": _ref("CapEnabled", resolved, "boolean"),
        "cruiseSpeed": _ref("EgoCruiseSpeed", resolved, "double"),
        "threatEntity": model.threat,
    }
    values.update(model.cap.properties())
    values.update(_exposed(model, "cap", resolved))
    return xosc.Controller(CAP_CONTROLLER, _properties(values))


def _polyline(e: EntitySpec) -> xosc.Polyline:
    tr = e.trajectory
    yaw = wrap_pi(tr.yaw)
    positions = [xosc.WorldPosition(_num(x), _num(y), 0.0, _num(h, 6)) for x, y, h in zip(tr.x, tr.y, yaw)]
    return xosc.Polyline([_num(t, 3) for t in tr.t], positions)


def _override(minor_version: int) -> xosc.Priority:
    """The priority that replaces running events: ``overwrite`` before 1.2, ``override`` since."""
    return xosc.Priority.override if minor_version >= 2 else xosc.Priority.overwrite


def _trajectory_event(e: EntitySpec, offset: str | float | None, minor_version: int) -> xosc.Event:
    """Follow the reconstructed path; with ``offset`` None the path only (speed from elsewhere),
    otherwise with absolute timing shifted by ``offset``."""
    traj = xosc.Trajectory(f"{e.name}_route", False)
    traj.add_shape(_polyline(e))
    if offset is None:
        action = xosc.FollowTrajectoryAction(traj, xosc.FollowingMode.position)
    else:
        action = xosc.FollowTrajectoryAction(
            traj, xosc.FollowingMode.position, xosc.ReferenceContext.absolute, scale=1, offset=offset
        )
    event = xosc.Event(f"{e.name}FollowsTrajectory", _override(minor_version))
    event.add_action(f"{e.name}FollowTrajectory", action)
    event.add_trigger(_at_start(f"{e.name}TrajectoryStart", minor_version))
    return event


def declares_time_shift(minor_version: int) -> bool:
    """Whether a parametrised scenario of this version declares ``TimeShift``: its Timing offset is the
    expression ``${-$TimeShift}``, and OpenSCENARIO 1.0 has no expressions."""
    return minor_version >= 1


def threat_offset(resolved: dict | None, minor_version: int) -> str | float:
    """The threat's Timing ``offset``. Players map simulation time t to trajectory time
    ``t * scale + offset`` (esmini's reading, and vei's), so a scooter delayed by ``TimeShift`` seconds
    has offset ``-TimeShift``. A 1.0 scenario, which cannot negate a parameter, replays as recorded
    (its ``--variants`` files carry each shift as a literal)."""
    if resolved is not None:
        return 0.0 - float(resolved["TimeShift"])
    return "${-$TimeShift}" if declares_time_shift(minor_version) else 0.0


def _at_start(name: str, minor_version: int) -> xosc.ValueTrigger:
    """True from the first evaluation (t = 0): the replay moves from the first step in vei and in
    esmini alike (``SimulationTime > 0`` would leave one step of Init motion before it). OpenSCENARIO
    1.0 has no ``greaterOrEqual``: there it is ``SimulationTime > -1``."""
    cond = (
        xosc.SimulationTimeCondition(0, xosc.Rule.greaterOrEqual)
        if minor_version >= 1
        else xosc.SimulationTimeCondition(-1, xosc.Rule.greaterThan)
    )
    return xosc.ValueTrigger(name, 0, xosc.ConditionEdge.none, cond)


def _parameter_trigger(name: str, alternatives: list[tuple[str, str]]) -> xosc.Trigger:
    """Start trigger true when any (parameter, value) pair holds: one condition group per pair (OR)."""
    trigger = xosc.Trigger()
    for i, (param, value) in enumerate(alternatives):
        group = xosc.ConditionGroup()
        group.add_condition(
            xosc.ValueTrigger(
                f"{name}{i}", 0, xosc.ConditionEdge.none, xosc.ParameterCondition(param, value, xosc.Rule.equalTo)
            )
        )
        trigger.add_conditiongroup(group)
    return trigger


def build_scenario(model: ScenarioModel, minor_version: int = 3, resolved: dict | None = None) -> xosc.Scenario:
    """The scenariogeneration object of the scenario (``resolved``: literal parameter values)."""
    params = xosc.ParameterDeclarations()
    if resolved is None:
        for p in model.parameters:
            if p.name == "TimeShift" and not declares_time_shift(minor_version):
                continue
            params.add_parameter(xosc.Parameter(p.name, getattr(xosc.ParameterType, p.type), p.literal(p.default)))

    entities = xosc.Entities()
    for e in model.entities:
        if e.name == "Ego":
            entities.add_scenario_object(e.name, _vehicle(e), _cap_controller(model, resolved))
        elif e.name == model.threat:
            entities.add_scenario_object(e.name, _vehicle(e), _sfm_controller(model, resolved))
        else:
            entities.add_scenario_object(e.name, _scenario_object(e, minor_version))

    init = xosc.Init()
    step = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0)
    for e in model.entities:
        tr = e.trajectory
        init.add_init_action(
            e.name,
            xosc.TeleportAction(
                xosc.WorldPosition(_num(tr.x[0]), _num(tr.y[0]), 0.0, _num(float(wrap_pi(tr.yaw[0])), 6))
            ),
        )
        if e.name == "Ego":  # the ego drives its path at the cruise speed unless the planner takes over
            cruise = _ref("EgoCruiseSpeed", resolved, "double")
            speed: str | float = float(cruise) if resolved is not None else cruise
        elif tr.t[0] > 0:  # waits where its recording starts
            speed = 0.0
        else:
            speed = _num(tr.speed[0], 3)
        init.add_init_action(e.name, xosc.AbsoluteSpeedAction(speed, step))

    replay = xosc.Story("Reconstruction")
    act = xosc.Act("ReplayRecordedTrajectories", _at_start("ReplayStart", minor_version))
    for e in model.entities:
        if e.name == "Ego":
            offset: str | float | None = None
        elif e.name == model.threat:
            offset = threat_offset(resolved, minor_version)
        else:
            offset = 0
        maneuver = xosc.Maneuver(f"{e.name}Replay")
        maneuver.add_event(_trajectory_event(e, offset, minor_version))
        group = xosc.ManeuverGroup(f"{e.name}ReplayGroup")
        group.add_actor(e.name)
        group.add_maneuver(maneuver)
        act.add_maneuver_group(group)
    replay.add_act(act)

    controllers = xosc.Story("Controllers")
    ctl_act = xosc.Act("ActivateControllers", _at_start("ControllersStart", minor_version))
    activations = [
        (
            model.threat,
            "ActivateSocialForce",
            [("RiderType", "normal"), ("RiderType", "aggressive")],
            xosc.ActivateControllerAction(lateral=True, longitudinal=True),
        ),
        (
            "Ego",
            "ActivateCollisionAvoidance",
            [("CapEnabled", "true")],
            xosc.ActivateControllerAction(lateral=False, longitudinal=True),
        ),
    ]
    for actor, event_name, conditions, action in activations:
        if resolved is not None:
            if not any(format_value("string", resolved[p]).lower() == v for p, v in conditions):
                continue
            trigger: xosc.Trigger | xosc.ValueTrigger = _at_start(f"{event_name}Start", minor_version)
        else:
            trigger = _parameter_trigger(f"{event_name}When", conditions)
        event = xosc.Event(event_name, xosc.Priority.parallel)
        event.add_action(event_name, action)
        event.add_trigger(trigger)
        maneuver = xosc.Maneuver(f"{event_name}Maneuver")
        maneuver.add_event(event)
        group = xosc.ManeuverGroup(f"{event_name}Group")
        group.add_actor(actor)
        group.add_maneuver(maneuver)
        ctl_act.add_maneuver_group(group)
    if ctl_act.maneuvergroup:
        controllers.add_act(ctl_act)

    stop = xosc.ValueTrigger(
        "EndOfClip",
        0,
        xosc.ConditionEdge.rising,
        xosc.SimulationTimeCondition(_num(model.duration_s, 3), xosc.Rule.greaterThan),
        "stop",
    )
    board = xosc.StoryBoard(init, stop)
    board.add_story(replay)
    if ctl_act.maneuvergroup:
        board.add_story(controllers)

    road = xosc.RoadNetwork(roadfile=model.road_file)
    return xosc.Scenario(
        model.name,
        AUTHOR,
        params,
        entities,
        board,
        road,
        xosc.Catalog(),
        osc_minor_version=minor_version,
        creation_date=header_date(model),
    )


def render(element_owner) -> bytes:
    """Pretty XML bytes of a scenariogeneration object (via lxml; minidom is too slow for long clips)."""
    data = ET.tostring(element_owner.get_element(), encoding="utf-8")
    root = etree.fromstring(data, safe_parser())
    etree.indent(root, space="  ")
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


def scenario_xml(model: ScenarioModel, minor_version: int = 3, resolved: dict | None = None) -> bytes:
    try:
        return render(build_scenario(model, minor_version, resolved))
    except OpenSCENARIOVersionError as exc:
        raise VeiInputError(
            None, "--osc-version", f"the scenario is not expressible in OpenSCENARIO 1.{minor_version}: {exc}"
        ) from None
