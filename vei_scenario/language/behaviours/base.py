"""What an atomic behaviour is: a named agent, a configuration with ranges, and OpenSCENARIO steps.

A behaviour compiles to :class:`Step` s, each one OpenSCENARIO ``Event`` of the actor's maneuver;
the steps of one behaviour run one after another (a step starts once the previous one is complete,
and when its own conditions hold). The writer (:mod:`vei_scenario.language.scenario_writer`) chains
behaviours into sequences and parallel groups with ``StoryboardElementStateCondition`` s.

Configuration values carry units in their names (``_m``, ``_s``, ``_mps``, ``_mps2``). ``PROFILES``
gives, per criticality word class (dangerous, moderate, safe), the ranges the rules backend samples
from; :data:`Parameter.default` is what an unqualified description gets.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from scenariogeneration import xosc

#: Standard gravity (m/s²): friction x g bounds braking.
G = 9.81


@dataclass(frozen=True)
class Parameter:
    default: float
    low: float
    high: float
    doc: str


@dataclass
class Condition:
    """A start condition of a step besides the previous step's completion.

    kind: ``ego_within`` (the free-space longitudinal distance between the ego and the actor below
    ``value`` m), ``ego_beyond`` (above it; OpenSCENARIO's distance has no sign, so a behaviour
    passes "alongside" first to know which side it is on), ``time_gap`` (the ego's time headway to
    the actor below ``value`` s), ``ego_near`` (the straight-line distance between the ego's and the
    actor's reference points below ``value`` m: for road users on different roads, e.g. one waiting
    in a side road). ``entity`` names the other party when it is not the ego (a lead that swerves
    round a stopped car watches that car)."""

    kind: str
    value: float
    entity: str = "Ego"


@dataclass
class Step:
    name: str
    actions: list
    conditions: list[Condition] = field(default_factory=list)
    delay_s: float = 0.0
    #: A step whose actions never end by themselves (continuous following, holding a speed) hands
    #: over to what follows after ``hold_s`` seconds.
    hold_s: float | None = None
    #: When its conditions may never hold (the ego brakes for something else and the gap never
    #: closes), the step starts anyway this long after it could have started (s).
    fallback_s: float | None = None


@dataclass
class ActorContext:
    """What a behaviour may know when it compiles: who acts, on which map, in which lanes."""

    actor: str
    actor_type: str
    ego: str
    ego_speed_mps: float
    actor_speed_mps: float
    ego_lane_id: int
    actor_lane_id: int
    actor_road: str
    actor_s_m: float
    lanes: int
    friction: float
    map_kind: str
    #: (road id, s at its junction end) of the actor's approach, and the road a turn leads to
    exits: dict[str, str] = field(default_factory=dict)
    junction_end_s_m: float | None = None
    #: For crossing behaviours (and a turn into the road from beside it): the path across the ego's
    #: road as world points, and the actor's distance to the ego's lane centre along it (m); the ego's
    #: distance to the conflict (m).
    crossing_path: list[tuple[float, float, float]] | None = None
    crossing_distance_m: float | None = None
    #: It stands beyond the far kerb and pulls out across the oncoming lanes along ``crossing_path``
    #: (a cut-in from a parking place there), not by a lane change.
    pulls_out_across: bool = False
    trajectories: dict[str, xosc.Trajectory] = field(default_factory=dict)
    #: The actor's Performance maxAcceleration: a speed it is told to reach takes at least v / a.
    actor_max_accel_mps2: float = 0.0
    #: The actor's Performance maxSpeed (0: not bounded): a timing worked out at a faster speed fails.
    actor_max_speed_mps: float = 0.0
    #: The ego's s on its road (m); the actor's length (m).
    ego_s_m: float = 0.0
    actor_length_m: float = 4.6
    #: A junction approach's exits seen by the actor itself (left, right, straight → road id).
    actor_exits: dict[str, str] = field(default_factory=dict)
    #: Which way the actor faces: ``with`` its lane's driving direction, or ``against`` it.
    facing: str = "with"
    #: The actor's offset from its lane's centre at the start (m): a rider at the kerb edge.
    actor_offset_m: float = 0.0
    #: An earlier behaviour of the actor has given it a route through the junction (a turn there).
    routed: bool = False
    #: Set once a behaviour of the actor is compiled: what follows it starts where that one left the
    #: actor (a cut-in after an overtake is already past the ego), not where it spawned
    acted: bool = False
    #: The ego's way through its junction (straight, left, right): what a road user must cross to meet it.
    ego_route: str = "straight"

    def on_another_arm(self) -> bool:
        """Whether the actor starts on another arm of the ego's junction or roundabout (one of the
        ego's exits), not on the ego's road. Why: lane ids are a road's own, and the ego's lane is
        no lane of that arm's; a lane change towards it would run on into the junction's roads,
        whose lanes do not link to it."""
        return self.actor_road in self.exits.values()

    def ego_to_junction_m(self) -> float:
        """The ego's distance to its junction entry (m), 0 on a map without one."""
        return max(0.0, self.junction_end_s_m - self.ego_s_m) if self.junction_end_s_m else 0.0

    def reachable(self, speed_mps: float, accel_mps2: float) -> tuple[float, float]:
        """(speed, acceleration) bounded by what the actor's vehicle can do: a timing worked out at
        more than that brings it to the meeting point late (a rider timed as a car comes out
        behind the ego)."""
        top = min(speed_mps, self.actor_max_speed_mps) if self.actor_max_speed_mps > 0 else speed_mps
        return top, min(accel_mps2, self.actor_max_accel_mps2) if self.actor_max_accel_mps2 > 0 else accel_mps2

    def max_decel(self, wanted: float) -> float:
        """``wanted`` bounded by what the road's friction allows."""
        return min(wanted, self.friction * G)


def speed_action(speed: float, rate: float | None = None, time: float | None = None) -> xosc.AbsoluteSpeedAction:
    """A speed change at a constant rate (m/s²) or over a time (s); a step change with neither."""
    if rate is not None:
        dyn = xosc.TransitionDynamics(xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, round(rate, 3))
    elif time is not None:
        dyn = xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, round(time, 3))
    else:
        dyn = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0.0)
    return xosc.AbsoluteSpeedAction(round(speed, 3), dyn)


def lane_change_to_ego(ego: str, duration: float) -> xosc.RelativeLaneChangeAction:
    dyn = xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, round(duration, 3))
    return xosc.RelativeLaneChangeAction(0, ego, dyn)


def lane_change_to(lane_id: int, duration: float) -> xosc.AbsoluteLaneChangeAction:
    dyn = xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, round(duration, 3))
    return xosc.AbsoluteLaneChangeAction(lane_id, dyn)


def route_action(
    ctx: ActorContext, turn: str, exit_s_m: float = 40.0, own_view: bool = False, exit_lane: int = 1
) -> xosc.AssignRouteAction:
    """A route from the actor's position through the junction to the exit on side ``turn``
    (straight, left, right; seen by the ego, or by the actor itself with ``own_view``): it leaves on
    the exit arm's lanes that drive away from the junction (lane ``exit_lane`` of them, 1 the one
    next to the centre)."""
    exit_road = (ctx.actor_exits if own_view else ctx.exits).get(turn)
    if exit_road is None:
        raise ValueError(f"{ctx.actor}: the {ctx.map_kind} map has no {turn} exit")
    route = xosc.Route(f"{ctx.actor}_{turn}")
    start = xosc.LanePosition(round(ctx.actor_s_m, 3), 0, ctx.actor_lane_id, ctx.actor_road)
    route.add_waypoint(start, xosc.RouteStrategy.shortest)
    route.add_waypoint(xosc.LanePosition(exit_s_m, 0, exit_lane, exit_road), xosc.RouteStrategy.shortest)
    return xosc.AssignRouteAction(route)


def value(cfg: dict, params: dict[str, Parameter], name: str) -> float:
    """A configuration value, its default when absent, clipped to the parameter's range."""
    p = params[name]
    v = float(cfg.get(name, p.default))
    return min(max(v, p.low), p.high)


def time_to_cover(distance_m: float, speed_mps: float, accel_mps2: float, start_mps: float = 0.0) -> float:
    """Time (s) to travel ``distance_m`` starting at ``start_mps`` and accelerating at ``accel_mps2``
    up to ``speed_mps`` (held from then on)."""
    v0, v, a = max(start_mps, 0.0), max(speed_mps, 0.1), max(accel_mps2, 0.1)
    if v0 >= v:
        return distance_m / v0 if v0 > 0 else float("inf")
    ramp_m = (v * v - v0 * v0) / (2 * a)
    if distance_m <= ramp_m:
        return (-v0 + (v0 * v0 + 2 * a * distance_m) ** 0.5) / a
    return (v - v0) / a + (distance_m - ramp_m) / v


def side_with_a_lane(ctx: ActorContext, cfg: dict, default: float) -> float:
    """The side (+1 left, -1 right) a lane change goes to: the one the configuration states, else
    ``default`` where the road has a lane there in the actor's direction, else the other side. Why:
    "the car ahead swerves out" leaves the side open, and from the innermost lane of a one-way road
    or a dual carriageway the only way out is to the right."""
    if "direction" in cfg:
        return float(cfg["direction"])
    try:
        neighbour_lane(ctx, default)
    except ValueError:
        return -default
    return default


def neighbour_lane(ctx: ActorContext, direction: float) -> int:
    """The lane next to the actor's in its own direction of travel, to the left (``direction`` ≥ 0)
    or the right; ValueError when the road has none there."""
    step = 1 if direction >= 0 else -1
    target = ctx.actor_lane_id + step
    if target == 0:
        target += step
    if abs(target) > ctx.lanes or (target > 0) != (ctx.actor_lane_id > 0):
        raise ValueError(f"{ctx.actor} has no lane to the {'left' if step > 0 else 'right'} in its direction")
    return target
