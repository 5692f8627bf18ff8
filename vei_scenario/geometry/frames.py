"""Ego-relative annotations → world positions.

Annotations give ``x`` forward and ``y`` lateral from the ego reference point (the GPS antenna). With
``y_axis: "right"`` (image convention) positive ``y`` points right, so it is negated to reach the
right-handed frame (x forward, y left) before rotating by the ego yaw.
"""

from __future__ import annotations

import numpy as np


def lateral_sign(y_axis: str) -> float:
    """+1 when annotation y already points left (right-handed), -1 when it points right."""
    if y_axis == "left":
        return 1.0
    if y_axis == "right":
        return -1.0
    raise ValueError(f"y_axis must be 'left' or 'right', not {y_axis!r}")


def ego_to_world(x_rel, y_rel, y_axis: str, ego_x, ego_y, ego_yaw) -> tuple[np.ndarray, np.ndarray]:
    """World position of points given in the ego frame, one ego pose per point."""
    xr = np.asarray(x_rel, float)
    yr = lateral_sign(y_axis) * np.asarray(y_rel, float)
    c, s = np.cos(ego_yaw), np.sin(ego_yaw)
    return ego_x + c * xr - s * yr, ego_y + s * xr + c * yr


def world_to_ego(x_w, y_w, y_axis: str, ego_x, ego_y, ego_yaw) -> tuple[np.ndarray, np.ndarray]:
    """Inverse of :func:`ego_to_world` (used by the example generator and the tests)."""
    dx, dy = np.asarray(x_w, float) - ego_x, np.asarray(y_w, float) - ego_y
    c, s = np.cos(ego_yaw), np.sin(ego_yaw)
    return c * dx + s * dy, lateral_sign(y_axis) * (-s * dx + c * dy)
