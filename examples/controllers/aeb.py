"""A small autonomous emergency braking (AEB) function, written to vei's controller contract.

    vei run out/case_study/scenario.xosc --controller Ego=examples/controllers/aeb.py:AEB

vei constructs ``AEB`` with the ego's controller properties from the scenario (and any
``--controller-param NAME=VALUE``) as text keyword arguments, calls ``reset(info)`` once before the
run and ``step(obs)`` every step; ``step`` returns the acceleration command in m/s².
"""

from __future__ import annotations

import math


def time_to_contact(ego, other, margin_m: float = 0.3) -> float:
    """Seconds until ``other``'s box centre enters the ego's path (its width plus ``margin_m`` on each
    side, ahead of its front bumper) at constant velocities; inf if it never does."""
    c, s = math.cos(ego.heading_rad), math.sin(ego.heading_rad)
    dx, dy = other.x_m - ego.x_m, other.y_m - ego.y_m
    ahead, left = c * dx + s * dy, -s * dx + c * dy  # other's position in the ego's frame
    vx = other.speed_mps * math.cos(other.heading_rad - ego.heading_rad) - ego.speed_mps
    vy = other.speed_mps * math.sin(other.heading_rad - ego.heading_rad)
    half_width = 0.5 * (ego.width_m + other.width_m) + margin_m
    front = 0.5 * (ego.length_m + other.length_m)
    if ahead <= 0:
        return math.inf
    # the times at which it is within the path's width and within reach of the front
    lat = (-math.inf, math.inf) if abs(vy) < 1e-9 else sorted(((-half_width - left) / vy, (half_width - left) / vy))
    if abs(vy) < 1e-9 and abs(left) > half_width:
        return math.inf
    if vx >= 0:
        return math.inf
    reach = (ahead - front) / -vx
    t = max(reach, lat[0], 0.0)
    return t if t <= lat[1] else math.inf


class AEB:
    """Brake at ``brake_mps2`` (default 8) while any road user is less than ``ttc_brake_s`` (default
    1.8 s) from the ego's path, else hold the speed."""

    def __init__(self, ttc_brake_s: str = "1.8", brake_mps2: str = "8", **scenario_properties: str) -> None:
        self.ttc_brake_s = float(ttc_brake_s)
        self.brake_mps2 = float(brake_mps2)

    def reset(self, info: dict) -> None:
        self.braking_since = None

    def step(self, obs) -> dict:
        ttc = min((time_to_contact(obs.ego, o) for o in obs.objects), default=math.inf)
        if ttc < self.ttc_brake_s:
            if self.braking_since is None:
                self.braking_since = obs.t_s
            return {"accel_mps2": -self.brake_mps2, "state": "aeb_brake"}
        self.braking_since = None
        return {"accel_mps2": 0.0, "state": "aeb_armed"}
