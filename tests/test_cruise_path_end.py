"""A road user whose untimed path has ended, with no road to drive on along: the step that reaches the
end goes on past it at the end's heading (engine._motion: "on past the end"), and then the road user
stands there, its speed 0, as esmini 3.6 leaves it (measured against esmini here). The core takes the
steps after it; before, it handed every one back to the interpreter (esmini's trailer_connect: a car
reversing onto a trailer ran 15 ms instead of 2).

Checked as the other quiet-stretch tests are: the run equals the stepped interpreter's bit for bit
while the core takes most steps, forwards and reversing; and where the road user stands is worked out
here from the path's last vertex and heading."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_cruise import assert_identical
from test_cruise_distances import _run_both
from xosc_parts import CAR, follow_trajectory, teleport

from vei_scenario.interpreter import run_scenario


def _polyline(points) -> str:
    vertices = "".join(f'<Vertex><Position><WorldPosition x="{x}" y="{y}"/></Position></Vertex>' for x, y in points)
    return f"<Polyline>{vertices}</Polyline>"


FORWARD = [(0.0, 0.0), (10.0, 0.0), (20.0, 5.0)]  # (5 m/s: at its end after ~4.2 s)
BACKWARD = [(0.0, 10.0), (15.0, 10.0)]  # (at -3 m/s: reversing along it, its end after 5 s)


def scenario(tmp_path) -> object:
    init = teleport("Fwd", 0, 0, 0, 5.0, follow_trajectory(_polyline(FORWARD)))
    init += teleport("Back", 0, 10, math.pi, -3.0, follow_trajectory(_polyline(BACKWARD)))
    xosc = tmp_path / "path_end.xosc"
    cars = "".join(f'<ScenarioObject name="{n}">{CAR}</ScenarioObject>' for n in ("Fwd", "Back"))
    xosc.write_text(f"""<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork/><Entities>{cars}</Entities><Storyboard><Init><Actions>{init}</Actions></Init>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="10" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup>
</StopTrigger></Storyboard></OpenSCENARIO>""")
    return xosc


def test_past_its_end_the_core_steps_as_the_interpreter(tmp_path, monkeypatch):
    fast, cruised, calls, slow = _run_both(scenario(tmp_path), monkeypatch)
    assert_identical(fast, slow)
    assert cruised > 0.8 * len(fast.t), f"only {cruised} of {len(fast.t)} steps cruised"
    assert calls <= 6, calls


def test_past_its_end_it_stands_where_its_last_step_left_it(tmp_path, monkeypatch):
    """The step that reaches the end goes to the end and the rest of the step straight on at the end's
    heading; then the entity stands, its speed 0 (worked out here from the path: Fwd passes its end
    (10 + √125 m) by what is left of its 5 cm step; Back reaches its 15 m in whole 3 cm steps)."""
    fast, *_ = _run_both(scenario(tmp_path), monkeypatch)
    late = fast.t > 7.0  # (both well past their ends)
    fwd, back = fast.traces["Fwd"], fast.traces["Back"]
    length = 10.0 + math.hypot(10.0, 5.0)
    over = 0.05 * (math.floor(length / 0.05) + 1) - length
    heading = math.atan2(5.0, 10.0)  # (the last segment's)
    np.testing.assert_allclose(fwd.x[late], 20.0 + over * math.cos(heading), atol=1e-6)
    np.testing.assert_allclose(fwd.y[late], 5.0 + over * math.sin(heading), atol=1e-6)
    np.testing.assert_allclose(back.x[late], 15.0, atol=1e-6)  # (facing back, reversing along the path)
    np.testing.assert_allclose(back.y[late], 10.0, atol=1e-9)
    assert np.all(fwd.speed[late] == 0.0) and np.all(back.speed[late] == 0.0)


@pytest.mark.parametrize("dt", [0.01, 0.05])
def test_past_its_end_it_stands_as_in_esmini(tmp_path, esmini, dt):
    """esmini 3.6 leaves the entity where the step that reached the end put it, at speed 0, at any
    step (vei was a step further on at its speed: 0.05 m at 0.01 s, 0.24 m at 0.05 s on esmini's
    truck_with_rotating_axle)."""
    from vei_scenario.conformance.esmini import compare_runs, run_esmini

    path = scenario(tmp_path)
    result = run_scenario(path, {}, dt)
    c = compare_runs(result, run_esmini(esmini, path, dt))
    assert {e.entity for e in c.entities} == {"Fwd", "Back"}
    assert c.max_deviation_m <= 1e-5, c.entities
    fwd = result.traces["Fwd"]
    assert fwd.speed[-1] == 0.0 and fwd.x[-1] > 20.0
