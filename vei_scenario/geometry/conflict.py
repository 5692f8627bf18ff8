"""Conflict analysis (the seed method's step 8).

For each scooter: where its path and the ego's cross or come closest, when each of them is there, and
the timing shift of the scooter that puts both there at once. Shifting time, not space, keeps the
recorded paths and speeds and turns a recorded near-encounter into a collision. The shift makes the
scooter's trajectory time ``τ`` play at scenario time ``τ + shift`` (the ``Timing`` offset of its
``FollowTrajectoryAction``).

The conflict margin of a scooter is the absolute shift (a post-encroachment time); the primary threat
is the scooter with the smallest margin among those whose path reaches the ego's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from vei_scenario.geometry.resample import Trajectory
from vei_scenario.models.boxes import boxes_overlap

#: Resolution of the scan for the interval of shifts that produce a box collision (s).
SHIFT_STEP_S = 0.02
#: Half-width of that scan around the conflict shift (s).
SHIFT_SCAN_S = 6.0
#: Time step of the replay in that scan (s).
SCAN_DT_S = 0.01


@dataclass(frozen=True)
class Conflict:
    track_id: str
    point_x: float
    point_y: float
    path_distance_m: float  # 0 where the paths cross
    t_ego_s: float
    t_scooter_s: float
    time_shift_s: float  # shift that makes the scooter reach the point with the ego
    reaches_ego_path: bool
    unshifted_min_distance_m: float  # closest centre distance at shift 0
    unshifted_collision: bool
    collision_shifts_s: tuple[float, float] | None  # contiguous shift interval with box contact

    @property
    def margin_s(self) -> float:
        return abs(self.time_shift_s) if self.reaches_ego_path else math.inf


def _time_at_arclength(traj: Trajectory, s: float) -> float:
    arc = traj.arc_length()
    # Arc length is non-decreasing; where an entity stands still take the first instant it is there.
    i = int(np.searchsorted(arc, s, side="left"))
    if i <= 0:
        return float(traj.t[0])
    if i >= arc.size:
        return float(traj.t[-1])
    a0, a1 = arc[i - 1], arc[i]
    f = 0.0 if a1 == a0 else (s - a0) / (a1 - a0)
    return float(traj.t[i - 1] + f * (traj.t[i] - traj.t[i - 1]))


def state_at(traj: Trajectory, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Replay semantics: linear between vertices, held at the first/last vertex outside the span."""
    t = np.asarray(t, float)
    yaw = np.interp(t, traj.t, np.unwrap(traj.yaw))
    return np.interp(t, traj.t, traj.x), np.interp(t, traj.t, traj.y), yaw


def analyse_conflict(
    track_id: str,
    ego: Trajectory,
    scooter: Trajectory,
    ego_box: tuple[float, float],
    scooter_box: tuple[float, float],
) -> Conflict:
    """Conflict point, timing shift and the shift interval giving box contact, for one scooter."""
    ego_line = shapely.LineString(ego.xy)
    sc_line = shapely.LineString(scooter.xy)
    crossing = ego_line.intersection(sc_line)
    candidates = [g for g in getattr(crossing, "geoms", [crossing]) if not g.is_empty and g.geom_type == "Point"]
    if candidates:
        best = None
        for pt in candidates:
            te = _time_at_arclength(ego, ego_line.project(pt))
            ts = _time_at_arclength(scooter, sc_line.project(pt))
            if best is None or abs(te - ts) < abs(best[1] - best[2]):
                best = (pt, te, ts)
        pt, te, ts = best
        px, py, dist = pt.x, pt.y, 0.0
    else:
        pe, ps = (shapely.Point(c) for c in shapely.shortest_line(ego_line, sc_line).coords)
        te = _time_at_arclength(ego, ego_line.project(pe))
        ts = _time_at_arclength(scooter, sc_line.project(ps))
        px, py, dist = 0.5 * (pe.x + ps.x), 0.5 * (pe.y + ps.y), pe.distance(ps)
    shift = te - ts
    reach = 0.5 * (ego_box[1] + scooter_box[1])  # lateral half-widths: boxes can touch across the gap
    reaches = dist <= reach

    # Closeness and contact at shift 0, on the ego's clock.
    sx, sy, syaw = state_at(scooter, ego.t)
    rec_dist = float(np.min(np.hypot(sx - ego.x, sy - ego.y)))
    rec_coll = bool(np.any(boxes_overlap(ego.x, ego.y, ego.yaw, *ego_box, sx, sy, syaw, *scooter_box)))

    interval = None
    if reaches:
        shifts = shift + np.arange(-SHIFT_SCAN_S, SHIFT_SCAN_S + 1e-9, SHIFT_STEP_S)
        # Replay both on a 10 ms grid around the conflict, finer than any output rate, keeping only the
        # instants when the ego is close enough to the scooter's path for the boxes to touch at all.
        et = np.arange(max(te - SHIFT_SCAN_S - 5, ego.t[0]), min(te + SHIFT_SCAN_S + 5, ego.t[-1]), SCAN_DT_S)
        ex, ey, eyaw = state_at(ego, et)
        contact_range = 0.5 * (np.hypot(*ego_box) + np.hypot(*scooter_box)) + 1e-6
        near = shapely.distance(shapely.points(ex, ey), sc_line) <= contact_range
        et, ex, ey, eyaw = et[near], ex[near], ey[near], eyaw[near]
        qx, qy, qyaw = state_at(scooter, et[None, :] - shifts[:, None])
        hit = boxes_overlap(ex, ey, eyaw, *ego_box, qx, qy, qyaw, *scooter_box).any(axis=1)
        centre = int(np.argmin(np.abs(shifts - shift)))
        if hit.any():
            idx = np.nonzero(hit)[0]
            # The contiguous run nearest the conflict shift.
            runs = np.split(idx, np.nonzero(np.diff(idx) > 1)[0] + 1)
            run = min(
                runs, key=lambda r: 0 if r[0] <= centre <= r[-1] else min(abs(r[0] - centre), abs(r[-1] - centre))
            )
            interval = (float(shifts[run[0]]), float(shifts[run[-1]]))
    return Conflict(
        track_id,
        float(px),
        float(py),
        float(dist),
        float(te),
        float(ts),
        float(shift),
        bool(reaches),
        rec_dist,
        rec_coll,
        interval,
    )


def primary_threat(conflicts: dict[str, Conflict]) -> str:
    """The scooter with the smallest conflict margin; ties and non-reaching paths by path distance."""
    return min(conflicts, key=lambda k: (conflicts[k].margin_s, conflicts[k].path_distance_m, k))
