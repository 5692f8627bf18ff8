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
  will end on the next segment's straight line, so each corner is cut and the schedule rejoined.
  The profile is continuous: the change starts within the step where it must, and each step gains
  the exact integral of its acceleration, so the speeds do not depend on the step (esmini 3.6's
  analytic profile: within 5e-7 m of it on esmini's ``speed-profile`` example at steps of 0.01 to
  0.1 s). The speed stays within ``maxSpeed``.

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
        self.segment, self.turning = self._past_steps(0), True
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
        # the last target. The change starts where it must, within the step, and the step gains the
        # exact integral of its acceleration: the speeds are those of the continuous profile at any dt.
        t, v = ctx.t, e.speed
        begins = t if self.turning else None  # when this step's change of acceleration begins
        nxt = self._past_steps(self.segment + 1)
        if not self.turning and nxt < len(self.slopes):
            a1 = self.slopes[nxt]
            jerk = math.copysign(self._rate(a1 > self.accel), a1 - self.accel)
            late = t + abs(a1 - self.accel) / abs(jerk) >= self._corner_end(nxt) - 1e-9
            when = t if late else self._cut(nxt, t, v, jerk)
            if when < t + dt:
                self.turning, self.segment, begins = True, nxt, max(t, when)
        a_target = self.slopes[self.segment]
        if self.segment == len(self.slopes) - 1 and not self.turning:  # after the schedule
            a_target, begins = (self.corners[-1][1] - v) / SPEED_TIME, t
        a_target = max(-self.decel_limit, min(self.accel_limit, a_target))
        gain, self.accel = self._integrate(self.accel, a_target, begins - t if begins is not None else dt, dt)
        if abs(self.accel - self.slopes[self.segment]) < 1e-12:
            self.turning = False
        e.speed = min(v + gain, self.max_speed)
        settled = self.segment == len(self.slopes) - 1 and not self.turning
        self.done = (
            settled and t_next >= self.corners[-1][0] - 1e-9 and abs(e.speed - self.corners[-1][1]) < SETTLED_SPEED
        )

    def _cut(self, k: int, t: float, v: float, jerk: float) -> float:
        """When a change of acceleration at ``jerk``, from the line the entity is on (through speed ``v``
        at ``t`` at its acceleration), ends on segment ``k``'s line: where the corner is cut. Lines
        ``v = a t + m``: from (a0, m0) to (a1, m1), the change lasts (a1 - a0) / jerk and gains its
        mean acceleration, so it starts at ((m1 - m0) + (a1 - a0)^2 / (2 jerk)) / (a0 - a1); at once
        when the lines are parallel (no change of acceleration to make)."""
        a0, a1 = self.accel, self.slopes[k]
        if a0 == a1:
            return t
        (tk, vk) = self.corners[k] if k < len(self.corners) - 1 else (0.0, self.corners[-1][1])
        m0, m1 = v - a0 * t, vk - a1 * tk
        return ((m1 - m0) + (a1 - a0) ** 2 / (2.0 * jerk)) / (a0 - a1)

    def _integrate(self, a0: float, a1: float, begins: float, dt: float) -> tuple[float, float]:
        """The speed a step of ``dt`` gains, and the acceleration it ends at: ``a0`` until ``begins``
        (into the step), then towards ``a1`` at the jerk limit, then ``a1`` once reached."""
        if begins >= dt or a0 == a1:
            return a0 * dt, a0
        rate = self._rate(a1 > a0)
        full = abs(a1 - a0) / rate
        ramp = min(full, dt - begins)
        a_end = a1 if full <= dt - begins else a0 + math.copysign(rate * ramp, a1 - a0)
        return a0 * begins + 0.5 * (a0 + a_end) * ramp + a1 * (dt - begins - ramp), a_end

    def _past_steps(self, k: int) -> int:
        """Segment ``k``, or the first after it that takes time: a target with no time is a step in the
        schedule, which a following entity cannot take (it heads for the segment after it at once,
        rather than spending a step on the step's zero slope)."""
        while k < len(self.slopes) - 1 and self.corners[k + 1][0] <= self.corners[k][0]:
            k += 1
        return k

    def _corner_end(self, k: int) -> float:
        return self.corners[k + 1][0] if k < len(self.corners) - 1 else math.inf

    def _rate(self, increasing: bool) -> float:
        rate = self.accel_rate if increasing else self.decel_rate
        return rate if math.isfinite(rate) and rate > 0 else 1e12
