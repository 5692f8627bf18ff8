"""Runtime controllers, bound to entities by Assign/ActivateController actions.

A controller that is active for a domain moves its entity in :meth:`move` and returns True; returning
False leaves the entity to its default motion (trajectory replay, speed actions). The models
themselves are the pure functions of :mod:`vei_scenario.models`; here they only meet the entities.
New controllers register in ``CONTROLLERS`` by the OpenSCENARIO ``Controller`` name.
"""

from __future__ import annotations

import math

from vei_scenario.core import layout
from vei_scenario.core import row as core_row
from vei_scenario.interpreter.entities import Entity
from vei_scenario.interpreter.motion import advance_along, lane_keep
from vei_scenario.interpreter.positions import ensure_lane, lane_state_at
from vei_scenario.models.acc import AccParameters, acc_speed, box_gaps, bumper_gap, close_ahead
from vei_scenario.models.cap import BRAKE, CapParameters, CapState, ThreatView, cap_step, threat_in_corridor
from vei_scenario.models.rider import recorded_start_speed, rider_route
from vei_scenario.models.sfm import RIDER_TYPES, SfmParameters, SfmState, sfm_step
from vei_scenario.models.vehicle import Longitudinal, longitudinal_step
from vei_scenario.roads.road_model import RoadPoint


def threat_view(
    ego: Entity, threat: Entity, margin_m: float, ego_speed: float | None = None, horizon_s: float | None = None
) -> ThreatView:
    """Time until the threat's box meets the ego's path corridor: the ego box widened by ``margin_m``
    on each side and lengthened by it in front, both moving at constant velocity (the ego at
    ``ego_speed`` along its heading when given). With ``horizon_s``, inf where the boxes' circumscribed
    circles stay apart for longer (the planner treats any time beyond its horizon as no conflict), as
    the sweep kernel does: the box test is left out."""
    speed = ego.speed if ego_speed is None else ego_speed
    ego_box, threat_box, threat_velocity = ego.box(), threat.box(), threat.velocity()
    return threat_in_corridor(ego_box, speed, margin_m, threat_box, threat_velocity, horizon_s)


class Controller:
    domains: tuple[str, ...] = ()

    def __init__(self, name: str, props: dict[str, str], el, ctx) -> None:
        self.name, self.props, self.el = name, props, el

    #: Whether its entity moves after every other one in a step (Simulation's order of moves).
    moves_last = False

    def move(self, e: Entity, ctx, dt: float) -> bool:  # pragma: no cover - interface
        raise NotImplementedError

    def activated(self, e: Entity, ctx, domains: tuple[str, ...]) -> None:
        """Called when an action activates the controller on ``domains`` of ``e``: most take over from
        the entity's state when they first move."""


class SocialForceController(Controller):
    """The e-scooter rider: steers at waypoints of its recorded route with the social force model.
    ``riderType`` normal: destination and repulsion from the ego; aggressive: no repulsion; replay:
    the controller leaves the entity to its recorded trajectory."""

    domains = ("lateral", "longitudinal")

    def __init__(self, name, props, el, ctx) -> None:
        super().__init__(name, props, el, ctx)
        try:
            self.params = SfmParameters.from_properties(props)
        except ValueError as exc:
            raise ctx.error(el, f"SocialForceModel: {exc}") from None
        self.rider = props.get("riderType", "normal")
        if self.rider not in RIDER_TYPES:
            raise ctx.error(el, f"riderType {self.rider!r} is not one of {', '.join(RIDER_TYPES)}")
        self.ego_name = props.get("egoEntity", "Ego")
        self.route_name = props.get("route")
        self.route: list[tuple[float, float]] | None = None
        self.state: SfmState | None = None
        self.t_start = 0.0
        self.v_start = 0.0

    def _prepare(self, e: Entity, ctx) -> None:
        polyline = ctx.trajectories.get(self.route_name) if self.route_name else None
        if polyline is None and e.follower is not None:
            polyline = e.follower.polyline
        if polyline is None:
            raise ctx.error(self.el, f"SocialForceModel on {e.name}: no route (a 'route' property or a trajectory)")
        self.route = rider_route(polyline)
        f = e.follower
        if f is not None and f.timing is not None and polyline.timed:
            # Ride from the moment the recording starts, shifted like the replay would be.
            self.t_start = f.sim_time_of(polyline.ts[0])
            self.v_start = recorded_start_speed(polyline)
        else:
            self.t_start, self.v_start = ctx.t, e.speed
        if self.ego_name not in ctx.entities:
            raise ctx.error(self.el, f"SocialForceModel: no ego entity {self.ego_name!r}")

    def move(self, e: Entity, ctx, dt: float) -> bool:
        if self.rider == "replay":
            return False
        if self.route is None:
            self._prepare(e, ctx)
        if ctx.t + dt < self.t_start - 1e-9:  # not yet on the road: wait where the recording starts
            return False
        if self.state is None:
            self.state = SfmState(e.x, e.y, self.v_start * math.cos(e.yaw), self.v_start * math.sin(e.yaw))
        ego = ctx.observed(self.ego_name)
        old_speed = e.speed
        self.state = sfm_step(self.state, self.route, self.params, self.rider == "normal", ego.box(), dt)
        st = self.state
        speed = math.hypot(st.vx, st.vy)
        e.x, e.y, e.speed = st.x, st.y, speed
        if speed > 0.05:
            e.yaw = math.atan2(st.vy, st.vx)
        e.accel = (speed - old_speed) / dt
        e.status = f"sfm_{self.rider}"
        return True


class CollisionAvoidanceController(Controller):
    """The ego's collision-avoidance planner: longitudinal only; the path stays the followed one (or
    the lane, for an ego that drives by lane). It brakes for ``threatEntity`` and, when the property
    ``watchEntities`` lists more (space-separated), for whichever of them meets its corridor first."""

    domains = ("longitudinal",)

    def __init__(self, name, props, el, ctx) -> None:
        super().__init__(name, props, el, ctx)
        try:
            self.params = CapParameters.from_properties(props)
        except ValueError as exc:
            raise ctx.error(el, f"CollisionAvoidancePlanner: {exc}") from None
        self.enabled = props.get("enabled", "true") == "true"
        try:
            self.cruise = float(props.get("cruiseSpeed", "nan"))
        except ValueError:
            self.cruise = math.nan
        if not math.isfinite(self.cruise) or self.cruise < 0:
            raise ctx.error(el, "CollisionAvoidancePlanner needs a non-negative property cruiseSpeed")
        self.threat = props.get("threatEntity")
        self.watch = [n for n in props.get("watchEntities", "").split() if n != self.threat]
        if self.threat is None and not self.watch:
            raise ctx.error(el, "CollisionAvoidancePlanner needs a threatEntity or watchEntities")
        # optional adaptive cruise: follow the nearest watched entity ahead in the path at this time gap
        try:
            self.follow_gap_s = float(props.get("followTimeGap", "0") or 0)
        except ValueError:
            self.follow_gap_s = math.nan
        if not (math.isfinite(self.follow_gap_s) and 0 <= self.follow_gap_s <= 60):
            raise ctx.error(el, "CollisionAvoidancePlanner: followTimeGap must be a number of seconds in 0..60")
        self.state = CapState()
        self.held_command = 0.0  # Jacobi coupling: the command computed in the previous step

    def move(self, e: Entity, ctx, dt: float) -> bool:
        if not self.enabled:
            return False
        threats = []
        for name in ([self.threat] if self.threat is not None else []) + self.watch:
            other = ctx.observed(name)
            if other is None:
                raise ctx.error(self.el, f"CollisionAvoidancePlanner: {name!r} is not an entity")
            threats.append(other)
        margin, horizon = self.params.corridor_margin_m, self.params.horizon_s
        view = min((threat_view(e, t, margin, None, horizon) for t in threats), key=lambda v: v.time_to_conflict_s)
        resume = None
        if self.state.mode == BRAKE:
            resume = min(
                (threat_view(e, t, margin, self.cruise, horizon) for t in threats), key=lambda v: v.time_to_conflict_s
            )
        cruise = self._acc_target(e, threats) if self.follow_gap_s > 0 else self.cruise
        self.state, a_cmd, _ = cap_step(self.state, self.params, cruise, e.speed, view, dt, resume)
        if ctx.snapshot is not None:  # Jacobi: the vehicle gets this command at the next step
            a_cmd, self.held_command = self.held_command, a_cmd
        lon = longitudinal_step(Longitudinal(0.0, e.speed, e.accel), a_cmd, e.limits, dt)
        if e.follower is None:  # an ego that drives by lane keeps to it
            ensure_lane(ctx, e)
            if e.lane is not None:
                lane_keep(e, lon.s, ctx)
            else:
                advance_along(e, lon.s)
        elif advance_along(e, lon.s):  # (at its path's end it stands: vei_ego_drive)
            lon = Longitudinal(lon.s, 0.0, 0.0)
        e.speed, e.accel = lon.v, lon.a
        e.status = f"cap_{self.state.mode}"
        return True

    def _acc_target(self, e: Entity, others: list[Entity]) -> float:
        """The cruise target with adaptive cruise: the leader's speed plus a correction that closes the
        gap to ``d0 + v·followTimeGap`` in ``ACC_RELAX_S``; the cruise speed when nobody leads. The
        leader is the nearest entity whose box lies ahead of the ego and overlaps its path width."""
        c, s = math.cos(e.yaw), math.sin(e.yaw)
        best = None
        for o in others:
            dx, dy = o.x - e.x, o.y - e.y
            ahead, side = dx * c + dy * s, -dx * s + dy * c
            if ahead <= 0 or abs(side) > 0.5 * (e.width + o.width):
                continue
            gap = ahead - 0.5 * (e.length + o.length)
            if best is None or gap < best[0]:
                rel = math.cos(o.yaw - e.yaw)
                best = (gap, o.speed * rel)
        if best is None:
            return self.cruise
        gap, v_lead = best
        desired = self.params.d0_m + e.speed * self.follow_gap_s
        return max(0.0, min(self.cruise, v_lead + (gap - desired) / ACC_RELAX_S))


class AdaptiveCruiseController(Controller):
    """esmini's ``ACCController`` (longitudinal; ``ALKSController`` is
    :class:`LaneKeepingCruiseController`): follows the nearest road user ahead in its lane at a time
    gap, else holds its set speed (:mod:`vei_scenario.models.acc`). Properties as in
    esmini: ``timeGap`` (s), ``setSpeed`` (m/s), ``lateralDist`` (m), ``mode`` (``additive``, the
    default: the set speed is the speed it has when activated and whatever speed an action gives it
    later; ``override``: ``setSpeed`` when given)."""

    domains = ("longitudinal",)

    def __init__(self, name, props, el, ctx) -> None:
        super().__init__(name, props, el, ctx)
        kind = controller_kind(name, props)
        values = {}
        for prop, key, lo, hi in (
            ("timeGap", "time_gap_s", 0.0, 60.0),
            ("lateralDist", "lateral_dist_m", 0.0, 100.0),
            ("setSpeed", "set_speed", 0.0, 1000.0),
        ):
            if prop in props:
                try:
                    v = float(props[prop])
                except (TypeError, ValueError):
                    v = math.nan
                if not (math.isfinite(v) and lo <= v <= hi):
                    raise ctx.error(el, f"{kind}: property {prop} must be a number in {lo:g}..{hi:g}")
                values[key] = v
        self.given_set_speed = values.pop("set_speed", None)
        self.params = AccParameters(**values)
        mode = props.get("mode", "additive")
        if mode not in ("additive", "override"):
            raise ctx.error(el, f"{kind}: property mode must be additive or override, not {mode!r}")
        self.additive = mode == "additive"
        if props.get("virtual", "false") != "false":
            raise ctx.error(el, f"{kind}: virtual mode (acceleration reported, not applied) is not supported")
        self.current = 0.0  # the speed it commands (m/s), from its activation on
        self.set_speed = 0.0
        self.first_step = -1  # the step it was activated in

    def activated(self, e: Entity, ctx, domains: tuple[str, ...]) -> None:
        self.first_step = ctx.step
        self.current = e.speed
        if self.additive or self.given_set_speed is None:
            self.set_speed = e.speed
        else:
            self.set_speed = self.given_set_speed
        if "lateral" in domains:  # along its lane, whichever way it drives
            ensure_lane(ctx, e)
            if e.lane is not None:
                e.lane.heading = 0.0

    def move(self, e: Entity, ctx, dt: float) -> bool:
        if ctx.step == self.first_step:  # (esmini steps a controller from the step after its activation)
            return False
        if self.additive and abs(e.speed - self.current) > 1e-3:  # an action set a speed: the set speed now
            self.set_speed = e.speed  # (overriding, the controller is deaf to speed actions, as in esmini)
        lim = e.limits
        v = acc_speed(self.params, self.current, self.set_speed, self._leader(e, ctx), lim.max_accel_mps2,
                      lim.max_decel_mps2, dt)  # fmt: skip
        self.current = v
        e.accel = (v - e.step_speed) / dt
        e.speed = v
        if e.follower is None:
            ensure_lane(ctx, e)
        if e.lane is not None and e.follower is None:
            lane_keep(e, v * dt, ctx)
        else:
            advance_along(e, v * dt)
        e.status = "acc"
        return True

    def core_columns(self, e: Entity, ctx, index: dict[str, int], sequential: bool) -> list[float] | None:
        """This cruise's columns for the core's quiet stretches (core_module.c: ACC_COLUMNS; ``index``: each
        road user's row), or None where the core does not step it: its road user off a lane or on a path
        (a SpeedAction's transition left on it is not read, as :meth:`move` does not). The core follows
        the leader as :meth:`_leader` does while every road user keeps its lane; it stops before a step
        where it could not tell (a road user changing lanes or off the lanes, the search ahead reaching
        the next road)."""
        if e.lane is None or e.follower is not None or ctx.step == self.first_step:
            return None
        road = ctx.roads.road(e.lane.road)
        linked = (road.successor if e.lane.forward else road.predecessor) is not None
        p, lim = self.params, e.limits
        values = {"ENTITY": index[e.name], "CURRENT": self.current, "SET_SPEED": self.set_speed,
                  "MAX_ACCEL": lim.max_accel_mps2, "MAX_DECEL": lim.max_decel_mps2,
                  "ADDITIVE": float(self.additive), "SEQUENTIAL": float(sequential), "LAST": float(self.moves_last),
                  "LINKED": float(linked),
                  "TIME_GAP": p.time_gap_s, "LATERAL_DIST": p.lateral_dist_m, "MIN_GAP": p.min_gap_m,
                  "APPROACH_GAIN": p.approach_gain, "DISTANCE_GAIN": p.distance_gain_mps2,
                  "STOP_GAP": p.stop_gap_m}  # fmt: skip
        return core_row("acc", values)

    @property
    def moves_last(self) -> bool:
        """In override mode esmini's cruise moves its entity itself, in the controller's step, after every
        other entity has moved (measured: acc-test plays within 1e-4 m so, 0.15 m in the entities'
        order); in additive mode it sets the speed and the entity moves in its turn."""
        return not self.additive

    def take_core_columns(self, columns) -> None:
        """The speed it commands and its set speed as the core's quiet steps left them."""
        self.current, self.set_speed = columns[_ACC["CURRENT"]], columns[_ACC["SET_SPEED"]]

    def _leader(self, e: Entity, ctx) -> tuple[float, float] | None:
        """(bumper-to-bumper gap, speed) of the road user it follows: the nearest one ahead in its
        lane within the look-ahead (along the lanes, reference points within ``lateralDist`` across),
        overridden by one right in front of its box (:func:`~vei_scenario.models.acc.close_ahead`)."""
        p, net = self.params, ctx.roads
        here = e.lane if e.lane is not None else (lane_state_at(net, e) if net is not None else None)
        if here is not None:  # (across the road: the lane's centre and its offset from it)
            my_t = net.road(here.road).lane_center_t(here.s, here.lane) + here.offset
        limit = p.lookahead_m(self.current, e.limits.max_decel_mps2)
        best: tuple[float, float] | None = None
        own_box = e.box()
        for o in ctx.entities.values():
            if o is e or o.deleted:
                continue
            o = ctx.observed(o.name)
            if here is not None:
                there = _road_point(net, o)
                if there is not None and there.lane is not None and abs(there.t - my_t) < p.lateral_dist_m:
                    ds = net.distance_along_lane(here.road, here.lane, here.s, here.forward, there, limit)
                    if ds is not None:
                        same_way = abs(math.remainder(o.yaw - e.yaw, 2 * math.pi)) < 0.5 * math.pi
                        gap = bumper_gap(ds, e.length, e.center_x, o.length, o.center_x, same_way)
                        if 0.0 < gap and (best is None or gap < best[0]):
                            best = (gap, o.speed)
                            continue
            x_gap, y_gap = box_gaps(own_box, o.box())
            if close_ahead(x_gap, y_gap, o.length, self.current - o.speed):
                best = (x_gap, o.speed)
        return best


def _road_point(net, e) -> RoadPoint | None:
    """Where ``e`` is on the road network: from its lane state while it keeps a lane (the lane it was
    placed in or changed to, as esmini keeps it: a car on a lane border stays in its lane), else, and
    while it changes lanes (it is in the lane its reference point is in), by projecting its position."""
    st = e.lane
    if st is None or e.lateral is not None:
        return net.project(e.x, e.y)
    road = net.road(st.road)
    return RoadPoint(road, st.s, road.lane_center_t(st.s, st.lane) + st.offset, st.lane, 0.0)


class LaneKeepingCruiseController(AdaptiveCruiseController):
    """esmini's ``ALKSController``: the adaptive cruise, in charge of the lateral domain too, where it
    keeps the lane offset it has (lane keeping as the default motion does it)."""

    domains = ("lateral", "longitudinal")


#: The core's columns of an adaptive cruise (core_module.c: ACC_COLUMNS).
_ACC = layout("acc")

#: Time in which the adaptive cruise closes a gap error (s).
ACC_RELAX_S = 3.0

CONTROLLERS = {
    "SocialForceModel": SocialForceController,
    "CollisionAvoidancePlanner": CollisionAvoidanceController,
    "ACCController": AdaptiveCruiseController,
    "ALKSController": LaneKeepingCruiseController,
}


class DefaultController(Controller):
    """A controller that names no model, neither vei's nor esmini's: a description of the driver (the
    ASAM example scenarios give their cars ``HAF_Driver`` and ``Default_Driver`` with weight, age and
    eye distance) or a model of a tool vei does not know. The entity keeps the default controller, the
    one esmini falls back to for a controller type it does not know; the run says so in a warning.
    It takes no domain, so activating it changes nothing."""

    domains = ()


class UnmodelledController(Controller):
    """One of esmini's own models that vei does not have (ESMINI_ONLY). Assigned and never activated
    it has no effect, in esmini as here (measured with esmini 3.6: pedestrian_traj_synch.xosc, whose
    Ego is given an InteractiveController it never activates, plays the same without it); the run
    stops with one line when an action activates it, since esmini would then drive the entity by it."""

    domains = ("lateral", "longitudinal")

    def __init__(self, name, props, el, ctx, kind: str) -> None:
        super().__init__(name, props, el, ctx)
        self.kind = kind

    def activated(self, e: Entity, ctx, domains: tuple[str, ...]) -> None:
        raise ctx.error(self.el, f"{_unsupported(self.kind)}; {e.name}'s is activated at t = {ctx.t:.2f} s")


def _unsupported(kind: str) -> str:
    return f"controller {kind!r} (an esmini model) is not supported by vei run (supported: {', '.join(CONTROLLERS)})"


#: The controller types esmini 3.6 has models of that vei does not: a scenario that activates one is
#: refused, since esmini would drive its entity by that model (measured: esmini falls back to the
#: default controller for any other name). SumoController: esmini built with SUMO.
ESMINI_ONLY = frozenset(
    {
        "ALKS_R157SM_Controller", "ControllerRel2Abs", "ECE_ALKS_RefDriverController", "ExternalController",
        "FollowGhostController", "FollowReferenceController", "FollowRouteController", "HIDController",
        "InteractiveController", "LoomingController", "NaturalDriver", "OffroadFollower", "SloppyDriverController",
        "SumoController", "UDPDriverController",
    }
)  # fmt: skip
#: Of those, the ones that act without being activated: esmini's SUMO controller adds and drives the
#: vehicles of a SUMO simulation from the start.
ACTS_UNACTIVATED = frozenset({"SumoController"})


def controller_kind(name: str, props: dict[str, str]) -> str:
    """The kind of controller a ``<Controller>`` is: its ``esminiController`` property, else its name
    (esmini's rule)."""
    return props.get("esminiController") or name


def make_controller(el, ctx) -> Controller:
    """A runtime controller from a ``<Controller>`` element: the kind its ``esminiController`` property
    names (esmini's rule), else its name. One of esmini's own models vei lacks is refused when it is
    activated (:class:`UnmodelledController`), or at once if it acts without (ACTS_UNACTIVATED); any
    other name is the default controller, with a warning (:class:`DefaultController`)."""
    name = el.get("name", "")
    props = {p.get("name"): p.get("value") for p in el.iterfind("Properties/Property")}
    if props.get("module"):  # the user's own (CARLA ScenarioRunner's convention)
        from vei_scenario.interpreter.plugged import scenario_controller

        return scenario_controller(name, props, el, ctx)
    kind = controller_kind(name, props)
    cls = CONTROLLERS.get(kind)
    if cls is None and kind in ACTS_UNACTIVATED:  # (named in the file it comes from: the scenario, or its catalog)
        raise ctx.error(el, _unsupported(kind))
    if cls is None and kind in ESMINI_ONLY:
        ctx.warn(el, f"controller {kind!r} (an esmini model vei run does not have): the run stops if it is activated")
        return UnmodelledController(name, props, el, ctx, kind)
    if cls is None:
        ctx.warn(el, f"controller {kind!r} names no model vei run has: it plays as the default controller (esmini's)")
        return DefaultController(name, props, el, ctx)
    return cls(name, props, el, ctx)
