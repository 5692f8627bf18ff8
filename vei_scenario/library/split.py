"""Cut a long recording into interaction clips (``vei clip split``).

A drive log is hours of ego GPS with annotations of everything the sensors saw; an interaction is
the stretch of it in which a vulnerable road user comes near the ego's path. The rules, in order:

1. **Who**: tracks whose category is one of ``categories`` (by default the e-scooter spellings vei
   compiles; any class, e.g. ``pedestrian``, can be added).
2. **Near**: an observation is placed in the world (the ego's fix and heading at its time, linear
   between fixes, plus its ego-frame offset); it is *near* when it lies within ``near_m`` of the ego's
   path from ``horizon_s`` before to ``horizon_s`` after that time (where the ego has been and is
   going: a rider crossing ahead is near before the ego gets there). Two consecutive observations of
   a track at most ``max_gap_s`` apart are joined by a straight line; where any of it is near, both
   observations' times are near, so that a rider crossing between two sparse annotations, or unseen
   (occluded, or out of a camera's field of view), is not missed.
3. **One interaction per track and approach**: a track's near times, each with the time the ego is
   at the nearest point of its path (the interaction is over when the ego has passed), form one
   interaction from the first to the last, unless more than ``max_gap_s`` apart (it came back: two).
4. **Padding**: each interaction starts ``pad_before_s`` earlier (the approach) and ends
   ``pad_after_s`` later, widened about its middle to at least ``min_length_s``, within the recording.
5. **Merging**: interactions that overlap, or are less than ``merge_gap_s`` apart, are one clip
   (several riders at once are one scenario).

Each clip keeps the ego fixes and annotation frames of its time range (tracks seen only once in it are
dropped: one observation is no trajectory), its map reference re-anchored to where it is written, and
its provenance under ``extensions.vei_split``: source file name and SHA-256, source id, time range on
the GPS clock and from the source's start, the tracks that made it an interaction, and the rules'
values. Clips are written only when all of them are ready.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
from dataclasses import asdict, dataclass, field
from datetime import datetime, timedelta
from pathlib import Path

import numpy as np

from vei_scenario.clip.loader import clip_from_document, read_json
from vei_scenario.clip.model import SCOOTER_CATEGORIES, Clip, local_tmerc
from vei_scenario.errors import VeiInputError

#: The longest recording ``vei clip split`` reads (s): a day's driving.
MAX_DRIVE_S = 24 * 3600.0


@dataclass(frozen=True)
class SplitOptions:
    """The rules of :mod:`vei_scenario.library.split` (distances in m, times in s)."""

    near_m: float = 3.5
    horizon_s: float = 5.0
    max_gap_s: float = 10.0
    pad_before_s: float = 6.0
    pad_after_s: float = 3.0
    merge_gap_s: float = 0.0
    min_length_s: float = 5.0
    categories: tuple[str, ...] = tuple(sorted(SCOOTER_CATEGORIES))

    def check(self) -> None:
        for name, low in (("near_m", 0.0), ("horizon_s", 0.0), ("max_gap_s", 0.0), ("min_length_s", 0.0)):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > low):
                raise VeiInputError(None, _flag(name), f"{value!r} must be a positive number")
        for name in ("pad_before_s", "pad_after_s", "merge_gap_s"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0):
                raise VeiInputError(None, _flag(name), f"{value!r} must be a number >= 0")
        if not self.categories:
            raise VeiInputError(None, "--category", "at least one category is needed")


def _flag(name: str) -> str:
    return "--" + name.removesuffix("_m").removesuffix("_s").replace("_", "-")


@dataclass(frozen=True)
class Interaction:
    """One clip to cut: its time range on the GPS clock, the tracks near the ego's path in it and the
    closest any of them came to that path (m)."""

    t_start: float
    t_end: float
    tracks: tuple[str, ...]
    closest_m: float


@dataclass
class SplitResult:
    source: Path
    t0: float  # the recording's first GPS fix
    duration_s: float
    interactions: list[Interaction]
    written: list[Path] = field(default_factory=list)


def load_drive(path: Path, frame_rate_hz: float | None = None, time_unit: str | None = None) -> tuple[Clip, dict]:
    """A recording to split (vei-clip/1 or OpenLABEL 1.0, up to MAX_DRIVE_S long, with or without
    e-scooters) and its vei-clip/1 document."""
    doc = read_json(path)
    if isinstance(doc, dict) and "openlabel" in doc:
        from vei_scenario.clip.openlabel import _checked_clip, openlabel_to_clip_document

        clip_doc, paths = openlabel_to_clip_document(path, doc, frame_rate_hz, time_unit)
        clip = _checked_clip(
            path, doc, clip_doc, paths, time_unit, frame_rate_hz, max_span_s=MAX_DRIVE_S, require_scooter=False
        )
        return clip, clip_doc
    if frame_rate_hz is not None or time_unit is not None:
        from vei_scenario.clip.openlabel import refuse_clock_options

        refuse_clock_options(path, frame_rate_hz, time_unit)
    return clip_from_document(path, doc, max_span_s=MAX_DRIVE_S, require_scooter=False), doc


def _ego_pose(clip: Clip):
    """The ego's pose at any GPS time: position and heading linear between fixes, in a local frame."""
    from vei_scenario.geometry.angles import unwrap_continuous
    from vei_scenario.geometry.projection import LocalProjection

    ego = clip.ego
    proj = LocalProjection(float(ego.lat[0]), float(ego.lon[0]))
    fx, fy = proj.forward(ego.lat, ego.lon)
    fyaw = unwrap_continuous(proj.heading_to_yaw(ego.lat, ego.lon, ego.heading_deg))

    def pose(t: np.ndarray):
        return np.interp(t, ego.t, fx), np.interp(t, ego.t, fy), np.interp(t, ego.t, fyaw)

    return fx, fy, pose


def _path_distance(geoms, t_lo: np.ndarray, t_hi: np.ndarray, ego_t, fx, fy, pose) -> tuple[np.ndarray, np.ndarray]:
    """Distance of each geometry to the ego's path over its time window [t_lo, t_hi], and the time at
    which the ego is at the nearest point of that path (linear between fixes)."""
    import shapely

    lines, times = [], []
    for lo, hi in zip(t_lo, t_hi):
        i0, i1 = np.searchsorted(ego_t, [lo, hi])
        ex0, ey0, _ = pose(lo)
        ex1, ey1, _ = pose(hi)
        xs = np.concatenate([[ex0], fx[i0:i1], [ex1]])
        ys = np.concatenate([[ey0], fy[i0:i1], [ey1]])
        lines.append(shapely.linestrings(np.column_stack([xs, ys])))
        times.append(
            (
                np.concatenate([[lo], ego_t[i0:i1], [hi]]),
                np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(xs), np.diff(ys)))]),
            )
        )
    geoms, lines = np.array(geoms, dtype=object), np.array(lines, dtype=object)
    dist = shapely.distance(geoms, lines)
    on_path = shapely.get_point(shapely.shortest_line(geoms, lines), 1)
    along = shapely.line_locate_point(lines, on_path)
    t_ego = np.array([np.interp(a, arc, tt) for (tt, arc), a in zip(times, along)])
    return dist, t_ego


def find_interactions(clip: Clip, opts: SplitOptions | None = None) -> list[Interaction]:
    """The interactions of a recording by the rules of this module, in time order."""
    import shapely

    from vei_scenario.geometry.frames import ego_to_world

    opts = opts or SplitOptions()
    opts.check()
    ego = clip.ego
    t0, t1 = float(ego.t[0]), float(ego.t[-1])
    fx, fy, pose = _ego_pose(clip)
    ann = clip.annotations
    wanted = {c.lower() for c in opts.categories}
    pieces: list[tuple[float, float, str, float]] = []  # (start, end, track, closest)
    for tid, obs in sorted(ann.tracks().items()):
        if obs[0].category.lower() not in wanted:
            continue
        t = np.array([o.t_annotation for o in obs]) + ann.time_offset_s
        ex, ey, eyaw = pose(t)
        wx, wy = ego_to_world([o.x_m for o in obs], [o.y_m for o in obs], ann.y_axis, ex, ey, eyaw)
        points = shapely.points(wx, wy)
        d_point, te = _path_distance(points, t - opts.horizon_s, t + opts.horizon_s, ego.t, fx, fy, pose)
        spans = [
            (min(float(t[i]), float(te[i])), max(float(t[i]), float(te[i])), float(d_point[i]))
            for i in np.nonzero(d_point <= opts.near_m)[0]
        ]
        joined = np.nonzero(np.diff(t) <= opts.max_gap_s)[0]
        if joined.size:
            segs = shapely.linestrings(
                np.stack([np.column_stack([wx, wy])[joined], np.column_stack([wx, wy])[joined + 1]], 1)
            )
            d_seg, te = _path_distance(
                list(segs), t[joined] - opts.horizon_s, t[joined + 1] + opts.horizon_s, ego.t, fx, fy, pose
            )
            spans += [
                (min(float(t[i]), float(e)), max(float(t[i + 1]), float(e)), float(d))
                for i, d, e in zip(joined, d_seg, te)
                if d <= opts.near_m
            ]
        spans.sort()
        for lo, hi, d in spans:  # near times more than max_gap_s apart: separate interactions
            if pieces and pieces[-1][2] == tid and lo - pieces[-1][1] <= opts.max_gap_s:
                a, b, _, c = pieces[-1]
                pieces[-1] = (a, max(b, hi), tid, min(c, d))
            else:
                pieces.append((lo, hi, tid, d))
    windows = []
    for lo, hi, tid, d in pieces:
        a, b = lo - opts.pad_before_s, hi + opts.pad_after_s
        if b - a < opts.min_length_s:
            mid = 0.5 * (a + b)
            a, b = mid - 0.5 * opts.min_length_s, mid + 0.5 * opts.min_length_s
        a, b = max(a, t0), min(b, t1)
        if b - a < opts.min_length_s:  # at an end of the recording: widened the other way
            a, b = (t0, min(t0 + opts.min_length_s, t1)) if a == t0 else (max(t1 - opts.min_length_s, t0), t1)
        windows.append((a, b, tid, d))
    windows.sort()
    out: list[Interaction] = []
    for a, b, tid, d in windows:
        if out and a <= out[-1].t_end + opts.merge_gap_s:
            last = out[-1]
            tracks = tuple(sorted(set(last.tracks) | {tid}))
            out[-1] = Interaction(last.t_start, max(last.t_end, b), tracks, min(last.closest_m, d))
        else:
            out.append(Interaction(a, b, (tid,), d))
    return out


def _shift_datetime(text: str | None, seconds: float) -> str | None:
    """An ISO 8601 time ``seconds`` later, in the form it was written (Z kept)."""
    if text is None:
        return None
    try:
        when = datetime.fromisoformat(text.replace("Z", "+00:00"))
    except ValueError:
        return text
    out = (when + timedelta(seconds=seconds)).isoformat()
    return out.replace("+00:00", "Z") if text.endswith("Z") else out


def clip_document(
    doc: dict, clip: Clip, part: Interaction, clip_id: str, out_dir: Path, provenance: dict
) -> tuple[dict, list[str]]:
    """The vei-clip/1 document of one interaction of ``doc`` (the recording ``clip`` was read from),
    and the tracks it drops (seen once in its range)."""
    a, b = part.t_start, part.t_end
    eps = 1e-9
    # the fixes from the last at or before the start to the first at or after the end: the range is
    # within the ego's span, as the annotations in it must be
    i0 = max(int(np.searchsorted(clip.ego.t, a + eps, side="right")) - 1, 0)
    i1 = min(int(np.searchsorted(clip.ego.t, b - eps, side="left")), clip.ego.t.size - 1)
    samples = doc["ego"]["samples"][i0 : i1 + 1]
    ann = doc["annotations"]
    offset = float(ann.get("time_offset_s", 0.0))
    frames = [f for f in ann["frames"] if a - eps <= float(f["t"]) + offset <= b + eps]
    counts: dict[str, int] = {}
    for f in frames:
        for o in f["objects"]:
            counts[o["track_id"]] = counts.get(o["track_id"], 0) + 1
    dropped = sorted(k for k, n in counts.items() if n < 2)
    kept_frames = []
    for f in frames:
        objects = [o for o in f["objects"] if counts[o["track_id"]] >= 2]
        if objects:
            kept_frames.append(dict(f, objects=objects))
    out: dict = {"format": "vei-clip/1", "id": clip_id}
    recorded = _shift_datetime(doc.get("recorded_at"), float(samples[0]["t"]) - float(clip.ego.t[0]))
    if recorded is not None:
        out["recorded_at"] = recorded
    out["ego"] = dict(doc["ego"], samples=samples)
    out["annotations"] = dict(ann, frames=kept_frames)
    if "map" in doc:
        out["map"] = dict(doc["map"])
        if "osm" in doc["map"] and clip.osm_path is not None:  # (relative to the clip: re-anchored)
            out["map"]["osm"] = Path(os.path.relpath(clip.osm_path, out_dir.resolve())).as_posix()
    out["extensions"] = dict(doc.get("extensions") or {}, vei_split=dict(provenance, dropped_tracks=dropped))
    return out, dropped


def split_drive(
    source: str | Path,
    out_dir: str | Path,
    opts: SplitOptions | None = None,
    to: str = "vei-clip",
    frame_rate_hz: float | None = None,
    time_unit: str | None = None,
) -> SplitResult:
    """Cut ``source`` into interaction clips written into ``out_dir`` (``to``: ``vei-clip`` or
    ``openlabel``), all or none. Every clip is checked as a clip before anything is written."""
    from vei_scenario.atomic_io import OutputSet

    opts = opts or SplitOptions()
    opts.check()
    if to not in ("vei-clip", "openlabel"):
        raise VeiInputError(None, "--to", f"{to!r} is not vei-clip or openlabel")
    source, out_dir = Path(source), Path(out_dir)
    clip, doc = load_drive(source, frame_rate_hz, time_unit)
    parts = find_interactions(clip, opts)
    digest = hashlib.sha256(source.read_bytes()).hexdigest()
    width = max(3, len(str(len(parts))))
    outputs = OutputSet()
    t0 = float(clip.ego.t[0])
    rules = {k: (list(v) if isinstance(v, tuple) else v) for k, v in asdict(opts).items()}
    for k, part in enumerate(parts, 1):
        clip_id = f"{clip.id}.{k:0{width}d}"
        provenance = {
            "source": source.name,
            "source_sha256": digest,
            "source_id": clip.id,
            "t_gps": [round(part.t_start, 6), round(part.t_end, 6)],
            "t_from_source_start_s": [round(part.t_start - t0, 6), round(part.t_end - t0, 6)],
            "tracks": list(part.tracks),
            "closest_to_ego_path_m": round(part.closest_m, 3),
            "rules": rules,
        }
        piece, _ = clip_document(doc, clip, part, clip_id, out_dir, provenance)
        path = out_dir / f"{clip_id}.json"
        clip_from_document(path, piece, require_scooter=False)  # (a bug, not the user's, if this refuses)
        if to == "openlabel":
            from vei_scenario.clip.openlabel import clip_document_to_openlabel, validate_openlabel

            first = piece["ego"]["samples"][0]
            proj = local_tmerc(float(first["lat"]), float(first["lon"]))
            piece = json.loads(json.dumps(clip_document_to_openlabel(piece, proj), allow_nan=False))
            validate_openlabel(path, piece)
        outputs.add(path, json.dumps(piece, indent=1, allow_nan=False) + "\n")
    outputs.commit()
    return SplitResult(source, t0, float(clip.ego.t[-1]) - t0, parts, outputs.paths)
