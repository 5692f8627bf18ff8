"""Oriented bounding boxes and their overlap by the separating-axis theorem, vectorised.

Two convex boxes in the plane are disjoint iff some edge normal of one of them separates their
projections; four axes suffice for two rectangles. Arrays broadcast, so the same code checks one pair
per step in the interpreter or thousands of (shift, time) pairs in the conflict analysis.
"""

from __future__ import annotations

import numpy as np


def box_corners(x, y, yaw, length, width) -> np.ndarray:
    """Corners (..., 4, 2) of boxes centred at (x, y), counter-clockwise; all arguments broadcast."""
    x, y, yaw, length, width = np.broadcast_arrays(*(np.asarray(v, float) for v in (x, y, yaw, length, width)))
    c, s = np.cos(yaw)[..., None], np.sin(yaw)[..., None]
    hl, hw = 0.5 * length, 0.5 * width
    lx = np.stack([hl, -hl, -hl, hl], axis=-1)
    ly = np.stack([hw, hw, -hw, -hw], axis=-1)
    cx = x[..., None] + c * lx - s * ly
    cy = y[..., None] + s * lx + c * ly
    return np.stack([cx, cy], axis=-1)


def boxes_overlap(xa, ya, yawa, la, wa, xb, yb, yawb, lb, wb) -> np.ndarray:
    """True where box A and box B intersect (touching counts as intersecting)."""
    dx = np.asarray(xb, float) - np.asarray(xa, float)
    dy = np.asarray(yb, float) - np.asarray(ya, float)
    ca, sa = np.cos(yawa), np.sin(yawa)
    cb, sb = np.cos(yawb), np.sin(yawb)
    sep = np.zeros(np.broadcast(dx, dy, ca, cb).shape, bool)
    # Axes: A's x and y, B's x and y. Projection radius of a box on unit axis (ux, uy):
    # hl*|u·e_long| + hw*|u·e_lat|.
    for ux, uy in ((ca, sa), (-sa, ca), (cb, sb), (-sb, cb)):
        ra = 0.5 * la * np.abs(ux * ca + uy * sa) + 0.5 * wa * np.abs(-ux * sa + uy * ca)
        rb = 0.5 * lb * np.abs(ux * cb + uy * sb) + 0.5 * wb * np.abs(-ux * sb + uy * cb)
        sep |= np.abs(dx * ux + dy * uy) > ra + rb
    return ~sep
