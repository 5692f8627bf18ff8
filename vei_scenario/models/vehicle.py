"""Longitudinal vehicle model: an entity moving along its path by arc length.

State (s, v, a). The commanded acceleration is reached at most at ``jerk_max`` and clipped to
[−max_decel, max_accel]; speed never goes below zero. Each step integrates the constant acceleration of
the step exactly, stopping at v = 0 inside the step if it comes to rest, so that braking distances match
v²/(2a) plus the jerk ramps (see tests/test_models.py). Before standstill the braking eases off at the
jerk limit (:func:`stop_ramp`), so stopping does not exceed it either.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class VehicleLimits:
    max_accel_mps2: float = 4.0
    max_decel_mps2: float = 9.0
    #: Jerk limit (m/s³); 50 m/s³ lets an emergency brake build up in ~0.15 s, typical of AEB actuators.
    jerk_max_mps3: float = 50.0


@dataclass
class Longitudinal:
    s: float
    v: float
    a: float = 0.0


def stop_ramp(v: float, limits: VehicleLimits, dt: float) -> float:
    """The strongest deceleration (negative) from which the braking can still ease off to zero at the
    jerk limit j by the time the vehicle stands. Easing off by j·dt a step from |a| = n·j·dt covers
    v = |a|(|a| + j·dt)/(2j), so |a| = (√((j·dt)² + 8·j·v) − j·dt)/2 (→ √(2·j·v) as dt → 0). Without
    it the deceleration would drop to zero in the step the vehicle stops (3 m/s² in 0.01 s: 300 m/s³)."""
    if v <= 0.0:
        return 0.0
    jdt = limits.jerk_max_mps3 * dt
    return -0.5 * (math.sqrt(jdt * jdt + 8.0 * limits.jerk_max_mps3 * v) - jdt)


def longitudinal_step(state: Longitudinal, a_cmd: float, limits: VehicleLimits, dt: float) -> Longitudinal:
    target = max(-limits.max_decel_mps2, min(limits.max_accel_mps2, a_cmd))
    if target < 0.0:
        target = max(target, stop_ramp(state.v, limits, dt))
    da = limits.jerk_max_mps3 * dt
    a = max(state.a - da, min(state.a + da, target))
    v0 = state.v
    if v0 <= 0.0 and a <= 0.0:
        return Longitudinal(state.s, 0.0, 0.0)
    v1 = v0 + a * dt
    if v1 < 0.0:  # comes to rest inside the step
        t_stop = v0 / -a
        return Longitudinal(state.s + v0 * t_stop + 0.5 * a * t_stop * t_stop, 0.0, a)
    return Longitudinal(state.s + v0 * dt + 0.5 * a * dt * dt, v1, a)


def longitudinal_step_arrays(s, v, a, a_cmd, limits: VehicleLimits, dt: float):
    """:func:`longitudinal_step` for many vehicles at once: (s, v, a) arrays."""
    s, v0, a0 = (np.asarray(q, float) for q in (s, v, a))
    target = np.maximum(-limits.max_decel_mps2, np.minimum(limits.max_accel_mps2, np.asarray(a_cmd, float)))
    jdt = limits.jerk_max_mps3 * dt
    ramp = np.where(v0 > 0.0, -0.5 * (np.sqrt(jdt * jdt + 8.0 * limits.jerk_max_mps3 * np.maximum(v0, 0.0)) - jdt), 0.0)
    target = np.where(target < 0.0, np.maximum(target, ramp), target)
    da = limits.jerk_max_mps3 * dt
    acc = np.maximum(a0 - da, np.minimum(a0 + da, target))
    resting = (v0 <= 0.0) & (acc <= 0.0)
    v1 = v0 + acc * dt
    stops = ~resting & (v1 < 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        t_stop = np.where(stops, v0 / -acc, 0.0)
    s_next = np.where(
        resting, s, np.where(stops, s + v0 * t_stop + 0.5 * acc * t_stop * t_stop, s + v0 * dt + 0.5 * acc * dt * dt)
    )
    return s_next, np.where(resting | stops, 0.0, v1), np.where(resting, 0.0, acc)
