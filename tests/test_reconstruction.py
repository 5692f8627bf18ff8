"""Reconstruction against the generator's ground truth, and the geometry it is built from."""

from __future__ import annotations

import json

import numpy as np
import pytest
from pyproj import Geod

from conftest import EXAMPLE_NAMES, EXAMPLES
from vei_scenario.clip import load_clip
from vei_scenario.geometry.angles import slerp_yaw, wrap_pi
from vei_scenario.geometry.frames import ego_to_world, world_to_ego
from vei_scenario.geometry.projection import LocalProjection
from vei_scenario.geometry.reconstruct import reconstruct
from vei_scenario.geometry.resample import output_grid


def keyframe_errors(clip_path, truth_path):
    """Max position (m) and heading (deg) error of scooter keyframes, and max ego error (m)."""
    rec = reconstruct(load_clip(clip_path))
    truth = json.loads(truth_path.read_text())
    proj = rec.projection
    pos, hdg = [], []
    for tid, track in rec.scooters.items():
        kf = truth["keyframes"][tid]
        assert len(kf) == track.key_t.size
        lat, lon = [k["lat"] for k in kf], [k["lon"] for k in kf]
        gx, gy = proj.forward(lat, lon)
        # positions of the written trajectory at the keyframe times
        tx = np.interp(track.key_t, track.trajectory.t, track.trajectory.x)
        ty = np.interp(track.key_t, track.trajectory.t, track.trajectory.y)
        pos.append(np.hypot(tx - gx, ty - gy).max())
        gyaw = proj.heading_to_yaw(lat, lon, [k["heading_deg"] for k in kf])
        hdg.append(np.degrees(np.abs(wrap_pi(track.key_yaw - gyaw))).max())
    ego = truth["ego"]
    ex, ey = proj.forward(ego["lat"], ego["lon"])
    t = np.asarray(ego["t_gps"]) - rec.t_gps0
    ego_err = np.hypot(np.interp(t, rec.ego.t, rec.ego.x) - ex, np.interp(t, rec.ego.t, rec.ego.y) - ey).max()
    return max(pos), max(hdg), ego_err


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_noise_free_keyframes_within_5cm_and_3deg(noise_free_dir, name):
    pos, hdg, ego = keyframe_errors(noise_free_dir / name / "clip.json", noise_free_dir / name / "ground_truth.json")
    assert pos <= 0.05, f"scooter keyframe position error {pos:.4f} m"
    assert hdg <= 3.0, f"scooter keyframe heading error {hdg:.2f} deg"
    assert ego <= 0.05, f"ego position error {ego:.4f} m"


#: Largest keyframe error (m, deg) and ego error (m) measured on the bundled (noisy) examples, with
#: 10-25 % headroom: a regression in smoothing or frame handling breaks them. stop_and_go: the 10° is
#: where the scooter sets off again, 0.46 m of GPS error seen from the car over a 0.2 m/s departure.
NOISY_BOUNDS = {
    "case_study": (1.25, 4.5, 1.3),
    "multi_scooter": (1.25, 4.5, 1.3),
    "no_map": (1.25, 4.5, 1.3),
    "stop_and_go": (0.6, 12.0, 0.9),
}


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_noisy_examples_stay_within_measured_bounds(name):
    pos, hdg, ego = keyframe_errors(EXAMPLES / name / "clip.json", EXAMPLES / name / "ground_truth.json")
    max_pos, max_hdg, max_ego = NOISY_BOUNDS[name]
    assert pos <= max_pos and hdg <= max_hdg and ego <= max_ego, (pos, hdg, ego)


def _progress(traj, along: np.ndarray) -> np.ndarray:
    return traj.x * along[0] + traj.y * along[1]


@pytest.mark.parametrize("noise", ["noise-free", "noisy"])
def test_a_scooter_that_stops_stays_stopped_and_never_runs_backwards(noise_free_dir, noise):
    """stop_and_go: the scooter stops for 3 s and sets off again. Reconstructed, it never moves against
    its direction of travel, stands still (within 1 mm, noise-free) between the keyframes where it stood,
    and faces its way while standing (a spline of position over time overshoots and turns it round)."""
    root = noise_free_dir if noise == "noise-free" else EXAMPLES
    clip = root / "stop_and_go" / "clip.json"
    truth = json.loads((root / "stop_and_go" / "ground_truth.json").read_text())
    rec = reconstruct(load_clip(clip))
    track = rec.scooters["scooter_1"]
    traj = track.trajectory
    kf = truth["keyframes"]["scooter_1"]
    gx, gy = rec.projection.forward([k["lat"] for k in kf], [k["lon"] for k in kf])
    along = np.array([gx[-1] - gx[0], gy[-1] - gy[0]]) / np.hypot(gx[-1] - gx[0], gy[-1] - gy[0])
    assert np.diff(_progress(traj, along)).min() >= -1e-9
    # its true standstill: keyframes with speed 0; in between, the reconstruction stands too
    standing = [k for k, f in enumerate(kf) if f["speed_mps"] == 0.0]
    assert len(standing) >= 2
    t0, t1 = track.key_t[standing[0]], track.key_t[standing[-1]]
    inside = (traj.t >= t0) & (traj.t <= t1)
    moved = np.hypot(np.ptp(traj.x[inside]), np.ptp(traj.y[inside]))
    heading = np.degrees(np.abs(wrap_pi(traj.yaw - np.arctan2(along[1], along[0]))))
    if noise == "noise-free":
        assert moved <= 1e-3 and np.all(traj.speed[inside] <= 1e-9)
        assert heading.max() <= 5.0
    else:  # the GPS-borne drift of a standing scooter is not taken for motion
        assert moved <= 1e-3 and heading[inside].max() <= 12.0


def test_heading_conversion_matches_geodesic_azimuth():
    proj = LocalProjection(60.165, 24.94)
    geod = Geod(ellps="WGS84")
    rng = np.random.default_rng(1)
    lat = 60.165 + rng.uniform(-0.02, 0.02, 50)
    lon = 24.94 + rng.uniform(-0.04, 0.04, 50)
    az = rng.uniform(0, 360, 50)
    lon2, lat2, _ = geod.fwd(lon, lat, az, np.full(50, 1.0))
    x1, y1 = proj.forward(lat, lon)
    x2, y2 = proj.forward(lat2, lon2)
    yaw_grid = np.arctan2(y2 - y1, x2 - x1)  # independent: direction of a 1 m geodesic step
    err = np.degrees(np.abs(wrap_pi(proj.heading_to_yaw(lat, lon, az) - yaw_grid)))
    assert err.max() < 1e-3
    back = proj.yaw_to_heading(lat, lon, yaw_grid)
    assert np.degrees(np.abs(wrap_pi(np.radians(back - az)))).max() < 1e-3


def test_projection_origin_is_first_fix_and_round_trips():
    proj = LocalProjection(39.7684, -86.1581)
    x, y = proj.forward(39.7684, -86.1581)
    assert abs(x) < 1e-9 and abs(y) < 1e-9
    lat, lon = proj.inverse(*proj.forward(39.77, -86.15))
    assert abs(lat - 39.77) < 1e-10 and abs(lon + 86.15) < 1e-10


@pytest.mark.parametrize("axis, sign", [("right", -1.0), ("left", 1.0)])
def test_ego_frame_lateral_axis_convention(axis, sign):
    # Ego at (10, 5) heading north (yaw 90°): an object 10 m ahead, 2 m to the annotated +y side.
    x, y = ego_to_world(10.0, 2.0, axis, 10.0, 5.0, np.pi / 2)
    # "right" (image convention): +y is to the ego's right, which is east (+x) when heading north.
    assert np.allclose([x, y], [10.0 - sign * 2.0, 15.0])
    back = world_to_ego(x, y, axis, 10.0, 5.0, np.pi / 2)
    assert np.allclose(back, [10.0, 2.0])


def test_slerp_takes_the_short_way_across_pi():
    yaw = slerp_yaw(np.array([0.0, 1.0]), np.array([np.radians(170), np.radians(-170)]), np.array([0.5]))
    assert abs(abs(np.degrees(yaw[0])) - 180.0) < 1e-6


def test_output_grid_shares_the_global_clock_and_keeps_ends():
    g = output_grid(1.23, 3.0, 10.0)
    assert g[0] == 1.23 and g[-1] == 3.0
    assert np.allclose(g[1:-1] * 10, np.round(g[1:-1] * 10))
    assert np.all(np.diff(g) > 0)


def test_tracks_with_gaps_and_other_categories_are_reported(compiled):
    notes = "\n".join(compiled["multi_scooter"].notes)
    assert "ped_1" in notes and "pedestrian" in notes
    assert "scooter_3: not observed for 4.0 s" in notes


def test_where_gcv_has_no_answer_the_spline_interpolates():
    """scipy's GCV finds samples spaced over nine orders of magnitude ill-posed (it raises): the penalty
    falls back to the least searched, and the spline still goes through the samples."""
    from scipy.interpolate import make_smoothing_spline

    from vei_scenario.geometry.resample import LOG_PENALTY_RANGE, gcv_penalty, smoothing_spline

    t = np.concatenate([[0.0], 1e9 + np.arange(99) * 0.1])
    y = np.sin(t)
    with pytest.raises(ValueError):  # (the case itself: if scipy learns to answer it, this test says so)
        make_smoothing_spline(t, y)
    assert gcv_penalty(t, y) == 10 ** LOG_PENALTY_RANGE[0]
    fit = smoothing_spline(t, y)(t)
    assert np.all(np.isfinite(fit)) and np.max(np.abs(fit - y)) < 1e-3


@pytest.mark.parametrize(
    "lat0, lon0",
    [(-33.86, 151.21), (64.14, -21.94), (0.0001, 179.9995), (-77.85, 166.67), (-0.0002, -78.5)],
    ids=["sydney", "reykjavik", "antimeridian", "antarctica", "equator-west"],
)
def test_the_same_drive_anywhere_on_earth_gives_the_same_scene(tmp_path, lat0, lon0):
    """The no-map clip moved, fix by fix, to another place on earth (the same distances and azimuths
    from its first fix: an azimuthal equidistant projection there and back), across the
    antimeridian, the equator and in Antarctica: the run's metrics equal the original's within
    0.5 mm and 1 ms (the projection is local to the clip; no UTM zone or sign of a longitude enters)."""
    from pyproj import Proj

    from vei_scenario.compiler import compile_clip
    from vei_scenario.interpreter import run_scenario
    from vei_scenario.metrics import PairSeries, compute_metrics

    doc = json.loads((EXAMPLES / "no_map" / "clip.json").read_text())
    first = doc["ego"]["samples"][0]
    here = Proj(proj="aeqd", lat_0=first["lat"], lon_0=first["lon"], datum="WGS84")
    there = Proj(proj="aeqd", lat_0=lat0, lon_0=lon0, datum="WGS84")
    for s in doc["ego"]["samples"]:
        lon, lat = there(*here(s["lon"], s["lat"]), inverse=True)
        s["lat"], s["lon"] = round(lat, 10), round(lon, 10)
    moved = tmp_path / "moved.json"
    moved.write_text(json.dumps(doc))

    def metrics(clip):
        xosc = compile_clip(clip, tmp_path / clip.stem / "scenario.xosc").written[0]
        return compute_metrics(PairSeries.from_run(run_scenario(xosc)))

    a, b = metrics(EXAMPLES / "no_map" / "clip.json"), metrics(moved)
    assert b["collision"] == a["collision"]
    assert b["min_gap_m"] == pytest.approx(a["min_gap_m"], abs=5e-4)
    assert b["min_ttc_s"] == pytest.approx(a["min_ttc_s"], abs=1e-3)
    assert b["act_min_s"] == pytest.approx(a["act_min_s"], abs=1e-3)
