"""Lane changes stepped as esmini 3.6 steps them, against esmini itself: the heading from the lateral rate
where a step starts (over time asin(rate / speed), over distance atan of the rate per metre), s moved by
the along-road part of the step taken at the offset the step brings the car to, a change over distance
progressing by those along-road parts, and a car that changes speed while it changes lanes stepping at
the speed its step began with when the SpeedAction comes after the lane change in the storyboard (esmini
steps running actions in document order) and at its new speed when it comes before.

Before, vei headed along each step's displacement and measured a change over distance by its odometer:
2-8 mm off on these, 6 cm on esmini's lane_change_simple. The quiet stretches of the core give the same
runs bit for bit."""

from __future__ import annotations

import numpy as np
import pytest
from test_cruise import assert_identical, run_both
from test_cruise_lateral import CASES, _event, _time, scenario
from xosc_parts import speed_action

from vei_scenario.interpreter import run_scenario

LANE_CHANGES = sorted(name for name in CASES if not name.startswith("lane_offset"))


def _against_esmini(esmini, path):
    from vei_scenario.conformance.esmini import compare_runs, run_esmini

    c = compare_runs(run_scenario(path, {}, 0.01), run_esmini(esmini, path, 0.01))
    assert c.entities and not c.notes, c.notes
    return c


@pytest.mark.parametrize("case", LANE_CHANGES)
def test_a_lane_change_follows_esmini_to_two_millimetres(tmp_path, esmini, case):
    action, start = CASES[case]
    c = _against_esmini(esmini, scenario(tmp_path, action, start))
    ego = next(e for e in c.entities if e.entity == "Ego")
    assert ego.max_deviation_m <= 2e-3, (case, ego)


def accelerating(tmp_path, speed_first: bool):
    """The Ego changes lanes (sinusoidal, 3 s from 1 s) while it speeds up from 14 to 20 m/s (from
    1.5 s over 3 s); the SpeedAction's event before or after the lane change's in the storyboard."""
    action, start = CASES["sinusoidal_time"]
    path = scenario(tmp_path, action, start)
    speed = _event("Faster", "Ego", speed_action(20.0, "linear", 3.0), _time(1.5))
    text = path.read_text()
    if speed_first:
        text = text.replace('<Act name="a">', '<Act name="a">' + speed, 1)
    else:
        i = text.index("</ManeuverGroup>", text.index('name="Shiftg"')) + len("</ManeuverGroup>")
        text = text[:i] + speed + text[i:]
    path.write_text(text)
    return path


@pytest.mark.parametrize("speed_first", [True, False])
def test_changing_speed_while_changing_lanes_follows_esmini(tmp_path, esmini, speed_first):
    c = _against_esmini(esmini, accelerating(tmp_path, speed_first))
    ego = next(e for e in c.entities if e.entity == "Ego")
    assert ego.max_deviation_m <= 2e-3, ego


@pytest.mark.parametrize("speed_first", [True, False])
def test_the_storyboard_order_decides_the_speed_of_a_lane_change_step(tmp_path, monkeypatch, speed_first):
    """Without esmini: the order changes where the Ego is (a step's speed difference each step of the
    lane change), and the core's quiet steps take it as the interpreter does."""
    fast, cruised, slow = run_both(accelerating(tmp_path, speed_first), monkeypatch)
    assert_identical(fast, slow)
    assert cruised > 0.9 * len(fast.t)
    (tmp_path / "other").mkdir()
    other = run_scenario(accelerating(tmp_path / "other", not speed_first))
    gap = np.max(np.abs(fast.traces["Ego"].x - other.traces["Ego"].x))
    assert 0.01 < gap < 0.2, gap  # (2 m/s² × 0.01 s per step over the 2.5 s both run: about 5 cm)


#: esmini's own examples with lane changes, and how close each now plays to esmini (before, 0.04-0.09 m
#: on most of them; lane_change_simple keeps 0.012 m late in its 150 s run, after its car is teleported
#: back to the start of the road and changes lanes again, not analysed further).
CLOSE = {"two_plus_one_road": 1e-4, "velodrome": 1e-4, "light_state": 1e-4, "lane_change_crest": 1e-3,
         "lane_change": 1e-3, "cut-in": 5e-3, "lane_change_simple": 0.02, "cut-in_simple": 1e-4,
         "cut-in_visibility": 5e-3}  # fmt: skip


@pytest.mark.parametrize("name", sorted(CLOSE))
def test_esminis_lane_change_examples_play_within_millimetres(esmini, name):
    path = esmini.parents[1] / "xosc" / f"{name}.xosc"
    if not path.is_file():
        pytest.skip(f"{path} not shipped beside esmini")
    c = _against_esmini(esmini, path)
    assert c.max_deviation_m <= CLOSE[name], c.entities
