"""overtake: pull out to the left, pass the ego, and return into its lane ``gap_m`` ahead of it."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import (
    ActorContext,
    Condition,
    Parameter,
    Step,
    lane_change_to,
    lane_change_to_ego,
    speed_action,
    value,
)

NAME = "overtake"
AGENT = "route follower"
SUMMARY = "Pull out to the left, pass the ego and cut back in gap_m ahead of it."
DEFAULT_SPAWN = {"relation": "behind"}
PARAMETERS = {
    "speed_gain_mps": Parameter(5.0, 1.0, 20.0, "how much faster than the ego it passes (m/s)"),
    "gap_m": Parameter(12.0, 1.0, 60.0, "free-space gap ahead of the ego when it returns (m)"),
    "lane_change_s": Parameter(2.5, 0.8, 6.0, "duration of each lane change (s)"),
    "delay_s": Parameter(0.5, 0.0, 30.0, "wait before pulling out (s)"),
}
PROFILES = {
    "dangerous": {"gap_m": (1.0, 4.0), "lane_change_s": (1.0, 1.6)},
    "moderate": {"gap_m": (8.0, 14.0), "lane_change_s": (2.0, 3.0)},
    "safe": {"gap_m": (25.0, 35.0), "lane_change_s": (3.0, 4.0)},
}


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    dur = value(cfg, PARAMETERS, "lane_change_s")
    if oncoming(ctx):
        return _oncoming_steps(ctx, cfg, dur)
    # it passes in the lane left of the ego (right-hand traffic: left of -k is -k+1, of -1 the
    # oncoming +1); one already there only speeds up
    left = ctx.ego_lane_id + 1 if ctx.ego_lane_id != -1 else 1
    fast = ctx.ego_speed_mps + value(cfg, PARAMETERS, "speed_gain_mps")
    pull_out = [speed_action(fast, rate=2.5)]
    if ctx.actor_lane_id != left:
        pull_out.insert(0, lane_change_to(left, dur))
    return [
        # (held 0 s: the watch for alongside starts with the pull-out, which a faster one may pass
        # the ego during; waiting for its end it would never see the gap at zero and never cut back)
        Step("pull_out", pull_out, delay_s=value(cfg, PARAMETERS, "delay_s"), hold_s=0.0),
        # alongside first (free space gap zero), then far enough ahead: the distance condition has no sign
        Step("alongside", [speed_action(fast, rate=2.5)], conditions=[Condition("ego_within", 0.01)]),
        Step(
            "cut_back",
            [lane_change_to_ego(ctx.ego, dur)],
            conditions=[Condition("ego_beyond", value(cfg, PARAMETERS, "gap_m"))],
        ),
    ]


#: How far behind the ego (m) an overtaker at the ego's speed starts, beyond half their lengths.
BEHIND_M = 15.0
#: The ego's speed (m/s) at or below which it stands, so that a road user filters past it from far back.
STANDING_MPS = 0.5
#: How much nearer than level with the ego (m) an overtaker coming up faster is out in the next lane.
OUT_BEFORE_LEVEL_M = 5.0


def place(ego_speed: float, lengths_m: float, cfg: dict, speed: float | None = None) -> tuple[float, float]:
    """(spawn longitudinal_m, speed_mps): behind the ego, at its speed until it pulls out.

    One that comes up past an ego that stands (``speed``: a rider filtering past a queue at the
    lights) starts as far back as it closes in while it waits and pulls out, and a little more: the
    pass is timed from level with the ego (its free-space gap zero) once the pull-out is over, and one
    that drew level during it would run into the ego's tail, or be past before the pass began, and
    never cut back in nor do what follows. Past a moving ego the pass is timed from behind it and
    needs no more room; starting a fast overtaker further back there leaves it short of the ego when
    the scenario ends."""
    if ego_speed > STANDING_MPS:
        return -(lengths_m / 2 + BEHIND_M), ego_speed
    closing = max((speed if speed is not None else ego_speed) - ego_speed, 0.0)
    out_s = value(cfg, PARAMETERS, "delay_s") + value(cfg, PARAMETERS, "lane_change_s")
    return -(lengths_m / 2 + max(BEHIND_M, closing * out_s + OUT_BEFORE_LEVEL_M)), ego_speed


def start_speed(ego_speed: float, speed: float, relation: str) -> float:
    """The speed (m/s) an overtaker starts at: its own, except that one behind a moving ego in its
    lane (``relation`` behind) and faster than it starts at the ego's and speeds up as it pulls out.
    Why: closing in on the ego's tail in its lane it is, to the ego's planner, a road user about to
    run into it, and the ego brakes hard for it (and is run into, or passed before the pull-out is
    over); pulling out first, as one who overtakes does, it comes past in the next lane."""
    if relation == "behind" and ego_speed > STANDING_MPS and speed > ego_speed:
        return ego_speed
    return speed


def stated_gain(cfg: dict, ego_speed: float, speed: float, relation: str) -> dict:
    """``cfg`` (an overtake's config) with ``speed_gain_mps`` the overtaker's stated ``speed`` less the
    ego's, within the parameter's bounds, where it starts at the ego's speed (:func:`start_speed`) and
    no gain is set. Why: starting at the ego's, it reaches only the ego's speed and the gain; without
    this the speed the text gives it ("a motorbike at 120 km/h overtakes", ego 50) is never played."""
    if start_speed(ego_speed, speed, relation) == speed or "speed_gain_mps" in cfg:
        return cfg
    p = PARAMETERS["speed_gain_mps"]
    return {**cfg, "speed_gain_mps": round(min(max(speed - ego_speed, p.low), p.high), 3)}


def oncoming(ctx: ActorContext) -> bool:
    """Whether the road user drives the other way on the ego's road: in a lane across the centre line,
    facing that lane's way (road users on other roads start in lanes of the ego's sign)."""
    return ctx.facing == "with" and (ctx.actor_lane_id > 0) != (ctx.ego_lane_id > 0)


def _oncoming_steps(ctx: ActorContext, cfg: dict, dur: float) -> list[Step]:
    """An oncoming road user overtaking what is ahead of it pulls out to its left, which is the ego's
    side of the road (the lane next to the centre line), passes at ``speed_gain_mps`` more, and
    pulls back into its own lane when the free-space gap to the ego is what a lane change at their
    closing speed leaves ``gap_m`` of. Why: to the ego that is the overtake it sees, a vehicle on its
    side coming at it that gets back in ``gap_m`` before they meet."""
    into = -1 if ctx.actor_lane_id > 0 else 1
    fast = ctx.actor_speed_mps + value(cfg, PARAMETERS, "speed_gain_mps")
    closing = ctx.ego_speed_mps + fast
    back_at = value(cfg, PARAMETERS, "gap_m") + closing * dur
    return [
        Step(
            "pull_out",
            [lane_change_to(into, dur), speed_action(fast, rate=2.5)],
            delay_s=value(cfg, PARAMETERS, "delay_s"),
        ),
        Step(
            "cut_back",
            [lane_change_to(ctx.actor_lane_id, dur), speed_action(ctx.actor_speed_mps, rate=2.5)],
            conditions=[Condition("ego_within", round(back_at, 2))],
        ),
    ]


def place_oncoming(ego_speed: float, speed: float, lengths_m: float, cfg: dict) -> float:
    """Spawn distance ahead of the ego of an oncoming overtaker: room to pull out, pass for a few
    seconds, and get back in before the gap it leaves (m)."""
    dur = value(cfg, PARAMETERS, "lane_change_s")
    closing = ego_speed + speed + value(cfg, PARAMETERS, "speed_gain_mps")
    return (
        lengths_m / 2 + value(cfg, PARAMETERS, "gap_m") + closing * (value(cfg, PARAMETERS, "delay_s") + 2 * dur + 3.0)
    )
