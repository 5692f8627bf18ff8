# ruff: noqa: E501  (the hand-written scenarios keep their XML lines whole)
"""A lane change pauses while its car stands: a car cannot move sideways without moving on. It keeps
its place across the road and its heading until it moves again, and then finishes the change (over
time: the time it stood does not count). esmini 3.6 does the same (measured on the ASAM example
EndofTrafficJamNeighboringLaneOccupied, whose car brakes to a stop in the middle of a lane change);
before, vei slid the standing car sideways to the target lane."""

from __future__ import annotations

import numpy as np
import pytest
from xosc_parts import speed_action

from vei_scenario.interpreter import Simulation, load_scenario

DT = 0.01
W = 3.5


def _scenario(tmp_path) -> object:
    lane = '<lane id="{i}" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>'
    (tmp_path / "road.xodr").write_text(
        '<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6" name="r" version="1"/>'
        '<road name="r" length="1000" id="1" junction="-1"><link/><planView><geometry s="0" x="0" y="0" hdg="0" '
        f'length="1000"><line/></geometry></planView><lanes><laneSection s="0"><center><lane id="0" type="none" level="false"/></center>'
        f"<right>{lane.format(i=-1)}{lane.format(i=-2)}</right></laneSection></lanes></road></OpenDRIVE>"
    )

    def event(name: str, action: str, at: float) -> str:
        return (
            f'<Event name="{name}" priority="parallel"><Action name="{name}A">{action}</Action><StartTrigger><ConditionGroup>'
            f'<Condition name="{name}C" delay="0" conditionEdge="rising"><ByValueCondition><SimulationTimeCondition value="{at}" rule="greaterOrEqual"/>'
            "</ByValueCondition></Condition></ConditionGroup></StartTrigger></Event>"
        )

    change = (
        '<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="3" dynamicsDimension="time"/>'
        '<LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>'
    )
    events = (
        event("change", change, 1.0)
        + event("brake", speed_action(0.0, "linear", 20.0, "rate"), 1.0)
        + event("go", speed_action(10.0), 4.0)
    )
    xosc = f"""<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="s" author="t"/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork><LogicFile filepath="road.xodr"/></RoadNetwork>
<Entities><ScenarioObject name="Car"><Vehicle name="c" vehicleCategory="car"><BoundingBox><Center x="1.4" y="0" z="0.9"/><Dimensions width="2" length="5" height="1.8"/></BoundingBox>
<Performance maxSpeed="69" maxDeceleration="30" maxAcceleration="30"/><Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/>
<RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles><Properties/></Vehicle></ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="Car">{speed_action(20.0)}<PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-1" offset="0" s="10"/></Position></TeleportAction></PrivateAction></Private></Actions></Init>
<Story name="S"><Act name="A"><ManeuverGroup maximumExecutionCount="1" name="G"><Actors selectTriggeringEntities="false"><EntityRef entityRef="Car"/></Actors><Maneuver name="M">{events}</Maneuver></ManeuverGroup>
<StartTrigger><ConditionGroup><Condition name="s" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising"><ByValueCondition><SimulationTimeCondition value="9" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    path = tmp_path / "s.xosc"
    path.write_text(xosc)
    return path


def test_a_standing_car_does_not_slide_sideways_and_finishes_once_it_moves(tmp_path):
    sim = Simulation(load_scenario(_scenario(tmp_path)), DT, 600.0, "sequential")
    result = sim.run()
    tr, t = result.traces["Car"], result.t
    standing = (t > 2.1) & (t < 3.99)
    assert np.all(tr.speed[standing] == 0.0)
    # halfway across or so when it stopped (1 s of the 3 s change), and there while it stands
    y_stop = float(tr.y[standing][0])
    assert -W - 0.5 * W < y_stop < -0.5 * W - 0.2
    assert np.ptp(tr.y[standing]) == 0.0 and np.ptp(tr.x[standing]) == 0.0 and np.ptp(tr.yaw[standing]) == 0.0
    assert float(tr.yaw[standing][0]) < -0.05  # (turned towards the lane it changes to, not along the road)
    # moving again at 4 s, it finishes the change with the 2 s it had left, in the target lane
    done = result.t[int(np.argmax(np.abs(tr.y + 1.5 * W) < 1e-9))]
    assert 5.9 <= done <= 6.1
    assert float(tr.y[-1]) == pytest.approx(-1.5 * W, abs=1e-9) and abs(float(tr.yaw[-1])) < 1e-9
    change = sim.ctx.elements[("Action", "changeA")]
    assert change.state == "complete"
