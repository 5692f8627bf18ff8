"""sudden stop: brake at (up to) the maximum deceleration the road allows, then stand still."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, speed_action, value

NAME = "sudden_stop"
AGENT = "route follower"
SUMMARY = "Brake hard to a standstill (maximum deceleration), then stand still."
DEFAULT_SPAWN = {"relation": "ahead"}
PARAMETERS = {
    "decel_mps2": Parameter(8.0, 3.0, 10.0, "deceleration (m/s²), bounded by friction x g"),
    "delay_s": Parameter(2.0, 0.0, 60.0, "driving time before the stop (s)"),
    "headway_s": Parameter(1.5, 0.3, 6.0, "time gap to the ego at the start (s; sets the spawn)"),
}
PROFILES = {
    "dangerous": {"decel_mps2": (8.0, 9.5), "delay_s": (1.0, 2.5), "headway_s": (0.6, 1.0)},
    "moderate": {"decel_mps2": (5.0, 7.0), "delay_s": (1.5, 3.0), "headway_s": (1.3, 1.8)},
    "safe": {"decel_mps2": (3.0, 4.5), "delay_s": (2.0, 4.0), "headway_s": (2.5, 3.5)},
}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    rate = ctx.max_decel(value(cfg, PARAMETERS, "decel_mps2"))
    return [Step("sudden_stop", [speed_action(0.0, rate=rate)], delay_s=value(cfg, PARAMETERS, "delay_s"))]


def place(ego_speed: float, lengths_m: float, cfg: dict) -> tuple[float, float]:
    """(spawn longitudinal_m, speed_mps): ahead in the ego's lane at ``headway_s``, at the ego's speed."""
    return lengths_m / 2 + float(cfg.get("headway_s", 1.5)) * ego_speed, ego_speed
