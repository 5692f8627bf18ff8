"""Generated road networks for language scenarios: the map kinds a description can ask for.

Every map is built with scenariogeneration's OpenDRIVE model and described by a :class:`MapInfo`
that says, in the terms placement needs, where the ego's road, its junction approach and the other
entrances are. Right-hand traffic: a road's forward direction is driven on its right lanes (negative
OpenDRIVE ids), lane -1 next to the centre line, lane -n at the kerb.

Kinds (``environment.map.kind``):

* ``straight``: one straight road, ``lanes_per_direction`` lanes each way.
* ``curve``: straight, a spiral-arc-spiral bend of ``curve_radius_m`` (to the left), straight.
* ``crossroad``: four roads into one junction (every turn connected), with a dynamic traffic light
  at each entrance (``signal_<road>``).
* ``roundabout``: a one-way ring of four arcs (anticlockwise) joined by four junctions, each with
  an approach road that enters and leaves the ring.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from scenariogeneration import xodr

LANE_WIDTH_M = 3.5
#: Length of the straight roads, and of a crossroad's four arms (m).
ROAD_LENGTH_M = 400.0
ARM_LENGTH_M = 300.0
#: Distance from the junction centre to where the arms start (m): room for the turning roads.
JUNCTION_RADIUS_M = 14.0
ROUNDABOUT_RADIUS_M = 30.0
#: Traffic light signal type (German catalogue 1000001: three-light signal) and its size.
SIGNAL_TYPE = "1000001"


@dataclass(frozen=True)
class MapInfo:
    """What placement needs to know of a generated map.

    ``ego_road`` is the road the ego drives on in its forward direction; ``approach_end_s`` where it
    reaches the junction (or the feature the ego is placed before); ``entrances`` maps a relation
    (``left``, ``right``, ``opposite``) to the road entering the junction from that side, seen by the
    ego; ``exits`` the road leaving the junction on that side; ``signals`` the traffic light of each
    entrance road."""

    kind: str
    lanes: int
    ego_road: str
    ego_road_length_m: float
    feature_s_m: float | None = None
    entrances: dict[str, str] = field(default_factory=dict)
    exits: dict[str, str] = field(default_factory=dict)
    signals: dict[str, str] = field(default_factory=dict)
    curve_start_s_m: float | None = None


def _road(geometry, road_id: int, lanes: int):
    return xodr.create_road(geometry, road_id, left_lanes=lanes, right_lanes=lanes, lane_width=LANE_WIDTH_M)


#: The curve: straight lead-in, spirals either side of an arc of this angle, straight run-out (m, rad).
CURVE_LEAD_M, CURVE_SPIRAL_M, CURVE_ANGLE_RAD, CURVE_OUT_M = 120.0, 30.0, math.pi / 3, 150.0


def _straight(lanes: int) -> tuple[xodr.OpenDrive, MapInfo]:
    odr = xodr.OpenDrive("straight")
    odr.add_road(_road(xodr.Line(ROAD_LENGTH_M), 1, lanes))
    odr.adjust_roads_and_lanes()
    return odr, _straight_info(lanes)


def _straight_info(lanes: int) -> MapInfo:
    return MapInfo("straight", lanes, "1", ROAD_LENGTH_M)


def _curve(lanes: int, radius: float) -> tuple[xodr.OpenDrive, MapInfo]:
    k = 1.0 / radius
    geometry = [
        xodr.Line(CURVE_LEAD_M),
        xodr.Spiral(0.0, k, CURVE_SPIRAL_M),
        xodr.Arc(k, angle=CURVE_ANGLE_RAD),
        xodr.Spiral(k, 0.0, CURVE_SPIRAL_M),
        xodr.Line(CURVE_OUT_M),
    ]
    odr = xodr.OpenDrive("curve")
    odr.add_road(_road(geometry, 1, lanes))
    odr.adjust_roads_and_lanes()
    return odr, _curve_info(lanes, radius)


def _curve_info(lanes: int, radius: float) -> MapInfo:
    length = CURVE_LEAD_M + 2 * CURVE_SPIRAL_M + radius * CURVE_ANGLE_RAD + CURVE_OUT_M
    return MapInfo("curve", lanes, "1", length, feature_s_m=CURVE_LEAD_M, curve_start_s_m=CURVE_LEAD_M)


def _signal(road_id: int, lanes: int) -> xodr.Signal:
    """A dynamic traffic light at the junction end of an arm, on the kerb side of its right lanes,
    facing the traffic that drives towards the junction."""
    return xodr.Signal(
        s=ARM_LENGTH_M - 2.0,
        t=-(lanes * LANE_WIDTH_M + 1.0),
        country="OpenDRIVE",  # (esmini finds dynamic signals by it, not by DEU)
        Type=SIGNAL_TYPE,
        subtype="-1",
        id=str(road_id),
        name=f"signal_{road_id}",
        dynamic=xodr.Dynamic.yes,
        zOffset=2.5,
        orientation=xodr.Orientation.positive,
        height=0.9,
        width=0.3,
    )


def _crossroad(lanes: int, signals: bool) -> tuple[xodr.OpenDrive, MapInfo]:
    """Four arms ending at the junction (their forward direction drives in). The ego's arm (1) comes
    from the east, heading west: arm 2 (north) is on its right, arm 4 (south) on its left, arm 3
    ahead."""
    # scenariogeneration remembers signal ids per process and renames repeats: every map starts afresh
    xodr.Signal._usedIDs.clear()
    xodr.Signal._IDCounter.clear()
    return _crossroad_roads(lanes, signals)


def _crossroad_roads(lanes: int, signals: bool) -> tuple[xodr.OpenDrive, MapInfo]:
    """Four arms ending at the junction (their forward direction drives in). The ego's arm (1) comes
    from the east, heading west: arm 2 (north) is on its right, arm 4 (south) on its left, arm 3
    ahead."""
    odr = xodr.OpenDrive("crossroad")
    junction = xodr.CommonJunctionCreator(100, "crossroad", startnum=100)
    for i in range(4):
        road = _road(xodr.Line(ARM_LENGTH_M), i + 1, lanes)
        if signals:
            road.add_signal(_signal(i + 1, lanes))
        odr.add_road(road)
        # arm i points at the centre from angle i·90° (arm 1 east, 2 north, 3 west, 4 south)
        junction.add_incoming_road_circular_geometry(road, JUNCTION_RADIUS_M, i * math.pi / 2, "successor")
    for i in range(4):
        for j in range(i + 1, 4):
            junction.add_connection(i + 1, j + 1)
    odr.add_junction_creator(junction)
    odr.adjust_roads_and_lanes()
    return odr, _four_arms("crossroad", lanes, {str(i + 1): str(i + 1) for i in range(4)} if signals else {})


def _four_arms(kind: str, lanes: int, signals: dict[str, str]) -> MapInfo:
    """The arm layout the crossroad and the roundabout share, seen by the ego on arm 1 (from the
    east): arm 2 on its right, 3 ahead, 4 on its left; each arm both enters and leaves."""
    return MapInfo(
        kind,
        lanes,
        "1",
        ARM_LENGTH_M,
        feature_s_m=ARM_LENGTH_M,
        entrances={"right": "2", "opposite": "3", "left": "4"},
        exits={"right": "2", "straight": "3", "left": "4"},
        signals=signals,
    )


def _roundabout(lanes: int) -> tuple[xodr.OpenDrive, MapInfo]:
    """A one-lane, one-way ring (anticlockwise, as right-hand traffic drives it) of four quarter
    arcs between four junctions; at each junction an approach arm (two-way, ``lanes`` lanes each
    way) enters and leaves the ring. The ego's approach (arm 1) comes from the east."""
    odr = xodr.OpenDrive("roundabout")
    ring_ids = [11, 12, 13, 14]
    arcs = []
    gap_angle = 0.35  # radians of ring taken by each junction
    for rid in ring_ids:
        arc = xodr.create_road(
            xodr.Arc(1.0 / ROUNDABOUT_RADIUS_M, angle=math.pi / 2 - gap_angle),
            rid,
            left_lanes=0,
            right_lanes=1,
            lane_width=LANE_WIDTH_M + 0.5,
        )
        arcs.append(arc)
        odr.add_road(arc)
    for k in range(4):
        junction = xodr.CommonJunctionCreator(100 + 10 * k, f"ring_{k}", startnum=100 + 10 * k)
        theta = k * math.pi / 2  # junction position on the ring (arm k+1 comes from there)
        arm = _road(xodr.Line(ARM_LENGTH_M), k + 1, lanes)
        odr.add_road(arm)
        d = ROUNDABOUT_RADIUS_M + 12.0
        junction.add_incoming_road_cartesian_geometry(
            arm, d * math.cos(theta), d * math.sin(theta), theta + math.pi, "successor"
        )
        # the arc before the junction ends here, the arc after it starts here (anticlockwise)
        before = arcs[(k - 1) % 4]
        after = arcs[k]
        half = gap_angle / 2
        x_in = ROUNDABOUT_RADIUS_M * math.cos(theta - half)
        y_in = ROUNDABOUT_RADIUS_M * math.sin(theta - half)
        x_out = ROUNDABOUT_RADIUS_M * math.cos(theta + half)
        y_out = ROUNDABOUT_RADIUS_M * math.sin(theta + half)
        junction.add_incoming_road_cartesian_geometry(before, x_in, y_in, theta - half + math.pi / 2, "successor")
        junction.add_incoming_road_cartesian_geometry(after, x_out, y_out, theta + half - math.pi / 2, "predecessor")
        junction.add_connection(k + 1, before.id)
        junction.add_connection(k + 1, after.id)
        junction.add_connection(before.id, after.id)
        _outer_arm_lanes_to_ring(junction, k + 1, before.id, after.id, lanes)
        odr.add_junction_creator(junction)
    odr.adjust_roads_and_lanes()
    return odr, _four_arms("roundabout", lanes, {})


def _outer_arm_lanes_to_ring(junction, arm: int, before: int, after: int, lanes: int) -> None:
    """Connect the arm's lanes beyond the one next to its centre line to the one-lane ring: each lane
    driving in merges onto the ring, and the ring feeds each lane driving out. Why: the ring has one
    lane and the arm ``lanes``, and of unequal lanes only the inner pair is joined by itself, so a
    road user in the kerb lane of a two-lane arm (the ego in lane 1, a road user waiting at an arm)
    would come to the ring and find no road on: it would stand at the arm's end for the whole run,
    and a route out to an outer lane would have no chain of roads."""
    for k in range(2, lanes + 1):
        junction.add_connection(arm, after, -k, -1)
        junction.add_connection(before, arm, -1, k)


def _read_spec(spec: dict) -> tuple[str, int, float, bool]:
    """``environment.map``'s kind, lanes per direction, curve radius (a curve's only) and traffic
    signals, with their defaults (one place for both :func:`layout` and :func:`build_map`)."""
    kind = spec["kind"]
    radius = float(spec.get("curve_radius_m", 150.0)) if kind == "curve" else 0.0
    return kind, int(spec.get("lanes_per_direction", 2)), radius, bool(spec.get("traffic_signals", True))


def layout(spec: dict) -> MapInfo:
    """The :class:`MapInfo` of ``environment.map`` without building its roads (what placement
    needs to know before anything is written)."""
    kind, lanes, radius, signals = _read_spec(spec)
    if kind == "straight":
        return _straight_info(lanes)
    if kind == "curve":
        return _curve_info(lanes, radius)
    if kind in ("crossroad", "roundabout"):
        heads = {str(i + 1): str(i + 1) for i in range(4)} if kind == "crossroad" and signals else {}
        return _four_arms(kind, lanes, heads)
    raise ValueError(f"map kind {kind!r} cannot be generated")


def build_map(spec: dict) -> tuple[xodr.OpenDrive, MapInfo]:
    """The OpenDRIVE model and its :class:`MapInfo` for ``environment.map`` of the layers."""
    kind, lanes, radius, signals = _read_spec(spec)
    if kind == "straight":
        return _straight(lanes)
    if kind == "curve":
        return _curve(lanes, radius)
    if kind == "crossroad":
        return _crossroad(lanes, signals)
    if kind == "roundabout":
        return _roundabout(lanes)
    raise ValueError(f"map kind {kind!r} cannot be generated")
