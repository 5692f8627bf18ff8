"""The ego's collision-avoidance planner (CAP): parameters and state machine.

A finite state machine: cruise (PID on speed towards the cruise speed along the ego's waypoints),
emergency brake when the threat will be in the ego's path corridor and the gap to that conflict is
below d_safe = v²/(2·a_max) + v·t_h + d0, resume when clear. The step is the compiled core's
(``vei_models.c``, shared by the interpreter, the sweep kernel and the FMUs). The compiler writes the
parameters into the controller properties.
"""

from __future__ import annotations

import math
from array import array
from dataclasses import asdict, astuple, dataclass
from functools import cached_property

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
    ``vei_cap_step``.

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
