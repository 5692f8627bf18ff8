"""Longitudinal vehicle model: an entity moving along its path by arc length.

State (s, v, a). The commanded acceleration is reached at most at ``jerk_max`` and clipped to
[−max_decel, max_accel]; speed never goes below zero. Each step integrates the constant acceleration of
the step exactly, stopping at v = 0 inside the step if it comes to rest, so that braking distances match
v²/(2a) plus the jerk ramps (see tests/test_models.py). Before standstill the braking eases off at the
jerk limit (the stop ramp of :func:`longitudinal_step`), so stopping does not exceed it either. The
step is the compiled core's; :func:`longitudinal_step_arrays` its one vectorised form.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from vei_scenario.core import _core


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


def longitudinal_step(state: Longitudinal, a_cmd: float, limits: VehicleLimits, dt: float) -> Longitudinal:
    """One step of the vehicle (the compiled core's ``vei_longitudinal_step``;
    :func:`longitudinal_step_arrays` is the same for arrays, held equal by tests): the command
    bounded by the acceleration limits, the acceleration moving towards it at most by the jerk limit,
    braking eased off before standstill at that limit (the stop ramp: from |a| = n·j·dt easing off by
    j·dt a step covers v = |a|(|a| + j·dt)/(2j), so |a| ≤ (√((j·dt)² + 8·j·v) − j·dt)/2), and a
    vehicle that comes to rest inside the step stops there."""
    s, v, a = _core.longitudinal_step(
        state.s, state.v, state.a, a_cmd, limits.max_accel_mps2, limits.max_decel_mps2, limits.jerk_max_mps3, dt
    )
    return Longitudinal(s, v, a)


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
