"""Actions: built from the XML once, then started, stepped and stopped by the engine.

Supported: TeleportAction (WorldPosition), SpeedAction (absolute or relative target; step, linear,
cubic, sinusoidal over time, rate or distance), FollowTrajectoryAction (Polyline; no timing or Timing
absolute/relative with scale and offset; following mode position or follow), AssignControllerAction,
ActivateControllerAction, ParameterSetAction. Anything else is refused with its line.
"""

from __future__ import annotations

from vei_scenario.interpreter.controllers import make_controller, polyline_from
from vei_scenario.interpreter.entities import PathFollower, SpeedProfile
from vei_scenario.safe_xml import first_element


class Action:
    done = False

    def start(self, ctx) -> None:
        pass

    def update(self, ctx) -> None:
        """Called after the entities moved: decide whether the action has completed."""

    def stop(self, ctx) -> None:
        pass


class Teleport(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        wp = el.find("Position/WorldPosition")
        if wp is None:
            pos = el.find("Position")
            kind = pos[0].tag if pos is not None and len(pos) else "none"
            raise ctx.error(el, f"TeleportAction position <{kind}> is not supported (WorldPosition only)")
        self.entity = entity
        self.x, self.y, self.h = float(wp.get("x")), float(wp.get("y")), float(wp.get("h", "0"))

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        e.x, e.y, e.yaw = self.x, self.y, self.h
        if e.follower is not None:
            e.follower = None
        self.done = True


class Speed(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        self.entity = entity
        dyn = el.find("SpeedActionDynamics")
        target = el.find("SpeedActionTarget")
        self.shape = dyn.get("dynamicsShape")
        self.dimension = dyn.get("dynamicsDimension")
        self.value = float(dyn.get("value"))
        if self.shape not in ("step", "linear", "cubic", "sinusoidal"):
            raise ctx.error(dyn, f"dynamicsShape {self.shape!r} is not supported")
        absolute, relative = target.find("AbsoluteTargetSpeed"), target.find("RelativeTargetSpeed")
        if absolute is not None:
            self.target = ("absolute", float(absolute.get("value")), None, None)
        elif relative is not None:
            if relative.get("continuous", "false") == "true":
                raise ctx.error(relative, "continuous RelativeTargetSpeed is not supported")
            ref = relative.get("entityRef")
            if ref not in ctx.entities:
                raise ctx.error(relative, f"no entity named {ref!r}")
            self.target = ("relative", float(relative.get("value")), ref, relative.get("speedTargetValueType"))
        else:
            raise ctx.error(target, "SpeedActionTarget without a target speed")

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        kind, value, ref, vtype = self.target
        if kind == "absolute":
            v1 = value
        else:
            base = ctx.entities[ref].speed
            v1 = base + value if vtype == "delta" else base * value
        v0 = e.speed
        if self.shape == "step" or self.value <= 0:
            duration = 0.0
        elif self.dimension == "time":
            duration = self.value
        elif self.dimension == "rate":
            duration = abs(v1 - v0) / self.value
        else:  # distance: the time to cover it at the mean speed of the transition
            mean = 0.5 * (v0 + v1)
            duration = self.value / mean if mean > 1e-9 else 0.0
        e.speed_profile = SpeedProfile(v0, v1, ctx.t, duration, self.shape)
        if duration == 0.0:
            e.speed = v1

    def update(self, ctx) -> None:
        e = ctx.entities[self.entity]
        p = e.speed_profile
        self.done = p is None or ctx.t >= p.t0 + p.duration - 1e-9

    def stop(self, ctx) -> None:
        ctx.entities[self.entity].speed_profile = None


class FollowTrajectory(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        self.entity = entity
        traj = el.find("TrajectoryRef/Trajectory")
        if traj is None:
            traj = el.find("Trajectory")
        if traj is None:
            raise ctx.error(el, "FollowTrajectoryAction: only an inline Trajectory is supported (no catalogs)")
        self.polyline = polyline_from(traj, ctx)
        tref = el.find("TimeReference")
        timing = tref.find("Timing") if tref is not None else None
        if timing is not None:
            if not self.polyline.timed:
                raise ctx.error(timing, "Timing needs a time on every vertex")
            if any(b <= a for a, b in zip(self.polyline.ts, self.polyline.ts[1:])):
                raise ctx.error(traj, "polyline vertex times must increase when the trajectory is timed")
            scale = float(timing.get("scale", "1"))
            if scale <= 0:
                raise ctx.error(timing, "Timing scale must be positive")
            self.timing = (timing.get("domainAbsoluteRelative"), scale, float(timing.get("offset", "0")))
        else:
            self.timing = None
        mode = el.find("TrajectoryFollowingMode")
        self.mode = mode.get("followingMode", "position") if mode is not None else "position"
        self.initial_s = float(el.get("initialDistanceOffset", "0"))

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        e.follower = PathFollower(self.polyline, self.timing, self.mode, ctx.t, self.initial_s)
        if self.timing is None:  # continue from where the entity is: its projection onto the path
            e.follower.s = max(self.polyline.project(e.x, e.y), self.initial_s)
        elif self.mode == "position" and ctx.initializing:  # logged at t = 0 on its trajectory
            e.x, e.y, e.yaw = self.polyline.at_time(e.follower.trajectory_time(ctx.t))

    def update(self, ctx) -> None:
        e = ctx.entities[self.entity]
        self.done = e.follower is None or e.follower.finished(ctx.t)

    def stop(self, ctx) -> None:
        ctx.entities[self.entity].follower = None


class AssignController(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        self.entity = entity
        ctrl = el.find("Controller")
        if ctrl is None:
            ctrl = el.find("ObjectController/Controller")
        if ctrl is None:
            raise ctx.error(el, "AssignControllerAction: only an inline Controller is supported (no catalogs)")
        self.controller = make_controller(ctrl, ctx)
        self.lateral = el.get("activateLateral") == "true"
        self.longitudinal = el.get("activateLongitudinal") == "true"

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        e.controllers = {self.controller.name: self.controller}
        e.active = {}
        activate(e, self.controller, self.lateral, self.longitudinal)
        self.done = True


def activate(e, controller, lateral: bool | None, longitudinal: bool | None) -> None:
    for domain, flag in (("lateral", lateral), ("longitudinal", longitudinal)):
        if flag is True and domain in controller.domains:
            e.active[domain] = controller
        elif flag is False:
            e.active.pop(domain, None)


class ActivateController(Action):
    def __init__(self, entity: str, el, ctx) -> None:
        self.entity, self.el = entity, el
        self.lateral = {"true": True, "false": False}.get(el.get("lateral"))
        self.longitudinal = {"true": True, "false": False}.get(el.get("longitudinal"))
        self.ref = el.get("controllerRef")

    def start(self, ctx) -> None:
        e = ctx.entities[self.entity]
        if not e.controllers:
            raise ctx.error(self.el, f"ActivateControllerAction: {self.entity} has no assigned controller")
        ctrl = e.controllers.get(self.ref) if self.ref else list(e.controllers.values())[-1]
        if ctrl is None:
            raise ctx.error(self.el, f"ActivateControllerAction: {self.entity} has no controller {self.ref!r}")
        activate(e, ctrl, self.lateral, self.longitudinal)
        self.done = True


class ParameterSet(Action):
    def __init__(self, name: str, value: str, el, ctx) -> None:
        if name not in ctx.parameters:
            raise ctx.error(el, f"ParameterSetAction on undeclared parameter {name!r}")
        self.name, self.value = name, value

    def start(self, ctx) -> None:
        ctx.parameters[self.name] = self.value
        self.done = True


def private_actions(pa, entity: str, ctx) -> list[Action]:
    """Runtime actions of a ``<PrivateAction>`` for one entity."""
    kind = first_element(pa)
    if kind is None:
        raise ctx.error(pa, "empty PrivateAction")
    if kind.tag == "TeleportAction":
        return [Teleport(entity, kind, ctx)]
    if kind.tag == "LongitudinalAction" and kind.find("SpeedAction") is not None:
        return [Speed(entity, kind.find("SpeedAction"), ctx)]
    if kind.tag == "RoutingAction" and kind.find("FollowTrajectoryAction") is not None:
        return [FollowTrajectory(entity, kind.find("FollowTrajectoryAction"), ctx)]
    if kind.tag == "ControllerAction":
        out: list[Action] = []
        for sub in kind:
            if sub.tag == "AssignControllerAction":
                out.append(AssignController(entity, sub, ctx))
            elif sub.tag == "ActivateControllerAction":
                out.append(ActivateController(entity, sub, ctx))
            else:
                raise ctx.error(sub, f"<{sub.tag}> is not supported by vei run")
        return out
    if kind.tag == "ActivateControllerAction":  # OpenSCENARIO 1.0/1.1 place it directly here
        return [ActivateController(entity, kind, ctx)]
    inner_el = first_element(kind)
    inner = inner_el.tag if inner_el is not None else ""
    raise ctx.error(kind, f"<{kind.tag}>{'/<' + inner + '>' if inner else ''} is not supported by vei run")


def global_actions(ga, ctx) -> list[Action]:
    kind = first_element(ga)
    if kind is not None and kind.tag == "ParameterAction" and kind.find("SetAction") is not None:  # 1.0
        return [ParameterSet(kind.get("parameterRef"), kind.find("SetAction").get("value"), kind, ctx)]
    if kind is not None and kind.tag == "ParameterSetAction":
        return [ParameterSet(kind.get("parameterRef"), kind.get("value"), kind, ctx)]
    raise ctx.error(ga, f"global action <{kind.tag if kind is not None else ''}> is not supported by vei run")
