"""keep lane: follow the current lane at a target speed (the actor's own speed by default)."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, speed_action, value

NAME = "keep_lane"
AGENT = "route follower"
SUMMARY = "Follow the lane at a target speed for a while."
PARAMETERS = {
    "target_speed_mps": Parameter(-1.0, -1.0, 45.0, "target speed (m/s); -1 keeps the actor's speed"),
    "accel_mps2": Parameter(1.5, 0.2, 4.0, "rate of the speed change (m/s²)"),
    "hold_s": Parameter(4.0, 0.0, 120.0, "how long it keeps the lane before what follows"),
}
PROFILES: dict[str, dict[str, tuple[float, float]]] = {}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    target = value(cfg, PARAMETERS, "target_speed_mps")
    target = ctx.actor_speed_mps if target < 0 else target
    action = speed_action(target, rate=value(cfg, PARAMETERS, "accel_mps2"))
    return [Step("keep_lane", [action], hold_s=value(cfg, PARAMETERS, "hold_s"))]
