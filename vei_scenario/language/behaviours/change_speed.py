"""change speed: accelerate or decelerate to a target speed at a rate."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, speed_action, value

NAME = "change_speed"
AGENT = "route follower"
SUMMARY = "Accelerate or decelerate to a target speed at a constant rate."
PARAMETERS = {
    "speed_delta_mps": Parameter(-4.0, -30.0, 20.0, "change of speed (m/s); negative slows down"),
    "rate_mps2": Parameter(2.0, 0.2, 10.0, "rate of the change (m/s²), bounded by road friction"),
    "delay_s": Parameter(1.0, 0.0, 60.0, "wait before the change (s)"),
}
PROFILES = {
    "dangerous": {"speed_delta_mps": (-10.0, -6.0), "rate_mps2": (5.0, 8.0)},
    "moderate": {"speed_delta_mps": (-5.0, -3.0), "rate_mps2": (2.0, 3.5)},
    "safe": {"speed_delta_mps": (-3.0, -1.0), "rate_mps2": (0.8, 1.5)},
}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    target = max(0.0, ctx.actor_speed_mps + value(cfg, PARAMETERS, "speed_delta_mps"))
    rate = ctx.max_decel(value(cfg, PARAMETERS, "rate_mps2"))
    return [Step("change_speed", [speed_action(target, rate=rate)], delay_s=value(cfg, PARAMETERS, "delay_s"))]
