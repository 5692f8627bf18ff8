"""The user's controller on an entity: each step it is shown the scene (:class:`~vei_scenario.sut.Observation`)
and its command moves the entity's speed through the vehicle model, along the path or lane it has.

Plugged in two ways: ``--controller ENTITY=...`` (:func:`plug`: it takes the place of the entity's
controllers, with their properties, and is in charge of the longitudinal domain from the start to the
end, whatever the storyboard activates), or a scenario ``Controller`` with a ``module`` property
(CARLA ScenarioRunner's convention; assigned and activated as the storyboard says).
"""

from __future__ import annotations

import signal
import threading
from pathlib import Path

from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter.entities import Entity
from vei_scenario.interpreter.motion import advance_along, lane_keep
from vei_scenario.interpreter.positions import ensure_lane
from vei_scenario.models.vehicle import Longitudinal, longitudinal_step
from vei_scenario.sut.contract import ControllerFault, ObjectState, Observation, StepTimeout, command_from
from vei_scenario.sut.spec import ControllerSpec, describe_exception

#: The scenario Controller property that names a user's controller (FILE.py:CLASS or MODULE:CLASS).
MODULE_PROPERTY = "module"


def _state(o: Entity) -> ObjectState:
    x, y, yaw, length, width = o.box()
    return ObjectState(o.name, o.kind, x, y, yaw, o.speed, o.accel, length, width)


class PluggedController:
    """A user's controller (the system under test), longitudinal: the entity keeps its path or lane.
    (The interface of :class:`~vei_scenario.interpreter.controllers.Controller`, which it does not
    import: that module makes one of these for a ``module`` property.)"""

    domains = ("longitudinal",)
    moves_last = False

    def __init__(self, name: str, props: dict[str, str], el, ctx, spec: ControllerSpec, entity: str = "") -> None:
        self.name, self.props, self.el = name, props, el
        self.spec = spec
        self.label = f"{entity}={spec.target}" if entity else spec.label
        spec.load()  # (refused here, before the run, when it cannot be loaded)
        self.properties = {k: v for k, v in props.items() if k != MODULE_PROPERTY and k}
        self.impl = None  # made when the run starts (an FMU instance is not made for a run never played)
        self.started = False
        self.held_command = 0.0  # Jacobi coupling: the command computed in the previous step

    def activated(self, e: Entity, ctx, domains: tuple[str, ...]) -> None:
        """It takes over from the entity's state when it first moves."""

    def finish(self) -> None:
        """After the run (or its failure): an implementation with ``close()`` (an FMU) ends there."""
        close = getattr(self.impl, "close", None) if self.impl is not None else None
        if callable(close):
            close()

    def instance(self):
        """The implementation for this run, constructed on first use."""
        if self.impl is None:
            self.impl = self.spec.instantiate(self.label, self.properties)
        return self.impl

    def _start(self, e: Entity, ctx) -> None:
        self.started = True
        reset = getattr(self.instance(), "reset", None)
        if callable(reset):
            info = {"entity": e.name, "scenario": str(ctx.path), "dt_s": ctx.dt, "threat": ctx.threat,
                    "parameters": dict(ctx.parameters)}  # fmt: skip
            try:
                reset(info)
            except Exception as exc:  # noqa: BLE001
                raise ControllerFault(self.label, f"reset raised {describe_exception(exc)}", ctx.t) from None

    def _step(self, obs: Observation, t: float):
        """``step(obs)``, any failure of it one :class:`ControllerFault`; with ``--controller-timeout``
        bounded in wall-clock time (SIGALRM: in the main thread of a process, as in ``vei run`` and a
        sweep's workers; elsewhere unbounded)."""
        limit = self.spec.step_timeout_s
        timed = limit is not None and threading.current_thread() is threading.main_thread()
        if timed:
            previous = signal.signal(signal.SIGALRM, _overran)
            signal.setitimer(signal.ITIMER_REAL, limit)
        try:
            return self.impl.step(obs)
        except ControllerFault:  # (an FMU's failed call, said already)
            raise
        except StepTimeout:
            reason = f"step did not return within {limit:g} s (--controller-timeout)"
            raise ControllerFault(self.label, reason, t) from None
        except Exception as exc:  # noqa: BLE001 (the user's code: any failure is theirs, said in one line)
            raise ControllerFault(self.label, f"step raised {describe_exception(exc)}", t) from None
        finally:
            if timed:
                signal.setitimer(signal.ITIMER_REAL, 0)
                signal.signal(signal.SIGALRM, previous)

    def observation(self, e: Entity, ctx) -> Observation:
        """What ``e``'s controller sees at the step's start (the others as coupling shows them)."""
        others = [ctx.observed(n) for n, o in ctx.entities.items() if o is not e and not o.deleted]
        objects = [_state(o) for o in others if o is not None]
        threat = next((o for o in objects if o.name == ctx.threat), None)
        return Observation(ctx.t, ctx.dt, _state(e), threat, objects)

    def move(self, e: Entity, ctx, dt: float) -> bool:
        if not self.started:
            self._start(e, ctx)
        cmd = command_from(self._step(self.observation(e, ctx), ctx.t), self.label, ctx.t)
        a_cmd = cmd.accel_mps2
        if ctx.snapshot is not None:  # Jacobi: the vehicle gets this command at the next step
            a_cmd, self.held_command = self.held_command, a_cmd
        lon = longitudinal_step(Longitudinal(0.0, e.speed, e.accel), a_cmd, e.limits, dt)
        s, v, a = lon.s, lon.v, lon.a
        if v > e.max_speed:  # (its Performance's maxSpeed: reached within the step, held there)
            v = e.max_speed
            a = (v - e.speed) / dt
            s = 0.5 * (e.speed + v) * dt
        if e.follower is None:  # an entity that drives by lane keeps to it
            ensure_lane(ctx, e)
            if e.lane is not None:
                lane_keep(e, s, ctx)
            else:
                advance_along(e, s)
        else:
            advance_along(e, s)
        e.speed, e.accel = v, a
        e.status = cmd.state
        return True


def _overran(signum, frame) -> None:
    raise StepTimeout()


def scenario_controller(name: str, props: dict[str, str], el, ctx) -> PluggedController:
    """A scenario ``Controller`` whose ``module`` property names the user's class (a relative file
    found from the scenario's directory)."""
    base = str(Path(str(ctx.path)).resolve().parent) if ctx.path else ""
    owner = _owner(el)  # (its messages name the entity, from loading the module on)
    spec = ControllerSpec(owner, props[MODULE_PROPERTY], base=base)
    if spec.osmp:  # an OSI traffic participant moves its entity itself
        from vei_scenario.sut.participant import scenario_participant

        return scenario_participant(name, props, ctx, spec, owner)
    return PluggedController(name, props, el, ctx, spec, owner)


def _owner(el) -> str:
    """The entity a Controller element belongs to (its ScenarioObject, or the action's Private), if any."""
    node = el
    while node is not None:
        if node.tag == "ScenarioObject":
            return node.get("name", "")
        if node.tag == "Private":
            return node.get("entityRef", "")
        node = node.getparent()
    return ""


def plug(ctx, specs: tuple[ControllerSpec, ...], scenario: object) -> None:
    """Put each spec's controller in charge of its entity's longitudinal domain for the whole run: it
    takes the place of the entity's controllers and their properties (overridden by the spec's)."""
    for spec in specs:
        e = ctx.entities.get(spec.entity)
        if e is None:
            names = ", ".join(ctx.entities)
            raise VeiInputError(scenario, "--controller", f"no entity {spec.entity!r} (entities: {names})")
        if spec.osmp:  # an OSI traffic participant moves its entity itself
            from vei_scenario.sut.participant import plug_osmp

            plug_osmp(ctx, spec, e)
            continue
        props: dict[str, str] = {}
        for c in e.controllers.values():
            props.update(c.props)
        plugged = PluggedController(spec.target, props, None, ctx, spec, spec.entity)
        e.controllers = {plugged.name: plugged}
        e.active = {"longitudinal": plugged}
        e.sut = plugged
