"""Pieces of OpenSCENARIO XML that the interpreter tests build their scenarios from."""

from __future__ import annotations


def vehicle(name: str = "v", center_x: float = 1.4, length: float = 4.5) -> str:
    """A car 1.8 m wide whose box centre is ``center_x`` ahead of its reference point."""
    return f"""<Vehicle name="{name}" vehicleCategory="car"><BoundingBox><Center x="{center_x}" y="0" z="0.7"/>
<Dimensions width="1.8" length="{length}" height="1.4"/></BoundingBox>
<Performance maxSpeed="60" maxAcceleration="10" maxDeceleration="10"/>
<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.6" positionX="2.8" positionZ="0.3"/>
<RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0" positionZ="0.3"/></Axles>
<Properties/></Vehicle>"""


#: A 4.5 m car with its rear axle as the reference point.
CAR = vehicle()

#: Absolute timing of a trajectory's vertex times.
ABSOLUTE_TIMING = '<Timing domainAbsoluteRelative="absolute" scale="1" offset="0"/>'


def speed_to(target: str, shape: str = "step", value: float = 0, dimension: str = "time") -> str:
    """A PrivateAction taking the speed to ``target`` (a SpeedActionTarget's child element) by a
    transition of ``shape`` over ``value`` of ``dimension``."""
    return (
        f'<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="{shape}" value="{value}" '
        f'dynamicsDimension="{dimension}"/><SpeedActionTarget>{target}</SpeedActionTarget>'
        "</SpeedAction></LongitudinalAction></PrivateAction>"
    )


def speed_action(v: float, shape: str = "step", value: float = 0, dimension: str = "time") -> str:
    """A PrivateAction taking the speed to ``v`` by a transition of ``shape`` over ``value`` of ``dimension``."""
    return speed_to(f'<AbsoluteTargetSpeed value="{v}"/>', shape, value, dimension)


def step_speed(v: float) -> str:
    """A PrivateAction setting the speed to ``v`` at once."""
    return speed_action(v)


def teleport(name: str, x: float, y: float, h: float, speed: float | None = None, extra: str = "") -> str:
    """An Init ``<Private>``: ``name`` placed by world coordinates, optionally given a speed, then ``extra``."""
    out = (
        f'<Private entityRef="{name}"><PrivateAction><TeleportAction><Position>'
        f'<WorldPosition x="{x}" y="{y}" h="{h}"/></Position></TeleportAction></PrivateAction>'
    )
    return out + (step_speed(speed) if speed is not None else "") + extra + "</Private>"


def follow_trajectory(shape: str, timing: str = "<None/>", closed: bool = False) -> str:
    """A PrivateAction following an inline trajectory of ``shape`` (position mode)."""
    return (
        '<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="t" '
        f'closed="{str(closed).lower()}"><Shape>{shape}</Shape></Trajectory></TrajectoryRef>'
        f'<TimeReference>{timing}</TimeReference><TrajectoryFollowingMode followingMode="position"/>'
        "</FollowTrajectoryAction></RoutingAction></PrivateAction>"
    )


def one_car(speed: str, end: float = 1.0, action: str = "") -> str:
    """A whole scenario without a road: one car set going at ``speed`` (an attribute's text: a number,
    a ``$parameter`` or an expression), given the PrivateAction ``action`` at once, stopped at ``end`` s."""
    story = ""
    if action:
        story = f"""<Story name="s"><Act name="a"><ManeuverGroup name="g" maximumExecutionCount="1">
<Actors selectTriggeringEntities="false"><EntityRef entityRef="Ego"/></Actors><Maneuver name="m">
<Event name="e" priority="overwrite"><Action name="x">{action}</Action><StartTrigger><ConditionGroup>
<Condition name="now" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0"
rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Event></Maneuver>
</ManeuverGroup><StartTrigger><ConditionGroup><Condition name="go" delay="0" conditionEdge="none">
<ByValueCondition><SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition>
</ConditionGroup></StartTrigger></Act></Story>"""
    return f"""<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2024-01-01T00:00:00" description="one car" author="vei"/>
<CatalogLocations/><RoadNetwork/><Entities><ScenarioObject name="Ego">{CAR}</ScenarioObject></Entities>
<Storyboard><Init><Actions>{teleport("Ego", 0, 0, 0, extra=speed_action(speed))}</Actions></Init>{story}
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="{end}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup>
</StopTrigger></Storyboard></OpenSCENARIO>
"""
