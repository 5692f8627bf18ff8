# ruff: noqa: E501  (the hand-written OpenDRIVE/OpenSCENARIO keep their XML lines whole)
"""A distance between boxes along the road (RelativeDistanceCondition and DistanceCondition with
coordinateSystem="road" and freespace="true") is measured from where the boxes are, not from the
reference points: a car's box sits ``center_x`` ahead of its reference point (1.4 m for a car whose
reference point is its rear axle, 0 for one whose reference point is its centre).

Before, vei took the reference points' s and subtracted the half lengths, so a rear-axle car's gap was
off by its ``center_x`` (the entity frame's freespace was right): esmini's cut-in_simple with the
condition written in road coordinates started its lane change a step after esmini's. Checked
analytically on a straight road and against esmini where it is present."""

from __future__ import annotations

import pytest
from xosc_parts import step_speed, vehicle

from vei_scenario.interpreter import run_scenario

DT = 0.01
ROAD = """<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="1000" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="1000"><line/></geometry></planView><lanes><laneSection s="0">
<center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/>
</lane></right></laneSection></lanes></road></OpenDRIVE>"""


def _car(name: str, center_x: float, length: float) -> str:
    return f'<ScenarioObject name="{name}">{vehicle(name, center_x, length)}</ScenarioObject>'


def _at(name: str, s: float, v: float) -> str:
    return (
        f'<Private entityRef="{name}"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-1" '
        f's="{s}" offset="0"/></Position></TeleportAction></PrivateAction>{step_speed(v)}</Private>'
    )


ARC = ROAD.replace("<line/>", '<arc curvature="0.03"/>')  # (a 33 m radius)


def scenario(tmp_path, condition: str, road: str = ROAD):
    """Lead (reference point at its box centre, 4 m long) 20 m ahead of Ego (rear axle, 1.4 m behind
    the centre of its 5 m box) on a straight lane, pulling away at 5 m/s; Ego stops at once when
    ``condition`` (its triggering entity Ego) first holds."""
    (tmp_path / "straight.xodr").write_text(road)
    path = tmp_path / "s.xosc"
    path.write_text(
        f"""<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork><LogicFile filepath="straight.xodr"/></RoadNetwork>
<Entities>{_car("Ego", 1.4, 5.0)}{_car("Lead", 0.0, 4.0)}</Entities>
<Storyboard><Init><Actions>{_at("Ego", 10, 10.0)}{_at("Lead", 30, 15.0)}</Actions></Init>
<Story name="s"><Act name="a"><ManeuverGroup maximumExecutionCount="1" name="g"><Actors selectTriggeringEntities="false">
<EntityRef entityRef="Ego"/></Actors><Maneuver name="m"><Event name="stop" priority="override"><Action name="stopa">
{step_speed(0.0)}</Action><StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="none">
<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities>
<EntityCondition>{condition}</EntityCondition></ByEntityCondition></Condition></ConditionGroup></StartTrigger></Event>
</Maneuver></ManeuverGroup><StartTrigger><ConditionGroup><Condition name="go" delay="0" conditionEdge="none">
<ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition>
</ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="6" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""
    )
    return path


RELATIVE = (
    '<RelativeDistanceCondition entityRef="Lead" value="{v}" freespace="true" relativeDistanceType="longitudinal" '
    'coordinateSystem="{cs}" rule="greaterThan"/>'
)
#: a position 40 m ahead of where the Ego starts: the box's front reaches within ``v`` of it
TO_POSITION = (
    '<DistanceCondition value="{v}" freespace="true" relativeDistanceType="longitudinal" coordinateSystem="{cs}" '
    'rule="lessThan"><Position><LanePosition roadId="1" laneId="-1" s="50" offset="0"/></Position></DistanceCondition>'
)


def _stopped_at(result) -> float:
    """When the Ego's stop took effect (its first standing sample)."""
    ego = result.traces["Ego"]
    return float(ego.t[(ego.speed == 0.0).argmax()])


@pytest.mark.parametrize("cs", ["road", "entity"])
def test_the_gap_between_the_boxes_along_the_road(tmp_path, cs):
    """The boxes' gap: Lead's rear at 30 - 2 = 28 m, Ego's front at 10 + 1.4 + 2.5 = 13.9 m: 14.1 m at
    the start, opening at 5 m/s, so past 20 m after 1.18 s (the condition holds at the first step
    after it; the stop shows a step later). From the reference points less the half lengths it would be
    20 - 4.5 = 15.5 m, and past 20 m after 0.9 s."""
    r = run_scenario(scenario(tmp_path, RELATIVE.format(v=20.0, cs=cs)), {}, DT)
    assert _stopped_at(r) == pytest.approx(1.19 + DT, abs=1e-9)


@pytest.mark.parametrize("cs", ["road", "entity"])
def test_the_distance_from_a_box_to_a_position_along_the_road(tmp_path, cs):
    """Ego's front starts 50 - 13.9 = 36.1 m short of the position and closes at 10 m/s: under 30 m
    after 0.61 s (from the reference point less half the length: 37.5 m, 0.75 s)."""
    r = run_scenario(scenario(tmp_path, TO_POSITION.format(v=30.0, cs=cs)), {}, DT)
    assert _stopped_at(r) == pytest.approx(0.62 + DT, abs=1e-9)


@pytest.mark.parametrize("template", [RELATIVE, TO_POSITION], ids=["relative", "position"])
def test_road_freespace_distances_fire_when_esminis_do(tmp_path, esmini, template):
    from vei_scenario.conformance.esmini import compare_runs, run_esmini

    value = 20.0 if template is RELATIVE else 30.0
    path = scenario(tmp_path, template.format(v=value, cs="road"))
    c = compare_runs(run_scenario(path, {}, DT), run_esmini(esmini, path, DT))
    assert c.entities and c.max_deviation_m < 1e-6, c.entities


def test_a_time_headway_in_road_coordinates_is_the_road_distance_over_the_speed(tmp_path):
    """TimeHeadwayCondition reads coordinateSystem and relativeDistanceType as the distance conditions do
    (it took the distance along the Ego's heading whatever they said): on a 33 m radius arc, a 2 s
    headway at the Ego's 10 m/s fires on the step the 20 m gap along the road does, tens of steps before the
    gap along the Ego's heading (the chord's projection, shorter than the arc) would."""
    headway = (
        '<TimeHeadwayCondition entityRef="Lead" value="2.0" freespace="true" coordinateSystem="road" '
        'relativeDistanceType="longitudinal" rule="greaterThan"/>'
    )
    along_road = run_scenario(scenario(tmp_path, RELATIVE.format(v=20.0, cs="road"), ARC), {}, DT)
    along_heading = run_scenario(scenario(tmp_path, RELATIVE.format(v=20.0, cs="entity"), ARC), {}, DT)
    r = run_scenario(scenario(tmp_path, headway, ARC), {}, DT)
    assert _stopped_at(r) == _stopped_at(along_road)
    assert _stopped_at(along_heading) - _stopped_at(along_road) >= 20 * DT - 1e-9
