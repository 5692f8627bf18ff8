#!/usr/bin/env python3
"""Generate a benchmark dataset on the bundled OpenStreetMap extract, with its ground truth.

Two products, both deterministic (one seed gives the same bytes):

* ``clips OUT --n N``: N short vei-clip/1 interaction clips in ``OUT/clips/`` and their ground truth in
  ``OUT/truth.json``. Each clip has the ego driving a random route through the street graph of the
  extract (turns at junctions, 4-13 m/s, up to 20 % faster or slower over the clip), one e-scooter
  crossing its path at a random approach angle (30-150 degrees from either side) and
  post-encroachment time (0.8-4 s ahead of the ego, a fifth of them 0.8-2 s behind it), sometimes a
  rider who stops short of the ego's path and sets off again, sometimes a second crossing rider or an
  oncoming one, sometimes a pedestrian on the pavement; riders hidden for a while (occlusion) beside
  the camera's own field of view; GPS noise; annotation categories, axis conventions and clock offsets
  vary as they do between datasets.
* ``drive OUT --minutes 30 --encounters 20``: one long recording ``OUT/drive.json`` (the ego on a
  random route for the whole time, stopping now and then) with that many e-scooter encounters (a
  rider crossing the ego's path ahead of it), riders and pedestrians who never come near the ego's
  path, and ``OUT/drive_truth.json``: where and when each encounter is (``vei clip split`` is checked
  against it).

The map is copied to ``OUT/maps/`` and the clips refer to it there, so the folder can be moved.
Ground truth is computed here with pyproj and plain geometry, independently of ``vei_scenario``.
Map data © OpenStreetMap contributors, ODbL 1.0.

Run ``python examples/generate_dataset.py clips out/dataset --n 50``; ``--noise-free`` leaves out GPS
noise.
"""

from __future__ import annotations

import argparse
import json
import math
import shutil
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from generate_examples import (  # noqa: E402  (the example generator's frame, noise model and camera)
    MAP_BBOX,
    MAP_FILE,
    T_GPS0,
    DensePath,
    LocalFrame,
    ProfileMover,
    gps_noise,
    visible,
)

#: OSM highway classes a car drives on (links and service roads left out: too short to ride along).
DRIVABLE = frozenset({"primary", "secondary", "tertiary", "residential", "unclassified", "living_street"})
#: Keep the route this far inside the extract's bounding box (m), so that its roads are all in the map.
INNER_MARGIN_M = 40.0
#: The generator's map origin: the crossing of Annankatu and Bulevardi.
ORIGIN = (60.1650799, 24.939421)
LANE_OFFSET_M = 1.6  # centre of the right-hand lane (netconvert's 3.2 m lanes)
PAVEMENT_OFFSET_M = 6.5  # a pedestrian on the pavement: this far right or left of the ego's lane centre
SCOOTER_CATEGORIES = ("e-scooter", "escooter", "e_scooter", "scooter")


# --- the street graph ---------------------------------------------------------------------------------


class StreetGraph:
    """The drivable streets of the extract as a directed graph (one-way streets one way), cut to its
    inner box and to the part from which every other part can be reached (so a random route never
    ends in a dead end)."""

    def __init__(self, frame: LocalFrame, osm: Path = MAP_FILE) -> None:
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import connected_components

        root = ET.parse(osm).getroot()
        latlon = {n.get("id"): (float(n.get("lat")), float(n.get("lon"))) for n in root.iter("node")}
        s, w, n, e = MAP_BBOX
        lo = frame.xy((s, w)) + INNER_MARGIN_M
        hi = frame.xy((n, e)) - INNER_MARGIN_M
        ids: dict[str, int] = {}
        xy: list[np.ndarray] = []
        edges: set[tuple[int, int]] = set()
        for way in root.iter("way"):
            tags = {t.get("k"): t.get("v") for t in way.iter("tag")}
            if tags.get("highway") not in DRIVABLE:
                continue
            refs = [nd.get("ref") for nd in way.iter("nd") if nd.get("ref") in latlon]
            oneway = tags.get("oneway") in ("yes", "1", "true")
            for a, b in zip(refs, refs[1:]):
                pa, pb = frame.xy(latlon[a]), frame.xy(latlon[b])
                if not (np.all(pa > lo) and np.all(pa < hi) and np.all(pb > lo) and np.all(pb < hi)):
                    continue
                for r, p in ((a, pa), (b, pb)):
                    if r not in ids:
                        ids[r] = len(xy)
                        xy.append(p)
                edges.add((ids[a], ids[b]))
                if not oneway:
                    edges.add((ids[b], ids[a]))
        pairs = sorted(edges)
        m = coo_matrix((np.ones(len(pairs)), ([p[0] for p in pairs], [p[1] for p in pairs])), shape=(len(xy),) * 2)
        _, label = connected_components(m, directed=True, connection="strong")
        biggest = np.bincount(label).argmax()
        keep = label == biggest
        self.xy = np.array(xy)
        self.out: dict[int, list[int]] = {}
        for a, b in pairs:
            if keep[a] and keep[b]:
                self.out.setdefault(a, []).append(b)
        self.nodes = sorted(self.out)

    def route(self, rng: np.random.Generator, length_m: float) -> np.ndarray:
        """A random walk of at least ``length_m`` (m) through the graph, no U-turns where there is
        another way on: the polyline of its node positions."""
        prev, node = -1, int(self.nodes[rng.integers(len(self.nodes))])
        pts = [self.xy[node]]
        total = 0.0
        while total < length_m:
            options = [b for b in self.out[node] if b != prev] or self.out[node]
            nxt = int(options[rng.integers(len(options))])
            total += float(np.linalg.norm(self.xy[nxt] - self.xy[node]))
            pts.append(self.xy[nxt])
            prev, node = node, nxt
        return np.array(pts)


def smooth_path(poly: np.ndarray, lateral_m: float, ds_m: float = 0.05) -> DensePath:
    """The polyline with its corners rounded (Chaikin's corner cutting, 5 rounds), shifted
    ``lateral_m`` to the right and sampled every ``ds_m`` metres."""
    keep = np.concatenate([[True], np.hypot(*np.diff(poly, axis=0).T) > 0.5])
    p = poly[keep]
    for _ in range(5):
        q = 0.75 * p[:-1] + 0.25 * p[1:]
        r = 0.25 * p[:-1] + 0.75 * p[1:]
        p = np.vstack([p[:1], np.column_stack([q, r]).reshape(-1, 2), p[-1:]])
    seg = np.hypot(*np.diff(p, axis=0).T)
    arc = np.concatenate([[0.0], np.cumsum(seg)])
    s = np.arange(0.0, arc[-1], ds_m)
    x, y = np.interp(s, arc, p[:, 0]), np.interp(s, arc, p[:, 1])
    yaw = np.unwrap(np.arctan2(np.gradient(y), np.gradient(x)))
    x, y = x + lateral_m * np.sin(yaw), y - lateral_m * np.cos(yaw)
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
    return DensePath(arc, x, y, yaw)


def line_path(point: np.ndarray, yaw: float, before_m: float, after_m: float, sway: tuple[float, float]) -> DensePath:
    """A rider's line through ``point`` at ``yaw``, from ``before_m`` before it to ``after_m`` after,
    with a sinusoidal sway ``(amplitude, wavelength)``; arc length 0 at ``point`` minus ``before_m``."""
    d = np.array([math.cos(yaw), math.sin(yaw)])
    left = np.array([-d[1], d[0]])
    u = np.arange(-before_m, after_m, 0.02)
    amp, wl = sway
    off = amp * np.sin(2 * np.pi * u / wl)
    x = point[0] + u * d[0] + off * left[0]
    y = point[1] + u * d[1] + off * left[1]
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
    yaw_s = np.unwrap(np.arctan2(np.gradient(y), np.gradient(x)))
    return DensePath(arc, x, y, yaw_s)


def s_at_point(path: DensePath, p: np.ndarray) -> float:
    return float(path.s[np.argmin(np.hypot(path.x - p[0], path.y - p[1]))])


def time_at_s(m: ProfileMover, s_target: float, t_lo: float, t_hi: float) -> float:
    """The first time within [t_lo, t_hi] at which ``m`` is at arc length ``s_target`` (10 ms grid)."""
    t = np.arange(t_lo, t_hi, 0.01)
    s = m.s(t)
    i = int(np.searchsorted(s, s_target, side="left"))
    return float(t[min(i, t.size - 1)])


def moving_to(path: DensePath, s_target: float, t_target: float, knots_t, knots_v) -> ProfileMover:
    """A mover on ``path`` with the speed profile ``knots`` that is at ``s_target`` at ``t_target``."""
    m = ProfileMover(path, 0.0, tuple(knots_t), tuple(knots_v))
    m.s0 = s_target - float(m.s(t_target))
    return m


# --- recordings ---------------------------------------------------------------------------------------


@dataclass
class Actor:
    track_id: str
    category: str
    mover: ProfileMover
    active: tuple[float, float]  # scenario-time span in which it is on the scene
    hidden: tuple[tuple[float, float], ...] = ()  # occlusions: no annotation
    truth: dict = field(default_factory=dict)


@dataclass
class Recording:
    clip_id: str
    ego: ProfileMover
    actors: list[Actor]
    duration_s: float
    annotation_hz: float
    y_axis: str
    time_offset_s: float
    osm: str
    seed: int
    t_gps0: float = T_GPS0


def _r(a, nd: int) -> list[float]:
    return [round(float(v), nd) for v in np.atleast_1d(a)]


def build_document(rec: Recording, frame: LocalFrame, noise: bool) -> dict:
    """The vei-clip/1 document of a recording: the ego's fixes at 10 Hz (with GPS noise), the
    annotations at ``annotation_hz`` of whatever the forward camera sees and nothing hides."""
    rng = np.random.default_rng(rec.seed)
    n = int(round(rec.duration_s * 10)) + 1
    tau = np.arange(n) / 10.0
    ex, ey, eyaw, ev = rec.ego.state(tau)
    hdg = frame.true_heading_deg(ex, ey, eyaw)
    if noise:
        nx, ny = gps_noise(n, rng, 0.1)
        lat, lon = frame.latlon(ex + nx, ey + ny)
        hdg = np.mod(hdg + rng.normal(0, 0.8, n), 360.0)
        spd = np.maximum(ev + rng.normal(0, 0.05, n), 0.0)
    else:
        lat, lon = frame.latlon(ex, ey)
        spd = ev
    t_gps = np.round(rec.t_gps0 + tau, 3)
    lat, lon, hdg, spd = _r(lat, 9), _r(lon, 9), _r(hdg, 4), _r(spd, 4)
    samples = [
        {"t": float(t_gps[i]), "lat": lat[i], "lon": lon[i], "heading_deg": hdg[i], "speed_mps": spd[i]}
        for i in range(n)
    ]

    # annotation frames: from a phase after the first fix, strictly inside the GPS span
    phase = float(rng.uniform(0.05, 0.95)) / rec.annotation_hz
    tf = phase + np.arange(int((rec.duration_s - phase) * rec.annotation_hz) + 1) / rec.annotation_hz
    tf = tf[tf <= rec.duration_s - 0.05]
    gx, gy, gyaw, _ = rec.ego.state(tf)
    objects: list[list[dict]] = [[] for _ in tf]
    for a in rec.actors:
        idx = np.nonzero((tf >= a.active[0]) & (tf <= a.active[1]))[0]
        if idx.size == 0:
            continue
        sx, sy, _, _ = a.mover.state(tf[idx])
        dx, dy = sx - gx[idx], sy - gy[idx]
        c, s = np.cos(gyaw[idx]), np.sin(gyaw[idx])
        rx, ry_left = c * dx + s * dy, -s * dx + c * dy
        seen = visible(rx, ry_left)
        for lo, hi in a.hidden:
            seen &= ~((tf[idx] >= lo) & (tf[idx] <= hi))
        ry = -ry_left if rec.y_axis == "right" else ry_left
        for k in np.nonzero(seen)[0]:
            objects[idx[k]].append(
                {
                    "track_id": a.track_id,
                    "category": a.category,
                    "x_m": round(float(rx[k]), 3),
                    "y_m": round(float(ry[k]), 3),
                }
            )
    # a road user in view for one frame only is left unannotated, as annotators leave a glimpse (and one
    # observation is no trajectory: vei refuses an e-scooter track seen once)
    seen: dict[str, int] = {}
    for objs in objects:
        for o in objs:
            seen[o["track_id"]] = seen.get(o["track_id"], 0) + 1
    frames = [
        {
            "t": round(rec.t_gps0 + float(t) - rec.time_offset_s, 3),
            "objects": sorted((o for o in objs if seen[o["track_id"]] > 1), key=lambda o: o["track_id"]),
        }
        for t, objs in zip(tf, objects)
    ]
    return {
        "format": "vei-clip/1",
        "id": rec.clip_id,
        "recorded_at": "2024-05-14T17:03:00Z",
        "ego": {"length_m": 4.8, "width_m": 1.9, "samples": samples},
        "annotations": {"time_offset_s": rec.time_offset_s, "y_axis": rec.y_axis, "frames": frames},
        "map": {"osm": rec.osm},
        "extensions": {"generator": "examples/generate_dataset.py", "seed": rec.seed, "gps_noise": bool(noise)},
    }


def crossing_rider(
    rng: np.random.Generator,
    track_id: str,
    category: str,
    ego: ProfileMover,
    frame: LocalFrame,
    t_ego_cross: float,
    pet_s: float,
    stop: bool,
    t_gps0: float,
    angle_range_deg: tuple[float, float] = (30.0, 150.0),
) -> Actor:
    """An e-scooter crossing the ego's path where the ego is at ``t_ego_cross``, ``pet_s`` seconds
    before the ego (negative: after it), at a random angle to the ego's heading from a random side; with
    ``stop``, it stops 3-5 m short of the ego's path for 1-3 s and sets off again."""
    px, py, pyaw, _ = ego.state(t_ego_cross)
    p = np.array([float(px), float(py)])
    side = 1.0 if rng.random() < 0.5 else -1.0
    angle = math.radians(float(rng.uniform(*angle_range_deg)))
    yaw = float(pyaw) + side * angle  # approach from the right (side +1) or the left
    v = float(rng.uniform(3.0, 6.5))
    path = line_path(p, yaw, 90.0, 60.0, (float(rng.uniform(0.05, 0.3)), float(rng.uniform(12, 30))))
    s_p = s_at_point(path, p)
    t_rider = t_ego_cross - pet_s
    truth: dict = {}
    if stop:
        short = float(rng.uniform(3.0, 5.0))
        wait = float(rng.uniform(1.0, 3.0))
        # brake to a stand over 2.5 s, `short` metres before the crossing; wait; set off to v over 2.5 s;
        # the whole profile then moved in time so that the rider crosses at t_rider
        knots_t = np.array([-2.5, 0.0, wait, wait + 2.5])
        m = ProfileMover(path, 0.0, tuple(knots_t), (v, 0.0, 0.0, v))
        m.s0 = (s_p - short) - float(m.s(0.0))
        dt = t_rider - time_at_s(m, s_p, 0.0, 60.0)
        m = ProfileMover(path, 0.0, tuple(knots_t + dt), (v, 0.0, 0.0, v))
        m.s0 = (s_p - short) - float(m.s(dt))
        truth["stop"] = {
            "t_gps": [round(t_gps0 + dt, 3), round(t_gps0 + dt + wait, 3)],
            "short_of_path_m": round(short, 3),
        }
    else:
        m = moving_to(path, s_p, t_rider, (0.0, 1.0), (v, v))
    t_on = time_at_s(m, 0.0, t_rider - 200.0, t_rider)
    t_off = time_at_s(m, float(path.s[-1]), t_rider, t_rider + 200.0)
    lat, lon = frame.latlon(p[0], p[1])
    truth.update(
        {
            "kind": "crossing",
            "crossing": {"lat": round(float(lat), 9), "lon": round(float(lon), 9)},
            "t_gps_ego_at_crossing": round(t_gps0 + t_ego_cross, 3),
            "t_gps_rider_at_crossing": round(t_gps0 + t_rider, 3),
            "time_shift_s": round(t_ego_cross - t_rider, 3),
            "approach_angle_deg": round(math.degrees(side * angle), 3),
            "speed_mps": round(v, 3),
        }
    )
    return Actor(track_id, category, m, (max(t_on, t_rider - 40.0), min(t_off, t_rider + 30.0)), (), truth)


def occlusion(rng: np.random.Generator, a: Actor, t_rider: float) -> tuple[tuple[float, float], ...]:
    """A 1-3 s occlusion (a parked van) 3-8 s before the rider reaches the crossing."""
    start = t_rider - float(rng.uniform(3.0, 8.0))
    return ((start, start + float(rng.uniform(1.0, 3.0))),)


def side_walker(
    rng: np.random.Generator, track_id: str, category: str, ego: ProfileMover, t_mid: float, offset_m: float
) -> Actor | None:
    """A road user beside the ego's path, ``offset_m`` to its left (negative: right) all along it
    (the path's offset curve), coming towards the ego or going its way, next to it at ``t_mid``: it
    never comes nearer the ego's path than that offset."""
    import shapely

    span = 20.0
    s_lo, s_hi = float(ego.s(t_mid - span - 15.0)), float(ego.s(t_mid + span + 15.0))
    keep = (ego.path.s >= s_lo - 30.0) & (ego.path.s <= s_hi + 30.0)
    pts = np.column_stack([ego.path.x[keep], ego.path.y[keep]])[::10]
    line = shapely.LineString(pts)
    off = line.offset_curve(offset_m, join_style="round")
    part = max(getattr(off, "geoms", [off]), key=lambda g: g.length)
    xy = np.array(part.coords)
    if xy.shape[0] < 20 or part.distance(line) < abs(offset_m) - 0.5:  # (a U-turn, a loop: no side to walk)
        return None
    oncoming = rng.random() < 0.5
    if oncoming:
        xy = xy[::-1]
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(xy, axis=0).T))])
    path = DensePath(arc, xy[:, 0], xy[:, 1], np.unwrap(np.arctan2(np.gradient(xy[:, 1]), np.gradient(xy[:, 0]))))
    ex, ey, _, _ = ego.state(t_mid)
    v = float(rng.uniform(1.2, 1.6)) if category == "pedestrian" else float(rng.uniform(3.0, 5.5))
    m = moving_to(path, s_at_point(path, np.array([float(ex), float(ey)])), t_mid, (0.0, 1.0), (v, v))
    t_on = time_at_s(m, 0.0, t_mid - 200.0, t_mid)
    t_off = time_at_s(m, float(arc[-1]), t_mid, t_mid + 200.0)
    truth = {"kind": "beside", "offset_m": round(offset_m, 3), "t_gps_mid": round(T_GPS0 + t_mid, 3)}
    return Actor(track_id, category, m, (max(t_on, t_mid - span), min(t_off, t_mid + span)), (), truth)


def beside(
    rng: np.random.Generator, track_id: str, category: str, ego: ProfileMover, t_mid: float, offset_m: float
) -> Actor | None:
    """:func:`side_walker` at ``t_mid`` or, where the ego's path has no side there, a few seconds on."""
    for k in range(8):
        a = side_walker(rng, track_id, category, ego, t_mid + 3.0 * k, offset_m)
        if a is not None:
            return a
    return None


def ego_profile(rng: np.random.Generator, duration_s: float, stops: bool, keep_moving: list[float]) -> tuple:
    """Speed knots of the ego: a new cruise speed (4-13 m/s) every 6-20 s; with ``stops``, now and
    then a stop of 5-20 s (never within 25 s of a time in ``keep_moving``)."""
    t, v = [0.0], [float(rng.uniform(5.0, 11.0))]
    while t[-1] < duration_s + 10:
        t0 = t[-1]
        brake, hold = v[-1] / 2.0, float(rng.uniform(5.0, 20.0))
        clear = all(not (t0 - 25.0 < k < t0 + brake + hold + 4.0 + 25.0) for k in keep_moving)
        if stops and clear and rng.random() < 0.12:
            t += [t0 + brake, t0 + brake + hold, t0 + brake + hold + 4.0]
            v += [0.0, 0.0, float(rng.uniform(5.0, 10.0))]
        else:
            dt = float(rng.uniform(6.0, 20.0))
            t.append(t0 + dt)
            v.append(float(rng.uniform(4.0, 13.0)))
    return tuple(t), tuple(v)


# --- the two products ---------------------------------------------------------------------------------


def short_clip(index: int, seed: int, graph: StreetGraph, frame: LocalFrame) -> tuple[Recording, dict]:
    """Clip ``index`` of the set generated with ``seed``: 14-26 s, one crossing e-scooter (the
    encounter), maybe a stop, a second rider, a pedestrian, an occlusion. Drawn again (the next
    attempt's seed) until the camera sees the crossing rider at least three times."""
    for attempt in range(100):
        rec, truth = _short_clip_attempt(index, seed, attempt, graph, frame)
        doc = build_document(rec, frame, noise=False)
        seen = sum(o["track_id"] == "scooter_1" for f in doc["annotations"]["frames"] for o in f["objects"])
        if seen >= 3:
            return rec, truth
    raise RuntimeError(f"clip {index}: no attempt shows its rider")  # (never seen: 1 in 10^30 odds)


def _short_clip_attempt(
    index: int, seed: int, attempt: int, graph: StreetGraph, frame: LocalFrame
) -> tuple[Recording, dict]:
    clip_seed = int(np.random.SeedSequence([seed, index, attempt]).generate_state(1)[0])
    rng = np.random.default_rng(clip_seed)
    duration = float(np.round(rng.uniform(14.0, 26.0), 1))
    # the ego at 4-13 m/s, gently faster or slower over the clip (at most 20 %)
    v0 = float(rng.uniform(4.0, 13.0))
    knots_t, knots_v = (0.0, duration), (v0, v0 * float(rng.uniform(0.8, 1.2)))
    ego = ProfileMover(DensePath(np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(2)), 0.0, knots_t, knots_v)
    ego.s0 = float(rng.uniform(20.0, 60.0))
    ego.path = smooth_path(graph.route(rng, float(ego.s(duration)) + 80.0), LANE_OFFSET_M)
    t_cross = float(rng.uniform(0.45, 0.7) * duration)
    category = SCOOTER_CATEGORIES[int(rng.integers(len(SCOOTER_CATEGORIES)))]
    # mostly ahead of the ego (the forward camera sees it cross), sometimes just behind it
    pet = float(rng.uniform(0.8, 4.0)) if rng.random() < 0.8 else -float(rng.uniform(0.8, 2.0))
    main = crossing_rider(rng, "scooter_1", category, ego, frame, t_cross, pet, rng.random() < 0.25, T_GPS0)
    if rng.random() < 0.4:
        main.hidden = occlusion(rng, main, t_cross - pet)
        main.truth["hidden_t_gps"] = [_r(np.array(h) + T_GPS0, 3) for h in main.hidden]
    actors = [main]
    extra = rng.random()
    if extra < 0.3:  # a second rider crossing 2-6 s apart
        t2 = min(max(t_cross + float(rng.choice([-1, 1]) * rng.uniform(2.0, 6.0)), 3.0), duration - 3.0)
        second = crossing_rider(rng, "scooter_2", category, ego, frame, t2, float(rng.uniform(0.8, 4.0)), False, T_GPS0)
        actors.append(second)
    elif extra < 0.5:  # an oncoming rider in the other lane
        actors.append(beside(rng, "scooter_2", category, ego, t_cross + float(rng.uniform(-3, 3)), 3.2))
    if rng.random() < 0.3:
        side = float(rng.choice([-1.0, 1.0]))
        actors.append(beside(rng, "ped_1", "pedestrian", ego, t_cross, side * PAVEMENT_OFFSET_M))
    actors = [a for a in actors if a is not None]
    rec = Recording(
        clip_id=f"gen-{seed}-{index:05d}",
        ego=ego,
        actors=actors,
        duration_s=duration,
        annotation_hz=float(rng.choice([1.0, 2.0, 5.0])),
        y_axis="right" if rng.random() < 0.7 else "left",
        time_offset_s=round(float(rng.uniform(-0.5, 0.5)), 3),
        osm="../maps/helsinki_center.osm",
        seed=clip_seed,
    )
    truth = {
        "id": rec.clip_id,
        "duration_s": duration,
        "riders": {a.track_id: dict(a.truth, category=a.category) for a in actors},
    }
    return rec, truth


def long_drive(seed: int, minutes: float, encounters: int, graph: StreetGraph) -> tuple[Recording, dict]:
    """A drive of ``minutes`` with ``encounters`` crossing e-scooters, evenly spread (each at a random
    moment of its share of the drive), and road users beside the ego's path between them."""
    rng = np.random.default_rng(seed)
    duration = float(minutes * 60.0)
    share = (duration - 40.0) / max(encounters, 1)
    times = [20.0 + share * (k + float(rng.uniform(0.3, 0.7))) for k in range(encounters)]
    knots_t, knots_v = ego_profile(rng, duration, stops=True, keep_moving=times)
    ego = ProfileMover(DensePath(np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(2)), 0.0, knots_t, knots_v)
    length = float(ego.s(duration)) + 200.0
    ego.path = smooth_path(graph.route(rng, length + 100.0), LANE_OFFSET_M, ds_m=0.1)
    ego.s0 = 50.0
    frame = LocalFrame(*ORIGIN)
    actors: list[Actor] = []
    truth_enc = []
    for k, t in enumerate(times):
        category = SCOOTER_CATEGORIES[int(rng.integers(len(SCOOTER_CATEGORIES)))]
        pet = float(rng.uniform(0.8, 4.0))
        a = crossing_rider(rng, f"scooter_{k + 1:03d}", category, ego, frame, t, pet, rng.random() < 0.25, T_GPS0)
        if rng.random() < 0.5:
            a.hidden = occlusion(rng, a, t - pet)
            a.truth["hidden_t_gps"] = [_r(np.array(h) + T_GPS0, 3) for h in a.hidden]
        actors.append(a)
        truth_enc.append(dict(a.truth, track_id=a.track_id, category=a.category))
    # between encounters: a rider or a pedestrian well beside the ego's path
    beside_truth = []
    for k in range(len(times) - 1):
        t_mid = 0.5 * (times[k] + times[k + 1])
        cat = "pedestrian" if rng.random() < 0.5 else SCOOTER_CATEGORIES[int(rng.integers(len(SCOOTER_CATEGORIES)))]
        offset = float(rng.choice([-1.0, 1.0]) * rng.uniform(7.0, 10.0))
        a = beside(rng, f"{'ped' if cat == 'pedestrian' else 'rider'}_{k + 1:03d}", cat, ego, t_mid, offset)
        if a is None:
            continue
        actors.append(a)
        beside_truth.append(dict(a.truth, track_id=a.track_id, category=cat))
    rec = Recording(
        clip_id=f"drive-{seed}",
        ego=ego,
        actors=actors,
        duration_s=duration,
        annotation_hz=2.0,
        y_axis="right",
        time_offset_s=0.1,
        osm="maps/helsinki_center.osm",
        seed=seed,
    )
    truth = {
        "description": "Ground truth of the drive: each encounter (an e-scooter crossing the ego's path) with "
        "when the ego and the rider are at the crossing (GPS clock), and road users who stay beside the "
        "ego's path (offset_m to its left, negative: right) and are no encounter.",
        "id": rec.clip_id,
        "duration_s": duration,
        "encounters": truth_enc,
        "beside": beside_truth,
    }
    return rec, truth


def _write_json(path: Path, doc: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(doc, indent=1) + "\n", "utf-8")


def _copy_map(out: Path) -> None:
    dst = out / "maps" / MAP_FILE.name
    dst.parent.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(MAP_FILE, dst)


def write_clips(out: Path, n: int, seed: int, noise: bool = True) -> list[Path]:
    """``n`` clips into ``out/clips``, their truth in ``out/truth.json``, the map in ``out/maps``."""
    frame = LocalFrame(*ORIGIN)
    graph = StreetGraph(frame)
    _copy_map(out)
    truths, paths = [], []
    for i in range(n):
        rec, truth = short_clip(i, seed, graph, frame)
        path = out / "clips" / f"{rec.clip_id}.json"
        _write_json(path, build_document(rec, frame, noise))
        truths.append(truth)
        paths.append(path)
    _write_json(
        out / "truth.json",
        {
            "description": "Ground truth of the generated clips: per clip and rider, the crossing (where, when "
            "the ego and the rider are there on the GPS clock, the TimeShift that makes them meet: ego time "
            "minus rider time, as recorded; vei's scenario drives the ego at its median speed, which moves "
            "this by up to a few tenths of a second), approach angle (degrees from the ego's heading, positive: "
            "from the right), speed, stop and occlusions.",
            "seed": seed,
            "clips": truths,
        },
    )
    return paths


def write_drive(out: Path, minutes: float, encounters: int, seed: int, noise: bool = True) -> Path:
    """The drive into ``out/drive.json``, its truth into ``out/drive_truth.json``."""
    frame = LocalFrame(*ORIGIN)
    rec, truth = long_drive(seed, minutes, encounters, StreetGraph(frame))
    _copy_map(out)
    path = out / "drive.json"
    _write_json(path, build_document(rec, frame, noise))
    _write_json(out / "drive_truth.json", truth)
    return path


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="what", required=True)
    c = sub.add_parser("clips", help="N short interaction clips (OUT/clips/*.json) and OUT/truth.json")
    c.add_argument("out", type=Path)
    c.add_argument("--n", type=int, default=20, help="number of clips (default 20)")
    d = sub.add_parser("drive", help="one long drive (OUT/drive.json) and OUT/drive_truth.json")
    d.add_argument("out", type=Path)
    d.add_argument("--minutes", type=float, default=30.0, help="length of the drive (default 30)")
    d.add_argument("--encounters", type=int, default=20, help="e-scooter encounters in it (default 20)")
    for p in (c, d):
        p.add_argument("--seed", type=int, default=1, help="seed (default 1): the same seed, the same files")
        p.add_argument("--noise-free", action="store_true", help="no GPS noise")
    args = ap.parse_args(argv)
    if args.what == "clips":
        if not 1 <= args.n <= 100_000:
            ap.error("--n must be within 1..100000")
        paths = write_clips(args.out, args.n, args.seed, not args.noise_free)
        print(f"wrote {len(paths)} clips to {args.out / 'clips'} and their ground truth to {args.out / 'truth.json'}")
    else:
        if not (1.0 <= args.minutes <= 600.0) or not (0 <= args.encounters <= args.minutes * 2):
            ap.error("--minutes must be within 1..600 and --encounters within 0..2 per minute")
        path = write_drive(args.out, args.minutes, args.encounters, args.seed, not args.noise_free)
        print(f"wrote {path} ({args.minutes:g} min, {args.encounters} encounters) and {args.out / 'drive_truth.json'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
