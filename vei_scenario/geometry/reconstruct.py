"""Reconstruct world trajectories from a clip (the seed method's steps 1 and 4–7).

Order matters and follows the method: project the GPS track (4), put annotation times on the GPS clock
and take the ego pose at each of them (5), move each observation from the ego frame to the world (6),
then resample every track at the output rate (7). Step 1, the bounding box, is what the map stage
needs. Scenario time 0 is the first ego fix, and so is the projection's origin.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from vei_scenario.clip.model import SCOOTER_CATEGORIES, Clip
from vei_scenario.geometry.angles import slerp_yaw, unwrap_continuous
from vei_scenario.geometry.frames import ego_to_world
from vei_scenario.geometry.projection import LocalProjection
from vei_scenario.geometry.resample import (
    SAME_POINT_M,
    SAME_POINT_PER_SCATTER,
    Trajectory,
    output_grid,
    position_spline,
    resample_path,
    smoothing_spline,
)

#: A gap between two observations of one track longer than this is reported (the spline bridges it).
GAP_REPORT_S = 2.5


@dataclass(frozen=True)
class ScooterTrack:
    track_id: str
    category: str
    key_t: np.ndarray  # scenario time of each observation
    key_x: np.ndarray
    key_y: np.ndarray
    key_yaw: np.ndarray
    trajectory: Trajectory
    gaps: tuple[tuple[float, float], ...] = ()


@dataclass(frozen=True)
class Reconstruction:
    clip: Clip
    projection: LocalProjection
    t_gps0: float
    rate_hz: float
    ego: Trajectory
    ego_fix_t: np.ndarray
    ego_fix_x: np.ndarray
    ego_fix_y: np.ndarray
    ego_fix_yaw: np.ndarray
    scooters: dict[str, ScooterTrack]
    #: why a track is left out ({track id: reason}): a road user seen once has no trajectory to replay
    skipped_tracks: dict[str, str] = field(default_factory=dict)
    #: the other annotated road users (pedestrians, cyclists, cars ...), replayed as recorded
    others: dict[str, ScooterTrack] = field(default_factory=dict)

    @property
    def road_users(self) -> dict[str, ScooterTrack]:
        """Every reconstructed track: the e-scooters, then the other road users."""
        return {**self.scooters, **self.others}

    @property
    def duration_s(self) -> float:
        return float(self.ego.t[-1])

    def bbox_xy(self) -> tuple[float, float, float, float]:
        """Step 1: the box (min x, min y, max x, max y) around the ego and every road user's trajectory."""
        xs = [self.ego.x] + [s.trajectory.x for s in self.road_users.values()]
        ys = [self.ego.y] + [s.trajectory.y for s in self.road_users.values()]
        x, y = np.concatenate(xs), np.concatenate(ys)
        return float(x.min()), float(y.min()), float(x.max()), float(y.max())

    def bbox_latlon(self, margin_m: float) -> tuple[float, float, float, float]:
        """Box (south, west, north, east) in degrees around :meth:`bbox_xy` grown by ``margin_m``."""
        x0, y0, x1, y1 = self.bbox_xy()
        cx = np.array([x0 - margin_m, x1 + margin_m, x0 - margin_m, x1 + margin_m])
        cy = np.array([y0 - margin_m, y0 - margin_m, y1 + margin_m, y1 + margin_m])
        lat, lon = self.projection.inverse(cx, cy)
        return float(lat.min()), float(lon.min()), float(lat.max()), float(lon.max())


def reconstruct(clip: Clip, rate_hz: float = 10.0, smooth: bool = True) -> Reconstruction:
    """Run steps 4–7 on a loaded clip.

    With ``smooth`` (the default) positions and GPS headings, and the keyframes of tracks with five or
    more observations, are fitted with smoothing splines whose penalty generalised cross-validation
    picks. On noise-free data GCV picks almost no smoothing (the fit interpolates to the millimetre);
    on noisy GPS it halves the heading error at keyframes compared with an interpolating spline, whose
    end tangents amplify noise (measured on the bundled examples, see ``tests/test_reconstruction.py``).
    """
    ego = clip.ego
    proj = LocalProjection(float(ego.lat[0]), float(ego.lon[0]))

    # Step 4: projection and scenario clock.
    t_gps0 = float(ego.t[0])
    fix_t = ego.t - t_gps0
    fix_x, fix_y = proj.forward(ego.lat, ego.lon)
    fix_yaw = unwrap_continuous(proj.heading_to_yaw(ego.lat, ego.lon, ego.heading_deg))
    if smooth and fix_t.size >= 5:
        fix_yaw = smoothing_spline(fix_t, fix_yaw)(fix_t)

    sx, sy = position_spline(fix_t, fix_x, fix_y, smooth)
    # how far the GPS fixes scatter about the ego's track: annotated positions inherit it, so a road user
    # that stands still seems to drift by about as much (resample_path must not take that for motion)
    gps_scatter = float(np.sqrt(np.mean((sx(fix_t) - fix_x) ** 2 + (sy(fix_t) - fix_y) ** 2)))
    standing_m = max(SAME_POINT_M, SAME_POINT_PER_SCATTER * gps_scatter)
    grid = output_grid(0.0, float(fix_t[-1]), rate_hz)
    ego_traj = Trajectory(
        grid,
        np.asarray(sx(grid)),
        np.asarray(sy(grid)),
        slerp_yaw(fix_t, fix_yaw, grid),
        np.hypot(sx(grid, 1), sy(grid, 1)),
    )

    # Step 5: annotation clock → GPS clock → scenario clock; ego pose at every observation.
    ann = clip.annotations
    tracks = ann.tracks()
    scooters: dict[str, ScooterTrack] = {}
    others: dict[str, ScooterTrack] = {}
    skipped: dict[str, str] = {}
    for tid in sorted(tracks):
        obs = tracks[tid]
        scooter = obs[0].category.lower() in SCOOTER_CATEGORIES
        if len(obs) < 2:  # (the loader refuses a clip whose every e-scooter is seen once: a threat needs a path)
            skipped[tid] = f"category {obs[0].category!r} observed once: no trajectory to replay; skipped"
            continue
        kt = np.array([o.t_annotation for o in obs]) + ann.time_offset_s - t_gps0
        ex, ey = np.asarray(sx(kt)), np.asarray(sy(kt))
        eyaw = slerp_yaw(fix_t, fix_yaw, kt)
        # Step 6: ego frame → world, with the annotation's lateral axis convention.
        wx, wy = ego_to_world([o.x_m for o in obs], [o.y_m for o in obs], ann.y_axis, ex, ey, eyaw)
        # Step 7: cubic spline positions and SLERP headings at the output rate.
        traj, kyaw = resample_path(kt, wx, wy, rate_hz, smooth=smooth, standing_m=standing_m)
        dt = np.diff(kt)
        gaps = tuple((float(kt[i]), float(kt[i + 1])) for i in np.nonzero(dt > GAP_REPORT_S)[0])
        (scooters if scooter else others)[tid] = ScooterTrack(tid, obs[0].category, kt, wx, wy, kyaw, traj, gaps)

    return Reconstruction(
        clip, proj, t_gps0, rate_hz, ego_traj, fix_t, fix_x, fix_y, fix_yaw, scooters, skipped, others
    )
