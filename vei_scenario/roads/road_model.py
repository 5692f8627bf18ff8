"""An OpenDRIVE road model for playing scenarios: reference lines, lanes, links, s/t ↔ x/y.

What the interpreter needs of a road network: where a lane position is in the world (``LanePosition``,
``RoadPosition``), which road and lane a world point is on (projection), and how a road user that keeps
its lane moves on across road ends and junctions. Reference-line geometries: line, arc, spiral (Euler
spiral, integrated by Gauss–Legendre quadrature), poly3 and paramPoly3 (arc length tabulated against
the curve parameter). Lanes: lane offsets, lane sections, polynomial widths.

Considered and not used: pyxodr 0.1.3 evaluates the same geometries but offers no projection of a world
point onto roads and parses files itself, outside vei's hardened parser.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from vei_scenario.errors import VeiInputError
from vei_scenario.safe_xml import parse_xml

_GL_X, _GL_W = np.polynomial.legendre.leggauss(24)

_KEYS: dict[int, tuple[list, list]] = {}


def _keys(items: list, key) -> list:
    """The sorted search keys of a list that never changes once loaded (geometries, sections, width
    records), built once per list: a lookup stays O(log n), so a road of 100 000 geometries costs
    what one does per step (building the keys at each call made runs quadratic)."""
    hit = _KEYS.get(id(items))
    if hit is not None and hit[0] is items:
        return hit[1]
    keys = [key(x) for x in items]
    if len(_KEYS) > 100_000:  # (bounded: networks loaded again and again in a sweep come and go)
        _KEYS.clear()
    _KEYS[id(items)] = (items, keys)
    return keys


def _f(el, name: str, default: float = 0.0) -> float:
    v = el.get(name)
    return _number(v, f"<{el.tag} {name}>", el) if v not in (None, "") else default


#: Coordinates and lengths beyond this (m) are no road on earth: refused before they overflow.
MAX_COORDINATE_M = 1e8


def _number(text: str, what: str, el=None) -> float:
    """A finite number from an OpenDRIVE attribute; ValueError naming it (and its line) otherwise."""
    line = f" (line {el.sourceline})" if el is not None else ""
    try:
        v = float(text)
    except (TypeError, ValueError):
        raise ValueError(f"{what}={text!r}{line} is not a number") from None
    if not math.isfinite(v):
        raise ValueError(f"{what}={text!r}{line} is not a finite number")
    return v


@dataclass
class Geometry:
    s: float
    x: float
    y: float
    hdg: float
    length: float
    kind: str  # line | arc | spiral | poly3 | paramPoly3
    p: dict = field(default_factory=dict)

    @cached_property
    def _table(self) -> tuple[np.ndarray, np.ndarray] | None:
        """(arc length, curve parameter) for poly3 and paramPoly3."""
        if self.kind not in ("poly3", "paramPoly3"):
            return None
        if self.kind == "poly3":
            top = self.length * 1.5 + 1.0  # u runs at most as far as the arc length
        else:
            top = self.length if self.p.get("pRange", "arcLength") == "arcLength" else 1.0
        q = np.linspace(0.0, top, 2001)
        du, dv = self._derivatives(q)
        speed = np.hypot(du, dv)
        s = np.concatenate([[0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(q))])
        return s, q

    def _derivatives(self, q):
        p = self.p
        if self.kind == "poly3":
            return np.ones_like(q), p["b"] + 2 * p["c"] * q + 3 * p["d"] * q * q
        return (p["bU"] + 2 * p["cU"] * q + 3 * p["dU"] * q * q, p["bV"] + 2 * p["cV"] * q + 3 * p["dV"] * q * q)

    def pose(self, ds: float) -> tuple[float, float, float]:
        """World pose of the reference line ``ds`` metres into this geometry."""
        c, s_ = math.cos(self.hdg), math.sin(self.hdg)
        if self.kind == "line":
            return self.x + ds * c, self.y + ds * s_, self.hdg
        if self.kind == "arc":
            k = self.p["curvature"]
            if abs(k) < 1e-12:
                return self.x + ds * c, self.y + ds * s_, self.hdg
            h = self.hdg + k * ds
            return self.x + (math.sin(h) - s_) / k, self.y - (math.cos(h) - c) / k, h
        if self.kind == "spiral":
            k0, k1 = self.p["curvStart"], self.p["curvEnd"]
            rate = (k1 - k0) / self.length if self.length > 0 else 0.0
            u = 0.5 * ds * (_GL_X + 1.0)
            h = self.hdg + k0 * u + 0.5 * rate * u * u
            w = 0.5 * ds * _GL_W
            return (
                self.x + float(w @ np.cos(h)),
                self.y + float(w @ np.sin(h)),
                self.hdg + k0 * ds + 0.5 * rate * ds * ds,
            )
        s_tab, q_tab = self._table
        q = float(np.interp(ds, s_tab, q_tab))
        p = self.p
        if self.kind == "poly3":
            u, v = q, p["a"] + p["b"] * q + p["c"] * q * q + p["d"] * q**3
        else:
            u = p["aU"] + p["bU"] * q + p["cU"] * q * q + p["dU"] * q**3
            v = p["aV"] + p["bV"] * q + p["cV"] * q * q + p["dV"] * q**3
        du, dv = (float(np.asarray(a).reshape(-1)[0]) for a in self._derivatives(np.array([q])))
        return self.x + u * c - v * s_, self.y + u * s_ + v * c, self.hdg + math.atan2(dv, du)


@dataclass
class Lane:
    id: int
    type: str
    widths: list[tuple[float, float, float, float, float]]  # (sOffset, a, b, c, d), sorted
    successor: int | None = None
    predecessor: int | None = None

    def width(self, ds: float) -> float:
        if not self.widths:
            return 0.0
        k = max(0, bisect.bisect_right(_keys(self.widths, lambda w: w[0]), ds) - 1)
        s0, a, b, c, d = self.widths[k]
        u = ds - s0
        return a + b * u + c * u * u + d * u**3


@dataclass
class LaneSection:
    s: float
    lanes: dict[int, Lane]  # without the centre lane 0


@dataclass
class Link:
    kind: str  # road | junction
    id: str
    contact: str | None  # start | end (roads)


@dataclass
class Road:
    id: str
    length: float
    junction: str
    geometries: list[Geometry]
    offsets: list[tuple[float, float, float, float, float]]
    sections: list[LaneSection]
    predecessor: Link | None
    successor: Link | None
    rule: str = "RHT"

    def ref_pose(self, s: float) -> tuple[float, float, float]:
        s = min(max(s, 0.0), self.length)
        k = max(0, bisect.bisect_right(_keys(self.geometries, lambda g: g.s), s) - 1)
        g = self.geometries[k]
        return g.pose(min(s - g.s, g.length))

    superelevation: list[tuple[float, float, float, float, float]] = field(default_factory=list)

    def lane_offset(self, s: float) -> float:
        return _cubic_at(self.offsets, s)

    def roll(self, s: float) -> float:
        """Superelevation (rad) at ``s``: a banked road is narrower seen from above by cos(roll)."""
        return _cubic_at(self.superelevation, s)

    def section(self, s: float) -> LaneSection:
        k = max(0, bisect.bisect_right(_keys(self.sections, lambda sec: sec.s), s + 1e-9) - 1)
        return self.sections[k]

    def section_index(self, s: float) -> int:
        return max(0, bisect.bisect_right(_keys(self.sections, lambda sec: sec.s), s + 1e-9) - 1)

    def lane_borders(self, s: float, lane_id: int) -> tuple[float, float]:
        """t of the inner and outer border of lane ``lane_id`` at ``s``."""
        sec = self.section(s)
        if lane_id not in sec.lanes:
            raise KeyError(lane_id)
        ds = s - sec.s
        sign = 1 if lane_id > 0 else -1
        t = self.lane_offset(s)
        for k in range(1, abs(lane_id)):
            lane = sec.lanes.get(sign * k)
            t += sign * (lane.width(ds) if lane else 0.0)
        return t, t + sign * sec.lanes[lane_id].width(ds)

    def map_lane(self, lane_id: int, from_k: int, to_k: int) -> int | None:
        """The id lane ``lane_id`` of section ``from_k`` has in section ``to_k``, through the lane links
        (None where a link is missing: the lane starts or ends in between)."""
        step = 1 if to_k > from_k else -1
        for k in range(from_k, to_k, step):
            lane = self.sections[k].lanes.get(lane_id)
            nxt = (lane.successor if step > 0 else lane.predecessor) if lane is not None else None
            if nxt is None or nxt not in self.sections[k + step].lanes:
                return None
            lane_id = nxt
        return lane_id

    def section_span(self, k: int) -> tuple[float, float]:
        """(first, last) s of lane section ``k`` (the last just short of the next section)."""
        lo = self.sections[k].s
        return lo, self.sections[k + 1].s - 1e-9 if k + 1 < len(self.sections) else self.length

    def lane_center_t_in(self, k: int, s: float, lane_id: int) -> float:
        """Centre t of lane ``lane_id`` of section ``k``, at ``s`` held inside that section (a lane
        that begins or ends there is taken at its first or last point)."""
        lo, hi = self.section_span(k)
        s_in = min(max(s, lo), hi)
        mapped = self.map_lane(lane_id, k, self.section_index(s_in))
        return self.lane_center_t(s_in, mapped if mapped is not None else lane_id)

    def lane_center_t(self, s: float, lane_id: int) -> float:
        inner, outer = self.lane_borders(s, lane_id)
        return 0.5 * (inner + outer)

    @cached_property
    def varying_lanes(self) -> bool:
        """Whether a lane centre can run sideways: a lane offset or a lane width that is not constant."""
        polys = list(self.offsets) + [w for sec in self.sections for lane in sec.lanes.values() for w in lane.widths]
        return any(p[2] or p[3] or p[4] for p in polys)

    def lane_drift(self, s: float, lane_id: int, eps: float = 0.05) -> float:
        """dt/ds of lane ``lane_id``'s centre at ``s`` (within its lane section): where lanes widen,
        narrow or the lane offset changes, the centre runs sideways and whoever keeps the lane heads
        that way too (as esmini's entities do)."""
        if not self.varying_lanes:
            return 0.0
        k = self.section_index(s)
        lo, hi = self.section_span(k)
        a, b = max(s - eps, lo), min(s + eps, hi)
        if b <= a or lane_id not in self.sections[k].lanes:
            return 0.0
        return (self.lane_center_t(b, lane_id) - self.lane_center_t(a, lane_id)) / (b - a)

    def curvature(self, s: float, eps: float = 0.05) -> float:
        """Curvature of the reference line at ``s`` (1/m, positive turning left)."""
        a, b = max(s - eps, 0.0), min(s + eps, self.length)
        if b <= a:
            return 0.0
        dh = self.ref_pose(b)[2] - self.ref_pose(a)[2]
        return math.atan2(math.sin(dh), math.cos(dh)) / (b - a)

    def lane_heading(self, s: float, t: float, eps: float = 0.05) -> float:
        """Heading of the curve at constant ``t`` through ``s``: the reference heading, turned where a
        changing superelevation moves the curve sideways as seen from above."""
        h = self.ref_pose(s)[2]
        if not self.superelevation:
            return h
        a, b = max(s - eps, 0.0), min(s + eps, self.length)
        if b <= a:
            return h
        dt_ds = t * (math.cos(self.roll(b)) - math.cos(self.roll(a))) / (b - a)
        along = 1.0 - t * math.cos(self.roll(s)) * self.curvature(s)
        return h + math.atan2(dt_ds, along)

    def world(self, s: float, t: float) -> tuple[float, float, float]:
        """World x, y and reference-line heading of road coordinates (s, t)."""
        x, y, h = self.ref_pose(s)
        if self.superelevation:
            t *= math.cos(self.roll(s))
        return x - t * math.sin(h), y + t * math.cos(h), h

    def lane_at(self, s: float, t: float) -> int | None:
        """The lane containing lateral position ``t`` at ``s`` (None off the road)."""
        sec = self.section(s)
        for lane_id in sec.lanes:
            inner, outer = self.lane_borders(s, lane_id)
            if min(inner, outer) - 1e-9 <= t <= max(inner, outer) + 1e-9 and inner != outer:
                return lane_id
        return None

    def drives_forward(self, lane_id: int) -> bool:
        """Whether traffic in ``lane_id`` moves towards increasing s (right-hand traffic: right lanes)."""
        return (lane_id < 0) == (self.rule != "LHT")

    @cached_property
    def samples(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        n = max(2, int(math.ceil(self.length / 0.5)) + 1)
        ss = np.linspace(0.0, self.length, n)
        pts = np.array([self.ref_pose(float(s))[:2] for s in ss])
        return ss, pts[:, 0], pts[:, 1]


@dataclass
class Connection:
    incoming: str
    connecting: str  # the connecting road, or in a direct junction the linked road itself
    contact: str
    lane_links: dict[int, int]
    direct: bool = False  # a direct junction: roads meet without a connecting road, both ways


@dataclass
class RoadPoint:
    road: Road
    s: float
    t: float
    lane: int | None
    distance: float  # from the point to its projection (0 on the road surface)


class RoadNetwork:
    def __init__(self, roads: dict[str, Road], junctions: dict[str, list[Connection]], path: Path | None = None):
        self.roads, self.junctions, self.path = roads, junctions, path

    # --- loading ------------------------------------------------------------------------------------
    @classmethod
    def load(cls, path: str | Path) -> RoadNetwork:
        path = Path(path)
        root = parse_xml(path).getroot()
        if root.tag != "OpenDRIVE":
            raise VeiInputError(path, f"line {root.sourceline}", f"root element <{root.tag}> is not <OpenDRIVE>")
        roads: dict[str, Road] = {}
        for r in root.iterfind("road"):
            try:
                road = _road(r)
            except (TypeError, ValueError, KeyError) as exc:
                raise VeiInputError(path, f"line {r.sourceline}", f"road {r.get('id')!r}: {exc}") from None
            if road.length < 0 or road.length > MAX_COORDINATE_M:
                raise VeiInputError(
                    path, f"line {r.sourceline}", f"road {road.id!r}: length {road.length:g} m is out of range"
                )
            roads[road.id] = road
        if roads and sum(r.length for r in roads.values()) <= 0:
            raise VeiInputError(path, "", "every road has zero length: nothing can be driven")
        junctions: dict[str, list[Connection]] = {}
        for j in root.iterfind("junction"):
            conns = []
            direct = j.get("type") == "direct"
            for c in j.iterfind("connection"):
                links = {int(ll.get("from")): int(ll.get("to")) for ll in c.iterfind("laneLink")}
                other = c.get("linkedRoad") if direct else c.get("connectingRoad")
                conns.append(Connection(c.get("incomingRoad"), other, c.get("contactPoint"), links, direct))
            junctions[j.get("id")] = conns
        return cls(roads, junctions, path)

    # --- queries ------------------------------------------------------------------------------------
    def road(self, road_id: str) -> Road:
        road = self.roads.get(str(road_id))
        if road is None:
            raise KeyError(f"no road {road_id!r} in the road network")
        return road

    def project(self, x: float, y: float, prefer_road: str | None = None) -> RoadPoint | None:
        """The closest point on any road's reference line region, as road coordinates: roads whose
        lanes contain the point first (the one with the smallest |t| relative to its width), else the
        nearest reference line."""
        best: RoadPoint | None = None
        best_key = (2, math.inf)
        for road in self.roads.values():
            ss, xs, ys = road.samples
            d2 = (xs - x) ** 2 + (ys - y) ** 2
            k = int(np.argmin(d2))
            s = _refine(road, x, y, float(ss[k]), float(ss[1] - ss[0]))
            rx, ry, rh = road.ref_pose(s)
            t = -(x - rx) * math.sin(rh) + (y - ry) * math.cos(rh)
            if road.superelevation:
                t /= math.cos(road.roll(s))
            along = (x - rx) * math.cos(rh) + (y - ry) * math.sin(rh)
            lane = road.lane_at(s, t) if abs(along) < 0.5 else None
            dist = 0.0 if lane is not None else math.hypot(x - rx, y - ry)
            key = (0 if lane is not None and road.id == prefer_road else 1 if lane is not None else 2, dist)
            if lane is not None and key[0] == best_key[0]:
                key = (key[0], abs(t))  # nested lanes (junctions): the closest reference line
            if key < best_key:
                best, best_key = RoadPoint(road, s, t, lane, dist), key
        return best

    def next_road(
        self, road: Road, lane_id: int, at_end: bool, prefer: str | None = None
    ) -> tuple[Road, int, bool] | None:
        """Where a road user in ``lane_id`` continues after leaving ``road`` at its end (``at_end``) or
        start: (road, lane, entering at its start); at a junction the connecting road ``prefer``
        (a route's) when it leads on from here, else the first connection from the lane."""
        link = road.successor if at_end else road.predecessor
        if link is None:
            return None
        sec = road.sections[-1] if at_end else road.sections[0]
        lane = sec.lanes.get(lane_id)
        linked = lane.successor if (lane and at_end) else lane.predecessor if lane else None
        if link.kind == "road":
            nxt = self.roads.get(link.id)
            if nxt is None:
                return None
            start = link.contact != "end"
            new_lane = linked if linked is not None else lane_id
            target_sec = nxt.sections[0] if start else nxt.sections[-1]
            return (nxt, new_lane, start) if new_lane in target_sec.lanes else None
        conns = [c for c in self.junctions.get(link.id, []) if c.incoming == road.id]
        wanted = [c for c in conns if c.connecting == prefer and c.lane_links]
        if wanted:
            c = wanted[0]
            to = c.lane_links.get(lane_id)
            if to is None:  # the route turns from another lane: the linked lane nearest to ours
                to = c.lane_links[min(c.lane_links, key=lambda k: abs(k - lane_id))]
            nxt = self.roads.get(c.connecting)
            if nxt is not None:
                return nxt, to, c.contact != "end"
        for conn in conns:
            if lane_id not in conn.lane_links:
                continue
            nxt = self.roads.get(conn.connecting)
            if nxt is None:
                continue
            return nxt, conn.lane_links[lane_id], conn.contact != "end"
        for conn in self.junctions.get(link.id, []):  # a direct junction entered from its linked road
            if not conn.direct or conn.connecting != road.id:
                continue
            back = {to: frm for frm, to in conn.lane_links.items()}
            nxt = self.roads.get(conn.incoming)
            if lane_id not in back or nxt is None:
                continue
            via_end = nxt.successor is not None and nxt.successor.kind == "junction" and nxt.successor.id == link.id
            return nxt, back[lane_id], not via_end
        return None


def _refine(road: Road, x: float, y: float, s0: float, step: float) -> float:
    """Arc length of the point of the reference line nearest (x, y) near ``s0`` (ternary search)."""
    lo, hi = max(0.0, s0 - step), min(road.length, s0 + step)
    for _ in range(40):
        m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
        p1, p2 = road.ref_pose(m1), road.ref_pose(m2)
        if (p1[0] - x) ** 2 + (p1[1] - y) ** 2 <= (p2[0] - x) ** 2 + (p2[1] - y) ** 2:
            hi = m2
        else:
            lo = m1
    return 0.5 * (lo + hi)


def _check_geometry(g: Geometry, el) -> None:
    """Refuse a geometry no vehicle can drive: a negative or absurd length or position, or a shape
    whose end lies farther from its start than its length (a curve of arc length L reaches at most L
    away; huge polynomial coefficients break this, and their arc-length table with it)."""
    where = f"<geometry> (line {el.sourceline})"
    if (
        g.length < 0
        or g.length > MAX_COORDINATE_M
        or g.s < 0
        or abs(g.x) > MAX_COORDINATE_M
        or abs(g.y) > MAX_COORDINATE_M
    ):
        raise ValueError(f"{where}: s, x, y or length out of range (length {g.length:g} m)")
    if g.length == 0 or g.kind == "line":  # (a line of finite numbers is drivable)
        return
    with np.errstate(all="ignore"):
        try:
            points = [g.pose(k * g.length / 32) for k in range(33)]
        except (OverflowError, ValueError, ZeroDivisionError):
            points = [(math.inf, math.inf, math.inf)]
    for x, y, h in points:
        if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(h)):
            raise ValueError(f"{where}: the {g.kind} gives non-finite coordinates")
    # walked in 32 steps, a drivable curve of length L covers about L: much less means the shape's
    # coefficients and its length disagree (a huge coefficient), much more is impossible
    walked = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:]))
    if not (0.5 * g.length - 0.01 <= walked <= 1.01 * g.length + 0.01):
        raise ValueError(
            f"{where}: the {g.kind} covers {walked:.3g} m over its length {g.length:g} m "
            "(its coefficients and its length disagree, or it turns tighter than any road)"
        )


def _poly(el) -> tuple[float, float, float, float, float]:
    return tuple(_f(el, k) for k in ("sOffset" if el.get("sOffset") is not None else "s", "a", "b", "c", "d"))


def _link(el) -> Link | None:
    if el is None:
        return None
    return Link(el.get("elementType", "road"), el.get("elementId"), el.get("contactPoint"))


def _road(r) -> Road:
    geoms = []
    for g in r.iterfind("planView/geometry"):
        kind_el = next((c for c in g if isinstance(c.tag, str)), None)
        if kind_el is None:
            raise ValueError("geometry without a shape")
        kind = kind_el.tag
        if kind not in ("line", "arc", "spiral", "poly3", "paramPoly3"):
            raise ValueError(f"geometry <{kind}> is not supported")
        params: dict = {k: _number(v, f"<{kind} {k}>", kind_el) for k, v in kind_el.attrib.items() if k != "pRange"}
        if kind == "paramPoly3":
            params["pRange"] = kind_el.get("pRange", "normalized")
        geom = Geometry(_f(g, "s"), _f(g, "x"), _f(g, "y"), _f(g, "hdg"), _f(g, "length"), kind, params)
        _check_geometry(geom, g)
        geoms.append(geom)
    geoms.sort(key=lambda g: g.s)
    if not geoms:
        raise ValueError("no planView geometry")
    offsets = sorted(_poly(o) for o in r.iterfind("lanes/laneOffset"))
    sections = []
    for sec in r.iterfind("lanes/laneSection"):
        lanes = {}
        for side in ("left", "right"):
            for ln in sec.iterfind(f"{side}/lane"):
                lane_id = int(ln.get("id"))
                widths = sorted(_poly(w) for w in ln.iterfind("width"))
                if not widths:  # border-defined lanes: treat the border polynomials as widths of lane 1
                    widths = sorted(_poly(w) for w in ln.iterfind("border"))
                succ, pred = ln.find("link/successor"), ln.find("link/predecessor")
                lanes[lane_id] = Lane(
                    lane_id,
                    ln.get("type", "driving"),
                    widths,
                    int(succ.get("id")) if succ is not None else None,
                    int(pred.get("id")) if pred is not None else None,
                )
        sections.append(LaneSection(_f(sec, "s"), lanes))
    sections.sort(key=lambda sec: sec.s)
    if not sections:
        sections = [LaneSection(0.0, {})]
    return Road(
        r.get("id"),
        _f(r, "length"),
        r.get("junction", "-1"),
        geoms,
        offsets,
        sections,
        _link(r.find("link/predecessor")),
        _link(r.find("link/successor")),
        r.get("rule", "RHT"),
        sorted(_poly(e) for e in r.iterfind("lateralProfile/superelevation")),
    )


def _cubic_at(polys: list[tuple[float, float, float, float, float]], s: float) -> float:
    """Value at ``s`` of OpenDRIVE's piecewise cubic records (s0, a, b, c, d); 0 before the first."""
    if not polys:
        return 0.0
    k = bisect.bisect_right(_keys(polys, lambda p: p[0]), s) - 1
    if k < 0:
        return 0.0
    s0, a, b, c, d = polys[k]
    u = s - s0
    return a + b * u + c * u * u + d * u**3
