"""vei's own collision-avoidance planner as one implementation of the controller contract.

``--controller Ego=vei_scenario.sut.planner:CollisionAvoidancePlanner`` plugs in the same model the
built-in ``CollisionAvoidancePlanner`` controller runs (:mod:`vei_scenario.models.cap`), seeing only
what any user's controller sees (:class:`~vei_scenario.sut.contract.Observation`); on the case study it
reproduces the built-in planner (tests/test_sut.py). It is also a worked example of the contract.
"""

from __future__ import annotations

import math

from vei_scenario.models.cap import BRAKE, CapParameters, CapState, cap_step, threat_in_corridor
from vei_scenario.sut.contract import ObjectState, Observation


def _box(o: ObjectState) -> tuple[float, float, float, float, float]:
    return o.x_m, o.y_m, o.heading_rad, o.length_m, o.width_m


class CollisionAvoidancePlanner:
    """Cruise at ``cruiseSpeed`` (PID); brake when a watched road user (``threatEntity``, and those
    ``watchEntities`` lists) will meet the ego's path corridor within the safety distance; resume when
    none would at the cruise speed. Properties as the scenario's ``CollisionAvoidancePlanner``
    controller has them (``enabled`` "false": command 0, the speed kept)."""

    def __init__(self, **properties: str) -> None:
        self.params = CapParameters.from_properties(properties)
        self.enabled = properties.get("enabled", "true") == "true"
        self.cruise = float(properties.get("cruiseSpeed", "nan"))
        if not (math.isfinite(self.cruise) and self.cruise >= 0):
            raise ValueError("needs a non-negative property cruiseSpeed")
        if float(properties.get("followTimeGap", "0") or 0) > 0:
            raise ValueError("followTimeGap (adaptive cruise) is the built-in controller's only")
        threat = properties.get("threatEntity")
        self.watched = ([threat] if threat else []) + [
            n for n in properties.get("watchEntities", "").split() if n != threat
        ]
        self.state = CapState()

    def reset(self, info: dict) -> None:
        self.state = CapState()

    def step(self, obs: Observation) -> dict:
        if not self.enabled:
            return {"accel_mps2": 0.0, "state": "cap_off"}
        by_name = {o.name: o for o in obs.objects}
        watched = [by_name[n] for n in self.watched if n in by_name]
        if not watched and obs.threat is not None:
            watched = [obs.threat]
        ego, p = obs.ego, self.params
        margin, horizon = p.corridor_margin_m, p.horizon_s

        def view(o: ObjectState, speed: float):
            velocity = (o.speed_mps * math.cos(o.heading_rad), o.speed_mps * math.sin(o.heading_rad))
            return threat_in_corridor(_box(ego), speed, margin, _box(o), velocity, horizon)

        seen = min((view(o, ego.speed_mps) for o in watched), key=lambda v: v.time_to_conflict_s, default=None)
        resume = None
        if self.state.mode == BRAKE and watched:
            resume = min((view(o, self.cruise) for o in watched), key=lambda v: v.time_to_conflict_s)
        self.state, a_cmd, _ = cap_step(self.state, p, self.cruise, ego.speed_mps, seen, obs.dt_s, resume)
        return {"accel_mps2": a_cmd, "state": f"cap_{self.state.mode}"}
