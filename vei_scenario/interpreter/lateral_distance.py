"""LateralDistanceAction: reach, and with ``continuous`` keep, a lateral distance to another entity.

Read from the standard (OpenSCENARIO 1.3): the distance is measured across the road (road or lane
coordinates: the difference of t; entity coordinates: across the actor's heading), between reference
points or, with ``freespace``, between the boxes' sides; ``displacement`` puts the actor to the left
or right of the reference as the actor drives (``any``: the side it is on when the action starts).

Without DynamicConstraints the actor is put at the distance every step. With them it moves across
as fast as they allow: its lateral speed within ``maxSpeed``, and with ``maxAcceleration`` (and
``maxDeceleration`` for slowing, else the same) a time-optimal approach that brakes in time to stop
at the distance. It moves across within its lane's frame (its offset from the lane centre), heading
along the lane; a running lane change of the actor ends. A one-off action ends within 0.1 m of the
distance (esmini's threshold for the longitudinal one).
"""

from __future__ import annotations

import math

from vei_scenario.interpreter.action_base import Stepped, constraint, entity_ref
from vei_scenario.interpreter.positions import entity_lane

#: A one-off action ends this close (m) to its distance.
REACHED = 0.1


class LateralDistance(Stepped):
    def __init__(self, entity: str, el, ctx) -> None:
        from vei_scenario.safe_xml import float_attribute

        self.entity, self.el = entity, el
        self.ref = entity_ref(ctx, el)
        if self.ref == entity:  # (no side of itself to be on; esmini 3.6 moves it on by some reading of its own)
            raise ctx.error(el, "LateralDistanceAction: the reference entity is the actor itself")
        self.distance = float_attribute(ctx.path, el, "distance") if el.get("distance") not in (None, "") else 0.0
        if self.distance < 0:
            raise ctx.error(el, "LateralDistanceAction distance must not be negative")
        self.freespace = el.get("freespace", "false") == "true"
        self.continuous = el.get("continuous", "false") == "true"
        self.displacement = el.get("displacement", "any")
        if self.displacement not in ("any", "leftToReferencedEntity", "rightToReferencedEntity"):
            raise ctx.error(el, f"displacement {self.displacement!r} is not one of OpenSCENARIO's")
        system = el.get("coordinateSystem", "entity")
        if system not in ("entity", "road", "lane"):
            raise ctx.error(el, f"coordinateSystem {system!r} is not supported (entity, road, lane)")
        dyn = el.find("DynamicConstraints")
        self.max_accel = constraint(ctx, dyn, "maxAcceleration")
        self.max_decel = constraint(ctx, dyn, "maxDeceleration")
        self.max_speed = constraint(ctx, dyn, "maxSpeed")
        if math.isinf(self.max_decel):
            self.max_decel = self.max_accel
        for v in (self.max_accel, self.max_speed):
            if v <= 0:
                raise ctx.error(dyn, "DynamicConstraints must be positive")

    def start(self, ctx) -> None:
        e, st = entity_lane(ctx, self.el, self.entity)
        e.lane, e.follower, e.lateral = st, None, None
        st.heading = 0.0
        _, ref = entity_lane(ctx, self.el, self.ref)
        self.side = {"leftToReferencedEntity": 1.0, "rightToReferencedEntity": -1.0}.get(self.displacement)
        if self.side is None:  # any: the side it is on now
            self.side = 1.0 if self._across(ctx) >= 0.0 else -1.0
        self.v_lat = 0.0
        ctx.stepping.append(self)

    def _across(self, ctx) -> float:
        """The actor's lateral position minus the reference's, positive to the actor's left (m)."""
        e, ref = ctx.entities[self.entity], ctx.entities[self.ref]
        road = ctx.roads.road(e.lane.road)
        t_e = road.lane_center_t(e.lane.s, e.lane.lane) + e.lane.offset
        _, rst = entity_lane(ctx, self.el, self.ref)
        if rst.road == e.lane.road:
            t_r = road.lane_center_t(rst.s, rst.lane) + rst.offset
            d = t_e - t_r
        else:  # not on one road: across the actor's heading
            d = -math.sin(e.yaw) * (ref.x - e.x) + math.cos(e.yaw) * (ref.y - e.y)
            d = -d if e.lane.forward else d
        return d if e.lane.forward else -d

    def step(self, ctx) -> None:
        e, ref = ctx.entities[self.entity], ctx.entities[self.ref]
        if e.lane is None:
            return
        wanted = self.distance + (0.5 * (e.width + ref.width) if self.freespace else 0.0)
        error = self.side * wanted - self._across(ctx)  # how far to move left (m)
        if not self.continuous and abs(error) < REACHED:
            self.done = True
        dt = 0.0 if ctx.initializing or ctx.settling else ctx.dt
        if math.isinf(self.max_accel) and math.isinf(self.max_speed):
            move = error
        elif dt <= 0.0:
            move = 0.0
        else:
            # the lateral speed that still stops at the distance, within maxSpeed
            v_des = math.copysign(min(self.max_speed, math.sqrt(2.0 * self.max_decel * abs(error))), error)
            if math.isinf(self.max_decel):
                v_des = math.copysign(min(self.max_speed, abs(error) / dt), error)
            a = (v_des - self.v_lat) / dt
            limit = self.max_accel if abs(v_des) > abs(self.v_lat) else self.max_decel
            a = max(-limit, min(limit, a))
            self.v_lat += a * dt
            move = self.v_lat * dt
            if abs(move) > abs(error) and math.copysign(1.0, move) == math.copysign(1.0, error):
                move, self.v_lat = error, 0.0
        e.lane.offset += move if e.lane.forward else -move

    def taken_over(self, ctx) -> bool:
        return ctx.entities[self.entity].lateral is not None  # a lane change took the entity over
