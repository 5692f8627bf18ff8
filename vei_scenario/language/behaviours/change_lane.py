"""change lane: one lane to the left or to the right."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, lane_change_to, neighbour_lane, value

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


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    target = neighbour_lane(ctx, value(cfg, PARAMETERS, "direction"))
    dur = value(cfg, PARAMETERS, "lane_change_s")
    return [Step("change_lane", [lane_change_to(target, dur)], delay_s=value(cfg, PARAMETERS, "delay_s"))]
