"""The pure models against analytic solutions and independent references."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely

from vei_scenario.core import _core
from vei_scenario.models.boxes import time_to_contact
from vei_scenario.models.cap import BRAKE, CRUISE, CapParameters, CapState, ThreatView, cap_step
from vei_scenario.models.rider import ROUTE_EXTENSION_M, WAYPOINT_SPACING_M
from vei_scenario.models.sfm import SfmParameters, SfmState, sfm_step
from vei_scenario.models.vehicle import Longitudinal, VehicleLimits, longitudinal_step


def test_sfm_without_ego_converges_to_v0_towards_its_destination():
    p = SfmParameters(v0_mps=4.5)
    state = SfmState(0.0, 0.0, 0.0, 0.0)
    dest = [(600.0, 800.0)]  # 1 km away, bearing atan2(800, 600)
    for _ in range(1500):  # 15 s
        state = sfm_step(state, dest, p, True, None, 0.01)
    speed = math.hypot(state.vx, state.vy)
    # v_des = v0 d / sqrt(d² + σ²) differs from v0 by < 1e-6 this far from the destination
    assert speed == pytest.approx(4.5, rel=1e-3)
    assert math.atan2(state.vy, state.vx) == pytest.approx(math.atan2(800, 600), abs=1e-4)


def test_sfm_relaxation_matches_the_first_order_solution():
    """Far from the destination and below the limits, m dv/dt = k (v0 − v): v(t) = v0 (1 − e^(−t/τ))."""
    p = SfmParameters(v0_mps=4.0, tau_s=0.5, max_accel_mps2=100.0, max_decel_mps2=100.0)
    state = SfmState(0.0, 0.0, 0.0, 0.0)
    for _ in range(50):
        state = sfm_step(state, [(1e5, 0.0)], p, False, None, 0.001)
    assert state.vx == pytest.approx(4.0 * (1 - math.exp(-0.05 / 0.5)), rel=2e-3)


def test_aggressive_rider_without_ego_stays_within_1m_of_its_route(compiled):
    track = compiled["case_study"].reconstruction.scooters["scooter_1"].trajectory
    route_line = shapely.LineString(track.xy)
    length = route_line.length
    n = max(1, int(length // WAYPOINT_SPACING_M))
    route = [tuple(route_line.interpolate(length * (i + 1) / n).coords[0]) for i in range(n)]
    h = track.yaw[-1]
    route.append((track.x[-1] + ROUTE_EXTENSION_M * math.cos(h), track.y[-1] + ROUTE_EXTENSION_M * math.sin(h)))
    p = SfmParameters(v0_mps=float(np.median(track.speed)))
    state = SfmState(
        track.x[0], track.y[0], track.speed[0] * math.cos(track.yaw[0]), track.speed[0] * math.sin(track.yaw[0])
    )
    worst = 0.0
    for _ in range(int((track.t[-1] - track.t[0]) / 0.01)):
        state = sfm_step(state, route, p, False, None, 0.01)
        worst = max(worst, route_line.distance(shapely.Point(state.x, state.y)))
    assert worst <= 1.0, worst


def test_repulsion_pushes_the_normal_rider_away_from_the_ego():
    p = SfmParameters()
    ego_box = (0.0, 0.0, 0.0, 4.8, 1.9)  # ego at the origin, facing +x
    s = SfmState(0.0, 2.5, 4.0, 0.0)  # rider passing 1.55 m beside the ego's side
    pushed = sfm_step(s, [(100.0, 2.5)], p, True, ego_box, 0.01)
    free = sfm_step(s, [(100.0, 2.5)], p, False, ego_box, 0.01)
    assert pushed.vy > free.vy + 1e-3  # pushed in +y, away from the box side


@pytest.mark.parametrize("v0, a_max, jerk", [(10.0, 6.0, 50.0), (5.6, 6.0, 50.0), (20.0, 8.0, 1e9), (3.0, 2.0, 20.0)])
def test_braking_distance_matches_the_analytic_stop(v0, a_max, jerk):
    limits = VehicleLimits(max_accel_mps2=4.0, max_decel_mps2=a_max, jerk_max_mps3=jerk)
    st = Longitudinal(0.0, v0, 0.0)
    for _ in range(100_000):
        st = longitudinal_step(st, -a_max, limits, 0.01)
        if st.v == 0.0:
            break
    # Jerk ramp to a_max over T = a/j, then constant deceleration: s = v T − j T³/6 + v1²/(2a).
    T = min(a_max / jerk, v0 / a_max)
    v1 = v0 - 0.5 * jerk * T * T
    analytic = v0 * T - jerk * T**3 / 6 + v1 * v1 / (2 * a_max)
    assert st.s == pytest.approx(analytic, rel=0.01)
    if jerk > 1e6:
        assert st.s == pytest.approx(v0 * v0 / (2 * a_max), rel=0.01)


def test_ttc_agrees_with_analytic_crossing_geometry():
    rng = np.random.default_rng(3)
    for _ in range(200):
        v_e, v_s = rng.uniform(3, 15), rng.uniform(1, 6)
        gap_x, gap_y = rng.uniform(10, 60), rng.uniform(5, 40)
        le, we, ls, ws = 4.8, 1.9, 1.2, 0.6
        # Ego along +x from the origin; scooter along +y at x = gap_x, starting at y = −gap_y.
        # Contact needs |x_rel| ≤ (le + ws)/2 and |y_rel| ≤ (we + ls)/2 at the same time.
        tx = ((gap_x - (le + ws) / 2) / v_e, (gap_x + (le + ws) / 2) / v_e)
        ty = ((gap_y - (we + ls) / 2) / v_s, (gap_y + (we + ls) / 2) / v_s)
        lo, hi = max(tx[0], ty[0]), min(tx[1], ty[1])
        expected = lo if lo <= hi else math.inf
        got = float(time_to_contact(0, 0, 0, le, we, v_e, 0, gap_x, -gap_y, math.pi / 2, ls, ws, 0, v_s))
        scalar = _core.time_to_contact((0, 0, 0, le, we), v_e, 0, (gap_x, -gap_y, math.pi / 2, ls, ws), 0, v_s)
        assert got == pytest.approx(expected, abs=1e-9) or (math.isinf(got) and math.isinf(expected))
        assert scalar == pytest.approx(got, abs=1e-12) or (math.isinf(scalar) and math.isinf(got))


def test_cap_brakes_below_d_safe_and_resumes_when_clear():
    p = CapParameters()
    v = 5.6
    d_safe = v * v / (2 * p.a_max_mps2) + v * p.t_h_s + p.d0_m
    assert p.d_safe_m(v) == pytest.approx(d_safe)
    # Conflict 3 s ahead: gap = 16.8 m > d_safe: keep cruising.
    st, a, _ = cap_step(CapState(), p, 5.6, v, ThreatView(3.0), 0.01)
    assert st.mode == CRUISE and abs(a) < 1e-9
    # Conflict 1 s ahead: gap 5.6 m < d_safe: brake to stop d0 short: a = v²/(2 (gap − d0)), capped.
    st, a, _ = cap_step(CapState(), p, 5.6, v, ThreatView(1.0), 0.01)
    assert st.mode == BRAKE and a == pytest.approx(-min(p.a_max_mps2, v * v / (2 * (5.6 - p.d0_m))))
    # Clear at cruise speed: resume and accelerate back towards the cruise speed.
    st, a, _ = cap_step(st, p, 5.6, 2.0, ThreatView(math.inf), 0.01, ThreatView(math.inf))
    assert st.mode == CRUISE and a > 0


def test_speed_loop_of_the_default_gains_is_stable_and_well_damped():
    from vei_scenario.models.cap_analysis import analyse_speed_loop

    loop = analyse_speed_loop()
    assert loop.stable and np.all(loop.poles.real < 0)
    assert loop.overshoot_pct < 5.0 and loop.settling_time_s < 5.0
    assert loop.steady_state_error < 1e-9
    # The analysis can fail: a negative gain destabilises the loop.
    assert not analyse_speed_loop(CapParameters(kp=-1.0)).stable


def test_braking_to_a_standstill_keeps_within_the_jerk_limit():
    """Full braking from 5 m/s: the deceleration eases off before the stop, so the vehicle comes to
    rest with the acceleration back at zero and every step's change of acceleration within j·dt."""
    from vei_scenario.models.vehicle import Longitudinal, VehicleLimits, longitudinal_step

    lim, dt = VehicleLimits(), 0.01
    st, accel = Longitudinal(0.0, 5.0, 0.0), [0.0]
    for _ in range(400):
        st = longitudinal_step(st, -lim.max_decel_mps2, lim, dt)
        accel.append(st.a)
    jerk = np.abs(np.diff(accel)) / dt
    assert st.v == 0.0 and st.a == 0.0 and jerk.max() <= lim.jerk_max_mps3 * (1 + 1e-9)
    assert min(accel) == pytest.approx(-lim.max_decel_mps2)  # it still brakes fully on the way


def test_circle_prefilters_never_hide_a_conflict_or_a_contact():
    """The planner leaves out the corridor box test where the circumscribed circles stay apart beyond
    its horizon (the core's time_to_conflict with a horizon, as vei run and the sweep kernel decide),
    and collision checks where the circles are apart: on 20 000 random states (many near the edge of
    the filters) the filtered time equals the box test's wherever that is within the horizon, and no
    contact is skipped."""
    from vei_scenario.models.boxes import boxes_overlap

    rng = np.random.default_rng(12)
    horizon, margin = 6.0, 0.5
    skipped = kept = 0
    for _ in range(20_000):
        ego = (*rng.uniform(-5, 5, 2), rng.uniform(-math.pi, math.pi), 4.6, 1.9)
        dist = rng.uniform(0, 60)
        ang = rng.uniform(-math.pi, math.pi)
        threat = (ego[0] + dist * math.cos(ang), ego[1] + dist * math.sin(ang), rng.uniform(-3.2, 3.2), 1.8, 0.7)
        v_ego, v_threat = rng.uniform(0, 15), tuple(rng.uniform(-7, 7, 2))
        full = _core.time_to_conflict(ego, v_ego, margin, threat, *v_threat)
        within = _core.time_to_conflict(ego, v_ego, margin, threat, *v_threat, horizon)
        if within == math.inf and full != math.inf:
            skipped += 1  # the circles said beyond the horizon: so must the boxes
            assert full > horizon
        else:
            kept += 1
            assert within == full
        reach = 0.5 * (math.hypot(ego[3], ego[4]) + math.hypot(threat[3], threat[4]))
        if math.hypot(threat[0] - ego[0], threat[1] - ego[1]) > reach:
            assert not boxes_overlap(*ego, *threat)
    assert skipped > 50 and kept > 2_000  # both sides of the filter are exercised (100 and 19 900 here)


def test_the_cores_collision_check_equals_the_vectorised_box_model_on_random_states():
    """vei run's collision check (the compiled core: every pair, circle prefilter, separating axes)
    finds exactly the pairs the numpy box model says overlap, on 300 random scenes of 12 boxes
    (many just touching or just apart)."""
    from array import array

    from vei_scenario.core import _core
    from vei_scenario.models.boxes import boxes_overlap

    rng = np.random.default_rng(24)
    found = 0
    for _ in range(300):
        n = 12
        boxes = np.column_stack(
            [
                rng.uniform(-8, 8, n),
                rng.uniform(-8, 8, n),
                rng.uniform(-4, 4, n),
                rng.uniform(0.3, 6, n),
                rng.uniform(0.3, 2.5, n),
            ]
        )
        got = set(_core.overlapping(array("d", boxes.ravel()).tobytes()))
        want = {(i, j) for i in range(n) for j in range(i + 1, n) if boxes_overlap(*boxes[i], *boxes[j])}
        assert got == want
        found += len(want)
    assert found > 300  # overlapping and separate pairs both occur


def test_the_vectorised_box_distance_and_contact_time_equal_the_cores():
    """The numpy box model kept for whole-run metrics gives what the core gives the interpreter's
    conditions and guards (box distance, time to contact), on random pairs near and far, touching and
    apart; and the distance is 0 exactly where the boxes overlap."""
    from vei_scenario.core import _core
    from vei_scenario.models.boxes import box_distance, boxes_overlap, time_to_contact

    rng = np.random.default_rng(31)
    hits = touching = 0
    for v in rng.uniform(-1, 1, (4000, 14)):
        a = (8 * v[0], 8 * v[1], 4 * v[2], 3 + 2 * v[3], 1.5 + v[4] / 2)
        b = (8 * v[5], 8 * v[6], 4 * v[7], 3 + 2 * v[8], 1.5 + v[9] / 2)
        d = _core.box_distance(a, b)
        assert d == pytest.approx(float(box_distance(*a, *b)), abs=1e-12)
        assert (d == 0.0) == bool(boxes_overlap(*a, *b))
        touching += d == 0.0
        ttc = _core.time_to_contact(a, 10 * v[10], 10 * v[11], b, 10 * v[12], 10 * v[13])
        want = float(time_to_contact(*a, 10 * v[10], 10 * v[11], *b, 10 * v[12], 10 * v[13]))
        assert ttc == pytest.approx(want, rel=1e-12, abs=1e-12) or ttc == want == math.inf
        hits += math.isfinite(ttc) and ttc > 0
    assert touching > 100 and hits > 100
