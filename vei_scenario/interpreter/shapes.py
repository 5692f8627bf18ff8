"""Trajectory shapes other than a polyline, sampled into one: Clothoid and ClothoidSpline.

A clothoid's heading is quadratic in arc length, so its points have no closed form (Fresnel
integrals). The core integrates them on a fine grid (``vei_clothoid_sample``: trapezoid on 5 mm
steps; for a curvature rate of 0.01 1/m² over 100 m the error stays below 1e-6 m) and keeps them
every 5 cm, where a straight chord departs from the curve by at most κ·(0.05 m)²/8 (3 µm at a 10 m
radius). The player then follows the polyline as it follows any other.
"""

from __future__ import annotations

import array
import math

import numpy as np
from lxml import etree

from vei_scenario.core import _core
from vei_scenario.interpreter.entities import Polyline
from vei_scenario.interpreter.positions import RESOLVED_ELSEWHERE, Pose, lane_of, number, oriented, resolve
from vei_scenario.models.angles import wrap_angle
from vei_scenario.safe_xml import first_element

_FINE_M = 0.005
_KEEP_EVERY = 10  # kept vertices every 5 cm
#: The longest curve sampled into a polyline: a clothoid, a clothoid spline's segments together, a
#: Nurbs's control polygon (a clothoid's points every 5 cm: 2 million vertices).
_MAX_CURVE_M = 100_000.0


def clothoid_points(
    x0: float, y0: float, h0: float, curvature: float, curvature_rate: float, length: float
) -> tuple[array.array, array.array, array.array]:
    """x, y, heading along a clothoid from (x0, y0, h0) of start ``curvature``, its rate of change
    along the arc (1/m²) and ``length``; the last sample is the end point. The core samples it
    (``vei_clothoid_sample``: the trapezoid rule, a cosine and a sine per fine step, in C) into arrays
    of doubles (a spline of a few hundred metres is thousands of points: never Python floats)."""
    out = []
    for raw in _core.clothoid(x0, y0, h0, curvature, curvature_rate, length, _FINE_M, _KEEP_EVERY):
        a = array.array("d")
        a.frombytes(raw)
        out.append(a)
    return out[0], out[1], out[2]


def _sampled(ctx, el, x0: float, y0: float, h0: float, curvature: float, rate: float, length: float):
    """clothoid_points of element ``el``'s clothoid; one line naming it where its numbers, each finite,
    make none (a curvature change over the length that overflows, a start too far away)."""
    try:
        return clothoid_points(x0, y0, h0, curvature, rate, length)
    except ValueError:
        raise ctx.error(
            el,
            f"<{el.tag}>: no clothoid of curvature {curvature:g}, rate {rate:g} 1/m² and length "
            f"{length:g} m from ({x0:g}, {y0:g}, {h0:g})",
        ) from None


def _num(ctx, el, name: str, default: float | None = None) -> float:
    v = el.get(name)
    if v in (None, ""):
        if default is None:
            raise ctx.error(el, f"<{el.tag}> needs {name}")
        return default
    return float(v)


def _clothoid_length(ctx, el) -> float:
    """A clothoid's (or spline segment's) ``length``: positive (the standard's range) and at most
    100 km (what is sampled into a polyline)."""
    length = _num(ctx, el, "length")
    if not 0.0 < length <= _MAX_CURVE_M:
        raise ctx.error(el, f"<{el.tag}> needs a length above 0 and at most {_MAX_CURVE_M:g} m (got {length:g})")
    return length


def _start_pose(ctx, pos_el, entity):
    """Where a clothoid starts: its position, else where the entity following it is now."""
    if pos_el is not None:
        return resolve(ctx, pos_el)
    if entity is None:
        return None
    e = ctx.entities[entity]
    return Pose(e.x, e.y, e.yaw)


def _clothoid(el, ctx, start) -> tuple[list, list, list, float]:
    if start is None:
        raise ctx.error(el, "a Clothoid needs a start Position")
    rate = el.get("curvaturePrime") if el.get("curvaturePrime") is not None else el.get("curvatureDot")
    length = _clothoid_length(ctx, el)
    x, y, h = _sampled(ctx, el, start.x, start.y, start.h, _num(ctx, el, "curvature"), float(rate or 0.0), length)
    return x, y, h, length


def placed_when_built(traj) -> bool:
    """Whether a ``<Trajectory>``'s points can be placed when the scenario is built: none is relative
    to an entity and every clothoid has a start position (else they are placed when its action
    starts, where the entities then are)."""
    if any(isinstance(x.tag, str) and x.tag.startswith("Relative") for x in traj.iter()):
        return False
    if traj.find("Shape/Clothoid") is not None and traj.find("Shape/Clothoid/Position") is None:
        return False
    return traj.find("Shape/ClothoidSpline") is None or any(True for _ in traj.iter("PositionStart"))


#: Positions whose place depends on nothing but their own attributes and the road network.
_FIXED_POSITIONS = frozenset({"WorldPosition", "LanePosition", "RoadPosition"})
#: Trajectories of world positions built so far in this process: their XML -> the polyline (those on
#: roads: in their network's memo). A sweep builds the same trajectories for most variants; a polyline
#: is only read once built.
_BUILT: dict[bytes, Polyline] = {}


def polyline_from(el, ctx, place: bool = True, entity: str | None = None) -> Polyline:
    """A ``<Trajectory>``'s shape as a polyline (Polyline, Clothoid, ClothoidSpline); with ``place``
    False only the vertex times are read (positions relative to entities are placed when the action
    starts). A clothoid without a start position starts where ``entity`` is. ``closed`` adds the
    segment back to the first vertex of a Polyline; a curve (Nurbs, clothoids) closes, or not, by its
    own definition, so the flag adds nothing to it.

    A trajectory whose positions are all fixed (world, lane, road) is built once per process for its
    XML and road network (tests/test_catalog_reuse.py)."""
    built = _built(el, ctx) if place and entity is None and _fixed(el) else None
    if built is None:
        return _polyline(el, ctx, place, entity)
    key = etree.tostring(el)
    line = built.get(key)
    if line is None:
        line = _polyline(el, ctx, place, entity)
        if len(built) >= 1024:
            built.clear()
        built[key] = line
    return line


def _built(el, ctx) -> dict | None:
    """Where the polylines of trajectories like ``el`` are kept: its road network's memo when it has
    positions on roads (None without a network: the build says why), else this process's."""
    if next(el.iter("LanePosition", "RoadPosition"), None) is None:
        return _BUILT
    net = ctx.roads
    return None if net is None else net.memo.setdefault("polylines", {})


def _fixed(el) -> bool:
    """Whether every position in trajectory ``el`` is fixed: its place read from itself (and roads)."""
    for pos in el.iter("Position", "PositionStart"):
        for child in pos:
            if isinstance(child.tag, str) and child.tag not in _FIXED_POSITIONS and child.tag != "Position":
                return False
    return True


def _polyline(el, ctx, place: bool, entity: str | None) -> Polyline:
    closed = el.get("closed", "false") in ("true", "1")
    shape = el.find("Shape")
    kind = first_element(shape) if shape is not None else None
    if kind is None or kind.tag not in ("Polyline", "Clothoid", "ClothoidSpline", "Nurbs"):
        tag = kind.tag if kind is not None else "none"
        raise ctx.error(el, f"trajectory shape <{tag}> is not supported (Polyline, Clothoid, ClothoidSpline, Nurbs)")
    if kind.tag == "Nurbs":
        return _nurbs(kind, ctx, place)
    if kind.tag == "Clothoid":
        t0, t1 = kind.get("startTime"), kind.get("stopTime")
        if not place:
            return Polyline.unplaced([float(t0), float(t1)] if t0 and t1 else [None, None])
        xs, ys, hs, length = _clothoid(kind, ctx, _start_pose(ctx, kind.find("Position"), entity))
        return Polyline(xs, ys, hs, _times_along(xs, ys, t0, t1))
    if kind.tag == "ClothoidSpline":
        segments = kind.findall("ClothoidSplineSegment")
        if not segments:
            raise ctx.error(kind, "a ClothoidSpline needs segments")
        t0 = segments[0].get("timeStart")
        t1 = kind.get("timeEnd")
        if not place:
            return Polyline.unplaced([float(t0), float(t1)] if t0 and t1 else [None, None])
        xs, ys, hs = array.array("d"), array.array("d"), array.array("d")
        marks: list[int] = []  # index of each segment's first point
        jumped: list[bool] = []  # whether it starts away from where the one before ended
        total = 0.0
        for k, seg in enumerate(segments):
            pos = seg.find("PositionStart")
            # the standard types PositionStart as a Position (its child is the LanePosition,
            # WorldPosition ...); a <Position> wrapped inside it is read as well
            if pos is not None and pos.find("Position") is not None:
                pos = pos.find("Position")
            if k == 0 or pos is not None:  # a segment with its own start begins there (a jump, as esmini)
                start = _start_pose(ctx, pos, entity)
                if start is None:
                    raise ctx.error(seg, "the first ClothoidSplineSegment needs a PositionStart")
                x0, y0, h0 = start.x, start.y, start.h
            else:
                x0, y0, h0 = xs[-1], ys[-1], hs[-1]
            k0, k1 = _num(ctx, seg, "curvatureStart"), _num(ctx, seg, "curvatureEnd")
            length = _clothoid_length(ctx, seg)
            total += length
            if total > _MAX_CURVE_M:
                raise ctx.error(seg, f"the ClothoidSpline's segments are longer than {_MAX_CURVE_M:g} m together")
            h_off = _num(ctx, seg, "hOffset", 0.0)
            x, y, h = _sampled(ctx, seg, x0, y0, h0 + h_off, k0, (k1 - k0) / length, length)
            marks.append(len(xs))
            jumped.append(bool(xs) and math.hypot(x[0] - xs[-1], y[0] - ys[-1]) >= 1e-12)
            if xs and not jumped[-1]:
                x, y, h = x[1:], y[1:], h[1:]  # (continuing: the shared point once)
                marks[-1] -= 1
            xs += x
            ys += y
            hs += h
        return Polyline(xs, ys, hs, _spline_times(kind, segments, xs, ys, marks, jumped))
    vertices = kind.findall("Vertex")
    if not place:
        return Polyline.unplaced([float(v.get("time")) if v.get("time") is not None else None for v in vertices])
    xs, ys, hs, ts = [], [], [], []
    for v in vertices:
        wp = v.find("Position/WorldPosition")
        if wp is not None:
            xs.append(float(wp.get("x")))
            ys.append(float(wp.get("y")))
            hs.append(float(wp.get("h")) if wp.get("h") is not None else None)
        else:
            pos = v.find("Position")
            if pos is None:
                raise ctx.error(v, "vertex without a Position")
            pose = resolve(ctx, pos)
            xs.append(pose.x)
            ys.append(pose.y)
            # a vertex heading is set only by an Orientation; else the path's own direction (esmini)
            kind = first_element(pos)
            hs.append(pose.h if kind is not None and kind.find("Orientation") is not None else None)
        ts.append(float(v.get("time")) if v.get("time") is not None else None)
    if len(xs) < 2:
        raise ctx.error(el, "a polyline needs at least two vertices")
    if closed and math.hypot(xs[-1] - xs[0], ys[-1] - ys[0]) > 1e-9:
        # a closed polyline runs back to its first vertex (the standard; esmini 3.6 ignores `closed`).
        # That closing segment has no time of its own, so a timed one must close itself.
        if any(t is not None for t in ts):
            raise ctx.error(
                el, "a closed timed Polyline must end on its first vertex (the closing segment needs a time)"
            )
        xs.append(xs[0])
        ys.append(ys[0])
        hs.append(hs[0])
        ts.append(None)
    return Polyline(xs, ys, hs, ts)


def _spline_times(spline, segments, xs: list, ys: list, marks: list[int], jumped: list[bool]) -> list[float | None]:
    """Vertex times of a ClothoidSpline: each segment with a ``timeStart`` runs at constant speed
    until the next segment's ``timeStart`` (the last until the spline's ``timeEnd``); a segment without
    one shares the span of the timed segment before it, and a jump to a segment's own start takes no
    time. Untimed without a first timeStart and a timeEnd."""
    starts = [seg.get("timeStart") for seg in segments]
    t_end = spline.get("timeEnd")
    if not starts[0] or not t_end:
        return [None] * len(xs)
    bounds = [(marks[k], float(t), jumped[k]) for k, t in enumerate(starts) if t not in (None, "")]
    bounds.append((len(xs) - 1, float(t_end), False))
    times: list[float | None] = [None] * len(xs)
    for (i0, a, _), (i1, b, jump) in zip(bounds, bounds[1:]):
        end = i1 if jump else i1 + 1  # a jump to the next segment's start takes no time
        times[i0:end] = _times_along(xs[i0:end], ys[i0:end], str(a), str(b))
    times[-1] = float(t_end)
    return times


def _times_along(xs, ys, t0: str | None, t1: str | None) -> list[float | None]:
    """Vertex times spread over the arc from ``t0`` to ``t1`` (constant speed), or none."""
    if not t0 or not t1:
        return [None] * len(xs)
    s = np.concatenate(([0.0], np.cumsum(np.hypot(np.diff(xs), np.diff(ys)))))
    a, b = float(t0), float(t1)
    return (a + (b - a) * s / s[-1]).tolist() if s[-1] > 0 else [a] * len(xs)


#: A NURBS's control points are placed in its parameter on a grid of equal steps, one per metre of
#: its control polygon (esmini's sampling: where its vertex times are pinned comes from this grid).
NURBS_STEP_M = 1.0
#: A later sample must raise a basis function's peak by this much to move it (esmini keeps the first
#: of two nearly equal samples; measured on NURBS of order 2 to 4 against esmini 3.6).
NURBS_PEAK_TOLERANCE = 1e-4
#: The path itself is sampled this many times finer than that grid (a chord of 1 m on a 20 m radius
#: would sag 6 mm and shorten the arc).
NURBS_REFINE = 8


def _control_point_parameters(basis: np.ndarray, u: np.ndarray) -> np.ndarray:
    """The curve parameter each control point stands at: the sample where its basis function peaks.
    A control point's time is the time at that parameter, and time runs linearly in the parameter
    between them. (The standard leaves the timing of a NURBS open; this is esmini's reading, which
    vei matches within 0.08 m on esmini's trajectory-test and on NURBS of orders 2 to 4 written
    to probe it.)"""
    peaks = np.empty(basis.shape[1])
    for i in range(basis.shape[1]):
        col = basis[:, i]
        best, at = -1.0, u[0]
        for value, where in zip(col, u):
            if value > best + NURBS_PEAK_TOLERANCE:
                best, at = value, where
        peaks[i] = at
    return np.maximum.accumulate(peaks)


def _nurbs(el, ctx, place: bool) -> Polyline:
    """A ``<Nurbs>`` shape: the rational B-spline of order ``order`` (degree order − 1) through its
    weighted control points over its knot vector, sampled densely; a timed one runs through each
    control point's time where that point's basis function peaks (:func:`_control_point_parameters`)."""
    from scipy.interpolate import BSpline

    order = int(_num(ctx, el, "order"))
    points = el.findall("ControlPoint")
    knots = [_num(ctx, k, "value") for k in el.findall("Knot")]
    n = len(points)
    if order < 1 or n < order:
        raise ctx.error(el, f"a Nurbs of order {order} needs at least {max(order, 1)} control points, has {n}")
    if len(knots) != n + order:
        raise ctx.error(
            el, f"a Nurbs of order {order} with {n} control points needs {n + order} knots, has {len(knots)}"
        )
    if any(b < a for a, b in zip(knots, knots[1:])):
        raise ctx.error(el, "Nurbs knot values must not decrease")
    weights = [_num(ctx, p, "weight", 1.0) for p in points]
    if any(w <= 0 for w in weights):
        raise ctx.error(el, "Nurbs control point weights must be positive")
    times = [float(p.get("time")) if p.get("time") not in (None, "") else None for p in points]
    timed = all(t is not None for t in times)
    if not place:
        return Polyline.unplaced([times[0], times[-1]] if timed else [None, None])
    xy = []
    for p in points:
        pos = p.find("Position")
        if pos is None:
            raise ctx.error(p, "a Nurbs ControlPoint needs a Position")
        pose = resolve(ctx, pos)
        xy.append((pose.x, pose.y))
    degree = order - 1
    w = np.array(weights)
    cols = np.column_stack([np.array(xy) * w[:, None], w])
    lo, hi = knots[degree], knots[n]
    if not hi > lo:
        raise ctx.error(el, "Nurbs knots leave no parameter range")
    curve = BSpline(np.array(knots), cols, degree, extrapolate=False)
    polygon = float(np.hypot(*np.diff(np.array(xy), axis=0).T).sum()) if n > 1 else 0.0
    if not polygon <= _MAX_CURVE_M:  # (sampled every NURBS_STEP_M: its memory grows with it)
        raise ctx.error(el, f"a Nurbs's control polygon of {polygon:g} m is longer than {_MAX_CURVE_M:g} m")
    steps = max(1, math.ceil(polygon / NURBS_STEP_M - 1e-9))
    u = lo + (hi - lo) * np.arange(NURBS_REFINE * steps + 1) / (NURBS_REFINE * steps)
    u[-1] = hi - 1e-12 * max(1.0, abs(hi))  # (the closed end of the last knot span)
    grid = u[::NURBS_REFINE]  # (every NURBS_REFINE-th sample, the last one included)
    vals = curve(u)
    xs, ys = vals[:, 0] / vals[:, 2], vals[:, 1] / vals[:, 2]
    ts = [None] * len(u)
    if timed:
        basis = np.nan_to_num(BSpline(np.array(knots), np.eye(n), degree, extrapolate=False)(grid), nan=0.0)
        ts = list(np.interp(u, _control_point_parameters(basis, grid), times))
    line = Polyline(list(xs), list(ys), [None] * len(u), ts)
    if timed and len(u) > NURBS_REFINE:
        # it leaves at its speed along the chord of the last grid step (esmini's last vertex interval)
        k = len(u) - 1 - NURBS_REFINE
        dt_last = ts[-1] - ts[k]
        if dt_last > 0:
            line.exit_speed = math.hypot(xs[-1] - xs[k], ys[-1] - ys[k]) / dt_last
    return line


def trajectory_of(ctx, el):
    """The placed polyline of the trajectory a ``TrajectoryPosition`` refers to (inline or from a
    catalog, which the loader has already put in place)."""
    traj = el.find("TrajectoryRef/Trajectory")
    if traj is None:
        traj = el.find("Trajectory")  # (OpenSCENARIO 1.1 put it here)
    if traj is None:
        raise ctx.error(el, "TrajectoryPosition needs a TrajectoryRef with a Trajectory")
    return polyline_from(traj, ctx)


def trajectory_pose(ctx, el) -> Pose:
    """A ``TrajectoryPosition``: ``s`` metres along the trajectory, ``t`` to its left; heading along
    the trajectory's path — not the vertex headings an entity following it would take — with an
    Orientation relative to that, or absolute. Beyond the ends the path is
    continued straight, as a trajectory's own end is."""
    line = trajectory_of(ctx, el)
    s, t = number(el, "s"), number(el, "t")
    x, y, _ = line.at_s(s)
    h = line.direction_at_s(s) if len(line.xs) > 1 else line.hs[0]  # along the path (esmini)
    over = s - line.length if s > line.length else min(s, 0.0)
    x, y = x + over * math.cos(h), y + over * math.sin(h)
    x, y = x - t * math.sin(h), y + t * math.cos(h)
    pose_h = wrap_angle(oriented(el, h))
    return Pose(x, y, pose_h, lane_of(ctx, x, y, pose_h))


RESOLVED_ELSEWHERE["TrajectoryPosition"] = trajectory_pose
