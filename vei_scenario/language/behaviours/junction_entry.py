"""What the behaviours that enter a junction from another approach share: the actor stands at (or
rolls up to) its stop line, waits for the ego to come close, and then goes through the junction
along a route, timed so that the ego reaches the point where their paths meet ``arrival_gap_s``
after the actor does (negative: before it).

Geometry of the generated crossroad (:mod:`vei_scenario.language.maps`): four arms meet at right
angles, each ends :data:`~vei_scenario.language.maps.JUNCTION_RADIUS_M` from the centre. The ego's
distance from the actor is measured in a straight line between the two (``ego_near``), since they
are on different roads; the distances to the conflict point are the arms' closed forms below (a
turn's arc is taken as the straight legs it joins, which is within a few metres: the criticality
classes' ranges are wider than that)."""

from __future__ import annotations

import math
from dataclasses import replace

from vei_scenario.language.behaviours.base import (
    ActorContext,
    Condition,
    Step,
    route_action,
    speed_action,
    time_to_cover,
)
from vei_scenario.language.maps import JUNCTION_RADIUS_M, LANE_WIDTH_M, ROUNDABOUT_RADIUS_M

#: Where a waiting road user stands: this far before its arm's end (m).
STOP_LINE_M = 2.0
#: How far a roundabout's arms end from its centre (m), as :mod:`~vei_scenario.language.maps` builds it.
RING_ARM_END_M = ROUNDABOUT_RADIUS_M + 12.0
#: A quarter of the ring between two entries, as driven (m): the arcs less the junctions' share.
RING_QUARTER_M = ROUNDABOUT_RADIUS_M * math.pi / 2


def arm_end_m(ctx: ActorContext) -> float:
    """How far the arms end from the junction's centre (m): a roundabout's arms stop at its ring, well
    out from the centre, a crossroad's at its corner. Why: the straight-line distance at which a road
    user waiting at another arm sets off is measured from where the arms really end."""
    return RING_ARM_END_M if ctx.map_kind == "roundabout" else JUNCTION_RADIUS_M


def lane_offset_m(lane_id: int) -> float:
    """Distance of a lane's centre from its road's centre line (m)."""
    return (abs(lane_id) - 0.5) * LANE_WIDTH_M


def ego_trigger_distance_m(
    ctx: ActorContext,
    actor_path_m: float,
    ego_path_m: float,
    go_speed: float,
    accel: float,
    arrival_gap_s: float,
    t_actor_s: float | None = None,
) -> float:
    """Straight-line ego–actor distance at which the actor sets off: the actor needs
    ``actor_path_m`` (from standing, at ``accel`` up to ``go_speed``) to the conflict point, the ego
    ``ego_path_m`` beyond its junction entry plus what it still has before it. ``actor_path_m`` is
    counted from the stop line; the actor's reference point stands half its length behind it (a
    lorry's 4 m more to go), and it goes at what its vehicle can reach. A behaviour whose timing the
    sampler works out as well passes its time to the conflict (``t_actor_s``), from the one helper
    both use, so that the two never differ."""
    standing = STOP_LINE_M + ctx.actor_length_m / 2  # (its centre's distance to its arm's end)
    if t_actor_s is None:
        go_speed, accel = ctx.reachable(go_speed, accel)
        t_actor_s = time_to_cover(actor_path_m + standing - STOP_LINE_M, go_speed, accel, ctx.actor_speed_mps)
    t_actor = t_actor_s
    ego_before_conflict = max(ctx.ego_speed_mps * (t_actor + arrival_gap_s), 0.0)
    # the ego on its approach, the actor at its stop line on another arm: both about the centre
    r = arm_end_m(ctx)
    ego_from_centre = max(ego_before_conflict - ego_path_m, -r) + r
    actor_from_centre = r + standing
    e, a = lane_offset_m(ctx.ego_lane_id), lane_offset_m(ctx.actor_lane_id)
    # the ego comes from the east on the north half (x = ego_from_centre, y = e); the arm ahead of it
    # comes from the west (its lanes on the south half), the one on its left from the south (east
    # half), the one on its right from the north (west half)
    if ctx.actor_road == ctx.exits.get("straight"):
        ax, ay = -actor_from_centre, -a
    elif ctx.actor_road == ctx.exits.get("left"):
        ax, ay = a, -actor_from_centre
    else:
        ax, ay = -a, actor_from_centre
    return max(1.0, math.hypot(ego_from_centre - ax, e - ay))


def go_through(
    ctx: ActorContext, turn: str, speed: float, accel: float, trigger_m: float, name: str, delay_s: float = 0.0
) -> list[Step]:
    """Set off along the route that turns ``turn`` (seen by the actor) once the ego is within ``trigger_m``."""
    rate = min(accel, ctx.actor_max_accel_mps2 or accel)
    actions = [route_action(ctx, turn, own_view=True), speed_action(speed, rate=rate)]
    steps = []
    if rolls_up(ctx):  # rolling up to its stop line: it brakes to stand there first
        to_line = max((ctx.junction_end_s_m or 0.0) - STOP_LINE_M - ctx.actor_s_m, 0.5)
        v = ctx.actor_speed_mps
        decel = max(ctx.max_decel(v * v / (2 * to_line)), 0.3)
        steps.append(Step(f"{name}_brake", [speed_action(0.0, rate=decel)]))
    steps.append(Step(name, actions, conditions=[Condition("ego_near", round(trigger_m, 2))], delay_s=delay_s))
    return steps


def rolls_up(ctx: ActorContext) -> bool:
    """Whether the actor comes up to its stop line moving (its stated speed), not standing at it."""
    return ctx.actor_speed_mps > 0.1 and ctx.junction_end_s_m is not None


def from_standing(ctx: ActorContext) -> ActorContext:
    """``ctx`` as the actor sets off: standing at its line (one that rolled up has braked there)."""
    return replace(ctx, actor_speed_mps=0.0) if rolls_up(ctx) else ctx
