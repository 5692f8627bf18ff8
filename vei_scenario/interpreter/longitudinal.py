"""LongitudinalDistanceAction: keep a distance or time gap to another entity, ahead of it or behind.

Without DynamicConstraints the entity is put at the requested distance every step and given the
reference's speed (the reading of esmini and the standard: "as fast as possible"). With them it is
driven by a critically damped spring on the distance error, its stiffness scaled by the permitted
acceleration (when too far) or deceleration (when too close), the acceleration clipped to those
limits and, when rates are given, changed no faster than them; the speed stays within ``maxSpeed``.
Each limit is the constraint's within the entity's Performance (the smaller). This is the controller
esmini 3.6 implements, so both players keep the same gaps.
"""

from __future__ import annotations

import math

from vei_scenario.core import _core, layout
from vei_scenario.core import row as core_row
from vei_scenario.interpreter.action_base import SteppedLongitudinal, constraint, entity_ref
from vei_scenario.interpreter.motion import advance_along, lane_keep
from vei_scenario.interpreter.positions import ensure_lane

#: Core columns of a distance kept in a quiet stretch (core_module.c: KEEP_COLUMNS).
_KEEP = layout("keep")


def longitudinal_gap(a, b, freespace: bool, system: str) -> float:
    """Signed distance from ``a`` to ``b`` along ``a``'s direction of travel (positive: ``b`` ahead).

    Between reference points in the entity frame, or as a difference of s when ``system`` is road or
    lane and both are on one road. With ``freespace`` the gap between the boxes along ``a``'s
    heading, 0 while their projections on that axis overlap (side by side)."""
    if not freespace:
        la, lb = a.lane, b.lane
        if system in ("road", "lane") and la is not None and lb is not None and la.road == lb.road:
            return (lb.s - la.s) if la.forward else (la.s - lb.s)
    return _core.heading_gap(a, b, freespace)  # (the core's, the one its quiet stretches measure)


class LongitudinalDistance(SteppedLongitudinal):
    """A running LongitudinalDistanceAction; stepped before the entities move, as esmini does."""

    placed = False  # placed at the gap (no dynamic constraints) in an earlier step

    def __init__(self, entity: str, el, ctx) -> None:
        self.entity, self.ref = entity, entity_ref(ctx, el)
        if (el.get("distance") is None) == (el.get("timeGap") is None):
            raise ctx.error(el, "LongitudinalDistanceAction needs exactly one of distance and timeGap")
        self.by_time = el.get("timeGap") is not None
        self.value = abs(float(el.get("timeGap") if self.by_time else el.get("distance")))
        self.freespace = el.get("freespace", "false") == "true"
        self.continuous = el.get("continuous", "false") == "true"
        self.system = el.get("coordinateSystem", "entity")
        if self.system not in ("entity", "road", "lane"):
            raise ctx.error(el, f"coordinateSystem {self.system!r} is not supported (entity, road, lane)")
        self.displacement = el.get("displacement", "trailingReferencedEntity")
        if self.displacement not in ("trailingReferencedEntity", "leadingReferencedEntity", "any"):
            raise ctx.error(el, f"displacement {self.displacement!r} is not one of OpenSCENARIO's")
        dyn = el.find("DynamicConstraints")

        def get(name: str) -> float:
            return constraint(ctx, dyn, name)

        self.max_accel, self.max_decel = get("maxAcceleration"), get("maxDeceleration")
        self.max_speed = get("maxSpeed")
        self.accel_rate, self.decel_rate = get("maxAccelerationRate"), get("maxDecelerationRate")

    def start(self, ctx) -> None:
        e, ref = ctx.entities[self.entity], ctx.entities[self.ref]
        self.side = 1.0  # +1: behind the reference (trailing), -1: ahead of it (leading)
        if self.displacement == "leadingReferencedEntity":
            self.side = -1.0
        elif self.displacement == "any":  # keep the side it is on when the action starts
            self.side = -1.0 if longitudinal_gap(e, ref, self.freespace, "entity") < 0.0 else 1.0
        self.accel = 0.0
        # the spring's limits: the constraints' within the entity's Performance (esmini 3.6, measured;
        # placed at the gap without constraints, it is not held to the Performance)
        own = e.performance_limits
        self.limits = min(self.max_accel, own[0]), min(self.max_decel, own[1]), min(self.max_speed, own[2])
        e.take_longitudinal(self, ctx)
        ctx.stepping.append(self)

    def step(self, ctx) -> None:
        """Set the entity's speed (or place it) for the coming step from the gap now."""
        e, ref = ctx.entities[self.entity], ctx.entities[self.ref]
        ensure_lane(ctx, e)
        ensure_lane(ctx, ref)
        # every step is a whole step, the one it starts in too (esmini); in Init it only places
        dt = 0.0 if ctx.initializing or ctx.settling else ctx.dt
        gap = longitudinal_gap(e, ref, self.freespace, self.system)
        wanted = self.side * (abs(ref.speed) * self.value if self.by_time else self.value)
        error = gap - wanted
        # a one-off action ends once the gap is measured reached — or, placed at it, the step after
        # (esmini measures first; a gap that its own measure never confirms must not lock the entity)
        if not self.continuous and (abs(error) < 0.1 or self.placed):
            self.done = True
        if self.placing:  # at the distance, at its speed
            if e.lane is not None and ctx.roads is not None:
                lane_keep(e, error, ctx)
            else:
                advance_along(e, error)
            e.speed = ref.speed
            self.placed = True
            return
        # the damped spring on the gap (the core's spring_step, the one its quiet stretches take)
        max_accel, max_decel, max_speed = self.limits
        self.accel, e.speed = _core.spring_step(
            error, e.speed, ref.speed, max_accel, max_decel, self.accel_rate, self.decel_rate, self.accel, max_speed, dt
        )

    # --- in the core's quiet stretches (interpreter/cruise.py, core_module.c: keep_step) -------------
    def carried(self, ctx) -> bool:  # (whether its road users suit the core: core_columns, at the stretch)
        return self.continuous and not self.done

    @property
    def placing(self) -> bool:
        """Whether it places its entity at the gap (no dynamic constraints) rather than driving it there."""
        return math.isinf(self.max_accel) and math.isinf(self.max_decel)

    def core_columns(self, ctx, index: dict[str, int]) -> list[float] | None:
        """This action as the core steps it (KP_* columns), or None (the interpreter steps it). The core
        takes a continuous one whose entity has no speed of its own (no transition, no timed path, not
        towed) and, placed at the gap, keeps its lane without changing lanes; a gap along the road when
        both keep their lanes."""
        if not self.carried(ctx) or ctx.initializing or ctx.settling or self.ref == self.entity:
            return None  # (a gap to itself, an authoring slip esmini plays: the interpreter steps it)
        e, ref = ctx.entities[self.entity], ctx.entities[self.ref]
        if e.deleted or ref.deleted or e.towed_by is not None or e.speed_profile is not None:
            return None
        on_lane = e.lane is not None and e.follower is None and ctx.roads is not None
        if self.placing and not (on_lane and e.lateral is None):
            return None
        if e.follower is not None and e.follower.plays_time:
            return None  # (a timed path sets its speed)
        la, lb = e.lane, ref.lane
        along = not self.freespace and self.system in ("road", "lane") and la is not None and lb is not None
        along = along and la.road == lb.road
        if along and not (on_lane and ref.follower is None and ref.towed_by is None):
            return None  # (a gap along the road from a lane the core does not keep)
        values = {"ENTITY": index[self.entity], "REF": index[self.ref], "VALUE": self.value, "SIDE": self.side}
        values |= {"BY_TIME": float(self.by_time), "FREESPACE": float(self.freespace), "ALONG_ROAD": float(along)}
        if not self.placing:
            max_accel, max_decel, max_speed = self.limits
            values |= {"SPRING": 1.0, "MAX_ACCEL": max_accel, "MAX_DECEL": max_decel, "ACCEL": self.accel}
            values |= {"MAX_SPEED": max_speed, "ACCEL_RATE": self.accel_rate, "DECEL_RATE": self.decel_rate}
        return core_row("keep", values)

    def take_core_columns(self, cols) -> None:
        """The state the core left it in (its spring's last acceleration)."""
        self.accel = cols[_KEEP["ACCEL"]]
