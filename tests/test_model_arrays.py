"""The numpy (array) models equal the scalar models the interpreter uses, on 10 000 random states.

They are the reference the batch engine and the FMUs are built on; this pins them to the code that
``vei run`` executes."""

from __future__ import annotations

import math

import numpy as np

from vei_scenario.models.cap import BRAKE, CRUISE, CapParameters, CapState, ThreatView, cap_step, cap_step_arrays
from vei_scenario.models.sfm import SfmParameters, SfmState, sfm_step, sfm_step_arrays
from vei_scenario.models.vehicle import Longitudinal, VehicleLimits, longitudinal_step, longitudinal_step_arrays

N = 10_000
RTOL, ATOL = 1e-12, 1e-12


def test_sfm_arrays_equal_the_scalar_model():
    rng = np.random.default_rng(11)
    p = SfmParameters(v0_mps=4.3)
    route = np.cumsum(rng.uniform(2, 8, size=(12, 2)), axis=0)
    x, y = rng.uniform(-5, 60, N), rng.uniform(-5, 60, N)
    speed, heading = rng.uniform(0, 8, N), rng.uniform(-math.pi, math.pi, N)
    speed[::97] = 0.0  # standing riders
    vx, vy = speed * np.cos(heading), speed * np.sin(heading)
    wp = rng.integers(0, 12, N)
    rep = rng.random(N) < 0.5
    ego = (
        x + rng.uniform(-6, 6, N),
        y + rng.uniform(-6, 6, N),
        rng.uniform(-math.pi, math.pi, N),
        np.full(N, 4.8),
        np.full(N, 1.9),
    )
    ax, ay, avx, avy, awp = sfm_step_arrays(x, y, vx, vy, wp, route, p, rep, ego, 0.01)
    pts = [tuple(r) for r in route]
    for i in range(N):
        box = tuple(float(e[i]) for e in ego)
        s = sfm_step(SfmState(x[i], y[i], vx[i], vy[i], int(wp[i])), pts, p, bool(rep[i]), box, 0.01)
        assert s.waypoint == awp[i]
        np.testing.assert_allclose([s.x, s.y, s.vx, s.vy], [ax[i], ay[i], avx[i], avy[i]], rtol=RTOL, atol=ATOL)


def test_cap_arrays_equal_the_scalar_planner():
    rng = np.random.default_rng(12)
    p = CapParameters()
    brake = rng.random(N) < 0.4
    integral = rng.normal(0, 0.5, N)
    prev = np.where(rng.random(N) < 0.3, np.nan, rng.normal(0, 1, N))
    cruise = rng.uniform(3, 15, N)
    v = np.where(rng.random(N) < 0.05, 0.0, rng.uniform(0, 15, N))
    ttc = np.where(rng.random(N) < 0.3, np.inf, rng.uniform(0, 10, N))
    resume = np.where(rng.random(N) < 0.3, np.inf, rng.uniform(0, 10, N))
    b, integ, pe, a, d = cap_step_arrays(brake, integral, prev, p, cruise, v, ttc, 0.01, np.where(brake, resume, ttc))
    for i in range(N):
        st = CapState(BRAKE if brake[i] else CRUISE, integral[i], None if np.isnan(prev[i]) else prev[i])
        rv = ThreatView(resume[i]) if brake[i] else None
        st2, a_s, d_s = cap_step(st, p, cruise[i], v[i], ThreatView(ttc[i]), 0.01, rv)
        assert (st2.mode == BRAKE) == b[i]
        np.testing.assert_allclose([a_s, d_s, st2.integral], [a[i], d[i], integ[i]], rtol=RTOL, atol=ATOL)
        assert (st2.prev_error is None) == np.isnan(pe[i])
        if st2.prev_error is not None:
            assert abs(st2.prev_error - pe[i]) <= ATOL


def test_vehicle_arrays_equal_the_scalar_model():
    rng = np.random.default_rng(13)
    lim = VehicleLimits()
    s, v, a = (
        rng.uniform(0, 100, N),
        np.where(rng.random(N) < 0.1, 0.0, rng.uniform(0, 0.2, N) * 60),
        rng.uniform(-9, 4, N),
    )
    cmd = rng.uniform(-12, 6, N)
    s1, v1, a1 = longitudinal_step_arrays(s, v, a, cmd, lim, 0.01)
    for i in range(N):
        st = longitudinal_step(Longitudinal(s[i], v[i], a[i]), cmd[i], lim, 0.01)
        np.testing.assert_allclose([st.s, st.v, st.a], [s1[i], v1[i], a1[i]], rtol=RTOL, atol=ATOL)
