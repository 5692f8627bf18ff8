"""Layers → OpenSCENARIO XML + OpenDRIVE, through scenariogeneration's object model.

Structure of a written scenario:

* ``RoadNetwork``: the generated map (or the given OpenDRIVE file); traffic lights are dynamic
  signals of the OpenDRIVE, set in ``Init`` (the ego's approach and the one opposite green, the
  crossing approaches red).
* ``Entities``: ``Ego`` (car) with the ``CollisionAvoidancePlanner`` (agent ``cap``: cruise at its
  speed, emergency braking for every other entity), the adversaries by type, ``Background<k>``.
* ``Init``: every entity on its lane at its speed; the ego's route through the junction; the
  ``EnvironmentAction`` (weather, time of day, road friction).
* Story ``Behaviours``: one maneuver group per adversary; each atomic behaviour is one or more
  events, sequences chained by ``StoryboardElementStateCondition`` (the previous event complete, or
  running for the behaviour's ``hold_s``), parallel branches started by the same condition;
  ``priority="parallel"`` so that a starting event never cancels its concurrent sibling.
* Stop trigger: the duration. A collision does not end the run (every scenario of a batch lasts as
  long, so time shares such as comfort compare); it is recorded with who and when.
"""

from __future__ import annotations

import datetime as dt
import itertools
import math
import tempfile
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

from scenariogeneration import xosc

from vei_scenario.language import maps, placement
from vei_scenario.language.behaviours import behaviour, cut_in, overtake
from vei_scenario.language.behaviours.base import ActorContext, Condition, G, value
from vei_scenario.language.description_text import plain_text
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.models.cap import CapParameters
from vei_scenario.openscenario.scenario_writer import render
from vei_scenario.roads.opendrive_output import finalize_opendrive
from vei_scenario.roads.road_model import RoadNetwork

AUTHOR = "vei-scenario describe"
EGO = "Ego"
DEFAULT_DURATION_S = 20.0
#: The ego's adaptive-cruise time gap (s) when it follows a vehicle in its path.
EGO_TIME_GAP_S = 1.5
#: A crossing road user's path goes on this far beyond the far kerb (m).
CROSSING_BEYOND_M = 30.0
#: The step scenarios are run and scored at (Hz): vei run's own, so vei run replays a batch's run.
DEFAULT_RATE_HZ = 100.0
#: What the ego drives: the layers' ego is always this type (its length is what a start must clear).
EGO_KIND = "car"
#: Box (length, width, height m), category, mass (kg), max speed, acceleration, deceleration.
TYPES = {
    "car": ((4.6, 1.85, 1.5), "car", 1500.0, 50.0, 4.0, 9.0),
    "van": ((5.3, 2.0, 2.2), "van", 2500.0, 40.0, 3.0, 8.0),
    "truck": ((8.5, 2.5, 3.2), "truck", 12000.0, 30.0, 2.0, 7.0),
    "bicycle": ((1.8, 0.6, 1.7), "bicycle", 90.0, 10.0, 2.0, 4.0),
    "e-scooter": ((1.2, 0.6, 1.8), "bicycle", 95.0, 6.94, 2.0, 3.5),
    "pedestrian": ((0.5, 0.6, 1.8), "pedestrian", 75.0, 3.0, 1.5, 3.0),
}


def vulnerable(kind: str) -> bool:
    """A pedestrian, cyclist or e-scooter rider (its OpenSCENARIO category), not a vehicle."""
    return TYPES[kind][1] in ("pedestrian", "bicycle")


#: Behaviours of a rider at the kerb that move it sideways into the road along its lanes (a crossing
#: goes straight across instead, from beyond the kerb): a lane change can start only on a lane.
SWERVES_FROM_KERB = ("change_lane", "cut_in", "overtake", "forced_turn", "cut_out")
#: Riders who ride along the kerb or in a cycle lane (past waiting cars, or before they swerve into the
#: road); a walker there stands: what it does into the road is a crossing.
RIDERS_AT_KERB = ("bicycle", "e-scooter")
#: Signal state strings (red;yellow;green lamps), as esmini's examples write them.
RED, GREEN = "on;off;off", "off;off;on"
WEATHER = {  # cloud state, precipitation (type, intensity mm/h), fog visual range (m), default friction
    "clear": ("free", ("dry", 0.0), 100000, 1.0),
    "cloudy": ("overcast", ("dry", 0.0), 100000, 1.0),
    "rain": ("overcast", ("rain", 4.0), 8000, 0.7),
    "heavy_rain": ("rainy", ("rain", 20.0), 2000, 0.55),
    "fog": ("overcast", ("dry", 0.0), 150, 0.9),
    "snow": ("overcast", ("snow", 3.0), 3000, 0.35),
}


@dataclass
class WrittenScenario:
    xosc: bytes
    xodr: bytes
    actors: list[str]


def friction(layers: dict) -> float:
    w = layers["environment"]["weather"]
    return float(w.get("friction", WEATHER[w["condition"]][3]))


def top_speed(adv: dict, ego_speed: float, ctx: ActorContext) -> float:
    """The top speed (m/s) of adversary ``adv``'s vehicle, placed as ``ctx`` says: its kind's usual
    one, or more where its layers ask more of it: the speed they give it (a rider the text has doing
    30 mph rides a tuned scooter), and an overtake's pass, which must outrun the ego (at its kind's
    usual top a rider never gets past an ego as fast as that), as a cut-in's that comes past the ego
    first does (:func:`cut_in.comes_past_first`, the test its compile makes, on where it stands)."""
    top = max(TYPES[adv["type"]][3], float(adv.get("speed_mps", 0.0)))
    for n, (_, node) in enumerate(behaviour_nodes(adv["behaviour"])):
        if node["behaviour"] == "overtake":
            gain = value(node.get("config", {}), behaviour("overtake").PARAMETERS, "speed_gain_mps")
            top = max(top, ego_speed + gain)
        if node["behaviour"] == "cut_in" and n == 0 and cut_in.comes_past_first(ctx):
            top = max(top, cut_in.pass_speed_of(ctx, node.get("config", {})))
    return round(top, 3)


def _overtaking_at(node: dict, ego_speed: float, speed: float, relation: str) -> dict:
    """A copy of behaviour tree ``node`` whose overtakes pass at the overtaker's stated ``speed``
    (:func:`overtake.stated_gain`): one that starts at the ego's speed reaches its own as it passes."""
    if node.get("behaviour") == "overtake":
        return {**node, "config": overtake.stated_gain(node.get("config", {}), ego_speed, speed, relation)}
    out = dict(node)
    for key in ("sequence", "parallel"):
        if key in node:
            out[key] = [_overtaking_at(child, ego_speed, speed, relation) for child in node[key]]
    return out


def _vehicle(name: str, kind: str, mu: float, vmax: float | None = None):
    (length, width, height), category, mass, kind_vmax, amax, dmax = TYPES[kind]
    vmax = kind_vmax if vmax is None else vmax
    box = xosc.BoundingBox(width, length, height, 0.0, 0.0, height / 2)
    dmax = round(min(dmax, mu * G), 3)
    if category == "pedestrian":
        return xosc.Pedestrian(name, mass, xosc.PedestrianCategory.pedestrian, box, model=kind)
    front = xosc.Axle(0.5, 0.7, max(width - 0.2, 0.3), 0.3 * length if length > 3 else 0.5 * length, 0.35)
    rear = xosc.Axle(0.0, 0.7, max(width - 0.2, 0.3), 0.0, 0.35)
    cat = getattr(xosc.VehicleCategory, category)
    return xosc.Vehicle(name, cat, box, front, rear, vmax, amax, dmax)


def _properties(values: dict[str, object]) -> xosc.Properties:
    props = xosc.Properties()
    for k, v in values.items():
        props.add_property(k, v if isinstance(v, str) else f"{v:g}")
    return props


def _lane_position(pose: placement.Pose) -> xosc.LanePosition:
    orient = xosc.Orientation(h=math.pi, reference=xosc.ReferenceContext.relative) if pose.wrong_way else None
    args = (round(pose.s, 3), round(pose.offset, 3), pose.lane_id, pose.road)
    return xosc.LanePosition(*args, orient) if orient is not None else xosc.LanePosition(*args)


def _environment(layers: dict) -> xosc.EnvironmentAction:
    env = layers["environment"]
    cloud, (ptype, intensity), fog, _ = WEATHER[env["weather"]["condition"]]
    hour, minute = (int(v) for v in env["time_of_day"].split(":"))
    sun_elevation = max(-0.5, math.sin(math.pi * (hour + minute / 60 - 6) / 12)) * 1.0
    weather = xosc.Weather(
        cloudstate=getattr(
            xosc.FractionalCloudCover, {"free": "zeroOktas", "overcast": "sevenOktas", "rainy": "eightOktas"}[cloud]
        ),
        sun=xosc.Sun(1000.0 if sun_elevation > 0 else 0.0, 0.0, round(sun_elevation, 3)),
        fog=xosc.Fog(fog),
        precipitation=xosc.Precipitation(getattr(xosc.PrecipitationType, ptype), intensity),
    )
    tod = xosc.TimeOfDay(False, 2025, 6, 1, hour, minute, 0)
    road = xosc.RoadCondition(round(friction(layers), 3))
    return xosc.EnvironmentAction(xosc.Environment("environment", tod, weather, road))


class _Anchor:
    """What the next element of a sequence waits for: an event in one of ``states`` (each its own
    condition group), for ``delay`` seconds."""

    def __init__(self, event: str, states: tuple, delay: float = 0.0) -> None:
        self.event, self.states, self.delay = event, states, delay


def _after(anchor: _Anchor, state, delay: float, label: str) -> xosc.ValueTrigger:
    """The condition that ``anchor``'s event has been in ``state`` for its delay plus ``delay`` s."""
    cond = xosc.StoryboardElementStateCondition(xosc.StoryboardElementType.event, anchor.event, state)
    return xosc.ValueTrigger(label, round(anchor.delay + delay, 3), xosc.ConditionEdge.none, cond)


def _condition(c: Condition, actor: str, name: str):
    if c.kind in ("ego_within", "ego_beyond"):
        rule = xosc.Rule.lessThan if c.kind == "ego_within" else xosc.Rule.greaterThan
        cond = xosc.RelativeDistanceCondition(
            round(c.value, 3), rule, xosc.RelativeDistanceType.longitudinal, actor, freespace=True
        )
        return xosc.EntityTrigger(name, 0, xosc.ConditionEdge.none, cond, c.entity)
    if c.kind == "ego_near":
        cond = xosc.RelativeDistanceCondition(
            round(c.value, 3), xosc.Rule.lessThan, xosc.RelativeDistanceType.euclidianDistance, actor, freespace=False
        )
        return xosc.EntityTrigger(name, 0, xosc.ConditionEdge.none, cond, c.entity)
    if c.kind == "time_gap":
        cond = xosc.TimeHeadwayCondition(actor, round(c.value, 3), xosc.Rule.lessThan, freespace=True)
        return xosc.EntityTrigger(name, 0, xosc.ConditionEdge.none, cond, c.entity)
    raise ValueError(f"unknown condition kind {c.kind!r}")


class _StoryBuilder:
    def __init__(self, actor: str, ctx: ActorContext) -> None:
        self.actor, self.ctx = actor, ctx
        self.maneuver = xosc.Maneuver(f"{actor}_behaviour")
        self.count = 0
        #: A controller (the social force model) a crossing switched on is in charge of the actor
        self.controlled = False

    def emit(self, node: dict, after: list[_Anchor]) -> list[_Anchor]:
        if "sequence" in node:
            for child in node["sequence"]:
                after = self.emit(child, after)
            return after
        if "parallel" in node:
            ends: list[_Anchor] = []
            for child in node["parallel"]:
                ends += self.emit(child, after)
            return ends
        mod = behaviour(node["behaviour"])
        cfg = dict(node.get("config", {}))
        steps = mod.compile(self.ctx, cfg)
        self.ctx.acted = True
        activates = [a for st in steps for a in st.actions if isinstance(a, xosc.ActivateControllerAction)]
        if self.controlled and steps and not activates:
            # what follows a ride the social force model steered (a stop after crossing) is the
            # scenario's to play: the model would hold the rider at its own pace
            steps[0].actions.insert(0, xosc.ActivateControllerAction(lateral=False, longitudinal=False))
            self.controlled = False
        self.controlled = self.controlled or bool(activates)
        self.ctx.routed = self.ctx.routed or any(
            isinstance(a, xosc.AssignRouteAction) for st in steps for a in st.actions
        )
        start = node.get("start", {})
        prev = after
        for i, step in enumerate(steps):
            self.count += 1
            name = f"{self.actor}_{self.count}_{step.name}"
            event = xosc.Event(name, xosc.Priority.parallel)
            for j, action in enumerate(step.actions):
                event.add_action(f"{name}_action{j + 1}", action)
            conditions = list(step.conditions)
            delay = step.delay_s
            if i == 0:
                delay += float(start.get("delay_s", 0.0))
                if "ego_within_m" in start:
                    conditions.append(Condition("ego_within", float(start["ego_within_m"])))
                if "ego_time_gap_s" in start:
                    conditions.append(Condition("time_gap", float(start["ego_time_gap_s"])))
            trigger = xosc.Trigger("start")
            # a held step is over hold_s after it started, whether its actions have ended by then
            # (a speed reached) or go on (following): its state then is complete or still running.
            # States last, so the step after it may wait on conditions of its own as well.
            choices = [[(a, s) for s in a.states] for a in prev]
            for g, combo in enumerate(itertools.product(*choices)):
                group = xosc.ConditionGroup()
                k = 0
                for anchor, state in combo:
                    k += 1
                    label = f"{name}_after{k}" + (f"_{g + 1}" if g else "")
                    group.add_condition(_after(anchor, state, delay, label))
                for c in conditions:
                    k += 1
                    group.add_condition(_condition(c, self.actor, f"{name}_when{k}" + (f"_{g + 1}" if g else "")))
                if k == 0 or (not prev and delay > 0):
                    cond = xosc.SimulationTimeCondition(round(delay, 3), xosc.Rule.greaterOrEqual)
                    group.add_condition(xosc.ValueTrigger(f"{name}_at", 0, xosc.ConditionEdge.none, cond))
                trigger.add_conditiongroup(group)
                if step.fallback_s is not None and conditions:  # or: its own conditions never held
                    late = xosc.ConditionGroup()
                    for j, (anchor, state) in enumerate(combo):
                        late.add_condition(
                            _after(anchor, state, delay + step.fallback_s, f"{name}_late{j + 1}_{g + 1}")
                        )
                    if not combo:
                        cond = xosc.SimulationTimeCondition(round(delay + step.fallback_s, 3), xosc.Rule.greaterOrEqual)
                        late.add_condition(xosc.ValueTrigger(f"{name}_late", 0, xosc.ConditionEdge.none, cond))
                    trigger.add_conditiongroup(late)
            event.add_trigger(trigger)
            self.maneuver.add_event(event)
            done, running = xosc.StoryboardElementState.completeState, xosc.StoryboardElementState.runningState
            if step.hold_s is not None:
                prev = [_Anchor(name, (done, running), step.hold_s)]
            else:
                prev = [_Anchor(name, (done,))]
        return prev


def _roads(layers: dict, stem: str) -> tuple[bytes, maps.MapInfo, str]:
    spec = layers["environment"]["map"]
    if spec["kind"] == "file":
        raise placement.PlacementError("map kind 'file' is given by path: use environment.map.file with vei describe")
    odr, info = maps.build_map(spec)
    element = odr.get_element()
    for signal in element.iter("signal"):  # scenariogeneration upper-cases the country; the XSD wants OpenDRIVE
        if signal.get("country") == "OPENDRIVE":
            signal.set("country", "OpenDRIVE")
    raw = finalize_opendrive(ET.tostring(element), f"{stem}", None, None)
    return raw, info, f"{stem}.xodr"


def _road_network(xodr_bytes: bytes) -> RoadNetwork:
    """The road model of the written map, for geometry questions (it reads files)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "map.xodr"
        path.write_bytes(xodr_bytes)
        return RoadNetwork.load(path)


def write_scenario(layers: dict, stem: str) -> WrittenScenario:
    """The scenario of ``layers`` as (xosc bytes, xodr bytes); the xosc refers to ``<stem>.xodr``
    beside it. Raises :class:`~vei_scenario.language.placement.PlacementError` (or ValueError) with
    the reason when the layers ask for what the map cannot hold."""
    mu = friction(layers)
    xodr_bytes, info, xodr_name = _roads(layers, stem)
    net: RoadNetwork | None = None

    ego = layers["ego"]
    ego_pose = placement.ego_pose(info, ego)
    ego_speed = float(ego["speed_mps"])
    entities = xosc.Entities()
    init = xosc.Init()
    cap = CapParameters(a_max_mps2=round(min(CapParameters.a_max_mps2, mu * G), 3))
    others = [a["name"] for a in layers["adversaries"]] + [
        f"Background{k + 1}" for k in range(len(layers["background"]["vehicles"]))
    ]
    if ego.get("agent", "cap") == "cap" and others:  # (alone on the road it simply drives on)
        props: dict[str, object] = {"enabled": "true", "cruiseSpeed": ego_speed, "followTimeGap": EGO_TIME_GAP_S}
        if layers["adversaries"]:
            props["threatEntity"] = layers["adversaries"][0]["name"]
        props["watchEntities"] = " ".join(others)
        props.update(cap.properties())
        controller = xosc.Controller("CollisionAvoidancePlanner", _properties(props))
        entities.add_scenario_object(EGO, _vehicle(EGO, EGO_KIND, mu), controller)
        init.add_init_action(EGO, xosc.ActivateControllerAction(lateral=False, longitudinal=True))
    else:
        entities.add_scenario_object(EGO, _vehicle(EGO, EGO_KIND, mu))
    init.add_init_action(EGO, xosc.TeleportAction(_lane_position(ego_pose)))
    init.add_init_action(EGO, xosc.AbsoluteSpeedAction(ego_speed, _step()))
    if info.exits:
        route = xosc.Route("Ego_route")
        route.add_waypoint(_lane_position(ego_pose), xosc.RouteStrategy.shortest)
        exit_road = info.exits[ego.get("route", "straight")]
        route.add_waypoint(xosc.LanePosition(40.0, 0, -ego_pose.lane_id, exit_road), xosc.RouteStrategy.shortest)
        init.add_init_action(EGO, xosc.AssignRouteAction(route))
    init.add_global_action(_environment(layers))
    for road, signal in sorted(info.signals.items()):
        green = road in (info.ego_road, info.entrances.get("opposite"))
        init.add_global_action(xosc.TrafficSignalStateAction(signal, GREEN if green else RED))

    story = xosc.Story("Behaviours")
    act = xosc.Act("behaviours")
    for adv in layers["adversaries"]:
        name, kind = adv["name"], adv["type"]
        pose = placement.adversary_pose(info, ego_pose, adv["spawn"])
        speed = float(adv.get("speed_mps", 0.0 if vulnerable(kind) else ego_speed))
        ctx = ActorContext(
            actor=name,
            actor_type=kind,
            ego=EGO,
            ego_speed_mps=ego_speed,
            actor_speed_mps=speed,
            ego_lane_id=ego_pose.lane_id,
            actor_lane_id=pose.lane_id,
            actor_road=pose.road,
            actor_s_m=pose.s,
            lanes=info.lanes,
            friction=mu,
            map_kind=info.kind,
            exits=info.exits,
            junction_end_s_m=info.feature_s_m,
            actor_max_accel_mps2=TYPES[kind][4],
            ego_s_m=ego_pose.s,
            actor_length_m=TYPES[kind][0][0],
            actor_exits=_own_exits(info, pose.road),
            facing=pose.facing,
            ego_route=str(ego.get("route", "straight")),
        )
        controller = None
        does = [n["behaviour"] for _, n in behaviour_nodes(adv["behaviour"])]
        # (parked beyond the far kerb, a cut-in comes across the oncoming lanes as a turn in does)
        ctx.pulls_out_across = does[0] == "cut_in" and cut_in.pulls_out_across(kind, adv["spawn"]["relation"], speed)
        at_kerb = adv["spawn"]["relation"].startswith("roadside") and vulnerable(kind) and not ctx.pulls_out_across
        # (one whose first move is a swerve swerves from the kerb lane's edge, and crosses from that lane
        # after it, if it does; one that crosses first crosses from the kerb)
        swerves = does[0] in SWERVES_FROM_KERB or (set(does) & set(SWERVES_FROM_KERB) and "cross_in_front" not in does)
        # (a rider at the kerb whose first act is running the red rides on along the road through the
        # junction, as placement has it: from the kerb lane's edge too, as its route must start on a lane of its way)
        rides_through = does[0] == "run_red_light"
        if at_kerb and (swerves or rides_through):
            # a rider at the kerb that swerves into the road (or a walker at the verge the text has move
            # along it): on the kerb lane's edge, where a lane change can start; one that gives way first
            # still stands there as at the kerb, its way across measured from there; at the left kerb (a
            # writer who keeps left), on the left edge of the ego's direction. One riding on through
            # the red, past an ego that may wait in the kerb lane, rides just over the edge line, where
            # a rider filters past a waiting car, not at arm's length from its door.
            margin = placement.FILTERING_MARGIN_M if rides_through else placement.KERB_MARGIN_M
            pose = placement.kerb_edge(pose, TYPES[kind][0][1], margin)
            ctx.actor_offset_m = pose.offset
            ctx.actor_lane_id = pose.lane_id  # (from the left kerb: a lane of the ego's direction; routes start there)
            at_kerb = "give_way" in does
        if at_kerb:
            net = net or _road_network(xodr_bytes)  # (only crossings ask the road model)
            road = net.road(pose.road)
            t0 = road.lane_center_t(pose.s, pose.lane_id) + pose.offset
            t_ego = road.lane_center_t(pose.s, ego_pose.lane_id)
            # across the whole road and on beyond the far kerb, so that the path outlasts the run
            path = [road.world(pose.s, t0 - f * t0) for f in (0.0, 2.0 + CROSSING_BEYOND_M / abs(t0))]
            heading = math.atan2(path[1][1] - path[0][1], path[1][0] - path[0][0])
            ctx.crossing_path = [(x, y, heading) for x, y, _ in path]
            ctx.crossing_distance_m = abs(t_ego - t0)
            rides_sfm = any(n.get("config", {}).get("agent") == "sfm" for _, n in behaviour_nodes(adv["behaviour"]))
            if kind in ("e-scooter", "bicycle") and rides_sfm:  # (assigned only where it is activated)
                controller = xosc.Controller(
                    "SocialForceModel",
                    _properties({"riderType": "normal", "route": f"{name}_crossing", "egoEntity": EGO, "v0_mps": 4.5}),
                )
            position = xosc.WorldPosition(round(path[0][0], 3), round(path[0][1], 3), 0, round(heading, 5))
        elif (does[0] == "turn_into" and adv["spawn"]["relation"].startswith("roadside")) or ctx.pulls_out_across:
            net = net or _road_network(xodr_bytes)
            start = cut_in.NOSED_OUT_RAD if ctx.pulls_out_across else math.pi / 2
            ctx.crossing_path, ctx.crossing_distance_m = _turn_in_path(net, pose, ego_pose.lane_id, start)
            x, y, heading = ctx.crossing_path[0]
            position = xosc.WorldPosition(round(x, 3), round(y, 3), 0, round(heading, 5))
        else:
            position = _lane_position(pose)
        # (where it starts is settled: a rider at the kerb edge is in the lane it swerves from)
        top = ctx.actor_max_speed_mps = top_speed(adv, ego_speed, ctx)
        if controller is not None:
            entities.add_scenario_object(name, _vehicle(name, kind, mu, top), controller)
        else:
            entities.add_scenario_object(name, _vehicle(name, kind, mu, top))
        init.add_init_action(name, xosc.TeleportAction(position))
        tree = adv["behaviour"]
        if does[0] == "overtake":  # (one closing in behind the ego pulls out before it speeds up past)
            tree = _overtaking_at(tree, ego_speed, speed, adv["spawn"]["relation"])  # (to its stated speed)
            speed = overtake.start_speed(ego_speed, speed, adv["spawn"]["relation"])
        init.add_init_action(name, xosc.AbsoluteSpeedAction(round(speed, 3), _step()))
        builder = _StoryBuilder(name, ctx)
        builder.emit(tree, [])
        group = xosc.ManeuverGroup(f"{name}_group")
        group.add_actor(name)
        group.add_maneuver(builder.maneuver)
        act.add_maneuver_group(group)
    for k, bg in enumerate(layers["background"]["vehicles"]):
        name = f"Background{k + 1}"
        entities.add_scenario_object(name, _vehicle(name, bg.get("type", "car"), mu))
        pose = placement.Pose(bg["road"], int(bg["lane"]), float(bg["s_m"]))
        init.add_init_action(name, xosc.TeleportAction(_lane_position(pose)))
        init.add_init_action(name, xosc.AbsoluteSpeedAction(float(bg["speed_mps"]), _step()))

    duration = float(layers.get("duration_s", DEFAULT_DURATION_S))
    stop = xosc.ConditionGroup()
    stop.add_condition(
        xosc.ValueTrigger(
            "duration", 0, xosc.ConditionEdge.rising, xosc.SimulationTimeCondition(duration, xosc.Rule.greaterThan)
        )
    )
    stop_trigger = xosc.Trigger("stop")
    stop_trigger.add_conditiongroup(stop)
    board = xosc.StoryBoard(init, stop_trigger)
    if layers["adversaries"]:
        story.add_act(act)
        board.add_story(story)
    network = xosc.RoadNetwork(roadfile=xodr_name)
    scenario = xosc.Scenario(
        plain_text(str(layers.get("description", "language scenario")))[:200] or "language scenario",
        AUTHOR,
        xosc.ParameterDeclarations(),
        entities,
        board,
        network,
        xosc.Catalog(),
        osc_minor_version=3,
        creation_date=dt.datetime(1970, 1, 1),
    )
    return WrittenScenario(render(scenario), xodr_bytes, [a["name"] for a in layers["adversaries"]])


def _turn_in_path(
    net: RoadNetwork, pose: placement.Pose, ego_lane_id: int, start_rad: float = math.pi / 2
) -> tuple[list, float]:
    """(world points with headings of the way a road user standing beside the ego's road at ``pose``
    turns into the ego's lane, its distance across to that lane's centre (m)): the path of
    :func:`~vei_scenario.language.behaviours.turn_into.roadside_path_st`, from facing ``start_rad`` off
    the road's direction (square across it by default) to facing the ego's way. Why a path: it comes
    onto the road across the kerb line, where no lane change can start, and from the far side it must
    turn to face the ego's way, not drive its lane's."""
    from vei_scenario.language.behaviours.turn_into import roadside_path_st

    road = net.road(pose.road)
    t0 = road.lane_center_t(pose.s, pose.lane_id) + pose.offset
    t_lane = road.lane_center_t(pose.s, ego_lane_id)
    points = [road.world(s, t)[:2] for s, t in roadside_path_st(pose.s, t0, t_lane, start_rad)]
    headings = [math.atan2(q[1] - p[1], q[0] - p[0]) for p, q in zip(points, points[1:])]
    return [(x, y, h) for (x, y), h in zip(points, headings + headings[-1:])], abs(t_lane - t0)


def _own_exits(info: maps.MapInfo, road: str) -> dict[str, str]:
    """The exits of a four-arm junction seen by a road user entering it from arm ``road`` (arms are
    numbered anticlockwise from the ego's, so straight on is two arms on, left one back, right one on)."""
    arms = sorted(set(info.entrances.values()) | {info.ego_road})
    if not info.exits or road not in arms or len(arms) != 4:
        return {}
    k = arms.index(road)
    return {"straight": arms[(k + 2) % 4], "left": arms[(k - 1) % 4], "right": arms[(k + 1) % 4]}


def _step() -> xosc.TransitionDynamics:
    return xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0.0)
