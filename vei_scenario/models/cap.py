"""Parameters of the ego's collision-avoidance planner (CAP).

A finite state machine: cruise (PID on speed towards the cruise speed along the ego's waypoints),
emergency brake when the threat is in the ego's path corridor and the gap is below
d_safe = v²/(2·a_max) + v·t_h + d0, resume when clear. The dynamics live with the interpreter; the
parameters are here so that the compiler can write them into the controller properties.
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
