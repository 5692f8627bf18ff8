"""One row of a scenario library per clip, and the order of the rows.

A row says what a reviewer needs to pick scenarios from a dataset: where its files are, its road
users, how long it lasts, the conflict (the timing shift that makes the threat meet the ego, and the
collision interval around it), how close the recording came to a collision, and the compiler's
warnings. A clip that cannot be compiled is a row too, with its reason.

**Closeness to a collision** (the library's order): ``collision_margin_s``, the smallest change of the
threat's timing that makes the boxes touch (0 when they touch as recorded; none when no shift does),
then the conflict margin ``|conflict TimeShift|`` (a post-encroachment time), then the closest centre
distance as recorded. Rows that could not be compiled come last, by file name.
"""

from __future__ import annotations

import math

from vei_scenario.compiler import CompileResult


def _r(value: float | None, nd: int = 3) -> float | None:
    if value is None or not math.isfinite(value):
        return None
    return round(float(value), nd) + 0.0  # (+0.0: never -0.0)


def collision_margin_s(interval: tuple[float, float] | None, recorded_collision: bool) -> float | None:
    """How far TimeShift 0 (the recording) is from the nearest shift with box contact (s)."""
    if recorded_collision:
        return 0.0
    if interval is None:
        return None
    lo, hi = interval
    return 0.0 if lo <= 0.0 <= hi else min(abs(lo), abs(hi))


def ok_row(result: CompileResult, outputs: dict[str, str]) -> dict:
    """The row of a compiled clip (``outputs``: its files, relative to the library)."""
    m, rec = result.model, result.reconstruction
    c = m.conflicts[m.threat]
    others: dict[str, int] = {}
    for cat in rec.skipped_tracks.values():
        others[cat] = others.get(cat, 0) + 1
    tracks = []
    for tid, k in sorted(m.conflicts.items()):
        tracks.append(
            {
                "track_id": tid,
                "observed_s": [_r(rec.scooters[tid].key_t[0], 2), _r(rec.scooters[tid].key_t[-1], 2)],
                "reaches_ego_path": k.reaches_ego_path,
                "conflict_time_shift_s": _r(k.time_shift_s) if k.reaches_ego_path else None,
                "min_centre_distance_m": _r(k.unshifted_min_distance_m),
            }
        )
    return {
        "status": "ok",
        "error": "",
        "outputs": outputs,
        "duration_s": _r(m.duration_s, 2),
        "road": "fitted to the ego track" if result.road_source == "fitted" else result.road_source[4:],
        "ego_on_lanes": _r(result.ego_on_lanes, 4),
        "road_users": {"e-scooter": len(rec.scooters), **dict(sorted(others.items()))},
        "threat": m.threat,
        "conflict_time_shift_s": _r(c.time_shift_s) if c.reaches_ego_path else None,
        "conflict_margin_s": _r(c.margin_s),
        "collision_shifts_s": [_r(v) for v in c.collision_shifts_s] if c.collision_shifts_s else None,
        "collision_margin_s": _r(collision_margin_s(c.collision_shifts_s, c.unshifted_collision)),
        "recorded_collision": c.unshifted_collision,
        "min_centre_distance_m": _r(c.unshifted_min_distance_m),
        "tracks": tracks,
        "warnings": list(result.notes),
    }


def error_row(reason: str) -> dict:
    return {"status": "error", "error": reason}


def _inf(v: float | None) -> float:
    return math.inf if v is None else v


def closeness_key(row: dict) -> tuple:
    """The sort key of a row: compiled rows by closeness to a collision, then the rest (by file)."""
    if row["status"] != "ok":
        return (1, 0.0, 0.0, 0.0, row["file"])
    return (
        0,
        _inf(row["collision_margin_s"]),
        _inf(row["conflict_margin_s"]),
        _inf(row["min_centre_distance_m"]),
        row["file"],
    )


def ranked(rows: list[dict]) -> list[dict]:
    """The rows in library order, each with its ``rank`` (1 = closest to a collision; failed: none)."""
    out = []
    for k, row in enumerate(sorted(rows, key=closeness_key), 1):
        out.append({"rank": k if row["status"] == "ok" else None, **row})
    return out
