"""run the red light: drive straight through the crossroad against a red signal, timed to reach
the ego's path about when the ego does (``arrival_gap_s`` after it; negative: before it)."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, route_action, speed_action

NAME = "run_red_light"
AGENT = "route follower"
SUMMARY = "Drive straight through the junction against red, timed to meet the ego's path."
DEFAULT_SPAWN = {"relation": "junction_left"}
PARAMETERS = {
    "arrival_gap_s": Parameter(0.5, -4.0, 6.0, "when it reaches the ego's path after the ego does (s)"),
}
PROFILES = {
    "dangerous": {"arrival_gap_s": (-0.3, 0.3)},
    "moderate": {"arrival_gap_s": (1.0, 1.5)},
    "safe": {"arrival_gap_s": (3.0, 4.0)},
}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    # the spawn distance (placement) sets the timing; here only the route and the held speed
    return [Step("run_red_light", [route_action(ctx, "straight", own_view=True), speed_action(ctx.actor_speed_mps)])]
