"""The closed loop of a vei-compiled scenario, read once: the ego on its path with the collision-avoidance
planner, the rider on its recorded track with the social force model, their Init poses and speeds, the
acts' start and the storyboard's stop, and the XML attributes whose parameters a variant changes (the
rider's timing offset, rider type, planner switch, cruise speed, model properties that read a
parameter). The sweep kernel (:mod:`vei_scenario.batch`) and the FMU system and SSP writer
(:mod:`vei_scenario.fmu.system`) take it instead of reading the file again.

Static parts come from the interpreter's own building of the scenario (so they are what ``vei run``
plays); a scenario of another structure raises :class:`NotALoop` and callers use the interpreter.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np

from vei_scenario.interpreter.conditions import compare
from vei_scenario.interpreter.controllers import CollisionAvoidanceController, SocialForceController
from vei_scenario.interpreter.document import load_scenario, resolve_value
from vei_scenario.interpreter.engine import Simulation
from vei_scenario.interpreter.malformed import refused_when_malformed
from vei_scenario.models.cap import CapParameters
from vei_scenario.models.sfm import SfmParameters
from vei_scenario.safe_xml import parse_xml


class NotALoop(Exception):
    """The scenario is not of the structure ``vei compile`` writes."""


#: The controller kinds a closed loop has (the names ``vei compile`` gives them).
_LOOP_KINDS = (b"CollisionAvoidancePlanner", b"SocialForceModel")


def _cannot_be_a_loop(path: str | Path) -> bool:
    """Whether the file's text alone shows it is no closed loop: a controller's kind is written in the
    scenario (its name or its ``esminiController`` property, as a value or a parameter's default) or
    in a controller catalog, so a file that names neither kind nor a controller catalog has no planner
    and no rider. Why: a sweep of any other scenario asks first, and building the scenario to find
    out took a third of a two-variant Euro NCAP sweep."""
    try:  # (not a regular file, or unreadable: the full reading says what is wrong with it)
        text = Path(path).read_bytes() if Path(path).is_file() else None
    except OSError:
        text = None
    if text is None:
        return False
    return b"ControllerCatalog" not in text and not all(kind in text for kind in _LOOP_KINDS)


@dataclass
class Resolved:
    """Per-variant values of a batch (arrays over variants)."""

    duration: float
    rider: np.ndarray
    sfm_on: np.ndarray
    cap_on: np.ndarray
    cruise_mps: np.ndarray
    delays: dict[str, np.ndarray]  # per timed entity: how late it plays its trajectory (−Timing offset)
    init_speed: dict[str, np.ndarray]


class LoopScene:
    """The closed loop of ``path`` at step ``dt`` (attributes set once here, read-only after)."""

    def __init__(self, path: str | Path, dt: float = 0.01) -> None:
        self.path, self.dt = Path(path), dt
        if _cannot_be_a_loop(path):
            raise NotALoop("no CollisionAvoidancePlanner and SocialForceModel controllers")
        raw = parse_xml(path).getroot()  # (the attributes as written: "$Name" where a parameter decides)
        doc = None
        with refused_when_malformed(path, lambda: doc.root if doc is not None else None):
            doc = load_scenario(path, tree=copy.deepcopy(raw).getroottree())
            sim = Simulation(doc, dt)
        ctx = sim.ctx
        self.defaults = dict(doc.parameters)
        self.types = dict(doc.parameter_types)
        self._valid_values: set[tuple[str, str]] = set()
        self.names = list(ctx.entities)
        #: per entity: (ScenarioObject kind, category, object type), what the FMU loop's riders are checked by
        self.entity_kinds = {n: (e.kind, e.category, e.object_type) for n, e in ctx.entities.items()}
        self.ego, self.threat = sim.ego, sim.threat
        if self.ego != self.names[0] or self.threat is None:
            raise NotALoop("the ego must be the first entity and the planner must name a threat")
        ents = [ctx.entities[n] for n in self.names]
        self.length = [e.length for e in ents]
        self.width = [e.width for e in ents]
        if any(e.center_x != 0 for e in ents):
            raise NotALoop("box centres off the reference point")
        self.limits = ents[0].limits
        #: the ego's Performance maxSpeed (a plugged controller's speed is held there)
        self.max_speed = ents[0].max_speed
        ego_ctrls = [c for c in ents[0].controllers.values() if isinstance(c, CollisionAvoidanceController)]
        threat_ctrls = [
            c for c in ctx.entities[self.threat].controllers.values() if isinstance(c, SocialForceController)
        ]
        if len(ego_ctrls) != 1 or len(threat_ctrls) != 1:
            raise NotALoop("expected one planner on the ego and one social force model on the threat")
        if ego_ctrls[0].watch or ego_ctrls[0].follow_gap_s > 0 or threat_ctrls[0].ego_name != self.ego:
            # (other road users would then act on the pair: the sweep kernel leaves them out)
            raise NotALoop("the planner must watch the threat alone and the rider be repelled by the ego")
        self.cap_params = ego_ctrls[0].params
        self.sfm_params = threat_ctrls[0].params
        self.margin = self.cap_params.corridor_margin_m
        # Init: a teleport and a speed step per entity.
        self.init_pose, self.init_speed_raw = {}, {}
        self.raw = raw
        for private in raw.iterfind("Storyboard/Init/Actions/Private"):
            name = private.get("entityRef")
            wp = private.find("PrivateAction/TeleportAction/Position/WorldPosition")
            sp = private.find(".//SpeedAction")
            if wp is None or sp is None or sp.find("SpeedActionDynamics").get("dynamicsShape") != "step":
                raise NotALoop(f"Init of {name} is not teleport + step speed")
            self.init_pose[name] = tuple(
                float(resolve_value(self.path, wp, k, wp.get(k, "0"), self.defaults)) for k in ("x", "y", "h")
            )
            el = sp.find("SpeedActionTarget/AbsoluteTargetSpeed")
            self.init_speed_raw[name] = (el, el.get("value"))
        if set(self.init_pose) != set(self.names):
            raise NotALoop("every entity needs an Init teleport and speed")
        # Trajectories of the replay story, one per entity.
        self.paths, self.offset_raw = {}, {}
        for act in sim.storyboard.stories[0].children:
            if act.start_trigger is None:
                raise NotALoop("acts must start on SimulationTime > 0")
            for group in act.children:
                for man in group.children:
                    for ev in man.children:
                        for a in ev.children:
                            for rt in a.actions:
                                self.paths[rt.entity] = (rt.polyline, rt.timing)
        if set(self.paths) != set(self.names) or self.paths[self.ego][1] is not None:
            raise NotALoop("every entity follows one trajectory; the ego's without timing")
        for group in raw.iterfind("Storyboard/Story/Act/ManeuverGroup"):
            actor = group.find("Actors/EntityRef").get("entityRef")
            timing = group.find(".//FollowTrajectoryAction/TimeReference/Timing")
            if timing is not None:
                if timing.get("domainAbsoluteRelative") != "absolute" or float(timing.get("scale")) != 1.0:
                    raise NotALoop("scooter timing must be absolute with scale 1")
                self.offset_raw[actor] = (timing, timing.get("offset"))
        # Controller activations: ParameterCondition groups of the Controllers story.
        self.activation = {}
        for ev in raw.iterfind("Storyboard/Story/Act/ManeuverGroup/Maneuver/Event"):
            act = ev.find(".//ActivateControllerAction")
            if act is None:
                continue
            actor = ev.getparent().getparent().find("Actors/EntityRef").get("entityRef")
            groups = []
            for g in ev.iterfind("StartTrigger/ConditionGroup"):
                conds = [c.find("ByValueCondition/ParameterCondition") for c in g.iterfind("Condition")]
                if any(c is None for c in conds):
                    raise NotALoop("controller activations must depend on parameters only")
                groups.append([(c.get("parameterRef"), c.get("value"), c.get("rule")) for c in conds])
            self.activation[actor] = groups
        if set(self.activation) != {self.ego, self.threat}:
            raise NotALoop("expected activations of the planner and of the rider")
        starts = set()
        for act in raw.iterfind("Storyboard/Story/Act"):
            conds = act.findall("StartTrigger/ConditionGroup/Condition")
            st = act.find("StartTrigger//SimulationTimeCondition")
            rule = st.get("rule") if st is not None else None
            if len(conds) != 1 or rule not in ("greaterThan", "greaterOrEqual") or float(conds[0].get("delay", 0)):
                raise NotALoop("acts must start on one SimulationTime > t or >= t condition")
            value = float(resolve_value(self.path, st, "value", st.get("value"), self.defaults))
            # "t >= v" on the step grid is "t > v - dt/2": one threshold for both rules.
            starts.add(value - 0.5 * dt if rule == "greaterOrEqual" else value)
        if len(starts) != 1:
            raise NotALoop("all acts must start at the same time")
        #: The entities keep their Init speed and heading until the first step that begins after this
        #: (below 0 when the acts start at the first step).
        self.behaviour_start_s = starts.pop()
        stop = raw.find("Storyboard/StopTrigger//SimulationTimeCondition")
        if stop is None or stop.get("rule") != "greaterThan":
            raise NotALoop("the storyboard must stop on SimulationTime > duration")
        self.stop_raw = (stop, stop.get("value"))
        self.rider_raw = self._prop(self.threat, "riderType")
        self.enabled_raw = self._prop(self.ego, "enabled")
        # model properties that read a parameter ($Name): resolved per variant, one kernel scene per set
        self.model_raw = {
            which: {
                name: raw
                for name in (f.name for f in fields(cls))
                if (raw := self._prop_or_none(entity, name)) is not None and "$" in raw[1]
            }
            for which, entity, cls in (("cap", self.ego, CapParameters), ("sfm", self.threat, SfmParameters))
        }
        self.model_varies = any(self.model_raw.values())
        self.cruise_raw = self._prop(self.ego, "cruiseSpeed")
        #: the ego's controller properties as written (what a plugged controller is given, resolved per
        #: variant), or None when the scenario gives the ego properties from elsewhere too
        props = {
            p.get("name"): (p, p.get("value"))
            for obj in self.raw.iterfind("Entities/ScenarioObject")
            if obj.get("name") == self.ego
            for p in obj.iterfind("ObjectController/Controller/Properties/Property")
        }
        built = {k for c in ents[0].controllers.values() for k in c.props}
        self.ego_props_raw = props if set(props) == built else None

    def ego_properties(self, values: dict[str, str]) -> dict[str, str]:
        """The ego's controller properties resolved in a variant's values (as ``vei run`` gives them to
        a plugged controller)."""
        scope = {**self.defaults, **values}
        return {name: self._resolved(raw, scope) for name, raw in (self.ego_props_raw or {}).items()}

    def accepts(self, values: dict[str, str]) -> bool:
        """Whether this variant's values are all valid (others go through the interpreter, which
        reports exactly what is wrong with them)."""
        from vei_scenario.interpreter.document import check_type
        from vei_scenario.models.sfm import RIDER_TYPES

        scope = {**self.defaults, **values}
        known = self._valid_values  # (name, value) pairs already checked: a sweep repeats most of them
        for item in values.items():
            if item not in known:
                k, v = item
                if k not in self.types or check_type(self.types[k], v):
                    return False
                known.add(item)
        try:
            if self.model_varies:
                self.model_params(values)  # (a value the models refuse: the interpreter says which)
            return self._resolved(self.rider_raw, scope) in RIDER_TYPES
        except Exception:  # noqa: BLE001 - anything unresolvable is for the interpreter to report
            return False

    def kernel_accepts(self, values: dict[str, str]) -> bool:
        """:meth:`accepts`, and none of what ``vei run`` refuses that the kernel would play anyway (a
        negative cruise speed, which the interpreter's planner refuses): such a variant goes through
        the interpreter and becomes the same failed row as ``vei run`` says."""
        if not self.accepts(values):
            return False
        try:
            cruise = float(self._resolved(self.cruise_raw, {**self.defaults, **values}))
        except Exception:  # noqa: BLE001 - for the interpreter to report
            return False
        return math.isfinite(cruise) and cruise >= 0

    def _prop_or_none(self, entity: str, name: str):
        try:
            return self._prop(entity, name)
        except NotALoop:
            return None

    def model_key(self, values: dict[str, str]) -> tuple:
        """What a variant's values make of the model properties that read parameters (() when none do)."""
        if not self.model_varies:
            return ()
        scope = {**self.defaults, **values}
        return tuple(self._resolved(raw, scope) for which in ("cap", "sfm") for raw in self.model_raw[which].values())

    def model_params(self, values: dict[str, str]):
        """(CapParameters, SfmParameters) of a variant: the file's, with properties that read a
        parameter resolved in the variant's values. ValueError for values the models refuse."""
        if not self.model_varies:
            return self.cap_params, self.sfm_params
        scope = {**self.defaults, **values}
        out = []
        for which, base in (("cap", self.cap_params), ("sfm", self.sfm_params)):
            props = {k: str(v) for k, v in base.properties().items()}
            props.update({k: self._resolved(raw, scope) for k, raw in self.model_raw[which].items()})
            out.append(type(base).from_properties(props))
        return tuple(out)

    def shared_model(self, variants: list[dict[str, str]]) -> tuple[tuple, tuple | None]:
        """(model key, (CapParameters, SfmParameters)) that ``variants`` share; ((), None) when no model
        property reads a parameter. ValueError when they differ: run each of :meth:`model_groups`."""
        if not self.model_varies:
            return (), None
        keys = {self.model_key(v) for v in variants}
        if len(keys) > 1:
            raise ValueError("variants with different model parameters: run each of model_groups() on its own")
        return keys.pop(), self.model_params(variants[0])

    def model_groups(self, indices: list[int], variants: list[dict[str, str]], size: int) -> list[list[int]]:
        """``indices`` of ``variants`` in groups of at most ``size`` that share their model parameters."""
        by: dict[tuple, list[int]] = {}
        for i in indices:
            by.setdefault(self.model_key(variants[i]), []).append(i)
        return [g[k : k + size] for g in by.values() for k in range(0, len(g), size)]

    def _prop(self, entity: str, name: str):
        for obj in self.raw.iterfind("Entities/ScenarioObject"):
            if obj.get("name") == entity:
                for p in obj.iterfind("ObjectController/Controller/Properties/Property"):
                    if p.get("name") == name:
                        return p, p.get("value")
        raise NotALoop(f"{entity} controller has no property {name}")

    def _resolved(self, raw, scope: dict[str, str]) -> str:
        el, value = raw
        return resolve_value(self.path, el, "value", value, scope)

    def resolve(self, variants: list[dict[str, str]]) -> Resolved:
        """What the variants' parameter values decide, per variant."""
        scopes = [{**self.defaults, **v} for v in variants]

        def per_variant(raw) -> list[str]:
            return [self._resolved(raw, s) for s in scopes]

        def active(actor: str) -> np.ndarray:
            out = []
            for s in scopes:
                out.append(
                    any(all(_param_condition(s, p, val, rule) for p, val, rule in g) for g in self.activation[actor])
                )
            return np.array(out, bool)

        stop_values = {float(v) for v in per_variant(self.stop_raw)}
        if len(stop_values) != 1:
            raise NotALoop("variants with different durations")
        rider = np.array(per_variant(self.rider_raw))
        return Resolved(
            stop_values.pop(),
            rider,
            active(self.threat) & np.isin(rider, ("normal", "aggressive")),
            active(self.ego) & (np.array(per_variant(self.enabled_raw)) == "true"),
            np.array([float(v) for v in per_variant(self.cruise_raw)]),
            {n: -np.array([float(v) for v in per_variant(raw)]) for n, raw in self.offset_raw.items()},
            {n: np.array([float(v) for v in per_variant(self.init_speed_raw[n])]) for n in self.names},
        )


def _param_condition(scope: dict[str, str], name: str, value: str, rule: str) -> bool:
    current = scope[name]
    try:
        return compare(rule, float(current), float(value))
    except ValueError:
        if rule == "equalTo":
            return current == value
        if rule == "notEqualTo":
            return current != value
        return False
