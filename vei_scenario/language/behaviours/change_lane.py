"""change lane: one lane to the left or to the right. A rider at the kerb edge of the ego's own lane
that changes lane towards the road moves into the ego's lane itself (to its centre): the lane it
swerves into is the one it rides at the edge of."""

from __future__ import annotations

import math

from scenariogeneration import xosc

from vei_scenario.language.behaviours.base import (
    ActorContext,
    Parameter,
    Step,
    lane_change_to,
    neighbour_lane,
    side_with_a_lane,
    value,
)

NAME = "change_lane"
AGENT = "route follower"
SUMMARY = "Change one lane to the left (direction +1) or right (-1)."
PARAMETERS = {
    "direction": Parameter(1.0, -1.0, 1.0, "+1 left, -1 right"),
    "lane_change_s": Parameter(3.0, 0.8, 6.0, "duration (s)"),
    "delay_s": Parameter(1.0, 0.0, 60.0, "wait before the change (s)"),
}
PROFILES = {
    "dangerous": {"lane_change_s": (0.9, 1.4)},
    "moderate": {"lane_change_s": (2.0, 3.0)},
    "safe": {"lane_change_s": (3.5, 5.0)},
}


#: An actor this far off its lane's centre (m) rides at the lane's edge.
AT_EDGE_M = 0.5


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    dur = value(cfg, PARAMETERS, "lane_change_s")
    direction = side_with_a_lane(ctx, cfg, PARAMETERS["direction"].default)
    # (a lane's t grows to the left of its driving direction on the right side, ids < 0)
    towards_centre = -ctx.actor_offset_m if ctx.actor_lane_id < 0 else ctx.actor_offset_m
    at_edge = abs(ctx.actor_offset_m) > AT_EDGE_M and towards_centre * direction > 0
    if ctx.actor_lane_id == ctx.ego_lane_id and at_edge:
        # to the lane's centre over ``dur``: a sinusoidal offset change peaks at (Δ/2)(π/T)²
        peak = abs(ctx.actor_offset_m) / 2 * (math.pi / dur) ** 2
        action = xosc.AbsoluteLaneOffsetAction(0.0, xosc.DynamicsShapes.sinusoidal, round(peak, 3))
    else:
        action = lane_change_to(neighbour_lane(ctx, direction), dur)
    return [Step("change_lane", [action], delay_s=value(cfg, PARAMETERS, "delay_s"))]
