"""run the red light: drive through the crossroad against a red signal, timed to reach the ego's
path about when the ego does (``arrival_gap_s`` after it; negative: before it).

Its way through is the one its ``turn`` says (``straight``, ``left`` or ``right``: what the text says of
it, "carried straight on past me"). Where nothing says it, it drives straight on, unless straight on
never meets the ego's way: from the arm opposite the ego, the two pass side by side when the ego goes
straight on or turns right, so that runner turns left, across the ego's path or into the road the ego
turns into (:func:`way_through`). Why: running the red is what puts it in the ego's way; a runner that
only passes the ego in its own lane is no conflict, unless the text says that is what it did."""

from __future__ import annotations

import math

from vei_scenario.language.behaviours.base import (
    ActorContext,
    Parameter,
    Step,
    route_action,
    speed_action,
    time_to_cover,
)
from vei_scenario.language.maps import JUNCTION_RADIUS_M, ROUNDABOUT_RADIUS_M

NAME = "run_red_light"
AGENT = "route follower"
SUMMARY = "Drive straight through the junction against red, timed to meet the ego's path."
DEFAULT_SPAWN = {"relation": "junction_left"}
PARAMETERS = {
    "arrival_gap_s": Parameter(0.5, -4.0, 6.0, "when it reaches the ego's path after the ego does (s)"),
}
#: Its ``turn`` (a word, as forced_turn's): its way through as it sees it; absent, :func:`way_through` chooses.
WAYS = ("straight", "left", "right")
PROFILES = {
    "dangerous": {"arrival_gap_s": (-0.3, 0.3)},
    "moderate": {"arrival_gap_s": (1.0, 1.5)},
    "safe": {"arrival_gap_s": (3.0, 4.0)},
}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    # the spawn distance (placement) sets the timing; here only the route and the held speed
    actions = [speed_action(running_mps(ctx))]
    if not ctx.routed:  # (one an earlier behaviour turns at the junction runs the red along that turn)
        # (the way the text says, else one that meets the ego: the maps drive on the right, and
        # way_through's choice for the opposite arm assumes so)
        said = cfg.get("turn")
        way = way_through(ctx, str(said) if said in WAYS else None)
        # (a turn leaves on the exit lane its own lane leads to: the arms' lanes are joined one to one)
        lane = {"exit_lane": abs(ctx.actor_lane_id)} if way != "straight" else {}
        actions.insert(0, route_action(ctx, way, own_view=True, **lane))
    return [Step("run_red_light", actions, hold_s=through_s(ctx))]


def way_through(ctx: ActorContext, said: str | None = None) -> str:
    """The runner's way through a crossroad, as it sees it: the way ``said`` (the text's) where its arm
    has that exit; where none is said, straight on, or left from the arm opposite the ego when the ego
    goes straight on or turns right (right-hand traffic, as the maps are built: straight on, the runner
    would only pass the ego side by side; turning left it crosses the ego's way, or merges into the
    road the ego turns into). Elsewhere, and where the arm has no such exit, straight on."""
    if said is not None:
        return said if said == "straight" or ctx.actor_exits.get(said) else "straight"
    opposite = ctx.exits.get("straight")
    if ctx.map_kind == "crossroad" and ctx.actor_road == opposite and ctx.ego_route in ("straight", "right"):
        if ctx.actor_exits.get("left"):
            return "left"
    return "straight"


def passes_by(relation: str, said: object, ego_route: str) -> bool:
    """Whether a runner the text sends straight on (``said``, its ``turn``) from the arm opposite the ego
    only passes the ego side by side (the ego going straight on or turning right, right-hand traffic):
    its way never meets the ego's, as the text says, so no run near the ego's path is to be asked of it."""
    return relation == "junction_opposite" and said == "straight" and ego_route in ("straight", "right")


def through_s(ctx: ActorContext) -> float:
    """How long the run lasts (s): until the runner is through the junction's middle, or half round a
    roundabout's ring (from the entry left of the ego's the ways meet only after a quarter). Why: its actions end at
    once, and what the text has it do next ("... and stops dead") must come once it is on the ego's
    path, not seconds after it set off far up its arm."""
    to_entry = max(0.0, ctx.junction_end_s_m - ctx.actor_s_m) if ctx.junction_end_s_m else 0.0
    through = math.pi * ROUNDABOUT_RADIUS_M if ctx.map_kind == "roundabout" else 2 * JUNCTION_RADIUS_M
    v = running_mps(ctx)
    return round(min(time_to_cover(to_entry + through, v, ctx.actor_max_accel_mps2, start_mps=v), 60.0), 3)


#: Below this start speed (m/s) a runner set off from a standstill: it stood until now.
STANDING_MPS = 0.5


def running_mps(ctx: ActorContext) -> float:
    """The speed it runs the red at: its own, or, where it starts standing (a rider who crossed from the
    kerb first, one who stood at the kerb: "came off the pavement and went straight through his red
    light"), a walker's or rider's pace for its kind, else the ego's. Why: held at the standstill it
    started in, it never set off, and the run the text tells was never made."""
    if ctx.actor_speed_mps >= STANDING_MPS:
        return ctx.actor_speed_mps
    from vei_scenario.language.behaviours.along_road import PACE_MPS

    return PACE_MPS.get(ctx.actor_type, max(ctx.ego_speed_mps, 8.0))
