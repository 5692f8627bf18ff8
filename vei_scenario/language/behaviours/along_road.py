"""along the road: a pedestrian, cyclist or e-scooter rider moving along the ego's road in the ego's
lane or at its kerb edge, in the ego's direction or towards it (the Euro NCAP longitudinal cases
CPLA and CBLA). Where it is in the lane is its spawn's ``lateral_m``, which way it faces the
spawn's ``facing``; here it holds its speed for ``hold_s``. Going the ego's way towards a junction
it goes straight on through it, as the ego's own road does (left to itself a road user takes the
junction's first link, a turn)."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, route_action, speed_action, value

NAME = "along_road"
AGENT = "route follower"
SUMMARY = "Walk or ride along the ego's lane (with the traffic or towards it) at its own pace."
DEFAULT_SPAWN = {"relation": "ahead"}
PARAMETERS = {
    "hold_s": Parameter(8.0, 0.0, 120.0, "how long before what follows (s)"),
    # (what the text says of the encounter, kept for what the run is checked against; where it starts is
    # its spawn: see vei_scenario.language.closest_approach)
    "gap_m": Parameter(1.5, 0.0, 60.0, "how near the ego comes to it, passing or stopping behind it (m)"),
}
PROFILES: dict[str, dict[str, tuple[float, float]]] = {}
#: Speeds when the text gives none (m/s): walking, cycling, riding an e-scooter.
PACE_MPS = {"pedestrian": 1.4, "bicycle": 4.5, "e-scooter": 4.0}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    actions: list = [speed_action(ctx.actor_speed_mps)]
    on_ego_road = ctx.exits and ctx.actor_exits.get("straight") == ctx.exits.get("straight")
    if on_ego_road and ctx.facing == "with" and ctx.actor_lane_id < 0:
        actions.insert(0, route_action(ctx, "straight", own_view=True, exit_lane=-ctx.actor_lane_id))
    return [Step("along_road", actions, hold_s=value(cfg, PARAMETERS, "hold_s"))]
