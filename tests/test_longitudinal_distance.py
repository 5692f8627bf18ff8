"""LongitudinalDistanceAction and direct junctions in the road-aware player, against closed forms."""

from __future__ import annotations

import numpy as np
import pytest
from xosc_parts import CAR, step_speed

from vei_scenario.interpreter import run_scenario

ROAD = """<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="1000" junction="-1"><planView>
<geometry s="0" x="0" y="0" hdg="0" length="1000"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"""


def _scenario(tmp_path, keep: str, follower_s: float, follower_v: float, seconds: float = 30.0):
    (tmp_path / "r.xodr").write_text(ROAD)
    xosc = tmp_path / "d.xosc"
    xosc.write_text(
        f"""<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork><LogicFile filepath="r.xodr"/></RoadNetwork>
<Entities><ScenarioObject name="Lead">{CAR}</ScenarioObject><ScenarioObject name="F">{CAR}</ScenarioObject></Entities>
<Storyboard><Init><Actions>
<Private entityRef="Lead"><PrivateAction><TeleportAction><Position>
<LanePosition roadId="1" laneId="-1" s="100" offset="0"/></Position></TeleportAction></PrivateAction>
{step_speed(20)}</Private>
<Private entityRef="F"><PrivateAction><TeleportAction><Position>
<LanePosition roadId="1" laneId="-1" s="{follower_s}" offset="0"/></Position></TeleportAction></PrivateAction>
{step_speed(follower_v)}
<PrivateAction><LongitudinalAction>{keep}</LongitudinalAction></PrivateAction></Private>
</Actions></Init>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="{seconds}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup>
</StopTrigger>
</Storyboard></OpenSCENARIO>"""
    )
    r = run_scenario(xosc, {}, 0.01)
    return r.traces["Lead"], r.traces["F"]


def test_without_constraints_it_is_held_at_the_distance_at_the_referencestep_speed(tmp_path):
    keep = '<LongitudinalDistanceAction entityRef="Lead" distance="12" freespace="false" continuous="true"/>'
    lead, f = _scenario(tmp_path, keep, 20.0, 0.0, seconds=5.0)
    # from t = 0 on (an Init action acts before the first record): 12 m behind, at the lead's speed
    assert np.max(np.abs(lead.x - f.x - 12.0)) < 1e-9
    assert np.all(f.speed == pytest.approx(20.0)) and np.all(np.abs(f.y - lead.y) < 1e-12)


def test_spring_closes_the_time_gap_within_the_limits(tmp_path):
    """20 m/s lead, follower 80 m behind at 20 m/s, time gap 1 s (20 m between reference points):
    the gap closes to 20 m, the acceleration stays within [-5, 3] m/s² and grows no faster than
    the rates (2 up, 4 down)."""
    keep = (
        '<LongitudinalDistanceAction entityRef="Lead" timeGap="1" freespace="false" continuous="true">'
        '<DynamicConstraints maxAcceleration="3" maxDeceleration="5" maxSpeed="40" maxAccelerationRate="2" '
        'maxDecelerationRate="4"/></LongitudinalDistanceAction>'
    )
    lead, f = _scenario(tmp_path, keep, 20.0, 20.0)
    gap = lead.x - f.x
    assert gap[-1] == pytest.approx(20.0, abs=0.05) and f.speed[-1] == pytest.approx(20.0, abs=0.02)
    a = f.accel
    assert a.max() <= 3.0 + 1e-9 and a.min() >= -5.0 - 1e-9 and a.max() > 2.9  # it used the limit
    jerk = np.diff(a) / 0.01
    growing_up = (a[1:] > 0) & (a[1:] > a[:-1])
    growing_down = (a[1:] < 0) & (a[1:] < a[:-1])
    assert np.all(jerk[growing_up] <= 2.0 + 1e-6) and np.all(jerk[growing_down] >= -4.0 - 1e-6)
    # the first second: the rate limit alone sets the acceleration, a = 2 t
    k = int(np.argmin(np.abs(f.t - 0.5)))
    assert a[k] == pytest.approx(2.0 * f.t[k], abs=1e-9)


def test_freespace_gap_is_between_the_boxes_and_leading_keeps_it_ahead(tmp_path):
    keep = (
        '<LongitudinalDistanceAction entityRef="Lead" distance="10" freespace="true" continuous="true" '
        'displacement="leadingReferencedEntity"><DynamicConstraints maxAcceleration="4" maxDeceleration="6" '
        'maxSpeed="50"/></LongitudinalDistanceAction>'
    )
    lead, f = _scenario(tmp_path, keep, 140.0, 20.0, seconds=40.0)
    # ahead of the lead with 10 m between the boxes: reference points 10 + 4.5 m apart
    assert f.x[-1] - lead.x[-1] == pytest.approx(14.5, abs=0.05)


DIRECT = """<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" length="100" junction="-1"><link><successor elementType="junction" elementId="9"/></link><planView>
<geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road>
<road id="2" length="100" junction="-1"><link><predecessor elementType="junction" elementId="9"/></link><planView>
<geometry s="0" x="100" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road>
<junction id="9" type="direct"><connection id="0" incomingRoad="1" linkedRoad="2" contactPoint="start">
<laneLink from="-1" to="-2"/></connection></junction></OpenDRIVE>"""


def test_direct_junction_is_crossed_both_ways(tmp_path):
    """A direct junction has no connecting road: lane -1 of road 1 goes on as lane -2 of road 2, and
    a road user driving backwards on road 2's lane -2 comes back onto road 1's lane -1."""
    from vei_scenario.roads.road_model import RoadNetwork

    (tmp_path / "j.xodr").write_text(DIRECT)
    net = RoadNetwork.load(tmp_path / "j.xodr")
    nxt, lane, start = net.next_road(net.road("1"), -1, True)
    assert (nxt.id, lane, start) == ("2", -2, True)
    back, lane, start = net.next_road(net.road("2"), -2, False)
    assert (back.id, lane, start) == ("1", -1, False)
    assert net.next_road(net.road("2"), -1, False) is None  # no link from that lane
