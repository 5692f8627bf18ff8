"""Sparse keyframes → trajectories at the output rate: cubic-spline positions, SLERP headings.

Annotated road users are resampled along their path (:func:`resample_path`): a cubic spline through the
keyframes where they moved, travelled at a monotone (shape-preserving, PCHIP) pace. A road user that
stops stays where it stopped, facing where it was going, and never runs backwards between keyframes, as
a cubic spline of position over time does around a stop.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline, PchipInterpolator, make_smoothing_spline

from vei_scenario.geometry.angles import slerp_yaw


@dataclass(frozen=True)
class Trajectory:
    """A world trajectory in the scenario frame: scenario time (s), position (m), yaw (rad), speed (m/s)."""

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    yaw: np.ndarray
    speed: np.ndarray

    def __len__(self) -> int:
        return int(self.t.size)

    @property
    def xy(self) -> np.ndarray:
        return np.column_stack([self.x, self.y])

    def position_at(self, t) -> tuple[np.ndarray, np.ndarray]:
        """Piecewise-linear position at ``t`` (clamped to the span), as a polyline follower sees it."""
        return np.interp(t, self.t, self.x), np.interp(t, self.t, self.y)

    def arc_length(self) -> np.ndarray:
        return np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(self.x), np.diff(self.y)))])


def output_grid(t_start: float, t_end: float, rate_hz: float) -> np.ndarray:
    """Times ``k / rate`` inside [t_start, t_end], plus both ends, so every entity shares one clock."""
    k0 = int(np.ceil(t_start * rate_hz - 1e-9))
    k1 = int(np.floor(t_end * rate_hz + 1e-9))
    grid = np.arange(k0, k1 + 1) / rate_hz
    grid = np.concatenate([[t_start], grid, [t_end]])
    grid = np.unique(np.round(grid, 9))
    # Drop grid points closer than 1 ms to an end point: vertex times must strictly increase.
    keep = np.ones(grid.size, bool)
    keep[1:-1] = (grid[1:-1] - grid[0] > 1e-3) & (grid[-1] - grid[1:-1] > 1e-3)
    return grid[keep]


#: Generalised cross-validation runs on at most this many samples (scipy's GCV costs a Python loop per
#: sample and evaluation); the penalty it finds applies to the whole series, whose noise and sampling
#: interval are the same throughout a clip.
GCV_WINDOW = 100


#: The penalty range :func:`_penalty_of` searches (log10): from interpolating to stiff.
LOG_PENALTY_RANGE = (-12.0, 6.0)


def gcv_penalty(t: np.ndarray, y: np.ndarray) -> float:
    """The smoothing penalty generalised cross-validation picks on the first ``GCV_WINDOW`` samples;
    where GCV has no answer (scipy finds it ill-posed: samples whose spacing spans many orders of
    magnitude), the least penalty searched, which interpolates the samples as they are."""
    n = min(t.size, GCV_WINDOW)
    try:
        probe = make_smoothing_spline(t[:n], y[:n])
    except ValueError:
        return float(10 ** LOG_PENALTY_RANGE[0])
    return _penalty_of(probe, t[:n], y[:n])


def smoothing_spline(t: np.ndarray, y: np.ndarray, lam: float | None = None):
    """Cubic smoothing spline of y(t); penalty ``lam`` or, by default, the GCV choice."""
    return make_smoothing_spline(t, y, lam=gcv_penalty(t, y) if lam is None else lam)


def _penalty_of(spline, t: np.ndarray, y: np.ndarray) -> float:
    """Recover the GCV penalty scipy chose (it is not returned) by matching the fit at the samples."""
    target = spline(t)
    lo, hi = LOG_PENALTY_RANGE
    for _ in range(14):  # bisection on log10(lam) to 0.001 decades; the residual grows with lam
        mid = 0.5 * (lo + hi)
        res = np.sum((make_smoothing_spline(t, y, lam=10**mid)(t) - y) ** 2)
        if res < np.sum((target - y) ** 2):
            lo = mid
        else:
            hi = mid
    return float(10 ** (0.5 * (lo + hi)))


def position_spline(t: np.ndarray, x: np.ndarray, y: np.ndarray, smooth: bool) -> tuple:
    """Cubic splines x(t), y(t). ``smooth`` picks smoothing splines with the penalty chosen by
    generalised cross-validation (for noisy GPS); otherwise interpolating not-a-knot splines."""
    if smooth and t.size >= 5:
        # One receiver, one noise level: the penalty GCV picks for east serves north too.
        lam = gcv_penalty(t, x)
        return smoothing_spline(t, x, lam), smoothing_spline(t, y, lam)
    return CubicSpline(t, x), CubicSpline(t, y)


#: A keyframe this close to the last point the road user was seen moving from is taken as standing
#: there (noise-free standstill moves millimetres) ...
SAME_POINT_M = 0.05
#: ... or this many times the scatter of the positions it is computed from (the ego's GPS), whichever
#: is larger: a road user seen from a GPS-positioned car seems to drift while it stands.
SAME_POINT_PER_SCATTER = 3.0
#: Below this speed along its path a road user's heading is taken from where it goes, not its motion.
SLOW_MPS = 0.5


def standing_keyframes(x_key: np.ndarray, y_key: np.ndarray, tolerance_m: float) -> np.ndarray:
    """Index of the keyframe each keyframe stands at: itself where the road user moved on from the
    last such keyframe by more than ``tolerance_m``, else that keyframe."""
    at = np.zeros(x_key.size, int)
    for k in range(1, x_key.size):
        j = at[k - 1]
        at[k] = k if math.hypot(x_key[k] - x_key[j], y_key[k] - y_key[j]) > tolerance_m else j
    return at


def resample_path(
    t_key: np.ndarray,
    x_key: np.ndarray,
    y_key: np.ndarray,
    rate_hz: float,
    smooth: bool = False,
    standing_m: float = SAME_POINT_M,
) -> tuple[Trajectory, np.ndarray]:
    """Resample an annotated road user's keyframes at ``rate_hz``; returns the trajectory and the
    headings at the keyframes.

    A road user that keeps moving: cubic splines of position over time (smoothing splines with the
    GCV penalty with ``smooth`` and five or more keyframes), headings SLERPed between the spline's
    directions of motion at the keyframes. One that stops (keyframes within ``standing_m`` of where
    it stood): the path is the spline through the keyframes where it moved on, over their times u
    without the standstills; it runs along it at u(t), the monotone PCHIP interpolant of u at the
    keyframes, so it stays where it stopped, facing where it was going, and never runs backwards (a
    spline of position over time through a stop overshoots and returns)."""
    at = standing_keyframes(x_key, y_key, standing_m)
    node = np.unique(at)
    if node.size == t_key.size:  # it never stands still
        return resample_keyframes(t_key, x_key, y_key, rate_hz, smooth=smooth)
    grid = output_grid(float(t_key[0]), float(t_key[-1]), rate_hz)
    if node.size == 1:  # it never moves: where it was seen first
        m = grid.size
        still = Trajectory(grid, np.full(m, x_key[0]), np.full(m, y_key[0]), np.zeros(m), np.zeros(m))
        return still, np.zeros(t_key.size)
    # the path's parameter: time with the standstills taken out (a stop lasts one keyframe interval),
    # so the spline sees a road user that slows down and sets off again, not one that hovers
    after = np.minimum(node + 1, t_key.size - 1)
    tau = np.concatenate([[t_key[node[0]]], t_key[node[0]] + np.cumsum(t_key[after[:-1]] - t_key[node[:-1]])])
    # shape-preserving (PCHIP) through the (smoothed) points it moved on from: where the points progress
    # one way, so does the path between them — no overshoot past a stop and back
    sx, sy = position_spline(tau, x_key[node], y_key[node], smooth)
    cx, cy = PchipInterpolator(tau, sx(tau)), PchipInterpolator(tau, sy(tau))
    u_key = tau[np.searchsorted(node, at)]
    u_of_t = PchipInterpolator(t_key, u_key)
    u, du = u_of_t(grid), np.maximum(u_of_t(grid, 1), 0.0)
    vx, vy = cx(u, 1), cy(u, 1)
    # heading at a keyframe: the path's direction there, but around a standstill (slow, or against the
    # way it goes on) the direction from the point it came from to the point it goes on to
    kvx, kvy = cx(u_key, 1), cy(u_key, 1)
    yaw_key = np.arctan2(kvy, kvx)
    slot = np.searchsorted(node, at)
    prev_n, next_n = node[np.maximum(slot - 1, 0)], node[np.minimum(slot + 1, node.size - 1)]
    chord_x, chord_y = x_key[next_n] - x_key[prev_n], y_key[next_n] - y_key[prev_n]
    slow = (np.hypot(kvx, kvy) < SLOW_MPS) | (kvx * chord_x + kvy * chord_y <= 0.0) | (at != np.arange(at.size))
    yaw_key = np.where(slow, np.arctan2(chord_y, chord_x), yaw_key)
    yaw = slerp_yaw(t_key, yaw_key, grid)
    traj = Trajectory(grid, np.asarray(cx(u)), np.asarray(cy(u)), yaw, np.hypot(vx, vy) * du)
    return traj, yaw_key


def resample_keyframes(
    t_key: np.ndarray,
    x_key: np.ndarray,
    y_key: np.ndarray,
    rate_hz: float,
    yaw_key: np.ndarray | None = None,
    smooth: bool = False,
) -> tuple[Trajectory, np.ndarray]:
    """Resample a keyframed track at ``rate_hz``.

    Positions follow cubic splines. Headings are SLERPed between keyframe headings; without given
    headings, keyframe headings are the spline's direction of motion there. Returns the trajectory and
    the keyframe headings used.
    """
    sx, sy = position_spline(t_key, x_key, y_key, smooth)
    if yaw_key is None:
        vx, vy = sx(t_key, 1), sy(t_key, 1)
        yaw_key = np.arctan2(vy, vx)
    grid = output_grid(float(t_key[0]), float(t_key[-1]), rate_hz)
    x, y = sx(grid), sy(grid)
    speed = np.hypot(sx(grid, 1), sy(grid, 1))
    yaw = slerp_yaw(t_key, yaw_key, grid)
    return Trajectory(grid, np.asarray(x), np.asarray(y), yaw, np.asarray(speed)), np.asarray(yaw_key)
