"""turn into: a road user waiting in a side road pulls out of it into the ego's road, ahead of the
ego and in its direction (from the left it turns left across the near half, from the right it turns
right). It sets off when the ego is close enough that the ego reaches the point where it joins
``arrival_gap_s`` after it, then drives on to ``speed_mps``.

One that waits beside the ego's road instead (a spawn on a roadside: it comes out of a driveway, a
field gate, a car park) has no side road to drive along: it stands off the road facing it, and turns
out across the kerb line along a path (:func:`roadside_path_st`) that ends in the ego's lane, in the
ego's direction (from the far side across the oncoming lanes first); there it drives on along the
lane. Its timing is the same: the ego reaches where it joins ``arrival_gap_s`` after it."""

from __future__ import annotations

import math
from dataclasses import replace

from scenariogeneration import xosc

from vei_scenario.language.behaviours.base import (
    ActorContext,
    Condition,
    Parameter,
    Step,
    route_action,
    speed_action,
    time_to_cover,
    value,
)
from vei_scenario.language.behaviours.junction_entry import (
    RING_ARM_END_M,
    RING_QUARTER_M,
    ego_trigger_distance_m,
    from_standing,
    go_through,
    lane_offset_m,
)
from vei_scenario.language.maps import JUNCTION_RADIUS_M, ROUNDABOUT_RADIUS_M

NAME = "turn_into"
AGENT = "route follower"
SUMMARY = "Pull out of a side road into the ego's road ahead of it, in its direction."
DEFAULT_SPAWN = {"relation": "junction_right"}
PARAMETERS = {
    "arrival_gap_s": Parameter(1.5, -2.0, 8.0, "the ego reaches where it joins this long after it (s)"),
    "speed_mps": Parameter(10.0, 2.0, 25.0, "speed it drives on at once in the ego's road (m/s)"),
    "accel_mps2": Parameter(2.5, 0.5, 5.0, "acceleration from its stop line (m/s²)"),
}
PROFILES = {
    "dangerous": {"arrival_gap_s": (0.0, 0.6)},
    "moderate": {"arrival_gap_s": (1.5, 2.2)},
    "safe": {"arrival_gap_s": (3.5, 5.0)},
}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    if ctx.crossing_path is not None:  # (the writer's path out of a place beside the road)
        return from_the_roadside(ctx, cfg)
    from_left = ctx.actor_road == ctx.exits.get("left")
    turn = "left" if from_left else "right"
    if ctx.actor_exits.get(turn) != ctx.exits.get("straight"):
        raise ValueError(f"{ctx.actor}: turn_into needs a spawn on a side road (junction_left or junction_right)")
    actor_path, ego_path = paths_m(from_left, ctx.ego_lane_id, ring=ctx.map_kind == "roundabout")
    v = value(cfg, PARAMETERS, "speed_mps")
    a = value(cfg, PARAMETERS, "accel_mps2")
    standing = from_standing(ctx)
    t_actor = time_to_join_s(
        actor_path, cfg, ctx.actor_length_m, ctx.actor_max_speed_mps, ctx.actor_max_accel_mps2, standing.actor_speed_mps
    )
    gap = value(cfg, PARAMETERS, "arrival_gap_s")
    trigger = ego_trigger_distance_m(standing, actor_path, ego_path, min(v, JOIN_SPEED_CAP_MPS), a, gap, t_actor)
    return go_through(ctx, turn, v, a, trigger, "turn_into")


#: The fastest a road user pulling out is counted on to go until it has joined the ego's road (m/s).
JOIN_SPEED_CAP_MPS = 8.0


def time_to_join_s(
    actor_path_m: float,
    cfg: dict,
    length_m: float = 0.0,
    top_mps: float = 0.0,
    max_accel_mps2: float = 0.0,
    start_mps: float = 0.0,
) -> float:
    """The road user's time from its stop line to where it joins the ego's road (s): ``actor_path_m``
    (:func:`paths_m`) plus the half of its length its reference point stands behind the line, at its
    acceleration up to its speed (held below :data:`JOIN_SPEED_CAP_MPS` until it is in), each no more
    than its vehicle's (``top_mps``, ``max_accel_mps2``; 0: not bounded). Why one helper: the writer's
    trigger, the sampler's room for the ego and its timing for a stated gap must agree, or a road
    user told to pull out 20 m ahead sets off at another distance."""
    v = min(value(cfg, PARAMETERS, "speed_mps"), JOIN_SPEED_CAP_MPS)
    a = value(cfg, PARAMETERS, "accel_mps2")
    v = min(v, top_mps) if top_mps > 0 else v
    a = min(a, max_accel_mps2) if max_accel_mps2 > 0 else a
    return time_to_cover(actor_path_m + length_m / 2, v, a, start_mps)


def paths_m(from_left: bool, ego_lane_id: int, ring: bool = False) -> tuple[float, float]:
    """(the road user's path from its stop line to where it joins, the ego's from its junction entry
    to there) (m): from the left it crosses the far half and joins beyond the centre, from the right
    it joins at once. On a roundabout (``ring``) the ring runs anticlockwise: from the entry on the
    ego's left it goes a quarter round to the ego's own entry and joins there, in front of the ego;
    from the entry on its right it joins at once, where the ego arrives a quarter round later."""
    if ring:
        to_ring = RING_ARM_END_M - ROUNDABOUT_RADIUS_M
        if from_left:
            return 2.0 + to_ring + RING_QUARTER_M, to_ring
        return 2.0 + to_ring + 3.0, to_ring + RING_QUARTER_M
    r = JUNCTION_RADIUS_M
    e = lane_offset_m(ego_lane_id)
    return 2.0 + (r + e + 3.0 if from_left else 0.6 * r + 3.0), r + (r * 0.5 if from_left else 3.0)


def gap_for_distance(
    distance_m: float,
    ego_speed_mps: float,
    from_left: bool,
    ego_lane_id: int,
    cfg: dict,
    vehicle: tuple[float, float, float] = (0.0, 0.0, 0.0),
    ring: bool = False,
) -> float:
    """The ``arrival_gap_s`` that sets it off from its stop line when the ego is ``distance_m`` before
    the side road's mouth ("pulls out of a side road 20 m ahead of me": the distance the driver sees
    to the road it comes out of): the ego's time to where it joins less its own time to get there
    (:func:`time_to_join_s`; ``vehicle`` its length, top speed and acceleration)."""
    actor_path, ego_path = paths_m(from_left, ego_lane_id, ring)
    t_actor = time_to_join_s(actor_path, cfg, *vehicle)
    return (distance_m + ego_path) / max(ego_speed_mps, 0.5) - t_actor


def ego_distance_at_set_off_m(ego_speed_mps: float, t_actor_s: float, ego_path_m: float, arrival_gap_s: float) -> float:
    """How far before its junction entry the ego is when the road user sets off (m): it reaches
    where the road user joins ``arrival_gap_s`` after the road user's ``t_actor_s``."""
    return ego_speed_mps * (t_actor_s + arrival_gap_s) - ego_path_m


#: How far along the road (m) a road user turning out of a place beside it at least goes while it turns
#: into its lane (a tight turn out of a driveway); across a wider way it turns as wide as it goes over.
TURN_OUT_MIN_M = 6.0
#: How far (m) its path runs straight on in the ego's lane after the turn, before it keeps the lane on
#: its own (a path ending on a lane hands the road user to the lane, as esmini does).
SETTLE_M = 4.0
#: Points of the path's turn.
_TURN_POINTS = 12


def roadside_path_st(s0: float, t0: float, t_lane: float, start_rad: float = math.pi / 2) -> list[tuple[float, float]]:
    """The path (s, t on the ego's road) of a road user turning out of a place beside the road at
    (``s0``, ``t0``) into the lane whose centre is at ``t_lane``, in the road's direction of increasing
    s (the ego's): part of a quarter ellipse, from ``start_rad`` off the road's direction (square to
    the kerb by default) to facing along it, then a short straight in the lane. Why an ellipse: it
    leaves the roadside square to the kerb, as one out of a drive does (or at the angle of one nosed
    out of a parking space, the rest of the same turn), and meets the lane tangent to it, so that the
    lane takes it over without a kink."""
    a, b, skipped = _turn_axes(t_lane - t0, start_rad)
    turn = [
        (s0 + a * (math.cos(skipped) - math.cos(f)), t0 + b * (math.sin(f) - math.sin(skipped)))
        for f in (skipped + (math.pi / 2 - skipped) * k / _TURN_POINTS for k in range(_TURN_POINTS + 1))
    ]
    return turn + [(s0 + a * math.cos(skipped) + SETTLE_M, t_lane)]


def _turn_axes(lateral_m: float, start_rad: float) -> tuple[float, float, float]:
    """(the along and across semi-axes of the ellipse of :func:`roadside_path_st` over ``lateral_m``,
    the part of its quarter (rad) already turned at ``start_rad`` off the road's direction)."""
    skipped = math.pi / 2 - min(max(start_rad, 0.1), math.pi / 2)
    b = lateral_m / (1.0 - math.sin(skipped))
    return max(abs(b), TURN_OUT_MIN_M), b, skipped


def roadside_turn_m(lateral_m: float, start_rad: float = math.pi / 2) -> tuple[float, float]:
    """(the length of the turn of :func:`roadside_path_st` over ``lateral_m`` from ``start_rad`` off
    the road's direction, how far along the road it goes meanwhile) (m)."""
    pts = roadside_path_st(0.0, 0.0, lateral_m, start_rad)[:-1]
    a, _, skipped = _turn_axes(lateral_m, start_rad)
    return sum(math.dist(p, q) for p, q in zip(pts, pts[1:])), a * math.cos(skipped)


def roadside_trigger_m(
    ego_speed_mps: float, lateral_m: float, cfg: dict, vehicle: tuple[float, float, float] = (0.0, 0.0, 0.0)
) -> float:
    """Free-space distance of the ego at which a road user beside the road ``lateral_m`` from the ego's
    lane centre sets off to turn into it: the ego reaches where it joins ``arrival_gap_s`` after it
    (its time to join by :func:`time_to_join_s`, ``vehicle`` its length, top speed and acceleration,
    less how far along it has gone by then). Why one helper: the writer's trigger and the sampler's
    spawn (far enough ahead for the ego to close in first) must agree."""
    turn_m, along_m = roadside_turn_m(lateral_m)
    t_actor = time_to_join_s(turn_m, cfg, *vehicle)
    return max(1.0, ego_speed_mps * (t_actor + value(cfg, PARAMETERS, "arrival_gap_s")) - along_m)


#: Below this speed (m/s) the ego stands: a turn in timed to meet it would wait for it for ever.
EGO_AT_REST_MPS = 0.5


def from_the_roadside(ctx: ActorContext, cfg: dict) -> list[Step]:
    """Turn out of a place beside the road along the writer's path (``ctx.crossing_path``, world
    points of :func:`roadside_path_st`) into the ego's lane, speeding up to ``speed_mps``; set off
    when the ego is :func:`roadside_trigger_m` away (in front of a standing ego: at once)."""
    v, a = ctx.reachable(value(cfg, PARAMETERS, "speed_mps"), value(cfg, PARAMETERS, "accel_mps2"))
    actions = turn_out_actions(ctx, v, a)
    if ctx.ego_speed_mps < EGO_AT_REST_MPS:
        return [Step(NAME, actions)]
    vehicle = (ctx.actor_length_m, ctx.actor_max_speed_mps, ctx.actor_max_accel_mps2)
    trigger = roadside_trigger_m(ctx.ego_speed_mps, ctx.crossing_distance_m or 0.0, cfg, vehicle)
    return [Step(NAME, actions, conditions=[Condition("ego_within", round(trigger, 2))])]


def turn_out_actions(ctx: ActorContext, speed_mps: float, accel_mps2: float) -> list:
    """The actions of a road user turning out of a place beside the road into the ego's lane: along
    the writer's path (``ctx.crossing_path``), speeding up to ``speed_mps`` at ``accel_mps2``, and on a
    map with a junction ahead its route straight over it in the ego's lane. Why one helper: whatever
    brings it out of there (a turn in, a pull out from the far kerb), the way into the lane is one."""
    traj = xosc.Trajectory(f"{ctx.actor}_turn_in", False)
    points = [xosc.WorldPosition(round(x, 3), round(y, 3), 0, round(h, 5)) for x, y, h in ctx.crossing_path or []]
    traj.add_shape(xosc.Polyline([], points))
    ctx.trajectories[traj.name] = traj
    actions = [xosc.FollowTrajectoryAction(traj, xosc.FollowingMode.position), speed_action(speed_mps, rate=accel_mps2)]
    if ctx.exits.get("straight"):  # (in the ego's lane it goes on straight over the junction ahead)
        in_lane = replace(ctx, actor_lane_id=ctx.ego_lane_id, actor_s_m=ctx.ego_s_m)
        actions.append(route_action(in_lane, "straight", exit_lane=abs(ctx.ego_lane_id)))
    return actions
