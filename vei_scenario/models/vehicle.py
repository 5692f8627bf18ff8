"""Longitudinal vehicle model: an entity moving along its path by arc length.

State (s, v, a). The commanded acceleration is reached at most at ``jerk_max`` and clipped to
[−max_decel, max_accel]; speed never goes below zero. Each step integrates the constant acceleration of
the step exactly, stopping at v = 0 inside the step if it comes to rest, so that braking distances match
v²/(2a) plus the jerk ramps (see tests/test_models.py). Before standstill the braking eases off at the
jerk limit (the stop ramp of :func:`longitudinal_step`), so stopping does not exceed it either. The
step is the compiled core's (one definition for the interpreter, the sweep kernel and the FMUs).
"""

from __future__ import annotations

from dataclasses import dataclass

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
    """One step of the vehicle (the compiled core's ``vei_longitudinal_step``): the command
    bounded by the acceleration limits, the acceleration moving towards it at most by the jerk limit,
    braking eased off before standstill at that limit (the stop ramp: from |a| = n·j·dt easing off by
    j·dt a step covers v = |a|(|a| + j·dt)/(2j), so |a| ≤ (√((j·dt)² + 8·j·v) − j·dt)/2), and a
    vehicle that comes to rest inside the step stops there."""
    s, v, a = _core.longitudinal_step(
        state.s, state.v, state.a, a_cmd, limits.max_accel_mps2, limits.max_decel_mps2, limits.jerk_max_mps3, dt
    )
    return Longitudinal(s, v, a)
