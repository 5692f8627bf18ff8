"""cut in: from the neighbouring lane into the ego's lane, just in front of it.

The actor drives in the lane beside the ego, ahead of it and slower (the ego closes in); when the
free-space gap between them falls to ``gap_m`` it changes into the ego's lane over
``lane_change_s`` (sinusoidal) and at the same time slows by ``brake_delta_mps`` at
``brake_rate_mps2``. Gap, lane-change time and braking are what the criticality words set.

One that starts behind the ego in its own lane (a car "behind us" that pulls out and cuts in) has no
lane to change from: it pulls out into the lane beside the ego's, comes past faster than the ego, and
changes back into the ego's lane once it is ``gap_m`` ahead, as an overtaker does; a cut-in is an
entry in front of the ego, which one that stays behind it never makes.

One parked beyond the far kerb (``roadside_left``: across the oncoming lanes of this right-hand-traffic
road) has no lane change into the ego's lane: it pulls out nosed out as a parked car is, across the
oncoming lanes along the turn of :func:`~vei_scenario.language.behaviours.turn_into.roadside_path_st`,
and is in the ego's lane ``gap_m`` ahead of the ego when it has turned into it.
"""

from __future__ import annotations

import math

from vei_scenario.language.behaviours import turn_into
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

NAME = "cut_in"
AGENT = "route follower"
SUMMARY = "Change into the ego's lane just in front of it once the gap has closed to gap_m."
DEFAULT_SPAWN = {"relation": "left"}
PARAMETERS = {
    "gap_m": Parameter(10.0, 0.5, 80.0, "free-space gap to the ego when the lane change starts (m)"),
    "lane_change_s": Parameter(2.5, 0.6, 6.0, "duration of the lane change (s)"),
    "closing_mps": Parameter(2.0, 0.3, 10.0, "how much slower than the ego it drives before the cut-in (m/s)"),
    "brake_delta_mps": Parameter(0.0, 0.0, 15.0, "further slow-down during the cut-in (m/s)"),
    "brake_rate_mps2": Parameter(2.0, 0.3, 9.0, "rate of that slow-down (m/s²)"),
    "lead_s": Parameter(2.5, 0.5, 8.0, "seconds of closing in before the gap is down to gap_m (sets the spawn)"),
}
PROFILES = {
    "dangerous": {
        "gap_m": (1.0, 6.0),
        "lane_change_s": (1.0, 1.8),
        "closing_mps": (2.0, 4.0),
        "brake_delta_mps": (1.5, 4.5),
        "brake_rate_mps2": (4.0, 7.0),
    },
    "moderate": {
        "gap_m": (9.0, 14.0),
        "lane_change_s": (2.0, 3.0),
        "closing_mps": (1.5, 2.5),
        "brake_delta_mps": (0.5, 1.5),
        "brake_rate_mps2": (1.0, 2.0),
    },
    "safe": {
        "gap_m": (28.0, 40.0),
        "lane_change_s": (3.0, 4.5),
        "closing_mps": (0.5, 1.0),
        "brake_delta_mps": (0.0, 0.0),
        "brake_rate_mps2": (0.5, 1.0),
    },
}


def initial_speed(ego_speed: float, cfg: dict) -> float:
    """The actor's speed before the cut-in: slower than the ego by ``closing_mps``."""
    return max(1.0, ego_speed - value(cfg, PARAMETERS, "closing_mps"))


#: An actor this much faster than the ego (m/s) passes it first and cuts in once gap_m ahead.
FASTER_MPS = 0.5
#: Below this speed (m/s) the actor stands (a parked car): it pulls out, speeding up as it changes lane.
STANDING_MPS = 0.5


#: A cut-in's brake leaves it at least this fast (m/s), or as fast as it was when slower.
MOVING_MPS = 1.0
#: How long after its planned closing time a cut-in goes ahead without its gap (s).
LATE_S = 2.0
#: How hard a standing road user speeds up as it pulls out (m/s²) where its performance says nothing.
PULL_OUT_ACCEL_MPS2 = 3.0


def compile(ctx: ActorContext, cfg: dict) -> list[Step]:
    if ctx.pulls_out_across:
        return across_from_the_far_kerb(ctx, cfg)
    gap = value(cfg, PARAMETERS, "gap_m")
    duration = value(cfg, PARAMETERS, "lane_change_s")
    if ctx.actor_speed_mps < STANDING_MPS:  # pulling out: off when the ego is a lane change away from the gap
        merge = initial_speed(ctx.ego_speed_mps, cfg)
        accel = ctx.actor_max_accel_mps2 or PULL_OUT_ACCEL_MPS2
        actions = [lane_change_to_ego(ctx.ego, duration), speed_action(merge, rate=accel)]
        return [
            Step("cut_in", actions, conditions=[Condition("ego_within", pull_out_distance_m(ctx.ego_speed_mps, cfg))])
        ]
    # it brakes as it comes over, but not to a stand: standing still it would move sideways no further
    after = max(
        0.0, ctx.actor_speed_mps - value(cfg, PARAMETERS, "brake_delta_mps"), min(ctx.actor_speed_mps, MOVING_MPS)
    )
    rate = ctx.max_decel(value(cfg, PARAMETERS, "brake_rate_mps2"))
    actions = [lane_change_to_ego(ctx.ego, duration), speed_action(after, rate=rate)]
    if comes_past_first(ctx):
        return from_behind(ctx, cfg, actions)
    # if the gap never comes (the ego slows for something else), it cuts in when it planned to anyway
    late = float(cfg.get("lead_s", 2.5)) + LATE_S
    if ctx.actor_speed_mps > ctx.ego_speed_mps + FASTER_MPS:  # faster than the ego: in once it is gap_m ahead
        return [Step("cut_in", actions, conditions=[Condition("ego_beyond", gap)], fallback_s=late)]
    return [Step("cut_in", actions, conditions=[Condition("ego_within", gap)], fallback_s=late)]


#: How much faster than the ego (m/s) one that cuts in from behind it comes past, at the least.
PASS_GAIN_MPS = 5.0
#: About how long (s) one that cuts in from behind takes from its start to the gap ahead of the ego.
PASS_S = 8.0
#: How hard (m/s²) it speeds up as it pulls out to pass, within what its vehicle can do.
PASS_ACCEL_MPS2 = 2.5


def behind_in_ego_lane(ctx: ActorContext) -> bool:
    """Whether the actor starts behind the ego in the ego's own lane on the ego's road (its spawn
    relation ``behind``): from there a change "into the ego's lane" goes nowhere, and slower than the
    ego it would never be in front of it."""
    if ctx.on_another_arm() or ctx.actor_lane_id != ctx.ego_lane_id:
        return False
    forward = 1.0 if ctx.ego_lane_id < 0 else -1.0  # (right-hand traffic: lanes of -s run along s)
    return (ctx.ego_s_m - ctx.actor_s_m) * forward > 0.0


def comes_past_first(ctx: ActorContext) -> bool:
    """Whether the actor's cut-in comes past the ego first (:func:`from_behind`): it moves, behind the
    ego in the ego's own lane (:func:`behind_in_ego_lane`), and does not pull out across the oncoming
    lanes. Why one predicate: the writer raises the vehicle's top speed to :func:`pass_speed_of` where
    this holds and nowhere else, so the pass compiled is the one its vehicle can drive. Only as the
    actor's first act: after an overtake it is already past the ego, and cuts in from beside it."""
    return (
        not ctx.acted and not ctx.pulls_out_across and ctx.actor_speed_mps >= STANDING_MPS and behind_in_ego_lane(ctx)
    )


def passing_lane(ctx: ActorContext) -> int:
    """The lane beside the ego's that one coming past it uses: the next one of the ego's direction to
    its left, else (the ego in the lane by the centre line) the one to its right, else (one lane each
    way) the oncoming lane over the centre line."""
    if ctx.ego_lane_id < -1:
        return ctx.ego_lane_id + 1
    if ctx.lanes > 1:
        return ctx.ego_lane_id - 1
    return 1


def pass_speed(ego_speed: float, speed: float, behind_m: float, cfg: dict) -> float:
    """The speed (m/s) one starting ``behind_m`` behind the ego at ``speed`` comes past it at, to cut
    in from behind: at least :data:`PASS_GAIN_MPS` more than the faster of the two, and enough to be
    ``gap_m`` ahead about :data:`PASS_S` after the start. Why one helper: the writer gives the
    vehicle this top speed (a rider at its kind's usual top never gets past a faster ego)."""
    gap = value(cfg, PARAMETERS, "gap_m")
    return max(max(ego_speed, speed) + PASS_GAIN_MPS, ego_speed + (behind_m + gap) / PASS_S)


def pass_speed_of(ctx: ActorContext, cfg: dict) -> float:
    """The speed (m/s) the actor of ``ctx`` comes past the ego at (:func:`pass_speed`), from where it
    starts behind the ego."""
    return pass_speed(ctx.ego_speed_mps, ctx.actor_speed_mps, abs(ctx.ego_s_m - ctx.actor_s_m), cfg)


def from_behind(ctx: ActorContext, cfg: dict, cut: list) -> list[Step]:
    """Out into :func:`passing_lane`, past the ego faster than it (by enough to be ``gap_m`` ahead
    about :data:`PASS_S` after the start, and at least :data:`PASS_GAIN_MPS`), and in with ``cut``
    (the cut-in's lane change and brake) once the free-space gap ahead is ``gap_m``. Why level first:
    the distance condition has no sign, and ``gap_m`` behind would trigger it before the pass."""
    duration = value(cfg, PARAMETERS, "lane_change_s")
    gap = value(cfg, PARAMETERS, "gap_m")
    fast, accel = ctx.reachable(pass_speed_of(ctx, cfg), PASS_ACCEL_MPS2)
    out = [lane_change_to(passing_lane(ctx), duration), speed_action(fast, rate=accel)]
    return [
        Step("pull_out", out, hold_s=0.0),
        Step("alongside", [speed_action(fast, rate=accel)], conditions=[Condition("ego_within", 0.01)]),
        Step("cut_in", cut, conditions=[Condition("ego_beyond", gap)]),
    ]


def pull_out_distance_m(ego_speed: float, cfg: dict) -> float:
    """Free-space distance of the ego at which a standing actor pulls out: the gap it leaves plus
    what the ego covers during the lane change."""
    return value(cfg, PARAMETERS, "gap_m") + ego_speed * value(cfg, PARAMETERS, "lane_change_s")


def place(ego_speed: float, lengths_m: float, cfg: dict) -> tuple[float, float]:
    """(spawn longitudinal_m, speed_mps): beside and ahead of the ego, ``lead_s`` seconds of closing
    before the gap is down to ``gap_m``."""
    closing = value(cfg, PARAMETERS, "closing_mps")
    lead = float(cfg.get("lead_s", 2.5))
    return lengths_m / 2 + value(cfg, PARAMETERS, "gap_m") + closing * lead, initial_speed(ego_speed, cfg)


#: How far off the road's direction a car parked at the far kerb is turned when it moves off (rad):
#: nosed out of its space towards the road, as one pulling out is, not square to the kerb.
NOSED_OUT_RAD = math.pi / 4


def pulls_out_across(kind: str, relation: str, speed_mps: float) -> bool:
    """Whether a cut-in by a road user of ``kind`` from spawn ``relation`` at ``speed_mps`` pulls out
    from beyond the far kerb: a vehicle or rider standing at the roadside across the oncoming lanes
    (``roadside_left`` on this right-hand-traffic road; a walker there steps out, a crossing). Why
    apart: from there the ego's lane is no lane change away; it comes across the oncoming lanes first,
    turning into the ego's way as one out of a place beside the road does."""
    return kind != "pedestrian" and relation == "roadside_left" and speed_mps < STANDING_MPS


def across_turn_cfg(ego_speed: float, cfg: dict, accel_mps2: float) -> dict:
    """The turn-in configuration (:mod:`~vei_scenario.language.behaviours.turn_into`) of a pull-out
    from the far kerb: it speeds up at ``accel_mps2`` to its cut-in speed (:func:`initial_speed`)."""
    return {"speed_mps": initial_speed(ego_speed, cfg), "accel_mps2": accel_mps2}


def across_distance_m(ego_speed: float, lateral_m: float, cfg: dict, vehicle: tuple[float, float, float]) -> float:
    """Free-space distance of the ego at which one parked ``lateral_m`` from the centre of the ego's lane
    beyond the far kerb pulls out (``vehicle``: its length, top speed and acceleration): when it has
    turned into the ego's lane the ego is ``gap_m`` behind it (its time to get there by
    :func:`~vei_scenario.language.behaviours.turn_into.time_to_join_s`, less how far along the road it
    has gone meanwhile). Why one helper: the writer's trigger and the sampler's spawn must agree."""
    turn_m, along_m = turn_into.roadside_turn_m(lateral_m, NOSED_OUT_RAD)
    t_actor = turn_into.time_to_join_s(
        turn_m, across_turn_cfg(ego_speed, cfg, vehicle[2] or PULL_OUT_ACCEL_MPS2), *vehicle
    )
    return max(1.0, value(cfg, PARAMETERS, "gap_m") + ego_speed * t_actor - along_m)


def across_from_the_far_kerb(ctx: ActorContext, cfg: dict) -> list[Step]:
    """Pull out from the far kerb along the writer's turn-in path (``ctx.crossing_path``) at no more
    than :data:`~vei_scenario.language.behaviours.turn_into.JOIN_SPEED_CAP_MPS` until it is in the
    ego's lane, then speed up to its cut-in speed; set off when the ego is :func:`across_distance_m`
    away (in front of a standing ego: at once)."""
    turn = turn_into.JOIN_SPEED_CAP_MPS
    v, a = ctx.reachable(initial_speed(ctx.ego_speed_mps, cfg), ctx.actor_max_accel_mps2 or PULL_OUT_ACCEL_MPS2)
    steps = [Step(NAME, turn_into.turn_out_actions(ctx, min(v, turn), a))]
    if ctx.ego_speed_mps >= turn_into.EGO_AT_REST_MPS:
        vehicle = (ctx.actor_length_m, ctx.actor_max_speed_mps, a)
        trigger = across_distance_m(ctx.ego_speed_mps, ctx.crossing_distance_m or 0.0, cfg, vehicle)
        steps[0].conditions.append(Condition("ego_within", round(trigger, 2)))
    if v > turn:  # (in the lane it speeds up to its cut-in speed)
        steps.append(Step(NAME, [speed_action(v, rate=a)]))
    return steps
