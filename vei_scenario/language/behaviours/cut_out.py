"""cut out: the vehicle ahead of the ego in its lane changes lane round something standing in the lane
(``obstacle``, another actor) and so reveals it to the ego late. It swerves when its free-space gap
to the obstacle is down to what leaves the ego ``reveal_ttc_s`` seconds to it at its speed."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import (
    ActorContext,
    Condition,
    Parameter,
    Step,
    lane_change_to,
    neighbour_lane,
    side_with_a_lane,
    value,
)

NAME = "cut_out"
AGENT = "route follower"
SUMMARY = "Swerve out of the ego's lane round a standing obstacle, revealing it late (obstacle: its name)."
DEFAULT_SPAWN = {"relation": "ahead"}
PARAMETERS = {
    "direction": Parameter(1.0, -1.0, 1.0, "+1 to the left lane, -1 to the right"),
    "reveal_ttc_s": Parameter(3.5, 1.0, 10.0, "the ego's time to the obstacle when the lead swerves (s)"),
    "lane_change_s": Parameter(2.0, 0.8, 5.0, "duration of the swerve (s)"),
}
PROFILES = {
    "dangerous": {"reveal_ttc_s": (1.8, 2.4), "lane_change_s": (0.9, 1.3)},
    "moderate": {"reveal_ttc_s": (3.0, 3.8), "lane_change_s": (1.5, 2.2)},
    "safe": {"reveal_ttc_s": (5.5, 7.0), "lane_change_s": (2.0, 3.0)},
}
#: The lead's gap to the ego when it is placed, in seconds at the ego's speed.
LEAD_GAP_S = 1.5


def reveal_gap(ego_speed: float, lead_speed: float, lead_gap_m: float, lead_length_m: float, cfg: dict) -> float:
    """Free-space gap between the lead and the obstacle at which it swerves (m): what leaves the ego
    ``reveal_ttc_s`` to the obstacle, but no less than the lead needs to get half its width past it
    during the swerve."""
    ego_to_obstacle = ego_speed * value(cfg, PARAMETERS, "reveal_ttc_s")
    room = lead_speed * value(cfg, PARAMETERS, "lane_change_s") * 0.6 + 1.0
    return max(ego_to_obstacle - lead_gap_m - lead_length_m, room)


def reveal_gap_m(ctx: ActorContext, cfg: dict) -> float:
    lead_gap = max(ctx.actor_s_m - ctx.ego_s_m - (ctx.actor_length_m + 4.6) / 2, 0.0)
    return reveal_gap(ctx.ego_speed_mps, ctx.actor_speed_mps, lead_gap, ctx.actor_length_m, cfg)


def swerve_lane(ctx: ActorContext, cfg: dict) -> int:
    """The lane the lead swerves into: the neighbour lane of its own direction on the side said (or
    the side that has one); on a road with no such lane (one lane each way) the oncoming lane next to
    the centre line, which is where drivers go round what stands in their lane."""
    try:
        return neighbour_lane(ctx, side_with_a_lane(ctx, cfg, PARAMETERS["direction"].default))
    except ValueError:
        if ctx.lanes != 1:
            raise
        return -1 if ctx.actor_lane_id > 0 else 1


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    obstacle = cfg.get("obstacle")
    if not isinstance(obstacle, str) or not obstacle:
        raise ValueError(f"{ctx.actor}: cut_out needs config obstacle (the name of what stands in the lane)")
    target = swerve_lane(ctx, cfg)
    change = lane_change_to(target, value(cfg, PARAMETERS, "lane_change_s"))
    return [Step("cut_out", [change], conditions=[Condition("ego_within", round(reveal_gap_m(ctx, cfg), 2), obstacle)])]


def place(ego_speed: float, lengths_m: float, cfg: dict) -> tuple[float, float]:
    """(spawn longitudinal_m, speed_mps): ``LEAD_GAP_S`` ahead of the ego at the ego's speed."""
    return lengths_m / 2 + ego_speed * LEAD_GAP_S, ego_speed
