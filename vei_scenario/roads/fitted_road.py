"""An OpenDRIVE road fitted to the ego track, for clips without a map.

The smoothed ego path is cut into pieces of about ``SEGMENT_M`` metres; each piece becomes a
``paramPoly3`` (normalised range) built as a cubic Hermite curve through the end points with the path's
tangents there, so the reference line is continuous in position and heading at every joint. Two
driving lanes of ``LANE_WIDTH_M``; a lane offset puts the ego in the middle of the right-hand lane,
which is where a car drives when there is no map to say otherwise.
"""

from __future__ import annotations

import numpy as np
from scenariogeneration import xodr

from vei_scenario.geometry.resample import Trajectory

SEGMENT_M = 15.0
LANE_WIDTH_M = 3.5
#: Extra road before the first and after the last ego position, so boxes at the ends stay on the road.
END_EXTENSION_M = 10.0


def _path_samples(ego: Trajectory, step_m: float = 0.5) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Points every ``step_m`` along the ego path, extended straight at both ends; headings by tangent."""
    arc = ego.arc_length()
    keep = np.concatenate([[True], np.diff(arc) > 1e-6])
    arc, x, y = arc[keep], ego.x[keep], ego.y[keep]
    if arc[-1] < 1.0:
        raise ValueError("the ego moves less than 1 m; no road can be fitted to its track")
    s = np.arange(0.0, arc[-1], step_m)
    s = np.append(s, arc[-1])
    px, py = np.interp(s, arc, x), np.interp(s, arc, y)
    h0 = np.arctan2(py[1] - py[0], px[1] - px[0])
    h1 = np.arctan2(py[-1] - py[-2], px[-1] - px[-2])
    e = np.arange(step_m, END_EXTENSION_M + 1e-9, step_m)
    px = np.concatenate([px[0] - e[::-1] * np.cos(h0), px, px[-1] + e * np.cos(h1)])
    py = np.concatenate([py[0] - e[::-1] * np.sin(h0), py, py[-1] + e * np.sin(h1)])
    heading = np.unwrap(np.arctan2(np.gradient(py), np.gradient(px)))
    return px, py, heading


def _hermite_piece(x0, y0, h0, x1, y1, h1) -> xodr.ParamPoly3:
    """Cubic Hermite curve in the local frame of (x0, y0, h0), parameter p in [0, 1]."""
    c, s = np.cos(h0), np.sin(h0)
    dx, dy = x1 - x0, y1 - y0
    u1, v1 = c * dx + s * dy, -s * dx + c * dy
    chord = float(np.hypot(u1, v1))
    t0 = np.array([chord, 0.0])
    t1 = chord * np.array([np.cos(h1 - h0), np.sin(h1 - h0)])
    p1 = np.array([u1, v1])
    b = t0
    cc = 3 * p1 - 2 * t0 - t1
    d = -2 * p1 + t0 + t1
    return xodr.ParamPoly3(0.0, b[0], cc[0], d[0], 0.0, b[1], cc[1], d[1], prange="normalized")


def fitted_road_element(ego: Trajectory, rev_minor: int = 7):
    """An ``<OpenDRIVE>`` element (scenariogeneration) with one two-lane road along the ego track."""
    px, py, heading = _path_samples(ego)
    n_seg = max(1, int(round((px.size - 1) * 0.5 / SEGMENT_M)))
    idx = np.unique(np.linspace(0, px.size - 1, n_seg + 1).round().astype(int))
    plan = xodr.PlanView(float(px[0]), float(py[0]), float(heading[0]))
    for i0, i1 in zip(idx[:-1], idx[1:]):
        plan.add_geometry(_hermite_piece(px[i0], py[i0], heading[i0], px[i1], py[i1], heading[i1]))

    center = xodr.Lane(lane_type=xodr.LaneType.none)
    center.add_roadmark(xodr.RoadMark(xodr.RoadMarkType.broken, 0.12))
    section = xodr.LaneSection(0, center)
    for side in ("left", "right"):
        lane = xodr.Lane(lane_type=xodr.LaneType.driving, a=LANE_WIDTH_M)
        lane.add_roadmark(xodr.RoadMark(xodr.RoadMarkType.solid, 0.12))
        getattr(section, f"add_{side}_lane")(lane)
    lanes = xodr.Lanes()
    lanes.add_lanesection(section)
    lanes.add_laneoffset(xodr.LaneOffset(0, LANE_WIDTH_M / 2))

    road = xodr.Road(1, plan, lanes, name="ego_track")
    odr = xodr.OpenDrive("fitted", revMinor=str(rev_minor))
    odr.add_road(road)
    odr.adjust_roads_and_lanes()
    return odr.get_element()
