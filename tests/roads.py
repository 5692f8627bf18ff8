"""Roads the interpreter tests drive on, generated with scenariogeneration so the suite needs nothing
beside the checkout. ``straight_500m`` has the lane layout of esmini's road of that name (road 1, a
500 m line along x; each side a 3.07 m driving lane, a 1.68 m shoulder and a 6 m border), so a test
that compares with esmini when it is present runs the same file in both players."""

from __future__ import annotations

import atexit
import shutil
import tempfile
from functools import cache
from pathlib import Path

#: (lane type, width m) outwards from the centre lane, the same on both sides.
STRAIGHT_500M_LANES = (("driving", 3.07), ("shoulder", 1.68), ("border", 6.0))


@cache
def _folder() -> Path:
    folder = Path(tempfile.mkdtemp(prefix="vei-test-roads-"))
    atexit.register(shutil.rmtree, folder, True)
    return folder


@cache
def straight_500m() -> Path:
    """The 500 m straight road, written once per test process; returns its path."""
    from scenariogeneration import xodr

    section = xodr.LaneSection(0, xodr.standard_lane())
    for kind, width in STRAIGHT_500M_LANES:
        section.add_left_lane(xodr.Lane(lane_type=getattr(xodr.LaneType, kind), a=width))
        section.add_right_lane(xodr.Lane(lane_type=getattr(xodr.LaneType, kind), a=width))
    lanes = xodr.Lanes()
    lanes.add_lanesection(section)
    plan = xodr.PlanView(0, 0, 0)
    plan.add_geometry(xodr.Line(500))
    network = xodr.OpenDrive("straight_500m", revMinor=4)
    network.add_road(xodr.Road(1, plan, lanes))
    network.adjust_roads_and_lanes()
    path = _folder() / "straight_500m.xodr"
    network.write_xml(str(path))
    return path
