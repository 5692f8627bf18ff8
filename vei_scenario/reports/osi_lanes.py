"""The lanes of an OpenDRIVE road network as ASAM OSI ``osi3.Lane`` messages (what an OSI traffic
participant is shown of the road, :mod:`vei_scenario.sut.participant`).

One lane per OpenDRIVE lane and lane section: its centre line sampled at most :data:`SPACING_M` apart
along the reference line
(and at the section's ends), in the road's direction of increasing s, ``centerline_is_driving_direction``
where traffic in the lane goes that way (right-hand traffic: the right lanes), the neighbours in the
section as left/right adjacent lanes (left and right seen along the centre line, as OSI defines them), a
driving lane ``TYPE_DRIVING``, any lane of a junction's road ``TYPE_INTERSECTION``, other lanes
``TYPE_NONDRIVING``; ``source_reference`` names the road, the section's index and the lane id. Lane
boundaries are not described.
"""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

#: The longest step between two centre-line points along the reference line (m).
SPACING_M = 2.0


def _neighbour(lanes, lane_id: int, step: int) -> int | None:
    other = lane_id + step
    if other == 0:
        other += step
    return other if other in lanes else None


@lru_cache(maxsize=8)
def _lanes(road_file: str, first_id: int) -> bytes:
    from osi3 import osi_groundtruth_pb2, osi_lane_pb2

    from vei_scenario.roads.road_model import RoadNetwork

    net = RoadNetwork.load(road_file)
    gt = osi_groundtruth_pb2.GroundTruth()
    cls = osi_lane_pb2.Lane.Classification
    ids: dict[tuple[str, int, int], int] = {}
    for road in net.roads.values():
        for k, sec in enumerate(road.sections):
            for lane_id in sorted(sec.lanes):
                ids[(road.id, k, lane_id)] = first_id + len(ids)
    for road in net.roads.values():
        for k, sec in enumerate(road.sections):
            lo, hi = road.section_span(k)
            n = max(1, math.ceil((hi - lo) / SPACING_M))
            stations = [lo + (hi - lo) * i / n for i in range(n + 1)]
            for lane_id in sorted(sec.lanes):
                lane = gt.lane.add()
                lane.id.value = ids[(road.id, k, lane_id)]
                c = lane.classification
                if road.junction not in ("", "-1"):
                    c.type = cls.TYPE_INTERSECTION
                else:
                    c.type = cls.TYPE_DRIVING if sec.lanes[lane_id].type == "driving" else cls.TYPE_NONDRIVING
                c.centerline_is_driving_direction = road.drives_forward(lane_id)
                for s in stations:
                    x, y, _ = road.world(s, road.lane_center_t_in(k, s, lane_id))
                    p = c.centerline.add()
                    p.x, p.y = x, y
                for step, field in ((1, "left_adjacent_lane_id"), (-1, "right_adjacent_lane_id")):
                    other = _neighbour(sec.lanes, lane_id, step)
                    if other is not None:
                        getattr(c, field).add().value = ids[(road.id, k, other)]
                ref = lane.source_reference.add()
                ref.type = "net.asam.opendrive"
                ref.identifier.extend([road.id, str(k), str(lane_id)])
    return gt.SerializeToString()


def lanes_bytes(road_file: Path, first_id: int) -> bytes:
    """The road network's lanes as a serialised ``osi3.GroundTruth`` holding only ``lane`` (ids from
    ``first_id`` on): appended to a serialised GroundTruth, protobuf merges them into it. Built once per
    file and first id."""
    return _lanes(str(Path(road_file).resolve()), first_id)
