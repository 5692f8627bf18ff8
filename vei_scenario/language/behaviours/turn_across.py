"""turn across: a road user coming the other way turns across the ego's path at the junction (the
left turn across path of right-hand traffic, LTAP/OD). It waits at its stop line on the arm
opposite the ego and turns when the ego is close enough that the ego reaches their paths' meeting
point ``arrival_gap_s`` after it (negative: before it)."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, value
from vei_scenario.language.behaviours.junction_entry import (
    ego_trigger_distance_m,
    from_standing,
    go_through,
    lane_offset_m,
)
from vei_scenario.language.maps import JUNCTION_RADIUS_M

NAME = "turn_across"
AGENT = "route follower"
SUMMARY = "Come the other way and turn left across the ego's path at the junction."
DEFAULT_SPAWN = {"relation": "junction_opposite"}
PARAMETERS = {
    "arrival_gap_s": Parameter(1.0, -3.0, 6.0, "the ego reaches the meeting point this long after it (s)"),
    "turn_speed_mps": Parameter(7.0, 2.0, 14.0, "speed it turns at (m/s)"),
    "accel_mps2": Parameter(2.5, 0.5, 5.0, "acceleration from its stop line (m/s²)"),
}
PROFILES = {
    "dangerous": {"arrival_gap_s": (-0.3, 0.4)},
    "moderate": {"arrival_gap_s": (1.2, 1.8)},
    "safe": {"arrival_gap_s": (3.0, 4.0)},
}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    v = value(cfg, PARAMETERS, "turn_speed_mps")
    a = value(cfg, PARAMETERS, "accel_mps2")
    r = JUNCTION_RADIUS_M
    # its path: to the centre line of the junction, then across the ego's half; the ego's: its entry
    # to the point opposite that crossing
    actor_path = 2.0 + r + lane_offset_m(ctx.ego_lane_id) + 5.0
    ego_path = r - lane_offset_m(1) - 2.0
    gap = value(cfg, PARAMETERS, "arrival_gap_s")
    trigger = ego_trigger_distance_m(from_standing(ctx), actor_path, ego_path, v, a, gap)
    return go_through(ctx, "left", v, a, trigger, "turn_across")
