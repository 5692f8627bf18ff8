"""wrong way: a vehicle drives against the traffic in the ego's lane, head-on towards the ego: from
the start (its spawn faces ``against`` the ego's lane), or, spawned oncoming in its own lane, it
drifts over into the ego's lane when the gap has closed to ``enter_ttc_s`` seconds at their closing
speed. With ``returns`` it swerves back to its own side at ``return_ttc_s``; without, it stays."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import (
    ActorContext,
    Condition,
    Parameter,
    Step,
    lane_change_to,
    speed_action,
    value,
)

NAME = "wrong_way"
AGENT = "route follower"
SUMMARY = "Drive head-on towards the ego in its lane; optionally swerve back to its own side."
DEFAULT_SPAWN = {"relation": "ahead", "facing": "against"}
PARAMETERS = {
    "returns": Parameter(0.0, 0.0, 1.0, "1: it swerves back to its own side, 0: it stays in the ego's lane"),
    "return_ttc_s": Parameter(3.0, 0.5, 10.0, "time to collision with the ego when it swerves back (s)"),
    "lane_change_s": Parameter(1.5, 0.6, 4.0, "duration of the swerve back (s)"),
    "enter_ttc_s": Parameter(5.0, 1.5, 12.0, "time to collision when it drifts into the ego's lane, from its own (s)"),
}
PROFILES = {
    "dangerous": {"return_ttc_s": (0.9, 1.4), "lane_change_s": (0.8, 1.1)},
    "moderate": {"return_ttc_s": (2.0, 3.0), "lane_change_s": (1.2, 1.8)},
    "safe": {"return_ttc_s": (4.5, 6.0), "lane_change_s": (1.5, 2.5)},
}
#: Seconds of head-on approach before it would meet the ego, when the text gives no distance.
APPROACH_S = 7.0


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    closing = ctx.ego_speed_mps + ctx.actor_speed_mps
    duration = value(cfg, PARAMETERS, "lane_change_s")
    returns = value(cfg, PARAMETERS, "returns") >= 0.5
    return_ttc = value(cfg, PARAMETERS, "return_ttc_s")
    if ctx.facing == "against":  # already in the ego's lane, the wrong way
        steps = [Step("wrong_way", [speed_action(ctx.actor_speed_mps)], hold_s=0.0)]
        own = 1 if ctx.actor_lane_id < 0 else -1  # its own side: next to the centre line, its way
    else:  # oncoming in its own lane: over into the ego's
        enter = max(value(cfg, PARAMETERS, "enter_ttc_s"), return_ttc + duration + 1.0 if returns else 0.0)
        over = Step("wrong_way", [lane_change_to(ctx.ego_lane_id, duration)])
        over.conditions.append(Condition("ego_within", round(max(closing * enter, 1.0), 2)))
        steps, own = [over], ctx.actor_lane_id
    if not returns:
        return steps
    back = Step("wrong_way_back", [lane_change_to(own, duration)])
    back.conditions.append(Condition("ego_within", round(max(closing * return_ttc, 1.0), 2)))
    return steps + [back]


def place(ego_speed: float, lengths_m: float, cfg: dict, speed: float) -> float:
    """Spawn distance ahead of the ego: ``APPROACH_S`` of closing, and room for the swerve back."""
    closing = ego_speed + speed
    extra = value(cfg, PARAMETERS, "enter_ttc_s") + value(cfg, PARAMETERS, "return_ttc_s")
    return lengths_m / 2 + closing * max(APPROACH_S, extra + 2.0)
