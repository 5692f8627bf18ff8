"""A scenario written with scenariogeneration (another author's tool, not vei's writer): a car in the
next lane overtakes the ego and cuts in 10 m ahead of it, the ego brakes when its free-space headway
to that car falls below 1 s, and a slow car ahead speeds up on a curved two-lane road. vei plays it as
esmini 3.6 does. Before the free-space headway read esmini's signed distance (boxes overlapping along
the way: a headway of 0), the ego braked 1.7 s late and ended 11.6 m away from esmini's."""

from __future__ import annotations

from pathlib import Path

from scenariogeneration import xodr, xosc

from vei_scenario.conformance.esmini import cross_check


def _write(out: Path) -> Path:
    road = xodr.create_road(
        [xodr.Line(300), xodr.Arc(0.004, angle=0.3), xodr.Line(200)], id=0, left_lanes=2, right_lanes=2
    )
    odr = xodr.OpenDrive("road")
    odr.add_road(road)
    odr.adjust_roads_and_lanes()
    odr.write_xml(str(out / "road.xodr"))
    params = xosc.ParameterDeclarations()
    params.add_parameter(xosc.Parameter("TargetSpeed", xosc.ParameterType.double, "25"))
    box = xosc.BoundingBox(2, 5, 1.8, 2.0, 0, 0.9)
    car = xosc.Vehicle(
        "car", xosc.VehicleCategory.car, box, xosc.Axle(0.5, 0.8, 1.68, 2.98, 0.4), xosc.Axle(0, 0.8, 1.68, 0, 0.4),
        69, 10, 10,
    )  # fmt: skip
    entities = xosc.Entities()
    for name in ("Ego", "Target", "Slow"):
        entities.add_scenario_object(name, car)
    init = xosc.Init()
    shape, dim = xosc.DynamicsShapes, xosc.DynamicsDimension
    step = xosc.TransitionDynamics(shape.step, dim.time, 1)
    for name, s, lane, speed in (("Ego", 20, -1, 22), ("Target", 5, -2, "$TargetSpeed"), ("Slow", 150, -1, 12)):
        init.add_init_action(name, xosc.TeleportAction(xosc.LanePosition(s, 0, lane, 0)))
        init.add_init_action(name, xosc.AbsoluteSpeedAction(speed, step))

    def group(actor: str, name: str, action, trigger) -> xosc.ManeuverGroup:
        event = xosc.Event(name, xosc.Priority.override)
        event.add_action(name, action)
        event.add_trigger(trigger)
        maneuver = xosc.Maneuver(name)
        maneuver.add_event(event)
        g = xosc.ManeuverGroup(name)
        g.add_actor(actor)
        g.add_maneuver(maneuver)
        return g

    cut_in = group(
        "Target", "cut_in",
        xosc.AbsoluteLaneChangeAction(-1, xosc.TransitionDynamics(shape.sinusoidal, dim.time, 3)),
        xosc.EntityTrigger("ahead", 0, xosc.ConditionEdge.rising, xosc.RelativeDistanceCondition(
            10, xosc.Rule.greaterThan, xosc.RelativeDistanceType.longitudinal, "Ego", freespace=False), "Target"),
    )  # fmt: skip
    brake = group(
        "Ego", "brake",
        xosc.AbsoluteSpeedAction(15, xosc.TransitionDynamics(shape.linear, dim.rate, 4)),
        xosc.EntityTrigger("close", 0, xosc.ConditionEdge.rising, xosc.TimeHeadwayCondition(
            "Target", 1.0, xosc.Rule.lessThan, freespace=True), "Ego"),
    )  # fmt: skip
    speed_up = group(
        "Slow", "speed_up",
        xosc.AbsoluteSpeedAction(20, xosc.TransitionDynamics(shape.cubic, dim.time, 4)),
        xosc.ValueTrigger("t6", 0, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(6, xosc.Rule.greaterThan)),
    )  # fmt: skip
    act = xosc.Act("act", xosc.ValueTrigger(
        "start", 0, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(0, xosc.Rule.greaterThan)))  # fmt: skip
    for g in (cut_in, brake, speed_up):
        act.add_maneuver_group(g)
    stop = xosc.ValueTrigger(
        "stop", 0, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(20, xosc.Rule.greaterThan), "stop"
    )
    board = xosc.StoryBoard(init, stop)
    board.add_act(act)
    scenario = xosc.Scenario(
        "cut-in",
        "vei tests",
        params,
        entities,
        board,
        xosc.RoadNetwork("road.xodr"),
        xosc.Catalog(),
        osc_minor_version=2,
    )
    scenario.write_xml(str(out / "s.xosc"))
    return out / "s.xosc"


def test_a_scenariogeneration_cut_in_plays_as_esmini_plays_it(tmp_path, esmini):
    c = cross_check(esmini, _write(tmp_path), {}, 0.01)
    assert c.max_deviation_m < 0.01, [(e.entity, e.max_deviation_m, e.at_time_s) for e in c.entities]
    assert c.same_verdict and c.end_time_difference_s <= 0.01 + 1e-9
