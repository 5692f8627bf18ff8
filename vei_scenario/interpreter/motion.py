"""How an entity moves when nothing else steers it: along its lane (esmini's default behaviour, on
across road ends and junctions) or along the path it follows. Used by the engine's default motion,
the controllers and the actions that move an entity themselves."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from vei_scenario.interpreter.entities import Entity


def advance_along(e: Entity, ds: float) -> bool:
    """Move an entity ``ds`` metres along its followed path, or straight ahead without one. True where
    the step reaches the end of its path (forwards): a road user with a model of its own (a
    vei-compiled ego) stands there, as the sweep kernel and the FMUs have it (:func:`stand`)."""
    f = e.follower
    if f is not None:  # (the core's path step, the one its quiet stretches take)
        at_end = not f.reverse and f.s + ds >= f.polyline.length
        e.x, e.y, e.yaw, f.s = f.polyline.core.advance(f.s, ds, f.reverse)
        return at_end
    e.x += ds * math.cos(e.yaw)
    e.y += ds * math.sin(e.yaw)
    return False


def lane_keep(e, ds: float, ctx) -> None:
    """Move ``e`` ``ds`` metres along its lane (esmini's default behaviour), on across road ends and
    junctions, with a running lane change shifting it sideways."""
    net = ctx.roads
    st = e.lane
    if ds == 0.0 and e.lateral is not None and e.lateral.projects_step:
        # a lane change pauses while the car stands: it cannot move sideways without moving on, and
        # keeps the heading it had (esmini 3.6: measured, a car braking to a stop mid-change)
        e.lateral.pause(ctx.dt)
        return
    road = net.road(st.road)
    forward = st.forward
    if e.lateral is None:  # most steps: on along the same road, in one call of the core
        step = road.core.lane_advance(st.s, st.lane, st.offset, ds, forward)
        if step is not None:
            st.s, st.lane, e.x, e.y, base = step
            e.yaw = _lane_yaw(base if forward else base + math.pi, st.heading)
            return
    # ds is travelled along the lane: scale to reference-line arc length where the lane is offset on a curve
    offset = st.offset
    turn = None  # (a lane change's heading in this step, from its lane's direction towards increasing t)
    if e.lateral is not None and e.lateral.projects_step:  # only the along-road part of the step moves s
        turn = e.lateral.step_heading(ds, ctx)
        ds *= math.cos(turn)
        # (the along-road part taken at the offset the step brings it to: esmini shifts it there first)
        offset = e.lateral.offset(e, ctx, road)
    stretch = road.lane_stretch(st.s, st.lane, offset)
    s = st.s + (ds if forward else -ds) / stretch
    hops = 0
    while s > road.length or s < 0.0:
        at_end = s > road.length
        over = s - road.length if at_end else -s
        nxt = net.next_road(road, st.lane, at_end, e.route.next_road(road.id) if e.route else None)
        hops += 1
        if hops > 2 * len(net.roads) + 2:  # round a loop of roads too short to take the step: a dead end
            nxt = None
        if nxt is None:  # the end of the road: it stops there, and stands once it cannot move (esmini)
            edge = road.length if at_end else 0.0
            if road.id == st.road and abs(st.s - edge) < 1e-9:
                e.speed = 0.0
            s = edge
            break
        road, st.lane, start = nxt
        s = over if start else road.length - over
        if start != forward:  # the new road runs the other way: an offset (along t) keeps its side
            st.offset = -st.offset
        forward = st.forward = start
    # the lane it is in now: on through the lane links of the sections passed on this road; where its
    # lane ends, the nearest on its side; where its lane narrows to nothing (a merge), over to the
    # nearest driving lane (esmini)
    st.lane = road.lane_on(st.s, s, st.lane, road.id == st.road)
    st.road, st.s = road.id, s
    if e.lateral is not None:
        st.offset = e.lateral.offset(e, ctx, road)
    # where it is, and the heading of its lane there (along a lane centre that runs sideways, where a
    # lane widens or narrows)
    x, y, base, _t = road.lane_pose(s, st.lane, st.offset)
    moved = math.hypot(x - e.x, y - e.y)
    e.x, e.y = x, y
    base = base if forward else base + math.pi
    e.yaw = _lane_yaw(base, st.heading)
    if e.lateral is not None and moved > 1e-9:
        if turn is None:  # (a lane offset heads where it moves)
            e.yaw = e.lateral.heading(e, base)
        elif e.lateral.fraction < 1.0:  # (along its lane again on the step that completes it)
            e.yaw = _lane_yaw(base, turn if forward else -turn)


def _lane_yaw(base: float, heading: float) -> float:
    """The yaw of a road user turned ``heading`` from its lane's direction ``base``, in (-π, π]."""
    return math.atan2(math.sin(base + heading), math.cos(base + heading))
