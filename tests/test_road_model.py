# ruff: noqa: E501  (hand-written OpenDRIVE/OpenSCENARIO keep their XML lines whole)
"""The OpenDRIVE road model against analytic geometry, and lane positions / catalogs in vei run."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import fresnel

from vei_scenario.roads.road_model import Geometry, RoadNetwork


def test_arc_follows_its_circle():
    g = Geometry(0.0, 10.0, 5.0, 0.3, 50.0, "arc", {"curvature": 0.02})
    r = 1 / 0.02
    cx, cy = 10.0 - r * math.sin(0.3), 5.0 + r * math.cos(0.3)  # centre to the left
    for ds in np.linspace(0, 50, 11):
        x, y, h = g.pose(float(ds))
        assert math.hypot(x - cx, y - cy) == pytest.approx(r, abs=1e-9)
        assert h == pytest.approx(0.3 + 0.02 * ds, abs=1e-12)


def test_spiral_matches_fresnel_integrals():
    """Clothoid from curvature 0 to k1 over L: x = a·C(u/a'), y = a·S(u/a') with a = sqrt(π·L/k1)."""
    L, k1 = 80.0, 0.025
    g = Geometry(0.0, 0.0, 0.0, 0.0, L, "spiral", {"curvStart": 0.0, "curvEnd": k1})
    a = math.sqrt(math.pi * L / k1)
    for ds in (10.0, 40.0, 80.0):
        S, C = fresnel(ds / a)
        x, y, h = g.pose(ds)
        assert x == pytest.approx(a * C, abs=1e-9) and y == pytest.approx(a * S, abs=1e-9)
        assert h == pytest.approx(0.5 * k1 / L * ds * ds, abs=1e-12)


def test_param_poly3_straight_and_lane_centres(tmp_path):
    xodr = tmp_path / "r.xodr"
    xodr.write_text(
        """<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="7" length="100" junction="-1"><planView>
<geometry s="0" x="1" y="2" hdg="0.5" length="100"><paramPoly3 aU="0" bU="1" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0" pRange="arcLength"/></geometry>
</planView><lanes><laneOffset s="0" a="0.5" b="0" c="0" d="0"/><laneSection s="0">
<left><lane id="1" type="driving"><width sOffset="0" a="3.0" b="0" c="0" d="0"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
<lane id="-2" type="driving"><width sOffset="0" a="3.0" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"""
    )
    net = RoadNetwork.load(xodr)
    road = net.road("7")
    assert road.lane_center_t(30, -1) == pytest.approx(0.5 - 1.75)
    assert road.lane_center_t(30, -2) == pytest.approx(0.5 - 3.5 - 1.5)
    assert road.lane_center_t(30, 1) == pytest.approx(0.5 + 1.5)
    x, y, h = road.world(30.0, road.lane_center_t(30, -2))
    t = -4.5
    assert (x, y) == pytest.approx(
        (1 + 30 * math.cos(0.5) - t * math.sin(0.5), 2 + 30 * math.sin(0.5) + t * math.cos(0.5))
    )
    rp = net.project(x, y)
    assert rp.road.id == "7" and rp.lane == -2 and rp.s == pytest.approx(30.0, abs=1e-6)


def test_catalog_entity_keeps_its_lane_at_its_speed(tmp_path):
    """A catalog vehicle (parameter assigned by the reference) on a LanePosition, no controller:
    it keeps its lane at its speed, as esmini's default controller does."""
    from vei_scenario.interpreter import run_scenario

    (tmp_path / "cat").mkdir()
    (tmp_path / "cat" / "v.xosc").write_text(
        """<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="c" author="t"/>
<Catalog name="VehicleCatalog"><Vehicle name="car" vehicleCategory="car">
<ParameterDeclarations><ParameterDeclaration name="Len" parameterType="double" value="4"/></ParameterDeclarations>
<BoundingBox><Center x="1.3" y="0" z="0.7"/><Dimensions width="1.8" length="$Len" height="1.4"/></BoundingBox>
<Performance maxSpeed="60" maxAcceleration="5" maxDeceleration="9"/>
<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.6" positionX="2.6" positionZ="0.3"/>
<RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0" positionZ="0.3"/></Axles>
<Properties/></Vehicle></Catalog></OpenSCENARIO>"""
    )
    (tmp_path / "road.xodr").write_text(
        """<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="300" junction="-1"><planView>
<geometry s="0" x="0" y="0" hdg="0" length="300"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"""
    )
    (tmp_path / "s.xosc").write_text(
        """<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="s" author="t"/>
<ParameterDeclarations><ParameterDeclaration name="L" parameterType="double" value="4.6"/></ParameterDeclarations>
<CatalogLocations><VehicleCatalog><Directory path="cat"/></VehicleCatalog></CatalogLocations>
<RoadNetwork><LogicFile filepath="road.xodr"/></RoadNetwork>
<Entities><ScenarioObject name="Ego"><CatalogReference catalogName="VehicleCatalog" entryName="car">
<ParameterAssignments><ParameterAssignment parameterRef="Len" value="$L"/></ParameterAssignments></CatalogReference>
</ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="Ego">
<PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-1" s="20" offset="0"/></Position></TeleportAction></PrivateAction>
<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/>
<SpeedActionTarget><AbsoluteTargetSpeed value="10"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>
</Private></Actions></Init>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising"><ByValueCondition>
<SimulationTimeCondition value="5" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""
    )
    r = run_scenario(tmp_path / "s.xosc", {"L": "5.0"})
    tr = r.traces["Ego"]
    assert tr.length == 5.0 and tr.center_x == pytest.approx(1.3)
    k = int(np.argmin(np.abs(tr.t - 4.0)))
    assert tr.x[k] == pytest.approx(20 + 10 * 4.0, abs=1e-9) and tr.y[k] == pytest.approx(-1.75, abs=1e-12)
    with pytest.raises(Exception, match="catalog entry VehicleCatalog/nope not found"):
        (tmp_path / "bad.xosc").write_text(
            (tmp_path / "s.xosc").read_text().replace('entryName="car"', 'entryName="nope"')
        )
        run_scenario(tmp_path / "bad.xosc")


def test_trajectory_clothoid_matches_fresnel_integrals():
    """The sampled Clothoid shape of a trajectory (heading quadratic in arc length) against Fresnel."""
    from vei_scenario.interpreter.shapes import clothoid_points

    L, rate = 60.0, 0.0005  # curvature from 0 rising by 0.0005 1/m per m
    x, y, h = clothoid_points(0.0, 0.0, 0.0, 0.0, rate, L)
    a = math.sqrt(math.pi / rate)
    S, C = fresnel(L / a)
    assert x[-1] == pytest.approx(a * C, abs=1e-6) and y[-1] == pytest.approx(a * S, abs=1e-6)
    assert h[-1] == pytest.approx(0.5 * rate * L * L, abs=1e-12)
    assert np.max(np.hypot(np.diff(x), np.diff(y))) <= 0.05 + 1e-9


def _two_section_road(tmp_path, banked: bool = False):
    xodr = tmp_path / "s.xodr"
    bank = (
        '<lateralProfile><superelevation s="0" a="-1.0471975511965976" b="0" c="0" d="0"/></lateralProfile>'
        if banked
        else ""
    )
    xodr.write_text(
        f"""<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" length="200" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="200"><line/></geometry></planView>{bank}
<lanes>
<laneSection s="0"><center><lane id="0" type="none"/></center><right>
  <lane id="-1" type="driving"><link><successor id="-2"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection>
<laneSection s="100"><center><lane id="0" type="none"/></center><right>
  <lane id="-1" type="driving"><width sOffset="0" a="3.0" b="0" c="0" d="0"/></lane>
  <lane id="-2" type="driving"><link><predecessor id="-1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection>
</lanes></road></OpenDRIVE>"""
    )
    return RoadNetwork.load(xodr)


def test_lane_links_across_sections_and_superelevation(tmp_path):
    road = _two_section_road(tmp_path).road("1")
    assert road.map_lane(-1, 0, 1) == -2 and road.map_lane(-2, 1, 0) == -1 and road.map_lane(-1, 1, 0) is None
    assert road.lane_center_t(50, -1) == pytest.approx(-1.75) and road.lane_center_t(150, -2) == pytest.approx(-4.75)
    banked = _two_section_road(tmp_path, banked=True).road("1")
    # 60° of bank: the lane is half as far from the reference line seen from above
    assert banked.world(50, -1.75)[1] == pytest.approx(-0.875, abs=1e-12)


def _lane_keeping_scenario(tmp_path, xodr_name: str, story: str = "") -> object:
    from vei_scenario.interpreter import run_scenario

    xosc = tmp_path / "k.xosc"
    xosc.write_text(
        f"""<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<RoadNetwork><LogicFile filepath="{xodr_name}"/></RoadNetwork>
<Entities><ScenarioObject name="A"><Vehicle name="v" vehicleCategory="car"><BoundingBox><Center x="0" y="0" z="0"/><Dimensions width="2" length="4" height="1.5"/></BoundingBox>
<Performance maxSpeed="50" maxAcceleration="5" maxDeceleration="10"/><Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.6" positionX="2.8" positionZ="0.3"/><RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0" positionZ="0.3"/></Axles><Properties/></Vehicle></ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="A">
<PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="-1" s="10" offset="0"/></Position></TeleportAction></PrivateAction>
<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="cubic" dynamicsDimension="time" value="1"/><SpeedActionTarget><AbsoluteTargetSpeed value="20"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>
</Private></Actions></Init>{story}
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="14" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""
    )
    return run_scenario(xosc, {}, 0.01)


def test_lane_keeping_follows_lane_links_and_performance_limits(tmp_path):
    _two_section_road(tmp_path)
    tr = _lane_keeping_scenario(tmp_path, "s.xodr").traces["A"]
    # the cubic 0 -> 20 m/s in 1 s would peak at 30 m/s²; stretched to maxAcceleration 5: 1.5·20/5 = 6 s
    k = int(np.argmax(tr.speed >= 20.0 - 1e-9))
    assert tr.t[k] == pytest.approx(6.0, abs=0.011) and np.max(tr.accel) <= 5.0 + 1e-6
    # lane -1 links to lane -2 at s = 100: the car follows the link (without it: lane -1, y = -1.5)
    assert np.all(np.abs(tr.y[tr.x < 99.9] + 1.75) < 1e-9) and np.all(np.abs(tr.y[tr.x > 100.1] + 4.75) < 1e-9)
    # the end of the road: it stops there and stands
    assert tr.x[-1] == pytest.approx(200.0) and tr.speed[-1] == 0.0


def test_a_network_is_built_once_per_file_content(tmp_path):
    """Loading the same bytes again gives the network already built (a sweep's variants share it);
    changed bytes, even of the same length in the same instant, give a new one."""
    from vei_scenario.roads.road_model import RoadNetwork

    def road(length: str) -> str:
        return (
            f'<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="{length}" junction="-1"><planView>'
            f'<geometry s="0" x="0" y="0" hdg="0" length="{length}"><line/></geometry></planView><lanes><laneSection '
            's="0"><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><width sOffset="0" '
            'a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road></OpenDRIVE>'
        )

    path = tmp_path / "r.xodr"
    path.write_text(road("100"))
    first = RoadNetwork.load(path)
    assert RoadNetwork.load(path) is first
    path.write_text(road("200"))  # same size
    second = RoadNetwork.load(path)
    assert second is not first and second.road("1").length == 200.0 and first.road("1").length == 100.0


def test_a_road_without_an_id_is_refused_naming_its_line(tmp_path):
    """Links and positions name roads by id: a road without one could be driven onto and never found."""
    from vei_scenario.errors import VeiInputError
    from vei_scenario.roads.road_model import RoadNetwork

    path = tmp_path / "r.xodr"
    path.write_text(
        '<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="4"/>\n'
        '<road length="10" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/>'
        '</geometry></planView><lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>'
        '<lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>'
        "</laneSection></lanes></road></OpenDRIVE>"
    )
    with pytest.raises(VeiInputError) as info:
        RoadNetwork.load(path)
    assert str(info.value).startswith(f"{path}: line 2: ") and "needs an id" in str(info.value)


def test_a_lane_renamed_in_the_next_section_is_posed_up_to_its_end(tmp_path):
    """A lane whose id changes at a section boundary (a merge: -2 goes on as -1) is posed right up to
    the boundary: the heading's estimate of where its centre drifts stays within the section (it asked
    the next section for lane -2 within 5 cm of the boundary, and a car keeping that lane stopped the
    run with KeyError -2)."""
    closing = '<width sOffset="0" a="3.5" b="0" c="-0.0042" d="5.6e-05"/>'  # (3.5 m to 0 over 50 m)
    wide = '<width sOffset="0" a="3.5" b="0" c="0" d="0"/>'
    xodr = tmp_path / "merge.xodr"
    xodr.write_text(
        '<OpenDRIVE><header revMajor="1" revMinor="6"/><road id="1" length="200" junction="-1"><planView>'
        '<geometry s="0" x="0" y="0" hdg="0" length="200"><line/></geometry></planView><lanes>'
        '<laneSection s="0"><center><lane id="0" type="none"/></center><right>'
        f'<lane id="-1" type="driving">{closing}</lane>'
        f'<lane id="-2" type="driving"><link><successor id="-1"/></link>{wide}</lane></right></laneSection>'
        '<laneSection s="50"><center><lane id="0" type="none"/></center><right>'
        f'<lane id="-1" type="driving"><link><predecessor id="-2"/></link>{wide}</lane></right></laneSection>'
        "</lanes></road></OpenDRIVE>"
    )
    road = RoadNetwork.load(xodr).road("1")
    for s in np.linspace(49.9, 50.0 - 1e-7, 101):
        x, y, heading, t = road.lane_pose(s, -2, 0.0)
        assert t == pytest.approx(-1.75, abs=1e-3) and abs(heading) < 1e-3, s
    x, y, heading, t = road.lane_pose(50.0, -1, 0.0)  # (and on as -1 beyond)
    assert t == pytest.approx(-1.75)
