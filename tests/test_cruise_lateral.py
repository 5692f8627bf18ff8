"""Lane changes and lane offsets in quiet stretches: the core shifts a road user sideways as
``actions.LaneChangeRuntime`` does (the offset from the target lane's centre going from where it
started to the target offset by the transition's shape, over time or distance; s advanced by the
along-road part of each step for a lane change; the road user heading where it moves) and stops before
the step that completes the transition, whose evaluation ends the action.

The reference is the same interpreter with the cruise switched off (tests/test_cruise.py's
``run_both``); each case checks that the lane change happened, that a later event fired on time, and
that most steps were cruised."""

from __future__ import annotations

import numpy as np
import pytest
from test_cruise import ROAD, _lane, assert_identical, run_both
from xosc_parts import CAR, step_speed


def _lane_change(target: str, shape: str, dimension: str, value: float, offset: float = 0.0) -> str:
    return (
        '<PrivateAction><LateralAction><LaneChangeAction targetLaneOffset="{offset}"><LaneChangeActionDynamics '
        f'dynamicsShape="{shape}" value="{value}" dynamicsDimension="{dimension}"/><LaneChangeTarget>{target}'
        "</LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"
    ).replace("{offset}", str(offset))


def _lane_offset(value: float, shape: str, max_acc: float) -> str:
    return (
        f'<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics '
        f'maxLateralAcc="{max_acc}" dynamicsShape="{shape}"/><LaneOffsetTarget><AbsoluteTargetLaneOffset '
        f'value="{value}"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>'
    )


def _event(name: str, actor: str, action: str, condition: str) -> str:
    return (
        f'<ManeuverGroup maximumExecutionCount="1" name="{name}g"><Actors selectTriggeringEntities="false">'
        f'<EntityRef entityRef="{actor}"/></Actors><Maneuver name="{name}m"><Event name="{name}" priority="parallel">'
        f'<Action name="{name}a">{action}</Action><StartTrigger><ConditionGroup><Condition name="{name}c" delay="0" '
        f'conditionEdge="none">{condition}</Condition></ConditionGroup></StartTrigger></Event></Maneuver>'
        "</ManeuverGroup>"
    )


def _time(t: float) -> str:
    return f'<ByValueCondition><SimulationTimeCondition value="{t}" rule="greaterThan"/></ByValueCondition>'


ABSOLUTE_RIGHT = '<AbsoluteTargetLane value="-2"/>'
RELATIVE_TO_OTHERS = '<RelativeTargetLane entityRef="Other" value="0"/>'


def scenario(tmp_path, action: str, start: float, ego_v: float = 14.0):
    """The Ego on lane -1 of tests/test_cruise.py's road (a 100 m radius arc from 100 m) at ``ego_v``,
    Other on lane -2; ``action`` on the Ego at ``start`` s, and the Ego slowing to 6 m/s once it has
    ended (a StoryboardElementStateCondition on its end)."""
    (tmp_path / "arc.xodr").write_text(ROAD)
    ended = (
        '<ByValueCondition><StoryboardElementStateCondition storyboardElementType="action" '
        'storyboardElementRef="Shifta" state="endTransition"/></ByValueCondition>'
    )
    story = _event("Shift", "Ego", action, _time(start)) + _event("After", "Ego", step_speed(6.0), ended)
    xosc = tmp_path / "lateral.xosc"
    objects = "".join(f'<ScenarioObject name="{n}">{CAR}</ScenarioObject>' for n in ("Ego", "Other"))
    xosc.write_text(
        f"""<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork><LogicFile filepath="arc.xodr"/></RoadNetwork><Entities>{objects}</Entities>
<Storyboard><Init><Actions>{_lane("Ego", -1, 5, ego_v)}{_lane("Other", -2, 60, 9)}</Actions></Init>
<Story name="s"><Act name="a">{story}<StartTrigger><ConditionGroup><Condition name="go" delay="0"
conditionEdge="none">{_time(-1)}</Condition></ConditionGroup></StartTrigger></Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none">{_time(16)}</Condition>
</ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    )
    return xosc


CASES = {
    # a lane change over time, each shape, on the straight and into the arc
    "sinusoidal_time": (_lane_change(ABSOLUTE_RIGHT, "sinusoidal", "time", 3.0), 1.0),
    "cubic_time_on_the_arc": (_lane_change(ABSOLUTE_RIGHT, "cubic", "time", 4.0), 6.5),
    "linear_time": (_lane_change(ABSOLUTE_RIGHT, "linear", "time", 2.5), 2.0),
    # over distance, to an offset in the target lane
    "cubic_distance_offset": (_lane_change(ABSOLUTE_RIGHT, "cubic", "distance", 60.0, 0.6), 1.5),
    # at a lateral rate, to another road user's lane
    "sinusoidal_rate_relative": (_lane_change(RELATIVE_TO_OTHERS, "sinusoidal", "rate", 1.2, -0.4), 3.0),
    # a lane offset (its progress taken at the step's start; s advances by the whole step)
    "lane_offset_sinusoidal": (_lane_offset(1.1, "sinusoidal", 0.8), 1.0),
    "lane_offset_cubic_on_the_arc": (_lane_offset(-0.9, "cubic", 0.5), 7.5),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_lateral_transitions_in_quiet_stretches_equal_the_stepped_run(tmp_path, monkeypatch, case):
    action, start = CASES[case]
    fast, cruised, slow = run_both(scenario(tmp_path, action, start), monkeypatch)
    assert_identical(fast, slow)
    ego = fast.traces["Ego"]
    i0, i1 = int(np.searchsorted(fast.t, start)), int(np.searchsorted(fast.t, start + 1.0))
    assert np.ptp(np.diff(ego.yaw[i0:i1])) > 1e-4, f"{case}: the Ego did not turn aside"
    after = np.flatnonzero(np.isclose(ego.speed, 6.0))
    assert after.size, f"{case}: the transition's end was never seen"
    assert fast.t[after[0]] > start + 0.5
    # (stepping through the transition leaves 67-84 % cruised: the core takes it)
    assert cruised > 0.97 * len(fast.t), f"{case}: only {cruised} of {len(fast.t)} steps cruised"


def test_a_lane_change_ends_where_the_stepped_run_ends_it(tmp_path, monkeypatch):
    """A 3 s lane change from 1 s (its first step from 1.01 s): the event waiting for its end starts on
    the step the stepped run starts it, a step after the transition completes (4.01 s to 4.03 s), and
    the Ego then keeps the centre of lane -2 (3.5 m to the right of where it started)."""
    action, start = CASES["sinusoidal_time"]
    fast, _, slow = run_both(scenario(tmp_path, action, start), monkeypatch)
    assert_identical(fast, slow)
    ego = fast.traces["Ego"]
    k = int(np.argmax(np.isclose(ego.speed, 6.0)))
    assert 4.0 <= fast.t[k] <= 4.04, fast.t[k]
    assert ego.y[k] == pytest.approx(ego.y[0] - 3.5, abs=1e-6) and ego.yaw[k] == pytest.approx(0.0, abs=1e-9)


def _road_lane(lane_id: int, width: str, link: str = "") -> str:
    return f'<lane id="{lane_id}" type="driving">{link}<width sOffset="0" {width}/></lane>'


def _links(pred: int | None, succ: int | None) -> str:
    ends = (f'<predecessor id="{pred}"/>' if pred else "") + (f'<successor id="{succ}"/>' if succ else "")
    return f"<link>{ends}</link>"


WIDE = 'a="3.5" b="0" c="0" d="0"'
OPENING = (
    '<width sOffset="0" a="0" b="0" c="0.0065625" d="-0.000109375"/><width sOffset="40" a="3.5" b="0" c="0" d="0"/>'
)
#: Three lane sections: two lanes, then a third one opening on the right (from 0 to 3.5 m over 40 m,
#: smoothly)
#: and running on to 200 m, then two lanes again; lanes linked across the sections.
SECTIONS = f"""<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="300" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry></planView><lanes>
<laneSection s="0"><center><lane id="0" type="none"/></center><right>{_road_lane(-1, WIDE, _links(None, -1))}
{_road_lane(-2, WIDE, _links(None, -2))}</right></laneSection>
<laneSection s="60"><center><lane id="0" type="none"/></center><right>{_road_lane(-1, WIDE, _links(-1, -1))}
{_road_lane(-2, WIDE, _links(-2, -2))}<lane id="-3" type="driving">{OPENING}</lane></right></laneSection>
<laneSection s="200"><center><lane id="0" type="none"/></center><right>{_road_lane(-1, WIDE, _links(-1, None))}
{_road_lane(-2, WIDE, _links(-2, None))}</right></laneSection></lanes></road></OpenDRIVE>"""


#: The same with the new lane opening between lanes -1 and -2 of the first section: their -2 is the
#: second section's -3 (a lane change to -2 named in the first section heads for the second's -3, its
#: centre pushed out as the lane between opens).
BETWEEN = f"""<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="300" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry></planView><lanes>
<laneSection s="0"><center><lane id="0" type="none"/></center><right>{_road_lane(-1, WIDE, _links(None, -1))}
{_road_lane(-2, WIDE, _links(None, -3))}</right></laneSection>
<laneSection s="60"><center><lane id="0" type="none"/></center><right>{_road_lane(-1, WIDE, _links(-1, -1))}
<lane id="-2" type="driving">{OPENING}</lane>{_road_lane(-3, WIDE, _links(-2, -2))}</right></laneSection>
<laneSection s="200"><center><lane id="0" type="none"/></center><right>{_road_lane(-1, WIDE, _links(-1, None))}
{_road_lane(-2, WIDE, _links(-3, None))}</right></laneSection></lanes></road></OpenDRIVE>"""


@pytest.mark.parametrize(
    "road, target, start, y_end, least",
    [
        (SECTIONS, '<AbsoluteTargetLane value="-3"/>', 5.0, (-8.75, -8.75), 0.97),  # into the lane that opened
        # from the first section on into the second: the steps beyond the first are the interpreter's (all
        # of the lane change's were before: 0.74 of the run)
        (SECTIONS, '<AbsoluteTargetLane value="-2"/>', 3.0, (-5.25, -5.25), 0.8),
        (BETWEEN, '<AbsoluteTargetLane value="-2"/>', 3.0, (-8.75, -7.0), 0.8),
    ],
)
def test_a_lane_change_across_lane_sections(tmp_path, monkeypatch, road, target, start, y_end, least):
    """The target lane's centre is taken within the section the lane change named it in (the
    interpreter maps the lane where the road user passes into another section): the core takes the
    steps inside that section and leaves the ones beyond it to the interpreter."""
    path = scenario(tmp_path, _lane_change(target, "cubic", "distance", 50.0), start, ego_v=12.0)
    (tmp_path / "arc.xodr").write_text(road)
    other = 'laneId="-2" s="60" offset="0"'  # (Other ahead in lane -1, clear of the lane that opens)
    path.write_text(path.read_text().replace(other, 'laneId="-1" s="150" offset="0"'))
    fast, cruised, slow = run_both(path, monkeypatch)
    assert_identical(fast, slow)
    ego = fast.traces["Ego"]
    after = np.flatnonzero(np.isclose(ego.speed, 6.0))
    assert after.size and fast.t[after[0]] > start + 3.0  # the lane change ended (over 50 m at 12 m/s)
    k = after[0]
    assert y_end[0] - 1e-6 <= ego.y[k] <= y_end[1] + 1e-6, ego.y[k]
    assert cruised > least * len(fast.t), f"only {cruised} of {len(fast.t)} steps cruised"
