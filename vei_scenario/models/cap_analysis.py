"""Linear analysis of the planner's cruise speed loop with python-control.

The loop: PID C(s) = kp + ki/s + kd·s on the speed error, commanding acceleration to a vehicle whose
acceleration follows the command with a first-order lag τ (the jerk-limited actuator; τ ≈ a_max/jerk)
and whose speed integrates it: G(s) = 1 / (s (τ s + 1)). Requires ``pip install control``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from vei_scenario.models.cap import CapParameters

#: Actuator lag of the linearised vehicle (s): a 6 m/s² command at the 50 m/s³ jerk limit takes 0.12 s.
ACTUATOR_LAG_S = 0.12


@dataclass(frozen=True)
class SpeedLoop:
    poles: np.ndarray
    stable: bool
    overshoot_pct: float
    settling_time_s: float  # 2 % band
    steady_state_error: float


def analyse_speed_loop(params: CapParameters | None = None, lag_s: float = ACTUATOR_LAG_S) -> SpeedLoop:
    import control as ct

    p = params or CapParameters()
    plant = ct.tf([1.0], [lag_s, 1.0, 0.0])
    pid = ct.tf([p.kd, p.kp, p.ki], [1.0, 0.0])
    closed = ct.feedback(pid * plant, 1)
    poles = ct.poles(closed)
    stable = bool(np.all(poles.real < 0))
    t = np.linspace(0.0, 120.0, 12001)
    info = ct.step_info(closed, T=t, SettlingTimeThreshold=0.02) if stable else {}
    return SpeedLoop(
        poles=poles,
        stable=stable,
        overshoot_pct=float(info.get("Overshoot", np.inf)),
        settling_time_s=float(info.get("SettlingTime", np.inf)),
        steady_state_error=float(abs(1.0 - ct.dcgain(closed))) if stable else np.inf,
    )
