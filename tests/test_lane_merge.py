"""Keeping a lane whose width changes: the entity heads along the lane centre as it runs sideways, and
when its lane narrows to nothing (a merge) it carries on in the nearest driving lane — closed forms
on a straight road whose outer lane tapers linearly (esmini does the same on its multi-intersection
road; see test_esmini_conformance.py, trailers)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from xosc_parts import CAR, step_speed

from vei_scenario.interpreter import run_scenario

ROAD = """<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="300" junction="-1"><planView>
<geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/>
<width sOffset="50" a="3.5" b="-0.07" c="0" d="0"/><width sOffset="100" a="0" b="0" c="0" d="0"/></lane>
<lane id="-3" type="border"><width sOffset="0" a="0.3" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"""


def _run(tmp_path):
    (tmp_path / "r.xodr").write_text(ROAD)
    xosc = tmp_path / "m.xosc"
    xosc.write_text(
        f"""<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork><LogicFile filepath="r.xodr"/></RoadNetwork>
<Entities><ScenarioObject name="Car">{CAR}</ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="Car"><PrivateAction><TeleportAction><Position>
<LanePosition roadId="1" laneId="-2" s="10" offset="0"/></Position></TeleportAction></PrivateAction>
{step_speed(10)}</Private></Actions></Init>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="15" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup>
</StopTrigger></Storyboard></OpenSCENARIO>"""
    )
    return run_scenario(xosc).traces["Car"]


def test_a_tapering_lane_is_followed_along_its_centre_and_left_where_it_ends(tmp_path):
    car = _run(tmp_path)
    before = car.x < 49.0
    assert np.allclose(car.y[before], -3.5 - 1.75) and np.allclose(car.yaw[before], 0.0)
    taper = (car.x > 55.0) & (car.x < 95.0)  # centre t = −3.5 − w/2, w = 3.5 − 0.07 (s − 50): dt/ds = 0.035
    assert np.allclose(car.y[taper], -3.5 - 0.5 * (3.5 - 0.07 * (car.x[taper] - 50.0)), atol=1e-6)
    assert np.allclose(car.yaw[taper], math.atan(0.035), atol=1e-6)
    after = car.x > 101.0  # lane −2 is gone (the border lane beyond is no driving lane): lane −1
    assert after.any() and np.allclose(car.y[after], -1.75) and np.allclose(car.yaw[after], 0.0)
    assert car.x[-1] == pytest.approx(10.0 + 10.0 * car.t[-1], abs=1e-6)
