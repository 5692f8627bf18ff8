"""Load and check a ``vei-clip/1`` file.

Two layers: the JSON Schema (``schemas/clip.schema.json``) pins types, ranges and allowed fields; the
checks here pin what a schema cannot say (strictly increasing times, annotations inside the GPS time
span, tracks that are not empty). Every failure is one :class:`VeiInputError` naming the field.
"""

from __future__ import annotations

import json
import math
import re
import sys
from functools import lru_cache
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from vei_scenario.clip.model import (
    DEFAULT_EGO_LENGTH_M,
    DEFAULT_EGO_WIDTH_M,
    SCOOTER_CATEGORIES,
    Annotations,
    Clip,
    EgoTrack,
    Observation,
)
from vei_scenario.errors import VeiInputError


@lru_cache(maxsize=1)
def clip_schema() -> dict:
    text = resources.files("vei_scenario").joinpath("data/clip.schema.json").read_text("utf-8")
    return json.loads(text)


class _NonJsonConstant(ValueError):
    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.name = name


def _reject_constant(name: str) -> Any:
    raise _NonJsonConstant(name)


def _field_path(parts) -> str:
    out = ""
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out or "(top level)"


def read_json(path: Path) -> Any:
    """Strict JSON (no NaN or Infinity literals) with errors naming the line and column."""
    if not path.is_file():
        raise VeiInputError(path, "", "file not found")
    try:
        text = path.read_text("utf-8-sig")  # (a byte-order mark, as Windows editors write, is no content)
    except UnicodeDecodeError as exc:
        raise VeiInputError(path, "", f"not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    except OSError as exc:
        raise VeiInputError(path, "", f"cannot read: {exc.strerror or exc}") from None
    try:
        # (a number that overflows, 1e400, reads as infinity: the checks after the schema name its field)
        return json.loads(text, parse_constant=_reject_constant)
    except RecursionError:
        raise VeiInputError(
            path, "", "nested too deeply to read (more than ~900 levels of arrays or objects)"
        ) from None
    except json.JSONDecodeError as exc:
        hint = ""
        if text.lstrip("\ufeff \t\r\n").startswith("<"):  # a scenario or road network given for a clip
            hint = f" (the file is XML, not a JSON clip: if it is an OpenSCENARIO scenario, play it: vei run {path})"
        raise VeiInputError(path, f"line {exc.lineno} column {exc.colno}", f"invalid JSON: {exc.msg}{hint}") from None
    except _NonJsonConstant as exc:  # NaN / Infinity literals, which Python accepts and JSON does not
        m = re.search(rf"(?<![\w\"]){re.escape(exc.name)}(?![\w\"])", text)
        where = ""
        if m:
            line = text.count("\n", 0, m.start()) + 1
            where = f"line {line} column {m.start() - text.rfind(chr(10), 0, m.start())}"
        raise VeiInputError(path, where, f"invalid JSON: {exc.name} is not a number JSON allows") from None
    except ValueError:  # (an integer of thousands of digits: Python refuses to convert it)
        limit = sys.get_int_max_str_digits()
        raise VeiInputError(path, "", f"invalid JSON: a number of more than {limit} digits, too long to read") from None


def _schema_check(path: Path, doc: Any) -> None:
    import jsonschema

    validator = jsonschema.Draft202012Validator(clip_schema())
    errors = sorted(validator.iter_errors(doc), key=lambda e: (len(e.absolute_path), list(map(str, e.absolute_path))))
    if not errors:
        return
    err = jsonschema.exceptions.best_match(errors)
    where = _field_path(err.absolute_path)
    if err.validator == "additionalProperties":
        reason = f"{err.message} (extra fields belong under an 'extensions' object)"
    elif err.validator == "const" and list(err.absolute_path) == ["format"]:
        reason = f"unsupported format {err.instance!r}; expected 'vei-clip/1'"
    elif err.validator == "type" and len(err.message) > MAX_REASON_CHARS:  # (it quotes a large value whole)
        reason = f"must be {_json_type_name(err.validator_value)}, not {_json_type_name(_json_type(err.instance))}"
    else:
        reason = err.message if len(err.message) <= MAX_REASON_CHARS else err.message[:MAX_REASON_CHARS] + " [...]"
    raise VeiInputError(path, where, reason)


#: The longest schema message quoted (a message that quotes a large value is cut).
MAX_REASON_CHARS = 200


def _json_type(value: Any) -> str:
    if isinstance(value, bool):
        return "boolean"
    if isinstance(value, (int, float)):
        return "number"
    return {dict: "object", list: "array", str: "string", type(None): "null"}.get(type(value), type(value).__name__)


def _json_type_name(kind: Any) -> str:
    kinds = [kind] if isinstance(kind, str) else list(kind)
    article = {"array": "an array", "object": "an object", "integer": "an integer"}
    return " or ".join(article.get(k, f"a {k}") for k in kinds)


def _strictly_increasing(path: Path, values: np.ndarray, field: str) -> None:
    bad = np.nonzero(np.diff(values) <= 0)[0]
    if bad.size:
        i = int(bad[0]) + 1
        what = "duplicate" if values[i] == values[i - 1] else "decreasing"
        raise VeiInputError(
            path,
            field.format(i=i),
            f"times must be strictly increasing ({what}: {values[i]!r} after {values[i - 1]!r})",
        )


#: The fastest an ego's fixes may move apart (m/s): the schema's bound on ``speed_mps``; with
#: GPS_ERROR_M on top for a fix that is off (multipath in a street canyon).
MAX_TRACK_SPEED_MPS = 100.0
GPS_ERROR_M = 50.0


#: The longest clip (s) from its first GPS fix to its last: an interaction, not a day's drive (the
#: scenario is sampled at up to 100 Hz over it).
MAX_CLIP_S = 3600.0


def _clip_span_fits(path: Path, t: np.ndarray, field: str, max_span_s: float = MAX_CLIP_S) -> None:
    """Refuse a clip whose times span more than MAX_CLIP_S, naming the sample after the widest gap (a
    time in other units or from another clock, typically)."""
    if t[-1] - t[0] > max_span_s:
        i = int(np.argmax(np.diff(t))) + 1
        raise VeiInputError(
            path,
            field.format(i=i),
            f"the times span {t[-1] - t[0]:.6g} s (a gap of {t[i] - t[i - 1]:.6g} s before this one); a clip "
            f"spans at most {max_span_s:g} s",
        )


def _track_moves_as_a_vehicle(path: Path, ego: EgoTrack) -> None:
    """Refuse a fix that jumps further from the one before than a road vehicle goes (a GPS outlier,
    lat/lon swapped, a sign lost): the road fitted to the track and the projection would span it."""
    from pyproj import Geod

    _, _, d = Geod(ellps="WGS84").inv(ego.lon[:-1], ego.lat[:-1], ego.lon[1:], ego.lat[1:])
    dt = np.diff(ego.t)
    bad = np.nonzero(d > MAX_TRACK_SPEED_MPS * dt + GPS_ERROR_M)[0]
    if bad.size:
        i = int(bad[0])
        raise VeiInputError(
            path,
            f"ego.samples[{i + 1}]",
            f"the fix lies {d[i]:.0f} m from the one before, {dt[i]:.3g} s earlier ({d[i] / dt[i]:.0f} m/s): "
            "no road vehicle moves so (a GPS outlier, or lat and lon swapped?)",
        )


def clip_from_document(path: Path, doc: Any, *, max_span_s: float = MAX_CLIP_S, require_scooter: bool = True) -> Clip:
    """A ``vei-clip/1`` document (already parsed) checked and normalised; ``path`` names it in errors
    and anchors the map file. ``max_span_s`` and ``require_scooter`` are what a clip to compile needs;
    a whole drive to cut into clips (``vei clip split``) may be longer and have no e-scooter."""
    _schema_check(path, doc)

    ego_doc = doc["ego"]
    samples = ego_doc["samples"]
    cols = {k: np.array([float(s[k]) for s in samples]) for k in ("t", "lat", "lon", "heading_deg", "speed_mps")}
    for k, arr in cols.items():  # json forbids NaN already; huge exponents can still overflow to inf
        bad = np.nonzero(~np.isfinite(arr))[0]
        if bad.size:
            raise VeiInputError(path, f"ego.samples[{int(bad[0])}].{k}", "not a finite number")
    _strictly_increasing(path, cols["t"], "ego.samples[{i}].t")
    _clip_span_fits(path, cols["t"], "ego.samples[{i}].t", max_span_s)
    ego = EgoTrack(
        t=cols["t"],
        lat=cols["lat"],
        lon=cols["lon"],
        heading_deg=cols["heading_deg"],
        speed_mps=cols["speed_mps"],
        length_m=float(ego_doc.get("length_m", DEFAULT_EGO_LENGTH_M)),
        width_m=float(ego_doc.get("width_m", DEFAULT_EGO_WIDTH_M)),
    )
    _track_moves_as_a_vehicle(path, ego)

    ann_doc = doc["annotations"]
    offset = float(ann_doc.get("time_offset_s", 0.0))
    y_axis = ann_doc.get("y_axis", "right")
    frames = ann_doc["frames"]
    frame_t = np.array([float(f["t"]) for f in frames])
    if not np.all(np.isfinite(frame_t)):
        i = int(np.nonzero(~np.isfinite(frame_t))[0][0])
        raise VeiInputError(path, f"annotations.frames[{i}].t", "not a finite number")
    _strictly_increasing(path, frame_t, "annotations.frames[{i}].t")

    t0, t1 = ego.t[0], ego.t[-1]
    observations: list[Observation] = []
    categories: dict[str, str] = {}
    for i, frame in enumerate(frames):
        t_gps = frame_t[i] + offset
        if not (t0 - 1e-9 <= t_gps <= t1 + 1e-9):
            raise VeiInputError(
                path,
                f"annotations.frames[{i}].t",
                f"annotation at GPS time {t_gps:.3f} s (t + time_offset_s) lies outside the ego GPS span "
                f"[{t0:.3f}, {t1:.3f}] s",
            )
        seen: set[str] = set()
        for j, obj in enumerate(frame["objects"]):
            where = f"annotations.frames[{i}].objects[{j}]"
            tid = obj["track_id"]
            if tid in seen:
                raise VeiInputError(path, f"{where}.track_id", f"track {tid!r} appears twice in one frame")
            seen.add(tid)
            if categories.setdefault(tid, obj["category"]) != obj["category"]:
                raise VeiInputError(
                    path,
                    f"{where}.category",
                    f"track {tid!r} changes category ({categories[tid]!r} → {obj['category']!r})",
                )
            for k in ("x_m", "y_m"):
                if not math.isfinite(float(obj[k])):
                    raise VeiInputError(path, f"{where}.{k}", "not a finite number")
            observations.append(
                Observation(float(frame_t[i]), tid, obj["category"], float(obj["x_m"]), float(obj["y_m"]), i)
            )

    annotations = Annotations(offset, y_axis, frame_t, tuple(observations))
    scooters = annotations.tracks(SCOOTER_CATEGORIES)
    if not scooters and require_scooter:
        raise VeiInputError(
            path, "annotations.frames", f"no e-scooter track (category one of {sorted(SCOOTER_CATEGORIES)})"
        )
    if require_scooter and all(len(obs) < 2 for obs in scooters.values()):
        # (an e-scooter seen once beside one seen more often is skipped with a note by the reconstruction)
        tid, obs = min(scooters.items())
        raise VeiInputError(
            path,
            f"annotations.frames[{obs[0].frame_index}].objects",
            f"track {tid!r} has {len(obs)} observation; at least 2 are needed to reconstruct a trajectory"
            + (" (and so has every other e-scooter track)" if len(scooters) > 1 else ""),
        )

    osm_path = None
    if "map" in doc and "osm" in doc["map"]:
        osm_path = (path.parent / doc["map"]["osm"]).resolve()
    return Clip(
        path=path,
        id=doc["id"],
        recorded_at=doc.get("recorded_at"),
        ego=ego,
        annotations=annotations,
        osm_path=osm_path,
        extensions=doc.get("extensions", {}),
    )
