"""Series that lie on each other: drawn so that none hides another, and named in the legend.

Two configurations often give the same curve (the planner brakes the same for a normal and an
aggressive rider; a grid of rider types scores S = 1.0 alike far from the conflict). Drawn one over the
other in the same style, the first disappears and a reader concludes it is missing. Each series
therefore gets its own marker shape, its markers staggered along the line (so that coinciding lines
still show every series' markers side by side), a line width that shrinks with its order (the one
below peeks out around the one above), and a legend note naming the series it coincides with.
"""

from __future__ import annotations

import numpy as np

#: Marker shape per series, in drawing order.
MARKERS = ("o", "s", "^", "D", "v", "P", "X", "<", ">", "h")
#: Dash pattern per series where the line style carries no other meaning (the sweep plots).
LINE_STYLES = ("-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1)))
#: Two series closer than this share of the plotted data's range everywhere draw as one line.
COINCIDE_SHARE = 0.01
#: Markers along one line (staggered between the series).
MARKS_PER_LINE = 12


def tolerance(ys: list[np.ndarray]) -> float:
    """How close two series must be to draw over each other: COINCIDE_SHARE of the data's range."""
    finite = [y[np.isfinite(y)] for y in ys]
    finite = [f for f in finite if f.size]
    if not finite:
        return 0.0
    lo, hi = min(float(f.min()) for f in finite), max(float(f.max()) for f in finite)
    return COINCIDE_SHARE * (hi - lo) if hi > lo else 1e-9 * max(1.0, abs(hi))


def shared_points(x1: np.ndarray, y1: np.ndarray, x2: np.ndarray, y2: np.ndarray, tol: float) -> tuple[int, int]:
    """(points where the two series draw at the same place, points they have in common): the common x
    values where both values are within ``tol``, or both missing."""
    common, i, j = np.intersect1d(np.asarray(x1, float), np.asarray(x2, float), return_indices=True)
    if not common.size:
        return 0, 0
    a, b = np.asarray(y1, float)[i], np.asarray(y2, float)[j]
    both_missing = np.isnan(a) & np.isnan(b)
    with np.errstate(invalid="ignore"):
        close = np.abs(a - b) <= tol
    return int((close | both_missing).sum()), int(common.size)


def coincidence_notes(series: list[tuple[str, np.ndarray, np.ndarray]], partial: bool = False) -> list[str]:
    """Per series (label, x, y), a legend note naming the first earlier series it lies on: all of its
    common points (``coincides with``), or with ``partial`` at least half of them (``equal to ... at
    n of m points``); "" when none."""
    tol = tolerance([y for _, _, y in series])
    notes = []
    for k, (_, x, y) in enumerate(series):
        note = ""
        for label_j, x_j, y_j in series[:k]:
            same, common = shared_points(x, y, x_j, y_j, tol)
            if common and same == common:
                note = f" (coincides with {label_j} to {COINCIDE_SHARE:.0%} of the axis)"
                break
            if partial and common and 2 * same >= common and not note:
                note = f" (equal to {label_j} at {same} of {common} points)"
        notes.append(note)
    return notes


def style(k: int, count: int, points: int, base_width: float = 1.4) -> dict:
    """Matplotlib keywords of the ``k``-th of ``count`` series of ``points`` points each: its marker,
    staggered against the others', and a width that shrinks with k so the lines below show."""
    every = max(1, points // MARKS_PER_LINE)
    return {
        "marker": MARKERS[k % len(MARKERS)],
        "markevery": (int(every * k / max(count, 1)) % every, every),
        "ms": 4.5,
        "mfc": "none",
        "lw": base_width + 1.2 * (count - 1 - k) / max(count - 1, 1),
    }
