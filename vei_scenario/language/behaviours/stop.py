"""stop: the cautious planner's stop, a comfortable deceleration to standstill, then standing."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, speed_action, value

NAME = "stop"
AGENT = "cautious planner"
SUMMARY = "Decelerate comfortably to a standstill and stand."
PARAMETERS = {
    "decel_mps2": Parameter(2.5, 0.5, 4.0, "comfortable deceleration (m/s²)"),
    "delay_s": Parameter(1.0, 0.0, 60.0, "wait before braking (s)"),
}
PROFILES: dict[str, dict[str, tuple[float, float]]] = {}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    rate = ctx.max_decel(value(cfg, PARAMETERS, "decel_mps2"))
    return [Step("stop", [speed_action(0.0, rate=rate)], delay_s=value(cfg, PARAMETERS, "delay_s"))]
