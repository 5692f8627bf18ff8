"""Actions: built from the XML once, then started, stepped and stopped by the engine.

Teleport, Speed, LaneChange, LaneOffset, AssignRoute, AcquirePosition, FollowTrajectory, controller
and parameter actions, traffic signal states; LongitudinalDistance lives in ``longitudinal.py``. The
README lists what each supports; anything else is refused with its line.
"""

from __future__ import annotations

import bisect
import math

from vei_scenario.core import row as core_row
from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter.action_base import Action
from vei_scenario.interpreter.clock import step_time
from vei_scenario.interpreter.controllers import make_controller
from vei_scenario.interpreter.entities import PathFollower, SpeedProfile, lane_change_turn, transition_fraction
from vei_scenario.interpreter.positions import POSITION_KINDS, entity_lane, lane_id, lane_shift, lane_state_at, tilt
from vei_scenario.interpreter.positions import resolve as resolve_position
from vei_scenario.interpreter.shapes import placed_when_built, polyline_from
from vei_scenario.safe_xml import first_element


class Teleport(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        pos = el.find("Position")
        kind = first_element(pos) if pos is not None else None
        if kind is None or kind.tag not in SUPPORTED_POSITIONS:
            raise ctx.error(
                el, f"TeleportAction position <{kind.tag if kind is not None else 'none'}> is not supported"
            )
        self.entity, self.pos = entity, pos

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        pose = resolve_position(ctx, self.pos)  # relative positions are taken when the action starts
        e.x, e.y, e.yaw, e.lane = pose.x, pose.y, pose.h, pose.lane
        e.pitch, e.roll = tilt(ctx, self.pos)
        # placed by world coordinates: it takes up the lane it is on when it first drives by default
        e.find_lane = e.lane is None and ctx.road_file is not None
        f = e.follower
        if ctx.initializing and f is not None and f.timing is None and f.polyline.xs is not None:
            # a path assigned in Init stays (esmini): the teleport only says where on it to start
            f.s = f.polyline.project(e.x, e.y)
            e.lane, e.find_lane = None, False
        else:
            e.follower = None
        e.lateral = None
        e.placed = not ctx.initializing  # esmini leaves a teleported entity where it put it for this step
        self.done = True


#: The position kinds a TeleportAction takes: all of OpenSCENARIO 1.3's but GeoPosition.
SUPPORTED_POSITIONS = POSITION_KINDS - {"GeoPosition"}


class LaneChangeRuntime:
    """A lateral transition from the lane the entity was in to the target lane (and target offset)."""

    def __init__(
        self,
        start_lane: int,
        start_offset: float,
        target_lane: int,
        target_offset: float,
        shape: str,
        dimension: str,
        value: float,
        t0: float,
        odo0: float,
        projects_step: bool = True,
        steps_ahead: int = 1,
    ) -> None:
        """``projects_step``: s advances by the along-road part of each step (esmini's lane change; its
        lane offset keeps the full step). ``steps_ahead``: the progress over time applied in a step is that at
        its end (1, lane change) or at its start (0, lane offset: no motion in the first step)."""
        self.start_lane, self.start_offset = start_lane, start_offset
        self.target_lane, self.target_offset = target_lane, target_offset
        self.shape, self.dimension, self.value = shape, dimension, value
        self.t0, self.odo0 = t0, odo0
        self.fraction = 0.0
        self.projects_step, self.steps_ahead = projects_step, steps_ahead
        self.prev_xy: tuple[float, float] | None = None  # where the entity was a step ago
        self.start_rel: float | None = None  # its start, from the target lane's centre
        #: a lane change over distance: how far along the road it has come (its steps' along-road parts)
        self.param = 0.0
        #: its action's place in the storyboard (Context.acting)
        self.order = 0.0

    def pause(self, dt: float) -> None:
        """A step in which the transition does not progress (its road user stands): one over time
        ends that much later; one over distance waits for the road user anyway."""
        self.t0 += dt

    def progress(self, e, ctx) -> float:
        if self.value <= 0 or self.shape == "step":
            return 1.0
        if self.dimension == "time":
            done = ctx.t + self.steps_ahead * ctx.dt - self.t0
        else:
            done = self.param if self.projects_step else e.odometer - self.odo0
        return min(max(done / self.value, 0.0), 1.0)

    def step_heading(self, ds: float, ctx) -> float:
        """A lane change's heading in a step of ``ds`` metres, from its lane's direction (towards
        increasing t), as esmini 3.6 steps it (:func:`~vei_scenario.interpreter.entities.lane_change_turn`:
        from the lateral rate where the step starts); over distance its progress then advances by the
        step's along-road part, ``|ds|·cos(heading)``."""
        if self.value <= 0 or self.shape == "step" or self.start_rel is None:
            return 0.0
        by_time = self.dimension == "time"
        done = ctx.t + (self.steps_ahead - 1) * ctx.dt - self.t0 if by_time else self.param
        x = min(max(done / self.value, 0.0), 1.0)
        h = lane_change_turn(self.shape, by_time, self.target_offset - self.start_rel, self.value, x, ctx.dt, ds)
        if not by_time:
            self.param += abs(ds) * math.cos(h)
        return h

    #: (road, section index) the start and target lane ids belong to (set by the action)
    start_where: tuple[str, int] | None = None
    target_where: tuple[str, int] | None = None

    def _t(self, road, s: float, lane: int, where: tuple[str, int] | None) -> float:
        if where is not None and where[0] == road.id and where[1] < len(road.sections):
            return road.lane_center_t_in(where[1], s, lane)
        return road.lane_center_t(s, lane)

    def offset(self, e, ctx, road) -> float:
        """Offset from the centre of the entity's current lane at its current s."""
        try:
            return self._offset(e, ctx, road)
        except KeyError:  # (a road whose lanes do not go on where the transition does)
            raise VeiInputError(
                ctx.path,
                f"t={ctx.t:g} s",
                f"a lateral transition to lane {self.target_lane} reached road {road.id!r} at s={e.lane.s:g}, "
                f"where that lane or the road user's lane {e.lane.lane} is not (the road's lanes do not link)",
            ) from None

    def _offset(self, e, ctx, road) -> float:
        s = e.lane.s
        c_target = self._t(road, s, self.target_lane, self.target_where)
        if self.start_rel is None:  # where it starts, measured from the target lane's centre (esmini)
            try:
                t_start = self._t(road, s, self.start_lane, self.start_where) + self.start_offset
            except KeyError:
                t_start = c_target + self.start_offset
            self.start_rel = t_start - c_target
        self.fraction = self.progress(e, ctx)
        f = transition_fraction(self.shape, self.fraction)
        # the offset from the target lane's centre goes from where it started to the target offset,
        # wherever that centre moves meanwhile (a lane that widens from zero)
        return c_target + (1 - f) * self.start_rel + f * self.target_offset - road.lane_center_t(s, e.lane.lane)

    def heading(self, e, base: float) -> float:
        """During the transition the entity heads where it moves (``base`` on the first step)."""
        prev, self.prev_xy = self.prev_xy, (e.x, e.y)
        if self.fraction >= 1.0 or prev is None:
            return base
        dx, dy = e.x - prev[0], e.y - prev[1]
        return math.atan2(dy, dx) if math.hypot(dx, dy) > 1e-6 else base


class LaneChange(Action):
    """LaneChangeAction: to an absolute lane or one relative to an entity's, over time or distance."""

    def __init__(self, entity: str, el, ctx) -> None:
        self.entity, self.el = entity, el
        dyn = el.find("LaneChangeActionDynamics")
        self.shape = dyn.get("dynamicsShape")
        self.dimension = dyn.get("dynamicsDimension")
        self.value = float(dyn.get("value"))
        if self.shape not in ("step", "linear", "cubic", "sinusoidal") or self.dimension not in (
            "time",
            "distance",
            "rate",
        ):
            raise ctx.error(dyn, f"lane change dynamics {self.shape}/{self.dimension} are not supported")
        target = first_element(el.find("LaneChangeTarget"))
        self.target = target
        self.target_offset = float(el.get("targetLaneOffset", "0") or 0)
        if target is None or target.tag not in ("AbsoluteTargetLane", "RelativeTargetLane"):
            raise ctx.error(el, "LaneChangeTarget must be AbsoluteTargetLane or RelativeTargetLane")

    def start(self, ctx) -> None:
        e, st = entity_lane(ctx, self.el, self.entity)
        e.lane = st
        e.follower = None
        st.heading = 0.0  # a lateral transition ends heading along the lane
        road = ctx.roads.road(st.road)
        here = road.section_index(st.s)
        if self.target.tag == "AbsoluteTargetLane":
            lane, where = lane_id(ctx, self.target, "value"), (road.id, here)
        else:
            _, ref = entity_lane(ctx, self.el, self.target.get("entityRef"))
            lane = lane_shift(ref.lane, lane_id(ctx, self.target, "value"), ref.forward)
            where = (ref.road, ctx.roads.road(ref.road).section_index(ref.s))
        if lane == 0 or not _lane_exists(ctx.roads, st.road, lane, ref_where=where):
            raise ctx.error(self.el, f"LaneChangeAction: road {st.road} has no lane {lane} here")
        dimension, value = self.dimension, self.value
        if dimension == "rate":  # a peak lateral speed (m/s): the time the shape needs at it (esmini)
            span = (
                abs(
                    road.lane_center_t_in(where[1], st.s, lane)
                    + self.target_offset
                    - road.lane_center_t(st.s, st.lane)
                    - st.offset
                )
                if where[0] == road.id
                else 0.0
            )
            dimension, value = "time", (PEAK_RATE[self.shape] * span / self.value if self.value > 0 else 0.0)
        e.lateral = LaneChangeRuntime(
            st.lane,
            st.offset,
            lane,
            self.target_offset,
            self.shape,
            dimension,
            value,
            ctx.t,
            e.odometer,
        )
        e.lateral.start_where, e.lateral.target_where = (road.id, here), where
        e.lateral.order = ctx.acting
        # the entity now keeps the target lane, named as in its own lane section where it has a name
        mapped = road.map_lane(lane, where[1], here) if where[0] == road.id else None
        if mapped is not None or lane in road.section(st.s).lanes:
            e.lane.lane = mapped if mapped is not None else lane
        e.lane.offset = e.lateral.offset(e, ctx, road)

    def update(self, ctx) -> None:
        e = ctx.entities[self.entity]
        self.done = e.lateral is None or e.lateral.fraction >= 1.0
        if self.done and e.lateral is not None:
            rt, road = e.lateral, ctx.roads.road(e.lane.road)
            if rt.target_where is not None and rt.target_where[0] == road.id:
                mapped = road.map_lane(rt.target_lane, rt.target_where[1], road.section_index(e.lane.s))
                if mapped is not None:
                    e.lane.lane = mapped
            e.lane.offset = self.target_offset
            e.lateral = None

    def stop(self, ctx) -> None:
        ctx.entities[self.entity].lateral = None

    def carried(self, ctx) -> bool:
        return _lateral_carried(ctx, self.entity)


def _lateral_carried(ctx, entity: str) -> bool:
    """A lane change or lane offset under way: the core shifts its entity sideways as the runtime
    would (cruise._lateral says where it can) and stops before the step that completes it, whose
    evaluation would end the action."""
    rt = ctx.entities[entity].lateral
    return rt is not None and rt.fraction < 1.0


def _lane_exists(net, road_id: str, lane: int, ref_where: tuple[str, int]) -> bool:
    """Whether ``lane`` exists on the reference's road (``ref_where``) in any lane section — a lane
    change to a lane the road does not have is refused, not guessed."""
    road = net.road(ref_where[0])
    return any(lane in sec.lanes for sec in road.sections)


#: The lateral acceleration a LaneOffsetAction without maxLateralAcc is shaped to (m/s²; esmini 3.6).
DEFAULT_MAX_LATERAL_ACC = 0.5


class LaneOffset(Action):
    """LaneOffsetAction: to an absolute offset from the lane centre, or relative to another entity's,
    shaped so the lateral acceleration peaks at ``maxLateralAcc`` (esmini's reading: the transition
    time follows from the offset change and that limit)."""

    def __init__(self, entity: str, el, ctx) -> None:
        self.entity, self.el = entity, el
        dyn = el.find("LaneOffsetActionDynamics")
        self.shape = dyn.get("dynamicsShape", "sinusoidal")
        # (without one, esmini 3.6's default: measured the same as 0.5 written out)
        self.max_acc = float(dyn.get("maxLateralAcc") or DEFAULT_MAX_LATERAL_ACC)
        if self.shape not in ("step", "linear", "cubic", "sinusoidal"):
            raise ctx.error(dyn, f"lane offset dynamicsShape {self.shape!r} is not supported")
        target = first_element(el.find("LaneOffsetTarget"))
        if target is None or target.tag not in ("AbsoluteTargetLaneOffset", "RelativeTargetLaneOffset"):
            raise ctx.error(el, "LaneOffsetTarget must be AbsoluteTargetLaneOffset or RelativeTargetLaneOffset")
        self.target = target

    def _duration(self, change: float) -> float:
        if self.shape == "step" or change == 0.0 or self.max_acc <= 0.0:
            return 0.0
        if self.shape == "sinusoidal":  # a = (Δ/2)(π/T)² at the ends
            return math.pi * math.sqrt(change / (2.0 * self.max_acc))
        # cubic: a = 6Δ/T² at the ends; linear, whose acceleration is unbounded at its corners, takes
        # the cubic's time (esmini 3.6)
        return math.sqrt(6.0 * change / self.max_acc)

    def start(self, ctx) -> None:
        e, st = entity_lane(ctx, self.el, self.entity)
        e.lane, e.follower = st, None
        st.heading = 0.0
        value = float(self.target.get("value"))
        if self.target.tag == "RelativeTargetLaneOffset":
            _, ref = entity_lane(ctx, self.el, self.target.get("entityRef"))
            value += ref.offset
        self.goal = value
        duration = self._duration(abs(value - st.offset))
        e.lateral = LaneChangeRuntime(
            st.lane, st.offset, st.lane, value, self.shape, "time", duration, ctx.t, e.odometer, False, 0
        )
        e.lane.offset = e.lateral.offset(e, ctx, ctx.roads.road(st.road))

    def update(self, ctx) -> None:
        e = ctx.entities[self.entity]
        if e.lateral is not None and e.lateral.fraction >= 1.0:
            e.lane.offset = self.goal
            e.lateral = None
        # ends when the offset is reached, continuous or not (esmini: the entity keeps the offset)
        self.done = e.lateral is None

    def stop(self, ctx) -> None:
        ctx.entities[self.entity].lateral = None

    def carried(self, ctx) -> bool:
        return _lateral_carried(ctx, self.entity)


class AssignRoute(Action):
    """AssignRouteAction: the entity takes the route's roads at junctions from now on."""

    def __init__(self, entity: str, el, ctx) -> None:
        self.entity, self.el = entity, el

    def start(self, ctx) -> None:
        from vei_scenario.interpreter.positions import route_from

        ctx.entities[self.entity].route = route_from(ctx, self.el.find("Route"), self.el)
        self.done = True


class AcquirePosition(Action):
    """AcquirePositionAction: a route from where the entity is to the position, taken at junctions."""

    def __init__(self, entity: str, el, ctx) -> None:
        self.entity, self.el = entity, el
        if el.find("Position") is None:
            raise ctx.error(el, "AcquirePositionAction needs a Position")

    def start(self, ctx) -> None:
        from vei_scenario.interpreter.routes import plan_route

        e, st = entity_lane(ctx, self.el, self.entity)
        goal = resolve_position(ctx, self.el.find("Position"))
        if goal.lane is None:
            raise ctx.error(self.el, "AcquirePositionAction: the position is not on a lane")
        e.lane = st
        goal_road = ctx.roads.road(goal.lane.road)
        e.route = plan_route(
            ctx.roads,
            [(st.road, st.s, st.forward), (goal_road.id, goal.lane.s, goal_road.drives_forward(goal.lane.lane))],
        )
        self.done = True


class Ignored(Action):
    """An action with no effect on motion or on what vei measures (appearance, visibility)."""

    def __init__(self, *_args) -> None:
        self.done = True


#: Peak rate of a unit transition over unit time, per dynamicsShape (the slope of transition_fraction).
PEAK_RATE = {"linear": 1.0, "cubic": 1.5, "sinusoidal": math.pi / 2, "step": 0.0}


class Speed(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        self.entity = entity
        dyn = el.find("SpeedActionDynamics")
        target = el.find("SpeedActionTarget")
        self.shape = dyn.get("dynamicsShape")
        self.dimension = dyn.get("dynamicsDimension")
        self.value = float(dyn.get("value"))
        if self.shape not in ("step", "linear", "cubic", "sinusoidal"):
            raise ctx.error(dyn, f"dynamicsShape {self.shape!r} is not supported")
        absolute, relative = target.find("AbsoluteTargetSpeed"), target.find("RelativeTargetSpeed")
        if absolute is not None:
            self.target = ("absolute", float(absolute.get("value")), None, None)
        elif relative is not None:
            self.continuous = relative.get("continuous", "false") == "true"
            ref = relative.get("entityRef")
            if ref not in ctx.entities:
                raise ctx.error(relative, f"no entity named {ref!r}")
            self.target = ("relative", float(relative.get("value")), ref, relative.get("speedTargetValueType"))
        else:
            raise ctx.error(target, "SpeedActionTarget without a target speed")

    continuous = False  # RelativeTargetSpeed continuous="true": keep following the reference's speed

    @property
    def ref(self) -> str | None:
        """The entity a relative target speed is taken from (None: an absolute one)."""
        return self.target[2]

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        kind, value = self.target[:2]
        v1 = e.within_max_speed(value if kind == "absolute" else self._relative_target(ctx))
        v0 = e.speed
        self.rate = math.inf  # (dynamicsDimension rate: the rate the transition keeps, within the limits)
        if self.shape == "step" or self.value == 0 or (self.value < 0 and self.dimension != "rate"):
            duration = 0.0
        elif self.dimension == "time":
            duration = self.value
        elif self.dimension == "rate":  # the peak rate of the shape (esmini): the mean for linear
            duration = PEAK_RATE[self.shape] * abs((v1 - v0) / self.value)  # (the sign is the change's)
        else:  # distance: the time to cover it at the mean speed of the transition
            mean = 0.5 * (v0 + v1)
            duration = self.value / mean if mean > 1e-9 else 0.0
        if e.performance and duration > 0.0:  # as esmini: stretch the transition to the vehicle's limits
            limit = e.limits.max_accel_mps2 if v1 > v0 else e.limits.max_decel_mps2
            if limit > 0:
                duration = max(duration, PEAK_RATE[self.shape] * abs(v1 - v0) / limit)
            elif v1 != v0:  # a limit of 0: the speed never changes (esmini 3.6)
                duration = math.inf
        if self.dimension == "rate" and 0.0 < duration < math.inf:
            self.rate = PEAK_RATE[self.shape] * abs(v1 - v0) / duration
        if duration == 0.0 and ctx.initializing and e.longitudinal is not None and not e.longitudinal.done:
            # in Init a step speed only sets the initial speed: the longitudinal action started
            # before it (a kept distance) goes on, as in esmini
            e.speed = v1
            self.done = True
            return
        e.take_longitudinal(self, ctx)
        e.speed_profile = SpeedProfile(v0, v1, ctx.t, duration, self.shape, ctx.acting)
        if duration == 0.0:
            e.speed = v1

    def update(self, ctx) -> None:
        e = ctx.entities[self.entity]
        if e.longitudinal is not self:  # another longitudinal action took over
            self.done = True
            return
        p = e.speed_profile
        if self.continuous:  # keeps the relative speed after the transition; never ends by itself
            target = e.within_max_speed(self._relative_target(ctx))
            if p is None or ctx.t >= p.t0 + p.duration - 1e-9:
                # after the transition, towards the target within the Performance's limits (esmini 3.6)
                v = e.tracked_speed(target, ctx.dt)
                e.speed_profile = SpeedProfile(v, v, ctx.t, 0.0, "step")
            else:
                p.v1 = target
                if math.isfinite(self.rate):  # a transition at a rate keeps its rate to a moving target
                    p.duration = PEAK_RATE[self.shape] * abs(target - p.v0) / self.rate
            return
        self.done = p is None or ctx.t >= p.t0 + p.duration - 1e-9

    def stop(self, ctx) -> None:
        ctx.entities[self.entity].speed_profile = None

    def carried(self, ctx) -> bool:
        """A transition under way: the core sets the speed as it goes and stops before the step that
        ends it; one following another entity's speed continuously, once its transition is over: the
        core gives it that speed each step (:meth:`core_columns`)."""
        e = ctx.entities[self.entity]
        p = e.speed_profile
        if e.longitudinal is not self:
            return False
        if self.continuous:
            return p is None or (p.duration <= 0.0 and ctx.t >= p.t0 - 1e-9)
        return p is not None and ctx.t < p.t0 + p.duration - 1e-9

    def core_columns(self, ctx, index: dict[str, int]) -> list[float] | None:
        """A continuous relative target speed after its transition as the core steps it (a row of the
        core's keeps, FOLLOW): each step its entity takes its reference's speed at the step's start
        plus (times) the value, as :meth:`update` sets it. None when not carried."""
        e = ctx.entities[self.entity]
        if not self.continuous or not self.carried(ctx) or e.towed_by is not None or e.deleted:
            return None
        _, value, ref, vtype = self.target
        if ctx.entities[ref].deleted or ref == self.entity:
            return None  # (its own speed as its reference, as esmini plays it: the interpreter steps it)
        values = {"ENTITY": index[self.entity], "REF": index[ref], "VALUE": value, "FOLLOW": 1.0}
        max_accel, max_decel, _ = e.performance_limits  # (Entity.tracked_speed's)
        values |= {"MAX_SPEED": e.max_speed, "MAX_ACCEL": max_accel, "MAX_DECEL": max_decel}
        return core_row("keep", values | {"BY_FACTOR": float(vtype != "delta")})

    def after_core(self, ctx, stepped_before: bool) -> None:
        """After the core's stretch: the step profile :meth:`update` leaves at the end of a step, when
        it is updated there (a storyboard action's was there when the stretch began)."""
        if stepped_before:
            e, t0 = ctx.entities[self.entity], step_time(ctx.step - 1, ctx.dt)
            v = e.tracked_speed(e.within_max_speed(self._relative_target(ctx)), ctx.dt)
            e.speed_profile = SpeedProfile(v, v, t0, 0.0, "step")

    def _relative_target(self, ctx) -> float:
        """A relative target speed: its reference's speed now plus (delta) or times (factor) the value."""
        _, value, ref, vtype = self.target
        base = ctx.entities[ref].speed
        return base + value if vtype == "delta" else base * value


def _time_at_s(polyline, s: float) -> float:
    """The time a timed polyline passes arc length ``s`` (its vertex times, linear between them; the
    last vertex's time past its end)."""
    arcs, times = polyline.s, polyline.ts
    k = bisect.bisect_right(arcs, s) - 1
    if k >= len(arcs) - 1:
        return times[-1]
    if k < 0:
        return times[0]
    span = arcs[k + 1] - arcs[k]
    return times[k] if span <= 0.0 else times[k] + (times[k + 1] - times[k]) * (s - arcs[k]) / span


class FollowTrajectory(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        self.entity = entity
        traj = el.find("TrajectoryRef/Trajectory")
        if traj is None:
            traj = el.find("Trajectory")
        if traj is None:
            raise ctx.error(el, "FollowTrajectoryAction: only an inline Trajectory is supported (no catalogs)")
        self.traj = traj
        # vertices relative to an entity are placed when the action starts (esmini), others now
        self.polyline = polyline_from(traj, ctx, place=placed_when_built(traj))
        tref = el.find("TimeReference")
        timing = tref.find("Timing") if tref is not None else None
        if timing is not None:
            if not self.polyline.timed:
                raise ctx.error(timing, "Timing needs a time on every vertex")
            if any(b < a for a, b in zip(self.polyline.ts, self.polyline.ts[1:])) or not (
                self.polyline.ts[-1] > self.polyline.ts[0]
            ):
                raise ctx.error(
                    traj, "vertex times must not decrease (and must span some time) when the trajectory is timed"
                )
            scale = float(timing.get("scale", "1"))
            if scale <= 0:
                raise ctx.error(timing, "Timing scale must be positive")
            self.timing = (timing.get("domainAbsoluteRelative"), scale, float(timing.get("offset", "0")))
        else:
            self.timing = None
            ts = self.polyline.ts
            back = next((k for k in range(1, len(ts)) if None not in ts[k - 1 : k + 1] and ts[k] < ts[k - 1]), None)
            if back is not None:  # (esmini plays the path and reads no time of it: so does vei, but it says so)
                ctx.warn(
                    traj,
                    f"trajectory {traj.get('name')!r}: vertex times go back ({ts[back - 1]:g} -> {ts[back]:g} at "
                    f"vertex {back}); with no Timing they are not played (the path is followed at the entity's "
                    "speed)",
                )
        mode = el.find("TrajectoryFollowingMode")
        self.mode = mode.get("followingMode", "position") if mode is not None else "position"
        self.initial_s = float(el.get("initialDistanceOffset", "0"))

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        if self.polyline.xs is None:
            self.polyline = polyline_from(self.traj, ctx, entity=self.entity)
        timing = self.timing
        if timing is not None and self.initial_s > 0.0 and self.polyline.timed:
            # a timed path entered initialDistanceOffset metres in is entered at that point's time
            # too (the standard; esmini): every later vertex is reached that much sooner
            shift = _time_at_s(self.polyline, self.initial_s) - self.polyline.ts[0]
            timing = (timing[0], timing[1], timing[2] + shift)
        e.follower = PathFollower(self.polyline, timing, self.mode, ctx.t, self.initial_s)
        e.follower.reverse = self.timing is None and e.speed < 0.0
        if self.timing is None:  # on its path at initialDistanceOffset, at t = 0 and later (esmini)
            e.follower.s = self.initial_s
            e.x, e.y, e.yaw = self.polyline.at_s(self.initial_s)
            if e.follower.reverse:
                e.yaw = math.atan2(-math.sin(e.yaw), -math.cos(e.yaw))
        elif ctx.initializing:  # logged at t = 0 on its trajectory
            e.x, e.y, e.yaw = self.polyline.at_time(e.follower.trajectory_time(ctx.t))
        if self.timing is not None and self.polyline.timed and not (ctx.initializing or ctx.settling):
            # started during the run it takes the trajectory's speed at once (esmini; at t = 0 the first
            # step gives it that speed anyway, and t = 0 is logged as the scenario put it)
            f, tt = e.follower, e.follower.trajectory_time(ctx.t)
            h = 1e-3
            e.speed = (self.polyline.s_at_time(tt + h) - self.polyline.s_at_time(tt)) / h * f.timing[1]
        e.lane, e.find_lane = None, False

    def update(self, ctx) -> None:
        e = ctx.entities[self.entity]
        self.done = e.follower is None or e.follower.finished(ctx.t, ctx.dt)
        f = e.follower
        if self.done and f is not None and not e.modelled and ctx.road_file is None and not f.plays_time:
            # an untimed path ended with no road to drive on along: the entity stands where the step
            # that reached the end left it (the rest of that step straight on at the end's heading), as
            # esmini 3.6 leaves it, its speed 0 (measured: it was a step further on, at its speed)
            e.speed, e.speed_profile, e.follower = 0.0, None, None
            return
        if self.done and f is not None and e.modelled and not f.plays_time:
            ctx.warn(
                self.traj,
                f"{self.entity} reaches the end of its path {self.traj.get('name')!r} at {ctx.t + ctx.dt:.2f} s and "
                "stands there (its controller keeps it on its path)",
            )
        # the path ends on a lane: the entity drives on along it by default (at the speed it had at
        # the end, a timed one too), as esmini's does. (An entity with one of vei's model controllers
        # — a compiled ego or rider — keeps to what the sweep kernel and the FMUs do; and
        # the roads are only loaded when they are needed.)
        if self.done and e.follower is not None and not e.modelled and ctx.road_file is not None:
            if ctx.roads is None:
                return
            if e.follower.plays_time:
                e.speed = e.follower.polyline.end_speed * e.follower.timing[1]
                e.speed_profile = None  # (the timing set the speed: an older SpeedAction has no say)
            e.lane = lane_state_at(ctx.roads, e)  # its heading relative to the lane is kept (esmini)
            e.follower = None  # (an Init action is never stopped)

    def stop(self, ctx) -> None:
        ctx.entities[self.entity].follower = None

    def carried(self, ctx) -> bool:
        """A path not at its end: the core moves the entity along it (an untimed one at its speed, a
        timed one by its time) and stops before the step that reaches the end (the evaluation that
        ends a timed one)."""
        f = ctx.entities[self.entity].follower
        return f is not None and not f.finished(ctx.t, ctx.dt)


class AssignController(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        self.entity = entity
        ctrl = el.find("Controller")
        if ctrl is None:
            ctrl = el.find("ObjectController/Controller")
        if ctrl is None:
            raise ctx.error(el, "AssignControllerAction: only an inline Controller is supported (no catalogs)")
        self.controller = make_controller(ctrl, ctx)
        self.lateral = el.get("activateLateral") == "true"
        self.longitudinal = el.get("activateLongitudinal") == "true"

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        if e.sut is not None:  # the system under test stays in charge (interpreter.plugged.plug)
            self.done = True
            return
        e.controllers = {self.controller.name: self.controller}
        e.active = {}
        activate(e, self.controller, self.lateral, self.longitudinal, ctx)
        self.done = True


def activate(e, controller, lateral: bool | None, longitudinal: bool | None, ctx) -> None:
    """Put ``controller`` in charge of the domains flagged True (that it controls), take the ones
    flagged False from whichever controller had them; the controller hears which it took over."""
    taken = []
    for domain, flag in (("lateral", lateral), ("longitudinal", longitudinal)):
        if flag is True and domain in controller.domains:
            if e.active.get(domain) is not controller:
                taken.append(domain)
            e.active[domain] = controller
        elif flag is False:
            e.active.pop(domain, None)
    if taken:
        controller.activated(e, ctx, tuple(taken))


class ActivateController(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        self.entity, self.el = entity, el
        self.lateral = {"true": True, "false": False}.get(el.get("lateral"))
        self.longitudinal = {"true": True, "false": False}.get(el.get("longitudinal"))
        self.ref = el.get("controllerRef")

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        # the system under test stays in charge; the default controller is what it has: it stays on
        if e.sut is not None or (not e.controllers and not self.ref):
            self.done = True
            return
        ctrl = e.controllers.get(self.ref) if self.ref else list(e.controllers.values())[-1]
        if ctrl is None:
            raise ctx.error(self.el, f"ActivateControllerAction: {self.entity} has no controller {self.ref!r}")
        activate(e, ctrl, self.lateral, self.longitudinal, ctx)
        self.done = True


class TrailerHitching(Action):
    """TrailerAction (1.3): ConnectTrailerAction hitches the named trailer to the actor (it is put in
    line behind it, its coupler on the hitch), DisconnectTrailerAction unhitches it where it stands."""

    def __init__(self, entity: str, el, ctx) -> None:
        if el.tag not in ("ConnectTrailerAction", "DisconnectTrailerAction"):
            raise ctx.error(el, f"<TrailerAction>/<{el.tag}> is not supported by vei run")
        self.entity, self.el = entity, el
        self.trailer = el.get("trailerRef")
        tow = ctx.entities[entity]
        if el.tag == "ConnectTrailerAction":
            other = ctx.entities.get(self.trailer or "")
            if other is None or other is tow:
                raise ctx.error(el, f"ConnectTrailerAction: trailerRef {self.trailer!r} names no other entity")
            if tow.hitch_dx is None:
                raise ctx.error(el, f"ConnectTrailerAction: {entity} has no TrailerHitch")

    def start(self, ctx) -> None:
        from vei_scenario.interpreter import trailers

        if self.el.tag == "DisconnectTrailerAction":
            trailers.disconnect(ctx.entities, self.entity)
        else:
            towed_by = ctx.entities[self.trailer].towed_by
            if towed_by is not None and towed_by != self.entity:
                raise ctx.error(self.el, f"ConnectTrailerAction: {self.trailer} is towed by {towed_by} already")
            trailers.connect(ctx.entities, self.entity, self.trailer)
        self.done = True


class StoreAction(Action):
    """ParameterAction (OpenSCENARIO 1.0/1.1) and VariableAction (1.2): SetAction sets the value,
    ModifyAction adds to it or multiplies it (AddValue / MultiplyByValue); the result is checked
    against the declared type (an integer stays an integer: 2 * 1.5 is refused, not rounded).
    esmini 3.6 sets parameters but does not modify them (it warns and goes on); the standard says
    what a modification means, and vei does it. A parameter changed here reaches ParameterConditions;
    the attributes that named it were resolved when the file was loaded (the standard's rule)."""

    def __init__(self, el, ctx, store: str = "variable") -> None:
        from vei_scenario.safe_xml import float_attribute

        self.store, self.el = store, el
        values, _ = self._store(ctx)
        self.name = (el.get(f"{store}Ref") or "").lstrip("$")
        if self.name not in values:
            raise ctx.error(el, f"{el.tag} on undeclared {store} {self.name!r}")
        set_el, mod = el.find("SetAction"), el.find("ModifyAction/Rule")
        rule = first_element(mod) if mod is not None else None
        if set_el is not None:
            self.kind, self.value = "set", set_el.get("value", "")
        elif rule is not None and rule.tag in ("AddValue", "MultiplyByValue"):
            self.kind, self.value = rule.tag, float_attribute(ctx.path, rule, "value")
        else:
            raise ctx.error(el, f"{el.tag} needs a SetAction or a ModifyAction with AddValue or MultiplyByValue")

    def _store(self, ctx) -> tuple[dict[str, str], dict[str, str]]:
        if self.store == "parameter":
            return ctx.parameters, ctx.parameter_types
        return ctx.variables, ctx.variable_types

    def start(self, ctx) -> None:
        from vei_scenario.interpreter.document import check_type

        values, types = self._store(ctx)
        type_ = types.get(self.name, "string")
        if self.kind == "set":
            value = self.value
        else:
            try:
                current = float(values[self.name])
            except ValueError:
                problem = f"{self.store} {self.name!r} = {values[self.name]!r} is not a number"
                raise ctx.error(self.el, problem) from None
            result = current + self.value if self.kind == "AddValue" else current * self.value
            if not math.isfinite(result):
                raise ctx.error(self.el, f"{self.store} {self.name!r} would become {result}")
            value = repr(int(result)) if result.is_integer() and type_ != "double" else repr(result)
        problem = check_type(type_, value)
        if problem:
            raise ctx.error(self.el, f"{self.store} {self.name} = {value!r} {problem}")
        values[self.name] = value
        self.done = True


class EntityPresence(Action):
    """EntityAction: DeleteEntityAction takes the entity out of the simulation (it no longer moves,
    collides or triggers distance conditions; its trace keeps its last pose, marked ``deleted``);
    AddEntityAction puts a declared entity (back) in at a position, standing."""

    def __init__(self, el, ctx) -> None:
        self.name, self.el = el.get("entityRef"), el
        if self.name not in ctx.entities:
            raise ctx.error(el, f"EntityAction: no entity named {self.name!r}")
        kind = first_element(el)
        if kind is None or kind.tag not in ("AddEntityAction", "DeleteEntityAction"):
            raise ctx.error(el, "EntityAction needs an AddEntityAction or a DeleteEntityAction")
        self.add = kind.tag == "AddEntityAction"
        self.position = kind.find("Position") if self.add else None
        if self.add and self.position is None:
            raise ctx.error(kind, "AddEntityAction needs a Position")

    def start(self, ctx) -> None:
        e = ctx.entities[self.name]
        if self.add:
            pose = resolve_position(ctx, self.position)
            e.x, e.y, e.yaw, e.lane = pose.x, pose.y, pose.h, pose.lane
            e.find_lane = e.lane is None and ctx.road_file is not None
            e.speed, e.accel, e.follower, e.lateral, e.speed_profile = 0.0, 0.0, None, None, None
            e.deleted = False
        else:
            e.deleted = True
            e.speed, e.accel = 0.0, 0.0
            if e.longitudinal is not None and not e.longitudinal.done:
                e.longitudinal.stop(ctx)
        self.done = True


class SignalState(Action):
    def __init__(self, name: str, state: str) -> None:
        self.name, self.state = name, state

    def start(self, ctx) -> None:
        ctx.signals[self.name] = self.state
        self.done = True


def private_actions(pa, entity: str, ctx) -> list[Action]:
    """Runtime actions of a ``<PrivateAction>`` for one entity."""
    kind = first_element(pa)
    if kind is None:
        raise ctx.error(pa, "empty PrivateAction")
    if kind.tag == "TeleportAction":
        return [Teleport(entity, kind, ctx)]
    if kind.tag == "LongitudinalAction" and kind.find("SpeedAction") is not None:
        return [Speed(entity, kind.find("SpeedAction"), ctx)]
    if kind.tag == "LongitudinalAction" and kind.find("SpeedProfileAction") is not None:
        from vei_scenario.interpreter.speed_profile import SpeedProfile as SpeedProfileAction  # (start-up: on use)

        return [SpeedProfileAction(entity, kind.find("SpeedProfileAction"), ctx)]
    if kind.tag == "LongitudinalAction" and kind.find("LongitudinalDistanceAction") is not None:
        from vei_scenario.interpreter.longitudinal import LongitudinalDistance  # (start-up: on use)

        return [LongitudinalDistance(entity, kind.find("LongitudinalDistanceAction"), ctx)]
    if kind.tag == "SynchronizeAction":
        from vei_scenario.interpreter.synchronize import Synchronize  # (start-up: on use)

        return [Synchronize(entity, kind, ctx)]
    if kind.tag == "LateralAction" and kind.find("LateralDistanceAction") is not None:
        from vei_scenario.interpreter.lateral_distance import LateralDistance  # (start-up: on use)

        return [LateralDistance(entity, kind.find("LateralDistanceAction"), ctx)]
    if kind.tag == "LateralAction" and kind.find("LaneChangeAction") is not None:
        return [LaneChange(entity, kind.find("LaneChangeAction"), ctx)]
    if kind.tag == "LateralAction" and kind.find("LaneOffsetAction") is not None:
        return [LaneOffset(entity, kind.find("LaneOffsetAction"), ctx)]
    if kind.tag == "RoutingAction" and kind.find("AcquirePositionAction") is not None:
        return [AcquirePosition(entity, kind.find("AcquirePositionAction"), ctx)]
    if kind.tag == "RoutingAction" and kind.find("AssignRouteAction") is not None:
        return [AssignRoute(entity, kind.find("AssignRouteAction"), ctx)]
    if kind.tag in ("VisibilityAction", "AppearanceAction"):
        return [Ignored()]
    if kind.tag == "RoutingAction" and kind.find("FollowTrajectoryAction") is not None:
        return [FollowTrajectory(entity, kind.find("FollowTrajectoryAction"), ctx)]
    if kind.tag == "ControllerAction":
        out: list[Action] = []
        for sub in kind:
            if sub.tag == "AssignControllerAction":
                out.append(AssignController(entity, sub, ctx))
            elif sub.tag == "ActivateControllerAction":
                out.append(ActivateController(entity, sub, ctx))
            elif sub.tag == "OverrideControllerValueAction":
                # Overrides switched off (active false, as scenarios write when they hand the car to
                # its controller) change nothing: vei never applies one. One switched on is refused.
                on = next((o for o in sub if isinstance(o.tag, str) and o.get("active") in ("true", "1")), None)
                if on is not None:
                    reason = f"OverrideControllerValueAction: an active <{on.tag}> override is not supported by vei run"
                    raise ctx.error(on, reason)
                out.append(Ignored())
            else:
                raise ctx.error(sub, f"<{sub.tag}> is not supported by vei run")
        return out
    if kind.tag == "ActivateControllerAction":  # OpenSCENARIO 1.0/1.1 place it directly here
        return [ActivateController(entity, kind, ctx)]
    if kind.tag == "TrailerAction" and first_element(kind) is not None:
        return [TrailerHitching(entity, first_element(kind), ctx)]
    inner_el = first_element(kind)
    inner = inner_el.tag if inner_el is not None else ""
    raise ctx.error(kind, f"<{kind.tag}>{'/<' + inner + '>' if inner else ''} is not supported by vei run")


def global_actions(ga, ctx) -> list[Action]:
    kind = first_element(ga)
    if kind is not None and kind.tag == "ParameterAction":  # (1.0, 1.1; deprecated in 1.2)
        return [StoreAction(kind, ctx, "parameter")]
    if kind is not None and kind.tag == "VariableAction":
        return [StoreAction(kind, ctx, "variable")]
    state = ga.find("InfrastructureAction/TrafficSignalAction/TrafficSignalStateAction")
    if state is not None:  # signal states: for TrafficSignalConditions (no default driver obeys them)
        return [SignalState(state.get("name"), state.get("state"))]
    if kind is not None and kind.tag == "EntityAction":
        return [EntityPresence(kind, ctx)]
    if kind is not None and kind.tag == "EnvironmentAction":  # weather and light: no effect on motion
        return [Ignored()]
    raise ctx.error(ga, f"global action <{kind.tag if kind is not None else ''}> is not supported by vei run")
