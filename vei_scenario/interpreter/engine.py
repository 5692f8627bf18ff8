"""The fixed-step engine: builds entities and the storyboard from a loaded scenario and runs them.

Each step, in this order: the storyboard (stop trigger, act and event triggers, element states), the
actions (which set what moves the entities), the motion of every entity (active controller, else its
followed trajectory or speed), collision detection between all oriented boxes, and recording.
Outputs (CSV, metrics, plots) are made from the returned :class:`RunResult` elsewhere.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from vei_scenario.core import _core
from vei_scenario.interpreter import trailers
from vei_scenario.interpreter.actions import (
    global_actions,
    private_actions,
)
from vei_scenario.interpreter.clock import step_time
from vei_scenario.interpreter.context import Context
from vei_scenario.interpreter.controllers import make_controller
from vei_scenario.interpreter.cruise import Offers, cruise, offered
from vei_scenario.interpreter.document import ScenarioDocument
from vei_scenario.interpreter.entities import Entity
from vei_scenario.interpreter.init_order import init_order
from vei_scenario.interpreter.motion import advance_along, lane_keep
from vei_scenario.interpreter.positions import ensure_lane
from vei_scenario.interpreter.recording import Recording
from vei_scenario.interpreter.shapes import placed_when_built, polyline_from
from vei_scenario.interpreter.storyboard import Storyboard
from vei_scenario.models.vehicle import VehicleLimits

#: Actions that only set a value (a signal state, a variable, a parameter): esmini carries them out as
#: their event starts, so triggers evaluated after it in the same step see the new value.

#: Runs end here at the latest (s) when the storyboard has no stop trigger that fires.
DEFAULT_MAX_TIME_S = 600.0
#: How often (steps) a run reports its progress to an ``on_progress`` callback.
PROGRESS_EVERY_STEPS = 2000

#: How entities see each other within a step. ``sequential`` (default, Gauss-Seidel): entities move
#: in declaration order and each sees those moved before it at their new state. ``jacobi``: every
#: entity sees the others as they were at the start of the step and the planner's command reaches the
#: vehicle one step later (it starts at 0) — what a co-simulation master does that steps all FMUs on
#: the outputs of the previous communication point (libcosim's fixed-step algorithm).
COUPLINGS = ("sequential", "jacobi")


@dataclass
class EntityTrace:
    name: str
    category: str
    length: float
    width: float
    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    yaw: np.ndarray
    speed: np.ndarray
    accel: np.ndarray
    status: list[str]
    center_x: float = 0.0  # box centre ahead of the reference point (x, y) along the heading (m)
    kind: str = "vehicle"  # vehicle, pedestrian or misc (the ScenarioObject's kind)
    object_type: str = ""  # finer type from the entity's properties (e.g. "e-scooter"), else ""
    height: float = 0.0


@dataclass
class RunResult:
    scenario: str
    dt: float
    t: np.ndarray
    traces: dict[str, EntityTrace]
    collisions: list[tuple[float, str, str]]  # onset time and the two entities
    parameters: dict[str, str]
    ego: str
    threat: str | None
    end_reason: str = ""
    road_file: Path | None = None
    #: What the run played in its own way (Context.warn): file, line, reason, once each.
    warnings: tuple[str, ...] = ()
    #: The declared type of each top-level parameter (double, boolean, string ...), for typed outputs.
    parameter_types: dict[str, str] = field(default_factory=dict)
    #: The systems under test plugged in (:class:`~vei_scenario.sut.ControllerSpec`), if any.
    controllers: tuple = ()


def _act(ctx) -> None:
    """Let the stepped actions act before the entities move, and take those that ended while acting
    (a one-off distance reached at once, in Init or as an event starts) out of the step loop: nothing
    updates an Init action once it is done, and a done action acting on would hold its entity (a gap
    kept that was to be set once)."""
    for a in list(ctx.stepping):
        a.step(ctx)
    if any(a.done for a in ctx.stepping):
        ctx.stepping[:] = [a for a in ctx.stepping if not a.done]


def _entity(obj, ctx, name: str | None = None) -> Entity:
    name = name or obj.get("name")
    if obj.find("CatalogReference") is not None:
        raise ctx.error(obj.find("CatalogReference"), "catalog references are not supported by vei run")
    kind = next((c for c in obj if c.tag in ("Vehicle", "Pedestrian", "MiscObject")), None)
    if kind is None:
        raise ctx.error(obj, f"entity {name!r}: only Vehicle, Pedestrian and MiscObject are supported")
    box = kind.find("BoundingBox")
    dims = box.find("Dimensions") if box is not None else None
    if dims is None or any(dims.get(k) is None for k in ("length", "width", "height")):
        raise ctx.error(
            kind, f"entity {name!r}: a {kind.tag} needs a BoundingBox with Dimensions length, width, height"
        )
    centre = box.find("Center")
    category = kind.get("vehicleCategory") or kind.get("pedestrianCategory") or kind.get("miscObjectCategory") or ""
    perf = kind.find("Performance")
    limits = VehicleLimits()
    if perf is not None:
        limits = VehicleLimits(
            float(perf.get("maxAcceleration")), float(perf.get("maxDeceleration")), limits.jerk_max_mps3
        )
    # esmini's reading, followed here: the position is the rear axle, so the box centre lies
    # Center.x - RearAxle.positionX ahead of it (the two agree when the rear axle is at 0).
    rear = kind.find("Axles/RearAxle")
    rear_x = float(rear.get("positionX", "0")) if rear is not None else 0.0
    props = {p.get("name", "").lower(): p.get("value", "") for p in kind.iterfind("Properties/Property")}
    object_type = next((props[k] for k in OBJECT_TYPE_PROPERTIES if props.get(k)), "")
    entity = Entity(
        name,
        category,
        float(dims.get("length")),
        float(dims.get("width")),
        float(dims.get("height")),
        float(centre.get("x", "0") if centre is not None else 0.0) - rear_x,
        limits,
        performance=perf is not None,
    )
    if perf is not None:
        entity.max_speed = float(perf.get("maxSpeed"))
    elif kind.tag == "MiscObject":
        entity.max_speed = 0.0
    entity.kind = KINDS[kind.tag]
    entity.object_type = object_type
    hitch, coupler = kind.find("TrailerHitch"), kind.find("TrailerCoupler")
    if hitch is not None:
        entity.hitch_dx = float(hitch.get("dx", "0"))
    if coupler is not None:
        entity.coupler_dx = float(coupler.get("dx", "0"))
    ref = kind.find("Trailer/TrailerRef")
    inline = kind.find("Trailer/Trailer")
    if (ref is not None and ref.get("entityRef")) or inline is not None:
        if hitch is None:
            raise ctx.error(kind.find("Trailer"), f"{name} tows a trailer but has no TrailerHitch")
        entity.trailer = ref.get("entityRef") if ref is not None else name + "+"
    return entity


def _entities(obj, ctx) -> list[Entity]:
    """A ScenarioObject's entity, and the trailers defined inside it: each an entity of its own,
    named after its tow vehicle with a "+" per link (as esmini names them)."""
    out = [_entity(obj, ctx)]
    inline = next((c for c in obj if c.tag in KINDS), obj).find("Trailer/Trailer")
    while inline is not None:
        out.append(_entity(inline, ctx, out[-1].name + "+"))
        inline = next((c for c in inline if c.tag in KINDS), inline).find("Trailer/Trailer")
    return out


def _declare_variables(root, ctx) -> None:
    """OpenSCENARIO 1.2 VariableDeclarations: values that actions change at run time (initial values
    resolved like parameters when the document was loaded)."""
    from vei_scenario.interpreter.document import check_type

    for d in root.iterfind("VariableDeclarations/VariableDeclaration"):
        name, type_ = (d.get("name") or "").lstrip("$"), d.get("variableType", "string")
        if not name:
            raise ctx.error(d, "VariableDeclaration without a name")
        value = d.get("value", "")
        problem = check_type(type_, value)
        if problem:
            raise ctx.error(d, f"variable {name} = {value!r} {problem}")
        ctx.variables[name], ctx.variable_types[name] = value, type_


#: ScenarioObject element → the kind of road user it is.
KINDS = {"Vehicle": "vehicle", "Pedestrian": "pedestrian", "MiscObject": "misc"}
#: Entity properties (lower case) that may name a finer object type than the vehicle category
#: (OpenSCENARIO has no e-scooter category; vei writes ``<Property name="objectType" value="e-scooter"/>``).
OBJECT_TYPE_PROPERTIES = ("objecttype", "type")


def _in_moving_order(entities: list) -> list:
    """The entities in the order they move in a step: as declared, those whose controller moves them after
    every other one (``Controller.moves_last``: esmini's cruise in override mode) at the end."""
    last = [e for e in entities if e.active and any(c is not None and c.moves_last for c in e.active.values())]
    if not last:
        return entities
    ids = {id(e) for e in last}
    return [e for e in entities if id(e) not in ids] + last


def _as_it_was(e: Entity) -> Entity:
    """A copy of ``e`` that its step leaves as it is: with its own lane state (a step moves the one it
    has in place), so that under Jacobi coupling others read where it was on its lane, not where it is."""
    snap = copy.copy(e)
    if e.lane is not None:
        snap.lane = copy.copy(e.lane)
    return snap


def _parked(e: Entity) -> tuple | None:
    """What decides a standing lane keeper's next step (its lane state and pose), or None while anything
    else may move it (a controller, a path, a speed profile, a lane change, a lane still to find)."""
    st = e.lane
    if st is None or e.active or e.follower is not None or e.speed_profile is not None or e.lateral is not None:
        return None
    if e.find_lane:  # (its lane state is not yet what lane keeping will read)
        return None
    return (st.road, st.s, st.lane, st.offset, st.forward, st.heading, e.x, e.y, e.yaw)


class Simulation:
    def __init__(
        self,
        doc: ScenarioDocument,
        dt: float = 0.01,
        max_time_s: float = DEFAULT_MAX_TIME_S,
        coupling: str = "sequential",
        controllers: tuple = (),
    ) -> None:
        """``controllers``: :class:`~vei_scenario.sut.ControllerSpec` of the systems under test, each in
        charge of its entity's speed throughout (:func:`~vei_scenario.interpreter.plugged.plug`)."""
        from vei_scenario.checks import check_dt, finite

        root = doc.root
        check_dt(dt)
        finite(max_time_s, "max_time_s", 1e-3, 1e6)
        if coupling not in COUPLINGS:
            raise ValueError(f"coupling must be one of {', '.join(COUPLINGS)}")
        self.doc, self.dt, self.max_time, self.coupling = doc, dt, max_time_s, coupling
        self.controllers = tuple(controllers)
        self.ctx = Context(doc.path, 0.0, dt, 0, {}, dict(doc.parameters))
        ctx = self.ctx
        ctx.road_file = doc.road_file
        ctx.parameter_types = dict(doc.parameter_types)
        _declare_variables(root, ctx)
        for sel in root.iter("EntitySelection"):
            raise ctx.error(sel, "entity selections are not supported by vei run")
        for obj in root.iterfind("Entities/ScenarioObject"):
            for e in _entities(obj, ctx):
                ctx.entities[e.name] = e
        if not ctx.entities:
            raise ctx.error(root, "the scenario has no entities")
        for e in ctx.entities.values():
            if e.trailer is not None:
                towed = ctx.entities.get(e.trailer)
                if towed is None or towed is e or towed.towed_by is not None:
                    problem = "names no entity" if towed is None else "is itself" if towed is e else "is towed already"
                    raise ctx.error(root, f"{e.name}'s TrailerRef {e.trailer!r} {problem}")
                towed.towed_by = e.name
        ctx.trajectories = {}  # by name, for controllers that follow a route (world positions)
        for traj in root.iter("Trajectory"):
            if traj.get("name") and traj.find("Shape/Polyline") is not None and placed_when_built(traj):
                ctx.trajectories[traj.get("name")] = polyline_from(traj, ctx)
        for obj in root.iterfind("Entities/ScenarioObject"):
            ctrl = obj.find("ObjectController/Controller")
            if obj.find("ObjectController/CatalogReference") is not None:
                raise ctx.error(obj.find("ObjectController"), "controller catalogs are not supported by vei run")
            if ctrl is not None:
                c = make_controller(ctrl, ctx)
                ctx.entities[obj.get("name")].controllers[c.name] = c
        if controllers:
            from vei_scenario.interpreter.plugged import plug

            plug(ctx, tuple(controllers), doc.path)

        self.init_actions = []
        privates = []
        for private in root.iterfind("Storyboard/Init/Actions/Private"):
            name = private.get("entityRef")
            if name not in ctx.entities:
                raise ctx.error(private, f"Init: no entity named {name!r}")
            privates += ((name, pa) for pa in private.iterfind("PrivateAction"))
        for name, pa in init_order(privates, ctx.entities, ctx.warn):  # (what an action reads is set first)
            self.init_actions.extend(private_actions(pa, name, ctx))
        for ga in root.iterfind("Storyboard/Init/Actions/GlobalAction"):
            self.init_actions.extend(global_actions(ga, ctx))
        for ua in root.iterfind("Storyboard/Init/Actions/UserDefinedAction"):
            raise ctx.error(ua, "user-defined actions are not supported by vei run")

        self.storyboard = Storyboard(root.find("Storyboard"), ctx)
        self.ego, self.threat = self._roles()
        ctx.threat = self.threat

    def _roles(self) -> tuple[str, str | None]:
        """The ego (entity named Ego, else the first) and its threat (the planner's threatEntity,
        else the nearest other entity at the start)."""
        names = list(self.ctx.entities)
        ego = "Ego" if "Ego" in names else names[0]
        for c in self.ctx.entities[ego].controllers.values():
            t = c.props.get("threatEntity")
            if t in self.ctx.entities:
                return ego, t
        others = [n for n in names if n != ego]
        return ego, (others[0] if others else None)

    def _move(self, e: Entity) -> None:
        if e.deleted:
            e.status, e.last_step_m = "deleted", 0.0
            return
        if e.placed:
            e.placed = False
            return
        if e.towed_by is not None:  # pulled by its tow vehicle once that has moved
            return
        if e.parked is not None and e.speed == 0.0 and e.step_speed == 0.0 and e.parked == _parked(e):
            # standing in its lane, with nothing to move it, where its last step left it as it was: lane
            # keeping reads only that state, so the step again changes nothing but the step's values
            e.status, e.accel, e.last_step_m = "default", (e.speed - e.step_speed) / self.dt, 0.0
            if e.standing_since is None:
                e.standing_since = self.ctx.t + self.dt
            return
        e.parked = None
        x0, y0 = e.x, e.y
        self._motion(e)
        e.last_step_m = _core.hypot(e.x - x0, e.y - y0)  # (a step measured as the core measures its own)
        e.odometer += e.last_step_m
        if abs(e.speed) < 1e-9:
            if e.standing_since is None:
                e.standing_since = self.ctx.t + self.dt
        else:
            e.standing_since = None

    def _motion(self, e: Entity) -> None:
        ctx, dt = self.ctx, self.dt
        if e.active:
            for domain in ("lateral", "longitudinal"):
                ctrl = e.active.get(domain)
                if ctrl is not None and ctrl.move(e, ctx, dt):
                    return
        e.status = "default"
        f = e.follower
        t_next = ctx.t + dt
        if f is not None and f.plays_time:  # (position: where the trajectory puts it; follow: tracking that)
            follow, lim = f.mode != "position", e.limits
            e.x, e.y, e.yaw, f.s, e.speed, e.accel = f.polyline.core.timed_step(
                f.trajectory_time(t_next), f.s, e.speed, follow, lim.max_accel_mps2, lim.max_decel_mps2, dt
            )
            e.status = "follow" if follow else "replay"
            return
        v0 = e.step_speed  # (an action stepped before the move may have set the speed already)
        profile = e.speed_profile
        if profile is not None:
            v, finished = profile.speed(t_next)
            e.speed = v
            if finished:
                e.speed_profile = None
        e.accel = (e.speed - v0) / dt
        ds = e.speed * dt  # esmini's default controller: the step's new speed over the whole step
        lateral = e.lateral
        if profile is not None and lateral is not None and lateral.projects_step and profile.order > lateral.order:
            # esmini steps a lane change before a SpeedAction after it in the storyboard: its step is
            # at the speed the step began with
            ds = v0 * dt
        if f is None:  # (projecting onto the network is costly: only once it drives by lane)
            ensure_lane(ctx, e)
        if e.lane is not None and f is None:
            before = _parked(e) if ds == 0.0 else None
            lane_keep(e, ds, ctx)
            if before is not None and before == _parked(e):  # a standing step that changed nothing
                e.parked = before
        elif f is not None and f.s + abs(ds) > f.polyline.length and (ds < 0) == f.reverse and not e.modelled:
            # on past the end (esmini)
            over = math.copysign(f.s + abs(ds) - f.polyline.length, ds)
            advance_along(e, ds - over)
            e.x += over * math.cos(e.yaw)
            e.y += over * math.sin(e.yaw)
        elif advance_along(e, ds) and e.modelled:  # (a modelled one stands at its path's end: vei_ego_drive)
            e.speed, e.accel = 0.0, 0.0

    def run(self, on_progress: Callable[[float], None] | None = None) -> RunResult:
        """Play the scenario to its end; the controllers that hold resources (an FMU) end with it."""
        try:
            return self._run(on_progress)
        finally:
            for e in self.ctx.entities.values():
                for c in e.controllers.values():
                    finish = getattr(c, "finish", None)
                    if finish is not None:
                        finish()

    def _run(self, on_progress: Callable[[float], None] | None = None) -> RunResult:
        ctx, dt = self.ctx, self.dt
        names = list(ctx.entities)
        recording = Recording([ctx.entities[n] for n in names])
        collisions: list[tuple[float, str, str]] = []

        def record() -> None:
            recording.record(ctx.t)

        ctx.initializing = True
        for a in self.init_actions:
            a.start(ctx)
        _act(ctx)  # Init actions that act every step act once before t = 0 is logged
        for tow, trailer in trailers.hitches(ctx.entities):  # hitched trailers start in line behind their tow
            trailers.place_behind(trailer, tow)
        # the storyboard is evaluated once at t = 0 before t = 0 is logged, with no time passing (as
        # esmini does): events that start at once place entities and set speeds, and what they
        # complete counts from t = 0 (a condition delayed after it fires on time)
        ctx.initializing, ctx.settling = False, True
        running = self.storyboard.step()
        if running:
            _act(ctx)
            self.storyboard.complete_finished()
        ctx.settling = False
        self._collide(collisions)
        record()
        reason = f"time limit {self.max_time:g} s"
        if not running:
            reason = "storyboard stop trigger"
        pending = [a for a in self.init_actions if not a.done]
        entities = list(ctx.entities.values())
        board, offers = self.storyboard, Offers()
        reported = 0
        while running and ctx.t < self.max_time - 1e-9:
            if on_progress is not None and ctx.step - reported >= PROGRESS_EVERY_STEPS:
                on_progress(ctx.t)  # (the simulated time reached: a long run shows it moves)
                reported = ctx.step
            before = ctx.transitions
            if not board.step():
                reason = "storyboard stop trigger"
                break
            ending = board.complete and board.stop_trigger is None  # (the loop ends after this step)
            if (
                ctx.transitions == before and not ending
                and (not pending or all(a.carried(ctx) for a in pending))
                and (not ctx.stepping or all(a.carried(ctx) for a in ctx.stepping))
            ):  # fmt: skip
                # (a controller in charge of a road user that the core does not step: no quiet stretch to offer)
                offer = offers.due() and offered(entities)
                sequential = self.coupling != "jacobi"
                if offer and cruise(ctx, board, entities, recording, self.max_time, offers, sequential):
                    continue  # (the core took this step's move and the quiet steps after it)
            if pending:  # Init actions still acting (a done one never acts again)
                for a in pending:
                    if not a.done:
                        a.update(ctx)
                pending = [a for a in pending if not a.done]
            for e in entities:
                e.step_speed = e.speed
            if ctx.stepping:
                _act(ctx)
            if self.coupling == "jacobi":
                ctx.snapshot = {n: _as_it_was(e) for n, e in ctx.entities.items()}
            for e in _in_moving_order(entities):
                self._move(e)
            for tow, trailer in trailers.hitches(ctx.entities):
                trailers.pull(trailer, tow, dt)
            ctx.snapshot = None
            self.storyboard.complete_finished()
            ctx.step += 1
            ctx.t = step_time(ctx.step, dt)
            self._collide(collisions)
            record()
            if self.storyboard.complete and self.storyboard.stop_trigger is None:
                reason = "all stories complete"
                break
        t, values = recording.arrays()
        traces = {}
        for n, v, status in zip(names, values, recording.status):
            e = ctx.entities[n]
            traces[n] = EntityTrace(
                n,
                e.category,
                e.length,
                e.width,
                t,
                *v,
                status,
                e.center_x,
                e.kind,
                e.object_type,
                e.height,
            )
        return RunResult(
            str(self.doc.path),
            dt,
            t,
            traces,
            collisions,
            dict(ctx.parameters),
            self.ego,
            self.threat,
            reason,
            self.doc.road_file,
            tuple(ctx.warnings),
            dict(ctx.parameter_types),
            self.controllers,
        )

    def _collide(self, collisions: list) -> None:
        ctx = self.ctx
        present = [e for e in ctx.entities.values() if not e.deleted]
        now: set[frozenset[str]] = set()
        if len(present) < 2:  # (nobody to collide with)
            ctx.colliding = now
            return
        for i, j in _core.overlapping(_core.entity_boxes(present)):  # every pair, in C (the core's boxes)
            a, b = present[i].name, present[j].name
            pair = frozenset((a, b))
            now.add(pair)
            if pair not in ctx.colliding:
                collisions.append((ctx.t, a, b))
        ctx.colliding = now
