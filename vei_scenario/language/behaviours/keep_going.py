"""keep going: carry on at the present speed, ignoring what happens (the default of an actor
that was told nothing else)."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, speed_action, value

NAME = "keep_going"
AGENT = "route follower"
SUMMARY = "Carry on at the present speed."
PARAMETERS = {"hold_s": Parameter(4.0, 0.0, 120.0, "how long before what follows (s)")}
PROFILES: dict[str, dict[str, tuple[float, float]]] = {}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    return [Step("keep_going", [speed_action(ctx.actor_speed_mps)], hold_s=value(cfg, PARAMETERS, "hold_s"))]
