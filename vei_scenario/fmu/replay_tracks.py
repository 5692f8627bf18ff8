"""The track the FMU loop gives a replayed rider: its recording, and after it the way ``vei run``
drives it on.

A replayed rider reacts to nothing, so its whole motion is an input of the loop. While its recording
lasts, the rider FMU plays it as ``vei run`` does (the same timed polyline of the core). Where the
recording ends before the run does, ``vei run`` hands the rider to the default behaviour, which on a
road drives it on along its lane (esmini's default), while the FMU would go on straight at its last
speed: it has no road. So the loop appends that way on to the track, as ``vei run`` plays it, sampled
at the loop's communication points (the only times a co-simulation master asks the FMU for its pose,
where the FMU's linear interpolation between vertices is exact). Samples that lie on the straight,
uniformly timed line between their neighbours are dropped (:func:`thin`) so the track fits the FMU's
:data:`~vei_scenario.fmu.variables.MAX_PATH` vertices: the finest tolerance of :data:`TOLERANCES_M`
that fits is taken, and a coarser one than 1e-6 m is said in a note.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: position (m) and heading (rad) tolerances tried in turn for the dropped samples, finest first
TOLERANCES_M = (1e-9, 1e-8, 1e-7, 2e-7, 5e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1)


@dataclass(frozen=True)
class DrivenOn:
    """A replayed track with the way on appended: trajectory times, x, y, headings (named as the
    interpreter's polyline names them); the tolerance its
    dropped samples keep (0 where nothing was appended); ``cut_s``: the trajectory time after which it
    goes on straight because even the coarsest tolerance does not fit (None where it all fits)."""

    ts: np.ndarray
    xs: np.ndarray
    ys: np.ndarray
    hs: np.ndarray
    tolerance_m: float = 0.0
    cut_s: float | None = None


def _wrap(a: np.ndarray) -> np.ndarray:
    return np.arctan2(np.sin(a), np.cos(a))


def thin(t: np.ndarray, x: np.ndarray, y: np.ndarray, h: np.ndarray, tol: float) -> list[int]:
    """Indices of the samples to keep: the first, the last and those without which the core's
    interpolation (linear in time for x and y, along the shorter turn for the heading) between the
    kept neighbours would miss a dropped sample by more than ``tol`` (m, rad). Greedy, from the start."""
    keep, i, n = [0], 0, t.size
    while i < n - 1:
        j = i + 1
        while j + 1 < n:
            c = j + 1
            f = (t[i + 1 : c] - t[i]) / (t[c] - t[i])
            ex, ey = x[i] + f * (x[c] - x[i]), y[i] + f * (y[c] - y[i])
            eh = _wrap(h[i] + f * _wrap(h[c] - h[i]))
            if np.max(np.hypot(ex - x[i + 1 : c], ey - y[i + 1 : c])) > tol:
                break
            if np.max(np.abs(_wrap(eh - h[i + 1 : c]))) > tol:
                break
            j = c
        keep.append(j)
        i = j
    return keep


def drive_on(track: tuple, run_trace, shift_s: float, max_vertices: int) -> DrivenOn:
    """``track`` (times, x, y, headings of the recording) with ``run_trace``'s poses (a ``vei run``
    :class:`~vei_scenario.interpreter.engine.EntityTrace` of the same rider) after its last time
    appended; ``shift_s``: how late the rider plays its track (simulation time = trajectory time +
    shift). At most ``max_vertices`` vertices."""
    ts, xs, ys, hs = (np.asarray(v, dtype=float) for v in track)
    tt = np.asarray(run_trace.t, dtype=float) - shift_s
    after = tt > ts[-1] + 1e-9
    if not after.any():
        return DrivenOn(ts, xs, ys, hs)
    # (the way on starts at the track's last vertex, which the FMU reaches at the track's last time)
    t = np.concatenate([ts[-1:], tt[after]])
    x = np.concatenate([xs[-1:], np.asarray(run_trace.x, dtype=float)[after]])
    y = np.concatenate([ys[-1:], np.asarray(run_trace.y, dtype=float)[after]])
    h = np.concatenate([hs[-1:], np.asarray(run_trace.yaw, dtype=float)[after]])
    room = max_vertices - ts.size + 1  # (the first of the way on is the track's last)
    if room < 2:
        return DrivenOn(ts, xs, ys, hs, cut_s=float(ts[-1]))
    for tol in TOLERANCES_M:
        keep = thin(t, x, y, h, tol)
        if len(keep) <= room:
            break
    cut = None
    if len(keep) > room:  # (the coarsest does not fit either: on straight after the last vertex that does)
        keep = keep[:room]
        cut = float(t[keep[-1]])
    k = np.asarray(keep[1:], dtype=int)
    return DrivenOn(
        np.concatenate([ts, t[k]]), np.concatenate([xs, x[k]]), np.concatenate([ys, y[k]]),
        np.concatenate([hs, h[k]]), tol, cut,
    )  # fmt: skip
