# ruff: noqa: E501  (the hand-written scenarios keep their XML lines whole)
"""A storyboard element's transition is seen once, where esmini sees it: esmini steps the storyboard in
document order, so a trigger after the element sees a transition in the step it happens, a trigger
before it in the next step. (The ASAM example FastOvertakeWithReInitialization teleports a car 2 s
after another car's action starts; with the acts in the file's order esmini does it one step sooner
than with them swapped.) Actions still act after all triggers are evaluated."""

from __future__ import annotations

import numpy as np
import pytest
from xosc_parts import speed_action

from vei_scenario.interpreter import run_scenario

DT = 0.01


def _road(path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    lane = '<lane id="{i}" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>'
    path.write_text(
        '<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6" name="r" version="1"/>'
        '<road name="r" length="2000" id="1" junction="-1"><link/><planView><geometry s="0" x="0" y="0" hdg="0" '
        'length="2000"><line/></geometry></planView><lanes><laneSection s="0">'
        f'<left>{lane.format(i=1)}</left><center><lane id="0" type="none" level="false"/></center>'
        f"<right>{lane.format(i=-1)}{lane.format(i=-2)}</right></laneSection></lanes></road></OpenDRIVE>"
    )


CAR = (
    '<ScenarioObject name="{n}"><Vehicle name="{n}" vehicleCategory="car"><BoundingBox><Center x="1.4" y="0" z="0.9"/>'
    '<Dimensions width="2" length="5" height="1.8"/></BoundingBox><Performance maxSpeed="69" maxDeceleration="30" maxAcceleration="30"/>'
    '<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/>'
    '<RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles><Properties/></Vehicle></ScenarioObject>'
)


def _act(name: str, actor: str, events: str) -> str:
    return (
        f'<Act name="{name}"><ManeuverGroup maximumExecutionCount="1" name="{name}G"><Actors selectTriggeringEntities="false">'
        f'<EntityRef entityRef="{actor}"/></Actors><Maneuver name="{name}M">{events}</Maneuver></ManeuverGroup>'
        '<StartTrigger><ConditionGroup><Condition name="" delay="0" conditionEdge="rising"><ByValueCondition>'
        '<SimulationTimeCondition value="0" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Act>'
    )


def _event(name: str, action: str, condition: str, delay: float = 0.0, count: int = 1, edge: str = "rising") -> str:
    return (
        f'<Event name="{name}" priority="override" maximumExecutionCount="{count}"><Action name="{name}Action">{action}</Action>'
        f'<StartTrigger><ConditionGroup><Condition name="{name}C" delay="{delay}" conditionEdge="{edge}">{condition}</Condition>'
        "</ConditionGroup></StartTrigger></Event>"
    )


def _state(ref: str, kind: str, state: str) -> str:
    return f'<ByValueCondition><StoryboardElementStateCondition storyboardElementType="{kind}" storyboardElementRef="{ref}" state="{state}"/></ByValueCondition>'


def _at(t: float) -> str:
    return f'<ByValueCondition><SimulationTimeCondition value="{t}" rule="greaterOrEqual"/></ByValueCondition>'


def _scenario(tmp_path, acts: list[str], variables: str = "") -> object:
    _road(tmp_path / "road.xodr")
    teleport = '<PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="{l}" offset="0" s="{s}"/></Position></TeleportAction></PrivateAction>'
    xosc = f"""<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="o" author="t"/>
<ParameterDeclarations/>{variables}<CatalogLocations/><RoadNetwork><LogicFile filepath="road.xodr"/></RoadNetwork>
<Entities>{CAR.format(n="A1")}{CAR.format(n="A2")}</Entities><Storyboard><Init><Actions>
<Private entityRef="A1">{speed_action(25.0)}{teleport.format(l=-1, s=10)}</Private>
<Private entityRef="A2">{teleport.format(l=1, s=1500)}</Private></Actions></Init>
<Story name="S">{"".join(acts)}</Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising">{_at(6.0)}</Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    path = tmp_path / "o.xosc"
    path.write_text(xosc)
    return path


def _teleport_after_slow_down(tmp_path, reader_first: bool) -> object:
    slow = _act("Slow", "A1", _event("SlowDown", speed_action(15.0, "linear", 4.0), _at(1.0)))
    move = '<PrivateAction><TeleportAction><Position><RelativeLanePosition entityRef="A1" dLane="-1" ds="-20"/></Position></TeleportAction></PrivateAction>'
    setup = _act("Move", "A2", _event("Place", move, _state("SlowDownAction", "action", "startTransition"), delay=2.0))
    return _scenario(tmp_path, [setup, slow] if reader_first else [slow, setup])


def _teleported_at(result) -> float:
    y = result.traces["A2"].y
    return float(result.t[int(np.argmax(y < 0))])


def test_a_trigger_after_the_element_sees_its_start_in_the_same_step(tmp_path):
    # SlowDown starts in the evaluation at t = 1.00; 2 s later the placing event fires: evaluated
    # after it in the file, in the evaluation at t = 3.00 (the car appears in the next record, 3.01);
    # evaluated before it, one step later
    after = run_scenario(_teleport_after_slow_down(tmp_path / "a", reader_first=False), {}, DT)
    before = run_scenario(_teleport_after_slow_down(tmp_path / "b", reader_first=True), {}, DT)
    assert _teleported_at(after) == pytest.approx(3.01, abs=1e-9)
    assert _teleported_at(before) == pytest.approx(3.02, abs=1e-9)


@pytest.mark.parametrize("reader_first", [False, True])
def test_the_placing_step_is_esminis(tmp_path, esmini, reader_first):
    from vei_scenario.conformance.esmini import run_esmini

    path = _teleport_after_slow_down(tmp_path, reader_first)
    ours = run_scenario(path, {}, DT)
    theirs = run_esmini(esmini, path, DT).tracks["A2"]
    first = int(np.argmax(theirs.y < 0))
    assert _teleported_at(ours) == pytest.approx(first * DT, abs=1e-9)


@pytest.mark.parametrize("reader_first", [False, True])
def test_a_transition_is_seen_once(tmp_path, reader_first):
    """An event that may run five times, on a condition without an edge, runs once for one start."""
    variables = '<VariableDeclarations><VariableDeclaration name="seen" variableType="integer" value="0"/></VariableDeclarations>'
    count = '<GlobalAction><VariableAction variableRef="seen"><ModifyAction><Rule><AddValue value="1"/></Rule></ModifyAction></VariableAction></GlobalAction>'
    slow = _act("Slow", "A1", _event("SlowDown", speed_action(15.0, "linear", 4.0), _at(1.0)))
    counting = _act(
        "Count", "A2", _event("Counter", count, _state("SlowDown", "event", "startTransition"), count=5, edge="none")
    )
    path = _scenario(tmp_path, [counting, slow] if reader_first else [slow, counting], variables)
    from vei_scenario.interpreter import Simulation, load_scenario

    sim = Simulation(load_scenario(path), DT, 600.0, "sequential")
    sim.run()
    assert sim.ctx.variables["seen"] == "1"
