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


def _point_box_distance(px, py, bx, by, byaw, length, width):
    c, s = np.cos(byaw), np.sin(byaw)
    dx, dy = px - bx, py - by
    lx, ly = c * dx + s * dy, -s * dx + c * dy
    ox = np.maximum(np.abs(lx) - 0.5 * length, 0.0)
    oy = np.maximum(np.abs(ly) - 0.5 * width, 0.0)
    return np.hypot(ox, oy)


def box_distance(xa, ya, yawa, la, wa, xb, yb, yawb, lb, wb) -> np.ndarray:
    """Shortest distance between two oriented boxes (0 where they overlap), vectorised.

    Two disjoint convex polygons are closest at a vertex of one of them, so the distance is the least
    corner-to-box distance in both directions.
    """
    ca = box_corners(xa, ya, yawa, la, wa)
    cb = box_corners(xb, yb, yawb, lb, wb)
    expand = (..., None)
    d_ab = _point_box_distance(
        ca[..., 0], ca[..., 1], *(np.asarray(v, float)[expand] for v in (xb, yb, yawb)), lb, wb
    ).min(axis=-1)
    d_ba = _point_box_distance(
        cb[..., 0], cb[..., 1], *(np.asarray(v, float)[expand] for v in (xa, ya, yawa)), la, wa
    ).min(axis=-1)
    d = np.minimum(d_ab, d_ba)
    return np.where(boxes_overlap(xa, ya, yawa, la, wa, xb, yb, yawb, lb, wb), 0.0, d)


def time_to_contact(xa, ya, yawa, la, wa, vxa, vya, xb, yb, yawb, lb, wb, vxb, vyb) -> np.ndarray:
    """Time until two boxes moving at constant velocity (and constant heading) first touch; 0 when
    they overlap now, ``inf`` when they never will. Exact for translating boxes.

    On each separating axis u the projected centre distance is u·d + τ u·w (w: relative velocity); the
    boxes overlap on u while its magnitude is at most the sum of the projected half-extents. They
    touch when every axis overlaps: the latest entry over the four axes, if it precedes the earliest
    exit.
    """
    xa, ya, yawa, vxa, vya, xb, yb, yawb, vxb, vyb = np.broadcast_arrays(
        *(np.asarray(v, float) for v in (xa, ya, yawa, vxa, vya, xb, yb, yawb, vxb, vyb))
    )
    dx, dy, wx, wy = xb - xa, yb - ya, vxb - vxa, vyb - vya
    ca, sa, cb, sb = np.cos(yawa), np.sin(yawa), np.cos(yawb), np.sin(yawb)
    enter = np.full(dx.shape, -np.inf)
    leave = np.full(dx.shape, np.inf)
    for ux, uy in ((ca, sa), (-sa, ca), (cb, sb), (-sb, cb)):
        r = 0.5 * la * np.abs(ux * ca + uy * sa) + 0.5 * wa * np.abs(-ux * sa + uy * ca)
        r = r + 0.5 * lb * np.abs(ux * cb + uy * sb) + 0.5 * wb * np.abs(-ux * sb + uy * cb)
        p = dx * ux + dy * uy
        q = wx * ux + wy * uy
        moving = np.abs(q) > 1e-12
        inside = np.abs(p) <= r
        with np.errstate(divide="ignore", invalid="ignore"):
            t1, t2 = (-r - p) / q, (r - p) / q
        # Without relative motion along u the axis overlaps always (inside) or never.
        lo = np.where(moving, np.minimum(t1, t2), np.where(inside, -np.inf, np.inf))
        hi = np.where(moving, np.maximum(t1, t2), np.where(inside, np.inf, -np.inf))
        enter = np.maximum(enter, lo)
        leave = np.minimum(leave, hi)
    hit = (enter <= leave) & (leave >= 0)
    return np.where(hit, np.maximum(enter, 0.0), np.inf)
