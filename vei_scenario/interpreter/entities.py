"""Runtime entities: pose, speed, box, and what moves them (path follower, speed profile, controllers)."""

from __future__ import annotations

import array
import bisect
import math
from dataclasses import dataclass, field

from vei_scenario.core import _core, layout
from vei_scenario.models.vehicle import VehicleLimits


def _f64(values) -> bytes:
    """Doubles as the core takes them: an array's own bytes, else the sequence's packed."""
    return values.tobytes() if isinstance(values, array.array) else array.array("d", values).tobytes()


class Polyline:
    """A trajectory shape: vertices with optional times and headings; evaluated by time or arc length.

    The evaluation is the compiled core's (``vei_models.c``, the same polyline the sweep kernel and
    the FMUs step along); this class adds what the storyboard needs around it."""

    def __init__(self, xs, ys, hs, ts: list[float | None]) -> None:
        """``xs``, ``ys``, ``hs``: lists (a heading None takes its segment's direction) or arrays of
        doubles (a sampled curve's thousands of points, handed to the core as they are)."""
        self.xs, self.ys, self.ts = xs, ys, ts
        if isinstance(hs, array.array):
            self.hs = hs
        elif None in hs:  # (a vertex without a heading takes its segment's direction)
            seg = [math.atan2(ys[i + 1] - ys[i], xs[i + 1] - xs[i]) for i in range(len(xs) - 1)] or [hs[0] or 0.0]
            self.hs = [h if h is not None else seg[min(i, len(seg) - 1)] for i, h in enumerate(hs)]
        else:
            self.hs = list(hs)
        self.timed = None not in ts
        times = _f64(ts) if self.timed else b""
        self.core = _core.Polyline(_f64(xs), _f64(ys), _f64(self.hs), times)
        self.s = self.core.arc_lengths()
        self.at_s = self.core.at_s
        self.project = self.core.project  # arc length of the closest point (the first of equally close)
        if self.timed:
            self.at_time = self.core.at_time
            self.s_at_time = self.core.s_at_time

    @classmethod
    def unplaced(cls, ts: list[float | None]) -> Polyline:
        """Vertex times only: a trajectory whose positions are resolved when its action starts."""
        p = cls.__new__(cls)
        p.xs = p.ys = p.hs = None
        p.ts = ts
        p.timed = all(t is not None for t in ts)
        return p

    @property
    def length(self) -> float:
        return self.s[-1]

    _exit_speed: float | None = None

    @property
    def exit_speed(self) -> float | None:
        """The speed it is left at, where a shape says so (a NURBS: its mean over the last metre or so)."""
        return self._exit_speed

    @exit_speed.setter
    def exit_speed(self, value: float | None) -> None:
        self._exit_speed = value
        self.core.set_exit_speed(math.nan if value is None else value)

    @property
    def end_speed(self) -> float:
        """The speed a replayed road user keeps after a timed polyline: its exit speed where a shape
        gives one, else its last segment's (the core's, as at_time continues past the end)."""
        return self.core.end_speed()

    # at_time(t): pose at trajectory time t: the first vertex before the first time (the road user
    # waits where its recording starts); after the last time on along the last vertex's heading at
    # end_speed, as esmini's default behaviour does once the trajectory action ends.
    # s_at_time(t): arc length at trajectory time t, continued past the end the same way.
    # at_s(s): pose at arc length s, clamped to the path. (All three: the core's, set in __init__.)

    def direction_at_s(self, s: float) -> float:
        """Direction of the segment at arc length ``s`` (the path's own heading, whatever headings its
        vertices give the entity that follows it)."""
        i = min(max(bisect.bisect_right(self.s, s) - 1, 0), len(self.xs) - 2)
        while i > 0 and self.s[i + 1] - self.s[i] <= 0.0:  # (a repeated vertex has no direction)
            i -= 1
        return math.atan2(self.ys[i + 1] - self.ys[i], self.xs[i + 1] - self.xs[i])


@dataclass
class PathFollower:
    """A running FollowTrajectoryAction on its entity."""

    polyline: Polyline
    timing: tuple[str, float, float] | None  # (absolute|relative, scale, offset) or None: path only
    mode: str  # "position" or "follow"
    t_start: float
    s: float = 0.0
    #: Reversing along the path: the entity faces against it and a negative speed moves it forward
    #: along it (an untimed path started at a negative speed, as esmini reads it).
    reverse: bool = False

    @property
    def plays_time(self) -> bool:
        """Whether the trajectory's time, not the entity's speed, moves it along: a timing and a
        polyline whose vertices all have times."""
        return self.timing is not None and self.polyline.timed

    def trajectory_time(self, t_sim: float) -> float:
        """The trajectory time played at simulation time ``t_sim``: ``t * scale + offset``, with t
        counted from 0 (absolute) or from the action's start (relative) — the reading esmini
        implements, so a positive offset plays the trajectory earlier."""
        domain, scale, offset = self.timing
        base = 0.0 if domain == "absolute" else self.t_start
        return (t_sim - base) * scale + offset

    def sim_time_of(self, t_traj: float) -> float:
        """Inverse of :meth:`trajectory_time`."""
        domain, scale, offset = self.timing
        return (t_traj - offset) / scale + (0.0 if domain == "absolute" else self.t_start)

    def finished(self, t_sim: float, dt: float = 0.0) -> bool:
        """Whether the path is done after the step that started at ``t_sim``. A timed one is done once
        less than one step of its time is left (esmini: what follows it starts a step sooner, from
        where the entity is, rather than after a last step that would only reach the final vertex)."""
        if self.plays_time:
            left = self.polyline.ts[-1] - self.trajectory_time(t_sim)
            return left <= dt * self.timing[1] + 1e-9
        return self.s >= self.polyline.length - 1e-9


#: A transition's shape (a SpeedAction's, a lane change's) as the core numbers it (core_module.c: SHAPES).
SHAPE_CODES = {name.lower(): float(code) for name, code in layout("shape").items()}


def transition_fraction(shape: str, x: float) -> float:
    """How far a transition of OpenSCENARIO ``dynamicsShape`` has come at progress ``x`` in [0, 1]
    (linear for any other shape; a step has no progress to speak of): the core's shape_fraction, the
    one its quiet stretches take."""
    return _core.transition_fraction(SHAPE_CODES.get(shape, -1.0), x)


def lane_change_turn(shape: str, by_time: bool, delta: float, value: float, x: float, dt: float, ds: float) -> float:
    """A lane change's heading from its lane's direction in a step of ``ds`` metres at progress ``x``
    (``delta`` metres sideways over ``value`` seconds or metres): the core's, the one its quiet
    stretches take."""
    return _core.lane_change_turn(SHAPE_CODES.get(shape, -1.0), by_time, delta, value, x, dt, ds)


@dataclass
class SpeedProfile:
    """A running SpeedAction: speed from v0 to v1 over ``duration`` with a transition shape."""

    v0: float
    v1: float
    t0: float
    duration: float
    shape: str
    order: float = 0.0  # its SpeedAction's place in the storyboard (Context.acting)

    def speed(self, t: float) -> tuple[float, bool]:
        """(The speed at ``t``, whether the transition is over): the core's transition_speed, the one
        its quiet steps take."""
        return _core.transition_speed(self.v0, self.v1, self.t0, self.duration, SHAPE_CODES.get(self.shape, -1.0), t)


@dataclass
class Entity:
    name: str
    category: str
    length: float
    width: float
    height: float
    center_x: float  # box centre relative to the reference point, along the heading
    limits: VehicleLimits
    x: float = 0.0
    y: float = 0.0
    yaw: float = 0.0
    pitch: float = 0.0  # set by a position's orientation (a fallen rider); turns the entity's frame
    roll: float = 0.0
    speed: float = 0.0
    accel: float = 0.0
    follower: PathFollower | None = None
    speed_profile: SpeedProfile | None = None
    controllers: dict = field(default_factory=dict)  # name -> runtime controller
    active: dict = field(default_factory=dict)  # domain ("lateral"/"longitudinal") -> controller
    status: str = "default"
    lane: object = None  # positions.LaneState while the entity keeps a lane by default
    lateral: object = None  # a running lane change (actions.LaneChangeRuntime)
    odometer: float = 0.0  # distance travelled (m), for TraveledDistanceCondition
    deleted: bool = False  # taken out by a DeleteEntityAction
    last_step_m: float = 0.0  # distance moved in the last step (0 before the first): its measured speed
    standing_since: float | None = None  # simulation time the entity came to a standstill
    route: object = None  # routes.Route assigned by AssignRouteAction
    placed: bool = False  # teleported during this step: it does not move until the next one
    performance: bool = False  # limits come from the entity's <Performance> (speed changes obey them)
    #: The fastest a SpeedAction takes it, either way (m/s): a vehicle's Performance maxSpeed; a
    #: MiscObject's is 0 (esmini 3.6 gives it no performance: a SpeedAction leaves it standing)
    max_speed: float = math.inf
    longitudinal: object = None  # the running action that sets the speed (SpeedAction, distance keeping)
    find_lane: bool = False  # placed off the lane model: look up its lane when it first needs one
    #: a lane keeper's lane state and pose after a step standing still (the engine's default motion
    #: would give it the same again: see Simulation._move), None while it moves
    parked: tuple | None = None
    step_speed: float = 0.0  # speed at the start of the current step (for the logged acceleration)
    kind: str = "vehicle"  # the ScenarioObject's kind: vehicle, pedestrian or misc (MiscObject)
    hitch_dx: float | None = None  # TrailerHitch: where a trailer is hitched, ahead of the reference point
    coupler_dx: float = 0.0  # TrailerCoupler: where it is hitched as a trailer, ahead of its rear axle
    trailer: str | None = None  # the entity it tows (interpreter.trailers)
    towed_by: str | None = None  # the entity that tows it: it is pulled, not moved by itself
    object_type: str = ""  # a finer type from the entity's <Properties> ("e-scooter"), else ""
    #: the user's controller plugged in by ``--controller`` (interpreter.plugged): in charge throughout
    sut: object = None

    def within_max_speed(self, v: float) -> float:
        """``v`` held to within ``max_speed`` either way (as esmini holds a SpeedAction's target speed)."""
        return v if abs(v) <= self.max_speed else math.copysign(self.max_speed, v)

    @property
    def performance_limits(self) -> tuple[float, float, float]:
        """(maxAcceleration, maxDeceleration, maxSpeed) of its Performance; no limits (inf) without
        one. What an action's own constraints are held within, where esmini 3.6 holds them."""
        if not self.performance:
            return math.inf, math.inf, math.inf
        return self.limits.max_accel_mps2, self.limits.max_decel_mps2, self.max_speed

    def tracked_speed(self, target: float, dt: float) -> float:
        """The speed after one step of ``dt`` towards ``target`` at no more than the Performance's
        maxAcceleration/maxDeceleration: how esmini 3.6 keeps a continuous relative target speed
        once its transition is over. The core's keep rows (FOLLOW, core_module.c) step the same
        arithmetic."""
        v0 = self.speed
        max_accel, max_decel, _ = self.performance_limits
        acc = (target - v0) / dt
        if acc > max_accel:
            return v0 + max_accel * dt
        if acc < -max_decel:
            return v0 - max_decel * dt
        return target

    def take_longitudinal(self, action, ctx) -> None:
        """``action`` now sets this entity's speed: the one that did so before ends (one action per
        domain, as esmini and the standard's conflict rule have it)."""
        old, self.longitudinal = self.longitudinal, action
        if old is not None and old is not action and not old.done:
            old.stop(ctx)
            old.done = True

    @property
    def modelled(self) -> bool:
        """Whether a controller with a model of its own is assigned (one that can take a domain): a
        controller vei plays as the default one (controllers.DefaultController) leaves the entity as
        if it had none."""
        return any(c.domains for c in self.controllers.values())

    def box(self) -> tuple[float, float, float, float, float]:
        """(centre x, centre y, yaw, length, width) of the bounding box (the collision check reads the
        same from every entity at once in C: core_module.c's entity_boxes)."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return self.x + c * self.center_x, self.y + s * self.center_x, self.yaw, self.length, self.width

    def velocity(self) -> tuple[float, float]:
        return self.speed * math.cos(self.yaw), self.speed * math.sin(self.yaw)
