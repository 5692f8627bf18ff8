"""OpenSCENARIO positions → world poses, on the scenario's road network where they need one.

Supported: WorldPosition, RelativeWorldPosition, RelativeObjectPosition, LanePosition, RoadPosition,
RelativeLanePosition, RelativeRoadPosition, RoutePosition, TrajectoryPosition. A road-based position
also gives the :class:`LaneState` an entity keeps when it drives on by default (esmini's default
controller: keep the lane at the current speed). Orientation: absolute, or relative — to the lane's
driving direction for lane positions, to increasing s for road positions (as esmini), to the path
for trajectory positions.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from vei_scenario.models.angles import wrap_angle
from vei_scenario.safe_xml import first_element


@dataclass
class LaneState:
    """Where a lane-keeping entity is: road, lane, s along the road, offset from the lane centre."""

    road: str
    lane: int
    s: float
    offset: float = 0.0
    forward: bool = True  # moves towards increasing s (taken from its heading, as esmini does)
    #: Heading relative to the direction of travel along the road, kept while it drives on (esmini
    #: keeps a relative orientation: an entity placed at an angle moves along the lane at that angle).
    heading: float = 0.0


def _relative_heading(h: float, road_h: float) -> tuple[bool, float]:
    """(moves towards increasing s, heading relative to that direction of travel)."""
    forward = _heads_forward(h, road_h)
    return forward, wrap_angle(h - (road_h if forward else road_h + math.pi))


@dataclass
class Pose:
    x: float
    y: float
    h: float
    lane: LaneState | None = None


def lane_id(ctx, el, name: str = "laneId", default: int | None = None) -> int:
    """A lane id (OpenSCENARIO types it as text; a lane is a whole number, written ``-1`` or, from a
    double parameter, ``-1.0``); one line naming ``el``'s line for anything else."""
    text = el.get(name)
    if text is None and default is not None:
        return default
    try:
        value = float(text)
    except (TypeError, ValueError):
        value = math.nan
    if not value.is_integer() or abs(value) > 1e6:
        raise ctx.error(el, f"<{el.tag}> {name}={text!r} is not a lane id (a whole number)")
    return int(value)


def number(el, name: str, default: float = 0.0) -> float:
    v = el.get(name)
    return float(v) if v not in (None, "") else default


def _heads_forward(h: float, road_h: float) -> bool:
    """Whether heading ``h`` points along the road's increasing s (its reference heading ``road_h``)."""
    return math.cos(h - road_h) >= 0.0


def oriented(el, base_h: float) -> float:
    o = el.find("Orientation")
    if o is None:
        return base_h
    h = number(o, "h")
    return h if o.get("type", "relative") == "absolute" else base_h + h


def object_offset(ref, dx: float, dy: float, dz: float) -> tuple[float, float]:
    """The world x, y of an offset given in entity ``ref``'s coordinate system. The standard's entity
    frame turns with the entity's heading, pitch and roll (z-y'-x'' order, ISO 8855), so a ``dz`` of a
    rolled-over entity moves sideways (as esmini measures too)."""
    cr, sr = math.cos(ref.roll), math.sin(ref.roll)
    y1, z1 = dy * cr - dz * sr, dy * sr + dz * cr
    cp, sp = math.cos(ref.pitch), math.sin(ref.pitch)
    x2 = dx * cp + z1 * sp
    c, s = math.cos(ref.yaw), math.sin(ref.yaw)
    return c * x2 - s * y1, s * x2 + c * y1


def tilt(ctx, pos) -> tuple[float, float]:
    """(pitch, roll) a ``<Position>`` gives an entity: a WorldPosition's p and r; an Orientation's p and
    r, added to the reference entity's for a relative orientation of a position relative to an
    entity. (vei's roads are taken as flat for an entity's pitch and roll.)"""
    el = pos if pos.tag in POSITION_KINDS else first_element(pos)
    if el is not None and el.tag == "WorldPosition":
        return wrap_angle(number(el, "p")), wrap_angle(number(el, "r"))
    o = el.find("Orientation") if el is not None else None
    if o is None:
        return 0.0, 0.0
    p, r = number(o, "p"), number(o, "r")
    ref = ctx.entities.get(el.get("entityRef") or "") if el.tag in _ENTITY_RELATIVE else None
    if ref is not None and o.get("type", "relative") != "absolute":
        p, r = p + ref.pitch, r + ref.roll
    return wrap_angle(p), wrap_angle(r)


_ENTITY_RELATIVE = ("RelativeWorldPosition", "RelativeObjectPosition")


def _network(ctx, el):
    net = getattr(ctx, "roads", None)
    if net is None:
        raise ctx.error(el, f"<{el.tag}> needs a road network (RoadNetwork/LogicFile)")
    return net


def lane_pose(ctx, el, road_id: str, lane_id: int, s: float, offset: float, forward: bool | None = None) -> Pose:
    """Pose on a lane, heading its driving direction, or along increasing s when ``forward`` says so
    (a position relative to an entity takes that entity's direction, as esmini does)."""
    net = _network(ctx, el)
    try:
        road = net.road(road_id)
        if lane_id == 0:
            return _centre_lane_pose(el, road, s, offset, forward)
        t = road.lane_center_t(s, lane_id) + offset
    except KeyError as exc:
        why = exc.args[0] if exc.args else exc
        if isinstance(why, int):  # (the core names the lane it lacks by its id alone)
            why = f"road {road_id} has no lane {why} at s = {s:g}"
        raise ctx.error(el, f"<{el.tag}>: {why}") from None
    x, y, h = road.world(s, t)
    forward = road.drives_forward(lane_id) if forward is None else forward
    drive_h = wrap_angle(oriented(el, h if forward else h + math.pi))
    return Pose(x, y, drive_h, LaneState(road.id, lane_id, s, offset, *_relative_heading(drive_h, h)))


def _centre_lane_pose(el, road, s: float, offset: float, forward: bool | None) -> Pose:
    """A pose on OpenDRIVE's centre lane 0 (no width: the reference line, shifted by the road's
    laneOffset): ``offset`` from it, heading along increasing s unless ``forward`` is False, as esmini
    3.6 places it (measured); it then drives on in the lane it is in (none off the road)."""
    inner = [road.lane_borders(s, lane)[0] for lane in (-1, 1) if lane in road.section(s).lanes]
    if not inner:
        raise KeyError(f"road {road.id} has no lanes at s = {s:g}")
    return _road_pose(el, road, s, inner[0] + offset, reverse=forward is False)


def _road_pose(el, road, s: float, t: float, reverse: bool = False) -> Pose:
    x, y, h = road.world(s, t)
    lane = road.lane_at(s, t)
    # along increasing s, whatever lane the point is in: the standard's reference for a road
    # position's orientation, and esmini's heading for one without (measured on a left-hand lane);
    # ``reverse``: against it
    pose_h = wrap_angle(oriented(el, h + math.pi if reverse else h))
    if lane is None:
        return Pose(x, y, pose_h)
    state = LaneState(road.id, lane, s, t - road.lane_center_t(s, lane), *_relative_heading(pose_h, h))
    return Pose(x, y, pose_h, state)


def entity_lane(ctx, el, name: str) -> tuple[object, LaneState]:
    e = ctx.entities.get(name)
    if e is None:
        raise ctx.error(el, f"no entity named {name!r}")
    if e.lane is not None:
        return e, e.lane
    state = lane_state_at(_network(ctx, el), e)
    if state is None:
        raise ctx.error(el, f"<{el.tag}>: {name} is not on a lane")
    return e, state


def lane_state_at(net, e) -> LaneState | None:
    """Where entity ``e`` is on the road network as a lane state (None off the lanes)."""
    rp = net.project(e.x, e.y)
    if rp is None or rp.lane is None:
        return None
    h_ref = rp.road.ref_pose(rp.s)[2]
    offset = rp.t - rp.road.lane_center_t(rp.s, rp.lane)
    return LaneState(rp.road.id, rp.lane, rp.s, offset, *_relative_heading(e.yaw, h_ref))


def ensure_lane(ctx, e) -> None:
    """Give an entity placed by world coordinates (``find_lane``) the lane it is on, once it needs one."""
    if e.find_lane:
        e.find_lane = False
        e.lane = lane_state_at(ctx.roads, e)


def lane_shift(lane: int, n: int, forward: bool) -> int:
    """The lane ``n`` lanes to the left (negative: right) of ``lane`` as seen in its driving direction
    (``forward``: towards increasing s). Lane ids grow to the left of the reference line; 0 is none."""
    step = 1 if (n > 0) == forward else -1
    for _ in range(abs(n)):
        lane += step
        if lane == 0:
            lane += step
    return lane


#: The kinds of position OpenSCENARIO 1.3 defines (the child of a ``<Position>``).
POSITION_KINDS = frozenset(
    (
        "WorldPosition",
        "RelativeWorldPosition",
        "RelativeObjectPosition",
        "RoadPosition",
        "RelativeRoadPosition",
        "LanePosition",
        "RelativeLanePosition",
        "RoutePosition",
        "GeoPosition",
        "TrajectoryPosition",
    )
)


#: Position kinds resolved by the module that defines their shapes: a TrajectoryPosition lies on a
#: trajectory, whose vertices are positions in turn (``shapes`` registers it; kind -> resolver).
RESOLVED_ELSEWHERE: dict[str, Callable] = {}


def resolve(ctx, pos) -> Pose:
    """The pose of a ``<Position>`` element (its first child decides the kind), or of any element the
    standard types as a Position (``PositionStart``, ...), or of a position kind itself."""
    el = pos if pos.tag in POSITION_KINDS else first_element(pos)
    if el is None:
        raise ctx.error(pos, "empty Position")
    tag = el.tag
    if tag == "WorldPosition":
        return Pose(number(el, "x"), number(el, "y"), number(el, "h"))
    if tag in ("RelativeWorldPosition", "RelativeObjectPosition"):
        ref = ctx.entities.get(el.get("entityRef"))
        if ref is None:
            raise ctx.error(el, f"no entity named {el.get('entityRef')!r}")
        dx, dy = number(el, "dx"), number(el, "dy")
        if tag == "RelativeObjectPosition":  # (dx, dy, dz) in the object's frame, turned by h, p and r
            dx, dy = object_offset(ref, dx, dy, number(el, "dz"))
        return Pose(ref.x + dx, ref.y + dy, wrap_angle(oriented(el, ref.yaw)))
    if tag == "LanePosition":
        return lane_pose(ctx, el, el.get("roadId"), lane_id(ctx, el), number(el, "s"), number(el, "offset"))
    if tag == "RoadPosition":
        net = _network(ctx, el)
        try:
            road = net.road(el.get("roadId"))
        except KeyError as exc:
            raise ctx.error(el, str(exc.args[0])) from None
        s, t = number(el, "s"), number(el, "t")
        return _road_pose(el, road, s, t)
    if tag in ("RelativeLanePosition", "RelativeRoadPosition"):
        e, st = entity_lane(ctx, el, el.get("entityRef"))
        road = _network(ctx, el).road(st.road)
        # along the road's reference line and by lane ids, whichever way the reference entity heads:
        # esmini 3.6 reads it so for entities in either lane direction, facing either way
        # (tests/test_init_order.py); the position heads along the road unless it has an Orientation
        forward = True
        if tag == "RelativeRoadPosition":
            s = st.s + number(el, "ds")
            t = road.lane_center_t(st.s, st.lane) + st.offset + number(el, "dt")
            return _road_pose(el, road, s, t)
        lane = lane_shift(st.lane, int(number(el, "dLane")), forward)
        ds = number(el, "ds", number(el, "dsLane"))
        s = st.s + (ds if forward else -ds)
        return lane_pose(ctx, el, road.id, lane, s, number(el, "offset"), forward)
    if tag == "RoutePosition":
        route = route_from(ctx, el.find("RouteRef/Route"), el)
        coords = el.find("InRoutePosition/FromLaneCoordinates")
        if coords is not None:
            leg, s = route.at(number(coords, "pathS"))
            lane = lane_id(ctx, coords)
            # facing the lane's driving direction (esmini), not necessarily the route's
            return lane_pose(ctx, el, leg.road, lane, s, number(coords, "laneOffset"))
        coords = el.find("InRoutePosition/FromRoadCoordinates")
        if coords is not None:
            leg, s = route.at(number(coords, "pathS"))
            return _road_pose(el, _network(ctx, el).road(leg.road), s, number(coords, "t"))
        raise ctx.error(el, "RoutePosition: InRoutePosition/FromCurrentEntity is not supported by vei run")
    if tag in RESOLVED_ELSEWHERE:
        return RESOLVED_ELSEWHERE[tag](ctx, el)
    raise ctx.error(el, f"position <{tag}> is not supported by vei run")


def lane_of(ctx, x: float, y: float, h: float) -> LaneState | None:
    """The lane state at a world point, when the scenario has roads and the point is on a lane."""
    net = getattr(ctx, "roads", None)
    if net is None:
        return None
    rp = net.project(x, y)
    if rp is None or rp.lane is None:
        return None
    h_ref = rp.road.ref_pose(rp.s)[2]
    offset = rp.t - rp.road.lane_center_t(rp.s, rp.lane)
    return LaneState(rp.road.id, rp.lane, rp.s, offset, *_relative_heading(h, h_ref))


def route_from(ctx, route_el, at):
    """The planned :class:`~vei_scenario.interpreter.routes.Route` of a ``<Route>`` element."""
    from vei_scenario.interpreter.routes import plan_route

    if route_el is None:
        raise ctx.error(at, "a route must be given inline or from a catalog")
    net = _network(ctx, at)
    points = []
    for wp in route_el.iterfind("Waypoint"):
        if wp.find("Position") is None:
            raise ctx.error(wp, "a Waypoint needs a Position")
        pose = resolve(ctx, wp.find("Position"))
        if pose.lane is None:
            raise ctx.error(wp, "waypoint is not on a lane")
        road = net.road(pose.lane.road)
        points.append((road.id, pose.lane.s, road.drives_forward(pose.lane.lane)))
    if len(points) < 2:
        raise ctx.error(route_el, "a route needs at least two waypoints")
    route = plan_route(net, points)
    if route is None:
        raise ctx.error(route_el, "no chain of roads joins the route's waypoints")
    return route
