# ruff: noqa: E501  (the hand-written scenarios keep their XML lines whole)
"""FollowTrajectoryAction's initialDistanceOffset on a timed trajectory: the entity enters the path that
far in and at that point's time, so every later vertex is reached that much sooner (the standard, and
esmini; the ASAM example CloseVehicleCrossing starts one of its two crossing cars 10 m in)."""

from __future__ import annotations

import pytest

from vei_scenario.interpreter import run_scenario

DT = 0.01


def _scenario(tmp_path, offset: float) -> object:
    (tmp_path / "road.xodr").write_text(
        '<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6" name="r" version="1"/>'
        '<road name="r" length="400" id="1" junction="-1"><link/><planView><geometry s="0" x="-100" y="0" hdg="0" '
        'length="400"><line/></geometry></planView><lanes><laneSection s="0"><center><lane id="0" type="none" level="false"/></center>'
        '<right><lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>'
        "</laneSection></lanes></road></OpenDRIVE>"
    )
    vertex = '<Vertex time="{t}"><Position><WorldPosition x="{x}" y="-1.75" h="0"/></Position></Vertex>'
    traj = f'<Trajectory name="T" closed="false"><Shape><Polyline>{vertex.format(t=0, x=0)}{vertex.format(t=5, x=100)}{vertex.format(t=10, x=150)}</Polyline></Shape></Trajectory>'
    xosc = f"""<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="o" author="t"/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork><LogicFile filepath="road.xodr"/></RoadNetwork>
<Entities><ScenarioObject name="Car"><Vehicle name="c" vehicleCategory="car"><BoundingBox><Center x="1.4" y="0" z="0.9"/><Dimensions width="2" length="5" height="1.8"/></BoundingBox>
<Performance maxSpeed="69" maxDeceleration="30" maxAcceleration="30"/><Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/>
<RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles><Properties/></Vehicle></ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="Car"><PrivateAction><TeleportAction><Position><TrajectoryPosition s="{offset}"><TrajectoryRef>{traj}</TrajectoryRef></TrajectoryPosition></Position></TeleportAction></PrivateAction></Private></Actions></Init>
<Story name="S"><Act name="A"><ManeuverGroup maximumExecutionCount="1" name="G"><Actors selectTriggeringEntities="false"><EntityRef entityRef="Car"/></Actors>
<Maneuver name="M"><Event name="E" priority="override"><Action name="Follow"><PrivateAction><RoutingAction>
<FollowTrajectoryAction initialDistanceOffset="{offset}"><TrajectoryRef>{traj}</TrajectoryRef><TimeReference><Timing domainAbsoluteRelative="relative" scale="1" offset="0"/></TimeReference>
<TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction></RoutingAction></PrivateAction></Action><StartTrigger/></Event></Maneuver></ManeuverGroup>
<StartTrigger><ConditionGroup><Condition name="" delay="0" conditionEdge="rising"><ByValueCondition><SimulationTimeCondition value="0" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising"><ByValueCondition><SimulationTimeCondition value="8" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    path = tmp_path / "t.xosc"
    path.write_text(xosc)
    return path


def _x_at(result, t: float) -> float:
    i = int(round(t / DT))
    assert result.t[i] == pytest.approx(t)
    return float(result.traces["Car"].x[i])


@pytest.mark.parametrize("offset, shift", [(0.0, 0.0), (20.0, 1.0), (120.0, 7.0)])
def test_a_timed_path_entered_further_in_is_entered_at_that_time(tmp_path, offset, shift):
    """Vertices at x 0, 100, 150 at 0, 5, 10 s: 20 m/s, then 10 m/s. 20 m in is 1 s in; 120 m is 7 s."""
    result = run_scenario(_scenario(tmp_path, offset), {}, DT)

    def path_x(tt: float) -> float:
        return 20.0 * tt if tt <= 5.0 else min(150.0, 100.0 + 10.0 * (tt - 5.0))

    assert _x_at(result, 0.0) == pytest.approx(offset, abs=1e-9)
    for t in (0.5, 2.0, 2.95):
        assert _x_at(result, t) == pytest.approx(path_x(t + shift), abs=0.25)  # (a step's motion at most)


def test_the_offset_plays_as_in_esmini(tmp_path, esmini):
    from vei_scenario.conformance.esmini import compare_runs, run_esmini

    path = _scenario(tmp_path, 20.0)
    c = compare_runs(run_scenario(path, {}, DT), run_esmini(esmini, path, DT))
    assert c.entities[0].max_deviation_m < 0.05, c
