"""ASAM OpenLABEL 1.0 clips: read an annotation into a :class:`~vei_scenario.clip.model.Clip`, and
write a ``vei-clip/1`` document as OpenLABEL.

Why: recordings are annotated in OpenLABEL (frames; objects with cuboids in a coordinate system; the
ego's odometry as per-frame transforms), so vei must take such a file as it is. The file is validated
against the OpenLABEL 1.0 JSON Schema and loaded with the VCD library (Vicomtech's OpenLABEL
implementation, ``vcd``); what vei needs is then read following the standard's conventions:

* **Ego frame** ``E``: the coordinate system named ``vehicle-iso8855`` (ISO 8855: x forward, y left,
  z up), else the local coordinate system that the per-frame odometry transforms connect to a scene
  (``scene_cs``) or geographic frame ``W``.
* **Ego odometry**: per frame, a transform between ``E`` and ``W`` (``frame_properties.transforms``,
  either direction; ``matrix4x4``, ``quaternion`` + ``translation`` or ``euler_angles`` +
  ``translation``). Its translation is the ego position in ``W``, its rotation the ego's yaw. ``W`` is
  placed on earth by a PROJ string in its ``geo_reference.proj`` (as OpenDRIVE's ``geoReference``) or
  an origin ``geo_reference.lat_deg``/``lon_deg`` (a local transverse Mercator there); without one it
  is a local frame placed at 0°N 0°E (fine without a map). A transform may also carry the exact fix
  as ``gnss: {lat_deg, lon_deg, heading_deg, speed_mps}`` (vei writes it so that a round trip is
  exact); otherwise heading and speed follow from the poses (``W`` is taken as east-north-up).
* **Times**: ``frame_properties.timestamp`` of every frame used (else its first stream's
  ``sync.timestamp``), in seconds (a number) or ISO 8601 (UTC when no zone is given). A file with no
  timestamps at all (the KITTI conversions of the VCD library have none) is read at a frame rate the
  user gives (``frame_rate_hz``, ``--frame-rate``): frame ``k`` at ``k / rate`` s.
* **Objects**: ``type`` is the class (e-scooter in any common spelling: ``e-scooter``, ``EScooter``,
  ``kick_scooter`` ...; other classes are read and then skipped by the compiler as in vei-clip),
  ``name`` the track id; each frame's first ``cuboid`` gives the centre. A cuboid in a child of ``E``
  is carried into ``E`` through the ``pose_wrt_parent`` chain; a cuboid in ``W`` through the frame's
  odometry. An e-scooter without any cuboid is refused.

Every problem is one :class:`VeiInputError` naming the path in the JSON
(``openlabel.frames.12.objects.3.object_data.cuboid[0].coordinate_system``).
"""

from __future__ import annotations

import copy
import functools
import math
import re
from datetime import datetime
from pathlib import Path
from typing import Any

import numpy as np

from vei_scenario.clip.loader import clip_from_document, read_json
from vei_scenario.clip.model import local_tmerc
from vei_scenario.errors import VeiInputError

EGO_FRAME = "vehicle-iso8855"
WORLD_FRAME = "odom"
#: A frame whose y axis points right (z down, SAE J670): the annotation convention y_axis = "right".
Y_RIGHT_FRAME = "vehicle-sae-j670"
#: Rotation of 180° about x (quaternion x, y, z, w): SAE J670 axes in ISO 8855 axes.
Y_FLIP_QUATERNION = [1.0, 0.0, 0.0, 0.0]
#: Object classes (lower case, letters and digits only) read as e-scooters.
SCOOTER_CLASSES = frozenset(
    {"escooter", "scooter", "standupscooter", "kickscooter", "electricscooter", "estepp", "emicromobility"}
)
SCOOTER_CATEGORY = "e-scooter"
#: Box written for an annotated scooter (the vei-clip format has no size): vei's e-scooter box (m).
SCOOTER_BOX_M = (1.2, 0.6, 1.9)
_TRACK_ID = re.compile(r"^[A-Za-z_][A-Za-z0-9_.-]*$")


def _err(path: Path, where: str, reason: str) -> VeiInputError:
    return VeiInputError(path, where, reason)


def _json_path(parts) -> str:
    out = ""
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out or "(top level)"


@functools.cache
def _typed_schema() -> dict:
    """The OpenLABEL 1.0 schema with the types it implies spelled out: a definition with properties is
    an object, one with items an array. (The schema leaves many out, so that a coordinate system or a
    transform written as a number passes it; the reader would then fail on it somewhere inside.)"""
    from vcd import schema

    def typed(node):
        if isinstance(node, list):
            return [typed(n) for n in node]
        if not isinstance(node, dict):
            return node
        out = {k: typed(v) for k, v in node.items()}
        if "type" not in out and "$ref" not in out:
            if {"properties", "patternProperties", "additionalProperties", "required"} & set(out):
                out["type"] = "object"
            elif "items" in out:
                out["type"] = "array"
        return out

    return typed(schema.openlabel_schema)


def validate_openlabel(path: Path, doc: Any) -> None:
    """Check ``doc`` against the OpenLABEL 1.0 JSON Schema (the VCD library's copy of it)."""
    import jsonschema
    from vcd import schema

    if not isinstance(doc.get("openlabel"), dict):
        raise _err(path, "openlabel", "not an object")
    version = (doc["openlabel"].get("metadata") or {}).get("schema_version")
    if version != schema.openlabel_schema_version:
        raise _err(path, "openlabel.metadata.schema_version", f"{version!r}: only OpenLABEL 1.0.0 is supported")
    validator = jsonschema.Draft7Validator(_typed_schema())
    errors = list(validator.iter_errors(doc))
    if errors:
        err = jsonschema.exceptions.best_match(errors)
        raise _err(path, _json_path(err.absolute_path), f"not valid OpenLABEL 1.0: {err.message[:300]}")


# --- transforms ---------------------------------------------------------------------------------------


def _matrix(path: Path, where: str, data: Any) -> np.ndarray:
    """A 4x4 homogeneous matrix from OpenLABEL transform data (X_dst = M X_src)."""
    from scipy.spatial.transform import Rotation

    def numbers(key: str, n: int) -> list[float]:
        vals = data.get(key)
        if not isinstance(vals, list) or len(vals) != n:
            raise _err(path, f"{where}.{key}", f"expected {n} numbers")
        out = []
        for i, v in enumerate(vals):
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise _err(path, f"{where}.{key}[{i}]", "not a finite number")
            out.append(float(v))
        return out

    if not isinstance(data, dict):
        raise _err(path, where, "transform data is not an object")
    m = np.eye(4)
    if "matrix4x4" in data:
        m = np.array(numbers("matrix4x4", 16)).reshape(4, 4)
        if not np.allclose(m[3], [0, 0, 0, 1]):
            raise _err(path, f"{where}.matrix4x4", "the last row of a homogeneous transform must be 0 0 0 1")
        return m
    if "quaternion" in data:
        q = numbers("quaternion", 4)
        if math.hypot(*q) < 1e-9:
            raise _err(path, f"{where}.quaternion", "a zero quaternion is no rotation")
        m[:3, :3] = _quaternion_matrix(q)
    elif "euler_angles" in data:
        seq = data.get("sequence", "ZYX")
        if not isinstance(seq, str) or len(seq) != 3 or set(seq.upper()) - set("XYZ"):
            raise _err(path, f"{where}.sequence", f"{seq!r} is not an Euler sequence such as ZYX")
        m[:3, :3] = Rotation.from_euler(seq.upper(), numbers("euler_angles", 3)).as_matrix()
    else:
        raise _err(path, where, "no matrix4x4, quaternion or euler_angles")
    m[:3, 3] = numbers("translation", 3)
    return m


def _quaternion_matrix(q: list[float]) -> np.ndarray:
    """Rotation matrix of a quaternion (x, y, z, w); exact for the axis-aligned ones vei writes."""
    x, y, z, w = q
    n = x * x + y * y + z * z + w * w
    if n != 1.0:
        s = 1.0 / math.sqrt(n)
        x, y, z, w = x * s, y * s, z * s, w * s
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def _stamp(k: int, frame: dict) -> tuple[str, Any] | None:
    """Where a frame's timestamp is written and its value: ``frame_properties.timestamp``, else its
    first stream's sync (``frame_properties.streams.NAME.sync.timestamp``); None when it has none."""
    props = frame.get("frame_properties") or {}
    if not isinstance(props, dict):
        return None
    if "timestamp" in props:
        return f"openlabel.frames.{k}.frame_properties.timestamp", props["timestamp"]
    streams = props.get("streams") or {}
    for name, stream in sorted(streams.items() if isinstance(streams, dict) else ()):
        sync = stream.get("sync") if isinstance(stream, dict) else None
        if isinstance(sync, dict) and "timestamp" in sync:
            return f"openlabel.frames.{k}.frame_properties.streams.{name}.sync.timestamp", sync["timestamp"]
    return None


def _frame_time(path: Path, k: int, frame: dict, unit_s: float = 1.0) -> float:
    """A frame's time (:func:`_stamp`), in seconds (``unit_s``: the unit of a timestamp written as a
    number, in seconds)."""
    where, value = _stamp(k, frame) or (f"openlabel.frames.{k}.frame_properties.timestamp", None)
    return _timestamp(path, where, value, unit_s)


def _timestamp(path: Path, where: str, value: Any, unit_s: float = 1.0) -> float:
    if isinstance(value, bool):
        raise _err(path, where, "a timestamp is seconds (a number) or ISO 8601 text, not a boolean")
    if isinstance(value, (int, float)):
        if not math.isfinite(value):
            raise _err(path, where, "not a finite number")
        return float(value) * unit_s
    if isinstance(value, str):
        text = value.strip()
        try:
            number = float(text)
        except ValueError:
            pass
        else:
            if not math.isfinite(number):
                raise _err(path, where, "not a finite number")
            return number * unit_s
        try:
            stamp = datetime.fromisoformat(text.replace("Z", "+00:00"))
        except ValueError:
            raise _err(path, where, f"{value!r} is neither seconds nor an ISO 8601 time") from None
        if stamp.tzinfo is None:  # (annotation tools often leave it out: taken as UTC, as GNSS time is)
            from datetime import timezone

            stamp = stamp.replace(tzinfo=timezone.utc)
        return stamp.timestamp()
    raise _err(
        path,
        where,
        "missing: every frame used needs frame_properties.timestamp (s or ISO 8601); for a clip without any "
        "timestamps, give its frame rate (--frame-rate HZ)",
    )


#: The frame rates a clip without timestamps may be read at (Hz).
FRAME_RATE_RANGE_HZ = (0.01, 10_000.0)
#: The units a timestamp written as a number may be in (``--time-unit``), in seconds: recorders write
#: seconds, milliseconds, microseconds (nuScenes) or nanoseconds (ROS) since an epoch.
TIME_UNITS_S = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "ns": 1e-9}


def refuse_clock_options(path: Path, frame_rate_hz: float | None, time_unit: str | None = None) -> None:
    """A vei-clip carries the time of every sample and annotation frame, in seconds: a frame rate or a
    unit of time has no place."""
    if frame_rate_hz is not None:
        raise _err(path, "--frame-rate", "a vei-clip has its own times (every sample's t): a frame rate is "
                   "only for OpenLABEL clips without timestamps")  # fmt: skip
    if time_unit is not None:
        raise _err(path, "--time-unit", "a vei-clip's times are seconds: a unit is only for OpenLABEL timestamps")


def _clock(path: Path, frames: dict[int, dict], frame_rate_hz: float | None, time_unit: str | None = None):
    """How a frame's time is read: its timestamps (numbers in ``time_unit``, seconds by default), or,
    for a file without any, its number at ``frame_rate_hz``. A rate given for a file that has
    timestamps is refused (which would count?), and so is a unit for a file without them."""
    if time_unit is not None and time_unit not in TIME_UNITS_S:
        raise _err(path, "--time-unit", f"{time_unit!r} is not one of {', '.join(TIME_UNITS_S)}")
    if time_unit is not None and frame_rate_hz is not None:
        raise _err(path, "--time-unit", "a unit of timestamps and a frame rate exclude each other")
    if frame_rate_hz is None:
        unit_s = TIME_UNITS_S[time_unit or "s"]
        return lambda k, frame: _frame_time(path, k, frame, unit_s)
    lo, hi = FRAME_RATE_RANGE_HZ
    if isinstance(frame_rate_hz, bool) or not isinstance(frame_rate_hz, (int, float)) or not lo <= frame_rate_hz <= hi:
        raise _err(path, "--frame-rate", f"{frame_rate_hz!r} is not a frame rate in {lo:g}..{hi:g} Hz")
    stamped = next((k for k, f in frames.items() if _stamp(k, f) is not None), None)
    if stamped is not None:
        raise _err(
            path,
            "--frame-rate",
            f"the clip has timestamps (openlabel.frames.{stamped}.frame_properties): "
            "a frame rate is only for clips without any",
        )
    return lambda k, frame: k / float(frame_rate_hz)


# --- reading ------------------------------------------------------------------------------------------


class _Frames:
    """The coordinate systems of a document: which is the ego's and the world's, and the static poses."""

    def __init__(self, path: Path, ol: dict) -> None:
        self.path = path
        self.systems: dict[str, dict] = ol.get("coordinate_systems") or {}
        self.ego = self.world = None
        self._static: dict[str, np.ndarray] = {}

    def kind(self, name: str) -> str:
        return str(self.systems.get(name, {}).get("type", ""))

    def find_ego(self, frames: dict) -> None:
        """Choose E and W from the names, the types and the per-frame transforms."""
        pairs: dict[tuple[str, str], int] = {}
        for f in frames.values():
            for t in ((f.get("frame_properties") or {}).get("transforms") or {}).values():
                a, b = t.get("src"), t.get("dst")
                if a in self.systems and b in self.systems:
                    pairs[(a, b)] = pairs.get((a, b), 0) + 1
        candidates = []
        for (a, b), n in pairs.items():
            for local, world in ((a, b), (b, a)):
                scene = self.kind(world) in ("scene_cs", "geo_utm") or world == WORLD_FRAME
                parent = (self.systems.get(local) or {}).get("parent") == world  # (types left out)
                if (scene or parent) and self.kind(local) not in ("scene_cs", "geo_utm", "geo_wgs84"):
                    candidates.append((local == EGO_FRAME, n, local, world))
        if EGO_FRAME in self.systems:
            mine = [c for c in candidates if c[2] == EGO_FRAME]
            if mine:
                candidates = mine
        if not candidates:
            if not self.systems:
                raise _err(self.path, "openlabel.coordinate_systems", "missing: no coordinate systems, so no ego frame")
            raise _err(
                self.path,
                "openlabel.frames",
                "no ego odometry: no frame has a transform between the ego's coordinate system (e.g. "
                f"{EGO_FRAME}, local_cs) and a scene_cs such as {WORLD_FRAME}",
            )
        _, _, self.ego, self.world = max(candidates)

    def to_ego(self, name: str, where: str) -> np.ndarray | None:
        """Static matrix from coordinate system ``name`` to E (None when ``name`` is not E or below it)."""
        if name in self._static:
            return self._static[name]
        if name not in self.systems:
            raise _err(self.path, where, f"unknown coordinate system {name!r} (not in openlabel.coordinate_systems)")
        m, cur, seen = np.eye(4), name, set()
        while cur != self.ego:
            if cur in seen:
                raise _err(self.path, f"openlabel.coordinate_systems.{cur}.parent", "the parents form a cycle")
            seen.add(cur)
            cs = self.systems.get(cur)
            if cs is None:
                raise _err(self.path, where, f"unknown coordinate system {cur!r}")
            parent = cs.get("parent") or ""
            if not parent:
                return None  # not below the ego frame (the world, or another tree)
            if "pose_wrt_parent" not in cs:
                raise _err(
                    self.path,
                    f"openlabel.coordinate_systems.{cur}.pose_wrt_parent",
                    f"missing: the pose of {cur!r} in its parent {parent!r} is needed to place its cuboids",
                )
            m = _matrix(self.path, f"openlabel.coordinate_systems.{cur}.pose_wrt_parent", cs["pose_wrt_parent"]) @ m
            cur = parent
        self._static[name] = m
        return m


def _geo(path: Path, world: dict):
    """(lat, lon) of world-frame points, from its ``geo_reference`` (None: a local frame at 0°N 0°E)."""
    import pyproj

    geo = world.get("geo_reference") if isinstance(world, dict) else None
    if isinstance(geo, dict) and isinstance(geo.get("proj"), str):
        proj = geo["proj"]
    elif isinstance(geo, dict) and {"lat_deg", "lon_deg"} <= set(geo):
        lat, lon = geo["lat_deg"], geo["lon_deg"]
        if not all(isinstance(v, (int, float)) and math.isfinite(v) for v in (lat, lon)) or abs(lat) > 90:
            raise _err(path, "openlabel.coordinate_systems.geo_reference", "lat_deg/lon_deg are not a place on earth")
        proj = f"+proj=tmerc +lat_0={lat} +lon_0={lon} +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m +no_defs"
    else:
        proj = "+proj=tmerc +lat_0=0 +lon_0=0 +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m +no_defs"
    try:
        to_geo = pyproj.Transformer.from_crs(pyproj.CRS.from_user_input(proj), "EPSG:4326", always_xy=True)
    except pyproj.exceptions.CRSError as exc:
        raise _err(path, "openlabel.coordinate_systems.geo_reference.proj", f"not a PROJ string: {exc}") from None
    return to_geo


#: Words of a class name (camel case, separators, digits apart): ``VRU/EScooterRider`` -> vru e scooter rider.
_CLASS_WORDS = re.compile(r"[A-Z]+(?=[A-Z][a-z])|[A-Z]?[a-z]+|[A-Z]+|[0-9]+")
#: Words that make a bare "scooter" something else: a motor scooter, a moped, a mobility scooter.
_NOT_E_SCOOTER = frozenset({"motor", "motorcycle", "motorbike", "moped", "mobility", "vespa", "gas", "petrol"})


def scooter_class(kind: str) -> bool:
    """Whether an object class names an e-scooter (or its rider), as annotation tools and datasets
    spell it: the class alone (``EScooter``, ``kick_scooter``) or within a longer name
    (``e_scooter_rider``, ``vru.e-scooter``, ``Rider on KickScooter``), and nuScenes' personal mobility
    (``human.pedestrian.personal_mobility``: e-scooters, segways, skateboards). A bare "scooter" is one
    unless the name says motor, moped or mobility."""
    if re.sub(r"[^a-z0-9]", "", kind.lower()) in SCOOTER_CLASSES:
        return True
    words = [w.lower() for w in _CLASS_WORDS.findall(kind)]
    joined = {"".join(words[i : i + n]) for n in (1, 2, 3) for i in range(len(words) - n + 1)}
    if "personalmobility" in joined:
        return True
    if joined & (SCOOTER_CLASSES - {"scooter"}):
        return True
    return "scooter" in words and not _NOT_E_SCOOTER & set(words)


def openlabel_to_clip_document(
    path: Path, doc: dict, frame_rate_hz: float | None = None, time_unit: str | None = None
) -> tuple[dict, dict[str, str]]:
    """The ``vei-clip/1`` document an OpenLABEL annotation stands for, and a map from its field paths
    (``ego.samples[3]``) to the OpenLABEL paths they came from (for error messages);
    ``frame_rate_hz``: the frame rate of a file without timestamps; ``time_unit``: the unit of its
    timestamps written as numbers (``TIME_UNITS_S``; seconds by default)."""
    from vcd import core

    validate_openlabel(path, doc)
    vcd = core.VCD()
    vcd.load_from_json(copy.deepcopy(doc), validation=False)  # validated above (with paths); it edits what it gets
    ol = vcd.data["openlabel"]
    frames: dict[int, dict] = dict(sorted((int(k), v) for k, v in (ol.get("frames") or {}).items()))
    if not frames:
        raise _err(path, "openlabel.frames", "missing: an annotation needs frames")
    frame_time_of = _clock(path, frames, frame_rate_hz, time_unit)
    cs = _Frames(path, ol)
    cs.find_ego(frames)
    to_geo = _geo(path, cs.systems.get(cs.world, {}))
    meta = ol.get("metadata") or {}

    # the ego: every frame with an odometry transform
    ego_t, ego_pose, ego_gnss, sources = [], [], [], []
    frame_time: dict[int, float] = {}
    for k, f in frames.items():
        props = f.get("frame_properties") or {}
        for name, tr in (props.get("transforms") or {}).items():
            if {tr.get("src"), tr.get("dst")} != {cs.ego, cs.world}:
                continue
            where = f"openlabel.frames.{k}.frame_properties.transforms.{name}"
            m = _matrix(path, f"{where}.transform_src_to_dst", tr.get("transform_src_to_dst"))
            if tr.get("src") == cs.world:
                m = np.linalg.inv(m)
            frame_time[k] = frame_time_of(k, f)
            ego_t.append(frame_time[k])
            ego_pose.append(m)
            gnss = tr.get("gnss")
            ego_gnss.append(gnss if isinstance(gnss, dict) else None)
            sources.append(where)
            break
    if len(ego_t) < 2:
        raise _err(path, "openlabel.frames", f"ego odometry in {len(ego_t)} frame(s); at least 2 are needed")
    order = np.argsort(np.array(ego_t), kind="stable")
    samples, paths = [], {}
    xs = np.array([ego_pose[i][0, 3] for i in order])
    ys = np.array([ego_pose[i][1, 3] for i in order])
    ts = np.array([ego_t[i] for i in order])
    if np.any(np.diff(ts) <= 0):
        j = int(np.nonzero(np.diff(ts) <= 0)[0][0]) + 1
        raise _err(path, sources[order[j]], f"ego odometry times must increase ({ts[j]!r} after {ts[j - 1]!r})")
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # (odd times or places: refused below,
        speed = np.hypot(np.gradient(xs, ts), np.gradient(ys, ts))  # naming the fix, not by numpy's warning)
    lon, lat = to_geo.transform(xs, ys)
    for n, i in enumerate(order):
        m, g = ego_pose[i], ego_gnss[i]
        yaw = math.degrees(math.atan2(m[1, 0], m[0, 0]))
        sample = {
            "t": float(ego_t[i]),
            "lat": float(lat[n]),
            "lon": float(lon[n]),
            "heading_deg": round((90.0 - yaw) % 360.0, 9),
            "speed_mps": float(speed[n]),
        }
        if g is not None:
            for key, field in (("lat_deg", "lat"), ("lon_deg", "lon"), ("heading_deg", "heading_deg")):
                if key in g:
                    sample[field] = g[key]
            if "speed_mps" in g:
                sample["speed_mps"] = g["speed_mps"]
        samples.append(sample)
        paths[f"ego.samples[{n}]"] = sources[i]
    ego_pose_at = {k: ego_pose[list(frame_time).index(k)] for k in frame_time}

    # the annotated objects
    objects: dict[str, dict] = ol.get("objects") or {}
    names: dict[str, str] = {}
    for uid, obj in objects.items():
        raw = str(obj.get("name") or "")
        tid = raw if _TRACK_ID.match(raw) else re.sub(r"[^A-Za-z0-9_.-]", "_", f"{obj.get('type', 'object')}_{uid}")
        if not _TRACK_ID.match(tid):
            tid = f"object_{uid}"
        if tid in names.values():
            tid = f"{tid}_{uid}"
        names[uid] = tid
    ann_frames, seen_cuboid = [], set()
    for k, f in frames.items():
        objs = []
        for uid, od in (f.get("objects") or {}).items():
            if uid not in objects:
                raise _err(path, f"openlabel.frames.{k}.objects.{uid}", "no such object in openlabel.objects")
            cuboids = (od.get("object_data") or {}).get("cuboid") or []
            if not cuboids:
                continue
            where = f"openlabel.frames.{k}.objects.{uid}.object_data.cuboid[0]"
            val = cuboids[0].get("val")
            if not isinstance(val, list) or len(val) not in (9, 10):
                raise _err(path, f"{where}.val", "a cuboid has 9 or 10 values")
            if not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in val):
                raise _err(path, f"{where}.val", "not finite numbers")
            system = cuboids[0].get("coordinate_system") or objects[uid].get("coordinate_system") or cs.ego
            m = cs.to_ego(system, f"{where}.coordinate_system")
            if m is None:  # in the world frame (or above the ego): through this frame's odometry
                if system != cs.world:
                    raise _err(path, f"{where}.coordinate_system", f"{system!r} is not related to {cs.ego!r}")
                if k not in ego_pose_at:
                    raise _err(path, where, f"a cuboid in {system!r} needs the ego's odometry in frame {k}")
                m = np.linalg.inv(ego_pose_at[k])
            p = m @ np.array([val[0], val[1], val[2], 1.0])
            kind = str(objects[uid].get("type", ""))
            category = SCOOTER_CATEGORY if scooter_class(kind) else kind or "unknown"
            objs.append({"track_id": names[uid], "category": category, "x_m": float(p[0]), "y_m": float(p[1])})
            seen_cuboid.add(uid)
        if objs:
            t = frame_time_of(k, f)
            paths[f"annotations.frames[{len(ann_frames)}]"] = f"openlabel.frames.{k}"
            ann_frames.append({"t": t, "objects": objs})
    for uid, obj in objects.items():
        if scooter_class(str(obj.get("type", ""))) and uid not in seen_cuboid:
            raise _err(
                path, f"openlabel.objects.{uid}", f"e-scooter {obj.get('name', uid)!r} has no cuboid in any frame"
            )
    if not ann_frames:
        raise _err(path, "openlabel.frames", "no object has a cuboid in any frame")
    paths["annotations.frames"] = "openlabel.objects"  # (a check over all tracks: which classes there are)
    ann_frames.sort(key=lambda fr: fr["t"])

    clip_id = str(meta.get("name") or path.stem)
    if not re.match(r"^[A-Za-z0-9_.-]+$", clip_id):
        clip_id = re.sub(r"[^A-Za-z0-9_.-]", "_", clip_id) or "openlabel"
    out: dict = {"format": "vei-clip/1", "id": clip_id}
    if isinstance(meta.get("recorded_at"), str):
        out["recorded_at"] = meta["recorded_at"]
    ego: dict = {"samples": samples}
    dims = cs.systems.get(cs.ego, {}).get("vehicle_dimensions")
    if isinstance(dims, dict):
        ego.update({k: dims[k] for k in ("length_m", "width_m") if k in dims})
    out["ego"] = ego
    out["annotations"] = {"time_offset_s": 0.0, "y_axis": "left", "frames": ann_frames}
    vei = meta.get("vei_clip")
    if isinstance(vei, dict):
        if isinstance(vei.get("map"), dict):
            out["map"] = vei["map"]
        if isinstance(vei.get("annotations"), dict):  # the original annotation frame (exact round trip)
            out["annotations"].update({k: vei["annotations"][k] for k in ("y_axis",) if k in vei["annotations"]})
            if out["annotations"]["y_axis"] == "right":
                for fr in ann_frames:
                    for o in fr["objects"]:
                        o["y_m"] = -o["y_m"]
        if isinstance(vei.get("extensions"), dict):
            out["extensions"] = vei["extensions"]
    return out, paths


def clip_from_openlabel(path: Path, doc: dict, frame_rate_hz: float | None = None, time_unit: str | None = None):
    """A :class:`~vei_scenario.clip.model.Clip` from an OpenLABEL document: converted, then checked as
    a vei-clip (times, spans, tracks), errors naming the OpenLABEL paths; ``frame_rate_hz``: the frame
    rate of a file without timestamps; ``time_unit``: the unit of timestamps written as numbers."""
    clip_doc, paths = openlabel_to_clip_document(path, doc, frame_rate_hz, time_unit)
    return _checked_clip(path, doc, clip_doc, paths, time_unit, frame_rate_hz)


def _checked_clip(
    path: Path,
    doc: dict,
    clip_doc: dict,
    paths: dict[str, str],
    time_unit: str | None,
    frame_rate_hz: float | None,
    **limits,
):
    """The vei-clip ``clip_doc`` converted from OpenLABEL ``doc`` checked as a clip, errors naming the
    OpenLABEL paths (``paths``) and said in OpenLABEL's terms; ``limits``: those of
    :func:`~vei_scenario.clip.loader.clip_from_document`."""
    try:
        return clip_from_document(path, clip_doc, **limits)
    except VeiInputError as exc:
        where = exc.where
        for prefix in sorted(paths, key=len, reverse=True):
            if where.startswith(prefix):
                where = paths[prefix] + f" ({where})"
                break
        reason = exc.reason
        if reason.startswith("no e-scooter track"):  # (say it in OpenLABEL's terms: the classes it has)
            found = sorted({str(o.get("type", "")) for o in (doc["openlabel"].get("objects") or {}).values()})
            reason = f"no object class names an e-scooter (classes: {', '.join(repr(k) for k in found)})"
        if "a clip spans at most" in reason and time_unit is None and frame_rate_hz is None:
            reason += " (timestamps written as numbers are read as seconds: --time-unit ms, us or ns for others)"
        raise VeiInputError(exc.file, where, reason) from None


# --- writing ------------------------------------------------------------------------------------------


def clip_document_to_openlabel(doc: dict, proj_string: str) -> dict:
    """An OpenLABEL 1.0 document for a ``vei-clip/1`` document (checked before): the ego odometry as
    ``vehicle-iso8855`` → ``odom`` transforms (``odom``: the local transverse Mercator
    ``proj_string``, carried as its ``geo_reference``; each transform also carries the exact fix as
    ``gnss``), the annotations as cuboids in ``vehicle-iso8855`` or, for ``y_axis: "right"``, in
    ``vehicle-sae-j670`` (y right, z down), on one clock (the GPS clock)."""
    import pyproj
    from vcd import core, types

    vcd = core.VCD()
    vcd.add_name(doc["id"])
    vcd.add_annotator("vei-scenario (vei clip convert)")
    extra: dict = {}
    if "recorded_at" in doc:
        extra["recorded_at"] = doc["recorded_at"]
    ann = doc["annotations"]
    y_right = ann.get("y_axis", "right") == "right"
    vei = {"format": "vei-clip/1", "annotations": {"y_axis": "right" if y_right else "left"}}
    if "map" in doc:
        vei["map"] = doc["map"]
    if "extensions" in doc:
        vei["extensions"] = doc["extensions"]
    extra["vei_clip"] = vei
    vcd.add_metadata_properties(extra)
    vcd.add_coordinate_system(WORLD_FRAME, types.CoordinateSystemType.scene_cs)
    vcd.add_coordinate_system(EGO_FRAME, types.CoordinateSystemType.local_cs, parent_name=WORLD_FRAME)
    systems = vcd.data["openlabel"]["coordinate_systems"]
    systems[WORLD_FRAME]["geo_reference"] = {"proj": proj_string}
    ego = doc["ego"]
    systems[EGO_FRAME]["vehicle_dimensions"] = {k: ego[k] for k in ("length_m", "width_m") if k in ego}
    annotation_cs = EGO_FRAME
    if y_right:
        annotation_cs = Y_RIGHT_FRAME
        vcd.add_coordinate_system(
            Y_RIGHT_FRAME,
            types.CoordinateSystemType.local_cs,
            parent_name=EGO_FRAME,
            pose_wrt_parent=types.PoseData(
                Y_FLIP_QUATERNION + [0.0, 0.0, 0.0], types.TransformDataType.quat_and_trans_7x1
            ),
        )
    to_xy = pyproj.Transformer.from_crs("EPSG:4326", pyproj.CRS.from_user_input(proj_string), always_xy=True)
    offset = float(ann.get("time_offset_s", 0.0))
    times = sorted({float(s["t"]) for s in ego["samples"]} | {float(f["t"]) + offset for f in ann["frames"]})
    index = {t: k for k, t in enumerate(times)}
    for s in ego["samples"]:
        k = index[float(s["t"])]
        x, y = to_xy.transform(s["lon"], s["lat"])
        yaw = math.radians(90.0 - s["heading_deg"])
        q = [0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)]
        transform = types.Transform(
            EGO_FRAME,
            WORLD_FRAME,
            types.TransformData(q + [float(x), float(y), 0.0], types.TransformDataType.quat_and_trans_7x1),
            gnss={
                "lat_deg": s["lat"],
                "lon_deg": s["lon"],
                "heading_deg": s["heading_deg"],
                "speed_mps": s["speed_mps"],
            },
        )
        vcd.add_transform(k, transform)
    uids: dict[str, int] = {}
    for f in ann["frames"]:
        k = index[float(f["t"]) + offset]
        for o in f["objects"]:
            tid = o["track_id"]
            if tid not in uids:
                uids[tid] = int(vcd.add_object(tid, o["category"]))
            box = [o["x_m"], o["y_m"], 0.0, 0.0, 0.0, 0.0, 1.0, *SCOOTER_BOX_M]
            vcd.add_object_data(uids[tid], types.cuboid("box", box, annotation_cs), frame_value=k)
    for t, k in index.items():
        vcd.add_frame_properties(k, timestamp=t)
    return vcd.data


def convert_clip(
    src: str | Path,
    dst: str | Path,
    to: str | None = None,
    frame_rate_hz: float | None = None,
    time_unit: str | None = None,
) -> tuple[Path, str]:
    """Convert a clip file between ``vei-clip/1`` and OpenLABEL 1.0 (``to``: ``openlabel`` or
    ``vei-clip``; by default the other format). Both are validated; the output is written atomically.
    ``frame_rate_hz``, ``time_unit``: the frame rate of an OpenLABEL file without timestamps, the unit
    of one's timestamps written as numbers. Returns the path written and its format."""
    import json

    from vei_scenario.atomic_io import write_bytes_atomic

    src, dst = Path(src), Path(dst)
    if dst.exists() and src.exists() and dst.resolve() == src.resolve():
        raise VeiInputError(dst, "-o", "is the input clip: write the converted clip to another file")
    doc = read_json(src)
    is_openlabel = isinstance(doc, dict) and "openlabel" in doc
    to = to or ("vei-clip" if is_openlabel else "openlabel")
    if to not in ("openlabel", "vei-clip"):
        raise VeiInputError(None, "--to", f"{to!r} is not openlabel or vei-clip")
    if is_openlabel:
        clip_doc, paths = openlabel_to_clip_document(src, doc, frame_rate_hz, time_unit)
        clip = _checked_clip(src, doc, clip_doc, paths, time_unit, frame_rate_hz)
    else:
        refuse_clock_options(src, frame_rate_hz, time_unit)
        clip_doc = doc
        clip = clip_from_document(src, doc)
    if to == "vei-clip":
        if "map" in clip_doc and "osm" in clip_doc["map"] and clip.osm_path is not None:
            # keep the map reachable from the new place (the reference is relative to the clip)
            import os

            clip_doc["map"] = dict(clip_doc["map"], osm=os.path.relpath(clip.osm_path, dst.resolve().parent))
        out = clip_doc
    else:
        if "map" in clip_doc and "osm" in clip_doc["map"] and clip.osm_path is not None:
            import os

            clip_doc = dict(
                clip_doc, map=dict(clip_doc["map"], osm=os.path.relpath(clip.osm_path, dst.resolve().parent))
            )
        proj = local_tmerc(float(clip.ego.lat[0]), float(clip.ego.lon[0]))
        # as JSON has it (string frame keys), checked against the schema before it is written
        out = json.loads(json.dumps(clip_document_to_openlabel(clip_doc, proj), allow_nan=False))
        validate_openlabel(dst, out)
    write_bytes_atomic(dst, (json.dumps(out, indent=1, allow_nan=False) + "\n").encode("utf-8"))
    return dst, to
