"""The ego's collision-avoidance planner (CAP): parameters and state machine.

A finite state machine: cruise (PID on speed towards the cruise speed along the ego's waypoints),
emergency brake when the threat is in the ego's path corridor and the gap is below
d_safe = v²/(2·a_max) + v·t_h + d0, resume when clear. Pure numerical code shared by the interpreter,
the batch engine and the FMU tests; the compiler writes the parameters into the controller properties.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass


@dataclass(frozen=True)
class CapParameters:
    #: Saturated emergency deceleration (m/s²): ~0.6 g, a conservative dry-asphalt AEB level.
    a_max_mps2: float = 6.0
    #: Time headway of the safety distance (s).
    t_h_s: float = 1.0
    #: Standstill margin of the safety distance (m).
    d0_m: float = 2.0
    #: PID gains of the cruise speed loop (acceleration per m/s of speed error).
    kp: float = 0.8
    ki: float = 0.1
    kd: float = 0.0
    #: Comfortable acceleration limits in cruise (m/s²).
    max_accel_mps2: float = 2.0
    max_cruise_decel_mps2: float = 3.0
    #: Extra half-width of the path corridor beyond the two boxes (m).
    corridor_margin_m: float = 0.5

    def d_safe_m(self, v_mps: float) -> float:
        """Safety distance d_safe = v²/(2·a_max) + v·t_h + d0."""
        return v_mps * v_mps / (2 * self.a_max_mps2) + v_mps * self.t_h_s + self.d0_m

    def properties(self) -> dict[str, float]:
        return asdict(self)

    @classmethod
    def from_properties(cls, props: dict[str, str]) -> CapParameters:
        names = set(cls.__dataclass_fields__)
        return cls(**{k: float(v) for k, v in props.items() if k in names})


CRUISE, BRAKE = "cruise", "brake"


@dataclass
class CapState:
    mode: str = CRUISE
    integral: float = 0.0
    prev_error: float | None = None


@dataclass(frozen=True)
class ThreatView:
    """The threat seen from the ego's path: ``gap_m`` along the path from the ego's front to the near
    edge of the threat (negative once beside or behind), ``lateral_m`` offset of the threat's centre
    from the path, ``lateral_rate_mps`` its rate of change (positive: moving left)."""

    gap_m: float
    lateral_m: float
    lateral_rate_mps: float


def in_corridor(view: ThreatView, half_width_m: float, ego_speed_mps: float) -> bool:
    """The threat is, or will be when the ego gets there, inside the path corridor.

    Constant-velocity prediction over the time the ego needs to close the gap: a crossing scooter that
    is still beside the road but will be in the ego's path when the ego arrives counts, one that will
    have left it does not.
    """
    if view.gap_m < -0.5:
        return False
    if abs(view.lateral_m) <= half_width_m:
        return True
    horizon = max(view.gap_m, 0.0) / max(ego_speed_mps, 0.1)
    later = view.lateral_m + view.lateral_rate_mps * horizon
    return min(view.lateral_m, later) <= half_width_m and max(view.lateral_m, later) >= -half_width_m


def cap_step(
    state: CapState,
    params: CapParameters,
    cruise_speed_mps: float,
    ego_speed_mps: float,
    view: ThreatView | None,
    corridor_half_width_m: float,
    dt: float,
) -> tuple[CapState, float, float]:
    """One planner step: (new state, acceleration command m/s², d_safe m).

    Cruise: PID on speed towards ``cruise_speed_mps``, limited to the comfort band, with conditional
    integration (anti-windup). Emergency brake when the threat is in the corridor ahead and the gap is
    below d_safe: the deceleration that stops ``d0`` short of the threat, saturated at ``a_max``.
    Resume cruise when the threat has left the corridor or is no longer ahead.
    """
    v = ego_speed_mps
    d_safe = params.d_safe_m(v)
    threat_ahead = view is not None and in_corridor(view, corridor_half_width_m, v)
    mode = state.mode
    if mode == CRUISE and threat_ahead and view.gap_m < d_safe:
        mode = BRAKE
    elif mode == BRAKE and not threat_ahead:
        mode = CRUISE
    if mode == BRAKE:
        room = max(view.gap_m - params.d0_m, 0.05)
        a_cmd = -min(params.a_max_mps2, v * v / (2 * room)) if v > 0 else 0.0
        return CapState(BRAKE, state.integral, None), a_cmd, d_safe
    error = cruise_speed_mps - v
    deriv = 0.0 if state.prev_error is None else (error - state.prev_error) / dt
    integral = state.integral + error * dt
    a_raw = params.kp * error + params.ki * integral + params.kd * deriv
    a_cmd = max(-params.max_cruise_decel_mps2, min(params.max_accel_mps2, a_raw))
    if a_cmd != a_raw:  # saturated: do not integrate further (anti-windup)
        integral = state.integral
    return CapState(CRUISE, integral, error), a_cmd, d_safe
