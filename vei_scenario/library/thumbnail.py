"""A small SVG map of a compiled scenario: its lanes, the ego's path, the riders' paths and the
conflict point. Plain SVG text (no plotting library): a few milliseconds a scenario, and the same
bytes every time."""

from __future__ import annotations

import html

import numpy as np
import shapely

from vei_scenario.compiler import CompileResult
from vei_scenario.roads.opendrive_lanes import read_lane_areas_from_bytes

SIZE_PX = 240
MARGIN_M = 15.0


def _points(xy: np.ndarray, to_px) -> str:
    px = to_px(xy)
    return " ".join(f"{x:.1f},{y:.1f}" for x, y in px)


def thumbnail_svg(result: CompileResult, xodr: bytes) -> str:
    """The SVG of ``result`` over its road network ``xodr``."""
    m, rec = result.model, result.reconstruction
    paths = [rec.ego.xy] + [rec.scooters[t].trajectory.xy for t in sorted(rec.scooters)]
    allxy = np.vstack(paths)
    x0, y0 = allxy.min(axis=0) - MARGIN_M
    x1, y1 = allxy.max(axis=0) + MARGIN_M
    span = max(x1 - x0, y1 - y0)
    cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
    x0, y0 = cx - span / 2, cy - span / 2
    scale = SIZE_PX / span

    def to_px(xy: np.ndarray) -> np.ndarray:
        xy = np.atleast_2d(xy)
        return np.column_stack([(xy[:, 0] - x0) * scale, SIZE_PX - (xy[:, 1] - y0) * scale])

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{SIZE_PX}" height="{SIZE_PX}" '
        f'viewBox="0 0 {SIZE_PX} {SIZE_PX}">',
        f'<rect width="{SIZE_PX}" height="{SIZE_PX}" fill="#f4f4f0"/>',
    ]
    box = shapely.box(x0, y0, x0 + span, y0 + span)
    lanes = [a.polygon for a in read_lane_areas_from_bytes(xodr, step_m=5.0, bbox=(x0, y0, x0 + span, y0 + span))]
    if lanes:
        road = shapely.union_all(lanes).intersection(box).simplify(0.3)
        for poly in getattr(road, "geoms", [road]):
            if poly.geom_type != "Polygon" or poly.is_empty:
                continue
            rings = [np.asarray(poly.exterior.coords)] + [np.asarray(r.coords) for r in poly.interiors]
            d = " ".join("M" + _points(r, to_px).replace(" ", " L") + " Z" for r in rings)
            out.append(f'<path d="{d}" fill="#d0d0d0" fill-rule="evenodd"/>')
    out.append(f'<polyline points="{_points(paths[0][::5], to_px)}" fill="none" stroke="#1f5fbf" stroke-width="2"/>')
    for tid in sorted(rec.scooters):
        colour = "#d62728" if tid == m.threat else "#ff9f40"
        xy = rec.scooters[tid].trajectory.xy[::5]
        out.append(f'<polyline points="{_points(xy, to_px)}" fill="none" stroke="{colour}" stroke-width="1.5"/>')
    c = m.conflicts[m.threat]
    if c.reaches_ego_path:
        ((px, py),) = to_px(np.array([c.point_x, c.point_y]))
        out.append(f'<circle cx="{px:.1f}" cy="{py:.1f}" r="4" fill="none" stroke="#000" stroke-width="1.5"/>')
    bar = 20.0 * scale  # a 20 m scale bar
    out.append(
        f'<line x1="8" y1="{SIZE_PX - 8}" x2="{8 + bar:.1f}" y2="{SIZE_PX - 8}" stroke="#000" stroke-width="2"/>'
        f'<text x="8" y="{SIZE_PX - 12}" font-size="9" font-family="sans-serif">20 m</text>'
    )
    out.append(f"<title>{html.escape(rec.clip.id)}</title></svg>")
    return "\n".join(out) + "\n"
