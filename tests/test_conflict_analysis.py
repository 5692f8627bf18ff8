"""Conflict analysis against analytic crossings, and the threat choice on the examples."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from vei_scenario.geometry.conflict import SCAN_DT_S, SHIFT_STEP_S, analyse_conflict
from vei_scenario.geometry.resample import Trajectory
from vei_scenario.models.boxes import box_corners, boxes_overlap


def straight(t, x0, y0, vx, vy):
    return Trajectory(
        t, x0 + vx * t, y0 + vy * t, np.full(t.shape, np.arctan2(vy, vx)), np.full(t.shape, np.hypot(vx, vy))
    )


def test_perpendicular_crossing_shift_and_collision_interval_are_analytic():
    t = np.arange(0, 25.0001, 0.01)
    ego = straight(t, 0.0, 0.0, 5.0, 0.0)  # reaches x = 50 at t = 10
    sc_t = np.arange(2.0, 12.0001, 0.01)
    scooter = straight(sc_t, 50.0, -20.0, 0.0, 4.0)  # x = 50; reaches y = 0 at t = 7
    scooter = Trajectory(sc_t, scooter.x - 0.0, -20.0 + 4.0 * (sc_t - 2.0), scooter.yaw, scooter.speed)
    c = analyse_conflict("s", ego, scooter, (4.8, 1.9), (1.2, 0.6))
    assert c.path_distance_m == 0.0 and c.reaches_ego_path
    assert c.point_x == pytest.approx(50.0, abs=1e-6) and c.point_y == pytest.approx(0.0, abs=1e-6)
    assert c.t_ego_s == pytest.approx(10.0, abs=1e-6) and c.t_scooter_s == pytest.approx(7.0, abs=1e-6)
    assert c.time_shift_s == pytest.approx(3.0, abs=1e-6)
    # Contact iff the ego box (x in 50 ± 2.7 incl. the scooter's half width) and the scooter box
    # (y in ± 1.55) overlap in time: ego there for t in (9.46, 10.54), scooter for t - s in (6.6125, 7.3875).
    lo, hi = 9.46 - 7.3875, 10.54 - 6.6125
    tol = SHIFT_STEP_S + SCAN_DT_S  # the scan's shift step plus its time step
    assert c.collision_shifts_s[0] == pytest.approx(lo, abs=tol)
    assert c.collision_shifts_s[1] == pytest.approx(hi, abs=tol)
    assert not c.unshifted_collision


def test_parallel_paths_do_not_reach_the_ego():
    t = np.arange(0, 10.0001, 0.1)
    ego = straight(t, 0.0, 0.0, 5.0, 0.0)
    oncoming = straight(t, 60.0, 3.5, -4.0, 0.0)
    c = analyse_conflict("s", ego, oncoming, (4.8, 1.9), (1.2, 0.6))
    assert not c.reaches_ego_path and c.margin_s == float("inf")
    assert c.path_distance_m == pytest.approx(3.5, abs=1e-9)


def test_threats_of_the_examples(compiled):
    assert compiled["case_study"].model.threat == "scooter_1"
    multi = compiled["multi_scooter"].model
    assert multi.threat == "scooter_2"  # crosses 1.4 s before the ego; scooter_1 3.0 s before
    assert not multi.conflicts["scooter_3"].reaches_ego_path  # oncoming in the other lane
    # The generator placed the case-study scooter 2.2 s ahead of the ego at the crossing.
    c = compiled["case_study"].model.conflicts["scooter_1"]
    assert c.time_shift_s == pytest.approx(2.2, abs=0.15)
    assert c.collision_shifts_s[0] < c.time_shift_s < c.collision_shifts_s[1]
    assert not c.unshifted_collision


def test_box_overlap_agrees_with_shapely_on_10000_random_pairs():
    rng = np.random.default_rng(42)
    n = 10_000
    a = (rng.uniform(-3, 3, n), rng.uniform(-3, 3, n), rng.uniform(-np.pi, np.pi, n))
    b = (rng.uniform(-3, 3, n), rng.uniform(-3, 3, n), rng.uniform(-np.pi, np.pi, n))
    la, wa, lb, wb = rng.uniform(0.5, 5, n), rng.uniform(0.3, 2.5, n), rng.uniform(0.5, 5, n), rng.uniform(0.3, 2.5, n)
    ours = boxes_overlap(*a, la, wa, *b, lb, wb)
    ca = box_corners(*a, la, wa)
    cb = box_corners(*b, lb, wb)
    ref = shapely.intersects(shapely.polygons(ca), shapely.polygons(cb))
    assert 0.2 < ref.mean() < 0.8  # both outcomes well represented
    assert np.array_equal(ours, ref)
