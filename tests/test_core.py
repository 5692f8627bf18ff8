# ruff: noqa: E501  (hand-written OpenDRIVE keeps its XML lines whole)
"""The compiled core's own answers, against closed forms and hand-made roads: projection onto an arc,
the lane a road user is in across lane sections (links, a lane that ends, a lane that narrows to
nothing), a single-vertex trajectory, and one clear error for a wrong call."""

from __future__ import annotations

import math
from array import array

import pytest

from vei_scenario.core import _core
from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter.entities import Polyline
from vei_scenario.roads.road_model import RoadNetwork

ARC_ROAD = """<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" length="100" junction="-1"><planView>
  <geometry s="0" x="0" y="0" hdg="0" length="100"><arc curvature="0.01"/></geometry></planView>
  <lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
    <right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
  </laneSection></lanes></road></OpenDRIVE>"""

# section 1 (0..40 m): lanes -1, -2 (-1 links to -1, -2 links to -2); section 2 (40..80 m): lane -2
# narrows from 3 m to nothing; section 3 (80..120 m): only lane -1
SECTIONS_ROAD = """<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" length="120" junction="-1"><planView>
  <geometry s="0" x="0" y="0" hdg="0" length="120"><line/></geometry></planView>
  <lanes>
    <laneSection s="0"><center><lane id="0" type="none"/></center><right>
      <lane id="-1" type="driving"><link><successor id="-1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
      <lane id="-2" type="driving"><link><successor id="-2"/></link><width sOffset="0" a="3" b="0" c="0" d="0"/></lane>
    </right></laneSection>
    <laneSection s="40"><center><lane id="0" type="none"/></center><right>
      <lane id="-1" type="driving"><link><predecessor id="-1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
      <lane id="-2" type="driving"><link><predecessor id="-2"/></link><width sOffset="0" a="3" b="-0.075" c="0" d="0"/></lane>
    </right></laneSection>
    <laneSection s="80"><center><lane id="0" type="none"/></center><right>
      <lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
    </right></laneSection>
  </lanes></road></OpenDRIVE>"""


def _road(tmp_path, text: str):
    path = tmp_path / "r.xodr"
    path.write_text(text)
    return RoadNetwork.load(path).road("1")


def test_a_point_off_an_arc_projects_to_its_angle_and_radius(tmp_path):
    road = _road(tmp_path, ARC_ROAD)
    r = 100.0  # the arc's centre is at (0, 100)
    for angle, offset in ((0.2, -1.75), (0.5, -1.0), (0.8, 0.5)):
        radius = r - offset  # t > 0 is to the left: towards the centre
        x, y = radius * math.sin(angle), r - radius * math.cos(angle)
        s, t, along, dist, lane = road.core.locate(x, y)
        assert s == pytest.approx(r * angle, abs=1e-6) and t == pytest.approx(offset, abs=1e-6)
        assert along == pytest.approx(0.0, abs=1e-6) and dist == pytest.approx(abs(offset), abs=1e-6)
        assert lane == (-1 if -3.5 <= offset <= 0 else None)


def test_the_lane_across_sections_follows_links_ends_and_merges(tmp_path):
    road = _road(tmp_path, SECTIONS_ROAD)
    assert road.lane_on(10.0, 50.0, -2, True) == -2  # linked on into section 2
    assert road.lane_on(10.0, 50.0, -1, True) == -1
    # lane -2 narrows to nothing at s = 80: just before, it is still there (0.0375 m wide) ...
    assert road.lane_on(50.0, 79.5, -2, True) == -2
    # ... and in section 3 it no longer exists: the nearest lane on its side
    assert road.lane_on(50.0, 90.0, -2, True) == -1
    # entering the road (not the same road) at s = 90 in lane -2: no links passed, the lane ends
    assert road.lane_on(0.0, 90.0, -2, False) == -1


def test_a_lane_narrowed_to_nothing_moves_over_to_the_nearest_driving_lane(tmp_path):
    text = SECTIONS_ROAD.replace('a="3" b="-0.075"', 'a="0" b="0"')  # lane -2 of section 2 has no width
    road = _road(tmp_path, text)
    assert road.lane_on(10.0, 50.0, -2, True) == -1


def test_a_timed_trajectory_of_one_vertex_stays_there():
    line = Polyline([3.0], [4.0], [0.5], [2.0])
    for t in (0.0, 2.0, 10.0):
        assert line.at_time(t) == (3.0, 4.0, 0.5)
        assert line.s_at_time(t) == 0.0


def test_exit_speed_carries_a_timed_trajectory_on_past_its_end():
    line = Polyline([0.0, 10.0], [0.0, 0.0], [0.0, 0.0], [0.0, 1.0])
    assert line.at_time(2.0)[0] == pytest.approx(20.0)  # the last segment's 10 m/s
    line.exit_speed = 4.0
    assert line.at_time(2.0)[0] == pytest.approx(14.0) and line.s_at_time(2.0) == pytest.approx(14.0)


def test_wrong_calls_are_one_clear_error():
    with pytest.raises(TypeError, match="takes 6 arguments"):
        _core.time_to_conflict((0, 0, 0, 4, 2), 1.0)
    with pytest.raises(TypeError):
        _core.overlapping([1.0, 2.0])
    with pytest.raises(AttributeError):
        _core.entity_boxes([object()])
    boxes = array("d", [0, 0, 0, 4, 2, 3, 0, 0, 4, 2, 10, 0, 0, 4, 2]).tobytes()
    assert _core.overlapping(boxes) == [(0, 1)]


def test_lane_ids_far_apart_are_answered_from_the_lanes_there_are(tmp_path):
    """Lane -1000000 beside lane -1 (the ids between missing, as a careless or hostile file may have):
    its inner border is lane -1's outer one, found from the lanes the section has rather than by
    walking every id in between; an id beyond ±1 000 000 is refused in one line naming it."""
    lane = '<lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>'
    far = '<lane id="{}" type="driving"><width sOffset="0" a="2" b="0" c="0" d="0"/></lane>'
    road = _road(tmp_path, ARC_ROAD.replace(lane, lane + far.format(-1000000)))
    assert road.lane_borders(10.0, -1000000) == (-3.5, -5.5)
    path = tmp_path / "far.xodr"
    path.write_text(ARC_ROAD.replace(lane, lane + far.format(-5000000000)))
    with pytest.raises(VeiInputError, match=r"lane id -5000000000 \(line \d+\) is out of range"):
        RoadNetwork.load(path)


def _trapezoid_clothoid(x0, y0, h0, k, rate, length, fine=0.005, keep=10):
    """The trapezoid rule on an even grid, written with numpy: the reference the core's sampling of a
    trajectory clothoid is held to, bit for bit."""
    import numpy as np

    n = max(2, math.ceil(length / fine) + 1)
    s = np.linspace(0.0, length, n)
    kept = np.arange(0, n, keep)
    if kept[-1] != n - 1:
        kept = np.append(kept, n - 1)
    if k == 0.0 and rate == 0.0:
        return list(x0 + math.cos(h0) * s[kept]), list(y0 + math.sin(h0) * s[kept]), [h0 + 0.0] * len(kept)
    h = h0 + k * s + 0.5 * rate * s * s
    out = []
    for start, f in ((x0, np.cos(h)), (y0, np.sin(h))):
        v = np.concatenate(([0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(s))))
        out.append(list(start + v[kept]))
    return out[0], out[1], list(h[kept])


def _doubles(raw: bytes) -> list[float]:
    a = array("d")
    a.frombytes(raw)
    return a.tolist()


@pytest.mark.parametrize("seed", range(4))
def test_a_trajectory_clothoid_is_the_trapezoid_rule_on_its_grid(seed):
    """Straight lines, arcs and clothoids of random start, curvature and length (a length of a few
    fine steps, of a whole number of kept points and not): the core's points equal the numpy
    reference's to the last bit, the last one its end."""
    import random

    rnd = random.Random(seed)
    for _ in range(150):
        x0, y0, h0 = rnd.uniform(-1e3, 1e3), rnd.uniform(-1e3, 1e3), rnd.uniform(-7.0, 7.0)
        k = rnd.choice([0.0, rnd.uniform(-0.2, 0.2)])
        rate = rnd.choice([0.0, rnd.uniform(-0.01, 0.01)])
        length = rnd.choice([rnd.uniform(1e-6, 0.1), rnd.uniform(0.1, 200.0), 0.05 * rnd.randint(1, 400)])
        got = [_doubles(raw) for raw in _core.clothoid(x0, y0, h0, k, rate, length, 0.005, 10)]
        assert got == list(_trapezoid_clothoid(x0, y0, h0, k, rate, length))


def test_a_clothoid_call_out_of_range_is_refused():
    for bad in ((0, 0, 0, 0.1, 0, 0.0), (0, 0, 0, 0.1, 0, -1.0), (0, 0, 0, 0.1, 0, 1e9), (0, 0, math.nan, 0, 0, 1)):
        with pytest.raises(ValueError, match="clothoid"):
            _core.clothoid(*bad, 0.005, 10)


def test_a_step_is_measured_by_the_libraries_hypot():
    """The core measures a step (the odometer) with the C library's hypot, which numpy's hypot also
    calls; the interpreter's own steps call the same function (_core.hypot)."""
    import numpy as np

    rnd = np.random.default_rng(7)
    xy = rnd.uniform(-50, 50, (20000, 2)) * 10.0 ** rnd.integers(-4, 3, (20000, 1))
    assert [_core.hypot(x, y) for x, y in xy] == list(np.hypot(xy[:, 0], xy[:, 1]))


@pytest.mark.parametrize(
    "shape, closed_form",
    [
        ("linear", lambda x: x),
        ("cubic", lambda x: x * x * (3 - 2 * x)),
        ("sinusoidal", lambda x: 0.5 * (1 - math.cos(math.pi * x))),
        ("step", lambda x: x),  # (any other shape: linear)
    ],
)
def test_a_transition_has_the_shape_the_standard_names(shape, closed_form):
    """The interpreter's transitions (SpeedAction, lane change, lane offset) take the core's shape:
    0 at the start, 1 at the end, the closed form between."""
    from vei_scenario.interpreter.entities import transition_fraction

    xs = [k / 64 for k in range(65)]
    assert [transition_fraction(shape, x) for x in xs] == pytest.approx([closed_form(x) for x in xs], abs=1e-15)
    assert transition_fraction(shape, 0.0) == 0.0 and transition_fraction(shape, 1.0) == 1.0


@pytest.mark.parametrize("shape", ["linear", "cubic", "sinusoidal"])
def test_a_speed_transition_runs_from_its_start_speed_to_its_target(shape):
    """SpeedProfile.speed (the core's transition_speed): v0 until it starts, v1 from its end on, the
    shape between; a transition without a duration is at v1 at once."""
    from vei_scenario.interpreter.entities import SpeedProfile, transition_fraction

    p = SpeedProfile(v0=4.0, v1=16.0, t0=2.0, duration=3.0, shape=shape)
    assert p.speed(0.0) == (4.0, False) and p.speed(2.0) == (4.0, False)
    assert p.speed(5.0) == (16.0, True) and p.speed(9.0) == (16.0, True)
    for t in (2.3, 3.5, 4.9):
        v, over = p.speed(t)
        assert not over and v == pytest.approx(4.0 + 12.0 * transition_fraction(shape, (t - 2.0) / 3.0), abs=1e-12)
    assert SpeedProfile(v0=4.0, v1=-2.0, t0=1.0, duration=0.0, shape=shape).speed(0.5) == (-2.0, True)


@pytest.mark.parametrize("coupler", [3.5, -1.2])
def test_a_pulled_trailer_keeps_its_rod_and_faces_the_hitch(coupler):
    """towed_pose (trailers.pull and the core's steps): after any move of the tow, the trailer's
    coupler is on the hitch again, its axle at the rod's length from it along its new heading; with the
    hitch where the axle is, it keeps its heading."""
    import numpy as np

    rnd = np.random.default_rng(3)
    for tx, ty, tyaw, x, y, yaw in rnd.uniform(-20, 20, (200, 6)):
        hitch = -2.0
        nx, ny, nyaw = _core.towed_pose(tx, ty, tyaw, hitch, coupler, x, y, yaw)
        hx, hy = tx + hitch * math.cos(tyaw), ty + hitch * math.sin(tyaw)
        assert nx + coupler * math.cos(nyaw) == pytest.approx(hx, abs=1e-9)
        assert ny + coupler * math.sin(nyaw) == pytest.approx(hy, abs=1e-9)
        # the axle moved along the line from where it was towards the hitch (no sideways slip)
        cross = (hx - x) * (ny - y) - (hy - y) * (nx - x)
        assert cross == pytest.approx(0.0, abs=1e-7 * (1 + math.hypot(hx - x, hy - y) ** 2))
    assert _core.towed_pose(0.0, 0.0, 0.0, -2.0, coupler, -2.0, 0.0, 0.7)[2] == 0.7


def test_a_timed_path_step_replays_or_follows_within_its_limits():
    """timed_step (engine's timed paths and the core's): in position mode the trajectory's pose and the
    speed that covers the arc; in follow mode at most max_accel / max_decel, never past the end."""
    line = Polyline([0.0, 100.0], [0.0, 0.0], [0.0, 0.0], [0.0, 10.0])  # 10 m/s along x
    x, y, yaw, s, v, a = line.core.timed_step(2.0, 15.0, 10.0, False, 5.0, 5.0, 0.1)
    assert (x, y, yaw, s) == (20.0, 0.0, 0.0, 20.0) and v == pytest.approx(50.0) and a == pytest.approx(400.0)
    # follow: 5 m behind the timed point, at 10 m/s: it speeds up at its limit
    x, y, yaw, s, v, a = line.core.timed_step(2.0, 15.0, 10.0, True, 3.0, 6.0, 0.1)
    assert a == 3.0 and v == pytest.approx(10.3) and s == pytest.approx(15.0 + 0.5 * (10.0 + 10.3) * 0.1)
    assert x == pytest.approx(s)
    # ahead of the timed point: it brakes at its limit, never below standstill
    assert line.core.timed_step(1.0, 50.0, 0.2, True, 3.0, 6.0, 0.1)[4:] == (0.0, -6.0)
    # never past the path's end
    assert line.core.timed_step(20.0, 99.9, 30.0, True, 3.0, 6.0, 0.1)[3] == 100.0
    with pytest.raises(ValueError, match="no vertex times"):
        Polyline([0.0, 1.0], [0.0, 0.0], [0.0, 0.0], [None, None]).core.timed_step(1.0, 0.0, 0.0, False, 1, 1, 0.1)


def test_the_gap_spring_is_critically_damped_within_its_limits():
    """spring_step (LongitudinalDistance's and the core's): with room to act, the gap's error e obeys
    e'' + 2w e' + w^2 e = 0 (w^2 = 0.4 x the permitted acceleration), whose closed form is
    (e0 + (e0' + w e0) t) exp(-w t); the acceleration stays within its limits and rates."""
    inf = math.inf
    a_max = 10.0
    w = math.sqrt(0.4 * a_max)
    dt, error = 1e-4, 2.0  # 2 m too far behind, at the reference's speed (the spring's pull: 0.8 a_max)
    speed, ref, last = 20.0, 20.0, 0.0
    for k in range(1, 30001):
        last, speed = _core.spring_step(error, speed, ref, a_max, a_max, inf, inf, last, inf, dt)
        error -= (speed - ref) * dt  # (the gap shrinks as it goes faster than its reference)
        if k % 5000 == 0:
            t = k * dt
            assert error == pytest.approx((2.0 + w * 2.0 * t) * math.exp(-w * t), abs=2e-3)
    # at the gap and at the reference's speed: nothing changes
    assert _core.spring_step(0.0, 12.0, 12.0, 3.0, 5.0, inf, inf, 0.0, 40.0, 0.1) == (0.0, 12.0)
    # far too close: braking at most max_decel, grown from the last acceleration at most decel_rate * dt
    acc, v = _core.spring_step(-50.0, 12.0, 12.0, 3.0, 5.0, 2.0, 4.0, -1.0, 40.0, 0.1)
    assert acc == pytest.approx(-1.4) and v == pytest.approx(12.0 - 0.14)
    assert _core.spring_step(-50.0, 12.0, 12.0, 3.0, 5.0, inf, inf, 0.0, 40.0, 0.1)[0] == -5.0
    # far too far: never faster than max_speed; in Init (dt 0) the acceleration does not grow and the speed stays
    assert _core.spring_step(80.0, 12.0, 12.0, 3.0, 5.0, inf, inf, 0.0, 12.1, 0.1) == (3.0, 12.1)
    assert _core.spring_step(80.0, 12.0, 12.0, 3.0, 5.0, 2.0, 2.0, 0.5, 40.0, 0.0) == (0.5, 12.0)


def test_the_gap_along_a_heading_is_between_the_boxes_projected_corners():
    """heading_gap (LongitudinalDistance's and the core's): between reference points, the offset along
    a's heading; with freespace, the gap between the two boxes' corners projected on that axis (0 where
    they overlap), against a corner-by-corner reference."""
    from types import SimpleNamespace

    import numpy as np

    def corners_along(e, c, s):
        bx, by = e.x + math.cos(e.yaw) * e.center_x, e.y + math.sin(e.yaw) * e.center_x
        u = np.array([math.cos(e.yaw), math.sin(e.yaw)])
        v = np.array([-u[1], u[0]])
        pts = [np.array([bx, by]) + i * 0.5 * e.length * u + j * 0.5 * e.width * v for i in (-1, 1) for j in (-1, 1)]
        return [c * p[0] + s * p[1] for p in pts]

    rnd = np.random.default_rng(11)
    for x, y, yaw, cx, ln, w, x2, y2, yaw2, cx2, ln2, w2 in rnd.uniform(-1, 1, (500, 12)):
        a = SimpleNamespace(x=20 * x, y=20 * y, yaw=3 * yaw, center_x=cx, length=3 + ln, width=1.5 + w / 2)
        b = SimpleNamespace(x=20 * x2, y=20 * y2, yaw=3 * yaw2, center_x=cx2, length=3 + ln2, width=1.5 + w2 / 2)
        c, s = math.cos(a.yaw), math.sin(a.yaw)
        assert _core.heading_gap(a, b, False) == pytest.approx(c * (b.x - a.x) + s * (b.y - a.y), abs=1e-12)
        pa, pb = corners_along(a, c, s), corners_along(b, c, s)
        want = min(pb) - max(pa) if max(pa) < min(pb) else max(pb) - min(pa) if max(pb) < min(pa) else 0.0
        assert _core.heading_gap(a, b, True) == pytest.approx(want, abs=1e-9)
    with pytest.raises(AttributeError):
        _core.heading_gap(object(), object(), True)


def test_advancing_along_a_path_stops_at_its_end_and_faces_back_when_reversing():
    """advance (motion.advance_along, the timed follow step and the core's path step): ds metres on
    along the path, never past its end; reversing, back along it facing against it."""
    line = Polyline([0.0, 10.0, 10.0], [0.0, 0.0, 10.0], [0.0, 0.0, 0.0], [None, None, None])
    assert line.core.advance(4.0, 3.0, False) == (7.0, 0.0, 0.0, 7.0)
    assert line.core.advance(8.0, 5.0, False) == (10.0, 3.0, 0.0, 13.0)  # round the corner, 3 m up
    assert line.core.advance(18.0, 7.0, False) == (10.0, 10.0, 0.0, 20.0)  # not past the end
    x, y, yaw, s = line.core.advance(7.0, 2.0, True)
    assert (x, y, s) == (5.0, 0.0, 5.0) and abs(yaw) == pytest.approx(math.pi)
