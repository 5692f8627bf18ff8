"""Trailers (OpenSCENARIO 1.3 TrailerHitch / TrailerCoupler / TrailerRef, Connect/DisconnectTrailerAction)
against closed forms: in line behind a straight-driving tow vehicle, on the steady-state radius
√(R_h² − c²) behind one driving a circle, placed on the hitch when connected and left standing when
disconnected (the esmini agreement on its trailer examples lives in test_esmini_conformance.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from xosc_parts import follow_trajectory, teleport

from vei_scenario.cli import main
from vei_scenario.interpreter import run_scenario

HEAD = """<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork/><Entities>{entities}</Entities>"""


def _vehicle(
    name: str, category: str = "car", hitch: float | None = None, coupler: float | None = None, tows: str = ""
) -> str:
    parts = ""
    if coupler is not None:
        parts += f'<TrailerCoupler dx="{coupler}"/>'
    if hitch is not None:
        parts += f'<TrailerHitch dx="{hitch}"/>'
    if tows:
        parts += f'<Trailer><TrailerRef entityRef="{tows}"/></Trailer>'
    return (
        f'<ScenarioObject name="{name}"><Vehicle name="{name}" vehicleCategory="{category}"><BoundingBox>'
        '<Center x="1" y="0" z="0.8"/><Dimensions width="2" length="4" height="1.5"/></BoundingBox>'
        '<Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/><Axles>'
        '<FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.8" positionX="2.8" positionZ="0.3"/>'
        '<RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.8" positionX="0" positionZ="0.3"/>'
        f"</Axles>{parts}<Properties/></Vehicle></ScenarioObject>"
    )


def _circle(radius: float, length: float) -> str:
    """A FollowTrajectoryAction along a left circle of ``radius`` from the origin, heading along x."""
    return follow_trajectory(
        f'<Clothoid curvature="{1 / radius}" curvatureDot="0" length="{length}"><Position>'
        '<WorldPosition x="0" y="0" h="0"/></Position></Clothoid>'
    )


def _scenario(tmp_path, entities: str, init: str, events: str = "", stop_s: float = 10.0):
    story = ""
    if events:
        story = (
            '<Story name="s"><Act name="a"><ManeuverGroup name="g" maximumExecutionCount="1">'
            '<Actors selectTriggeringEntities="false"><EntityRef entityRef="Car"/></Actors>'
            f'<Maneuver name="m">{events}</Maneuver></ManeuverGroup></Act></Story>'
        )
    text = HEAD.format(entities=entities) + (
        f"<Storyboard><Init><Actions>{init}</Actions></Init>{story}"
        '<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>'
        f'<SimulationTimeCondition value="{stop_s}" rule="greaterThan"/></ByValueCondition></Condition>'
        "</ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"
    )
    path = tmp_path / "s.xosc"
    path.write_text(text)
    return path


def _event(name: str, action: str, at_s: float) -> str:
    return (
        f'<Event name="{name}" priority="parallel"><Action name="{name}a"><PrivateAction>{action}</PrivateAction>'
        '</Action><StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="none"><ByValueCondition>'
        f'<SimulationTimeCondition value="{at_s}" rule="greaterOrEqual"/></ByValueCondition></Condition>'
        "</ConditionGroup></StartTrigger></Event>"
    )


def test_a_trailer_rides_in_line_behind_a_tow_vehicle_driving_straight(tmp_path):
    """Hitch 1.2 m behind the car's axle, coupler 3.25 m ahead of the trailer's: the trailer's axle is
    4.45 m behind the car's at every step, wherever its own Init put it, and moves at the car's speed."""
    entities = _vehicle("Car", hitch=-1.2, tows="Trailer") + _vehicle("Trailer", "trailer", coupler=3.25)
    init = teleport("Car", 10, 5, 0, speed=8.0) + teleport("Trailer", 50, 50, 2.0)
    r = run_scenario(_scenario(tmp_path, entities, init, stop_s=5.0))
    car, trailer = r.traces["Car"], r.traces["Trailer"]
    assert np.allclose(trailer.x, car.x - 4.45, atol=1e-9) and np.allclose(trailer.y, 5.0, atol=1e-9)
    assert np.allclose(trailer.yaw, 0.0, atol=1e-12) and np.allclose(trailer.speed[1:], 8.0)


def test_a_trailer_settles_on_the_inner_steady_radius_behind_a_tow_vehicle_on_a_circle(tmp_path):
    """Tow axle on a circle of R = 20 m, hitch 1 m behind it: the hitch runs on √(20² + 1²); a trailer
    with 5 m from coupler to axle settles where its axle moves along its own heading, on the radius
    √(R_h² − 5²) = √376 m about the same centre (the no-slip trailer in a steady turn)."""
    entities = _vehicle("Car", hitch=-1.0, tows="Trailer") + _vehicle("Trailer", "trailer", coupler=5.0)
    init = teleport("Car", 0, 0, 0, speed=5.0, extra=_circle(20.0, 2 * math.pi * 20 * 3))
    r = run_scenario(_scenario(tmp_path, entities, init, stop_s=40.0))
    car, trailer = r.traces["Car"], r.traces["Trailer"]
    assert np.allclose(np.hypot(car.x, car.y - 20.0), 20.0, atol=2e-3)
    late = trailer.t > 20.0  # (several trailer lengths after the start in line)
    radius = np.hypot(trailer.x[late], trailer.y[late] - 20.0)
    assert radius == pytest.approx(np.full(radius.shape, math.sqrt(376.0)), abs=0.02)


def test_a_chain_of_two_trailers_is_pulled_front_to_back(tmp_path):
    entities = (
        _vehicle("Car", hitch=-1.0, tows="T1")
        + _vehicle("T1", "trailer", coupler=6.0, hitch=-2.0, tows="T2")
        + _vehicle("T2", "trailer", coupler=4.0)
    )
    init = teleport("Car", 0, 0, 0, speed=10.0)
    r = run_scenario(_scenario(tmp_path, entities, init, stop_s=2.0))
    car, t1, t2 = (r.traces[n] for n in ("Car", "T1", "T2"))
    assert np.allclose(t1.x, car.x - 7.0) and np.allclose(t2.x, t1.x - 6.0)


def test_connect_puts_the_trailer_on_the_hitch_and_disconnect_leaves_it_standing(tmp_path):
    entities = _vehicle("Car", hitch=-1.0) + _vehicle("Trailer", "trailer", coupler=3.0)
    init = teleport("Car", 0, 0, 0, speed=4.0) + teleport("Trailer", -3.0, 0.5, 0.3)
    connect = '<TrailerAction><ConnectTrailerAction trailerRef="Trailer"/></TrailerAction>'
    disconnect = "<TrailerAction><DisconnectTrailerAction/></TrailerAction>"
    events = _event("on", connect, 1.0) + _event("off", disconnect, 3.0)
    r = run_scenario(_scenario(tmp_path, entities, init, events, stop_s=5.0))
    car, trailer = r.traces["Car"], r.traces["Trailer"]
    before = trailer.t < 0.99
    assert np.allclose(trailer.x[before], -3.0) and np.allclose(trailer.y[before], 0.5)
    towed = (trailer.t > 1.05) & (trailer.t < 2.95)
    assert np.allclose(trailer.x[towed], car.x[towed] - 4.0, atol=1e-9) and np.allclose(trailer.y[towed], 0.0)
    after = trailer.t > 3.05
    assert np.ptp(trailer.x[after]) == 0.0 and np.all(trailer.speed[after] == 0.0)
    assert car.x[-1] > trailer.x[-1] + 10.0  # the car drove on alone


def test_a_trailer_ref_to_no_entity_is_refused_in_one_line(tmp_path, capsys):
    entities = _vehicle("Car", hitch=-1.0, tows="Nobody")
    path = _scenario(tmp_path, entities, teleport("Car", 0, 0, 0, speed=1.0))
    assert main(["run", str(path), "-o", str(tmp_path / "o")]) != 0
    err = capsys.readouterr().err
    assert "TrailerRef 'Nobody' names no entity" in err and "Traceback" not in err


def _shaped(v: float, seconds: float) -> str:
    return (
        f'<LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="cubic" value="{seconds}" '
        f'dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="{v}"/></SpeedActionTarget>'
        "</SpeedAction></LongitudinalAction>"
    )


def _when_trailer(name: str, action: str, condition: str) -> str:
    """An event of the Car once ``condition`` holds for T1."""
    return (
        f'<Event name="{name}" priority="parallel"><Action name="{name}a"><PrivateAction>{action}</PrivateAction>'
        '</Action><StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="none">'
        '<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="T1"/>'
        f"</TriggeringEntities><EntityCondition>{condition}</EntityCondition></ByEntityCondition></Condition>"
        "</ConditionGroup></StartTrigger></Event>"
    )


CHAIN = (
    _vehicle("Car", hitch=-1.0, tows="T1")
    + _vehicle("T1", "trailer", coupler=6.0, hitch=-2.0, tows="T2")
    + _vehicle("T2", "trailer", coupler=-0.8)  # (a coupler behind the axle)
)
#: (entities, init, events, stop) of each run the core's trailers are compared on
PULLED = {
    "chain_on_a_circle": (CHAIN, teleport("Car", 0, 0, 0, speed=6.0, extra=_circle(25.0, 400.0)), "", 20.0),
    "slowing_on_a_circle": (
        CHAIN,
        teleport("Car", 0, 0, 0, speed=9.0, extra=_circle(30.0, 400.0)),
        _event("slow", _shaped(2.0, 4.0), 3.0),
        15.0,
    ),
    "connected_and_disconnected": (
        _vehicle("Car", hitch=-1.0) + _vehicle("T1", "trailer", coupler=3.0),
        teleport("Car", 0, 0, 0.2, speed=4.0) + teleport("T1", -3.0, 0.5, 0.3),
        _event("on", '<TrailerAction><ConnectTrailerAction trailerRef="T1"/></TrailerAction>', 1.0)
        + _event("off", "<TrailerAction><DisconnectTrailerAction/></TrailerAction>", 6.0),
        9.0,
    ),
    "watching_a_trailer": (
        CHAIN,
        teleport("Car", 0, 0, 0, speed=7.0, extra=_circle(40.0, 400.0)),
        _when_trailer("far", _shaped(12.0, 2.0), '<TraveledDistanceCondition value="31.4"/>')
        + _when_trailer("slow", _shaped(3.0, 1.0), '<SpeedCondition value="11.5" rule="greaterThan"/>'),
        14.0,
    ),
}


@pytest.mark.parametrize("case", sorted(PULLED))
def test_towed_trailers_in_the_core_equal_the_stepped_run(tmp_path, monkeypatch, case):
    """The core pulls towed trailers (front to back, after everyone has moved) as trailers.pull does:
    the run with quiet stretches equals the interpreter's step by step, bit for bit, and most steps
    are the core's."""
    from test_cruise import assert_identical, run_both

    entities, init, events, stop = PULLED[case]
    fast, cruised, slow = run_both(_scenario(tmp_path, entities, init, events, stop_s=stop), monkeypatch)
    assert_identical(fast, slow)
    assert "towed" in slow.traces["T1"].status
    assert np.ptp(slow.traces["T1"].yaw) > 0.1 or case == "connected_and_disconnected"
    if case == "watching_a_trailer":
        assert np.any(np.isclose(slow.traces["Car"].speed, 3.0)), "the trailer's speed was never watched"
    assert cruised > 0.5 * len(fast.t), f"only {cruised} of {len(fast.t)} steps cruised"
