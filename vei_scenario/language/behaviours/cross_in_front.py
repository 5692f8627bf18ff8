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


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    if ctx.crossing_path is None:
        raise ValueError(f"{ctx.actor}: cross_in_front needs a roadside spawn (roadside_right or roadside_left)")
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
    if cfg.get("immediately"):  # (after giving way: it goes as soon as the ego has passed)
        return [Step("cross", actions, hold_s=in_lane_s)]
    trigger = Condition("ego_within", round(trigger_distance_m(ctx, cfg), 2))
    return [Step("cross", actions, conditions=[trigger], hold_s=in_lane_s)]
