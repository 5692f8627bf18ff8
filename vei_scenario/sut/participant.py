"""An OSMP traffic participant in charge of an entity: each step it is shown the scene as an
``osi3.SensorView`` (and the storyboard's actions for it as an ``osi3.TrafficCommand``) and the
entity is put where its ``osi3.TrafficUpdate`` says, pose and velocity (both domains: the participant
moves itself, vei does not keep it on a path or lane).

The ground truth follows vei's OSI traces (:mod:`vei_scenario.reports.osi_trace`): every entity is an
object whose id is its index in the scenario's entity order; vehicles and pedestrians are moving
objects (with their OSI type: an e-scooter is ``TYPE_STANDUP_SCOOTER``), misc objects stationary
ones unless they move (:func:`moving_misc`: then moving objects of ``TYPE_OTHER``); poses are
bounding-box centres in the OpenDRIVE frame, the host vehicle id is the controlled entity's. The
OpenDRIVE road's lanes follow (:mod:`vei_scenario.reports.osi_lanes`: centre lines, types,
neighbours; ids after the entities'). The update's ``base.position`` is the box centre too.
"""

from __future__ import annotations

# (the entity ``e`` of the methods is an interpreter Entity and ``ctx`` its Context, not imported: the
# interpreter imports this package, not the other way round)
import math

from vei_scenario.sut.contract import ControllerFault
from vei_scenario.sut.participant_parameters import participant_properties
from vei_scenario.sut.spec import ControllerSpec, describe_exception

_SHAPES = {"linear": "DYNAMICS_SHAPE_LINEAR", "cubic": "DYNAMICS_SHAPE_CUBIC",
           "sinusoidal": "DYNAMICS_SHAPE_SINUSOIDAL", "step": "DYNAMICS_SHAPE_STEP"}  # fmt: skip
_UNSPECIFIED = "DYNAMICS_SHAPE_UNSPECIFIED"


def _timestamp(ts, t_s: float) -> None:
    ts.seconds, ts.nanos = divmod(int(round(t_s * 1e9)), 1_000_000_000)


class OsmpController:
    """The participant as a runtime controller of its entity (the interface of
    :class:`~vei_scenario.interpreter.controllers.Controller`)."""

    domains = ("longitudinal", "lateral")
    moves_last = False

    def __init__(self, name: str, props: dict[str, str], ctx, spec: ControllerSpec, entity: str) -> None:
        self.name, self.props, self.el = name, props, None
        self.spec, self.entity = spec, entity
        self.label = f"{entity}={spec.target}" if entity else spec.label
        self.ports = spec.load()
        self.properties = participant_properties(self.ports, props, ctx, self.label)
        self.impl = None
        self.ids: dict[str, int] = {}  # entity -> OSI id, once every entity is known (at the first step)
        self.names: dict[int, str] = {}
        self._static = None  # the map's reference and PROJ string
        self._lane_bytes: bytes | None = None
        self._commanded: dict[str, object] = {}  # domain -> the storyboard action last told
        self._action_id = 0
        self._moving_misc: set[str] = set()  # misc objects shown as moving objects (TYPE_OTHER)
        self.status = "osmp"

    def activated(self, e, ctx, domains: tuple[str, ...]) -> None:
        """It takes over from the entity's state when it first moves."""

    def finish(self) -> None:
        if self.impl is not None:
            self.impl.close()

    def instance(self):
        if self.impl is None:
            self.impl = self.spec.instantiate(self.label, self.properties)
        return self.impl

    # -- the messages --------------------------------------------------------------------------
    def sensor_view(self, e, ctx) -> bytes:
        """The scene at the step's start as a serialised ``osi3.SensorView`` (the others as
        coupling shows them: at the step's start under Jacobi coupling)."""
        from osi3 import osi_sensorview_pb2

        from vei_scenario.reports.osi_trace import classify_moving, geo_reference, interface_version

        version = interface_version()
        view = osi_sensorview_pb2.SensorView()
        view.version.CopyFrom(version)
        _timestamp(view.timestamp, ctx.t)
        view.host_vehicle_id.value = self.ids[e.name]
        gt = view.global_ground_truth
        gt.version.CopyFrom(version)
        _timestamp(gt.timestamp, ctx.t)
        gt.host_vehicle_id.value = self.ids[e.name]
        if ctx.road_file is not None:
            if self._static is None:
                self._static = (geo_reference(ctx.road_file), ctx.road_file.name)
            proj, ref = self._static
            if proj:
                gt.proj_string = proj
            gt.map_reference = ref
        for n, i in self.ids.items():
            o = e if n == e.name else ctx.observed(n)
            if o is None or o.deleted:
                continue
            x, y, yaw, length, width = o.box()
            if o.kind == "misc" and n not in self._moving_misc:
                obj = gt.stationary_object.add()
            else:
                obj = gt.moving_object.add()
                classify_moving(obj, o.kind, o.category, o.object_type, o.center_x)
                c, s = math.cos(yaw), math.sin(yaw)
                obj.base.velocity.x, obj.base.velocity.y = o.speed * c, o.speed * s
                obj.base.acceleration.x, obj.base.acceleration.y = o.accel * c, o.accel * s
            obj.id.value = i
            ref = obj.source_reference.add()  # (which entity it is, by the scenario's name)
            ref.type, ref.identifier[:] = "net.asam.openscenario", [n]
            b = obj.base
            b.dimension.length, b.dimension.width, b.dimension.height = length, width, o.height
            b.position.x, b.position.y, b.position.z = x, y, 0.5 * o.height
            b.orientation.yaw, b.orientation.pitch, b.orientation.roll = yaw, o.pitch, o.roll
        return view.SerializeToString() + self._lanes(ctx)

    def _lanes(self, ctx) -> bytes:
        """The road's lanes as the serialised part of a SensorView that holds only them (protobuf
        merges it into the step's view when appended to it): built once, ids after the entities'."""
        if self._lane_bytes is None:
            self._lane_bytes = b""
            if ctx.road_file is not None and ctx.road_file.is_file():
                from osi3 import osi_groundtruth_pb2, osi_sensorview_pb2

                from vei_scenario.reports.osi_lanes import lanes_bytes

                gt = osi_groundtruth_pb2.GroundTruth.FromString(lanes_bytes(ctx.road_file, len(self.ids)))
                if gt.lane:
                    view = osi_sensorview_pb2.SensorView()
                    view.global_ground_truth.CopyFrom(gt)
                    self._lane_bytes = view.SerializeToString()
        return self._lane_bytes

    def traffic_command(self, e, ctx) -> bytes:
        """The storyboard's actions for the entity that started since the last step, as OSI defines
        them: a SpeedAction (absolute target speed, shape, duration), a lane change (relative
        target lane, shape, duration or distance) and a FollowTrajectoryAction (its vertices as
        trajectory points with their simulation times where it is timed, else as path points)."""
        from osi3 import osi_trafficcommand_pb2

        from vei_scenario.reports.osi_trace import interface_version

        version = interface_version()
        cmd = osi_trafficcommand_pb2.TrafficCommand()
        cmd.version.CopyFrom(version)
        _timestamp(cmd.timestamp, ctx.t)
        cmd.traffic_participant_id.value = self.ids[e.name]
        action_cls = osi_trafficcommand_pb2.TrafficAction
        speed = e.longitudinal
        if speed is not None and speed is not self._commanded.get("longitudinal"):
            self._commanded["longitudinal"] = speed
            profile = e.speed_profile
            # (a SpeedAction: the longitudinal action with a speed target; duck-typed, as importing the
            # actions here would make the interpreter's modules import each other back)
            if profile is not None and getattr(speed, "target", (None,))[0] in ("absolute", "relative"):
                a = cmd.action.add().speed_action
                self._action_id += 1
                a.action_header.action_id.value = self._action_id
                a.absolute_target_speed = profile.v1
                a.dynamics_shape = action_cls.DynamicsShape.Value(_SHAPES.get(profile.shape, _UNSPECIFIED))
                if math.isfinite(profile.duration):
                    a.duration = profile.duration
        lateral = e.lateral
        if lateral is not None and lateral is not self._commanded.get("lateral"):
            self._commanded["lateral"] = lateral
            if hasattr(lateral, "target_lane") and lateral.target_lane != lateral.start_lane:
                a = cmd.action.add().lane_change_action
                self._action_id += 1
                a.action_header.action_id.value = self._action_id
                a.relative_target_lane = int(lateral.target_lane - lateral.start_lane)
                a.dynamics_shape = action_cls.DynamicsShape.Value(_SHAPES.get(lateral.shape, _UNSPECIFIED))
                if lateral.dimension == "time":
                    a.duration = lateral.value
                elif lateral.dimension == "distance":
                    a.distance = lateral.value
        follower = e.follower
        if follower is not None and follower is not self._commanded.get("path"):
            self._commanded["path"] = follower
            self._follow(cmd.action.add(), follower, e)
        return cmd.SerializeToString()

    def _follow(self, action, follower, e) -> None:
        """A FollowTrajectoryAction as ``follow_trajectory_action`` (timed: each vertex a trajectory
        point at the simulation time the timing plays it) or ``follow_path_action`` (untimed); each
        point the pose of the entity's bounding-box centre there, as every pose of vei's OSI messages."""
        from osi3 import osi_trafficcommand_pb2

        poly = follower.polyline
        if follower.plays_time:
            a = action.follow_trajectory_action
            points = a.trajectory_point
        else:
            a = action.follow_path_action
            points = a.path_point
        self._action_id += 1
        a.action_header.action_id.value = self._action_id
        modes = osi_trafficcommand_pb2.TrafficAction.FollowingMode
        a.following_mode = modes.Value(
            "FOLLOWING_MODE_FOLLOW" if follower.mode == "follow" else "FOLLOWING_MODE_POSITION"
        )
        a.constrain_orientation = True  # (vei heads the entity as the vertices do)
        for k in range(len(poly.xs)):
            h = poly.hs[k]
            p = points.add()
            if follower.plays_time:
                _timestamp(p.timestamp, follower.sim_time_of(poly.ts[k]))
            p.position.x = poly.xs[k] + math.cos(h) * e.center_x
            p.position.y = poly.ys[k] + math.sin(h) * e.center_x
            p.position.z = 0.5 * e.height
            p.orientation.yaw = h

    # -- the step ------------------------------------------------------------------------------
    def move(self, e, ctx, dt: float) -> bool:
        if not self.ids:
            self.ids = {n: i for i, n in enumerate(ctx.entities)}
            self.names = {i: n for n, i in self.ids.items()}
            self._moving_misc = moving_misc(ctx)
        impl = self.instance()
        view = self.sensor_view(e, ctx)
        command = self.traffic_command(e, ctx) if impl.ports.traffic_command is not None else None
        try:
            moved = impl.step(view, command, self.ids[e.name], ctx.t, dt, self.names)
        except ControllerFault:
            raise
        except Exception as exc:  # noqa: BLE001 (the participant's failure, said in one line)
            raise ControllerFault(self.label, f"step raised {describe_exception(exc)}", ctx.t) from None
        b = moved.base
        yaw = b.orientation.yaw if b.HasField("orientation") else e.yaw
        c, s = math.cos(yaw), math.sin(yaw)
        x0, y0, v0 = e.x, e.y, e.speed
        e.x, e.y, e.yaw = b.position.x - c * e.center_x, b.position.y - s * e.center_x, yaw
        if b.HasField("velocity"):
            v = _along(b.velocity.x * c + b.velocity.y * s)
        else:  # (the displacement over the step, along the heading)
            v = ((e.x - x0) * c + (e.y - y0) * s) / dt
        e.speed = v
        e.accel = _along(b.acceleration.x * c + b.acceleration.y * s) if b.HasField("acceleration") else (v - v0) / dt
        e.status = self.status
        return True


def _along(value: float) -> float:
    """A vector's component along the heading, rounded to 1e-12: a participant that writes ``a`` as
    ``(a cos yaw, a sin yaw)`` gets ``a`` back within a bit or two, and a threshold the built-in model
    meets exactly (a deceleration of 1 m/s², the brake onset) is met again."""
    return round(value, 12) + 0.0


def moving_misc(ctx) -> set[str]:
    """The misc objects that move in this run, as the SensorView can tell at its first step: those
    moving then (a speed, a trajectory) and those a storyboard action acts on. They are moving objects
    of ``TYPE_OTHER`` (a road user OpenSCENARIO has no class for, replayed from a clip), as in vei's
    OSI traces (which see the whole run); the others are stationary objects. Decided once, so an
    object keeps its kind and id for the whole run."""
    acted_on, seen, stack = set(), set(), list(ctx.elements.values())
    while stack:  # (every storyboard element and its children; names may repeat, elements do not)
        el = stack.pop()
        if id(el) in seen:
            continue
        seen.add(id(el))
        stack.extend(getattr(el, "children", ()))
        acted_on.update(a.entity for a in getattr(el, "actions", ()) if getattr(a, "entity", None))
    return {
        n
        for n, e in ctx.entities.items()
        if e.kind == "misc" and (n in acted_on or e.speed != 0.0 or e.follower is not None)
    }


def scenario_participant(name: str, props: dict[str, str], ctx, spec: ControllerSpec, entity: str) -> OsmpController:
    """A scenario ``Controller`` whose ``module`` property names an OSMP FMU: in charge of both domains
    as the storyboard assigns and activates it."""
    return OsmpController(name, {k: v for k, v in props.items() if k != "module"}, ctx, spec, entity)


def plug_osmp(ctx, spec: ControllerSpec, e) -> OsmpController:
    """Put the participant in charge of ``e`` for the whole run (both domains), in place of its
    controllers (their properties given to it, overridden by the spec's)."""
    props: dict[str, str] = {}
    for c in e.controllers.values():
        props.update(c.props)
    plugged = OsmpController(spec.target, props, ctx, spec, spec.entity)
    e.controllers = {plugged.name: plugged}
    e.active = {"longitudinal": plugged, "lateral": plugged}
    e.sut = plugged
    return plugged
