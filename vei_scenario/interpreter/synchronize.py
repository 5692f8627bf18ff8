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

import array
import math

from vei_scenario.core import _core, layout
from vei_scenario.core import row as core_row
from vei_scenario.interpreter.action_base import SteppedLongitudinal, entity_ref
from vei_scenario.interpreter.positions import Pose, ensure_lane
from vei_scenario.interpreter.positions import resolve as resolve_position
from vei_scenario.interpreter.routes import road_chains, road_distance
from vei_scenario.safe_xml import first_element

#: The distances a synchronisation starts from ("farther than anything": core_module.c's SYNC_LARGE).
LARGE = 1e10
#: A synchronisation's columns in the core (core_module.c: SYNC_COLUMNS): its state between steps.
_COLUMNS = layout("sync")
#: The profile's modes by the core's names (core_module.c: SYNC_MODES).
MODES = _core.CRUISE_LAYOUT["sync_mode"]


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
        steady = math.nan
        if self.steady is not None:
            kind, value = self.steady
            steady = value * self._final_speed(ctx) if kind == "time" else value
        mode = "NONE"
        if ctx.entities[self.master].last_step_m <= 0.0:  # esmini 3.6 holds the entity from the start
            mode = "WAITING"  # until it has seen the master move (a synchronisation from t = 0)
            e.speed = 0.0
        # the profile's state between steps, as the core reads and writes it (core_module.c: sync_speed)
        values = {"TOL": self.tolerance, "TOL_MASTER": self.tolerance_master, "STEADY": steady}
        values |= {"MODE": MODES.index(mode), "LAST": LARGE, "LAST_MASTER": LARGE, "FINAL": math.nan}
        self.state = array.array("d", core_row("sync", values))
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
        master_dist = self._distance(ctx, self.master, self.master_goal)
        dist = self._distance(ctx, self.entity, self.goal)
        if self.final is not None:
            self.state[_COLUMNS["FINAL"]] = self._final_speed(ctx)
        # the profile (core_module.c: sync_speed, the one the core's quiet steps take)
        v = _core.sync_speed(self.state, dist, master_dist, e.speed, master.speed, master.last_step_m > 0.0, ctx.dt)
        if v is None:  # a target reached or passed, or the master arrives in the coming step
            if self.final is not None:
                e.speed = self._final_speed(ctx)
            self.done = True
            return
        e.speed = v

    @property
    def mode(self) -> str:
        """The profile's mode now (MODES: NONE, WAITING, STEADY, STOP_NOW, STOPPED, LINEAR, NON_LINEAR)."""
        return MODES[int(self.state[_COLUMNS["MODE"]])]

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
        row = list(self.state)
        values = {
            "ENTITY": index[self.entity], "MASTER": index[self.master], "GOAL": goals[0], "PROGRAM": goals[1],
            "MASTER_GOAL": goals[2], "MASTER_PROGRAM": goals[3],
            "FINAL": self._final_speed(ctx) if self.final is not None else math.nan,
        }  # fmt: skip
        for name, value in values.items():
            row[_COLUMNS[name]] = value
        return row

    def take_core_columns(self, cols) -> None:
        """The state the core's steps left this synchronisation in."""
        for name in ("MODE", "SUBMODE", "LAST", "LAST_MASTER"):
            self.state[_COLUMNS[name]] = cols[_COLUMNS[name]]
