"""The ego's collision-avoidance planner (CAP): parameters and state machine.

A finite state machine: cruise (PID on speed towards the cruise speed along the ego's waypoints),
emergency brake when the threat will be in the ego's path corridor and the gap to that conflict is
below d_safe = v²/(2·a_max) + v·t_h + d0, resume when clear. The step is the compiled core's
(``vei_models.c``, shared by the interpreter, the sweep kernel and the FMUs); :func:`cap_step_arrays`
is its one vectorised form, for the numpy batch engine, held equal to it by tests. The compiler writes
the parameters into the controller properties.
"""

from __future__ import annotations

import math
from array import array
from dataclasses import asdict, astuple, dataclass
from functools import cached_property

import numpy as np

from vei_scenario.core import _core
from vei_scenario.models.properties import from_properties


@dataclass(frozen=True)
class CapParameters:
    #: Saturated emergency deceleration (m/s²): ~0.6 g, a conservative dry-asphalt AEB level.
    a_max_mps2: float = 6.0
    #: Time headway of the safety distance (s).
    t_h_s: float = 1.0
    #: Standstill margin of the safety distance (m).
    d0_m: float = 2.0
    #: PID gains of the cruise speed loop (acceleration per m/s of speed error). Chosen with
    #: :mod:`vei_scenario.models.cap_analysis` on the linearised loop (integrator plant with a 0.12 s
    #: actuator lag): 1.2 % overshoot, 1.4 s settling, closed-loop poles −5.0, −3.3, −0.025 (the slow
    #: pole sits on the PI zero). kp 0.8 / ki 0.1 overshot 10 % and settled in 18 s.
    kp: float = 2.0
    ki: float = 0.05
    kd: float = 0.0
    #: Comfortable acceleration limits in cruise (m/s²).
    max_accel_mps2: float = 2.0
    max_cruise_decel_mps2: float = 3.0
    #: Margin of the path corridor around the ego box, at each side and in front (m).
    corridor_margin_m: float = 0.5
    #: Look-ahead of the conflict prediction (s); beyond it a predicted conflict is ignored.
    horizon_s: float = 6.0

    def d_safe_m(self, v_mps: float) -> float:
        """Safety distance d_safe = v²/(2·a_max) + v·t_h + d0."""
        return v_mps * v_mps / (2 * self.a_max_mps2) + v_mps * self.t_h_s + self.d0_m

    def properties(self) -> dict[str, float]:
        return asdict(self)

    @cached_property
    def packed(self) -> bytes:
        """The parameters as the core's ``VeiCapParams`` (its field order is this class's)."""
        return array("d", astuple(self)).tobytes()

    @classmethod
    def from_properties(cls, props: dict[str, str]) -> CapParameters:
        return from_properties(cls, props)


CRUISE, BRAKE = "cruise", "brake"


@dataclass
class CapState:
    mode: str = CRUISE
    integral: float = 0.0
    prev_error: float | None = None


@dataclass(frozen=True)
class ThreatView:
    """The threat as the planner sees it: ``time_to_conflict_s``, the constant-velocity time until the
    threat's box touches the ego's path corridor (the ego box widened by the corridor margin on both
    sides and lengthened by it in front); ``inf`` when they do not meet."""

    time_to_conflict_s: float

    def in_path(self, horizon_s: float) -> bool:
        return self.time_to_conflict_s <= horizon_s


def threat_in_corridor(
    ego_box: tuple[float, float, float, float, float],
    ego_speed_mps: float,
    margin_m: float,
    threat_box: tuple[float, float, float, float, float],
    threat_velocity: tuple[float, float],
    horizon_s: float | None = None,
) -> ThreatView:
    """The planner's view of the threat: the constant-velocity time until the threat's box (x, y, yaw,
    length, width) meets the ego's path corridor, the ego box widened by ``margin_m`` on each side and
    lengthened by it in front, the ego moving at ``ego_speed_mps`` along its heading (the core's). With
    ``horizon_s``: inf where the corridor's and the threat's circumscribed circles stay apart for
    longer (the planner treats any time beyond its horizon as no conflict; the box test is left out,
    as in the sweep kernel)."""
    vx, vy = threat_velocity
    if horizon_s is None:
        return ThreatView(_core.time_to_conflict(ego_box, ego_speed_mps, margin_m, threat_box, vx, vy))
    return ThreatView(_core.time_to_conflict(ego_box, ego_speed_mps, margin_m, threat_box, vx, vy, horizon_s))


def cap_step(
    state: CapState,
    params: CapParameters,
    cruise_speed_mps: float,
    ego_speed_mps: float,
    view: ThreatView | None,
    dt: float,
    resume_view: ThreatView | None = None,
) -> tuple[CapState, float, float]:
    """One planner step: (new state, acceleration command m/s², d_safe m) — the compiled core's
    ``vei_cap_step``; :func:`cap_step_arrays` is the same step for arrays, held equal by tests.

    Cruise: PID on speed towards ``cruise_speed_mps``, limited to the comfort band, with conditional
    integration (anti-windup). Emergency brake when the threat will be in the ego's path corridor and
    the distance the ego covers before that moment, gap = v · time_to_conflict, is below
    d_safe = v²/(2·a_max) + v·t_h + d0: the deceleration that stops ``d0`` short of the conflict, at
    least the comfort deceleration, saturated at ``a_max``. Resume cruise once no conflict is
    predicted at the speed cruise would return to (``resume_view``: the threat seen with the ego at
    its cruise velocity; defaults to ``view``); resuming as soon as the slowed ego no longer meets the
    threat would drive it into the threat's wake.
    """
    ttc = view.time_to_conflict_s if view is not None else math.inf
    resume = resume_view.time_to_conflict_s if resume_view is not None else ttc
    brake, integral, prev, a_cmd, d_safe = _core.cap_step(
        state.mode == BRAKE, state.integral, state.prev_error, params.packed, cruise_speed_mps, ego_speed_mps,
        ttc, resume, dt,
    )  # fmt: skip
    return CapState(BRAKE if brake else CRUISE, integral, prev), a_cmd, d_safe


def cap_step_arrays(
    brake: np.ndarray,
    integral: np.ndarray,
    prev_error: np.ndarray,
    params: CapParameters,
    cruise_speed_mps: np.ndarray,
    ego_speed_mps: np.ndarray,
    time_to_conflict_s: np.ndarray,
    dt: float,
    resume_time_to_conflict_s: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:func:`cap_step` for many planners at once: (brake, integral, prev_error, a_cmd, d_safe).

    ``brake`` is the mode as a boolean array, ``prev_error`` NaN where the scalar state has None,
    ``time_to_conflict_s`` inf where there is no threat view. Same operations in the same order as the
    scalar planner, which tests/test_models.py checks on 10 000 random states."""
    v = np.asarray(ego_speed_mps, float)
    ttc = np.asarray(time_to_conflict_s, float)
    d_safe = v * v / (2 * params.a_max_mps2) + v * params.t_h_s + params.d0_m
    in_path = ttc <= params.horizon_s
    with np.errstate(invalid="ignore"):
        gap = np.where(in_path, v * ttc, np.inf)
    check = ttc if resume_time_to_conflict_s is None else np.asarray(resume_time_to_conflict_s, float)
    was_brake = np.asarray(brake, bool)
    now_brake = np.where(was_brake, check <= params.horizon_s, in_path & (gap < d_safe))
    room = np.maximum(gap - params.d0_m, 0.05)
    need = np.where(np.isfinite(gap), v * v / (2 * room), 0.0)
    a_brake = np.where(v > 0, -np.minimum(params.a_max_mps2, np.maximum(need, params.max_cruise_decel_mps2)), 0.0)
    error = np.asarray(cruise_speed_mps, float) - v
    prev = np.asarray(prev_error, float)
    deriv = np.where(np.isnan(prev), 0.0, (error - prev) / dt)
    integral_next = integral + error * dt
    a_raw = params.kp * error + params.ki * integral_next + params.kd * deriv
    a_cruise = np.maximum(-params.max_cruise_decel_mps2, np.minimum(params.max_accel_mps2, a_raw))
    integral_next = np.where(a_cruise != a_raw, integral, integral_next)
    return (
        now_brake,
        np.where(now_brake, integral, integral_next),
        np.where(now_brake, np.nan, error),
        np.where(now_brake, a_brake, a_cruise),
        d_safe,
    )
