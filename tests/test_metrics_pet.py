"""Post-encroachment time: an analytic crossing, and the conflict-area membership against shapely's
geometry of the swept areas (the union of each road user's boxes, intersected)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely

from vei_scenario.metrics import MetricConfig
from vei_scenario.metrics.definitions import conflict_area_samples, pet_s
from vei_scenario.metrics.series import PairSeries, Track
from vei_scenario.models.boxes import box_corners

DT = 0.01


def _pair(t, ego_xy, ego_yaw, other_xy, other_yaw, ego_box=(4.8, 1.9), other_box=(1.2, 0.6)) -> PairSeries:
    z = np.zeros_like(t)
    ego = Track("Ego", *ego_box, ego_xy[0], ego_xy[1], ego_yaw, z + 1, z)
    other = Track("s", *other_box, other_xy[0], other_xy[1], other_yaw, z + 1, z)
    return PairSeries(t, ego, other)


def test_pet_of_a_perpendicular_crossing_matches_the_analytic_value():
    t = np.round(np.arange(0, 20 + DT / 2, DT), 9)
    ve, vo = 8.0, 4.0
    ego = (-40 + ve * t, 0 * t)  # along x
    other = (0 * t, -60 + vo * t)  # along y, later
    p = _pair(t, ego, 0 * t, other, 0 * t + math.pi / 2)
    # conflict area |x| <= 0.3, |y| <= 0.95: the ego's box is in it while |x_e| <= 0.3 + 2.4,
    # the scooter's while |y_o| <= 0.95 + 0.6
    ego_exit = (2.7 + 40) / ve
    other_entry = (60 - 1.55) / vo
    grid = t[::5]
    expected = grid[grid >= other_entry][0] - grid[grid <= ego_exit][-1]
    got = float(pet_s(p, MetricConfig()))
    assert got == pytest.approx(expected, abs=1e-9)
    assert abs(got - (other_entry - ego_exit)) <= 0.1
    # following traffic on one line: no PET
    same = _pair(t, ego, 0 * t, (ego[0] - 20, ego[1]), 0 * t)
    assert math.isnan(float(pet_s(same, MetricConfig())))


def _shapely_membership(p: PairSeries):
    e, o = p.ego, p.other
    idx = np.arange(0, p.t.size, 5)
    pe = shapely.polygons(box_corners(e.x[idx], e.y[idx], e.yaw[idx], e.length, e.width))
    po = shapely.polygons(box_corners(o.x[idx], o.y[idx], o.yaw[idx], o.length, o.width))
    area = shapely.intersection(shapely.union_all(pe), shapely.union_all(po))
    return shapely.intersects(area, pe), shapely.intersects(area, po)


@pytest.mark.parametrize("seed", range(6))
def test_conflict_area_membership_agrees_with_shapely_on_curved_crossings(seed):
    rng = np.random.default_rng(seed)
    t = np.round(np.arange(0, 12 + DT / 2, DT), 9)
    # curved paths crossing near the origin at random angles and timings
    a0, a1 = rng.uniform(-math.pi, math.pi), rng.uniform(0.6, 2.5)
    k0, k1 = rng.uniform(-0.03, 0.03, 2)
    yaw_e = a0 + k0 * (t - 6) * 6
    yaw_o = a0 + a1 + k1 * (t - 6) * 4
    ve, vo = rng.uniform(5, 9), rng.uniform(3, 5)
    shift = rng.uniform(-1.5, 1.5)
    xe = np.cumsum(ve * np.cos(yaw_e)) * DT
    ye = np.cumsum(ve * np.sin(yaw_e)) * DT
    xo = np.cumsum(vo * np.cos(yaw_o)) * DT
    yo = np.cumsum(vo * np.sin(yaw_o)) * DT
    k = np.searchsorted(t, 6.0)
    ko = np.searchsorted(t, 6.0 + shift)
    p = _pair(t, (xe - xe[k], ye - ye[k]), yaw_e, (xo - xo[ko], yo - yo[ko]), yaw_o)
    ref_e, ref_o = _shapely_membership(p)
    assert ref_e.any() and ref_o.any()

    idx, in_e, in_o = conflict_area_samples(p)
    np.testing.assert_array_equal(idx, np.arange(0, t.size, 5))
    np.testing.assert_array_equal(in_e, ref_e)
    np.testing.assert_array_equal(in_o, ref_o)
    pet = float(pet_s(p, MetricConfig()))
    te, to = t[::5][ref_e], t[::5][ref_o]
    first_exit, second_entry = (te[-1], to[0]) if te[0] <= to[0] else (to[-1], te[0])
    assert pet == pytest.approx(max(0.0, second_entry - first_exit), abs=1e-12) or math.isnan(pet)


def test_median_equals_numpys_for_odd_and_even_counts():
    """metrics.series.median stands in for np.median (which imports numpy.ma): the same value bit for
    bit, the mean of the two middle values for an even count."""
    import numpy as np

    from vei_scenario.metrics.series import median

    rng = np.random.default_rng(7)
    for n in (1, 2, 3, 4, 5, 10, 11, 2501, 2502):
        a = rng.normal(size=n) * 10 ** rng.uniform(-3, 3, size=n)
        assert median(a) == float(np.median(a)), n
    assert median(np.array([1.0, 2.0])) == 1.5
