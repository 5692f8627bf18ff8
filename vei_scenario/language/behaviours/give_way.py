"""give way: a road user whose path meets the ego's lets the ego go first. On a side road it brakes
to a stop at its stop line (or stays there) and waits until the ego has cleared the junction by
``clear_s``, then goes on (straight, or ``turn`` left or right as it sees it); at the kerb it stands
until the ego has gone past by ``clear_s``
(a crossing that follows then passes behind the ego)."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext, Parameter, Step, route_action, speed_action, value
from vei_scenario.language.behaviours.junction_entry import STOP_LINE_M
from vei_scenario.language.maps import JUNCTION_RADIUS_M

NAME = "give_way"
AGENT = "route follower"
SUMMARY = "Stop short of the ego's path, let the ego pass, then go on."
DEFAULT_SPAWN = {"relation": "junction_right"}
PARAMETERS = {
    "clear_s": Parameter(1.5, 0.0, 10.0, "how long after the ego has passed it goes on (s)"),
    "go_speed_mps": Parameter(8.0, 1.0, 20.0, "speed it goes on at through the junction (m/s)"),
}
PROFILES = {
    "dangerous": {"clear_s": (0.0, 0.4)},
    "moderate": {"clear_s": (1.0, 2.0)},
    "safe": {"clear_s": (3.0, 4.0)},
}
#: The pace a vulnerable road user goes on at (m/s).
VRU_PACE_MPS = {"pedestrian": 1.5, "bicycle": 4.5, "e-scooter": 4.0}
#: What the ego has to cover beyond the actor before it counts as passed: its length and a margin (m).
EGO_CLEAR_M = 4.6 + 2.0


def ego_passed_s(ctx: ActorContext) -> float:
    """When the ego, at its speed, has gone past the actor's path (s from the start)."""
    if ctx.crossing_path is not None:  # at the kerb: the ego passes its longitudinal position
        beyond = ctx.actor_s_m - ctx.ego_s_m + EGO_CLEAR_M
    else:  # across the junction
        beyond = ctx.ego_to_junction_m() + 2 * JUNCTION_RADIUS_M + EGO_CLEAR_M
    return max(beyond, 0.0) / max(ctx.ego_speed_mps, 0.5)


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    clear = value(cfg, PARAMETERS, "clear_s")
    wait = ego_passed_s(ctx) + clear
    if ctx.crossing_path is not None:
        return [Step("give_way", [speed_action(0.0)], hold_s=round(wait, 3))]
    if not ctx.actor_exits:
        raise ValueError(f"{ctx.actor}: give_way needs a spawn at a junction arm or at the kerb")
    to_line = max((ctx.junction_end_s_m or 0.0) - STOP_LINE_M - ctx.actor_s_m, 0.5)
    v = ctx.actor_speed_mps
    steps = []
    if v > 0.1:  # rolling up: brake to stand at the line
        decel = ctx.max_decel(v * v / (2 * to_line))
        steps.append(Step("give_way_brake", [speed_action(0.0, rate=max(decel, 0.3))]))
        wait -= v / max(decel, 0.3)
    go = value(cfg, PARAMETERS, "go_speed_mps")
    if ctx.actor_type in VRU_PACE_MPS:  # a cyclist or a walker goes on at its own pace
        go = min(go, VRU_PACE_MPS[ctx.actor_type])
    rate = min(2.5, ctx.actor_max_accel_mps2 or 2.5)
    steps.append(
        Step(
            "give_way_go",
            [route_action(ctx, str(cfg.get("turn", "straight")), own_view=True), speed_action(go, rate=rate)],
            delay_s=round(max(wait, 0.0), 3),
        )
    )
    return steps
