"""Sparse keyframes → trajectories at the output rate: cubic-spline positions, SLERP headings."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline, make_smoothing_spline

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


def gcv_penalty(t: np.ndarray, y: np.ndarray) -> float:
    """The smoothing penalty generalised cross-validation picks on the first ``GCV_WINDOW`` samples."""
    n = min(t.size, GCV_WINDOW)
    probe = make_smoothing_spline(t[:n], y[:n])
    return _penalty_of(probe, t[:n], y[:n])


def smoothing_spline(t: np.ndarray, y: np.ndarray, lam: float | None = None):
    """Cubic smoothing spline of y(t); penalty ``lam`` or, by default, the GCV choice."""
    return make_smoothing_spline(t, y, lam=gcv_penalty(t, y) if lam is None else lam)


def _penalty_of(spline, t: np.ndarray, y: np.ndarray) -> float:
    """Recover the GCV penalty scipy chose (it is not returned) by matching the fit at the samples."""
    target = spline(t)
    lo, hi = -12.0, 6.0
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
