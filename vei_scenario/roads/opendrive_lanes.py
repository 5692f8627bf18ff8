"""Read lane surfaces out of an OpenDRIVE file as polygons.

Enough of OpenDRIVE to know where the lanes are: the plan-view geometries (line, arc, spiral, poly3,
paramPoly3), lane offsets and lane widths. Curves other than lines and arcs are evaluated by dense
sampling and numerical arc length, which is accurate to millimetres at the default resolution and
needs no special functions. Used to check that reconstructed trajectories lie on the road, and to
draw the road under plots.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import shapely
from lxml import etree

from vei_scenario.errors import VeiInputError
from vei_scenario.safe_xml import parse_xml, safe_parser


@dataclass(frozen=True)
class LaneArea:
    road_id: str
    lane_id: int
    lane_type: str
    polygon: shapely.Polygon


def _f(el, name: str, default: float = 0.0) -> float:
    v = el.get(name)
    return default if v is None else float(v)


def _local_curve(geom, length: float, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(u, v) points of a geometry in its local frame at ``n`` parameter values, and their arc length."""
    kind = geom[0]
    tag = kind.tag
    if tag == "line":
        s = np.linspace(0.0, length, n)
        return s, np.zeros(n), s
    if tag == "arc":
        k = _f(kind, "curvature")
        s = np.linspace(0.0, length, n)
        if abs(k) < 1e-12:
            return s, np.zeros(n), s
        return np.sin(k * s) / k, (1 - np.cos(k * s)) / k, s
    if tag == "spiral":
        c0, c1 = _f(kind, "curvStart"), _f(kind, "curvEnd")
        s = np.linspace(0.0, length, max(n, 200))
        theta = c0 * s + 0.5 * (c1 - c0) / length * s * s
        c, sn = np.cos(theta), np.sin(theta)
        ds = np.diff(s)
        u = np.concatenate([[0.0], np.cumsum(0.5 * (c[1:] + c[:-1]) * ds)])
        v = np.concatenate([[0.0], np.cumsum(0.5 * (sn[1:] + sn[:-1]) * ds)])
        return u, v, s
    if tag == "poly3":
        a, b, c, d = (_f(kind, k) for k in "abcd")
        # u runs over the chord; extend until the arc length reaches ``length``.
        u = np.linspace(0.0, length * 1.5, max(n, 400))
        v = a + b * u + c * u**2 + d * u**3
        arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(u), np.diff(v)))])
        keep = arc <= length + 1e-9
        return u[keep], v[keep] - a, arc[keep]
    if tag == "paramPoly3":
        coeffs = {k: _f(kind, k) for k in ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV")}
        p_end = 1.0 if kind.get("pRange", "normalized") == "normalized" else length
        p = np.linspace(0.0, p_end, max(n, 400))
        u = coeffs["aU"] + coeffs["bU"] * p + coeffs["cU"] * p**2 + coeffs["dU"] * p**3
        v = coeffs["aV"] + coeffs["bV"] * p + coeffs["cV"] * p**2 + coeffs["dV"] * p**3
        arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(u), np.diff(v)))])
        return u, v, arc
    raise VeiInputError(None, f"line {kind.sourceline}", f"unsupported OpenDRIVE geometry <{tag}>")


def reference_line(road, step_m: float = 0.5) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Sampled reference line of a ``<road>``: s, x, y, heading."""
    parts = []
    for geom in road.find("planView").findall("geometry"):
        s0, x0, y0, h0, length = (_f(geom, k) for k in ("s", "x", "y", "hdg", "length"))
        if length <= 0:
            continue
        n = max(2, int(np.ceil(length / step_m)) + 1)
        u, v, arc = _local_curve(geom, length, n)
        target = np.linspace(0.0, min(length, arc[-1]), n)
        uu, vv = np.interp(target, arc, u), np.interp(target, arc, v)
        c, s = np.cos(h0), np.sin(h0)
        x, y = x0 + c * uu - s * vv, y0 + s * uu + c * vv
        hx, hy = np.gradient(x), np.gradient(y)
        heading = np.arctan2(hy, hx) if n > 2 else np.full(n, np.arctan2(y[-1] - y[0], x[-1] - x[0]))
        parts.append((s0 + target, x, y, heading))
    if not parts:
        return (np.zeros(0),) * 4
    return tuple(np.concatenate([p[i] for p in parts]) for i in range(4))


def _poly(records: list[tuple[float, float, float, float, float]], ds: np.ndarray) -> np.ndarray:
    """Evaluate a piecewise cubic ``[(s_start, a, b, c, d), ...]`` at offsets ``ds``."""
    out = np.zeros_like(ds)
    if not records:
        return out
    starts = np.array([r[0] for r in records])
    idx = np.clip(np.searchsorted(starts, ds, side="right") - 1, 0, len(records) - 1)
    for i, (s0, a, b, c, d) in enumerate(records):
        m = idx == i
        t = ds[m] - s0
        out[m] = a + b * t + c * t * t + d * t**3
    return out


def read_lane_areas(path: Path | str, step_m: float = 0.5) -> list[LaneArea]:
    """Every lane of every road of an OpenDRIVE file as a polygon (zero-width lanes are skipped)."""
    return lane_areas(parse_xml(path).getroot(), step_m)


def read_lane_areas_from_bytes(
    data: bytes, step_m: float = 0.5, bbox: tuple[float, float, float, float] | None = None
) -> list[LaneArea]:
    return lane_areas(etree.fromstring(data, safe_parser()), step_m, bbox)


#: Roads whose reference line stays this far outside the ``bbox`` of :func:`lane_areas` are skipped (m);
#: wider than any plausible carriageway.
BBOX_MARGIN_M = 30.0


def lane_areas(root, step_m: float = 0.5, bbox: tuple[float, float, float, float] | None = None) -> list[LaneArea]:
    """Lane polygons of an ``<OpenDRIVE>`` element, optionally only of the roads near ``bbox``
    (min x, min y, max x, max y)."""
    areas: list[LaneArea] = []
    for road in root.iter("road"):
        s, x, y, hdg = reference_line(road, step_m)
        if s.size < 2:
            continue
        if bbox is not None and (
            x.max() < bbox[0] - BBOX_MARGIN_M
            or y.max() < bbox[1] - BBOX_MARGIN_M
            or x.min() > bbox[2] + BBOX_MARGIN_M
            or y.min() > bbox[3] + BBOX_MARGIN_M
        ):
            continue
        lanes = road.find("lanes")
        offsets = [tuple(_f(o, k) for k in ("s", "a", "b", "c", "d")) for o in lanes.findall("laneOffset")]
        t_center = _poly(sorted(offsets), s)
        nx, ny = -np.sin(hdg), np.cos(hdg)
        sections = lanes.findall("laneSection")
        starts = [_f(sec, "s") for sec in sections] + [np.inf]
        for k, sec in enumerate(sections):
            m = (s >= starts[k] - 1e-9) & (s <= starts[k + 1] + 1e-9)
            if m.sum() < 2:
                continue
            ds = s[m] - starts[k]
            for side, sign in (("left", 1.0), ("right", -1.0)):
                group = sec.find(side)
                if group is None:
                    continue
                lane_els = sorted(group.findall("lane"), key=lambda e: abs(int(e.get("id"))))
                inner = t_center[m].copy()
                for lane in lane_els:
                    widths = [tuple(_f(w, kk) for kk in ("sOffset", "a", "b", "c", "d")) for w in lane.findall("width")]
                    outer = inner + sign * _poly(sorted(widths), ds)
                    if np.max(np.abs(outer - inner)) > 1e-3:
                        xi, yi = x[m] + inner * nx[m], y[m] + inner * ny[m]
                        xo, yo = x[m] + outer * nx[m], y[m] + outer * ny[m]
                        ring = np.column_stack([np.concatenate([xi, xo[::-1]]), np.concatenate([yi, yo[::-1]])])
                        poly = shapely.make_valid(shapely.Polygon(ring))
                        areas.append(LaneArea(road.get("id"), int(lane.get("id")), lane.get("type", "none"), poly))
                    inner = outer
    return areas


def share_on_lanes(areas: list[LaneArea], x: np.ndarray, y: np.ndarray, lane_types=("driving",)) -> float:
    """Fraction of the points (x, y) inside a lane of one of ``lane_types``."""
    polys = [a.polygon for a in areas if a.lane_type in lane_types]
    if not polys or len(x) == 0:
        return 0.0
    surface = shapely.union_all(polys)
    shapely.prepare(surface)
    return float(np.mean(shapely.contains_xy(surface, np.asarray(x), np.asarray(y))))
