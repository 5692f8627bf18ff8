"""A quick box around the scene, from the raw clip alone (no splines, no scipy).

Good enough to cut the map region (the crop adds tens of metres of margin and keeps whole ways), and
available right after loading, so that netconvert can start while the reconstruction runs.
"""

from __future__ import annotations

import numpy as np

from vei_scenario.clip.model import Clip
from vei_scenario.geometry.frames import ego_to_world
from vei_scenario.geometry.projection import LocalProjection


def coarse_bbox_latlon(clip: Clip, proj: LocalProjection, margin_m: float) -> tuple[float, float, float, float]:
    """(south, west, north, east) around the GPS fixes and every road user's observation, grown by
    ``margin_m``; observations are placed with the ego pose interpolated linearly between fixes."""
    ego = clip.ego
    fx, fy = proj.forward(ego.lat, ego.lon)
    yaw = np.unwrap(proj.heading_to_yaw(ego.lat, ego.lon, ego.heading_deg))
    xs, ys = [fx], [fy]
    obs = list(clip.annotations.observations)
    if obs:
        t = np.array([o.t_annotation for o in obs]) + clip.annotations.time_offset_s
        wx, wy = ego_to_world(
            [o.x_m for o in obs],
            [o.y_m for o in obs],
            clip.annotations.y_axis,
            np.interp(t, ego.t, fx),
            np.interp(t, ego.t, fy),
            np.interp(t, ego.t, yaw),
        )
        xs.append(wx)
        ys.append(wy)
    x, y = np.concatenate(xs), np.concatenate(ys)
    cx = np.array([x.min(), x.max(), x.min(), x.max()]) + np.array([-1, 1, -1, 1]) * margin_m
    cy = np.array([y.min(), y.min(), y.max(), y.max()]) + np.array([-1, -1, 1, 1]) * margin_m
    lat, lon = proj.inverse(cx, cy)
    return float(lat.min()), float(lon.min()), float(lat.max()), float(lon.max())
