"""A batch engine for vei-compiled scenarios: many variants at once, as arrays.

It runs the same models as ``vei run`` (the array versions in :mod:`vei_scenario.models`, pinned to the
scalar ones by tests) in the same order within a step as :mod:`vei_scenario.interpreter.engine`, so a
variant's trajectories equal the interpreter's to rounding (tests/test_batch_engine.py compares them).
What it runs is the closed loop as :mod:`vei_scenario.loop` reads it (static parts from the
interpreter's own building of the scenario, what a variant changes resolved per variant); scenarios
of another structure raise :class:`~vei_scenario.loop.NotALoop` and callers fall back to the
interpreter.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from vei_scenario.interpreter.controllers import (
    recorded_start_speed,
    rider_route,
)
from vei_scenario.interpreter.entities import Polyline
from vei_scenario.loop.scene import LoopScene
from vei_scenario.models.angles import wrap_angle
from vei_scenario.models.boxes import boxes_overlap, time_to_contact
from vei_scenario.models.cap import cap_step_arrays
from vei_scenario.models.sfm import sfm_step_arrays
from vei_scenario.models.vehicle import longitudinal_step_arrays


class PathArrays:
    """A :class:`Polyline` evaluated for arrays of arc lengths or times (same arithmetic)."""

    def __init__(self, p: Polyline) -> None:
        self.x, self.y, self.h = np.array(p.xs), np.array(p.ys), np.array(p.hs)
        self.s = np.array(p.s)
        self.t = np.array(p.ts, float) if p.timed else None
        self.end_speed = p.end_speed if p.timed else 0.0
        self.length = p.length

    def _lerp(self, i, f):
        j = np.minimum(i + 1, self.x.size - 1)
        h0, h1 = self.h[i], self.h[j]
        return (
            self.x[i] + f * (self.x[j] - self.x[i]),
            self.y[i] + f * (self.y[j] - self.y[i]),
            wrap_angle(h0 + f * wrap_angle(h1 - h0)),
        )

    def at_s(self, s):
        i = np.clip(np.searchsorted(self.s, s, side="right") - 1, 0, self.x.size - 2)
        ds = self.s[i + 1] - self.s[i]
        with np.errstate(divide="ignore", invalid="ignore"):
            f = np.where(ds <= 0, 0.0, (s - self.s[i]) / ds)
        return self._held(self._lerp(i, f), s <= 0, s >= self.s[-1])

    def _held(self, pose, before, after):
        """Hold the first vertex before the path and the last one after it, as Polyline.at_s does."""
        return tuple(np.where(before, v[0], np.where(after, v[-1], q)) for v, q in zip((self.x, self.y, self.h), pose))

    def at_time(self, t):
        """Polyline.at_time: held before the start, continued along the last heading after the end."""
        ts = self.t
        i = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, ts.size - 2)
        x, y, h = self._held(self._lerp(i, (t - ts[i]) / (ts[i + 1] - ts[i])), t <= ts[0], t >= ts[-1])
        d = (t - ts[-1]) * self.end_speed
        after = t >= ts[-1]
        return (
            np.where(after, self.x[-1] + d * math.cos(self.h[-1]), x),
            np.where(after, self.y[-1] + d * math.sin(self.h[-1]), y),
            h,
        )

    def s_at_time(self, t):
        ts = self.t
        i = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, ts.size - 2)
        s = self.s[i] + (t - ts[i]) / (ts[i + 1] - ts[i]) * (self.s[i + 1] - self.s[i])
        return np.where(t <= ts[0], 0.0, np.where(t >= ts[-1], self.s[-1] + (t - ts[-1]) * self.end_speed, s))

    def project(self, px, py):
        """Arc length of the closest point of the path (the interpreter's FollowTrajectory start)."""
        best = np.zeros_like(px)
        best_d = np.full_like(px, np.inf)
        for i in range(self.x.size - 1):
            ax, ay, bx, by = self.x[i], self.y[i], self.x[i + 1], self.y[i + 1]
            L2 = (bx - ax) ** 2 + (by - ay) ** 2
            f = (
                0.0
                if L2 == 0
                else np.maximum(0.0, np.minimum(1.0, ((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / L2))
            )
            d = np.hypot(ax + f * (bx - ax) - px, ay + f * (by - ay) - py)
            closer = d < best_d - 1e-12
            best = np.where(closer, self.s[i] + f * (self.s[i + 1] - self.s[i]), best)
            best_d = np.where(closer, d, best_d)
        return best


@dataclass
class BatchResult:
    t: np.ndarray  # (T,)
    names: list[str]
    x: np.ndarray  # (E, V, T)
    y: np.ndarray
    yaw: np.ndarray
    speed: np.ndarray
    accel: np.ndarray
    collision_onsets: list[list[tuple[float, str, str]]]  # per variant, like RunResult.collisions
    ego: str
    threat: str
    lengths: list[float]
    widths: list[float]


def batch_pair(result: BatchResult):
    """The ego and the threat of every variant, as one batch :class:`PairSeries`."""
    from vei_scenario.metrics.series import PairSeries, Track

    def track(name: str) -> Track:
        k = result.names.index(name)
        return Track(
            name,
            result.lengths[k],
            result.widths[k],
            result.x[k],
            result.y[k],
            result.yaw[k],
            result.speed[k],
            result.accel[k],
        )

    return PairSeries(result.t, track(result.ego), track(result.threat))


class BatchScenario(LoopScene):
    """The closed loop, ready to run for arrays of parameter values."""

    def __init__(self, path: str | Path, dt: float = 0.01) -> None:
        super().__init__(path, dt)
        self.arrays = {name: PathArrays(polyline) for name, (polyline, _timing) in self.paths.items()}

    def run(self, variants: list[dict[str, str]]) -> BatchResult:
        """The variants as arrays; they share the model parameters (see :meth:`model_groups`)."""
        _, params = self.shared_model(variants)
        if params is None:
            return self._run(variants)
        saved = self.cap_params, self.sfm_params, self.margin
        self.cap_params, self.sfm_params = params
        self.margin = self.cap_params.corridor_margin_m
        try:
            return self._run(variants)
        finally:
            self.cap_params, self.sfm_params, self.margin = saved

    def _run(self, variants: list[dict[str, str]]) -> BatchResult:
        dt, V, E = self.dt, len(variants), len(self.names)
        r = self.resolve(variants)
        duration, rider, sfm_on, cap_on, cruise, delays = (
            r.duration,
            r.rider,
            r.sfm_on,
            r.cap_on,
            r.cruise_mps,
            r.delays,
        )
        repulsive = rider == "normal"

        x = np.empty((E, V))
        y, yaw, speed, accel = np.empty((E, V)), np.empty((E, V)), np.empty((E, V)), np.zeros((E, V))
        for k, n in enumerate(self.names):
            x[k], y[k], yaw[k] = self.init_pose[n]
            speed[k] = r.init_speed[n]
        fs = np.zeros((E, V))
        ti = self.names.index(self.threat)
        threat_poly = self.paths[self.threat][0]
        # The rider's route and start, as SocialForceController._prepare builds them.
        route = np.array(rider_route(threat_poly))
        t_start = threat_poly.ts[0] * 1.0 + delays[self.threat]
        v_start = recorded_start_speed(threat_poly)
        sfm = None  # (x, y, vx, vy, wp) once riding
        riding = np.zeros(V, bool)
        brake = np.zeros(V, bool)
        integral = np.zeros(V)
        prev_err = np.full(V, np.nan)

        rec = {q: [] for q in ("x", "y", "yaw", "speed", "accel")}
        times: list[float] = []
        onsets: list[list[tuple[float, str, str]]] = [[] for _ in range(V)]
        colliding = {}

        def record(t: float) -> None:
            times.append(t)
            for q, arr in (("x", x), ("y", y), ("yaw", yaw), ("speed", speed), ("accel", accel)):
                rec[q].append(arr.copy())

        def collide(t: float) -> None:
            for a in range(E):
                for b in range(a + 1, E):
                    hit = boxes_overlap(
                        x[a],
                        y[a],
                        yaw[a],
                        self.length[a],
                        self.width[a],
                        x[b],
                        y[b],
                        yaw[b],
                        self.length[b],
                        self.width[b],
                    )
                    before = colliding.get((a, b), np.zeros(V, bool))
                    for v in np.nonzero(hit & ~before)[0]:
                        onsets[v].append((t, self.names[a], self.names[b]))
                    colliding[(a, b)] = hit

        collide(0.0)
        record(0.0)
        step, t = 0, 0.0
        started = False
        prev_raw_stop: bool | None = None
        while t < 600.0 - 1e-9:
            raw_stop = t > duration
            if raw_stop and prev_raw_stop is False:
                break
            prev_raw_stop = raw_stop
            if not started and t > self.behaviour_start_s:
                started = True
                fs[0] = self.arrays[self.ego].project(x[0], y[0])
            t_next = t + dt
            for k, n in enumerate(self.names):
                path = self.arrays[n]
                if not started:  # no follower yet: straight ahead at the current speed
                    v0 = speed[k].copy()
                    accel[k] = (speed[k] - v0) / dt
                    ds = 0.5 * (v0 + speed[k]) * dt
                    x[k] = x[k] + ds * np.cos(yaw[k])
                    y[k] = y[k] + ds * np.sin(yaw[k])
                    continue
                if k == 0:
                    brake, integral, prev_err = self._move_ego(
                        path, x, y, yaw, speed, accel, fs, cap_on, cruise, ti, brake, integral, prev_err, dt
                    )
                    continue
                tt = t_next - delays.get(n, np.zeros(V))
                target = path.s_at_time(tt)
                px, py, ph = path.at_time(tt)
                spd = (target - fs[k]) / dt
                replay_accel = (spd - speed[k]) / dt
                if k == ti:
                    go = sfm_on & (t_next >= t_start - 1e-9)
                    begin = go & ~riding
                    if begin.any():
                        if sfm is None:
                            sfm = (x[k].copy(), y[k].copy(), np.zeros(V), np.zeros(V), np.zeros(V, np.int64))
                        sx, sy, svx, svy, swp = sfm
                        svx = np.where(begin, v_start * np.cos(yaw[k]), svx)
                        svy = np.where(begin, v_start * np.sin(yaw[k]), svy)
                        sx, sy = np.where(begin, x[k], sx), np.where(begin, y[k], sy)
                        sfm = (sx, sy, svx, svy, swp)
                        riding = riding | begin
                    if riding.any():
                        ego_box = (x[0], y[0], yaw[0], np.full(V, self.length[0]), np.full(V, self.width[0]))
                        nx_, ny_, nvx, nvy, nwp = sfm_step_arrays(*sfm, route, self.sfm_params, repulsive, ego_box, dt)
                        keep = ~riding
                        sfm = tuple(np.where(keep, old, new) for old, new in zip(sfm, (nx_, ny_, nvx, nvy, nwp)))
                        sp = np.hypot(sfm[2], sfm[3])
                        new_yaw = np.where(sp > 0.05, np.arctan2(sfm[3], sfm[2]), yaw[k])
                        accel[k] = np.where(riding, (sp - speed[k]) / dt, replay_accel)
                        x[k] = np.where(riding, sfm[0], px)
                        y[k] = np.where(riding, sfm[1], py)
                        yaw[k] = np.where(riding, new_yaw, ph)
                        speed[k] = np.where(riding, sp, spd)
                        fs[k] = np.where(riding, fs[k], target)
                        continue
                accel[k], speed[k] = replay_accel, spd
                fs[k] = target
                x[k], y[k], yaw[k] = px, py, ph
            step += 1
            t = round(step * dt, 9)
            collide(t)
            record(t)
        stack = {q: np.stack(v, axis=-1) for q, v in rec.items()}  # (E, V, T)
        return BatchResult(
            np.array(times),
            self.names,
            stack["x"],
            stack["y"],
            stack["yaw"],
            stack["speed"],
            stack["accel"],
            onsets,
            self.ego,
            self.threat,
            self.length,
            self.width,
        )

    def _move_ego(self, path, x, y, yaw, speed, accel, fs, cap_on, cruise, ti, brake, integral, prev_err, dt):
        """The ego's step (arrays updated in place): the planner where it is on, else its path at constant
        speed. Returns the planner state (brake, integral, previous error)."""
        p = self.cap_params
        c, s = np.cos(yaw[0]), np.sin(yaw[0])
        corridor = (
            x[0] + 0.5 * self.margin * c,
            y[0] + 0.5 * self.margin * s,
            yaw[0],
            self.length[0] + self.margin,
            self.width[0] + 2 * self.margin,
        )
        tvx, tvy = speed[ti] * np.cos(yaw[ti]), speed[ti] * np.sin(yaw[ti])
        threat_box = (x[ti], y[ti], yaw[ti], self.length[ti], self.width[ti])
        ttc = time_to_contact(*corridor, speed[0] * c, speed[0] * s, *threat_box, tvx, tvy)
        ttc_resume = time_to_contact(*corridor, cruise * c, cruise * s, *threat_box, tvx, tvy)
        nb, ni, npe, a_cmd, _ = cap_step_arrays(
            brake, integral, prev_err, p, cruise, speed[0], ttc, dt, np.where(brake, ttc_resume, ttc)
        )
        ds_cap, v_cap, a_cap = longitudinal_step_arrays(
            np.zeros_like(speed[0]), speed[0], accel[0], a_cmd, self.limits, dt
        )
        v0 = speed[0]
        ds = np.where(cap_on, ds_cap, 0.5 * (v0 + v0) * dt)
        fs[0] = np.minimum(fs[0] + ds, path.length)
        x[0], y[0], yaw[0] = path.at_s(fs[0])
        speed[0] = np.where(cap_on, v_cap, v0)
        accel[0] = np.where(cap_on, a_cap, (v0 - v0) / dt)
        return np.where(cap_on, nb, brake), np.where(cap_on, ni, integral), np.where(cap_on, npe, prev_err)
