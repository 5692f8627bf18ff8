"""forced turn: from the lane beside the ego, turn across the ego's lane at the crossroad.

The actor drives ahead of the ego in the neighbouring lane (left of it for a right turn); shortly
before the junction it cuts across the ego's lane over ``lane_change_s`` while slowing to
``turn_speed_mps``, and turns at the junction (a route through the exit on that side). One that comes
up on another arm of the junction (the one opposite) has no lane of the ego's to cut into: its turn
towards that exit is what crosses the ego's lane. Where the map has no exit on that side (a bend or
a straight road: the turn is into a car park or a drive the map does not hold), the cut across the
ego's lane while slowing for the turn is all of it the map can play, and it is what the ego meets.
"""

from __future__ import annotations

from vei_scenario.language.behaviours.base import (
    ActorContext,
    Condition,
    Parameter,
    Step,
    lane_change_to_ego,
    route_action,
    speed_action,
    value,
)

NAME = "forced_turn"
AGENT = "route follower"
SUMMARY = "Cut across the ego's lane just before the junction and turn (right by default)."
DEFAULT_SPAWN = {"relation": "left"}
PARAMETERS = {
    "gap_m": Parameter(8.0, 0.5, 60.0, "free-space gap to the ego when it cuts across (m)"),
    "lane_change_s": Parameter(1.8, 0.6, 5.0, "duration of the cut across (s)"),
    "turn_speed_mps": Parameter(6.0, 2.0, 12.0, "speed it turns at (m/s)"),
    "brake_rate_mps2": Parameter(3.0, 0.5, 8.0, "deceleration to the turn speed (m/s²)"),
    "closing_mps": Parameter(1.5, 0.3, 8.0, "how much slower than the ego it drives before (m/s)"),
    "lead_s": Parameter(2.5, 0.5, 8.0, "seconds of closing in before the gap is down to gap_m (sets the spawn)"),
}
PROFILES = {
    "dangerous": {"gap_m": (0.5, 4.0), "lane_change_s": (0.9, 1.4), "brake_rate_mps2": (4.0, 6.0)},
    "moderate": {"gap_m": (8.0, 12.0), "lane_change_s": (1.8, 2.5), "brake_rate_mps2": (2.0, 3.0)},
    "safe": {"gap_m": (20.0, 30.0), "lane_change_s": (2.5, 3.5), "brake_rate_mps2": (1.0, 2.0)},
}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    turn = str(cfg.get("turn", "right"))
    rate = ctx.max_decel(value(cfg, PARAMETERS, "brake_rate_mps2"))
    actions = [speed_action(value(cfg, PARAMETERS, "turn_speed_mps"), rate=rate)]
    if turn in ctx.exits:  # (a map with no exit on that side: only the cut across, see above)
        actions.insert(0, route_action(ctx, turn))
    if ctx.on_another_arm():
        # coming up to the junction on another arm, its turn itself crosses the ego's lane: it takes its
        # route and slows for the turn from the start (the gap to the ego, measured along its heading,
        # closes only once they have passed each other, after it would have driven through)
        return [Step("forced_turn", actions)]
    actions.insert(len(actions) - 1, lane_change_to_ego(ctx.ego, value(cfg, PARAMETERS, "lane_change_s")))
    return [Step("forced_turn", actions, conditions=[Condition("ego_within", value(cfg, PARAMETERS, "gap_m"))])]


def place(ego_speed: float, lengths_m: float, cfg: dict) -> tuple[float, float]:
    """(spawn longitudinal_m, speed_mps): beside and ahead of the ego, slower by ``closing_mps``."""
    closing = value(cfg, PARAMETERS, "closing_mps")
    lead = float(cfg.get("lead_s", 2.0))
    return lengths_m / 2 + value(cfg, PARAMETERS, "gap_m") + closing * lead, max(1.0, ego_speed - closing)
