"""Where the layers put the ego and the others, in OpenDRIVE lane terms.

Lanes of the layers count from the kerb: lane 1 is the rightmost driving lane of the ego's
direction (OpenDRIVE id ``-n`` on an ``n``-lane side), lane ``n`` the one next to the centre line
(id ``-1``). A spawn relation is resolved against the ego's lane; one that names a lane the map
does not have (``left`` of the leftmost lane) is refused with the reason, never moved silently.
"""

from __future__ import annotations

from dataclasses import dataclass

from vei_scenario.language.maps import JUNCTION_RADIUS_M, LANE_WIDTH_M, MapInfo

#: Default distance of the ego before the junction, curve or roundabout (m).
DEFAULT_FEATURE_DISTANCE_M = 70.0
#: Where the ego starts on a straight road (m from its start): room for traffic behind.
STRAIGHT_START_S_M = 120.0
#: Distance of the kerb-side start of a crossing road user beyond the outermost lane edge (m).
KERB_OFFSET_M = 1.0
DEFAULT_LONGITUDINAL_M = {"ahead": 30.0, "behind": -20.0, "left": 0.0, "right": 0.0, "oncoming": 90.0}


class PlacementError(ValueError):
    """A spawn the map cannot hold."""


@dataclass(frozen=True)
class Pose:
    road: str
    lane_id: int
    s: float
    #: Lateral offset from the lane centre along the road's t axis (m); roadside spawns stand beyond the kerb.
    offset: float = 0.0
    #: ``with`` the lane's driving direction, or ``against`` it (a wrong-way driver).
    facing: str = "with"

    @property
    def wrong_way(self) -> bool:
        """Facing against its lane's driving direction. (A lane position's heading is its lane's
        driving direction, so a left lane's road user faces against the road's reference line with
        no orientation given: that is how esmini places it, and vei run with it.)"""
        return self.facing == "against"


def lane_id(lanes: int, lane: int) -> int:
    """OpenDRIVE id of layers lane ``lane`` (1 = kerb) on the right side of an ``lanes``-lane road."""
    if not 1 <= lane <= lanes:
        raise PlacementError(f"lane {lane} does not exist: the road has {lanes} lane(s) per direction")
    return -(lanes - lane + 1)


def ego_pose(info: MapInfo, ego: dict) -> Pose:
    lid = lane_id(info.lanes, int(ego["lane"]))
    dist = float(ego.get("distance_m", DEFAULT_FEATURE_DISTANCE_M))
    placement = ego["placement"]
    if placement == "straight" or info.feature_s_m is None:
        if placement not in ("straight",):
            raise PlacementError(f"ego placement {placement!r} needs a map with one; this map is {info.kind!r}")
        return Pose(info.ego_road, lid, min(STRAIGHT_START_S_M, info.ego_road_length_m / 3))
    wanted = {"before_junction": ("crossroad",), "before_roundabout": ("roundabout",), "on_curve": ("curve",)}
    if info.kind not in wanted.get(placement, ()):
        raise PlacementError(f"ego placement {placement!r} does not fit a {info.kind!r} map")
    if dist > info.feature_s_m - 5.0:
        raise PlacementError(f"ego distance_m {dist} m is longer than the {info.feature_s_m:.0f} m road before it")
    return Pose(info.ego_road, lid, info.feature_s_m - dist)


def junction_conflict_m(info: MapInfo, ego_lane_id: int, relation: str, actor_lane_id: int) -> tuple[float, float]:
    """(ego's distance from its junction entry to where the paths cross, actor's from its entry),
    both going straight on a crossroad whose arms meet at right angles: the ego's lane centre lies
    ``(k - 0.5)·w`` right of its arm's reference line, the actor's likewise."""
    if info.kind != "crossroad":
        raise PlacementError(f"spawn {relation!r} needs a crossroad map; this map is {info.kind!r}")
    ek, ak = -ego_lane_id - 0.5, -actor_lane_id - 0.5
    r, w = JUNCTION_RADIUS_M, LANE_WIDTH_M
    if relation == "junction_left":
        return r - ak * w, r + ek * w
    if relation == "junction_right":
        return r + ak * w, r - ek * w
    raise PlacementError(f"no crossing path for {relation!r}")


def adversary_pose(info: MapInfo, ego: Pose, spawn: dict) -> Pose:
    pose = _lane_pose(info, ego, spawn)
    lateral = float(spawn.get("lateral_m", 0.0))  # left of the lane's driving direction
    facing = str(spawn.get("facing", "with"))
    if lateral or facing != "with":
        t = lateral if pose.lane_id < 0 else -lateral
        pose = Pose(pose.road, pose.lane_id, pose.s, pose.offset + t, facing)
    return pose


def _lane_pose(info: MapInfo, ego: Pose, spawn: dict) -> Pose:
    rel = spawn["relation"]
    lon = float(spawn.get("longitudinal_m", DEFAULT_LONGITUDINAL_M.get(rel, 40.0)))
    n = info.lanes
    if rel in ("ahead", "behind"):
        return _on_road(info, Pose(ego.road, ego.lane_id, ego.s + lon))
    if rel == "left":
        if ego.lane_id == -1:
            raise PlacementError("no lane left of the ego in its direction (it drives in the lane next to the centre)")
        return _on_road(info, Pose(ego.road, ego.lane_id + 1, ego.s + lon))
    if rel == "right":
        if ego.lane_id == -n:
            raise PlacementError("no lane right of the ego (it drives in the kerb lane)")
        return _on_road(info, Pose(ego.road, ego.lane_id - 1, ego.s + lon))
    if rel == "oncoming":
        return _on_road(info, Pose(ego.road, 1, ego.s + lon))
    if rel in ("junction_left", "junction_right", "junction_opposite"):
        side = rel.split("_", 1)[1]
        road = info.entrances.get(side)
        if road is None:
            raise PlacementError(f"spawn {rel!r} needs a junction; this map is {info.kind!r}")
        # lon: the distance before its junction entry
        return _on_road(info, Pose(road, -n, info.feature_s_m - lon))
    if rel in ("roadside_right", "roadside_left"):
        edge = n * LANE_WIDTH_M + KERB_OFFSET_M
        lane = -n if rel == "roadside_right" else n
        centre = (n - 0.5) * LANE_WIDTH_M
        return _on_road(info, Pose(ego.road, lane, ego.s + lon, -(edge - centre) if lane < 0 else edge - centre))
    raise PlacementError(f"unknown spawn relation {rel!r}")


def _on_road(info: MapInfo, pose: Pose) -> Pose:
    length = info.ego_road_length_m  # every generated arm and road the spawns use has this length
    if not 0.0 <= pose.s <= length:
        raise PlacementError(f"the spawn lies {pose.s:.1f} m along road {pose.road}, outside its 0..{length:.0f} m")
    return pose


#: How far a rider keeps inside its lane's edge line at the kerb (m): room to swerve out of.
KERB_MARGIN_M = 0.2
#: A rider filtering past waiting cars rides just over the edge line, in the gutter (m, negative:
#: outside the line): a car at its lane's centre then has about a third of a metre beside it.
FILTERING_MARGIN_M = -0.1


def edge_offset_m(width_m: float, margin_m: float = KERB_MARGIN_M) -> float:
    """How far from its lane's centre (m) a road user ``width_m`` wide rides ``margin_m`` inside the
    lane's edge line."""
    return LANE_WIDTH_M / 2 - width_m / 2 - margin_m


def kerb_edge(pose: Pose, width_m: float, margin_m: float = KERB_MARGIN_M) -> Pose:
    """``pose`` (beyond the kerb) moved onto the road, to the outer edge of the kerb lane, ``margin_m``
    inside its edge line: where a rider at the kerb rides before it swerves into the road (beyond the
    kerb it is on no lane, and a lane change cannot start there). A left kerb (said by a writer who
    keeps left, on whose road it is the near one) becomes the left edge of the ego's direction: the
    rider rides the ego's way on its left, as the writer has it."""
    inside = edge_offset_m(width_m, margin_m)
    if pose.lane_id > 0:  # the left kerb, across the other direction: the left edge of the ego's own
        return Pose(pose.road, -1, pose.s, inside, pose.facing)  # (a rider there goes the ego's way)
    return Pose(pose.road, pose.lane_id, pose.s, inside if pose.offset > 0 else -inside, pose.facing)
