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

import functools
import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from vei_scenario.core import _core
from vei_scenario.errors import VeiInputError
from vei_scenario.safe_xml import content_key, parse_xml

_GL_X, _GL_W = np.polynomial.legendre.leggauss(24)
_core.set_quadrature(_GL_X.tobytes(), _GL_W.tobytes())

#: geometry kinds in the order of the core's codes (core/src/road.h)
KINDS = ("line", "arc", "spiral", "poly3", "paramPoly3")
_PARAMS = {
    "arc": ("curvature",),
    "spiral": ("curvStart", "curvEnd"),
    "poly3": ("a", "b", "c", "d"),
    "paramPoly3": ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV"),
}


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

    @cached_property
    def _alone(self) -> _core.Road:
        """This geometry as a road of its own (for checking a geometry before its road exists)."""
        return _compiled_parts([self], [], [], [LaneSection(0.0, {})], self.s + self.length, False)

    def pose(self, ds: float) -> tuple[float, float, float]:
        """World pose of the reference line ``ds`` metres into this geometry."""
        return self._alone.geometry_pose(0, ds)

    def row(self, table_row: int) -> list[float]:
        """This geometry as a row of the core's geometry array (core/src/road.h)."""
        params = [self.p.get(k, 0.0) for k in _PARAMS.get(self.kind, ())]
        n_tab = len(self._table[0]) if self._table is not None else 0
        row = [self.s, self.x, self.y, self.hdg, self.length, KINDS.index(self.kind)]
        return row + params + [0.0] * (8 - len(params)) + [table_row if n_tab else -1, n_tab]


@dataclass
class Lane:
    id: int
    type: str
    widths: list[tuple[float, float, float, float, float]]  # (sOffset, a, b, c, d), sorted
    successor: int | None = None
    predecessor: int | None = None


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

    superelevation: list[tuple[float, float, float, float, float]] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.core = _compiled(self)
        # the per-step questions, answered by the compiled road (core/src/road.c)
        self.ref_pose = self.core.ref_pose  # (x, y, heading) of the reference line at s
        self.section_index = self.core.section_index
        self.lane_borders = self.core.lane_borders  # t of a lane's inner and outer border at s
        self.lane_center_t = self.core.lane_center_t
        self.world = self.core.world  # world x, y and reference heading of (s, t)
        self.lane_at = self.core.lane_at  # the lane containing t at s (None off the road)
        # a lane-keeping step in one call: (x, y, lane heading, t) at s — turned along a lane centre
        # that runs sideways, where lanes widen or narrow, as esmini's entities are — and the
        # along-lane stretch
        self.lane_pose = self.core.lane_pose
        self.lane_stretch = self.core.lane_stretch
        self.lane_on = self.core.lane_on  # the lane id further along (lane links, lane ends, merges)

    def section(self, s: float) -> LaneSection:
        return self.sections[self.core.section_index(s)]

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

    @cached_property
    def varying_lanes(self) -> bool:
        """Whether a lane centre can run sideways: a lane offset or a lane width that is not constant."""
        polys = list(self.offsets) + [w for sec in self.sections for lane in sec.lanes.values() for w in lane.widths]
        return any(p[2] or p[3] or p[4] for p in polys)

    def drives_forward(self, lane_id: int) -> bool:
        """Whether traffic in ``lane_id`` moves towards increasing s (right-hand traffic: right lanes)."""
        return (lane_id < 0) == (self.rule != "LHT")


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
        #: facts derived from the network by other modules, computed once (it never changes once built)
        self.memo: dict = {}

    # --- loading ------------------------------------------------------------------------------------
    @classmethod
    def load(cls, path: str | Path) -> RoadNetwork:
        """The network of an OpenDRIVE file, built once per process while the file stays as it was (a
        network is never changed once built; a sweep's variants share it)."""
        path = Path(path)
        return _network(cls, path, content_key(path))

    @classmethod
    def _read(cls, path: Path) -> RoadNetwork:
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
                try:
                    links = {_lane_id(ll.get("from"), ll): _lane_id(ll.get("to"), ll) for ll in c.iterfind("laneLink")}
                except ValueError as exc:
                    raise VeiInputError(path, f"line {c.sourceline}", f"junction {j.get('id')!r}: {exc}") from None
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
            s, t, _along, dist, lane = road.core.locate(x, y)
            if lane is not None:
                dist = 0.0
            key = (0 if lane is not None and road.id == prefer_road else 1 if lane is not None else 2, dist)
            if lane is not None and key[0] == best_key[0]:
                key = (key[0], abs(t))  # nested lanes (junctions): the closest reference line
            if key < best_key:
                best, best_key = RoadPoint(road, s, t, lane, dist), key
        return best

    def distance_along_lane(
        self, road_id: str, lane_id: int, s: float, forward: bool, target: RoadPoint, limit_m: float
    ) -> float | None:
        """How far ``target`` lies ahead along the lane a road user in ``lane_id`` at ``s`` drives
        (``forward``: towards increasing s), on across lane sections and road links as it would drive
        on (:meth:`next_road`), counted in s; negative when it lies behind on the same road; None when
        it is not on that lane within ``limit_m``."""
        road, lane, travelled = self.road(road_id), lane_id, 0.0
        for _ in range(2 * len(self.roads) + 2):
            if target.road is road:
                there = road.lane_on(s, target.s, lane, True) if (target.s >= s) == forward else lane
                if there == target.lane:
                    d = travelled + (target.s - s if forward else s - target.s)
                    return d if d <= limit_m else None
            travelled += road.length - s if forward else s
            if travelled > limit_m:
                return None
            nxt = self.next_road(road, road.lane_on(s, road.length if forward else 0.0, lane, True), forward)
            if nxt is None:
                return None
            road, lane, forward = nxt
            s = 0.0 if forward else road.length
        return None

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
            return (nxt, new_lane, start) if _enters(nxt, new_lane, start) else None
        conns = [c for c in self.junctions.get(link.id, []) if c.incoming == road.id]
        # (a route's connection when it is linked from our lane; from an unlinked lane a road user goes
        # no further than esmini takes it: to the end of its road, not across into a linked one)
        wanted = [c for c in conns if c.connecting == prefer and lane_id in c.lane_links]
        if wanted:
            c = wanted[0]
            to = c.lane_links[lane_id]
            nxt = self.roads.get(c.connecting)
            if _enters(nxt, to, c.contact != "end"):
                return nxt, to, c.contact != "end"
        for conn in conns:
            if lane_id not in conn.lane_links:
                continue
            nxt = self.roads.get(conn.connecting)
            if not _enters(nxt, conn.lane_links[lane_id], conn.contact != "end"):
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
            if not _enters(nxt, back[lane_id], not via_end):
                continue
            return nxt, back[lane_id], not via_end
        return None


def _enters(road: Road | None, lane_id: int, start: bool) -> bool:
    """Whether a road user can enter ``road`` in lane ``lane_id`` at its start (``start``) or end: a
    link to a lane the road does not have there leads nowhere (a dead end, where it stops)."""
    if road is None or not road.sections:
        return False
    return lane_id in (road.sections[0] if start else road.sections[-1]).lanes


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


#: Lane ids beyond this are no road's: refused (the compiled road keeps them as C ints).
MAX_LANE_ID = 1_000_000


def _lane_id(text, el) -> int:
    """A lane id (of a lane or a lane link) as an integer within ±MAX_LANE_ID; ValueError naming the line."""
    try:
        value = int(text)
    except (TypeError, ValueError):
        raise ValueError(f"lane id {text!r} (line {el.sourceline}) is not an integer") from None
    if abs(value) > MAX_LANE_ID:
        raise ValueError(f"lane id {value} (line {el.sourceline}) is out of range (at most ±{MAX_LANE_ID})")
    return value


def _poly(el) -> tuple[float, float, float, float, float]:
    return tuple(_f(el, k) for k in ("sOffset" if el.get("sOffset") is not None else "s", "a", "b", "c", "d"))


def _link(el) -> Link | None:
    if el is None:
        return None
    return Link(el.get("elementType", "road"), el.get("elementId"), el.get("contactPoint"))


def _road(r) -> Road:
    if not r.get("id"):
        raise ValueError("a road needs an id (links and positions name roads by it)")
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
                lane_id = _lane_id(ln.get("id"), ln)
                widths = sorted(_poly(w) for w in ln.iterfind("width"))
                if not widths:  # border-defined lanes: treat the border polynomials as widths of lane 1
                    widths = sorted(_poly(w) for w in ln.iterfind("border"))
                succ, pred = ln.find("link/successor"), ln.find("link/predecessor")
                lanes[lane_id] = Lane(
                    lane_id,
                    ln.get("type", "driving"),
                    widths,
                    _lane_id(succ.get("id"), succ) if succ is not None else None,
                    _lane_id(pred.get("id"), pred) if pred is not None else None,
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


def _compiled(road: Road) -> _core.Road:
    return _compiled_parts(
        road.geometries, road.offsets, road.superelevation, road.sections, road.length, road.varying_lanes
    )


def _compiled_parts(geometries, offsets, superelevation, sections, length: float, varying: bool) -> _core.Road:
    """The compiled form of a road (core/src/road.h): its records as flat arrays, lanes in file order."""
    rows, tab_s, tab_q, n_tab = [], [], [], 0
    for g in geometries:
        rows.append(g.row(n_tab))
        if g._table is not None:
            tab_s.append(g._table[0])
            tab_q.append(g._table[1])
            n_tab += len(g._table[0])
    lanes, widths, lane0 = [], [], [0]
    for k, sec in enumerate(sections):
        for lane in sec.lanes.values():
            links = [math.nan if v is None else v for v in (lane.successor, lane.predecessor)]
            lanes.append([k, lane.id, lane.type == "driving", len(widths), len(lane.widths), *links])
            widths.extend(lane.widths)
        lane0.append(len(lanes))

    def f64(rows, cols: int) -> bytes:
        return np.asarray(rows, dtype=np.float64).reshape(-1, cols).tobytes()

    return _core.Road(
        f64(rows, len(rows[0]) if rows else 1),
        np.concatenate(tab_s).tobytes() if tab_s else b"",
        np.concatenate(tab_q).tobytes() if tab_q else b"",
        f64(offsets, 5),
        f64(superelevation, 5),
        f64([sec.s for sec in sections], 1),
        np.asarray(lane0, dtype=np.intc).tobytes(),
        f64(lanes, 7),
        f64(widths, 5),
        float(length),
        bool(varying),
    )


@functools.lru_cache(maxsize=8)
def _network(cls, path: Path, key: bytes) -> RoadNetwork:
    return cls._read(path)
