"""SpeedProfileAction (OpenSCENARIO 1.2): a series of speed targets, each reached a given time after
the one before.

The standard's reading: each ``SpeedProfileEntry`` is reached ``time`` seconds after the previous one
(the first: after the action starts); without a time, as fast as the constraints (else the entity's
Performance) allow. Speeds are absolute, or relative to ``entityRef``'s speed.

* ``followingMode="position"``: the speed changes linearly from target to target (a zero time is a
  step); the schedule is exact where it is within the limits.

Either way the limits are the constraints' within the entity's Performance (the smaller of each), and
a target that its time would have reached faster than they allow is reached as fast as they allow,
the times of the targets after it shifted by as much (esmini 3.6, measured).
* ``followingMode="follow"``: the entity takes each segment's acceleration, changing it no faster
  than ``maxAccelerationRate``/``maxDecelerationRate`` (jerk) and within ``maxAcceleration``/
  ``maxDeceleration``; it starts the change to the next segment's acceleration when that change
  will end on the next segment's straight line, so each corner is cut and the schedule rejoined
  (esmini 3.6's profile: within 0.05 m of it on esmini's ``speed-profile`` example). The speed
  stays within ``maxSpeed``.

The action ends when the last target speed is reached (at the end of the schedule, or — following —
when the speed is within 1 mm/s of it and the acceleration has settled).
"""

from __future__ import annotations

import math

from vei_scenario.interpreter.action_base import SteppedLongitudinal, constraint, entity_ref

#: How close (m/s) a following entity must be to the last speed for the action to end.
SETTLED_SPEED = 1e-3
#: Time (s) over which a following entity makes up what is left to the last speed after the schedule.
SPEED_TIME = 1.0


class SpeedProfile(SteppedLongitudinal):
    def __init__(self, entity: str, el, ctx) -> None:
        from vei_scenario.safe_xml import float_attribute

        self.entity, self.el = entity, el
        self.ref = entity_ref(ctx, el) if el.get("entityRef") is not None else None
        self.mode = el.get("followingMode", "position")
        if self.mode not in ("position", "follow"):
            raise ctx.error(el, f"followingMode {self.mode!r} is not one of position, follow")
        self.entries: list[tuple[float | None, float]] = []
        for entry in el.iterfind("SpeedProfileEntry"):
            t = float_attribute(ctx.path, entry, "time") if entry.get("time") not in (None, "") else None
            if t is not None and t < 0:
                raise ctx.error(entry, "a SpeedProfileEntry time must not be negative")
            self.entries.append((t, float_attribute(ctx.path, entry, "speed")))
        if not self.entries:
            raise ctx.error(el, "SpeedProfileAction needs at least one SpeedProfileEntry")
        dyn = el.find("DynamicConstraints")

        def get(name: str) -> float:
            return constraint(ctx, dyn, name)

        self.max_accel, self.max_decel = get("maxAcceleration"), get("maxDeceleration")
        self.accel_rate, self.decel_rate = get("maxAccelerationRate"), get("maxDecelerationRate")
        self.max_speed = get("maxSpeed")
        for name, v in (("maxAcceleration", self.max_accel), ("maxDeceleration", self.max_decel)):
            if v <= 0:
                raise ctx.error(dyn, f"{name} must be positive")

    def _target(self, ctx, speed: float) -> float:
        return speed + ctx.entities[self.ref].speed if self.ref is not None else speed

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        e.take_longitudinal(self, ctx)
        e.speed_profile = None
        # the limits: the constraints', within the entity's Performance (esmini 3.6)
        own = e.performance_limits
        self.accel_limit, self.decel_limit = min(self.max_accel, own[0]), min(self.max_decel, own[1])
        # the schedule: (time, speed) corners from the current speed on
        accel = self.accel_limit if math.isfinite(self.accel_limit) else e.limits.max_accel_mps2
        decel = self.decel_limit if math.isfinite(self.decel_limit) else e.limits.max_decel_mps2
        t, v = ctx.t, e.speed
        self.corners: list[tuple[float, float]] = [(t, v)]
        for duration, speed in self.entries:
            target = min(self._target(ctx, speed), self.max_speed)
            rate = accel if target >= v else decel
            fastest = abs(target - v) / rate if rate > 0 else 0.0
            if duration is None:  # as fast as allowed
                duration = fastest
            elif math.isfinite(self.accel_limit if target > v else self.decel_limit):
                duration = max(duration, fastest)  # a change faster than the limits takes longer (esmini)
            t += duration
            self.corners.append((t, target))
            v = target
        self.accel = e.accel if self.mode == "follow" else 0.0
        # segment k runs from corner k to k + 1; after the last corner, a flat last segment
        self.slopes = [
            (v1 - v0) / (t1 - t0) if t1 > t0 else 0.0 for (t0, v0), (t1, v1) in zip(self.corners, self.corners[1:])
        ] + [0.0]
        self.segment, self.turning = 0, True
        ctx.stepping.append(self)

    def _scheduled(self, t: float) -> float:
        """The position-mode speed at time ``t`` (linear between corners; a zero duration is a step)."""
        c = self.corners
        if t >= c[-1][0]:
            return c[-1][1]
        for (t0, v0), (t1, v1) in zip(c, c[1:]):
            if t < t1:
                return v1 if t1 <= t0 else v0 + (v1 - v0) * (t - t0) / (t1 - t0)
        return c[-1][1]

    def step(self, ctx) -> None:
        if ctx.initializing or ctx.settling:  # no time passes before t = 0 is logged
            if self.mode == "position":
                ctx.entities[self.entity].speed = self._scheduled(ctx.t)
            return
        e, dt = ctx.entities[self.entity], ctx.dt
        t_next = ctx.t + dt
        if self.mode == "position":
            e.speed = self._scheduled(t_next)
            self.done = t_next >= self.corners[-1][0] - 1e-9
            return
        # follow: the acceleration of the schedule's segment, changed at the jerk limits; the change
        # to the next segment's starts when it will end on that segment's line (the corner is cut
        # and the schedule rejoined, as esmini's), and past the last corner the speed settles on
        # the last target
        nxt = self.segment + 1
        if not self.turning and nxt < len(self.slopes):
            a1 = self.slopes[nxt]
            rate = self._rate(a1 > self.accel)
            T = abs(a1 - self.accel) / rate
            v_end = e.speed + self.accel * T + 0.5 * math.copysign(rate, a1 - self.accel) * T * T
            t_end = ctx.t + T
            err = v_end - self._line(nxt, t_end)
            if (self.accel - a1) * err >= 0.0 or t_end >= self._corner_end(nxt) - 1e-9:
                self.turning, self.segment = True, nxt
        a_target = self.slopes[self.segment]
        if self.segment == len(self.slopes) - 1 and not self.turning:  # after the schedule
            a_target = (self.corners[-1][1] - e.speed) / SPEED_TIME
        step = self._rate(a_target > self.accel) * dt
        a = min(a_target, self.accel + step) if a_target > self.accel else max(a_target, self.accel - step)
        if abs(a - self.slopes[self.segment]) < 1e-12:
            self.turning = False
        a = max(-self.decel_limit, min(self.accel_limit, a))
        self.accel = a
        e.speed = min(e.speed + a * dt, self.max_speed)
        settled = self.segment == len(self.slopes) - 1 and not self.turning
        self.done = (
            settled and t_next >= self.corners[-1][0] - 1e-9 and abs(e.speed - self.corners[-1][1]) < SETTLED_SPEED
        )

    def _line(self, k: int, t: float) -> float:
        """Speed of segment ``k``'s straight line at ``t`` (the last segment: the last target)."""
        if k >= len(self.corners) - 1:
            return self.corners[-1][1]
        (t0, v0), (t1, v1) = self.corners[k], self.corners[k + 1]
        return v1 if t1 <= t0 else v0 + (v1 - v0) * (t - t0) / (t1 - t0)

    def _corner_end(self, k: int) -> float:
        return self.corners[k + 1][0] if k < len(self.corners) - 1 else math.inf

    def _rate(self, increasing: bool) -> float:
        rate = self.accel_rate if increasing else self.decel_rate
        return rate if math.isfinite(rate) and rate > 0 else 1e12
