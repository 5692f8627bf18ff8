"""Quiet stretches along timed trajectories, and conditions on speeds that change every step: the core
plays a timed path (position and follow mode; absolute and relative timing, scaled and offset; started
in Init or by an event; on a road network or without one, where the road user plays on past the path's
end) as the interpreter's step does, and stops before the evaluation that ends the path's action. A
condition comparing a speed or an acceleration that changes (a timed path, a transition) is handed to
the core as a guard, and the core stops before the step that would change the comparison.

The reference is the same interpreter with the cruise switched off (tests/test_cruise.py's
``run_both``); each case checks that its watched condition fired, and that most steps were cruised."""

from __future__ import annotations

import numpy as np
import pytest
from test_cruise import assert_identical, run_both
from test_cruise_sync import PEDESTRIAN, ROAD
from xosc_parts import CAR, step_speed

from vei_scenario.interpreter import run_scenario

#: The walker's recording: waiting, then across the road at x ~ 120, speeding up and slowing down, and a
#: pause half way (a standstill inside the path).
WALK = [
    (120.0, -12.0, 0.0),
    (120.0, -12.0, 1.0),
    (120.4, -9.0, 3.0),
    (120.9, -4.5, 4.5),
    (121.0, -3.0, 5.2),
    (121.0, -3.0, 6.0),
    (120.6, 0.5, 7.1),
    (119.5, 6.0, 9.0),
]


def _trajectory(mode: str, timing: str) -> str:
    vertices = "".join(
        f'<Vertex time="{t}"><Position><WorldPosition x="{x}" y="{y}"/></Position></Vertex>' for x, y, t in WALK
    )
    return (
        '<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="walk" closed="false">'
        f"<Shape><Polyline>{vertices}</Polyline></Shape></Trajectory></TrajectoryRef><TimeReference>{timing}"
        f'</TimeReference><TrajectoryFollowingMode followingMode="{mode}"/></FollowTrajectoryAction></RoutingAction>'
        "</PrivateAction>"
    )


def _timing(domain: str, scale: float, offset: float) -> str:
    return f'<Timing domainAbsoluteRelative="{domain}" scale="{scale}" offset="{offset}"/>'


def _condition(body: str, who: str) -> str:
    return (
        '<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any">'
        f'<EntityRef entityRef="{who}"/></TriggeringEntities><EntityCondition>{body}</EntityCondition>'
        "</ByEntityCondition>"
    )


def _event(name: str, actor: str, action: str, condition: str, edge: str = "none") -> str:
    return (
        f'<ManeuverGroup maximumExecutionCount="1" name="{name}g"><Actors selectTriggeringEntities="false">'
        f'<EntityRef entityRef="{actor}"/></Actors><Maneuver name="{name}m"><Event name="{name}" priority="parallel">'
        f'<Action name="{name}a">{action}</Action><StartTrigger><ConditionGroup><Condition name="{name}c" delay="0" '
        f'conditionEdge="{edge}">{condition}</Condition></ConditionGroup></StartTrigger></Event></Maneuver>'
        "</ManeuverGroup>"
    )


def _time(t: float) -> str:
    return f'<ByValueCondition><SimulationTimeCondition value="{t}" rule="greaterOrEqual"/></ByValueCondition>'


def scenario(tmp_path, c: dict):
    """Ego at 12 m/s on lane -1 (or straight on, without roads); the Walker on its timed path across the
    road, from Init or from ``start`` s; the Ego slows to 9 m/s once ``watch`` holds for ``who`` (on its
    ``edge``)."""
    roads = c.get("roads", True)
    if roads:
        (tmp_path / "straight.xodr").write_text(ROAD)
        network = '<RoadNetwork><LogicFile filepath="straight.xodr"/></RoadNetwork>'
        ego_at = '<LanePosition roadId="1" laneId="-1" s="10" offset="0"/>'
    else:
        network = "<RoadNetwork/>"
        ego_at = '<WorldPosition x="10" y="-1.75" h="0"/>'
    path = _trajectory(c.get("mode", "position"), _timing(*c.get("timing", ("absolute", 1.0, 0.0))))
    walker_at = f'<WorldPosition x="{WALK[0][0]}" y="{WALK[0][1]}" h="1.5708"/>'
    init = (
        f'<Private entityRef="Ego"><PrivateAction><TeleportAction><Position>{ego_at}</Position></TeleportAction>'
        f"</PrivateAction>{step_speed(c.get('ego_v', 12.0))}</Private>"
        f'<Private entityRef="Walker"><PrivateAction><TeleportAction><Position>{walker_at}</Position>'
        f"</TeleportAction></PrivateAction>{'' if 'start' in c else path}</Private>"
    )
    story = ""
    if "start" in c:
        story += _event("Walk", "Walker", path, _time(c["start"]))
    if "watch" in c:
        watch = _condition(c["watch"], c.get("who", "Walker"))
        story += _event("Watch", "Ego", step_speed(9.0), watch, c.get("edge", "none"))
    if "after" in c:  # an event waiting for the walk's end
        story += _event("After", "Ego", step_speed(7.0), c["after"])
    xosc = tmp_path / "timed.xosc"
    xosc.write_text(
        f"""<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
{network}<Entities><ScenarioObject name="Ego">{CAR}</ScenarioObject>
<ScenarioObject name="Walker">{PEDESTRIAN}</ScenarioObject></Entities>
<Storyboard><Init><Actions>{init}</Actions></Init>
<Story name="s"><Act name="a">{story}<StartTrigger><ConditionGroup><Condition name="go" delay="0"
conditionEdge="none">{_time(0)}</Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="{c.get("end", 14.0)}" rule="greaterThan"/></ByValueCondition></Condition>
</ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    )
    return xosc


def _speed(rule: str, value: float) -> str:
    return f'<SpeedCondition value="{value}" rule="{rule}"/>'


CASES = {
    # how the path is timed and played
    "init_absolute": {},
    "init_follow": {"mode": "follow"},
    "scaled_and_offset": {"timing": ("absolute", 0.8, 0.6)},
    "relative_from_an_event": {"start": 2.3, "timing": ("relative", 1.25, 0.0)},
    "relative_follow_from_an_event": {"start": 1.7, "mode": "follow", "timing": ("relative", 1.0, -0.4)},
    "no_roads_plays_past_the_end": {"roads": False, "end": 16.0},
    # the path's action ending (the core stops before the evaluation that ends it)
    "after_the_walk_ends": {
        "after": '<ByValueCondition><StoryboardElementStateCondition storyboardElementType="action" '
        'storyboardElementRef="Walka" state="endTransition"/></ByValueCondition>',
        "start": 1.1,
        "timing": ("relative", 1.0, 0.0),
    },
    # conditions on the walker, whose speed changes every step: guards in the core
    "speed_greater": {"watch": _speed("greaterThan", 2.9)},
    # (in follow mode the walker's speed swings, crossing these thresholds while it moves)
    "speed_less": {"watch": _speed("lessThan", 2.0), "mode": "follow", "edge": "rising"},
    "speed_greater_or_equal": {"watch": _speed("greaterOrEqual", 2.5), "mode": "follow"},
    "speed_less_or_equal": {"watch": _speed("lessOrEqual", 1.5), "mode": "follow", "edge": "rising"},
    "speed_equal": {"watch": _speed("equalTo", 0.0), "timing": ("absolute", 1.0, -1.5)},
    "speed_not_equal": {"watch": _speed("notEqualTo", 0.0)},
    "acceleration": {
        "watch": '<AccelerationCondition value="-5" rule="lessThan"/>',
        "mode": "follow",
        "edge": "rising",
    },
    "relative_speed": {
        "watch": '<RelativeSpeedCondition entityRef="Walker" value="9.6" rule="lessThan"/>',
        "who": "Ego",
    },
    # conditions that bound their steps by the walker's moves
    "traveled": {"watch": '<TraveledDistanceCondition value="7.5"/>'},
    "reach": {
        "watch": '<ReachPositionCondition tolerance="1.0"><Position><WorldPosition x="121" y="-3"/></Position>'
        "</ReachPositionCondition>"
    },
    "standstill": {"watch": '<StandStillCondition duration="0.5"/>', "timing": ("absolute", 1.0, 2.0)},
    "distance_to_the_ego": {
        "watch": '<RelativeDistanceCondition entityRef="Walker" relativeDistanceType="cartesianDistance" '
        'value="30" freespace="true" rule="lessThan"/>',
        "who": "Ego",
        "ego_v": 9.5,
    },
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_timed_paths_in_quiet_stretches_equal_the_stepped_run(tmp_path, monkeypatch, case):
    c = CASES[case]
    fast, cruised, slow = run_both(scenario(tmp_path, c), monkeypatch)
    assert_identical(fast, slow)
    walker = slow.traces["Walker"]
    assert np.ptp(walker.y) > 10.0, "the walker did not walk"
    assert {"replay" if c.get("mode", "position") == "position" else "follow"} <= set(walker.status)
    ego = slow.traces["Ego"].speed
    if "watch" in c:
        assert np.any(np.isclose(ego, 9.0)), f"{case}: the watched condition never fired"
    if "after" in c:
        assert np.any(np.isclose(ego, 7.0)), f"{case}: the walk's end was never seen"
    assert cruised > 0.5 * len(fast.t), f"{case}: only {cruised} of {len(fast.t)} steps cruised"


def test_a_guarded_speed_fires_on_the_step_it_crosses(tmp_path):
    """Not only equal to the stepped run: the Ego slows on the step after the walker's speed first
    exceeds the threshold (an analytic check on the recording's segment speeds)."""
    c = CASES["speed_greater"]
    r = run_scenario(scenario(tmp_path, c))
    walker, ego = r.traces["Walker"], r.traces["Ego"]
    first = int(np.argmax(walker.speed > 2.9))
    slowed = int(np.argmax(np.isclose(ego.speed, 9.0)))
    assert slowed == first + 1, (first, slowed)
    # the walker crosses 2.9 m/s on the segment from 3 s to 4.5 s (4.5 m in 1.5 s: 3.03 m/s)
    assert 3.0 <= r.t[first] <= 3.02, r.t[first]


def test_a_timed_path_stops_the_stretch_before_its_end(tmp_path, monkeypatch):
    """The walk's action ends in the evaluation the stepped run ends it in: the event waiting for its
    end starts on the same step, within a step of the path's last time (1.1 s + 9 s)."""
    c = CASES["after_the_walk_ends"]
    fast, _, slow = run_both(scenario(tmp_path, c), monkeypatch)
    assert_identical(fast, slow)
    k = int(np.argmax(np.isclose(fast.traces["Ego"].speed, 7.0)))
    assert abs(fast.t[k] - 10.1) <= 0.03, fast.t[k]
