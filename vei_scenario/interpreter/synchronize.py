"""SynchronizeAction: an entity times its arrival at a position to a master entity's arrival at another.

The standard (OpenSCENARIO 1.3, 7.4.2) fixes the goal, not the speed profile: when the master reaches
``TargetPositionMaster`` the entity reaches ``TargetPosition``, at ``FinalSpeed`` when one is given
(optionally holding that speed over a steady-state stretch before the target). The action only sets
the entity's speed; its path stays whatever it follows (a lane, a trajectory).

The profile is esmini's, so both players put a Euro NCAP VRU in the same place at the same time.
Each step, before the entities move:

* distances to the targets: along the followed trajectory when the entity follows one, else along the
  road network (shortest chain of roads), else straight;
* the master's time to its target from its current speed;
* without a final speed: the constant acceleration that covers the distance in that time;
* with one: the speed profile of constant-acceleration pieces that arrives at the final speed. On a
  straight speed line ("linear") when one exists; else first towards a peak (convex, rushing) or a
  trough (concave, lingering) and then on the line; where the trough would be a negative speed, it
  brakes to a stop, waits, and starts again in time (or stops at once when the stop would take more
  than half the distance); with a steady state, the final speed is reached that distance (or time)
  before the target and held.

The action ends when either entity is within its tolerance of its target (``targetTolerance``,
``targetToleranceMaster``, default 0 as in esmini), when either distance starts to grow (a target
passed), or when the master arrives within the coming step; the entity is then given the final speed.
"""

from __future__ import annotations

import math

from vei_scenario.core import layout
from vei_scenario.core import row as core_row
from vei_scenario.interpreter.action_base import SteppedLongitudinal, entity_ref
from vei_scenario.interpreter.positions import Pose, ensure_lane
from vei_scenario.interpreter.positions import resolve as resolve_position
from vei_scenario.interpreter.routes import road_chains, road_distance
from vei_scenario.safe_xml import first_element

SMALL = 1e-10
LARGE = 1e10
#: Braking used when a stop must start at once (esmini's MAX_DECELERATION), m/s².
STOP_DECELERATION = 8.0
#: How close (m/s) the speed must be to the straight speed line to switch to it.
ON_LINE_SPEED_TOLERANCE = 0.1
#: The profile's modes and submodes, numbered as the core numbers them (core_module.c: SM_*, SS_*).
_MODES = ("none", "waiting", "steady", "stop now", "stopped", "linear", "non-linear")
_SUBMODES = ("none", "convex", "concave")
#: A synchronisation's columns in the core (core_module.c: SYNC_COLUMNS).
_COLUMNS = layout("sync")


class Synchronize(SteppedLongitudinal):
    def __init__(self, entity: str, el, ctx) -> None:
        from vei_scenario.safe_xml import float_attribute

        self.entity, self.el = entity, el
        self._goal_on_path: dict[tuple, float] = {}
        self.master = entity_ref(ctx, el, "masterEntityRef")
        if self.master == entity:
            raise ctx.error(el, "SynchronizeAction: the master entity is the actor itself")
        self.master_pos = el.find("TargetPositionMaster")
        self.target_pos = el.find("TargetPosition")
        for name, pos in (("TargetPositionMaster", self.master_pos), ("TargetPosition", self.target_pos)):
            if pos is None or first_element(pos) is None:
                raise ctx.error(el, f"SynchronizeAction needs a {name}")
        self.tolerance = float_attribute(ctx.path, el, "targetTolerance") if el.get("targetTolerance") else 0.0
        self.tolerance_master = (
            float_attribute(ctx.path, el, "targetToleranceMaster") if el.get("targetToleranceMaster") else 0.0
        )
        if self.tolerance < 0 or self.tolerance_master < 0:
            raise ctx.error(el, "SynchronizeAction: a target tolerance is negative")
        self.final: tuple | None = None  # ("absolute", v) or ("relative", value, "delta"|"factor")
        self.steady: tuple[str, float] | None = None  # ("distance"|"time", value)
        final = el.find("FinalSpeed")
        if final is not None:
            kind = first_element(final)
            if kind is not None and kind.tag == "AbsoluteSpeed":
                self.final = ("absolute", float_attribute(ctx.path, kind, "value"))
            elif kind is not None and kind.tag == "RelativeSpeedToMaster":
                vtype = kind.get("speedTargetValueType", "delta")
                if vtype not in ("delta", "factor"):
                    raise ctx.error(kind, f"speedTargetValueType {vtype!r} is not one of delta, factor")
                self.final = ("relative", float_attribute(ctx.path, kind, "value"), vtype)
            else:
                raise ctx.error(final, "FinalSpeed needs AbsoluteSpeed or RelativeSpeedToMaster")
            ss = first_element(kind)
            if ss is not None and ss.tag == "SteadyState":  # (OpenSCENARIO 1.1 wraps it)
                ss = first_element(ss)
            if ss is not None:
                if ss.tag == "TargetDistanceSteadyState":
                    self.steady = ("distance", float_attribute(ctx.path, ss, "distance"))
                elif ss.tag == "TargetTimeSteadyState":
                    self.steady = ("time", float_attribute(ctx.path, ss, "time"))
                else:
                    raise ctx.error(ss, f"steady state <{ss.tag}> is not supported by vei run")
                if self.steady[1] < 0:
                    raise ctx.error(ss, "a steady state must not be negative")

    # --- the targets ----------------------------------------------------------------------------
    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        # positions relative to entities are taken when the action starts
        self.master_goal = resolve_position(ctx, self.master_pos)
        self.goal = resolve_position(ctx, self.target_pos)
        self.steady_dist = 0.0
        if self.steady is not None:
            kind, value = self.steady
            self.steady_dist = value * self._final_speed(ctx) if kind == "time" else value
        self.mode, self.submode = "none", "none"
        if ctx.entities[self.master].last_step_m <= 0.0:  # esmini 3.6 holds the entity from the start
            self.mode = "waiting"  # until it has seen the master move (a synchronisation from t = 0)
            e.speed = 0.0
        self.last_dist = self.last_master_dist = LARGE
        e.take_longitudinal(self, ctx)
        e.speed_profile = None
        ctx.stepping.append(self)

    def _final_speed(self, ctx) -> float:
        kind, value, *rest = self.final
        if kind == "absolute":
            return value
        base = ctx.entities[self.master].speed
        return base + value if rest[0] == "delta" else base * value

    def speed_heading(self, ctx) -> float:
        """The speed (m/s, >= 0) the entity heads for: its final speed, 0 without one (a bound for the
        core's quiet stretches to reason with, not a limit: the profile may pass it)."""
        return abs(self._final_speed(ctx)) if self.final is not None else 0.0

    def _goal_along(self, f, goal: Pose) -> float:
        """Where ``goal`` lies along the path ``f`` follows: the same each step while path and goal are
        (memoised)."""
        key = (f.polyline, goal.x, goal.y)
        s_goal = self._goal_on_path.get(key)
        if s_goal is None:
            s_goal = self._goal_on_path[key] = f.polyline.project(goal.x, goal.y)
        return s_goal

    def _distance(self, ctx, name: str, goal: Pose) -> float:
        """How far entity ``name`` still has to go to ``goal`` (>= 0)."""
        e = ctx.entities[name]
        f = e.follower
        if f is not None and f.polyline.xs is not None:
            return abs(self._goal_along(f, goal) - f.s)
        if ctx.roads is not None:
            ensure_lane(ctx, e)
            if e.lane is not None and goal.lane is not None:
                d = road_distance(ctx.roads, (e.lane.road, e.lane.s), (goal.lane.road, goal.lane.s))
                if d is not None:
                    return d
        return math.hypot(goal.x - e.x, goal.y - e.y)

    # --- each step ------------------------------------------------------------------------------
    def step(self, ctx) -> None:
        if ctx.initializing or ctx.settling:  # no time passes before t = 0 is logged
            return
        e, master = ctx.entities[self.entity], ctx.entities[self.master]
        dt = ctx.dt
        master_dist = self._distance(ctx, self.master, self.master_goal)
        dist = self._distance(ctx, self.entity, self.goal)
        done = (
            dist < self.tolerance + SMALL
            or master_dist < self.tolerance_master + SMALL
            or dist > self.last_dist
            or master_dist > self.last_master_dist
        )
        self.last_dist, self.last_master_dist = dist, master_dist
        dist = max(dist - self.tolerance, SMALL)
        master_dist = max(master_dist - self.tolerance_master, SMALL)
        master_time = LARGE
        master_speed = abs(master.speed)  # (a master reversing along its path comes closer too)
        if master_speed > SMALL:
            master_time = master_dist / master_speed
            if master_time < dt:
                done = True
        if done:
            if self.final is not None:
                e.speed = self._final_speed(ctx)
            self.done = True
            return
        if self.final is None:  # reach the target at whatever speed a constant acceleration gives
            v_end = 2.0 * dist / master_time - e.speed
            e.speed += (v_end - e.speed) / master_time * dt
            return
        self.master_moved = master.last_step_m > 0.0
        e.speed = self._profile_speed(e.speed, dist, master_time, self._final_speed(ctx), dt)

    master_moved = True

    # --- in the core's quiet stretches (interpreter/cruise.py, core_module.c: sync_step) ------------
    def carried(self, ctx) -> bool:  # (whether its distances suit the core: core_columns, at the stretch)
        return not self.done

    def core_columns(self, ctx, index: dict[str, int], programs: list[float]) -> list[float] | None:
        """This synchronisation as the core steps it (SY_* columns), or None when a distance is not
        along the path or roads the entity keeps in a quiet stretch. A distance over roads other than
        the entity's is :func:`~vei_scenario.interpreter.routes.road_distance`'s sum over its chains of
        roads, appended to ``programs`` (core_module.c: road_program) for the core to add up as it
        does."""
        if self.done or ctx.initializing or ctx.settling:
            return None
        goals = []
        for name, goal in ((self.entity, self.goal), (self.master, self.master_goal)):
            e = ctx.entities[name]
            f = e.follower
            if f is not None and f.polyline.xs is not None:
                goals += [self._goal_along(f, goal), -1.0]
            elif ctx.roads is not None and e.lane is not None and goal.lane is not None:
                if goal.lane.road == e.lane.road:
                    goals += [goal.lane.s, -1.0]
                    continue
                la, lb, sb = ctx.roads.road(e.lane.road).length, ctx.roads.road(goal.lane.road).length, goal.lane.s
                chains = road_chains(ctx.roads, e.lane.road, goal.lane.road)
                if not chains or not (0.0 <= e.lane.s <= la and 0.0 <= sb <= lb):
                    return None
                goals += [sb, float(len(programs))]
                programs += [la, lb, sb, len(chains)]
                for leave_forward, arrive_forward, middle in chains:
                    programs += [float(leave_forward), float(arrive_forward), len(middle), *middle]
            else:
                return None
        values = {
            "ENTITY": index[self.entity], "MASTER": index[self.master], "GOAL": goals[0], "PROGRAM": goals[1],
            "MASTER_GOAL": goals[2], "MASTER_PROGRAM": goals[3], "TOL": self.tolerance,
            "TOL_MASTER": self.tolerance_master, "MODE": _MODES.index(self.mode),
            "SUBMODE": _SUBMODES.index(self.submode), "LAST": self.last_dist, "LAST_MASTER": self.last_master_dist,
            "FINAL": self._final_speed(ctx) if self.final is not None else math.nan,
            "STEADY": self.steady_dist if self.steady is not None else math.nan,
        }  # fmt: skip
        return core_row("sync", values)

    def take_core_columns(self, cols) -> None:
        """The state the core's steps left this synchronisation in."""
        self.mode, self.submode = _MODES[int(cols[_COLUMNS["MODE"]])], _SUBMODES[int(cols[_COLUMNS["SUBMODE"]])]
        self.last_dist, self.last_master_dist = cols[_COLUMNS["LAST"]], cols[_COLUMNS["LAST_MASTER"]]

    def _profile_speed(self, v0: float, s: float, t: float, v1: float, dt: float) -> float:
        """The speed for the coming step of a profile that covers ``s`` in ``t`` ending at ``v1``."""
        if self.steady is not None and self.mode != "steady":
            time_to_steady = self.steady_dist / v1 if v1 > SMALL else LARGE
            if s - self.steady_dist < SMALL or t - time_to_steady < SMALL:
                self.mode, self.submode = "steady", "none"
            else:  # plan to reach the final speed where the steady stretch begins
                s -= self.steady_dist
                t -= time_to_steady
        if self.mode == "steady":
            return v1
        if self.mode == "waiting":  # stopped for a master that does not move
            if t >= LARGE:
                return v0
            self.mode = "none"
        if self.mode == "stop now":
            v = v0 - STOP_DECELERATION * dt
            if v < 0.0:
                self.mode = "waiting"
                return 0.0
            return v
        if self.mode == "stopped":
            if v1 > SMALL and t < 2.0 * s / v1:  # time to start again: on the line to the final speed
                self.mode = "linear"
            else:
                return 0.0
        if self.mode == "linear":
            if t > LARGE - 1.0:
                return 0.0
            return max(0.0, _line_start_speed(max(0.0, v1), t, s))
        if self.mode == "non-linear" and t < LARGE:
            if abs(v0 - (2.0 * s / t - v1)) < ON_LINE_SPEED_TOLERANCE:  # on the straight line: follow it
                self.mode = "linear"
                return v0
        if self.mode == "none":
            self.mode = "non-linear"
            # which side of the mean speed the profile bends to is judged from the master's measured
            # motion: before it has moved (a synchronisation started at t = 0) esmini 3.6 sees no time
            # limit and picks the lingering side, then takes the straight line at once if the first
            # piece must accelerate after all (its log: "Reached apex" in the first step)
            t_seen = t if self.master_moved else LARGE
            self.submode = "convex" if (v1 + v0) / 2.0 < s / t_seen else "concave"
        acc, vx = _two_piece_acceleration(v0, v1, s, t)
        if (self.submode == "concave" and acc > 0) or (self.submode == "convex" and acc < 0):
            self.mode = "linear"  # the apex is passed: keep the speed for this step, then the line
            acc = 0.0
        if self.mode == "non-linear" and vx < 0.0:  # the trough is below 0: brake to a stop, wait
            t1 = 2.0 * v0 * s / (v0 * v0 + v1 * v1)
            acc = -v0 / t1 if abs(t1) > SMALL else 0.0
            if t1 * v0 / 2.0 > s / 2.0:  # the stop needs more than half the way: stop at once
                acc = -STOP_DECELERATION
                self.mode = "stop now"
            if v0 + acc * dt < 0.0:
                self.mode = "stopped"
                return 0.0
        return v0 + acc * dt


def _line_start_speed(v_final: float, time: float, dist: float) -> float:
    """The speed now from which a constant acceleration covers ``dist`` in ``time`` ending at
    ``v_final`` (0 when either is vanishing)."""
    if time < 0.001 or dist < 0.001:
        return 0.0
    return 2.0 * dist / time - v_final


def _two_piece_acceleration(v0: float, v1: float, s: float, t: float) -> tuple[float, float]:
    """(acceleration of the first piece, speed at its end) of a profile of two constant-acceleration
    pieces from ``v0`` to a speed ``vx`` and on to ``v1`` covering ``s`` in ``t`` with the same
    magnitude of acceleration. From s = (v0 + vx) x / 2 + (vx + v1)(t - x) / 2 and
    (vx - v0) / x = (vx - v1) / (t - x): a quadratic in vx, whose root with 0 < x < t is taken."""
    if abs(v1 - v0) < SMALL:  # symmetric: the turn is half way
        vx = (s - (t / 2.0) * v0) / (t / 2.0)
        return (vx - v0) / (t / 2.0), vx
    root = math.sqrt(2.0) * math.sqrt(max(0.0, 2.0 * s * s - 2.0 * (v1 + v0) * t * s + (v1 * v1 + v0 * v0) * t * t))
    for sign in (1.0, -1.0):
        x = -(sign * root + 2.0 * s - 2.0 * v1 * t) / (2.0 * (v1 - v0))
        vx = (2.0 * s - sign * root) / (2.0 * t)
        if 0.0 < x < t:
            return (vx - v0) / x, vx
    return 0.0, 0.0
