"""A batch engine for vei-compiled scenarios: many variants at once, as arrays.

It runs the same models as ``vei run`` (the array versions in :mod:`vei_scenario.models`, pinned to the
scalar ones by tests) in the same order within a step as :mod:`vei_scenario.interpreter.engine`, so a
variant's trajectories equal the interpreter's to rounding (tests/test_batch_engine.py compares them).
Static parts (entities, boxes, paths, model parameters) come from the interpreter's own building of
the scenario; what a variant changes (the threat's timing offset, the ego's cruise speed, the rider
type, the planner switch) is resolved per variant from the XML attributes that hold the parameters.
Scenarios of another structure raise :class:`NotBatchable`; callers fall back to the interpreter.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np

from vei_scenario.interpreter.conditions import compare
from vei_scenario.interpreter.controllers import (
    CollisionAvoidanceController,
    SocialForceController,
    recorded_start_speed,
    rider_route,
)
from vei_scenario.interpreter.document import load_scenario, resolve_value
from vei_scenario.interpreter.engine import Simulation
from vei_scenario.interpreter.entities import Polyline
from vei_scenario.models.boxes import boxes_overlap, time_to_contact
from vei_scenario.models.cap import CapParameters, cap_step_arrays
from vei_scenario.models.sfm import SfmParameters, sfm_step_arrays
from vei_scenario.models.vehicle import longitudinal_step_arrays
from vei_scenario.safe_xml import parse_xml


class NotBatchable(Exception):
    """The scenario is not of the structure ``vei compile`` writes."""


def _wrap(a):
    return (a + math.pi) % (2 * math.pi) - math.pi


class PathArrays:
    """A :class:`Polyline` evaluated for arrays of arc lengths or times (same arithmetic)."""

    def __init__(self, p: Polyline) -> None:
        self.x, self.y, self.h = np.array(p.xs), np.array(p.ys), np.array(p.hs)
        self.s = np.array(p.s)
        self.t = np.array(p.ts, float) if p.timed else None
        self.end_speed = p.end_speed if p.timed else 0.0
        self.length = p.length

    def _lerp(self, i, f):
        j = np.minimum(i + 1, self.x.size - 1)
        h0, h1 = self.h[i], self.h[j]
        return (
            self.x[i] + f * (self.x[j] - self.x[i]),
            self.y[i] + f * (self.y[j] - self.y[i]),
            _wrap(h0 + f * _wrap(h1 - h0)),
        )

    def at_s(self, s):
        i = np.clip(np.searchsorted(self.s, s, side="right") - 1, 0, self.x.size - 2)
        ds = self.s[i + 1] - self.s[i]
        with np.errstate(divide="ignore", invalid="ignore"):
            f = np.where(ds <= 0, 0.0, (s - self.s[i]) / ds)
        return self._held(self._lerp(i, f), s <= 0, s >= self.s[-1])

    def _held(self, pose, before, after):
        """Hold the first vertex before the path and the last one after it, as Polyline.at_s does."""
        return tuple(np.where(before, v[0], np.where(after, v[-1], q)) for v, q in zip((self.x, self.y, self.h), pose))

    def at_time(self, t):
        """Polyline.at_time: held before the start, continued along the last heading after the end."""
        ts = self.t
        i = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, ts.size - 2)
        x, y, h = self._held(self._lerp(i, (t - ts[i]) / (ts[i + 1] - ts[i])), t <= ts[0], t >= ts[-1])
        d = (t - ts[-1]) * self.end_speed
        after = t >= ts[-1]
        return (
            np.where(after, self.x[-1] + d * math.cos(self.h[-1]), x),
            np.where(after, self.y[-1] + d * math.sin(self.h[-1]), y),
            h,
        )

    def s_at_time(self, t):
        ts = self.t
        i = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, ts.size - 2)
        s = self.s[i] + (t - ts[i]) / (ts[i + 1] - ts[i]) * (self.s[i + 1] - self.s[i])
        return np.where(t <= ts[0], 0.0, np.where(t >= ts[-1], self.s[-1] + (t - ts[-1]) * self.end_speed, s))

    def project(self, px, py):
        """Arc length of the closest point of the path (the interpreter's FollowTrajectory start)."""
        best = np.zeros_like(px)
        best_d = np.full_like(px, np.inf)
        for i in range(self.x.size - 1):
            ax, ay, bx, by = self.x[i], self.y[i], self.x[i + 1], self.y[i + 1]
            L2 = (bx - ax) ** 2 + (by - ay) ** 2
            f = (
                0.0
                if L2 == 0
                else np.maximum(0.0, np.minimum(1.0, ((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / L2))
            )
            d = np.hypot(ax + f * (bx - ax) - px, ay + f * (by - ay) - py)
            closer = d < best_d - 1e-12
            best = np.where(closer, self.s[i] + f * (self.s[i + 1] - self.s[i]), best)
            best_d = np.where(closer, d, best_d)
        return best


@dataclass
class BatchResult:
    t: np.ndarray  # (T,)
    names: list[str]
    x: np.ndarray  # (E, V, T)
    y: np.ndarray
    yaw: np.ndarray
    speed: np.ndarray
    accel: np.ndarray
    collision_onsets: list[list[tuple[float, str, str]]]  # per variant, like RunResult.collisions
    ego: str
    threat: str
    lengths: list[float]
    widths: list[float]


def batch_pair(result: BatchResult):
    """The ego and the threat of every variant, as one batch :class:`PairSeries`."""
    from vei_scenario.metrics.series import PairSeries, Track

    def track(name: str) -> Track:
        k = result.names.index(name)
        return Track(
            name,
            result.lengths[k],
            result.widths[k],
            result.x[k],
            result.y[k],
            result.yaw[k],
            result.speed[k],
            result.accel[k],
        )

    return PairSeries(result.t, track(result.ego), track(result.threat))


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


class BatchScenario:
    """The vei-compiled scenario, ready to run for arrays of parameter values."""

    def __init__(self, path: str | Path, dt: float = 0.01) -> None:
        self.path, self.dt = Path(path), dt
        doc = load_scenario(path)
        sim = Simulation(doc, dt)
        ctx = sim.ctx
        self.defaults = dict(doc.parameters)
        self.types = dict(doc.parameter_types)
        self._valid_values: set[tuple[str, str]] = set()
        self.names = list(ctx.entities)
        self.ego, self.threat = sim.ego, sim.threat
        if self.ego != self.names[0] or self.threat is None:
            raise NotBatchable("the ego must be the first entity and the planner must name a threat")
        ents = [ctx.entities[n] for n in self.names]
        self.length = [e.length for e in ents]
        self.width = [e.width for e in ents]
        if any(e.center_x != 0 for e in ents):
            raise NotBatchable("box centres off the reference point")
        self.limits = ents[0].limits
        ego_ctrls = [c for c in ents[0].controllers.values() if isinstance(c, CollisionAvoidanceController)]
        threat_ctrls = [
            c for c in ctx.entities[self.threat].controllers.values() if isinstance(c, SocialForceController)
        ]
        if len(ego_ctrls) != 1 or len(threat_ctrls) != 1:
            raise NotBatchable("expected one planner on the ego and one social force model on the threat")
        self.cap_params = ego_ctrls[0].params
        self.sfm_params = threat_ctrls[0].params
        self.margin = self.cap_params.corridor_margin_m
        # Init: a teleport and a speed step per entity.
        self.init_pose, self.init_speed_raw = {}, {}
        raw = parse_xml(path).getroot()
        self.raw = raw
        for private in raw.iterfind("Storyboard/Init/Actions/Private"):
            name = private.get("entityRef")
            wp = private.find("PrivateAction/TeleportAction/Position/WorldPosition")
            sp = private.find(".//SpeedAction")
            if wp is None or sp is None or sp.find("SpeedActionDynamics").get("dynamicsShape") != "step":
                raise NotBatchable(f"Init of {name} is not teleport + step speed")
            self.init_pose[name] = tuple(
                float(resolve_value(self.path, wp, k, wp.get(k, "0"), self.defaults)) for k in ("x", "y", "h")
            )
            el = sp.find("SpeedActionTarget/AbsoluteTargetSpeed")
            self.init_speed_raw[name] = (el, el.get("value"))
        if set(self.init_pose) != set(self.names):
            raise NotBatchable("every entity needs an Init teleport and speed")
        # Trajectories of the replay story, one per entity.
        self.paths, self.offset_raw = {}, {}
        for act in sim.storyboard.stories[0].children:
            if act.start_trigger is None:
                raise NotBatchable("acts must start on SimulationTime > 0")
            for group in act.children:
                for man in group.children:
                    for ev in man.children:
                        for a in ev.children:
                            for rt in a.actions:
                                self.paths[rt.entity] = (PathArrays(rt.polyline), rt.polyline, rt.timing)
        if set(self.paths) != set(self.names) or self.paths[self.ego][2] is not None:
            raise NotBatchable("every entity follows one trajectory; the ego's without timing")
        for group in raw.iterfind("Storyboard/Story/Act/ManeuverGroup"):
            actor = group.find("Actors/EntityRef").get("entityRef")
            timing = group.find(".//FollowTrajectoryAction/TimeReference/Timing")
            if timing is not None:
                if timing.get("domainAbsoluteRelative") != "absolute" or float(timing.get("scale")) != 1.0:
                    raise NotBatchable("scooter timing must be absolute with scale 1")
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
                    raise NotBatchable("controller activations must depend on parameters only")
                groups.append([(c.get("parameterRef"), c.get("value"), c.get("rule")) for c in conds])
            self.activation[actor] = groups
        if set(self.activation) != {self.ego, self.threat}:
            raise NotBatchable("expected activations of the planner and of the rider")
        starts = set()
        for act in raw.iterfind("Storyboard/Story/Act"):
            conds = act.findall("StartTrigger/ConditionGroup/Condition")
            st = act.find("StartTrigger//SimulationTimeCondition")
            rule = st.get("rule") if st is not None else None
            if len(conds) != 1 or rule not in ("greaterThan", "greaterOrEqual") or float(conds[0].get("delay", 0)):
                raise NotBatchable("acts must start on one SimulationTime > t or >= t condition")
            value = float(resolve_value(self.path, st, "value", st.get("value"), self.defaults))
            # "t >= v" on the step grid is "t > v - dt/2": one threshold for both rules.
            starts.add(value - 0.5 * dt if rule == "greaterOrEqual" else value)
        if len(starts) != 1:
            raise NotBatchable("all acts must start at the same time")
        #: The entities keep their Init speed and heading until the first step that begins after this
        #: (below 0 when the acts start at the first step).
        self.behaviour_start_s = starts.pop()
        stop = raw.find("Storyboard/StopTrigger//SimulationTimeCondition")
        if stop is None or stop.get("rule") != "greaterThan":
            raise NotBatchable("the storyboard must stop on SimulationTime > duration")
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

    def _prop_or_none(self, entity: str, name: str):
        try:
            return self._prop(entity, name)
        except NotBatchable:
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
        raise NotBatchable(f"{entity} controller has no property {name}")

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
            raise NotBatchable("variants with different durations")
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

    def run(self, variants: list[dict[str, str]]) -> BatchResult:
        """The variants as arrays; they share the model parameters (see :meth:`model_groups`)."""
        _, params = self.shared_model(variants)
        if params is None:
            return self._run(variants)
        saved = self.cap_params, self.sfm_params, self.margin
        self.cap_params, self.sfm_params = params
        self.margin = self.cap_params.corridor_margin_m
        try:
            return self._run(variants)
        finally:
            self.cap_params, self.sfm_params, self.margin = saved

    def _run(self, variants: list[dict[str, str]]) -> BatchResult:
        dt, V, E = self.dt, len(variants), len(self.names)
        r = self.resolve(variants)
        duration, rider, sfm_on, cap_on, cruise, delays = (
            r.duration,
            r.rider,
            r.sfm_on,
            r.cap_on,
            r.cruise_mps,
            r.delays,
        )
        repulsive = rider == "normal"

        x = np.empty((E, V))
        y, yaw, speed, accel = np.empty((E, V)), np.empty((E, V)), np.empty((E, V)), np.zeros((E, V))
        for k, n in enumerate(self.names):
            x[k], y[k], yaw[k] = self.init_pose[n]
            speed[k] = r.init_speed[n]
        fs = np.zeros((E, V))
        ti = self.names.index(self.threat)
        threat_path, threat_poly, _ = self.paths[self.threat]
        # The rider's route and start, as SocialForceController._prepare builds them.
        route = np.array(rider_route(threat_poly))
        t_start = threat_poly.ts[0] * 1.0 + delays[self.threat]
        v_start = recorded_start_speed(threat_poly)
        sfm = None  # (x, y, vx, vy, wp) once riding
        riding = np.zeros(V, bool)
        brake = np.zeros(V, bool)
        integral = np.zeros(V)
        prev_err = np.full(V, np.nan)

        rec = {q: [] for q in ("x", "y", "yaw", "speed", "accel")}
        times: list[float] = []
        onsets: list[list[tuple[float, str, str]]] = [[] for _ in range(V)]
        colliding = {}

        def record(t: float) -> None:
            times.append(t)
            for q, arr in (("x", x), ("y", y), ("yaw", yaw), ("speed", speed), ("accel", accel)):
                rec[q].append(arr.copy())

        def collide(t: float) -> None:
            for a in range(E):
                for b in range(a + 1, E):
                    hit = boxes_overlap(
                        x[a],
                        y[a],
                        yaw[a],
                        self.length[a],
                        self.width[a],
                        x[b],
                        y[b],
                        yaw[b],
                        self.length[b],
                        self.width[b],
                    )
                    before = colliding.get((a, b), np.zeros(V, bool))
                    for v in np.nonzero(hit & ~before)[0]:
                        onsets[v].append((t, self.names[a], self.names[b]))
                    colliding[(a, b)] = hit

        collide(0.0)
        record(0.0)
        step, t = 0, 0.0
        started = False
        prev_raw_stop: bool | None = None
        while t < 600.0 - 1e-9:
            raw_stop = t > duration
            if raw_stop and prev_raw_stop is False:
                break
            prev_raw_stop = raw_stop
            if not started and t > self.behaviour_start_s:
                started = True
                fs[0] = self.paths[self.ego][0].project(x[0], y[0])
            t_next = t + dt
            for k, n in enumerate(self.names):
                path, poly, timing = self.paths[n]
                if not started:  # no follower yet: straight ahead at the current speed
                    v0 = speed[k].copy()
                    accel[k] = (speed[k] - v0) / dt
                    ds = 0.5 * (v0 + speed[k]) * dt
                    x[k] = x[k] + ds * np.cos(yaw[k])
                    y[k] = y[k] + ds * np.sin(yaw[k])
                    continue
                if k == 0:
                    brake, integral, prev_err = self._move_ego(
                        path, x, y, yaw, speed, accel, fs, cap_on, cruise, ti, brake, integral, prev_err, dt
                    )
                    continue
                tt = t_next - delays.get(n, np.zeros(V))
                target = path.s_at_time(tt)
                px, py, ph = path.at_time(tt)
                spd = (target - fs[k]) / dt
                replay_accel = (spd - speed[k]) / dt
                if k == ti:
                    go = sfm_on & (t_next >= t_start - 1e-9)
                    begin = go & ~riding
                    if begin.any():
                        if sfm is None:
                            sfm = (x[k].copy(), y[k].copy(), np.zeros(V), np.zeros(V), np.zeros(V, np.int64))
                        sx, sy, svx, svy, swp = sfm
                        svx = np.where(begin, v_start * np.cos(yaw[k]), svx)
                        svy = np.where(begin, v_start * np.sin(yaw[k]), svy)
                        sx, sy = np.where(begin, x[k], sx), np.where(begin, y[k], sy)
                        sfm = (sx, sy, svx, svy, swp)
                        riding = riding | begin
                    if riding.any():
                        ego_box = (x[0], y[0], yaw[0], np.full(V, self.length[0]), np.full(V, self.width[0]))
                        nx_, ny_, nvx, nvy, nwp = sfm_step_arrays(*sfm, route, self.sfm_params, repulsive, ego_box, dt)
                        keep = ~riding
                        sfm = tuple(np.where(keep, old, new) for old, new in zip(sfm, (nx_, ny_, nvx, nvy, nwp)))
                        sp = np.hypot(sfm[2], sfm[3])
                        new_yaw = np.where(sp > 0.05, np.arctan2(sfm[3], sfm[2]), yaw[k])
                        accel[k] = np.where(riding, (sp - speed[k]) / dt, replay_accel)
                        x[k] = np.where(riding, sfm[0], px)
                        y[k] = np.where(riding, sfm[1], py)
                        yaw[k] = np.where(riding, new_yaw, ph)
                        speed[k] = np.where(riding, sp, spd)
                        fs[k] = np.where(riding, fs[k], target)
                        continue
                accel[k], speed[k] = replay_accel, spd
                fs[k] = target
                x[k], y[k], yaw[k] = px, py, ph
            step += 1
            t = round(step * dt, 9)
            collide(t)
            record(t)
        stack = {q: np.stack(v, axis=-1) for q, v in rec.items()}  # (E, V, T)
        return BatchResult(
            np.array(times),
            self.names,
            stack["x"],
            stack["y"],
            stack["yaw"],
            stack["speed"],
            stack["accel"],
            onsets,
            self.ego,
            self.threat,
            self.length,
            self.width,
        )

    def _move_ego(self, path, x, y, yaw, speed, accel, fs, cap_on, cruise, ti, brake, integral, prev_err, dt):
        """The ego's step (arrays updated in place): the planner where it is on, else its path at constant
        speed. Returns the planner state (brake, integral, previous error)."""
        p = self.cap_params
        c, s = np.cos(yaw[0]), np.sin(yaw[0])
        corridor = (
            x[0] + 0.5 * self.margin * c,
            y[0] + 0.5 * self.margin * s,
            yaw[0],
            self.length[0] + self.margin,
            self.width[0] + 2 * self.margin,
        )
        tvx, tvy = speed[ti] * np.cos(yaw[ti]), speed[ti] * np.sin(yaw[ti])
        threat_box = (x[ti], y[ti], yaw[ti], self.length[ti], self.width[ti])
        ttc = time_to_contact(*corridor, speed[0] * c, speed[0] * s, *threat_box, tvx, tvy)
        ttc_resume = time_to_contact(*corridor, cruise * c, cruise * s, *threat_box, tvx, tvy)
        nb, ni, npe, a_cmd, _ = cap_step_arrays(
            brake, integral, prev_err, p, cruise, speed[0], ttc, dt, np.where(brake, ttc_resume, ttc)
        )
        ds_cap, v_cap, a_cap = longitudinal_step_arrays(
            np.zeros_like(speed[0]), speed[0], accel[0], a_cmd, self.limits, dt
        )
        v0 = speed[0]
        ds = np.where(cap_on, ds_cap, 0.5 * (v0 + v0) * dt)
        fs[0] = np.minimum(fs[0] + ds, path.length)
        x[0], y[0], yaw[0] = path.at_s(fs[0])
        speed[0] = np.where(cap_on, v_cap, v0)
        accel[0] = np.where(cap_on, a_cap, (v0 - v0) / dt)
        return np.where(cap_on, nb, brake), np.where(cap_on, ni, integral), np.where(cap_on, npe, prev_err)


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
