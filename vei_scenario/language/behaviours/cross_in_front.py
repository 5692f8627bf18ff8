"""cross in front: a vulnerable road user crosses the ego's road from the roadside.

It waits at the kerb and sets off when the ego is close enough to meet it (with ``immediately``: as
soon as what came before it is over, e.g. after giving way): the ego reaches the
crossing point ``arrival_gap_s`` after the road user reaches the ego's lane (negative: before). It
follows a straight path across (FollowTrajectoryAction, which esmini plays); an e-scooter or bicycle
with ``agent`` = ``sfm`` rides it with the social force model instead, reacting to the ego.
"""

from __future__ import annotations

from scenariogeneration import xosc

from vei_scenario.language.behaviours.base import ActorContext, Condition, Parameter, Step, speed_action, value

NAME = "cross_in_front"
AGENT = "route follower (e-scooter social-force rider with agent=sfm)"
SUMMARY = "Cross the ego's road from the kerb, timed to meet the ego."
DEFAULT_SPAWN = {"relation": "roadside_right"}
PARAMETERS = {
    "crossing_speed_mps": Parameter(1.5, 0.5, 7.0, "speed across the road (m/s)"),
    "arrival_gap_s": Parameter(
        0.5, -3.0, 6.0, "the ego reaches the crossing this long after the road user reaches its lane (s)"
    ),
}
#: Time it is given to reach its crossing speed from standing (s).
START_RAMP_S = 0.5
PROFILES = {
    "dangerous": {"arrival_gap_s": (-0.2, 0.3)},
    "moderate": {"arrival_gap_s": (1.2, 1.8)},
    "safe": {"arrival_gap_s": (3.0, 4.0)},
}


def trigger_distance(ego_speed: float, crossing_m: float, speed: float, accel: float, arrival_gap_s: float) -> float:
    """Free-space distance of the ego at which a road user ``crossing_m`` from the ego's lane centre
    sets off to cross at ``speed``: it starts from standing, and reaching ``speed`` takes ``speed /
    accel`` (at least the start ramp), in which it covers half the distance it would at ``speed``."""
    ramp = max(START_RAMP_S, speed / accel if accel > 0 else 0.0)
    t_reach = crossing_m / speed + ramp / 2
    return max(1.0, ego_speed * (t_reach + arrival_gap_s))


def trigger_distance_m(ctx: ActorContext, cfg: dict) -> float:
    """Free-space distance of the ego at which the road user sets off."""
    v = value(cfg, PARAMETERS, "crossing_speed_mps")
    gap = value(cfg, PARAMETERS, "arrival_gap_s")
    return trigger_distance(ctx.ego_speed_mps, ctx.crossing_distance_m or 0.0, v, ctx.actor_max_accel_mps2, gap)


#: Below this speed (m/s) the ego stands: a crossing timed to meet it would wait for it for ever.
EGO_AT_REST_MPS = 0.5


def _ego_at_rest(ctx: ActorContext) -> bool:
    """Whether the ego stands still ("I was stopped at the lights when a rider crossed in front")."""
    return ctx.ego_speed_mps < EGO_AT_REST_MPS


#: Lane width the writer's maps use (m): a crossing from a lane measures its way across in lanes.
LANE_WIDTH_M = 3.5


def across_from_lane(ctx: ActorContext, cfg: dict) -> list[Step]:
    """A crossing by a road user that starts in a lane, not at the kerb (it came out of a driveway
    and along the road first, or the text puts it on the road): it has no kerb to set off from, so it
    moves over the ego's lane to the other side of it, at its crossing pace, ahead of the ego. From
    the ego's right it goes to the lane left of the ego (the oncoming one from the lane next to the
    centre); from the ego's left or its own lane to the ego's right, past the kerb lane's edge when
    there is no lane there."""
    right_of_ego = ctx.actor_lane_id < 0 and ctx.actor_lane_id < ctx.ego_lane_id
    offset = 0.0
    if right_of_ego:
        target = ctx.ego_lane_id + 1 if ctx.ego_lane_id != -1 else 1
    elif abs(ctx.ego_lane_id) < ctx.lanes:
        target = ctx.ego_lane_id - 1
    else:  # (the ego drives in the kerb lane: across it to its kerb edge)
        target, offset = ctx.ego_lane_id, -(LANE_WIDTH_M / 2 + 0.5)
    lanes_over = abs(target - ctx.actor_lane_id) - (1 if (target > 0) != (ctx.actor_lane_id > 0) else 0)
    across_m = max(lanes_over, 0) * LANE_WIDTH_M + abs(offset)
    v = value(cfg, PARAMETERS, "crossing_speed_mps")
    duration = min(max(across_m / v, 1.0), 6.0)
    dyn = xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, round(duration, 3))
    change = xosc.AbsoluteLaneChangeAction(target, dyn, round(offset, 3) if offset else None)
    # it sets off when the ego is as far away as it takes to get halfway over, plus the arrival gap
    gap = value(cfg, PARAMETERS, "arrival_gap_s")
    trigger = Condition("ego_within", round(max(1.0, ctx.ego_speed_mps * (duration / 2 + max(gap, 0.0))), 2))
    actions = [change] + ([speed_action(v, rate=v / START_RAMP_S)] if ctx.actor_speed_mps < 0.5 else [])
    if _ego_at_rest(ctx):  # (nothing to time against: it crosses in front of the standing ego at once)
        return [Step("cross", actions, fallback_s=2.0)]
    return [Step("cross", actions, conditions=[trigger], fallback_s=2.0)]


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    if ctx.crossing_path is None:
        return across_from_lane(ctx, cfg)
    traj = xosc.Trajectory(f"{ctx.actor}_crossing", False)
    traj.add_shape(
        xosc.Polyline(
            [], [xosc.WorldPosition(round(x, 3), round(y, 3), 0, round(h, 5)) for x, y, h in ctx.crossing_path]
        )
    )
    ctx.trajectories[traj.name] = traj
    follow = xosc.FollowTrajectoryAction(traj, xosc.FollowingMode.position)
    v = value(cfg, PARAMETERS, "crossing_speed_mps")
    # a linear ramp at its acceleration (the trigger's timing assumes just that)
    ramp = max(START_RAMP_S, v / ctx.actor_max_accel_mps2 if ctx.actor_max_accel_mps2 > 0 else 0.0)
    actions = [follow, speed_action(v, rate=v / ramp)]
    if cfg.get("agent") == "sfm" and ctx.actor_type in ("e-scooter", "bicycle"):
        actions.append(xosc.ActivateControllerAction(lateral=True, longitudinal=True))
    # what follows a crossing ("... and stops in the middle of the lane") starts in the ego's lane
    in_lane_s = round((ctx.crossing_distance_m or 0.0) / v + ramp / 2, 3)
    if cfg.get("immediately") or _ego_at_rest(ctx):
        # (after giving way it goes as soon as the ego has passed; in front of an ego that stands
        # there is nothing to time against, and an ego that never comes closer would never set it off)
        return [Step("cross", actions, hold_s=in_lane_s)]
    trigger_m = trigger_distance_m(ctx, cfg)
    trigger = Condition("ego_within", round(trigger_m, 2))
    return [Step("cross", actions, conditions=[trigger], hold_s=in_lane_s, fallback_s=late_s(ctx, trigger_m))]


#: How long after the ego should have come within its trigger distance a kerb-side crosser goes anyway (s).
LATE_S = 2.0


def late_s(ctx: ActorContext, trigger_m: float) -> float | None:
    """When a kerb-side crosser on the ego's road sets off if the ego never comes within its trigger
    distance (s): :data:`LATE_S` after the ego, at its speed, would have. Why: an ego that stops short
    for someone else (a rider ahead braking, a car pulling out) never comes closer, and a crossing
    timed only by its distance would then never be made, though the text says it was."""
    if ctx.on_another_arm() or ctx.ego_speed_mps < EGO_AT_REST_MPS:
        return None
    ahead_m = abs(ctx.actor_s_m - ctx.ego_s_m)
    return round(max(0.0, ahead_m - trigger_m) / ctx.ego_speed_mps + LATE_S, 3)
