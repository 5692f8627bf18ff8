"""A LanePosition on OpenDRIVE's centre lane (laneId 0): the lane of no width that the road's lanes are
counted from, at the reference line shifted by the road's laneOffset. esmini 3.6 places an entity there
(``offset`` from it, heading along increasing s) and drives it on; vei refused the position ("road 1
has no lane 0"), and with it esmini's own controller_test.xosc, whose stop trigger is a
ReachPositionCondition on lane 0."""

from __future__ import annotations

import pytest
from roads import straight_500m
from xosc_parts import CAR, step_speed

from conftest import SHARED
from vei_scenario.interpreter import run_scenario

XODR = SHARED / "esmini" / "xodr"


def _road(name: str):
    """The generated straight road, or one of esmini's roads (for the tests that compare with esmini)."""
    return straight_500m() if name == "straight_500m.xodr" else XODR / name


def _scenario(tmp_path, road: str, road_id: str, s: float, offset: float, stop: str = "") -> object:
    """A car placed on lane 0 of ``road`` at 5 m/s; stopped at 5 s, or by ``stop`` (a condition)."""
    stop = stop or '<ByValueCondition><SimulationTimeCondition value="5" rule="greaterThan"/></ByValueCondition>'
    xosc = tmp_path / "centre.xosc"
    xosc.write_text(f"""<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork><LogicFile filepath="{_road(road)}"/></RoadNetwork>
<Entities><ScenarioObject name="Car">{CAR}</ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="Car"><PrivateAction><TeleportAction><Position>
<LanePosition roadId="{road_id}" laneId="0" s="{s}" offset="{offset}"/></Position></TeleportAction></PrivateAction>
{step_speed(5.0)}</Private></Actions></Init>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none">{stop}</Condition>
</ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>""")
    return xosc


@pytest.mark.parametrize("offset", [0.0, 0.5, -2.0])
def test_a_car_on_the_centre_lane_is_on_the_reference_line_and_drives_along_it(tmp_path, offset):
    """straight_500m: the reference line is the x axis (no laneOffset), so the car starts at (50,
    offset) heading along x and is 25 m on after 5 s at 5 m/s, still at y = offset."""
    car = run_scenario(_scenario(tmp_path, "straight_500m.xodr", "1", 50.0, offset)).traces["Car"]
    assert (car.x[0], car.y[0], car.yaw[0]) == pytest.approx((50.0, offset, 0.0), abs=1e-9)
    k = int(round(5.0 / 0.01))
    assert (car.x[k], car.y[k]) == pytest.approx((75.0, offset), abs=1e-9)


def test_a_reach_position_condition_on_the_centre_lane_fires(tmp_path):
    """The stop trigger of esmini's controller_test, on lane 0 30 m ahead with a 1 m tolerance."""
    reach = (
        '<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Car"/>'
        '</TriggeringEntities><EntityCondition><ReachPositionCondition tolerance="1.0"><Position>'
        '<LanePosition roadId="1" laneId="0" s="80"/></Position></ReachPositionCondition></EntityCondition>'
        "</ByEntityCondition>"
    )
    result = run_scenario(_scenario(tmp_path, "straight_500m.xodr", "1", 50.0, 0.0, reach))
    assert result.end_reason == "storyboard stop trigger"
    assert result.t[-1] == pytest.approx((30.0 - 1.0) / 5.0 + 0.01, abs=0.011)  # (within 1 m of s = 80)


@pytest.mark.parametrize(
    ("road", "road_id", "s", "offset"),
    [("soderleden.xodr", "0", 20.0, 0.0), ("fabriksgatan.xodr", "0", 20.0, -1.0), ("curve_r100.xodr", "0", 200.0, 1.0)],
)
def test_the_centre_lane_is_where_esmini_puts_it(tmp_path, esmini, road, road_id, s, offset):
    """Roads with a laneOffset (soderleden 3.5 m, fabriksgatan 1.75 m) and a curve: within 1e-5 m of
    esmini over 5 s (measured 6.4e-6 m at most)."""
    from vei_scenario.conformance.esmini import compare_runs, run_esmini

    path = _scenario(tmp_path, road, road_id, s, offset)
    c = compare_runs(run_scenario(path, {}, 0.01), run_esmini(esmini, path, 0.01))
    assert [e.entity for e in c.entities] == ["Car"]
    assert c.max_deviation_m <= 1e-5, c.entities
