"""The closed loop of a vei-compiled scenario as FMU parameters and connections, and as an SSP 1.0
package (``vei fmu system``).

The loop: the ego vehicle FMU (its path, Init pose and speed), the planner FMU (the scenario's
CollisionAvoidancePlanner properties and CapEnabled) and one e-scooter FMU instance per rider: the
threat (component ``sfm``: its recorded track and TimeShift, its route, RiderType) and every other
rider of the scenario (components ``sfm_<entity>``, replaying their recorded tracks as ``vei run``
plays them), connected as ``vei run`` couples the entities. Values are
read through the loop's reading of the scenario (:mod:`vei_scenario.loop`), so a scenario it cannot run in batch (not of
the structure ``vei compile`` writes) is refused with the reason.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from vei_scenario.atomic_io import write_bytes_atomic
from vei_scenario.errors import VeiInputError
from vei_scenario.fmu.packaging import xml_value, zip_bytes
from vei_scenario.fmu.variables import MAX_PATH, MAX_ROUTE, SPECS
from vei_scenario.reports.osi_trace import SCOOTER_TYPES

#: The vehicle categories the FMU loop takes for riders (an e-scooter is also known by its objectType).
RIDER_CATEGORIES = ("bicycle", "motorbike")

#: (from component, output) -> [(to component, input)]: the couplings of vei run's step.
CONNECTIONS = (
    ("ego", "x", "cap", "ego_x"),
    ("ego", "y", "cap", "ego_y"),
    ("ego", "yaw", "cap", "ego_yaw"),
    ("ego", "speed", "cap", "ego_speed"),
    ("ego", "x", "sfm", "ego_x"),
    ("ego", "y", "sfm", "ego_y"),
    ("ego", "yaw", "sfm", "ego_yaw"),
    ("sfm", "x", "cap", "threat_x"),
    ("sfm", "y", "cap", "threat_y"),
    ("sfm", "yaw", "cap", "threat_yaw"),
    ("sfm", "speed", "cap", "threat_speed"),
    ("cap", "a_cmd", "ego", "a_cmd"),
)

#: Step order of a sequential (Gauss-Seidel) master reproducing vei run's default coupling: the
#: planner samples ego and threat at the start of the step, the ego moves with its command, the rider
#: reacts to the ego's new position.
SEQUENTIAL_ORDER = ("cap", "ego", "sfm")


def model_of(component: str) -> str:
    """The model (:data:`~vei_scenario.fmu.variables.SPECS` key) a component instantiates: ``sfm_<entity>``
    is an e-scooter rider like ``sfm``."""
    return "sfm" if component.startswith("sfm_") else component


@dataclass
class ClosedLoop:
    """Parameter values per component (FMU variable name -> value) and the run's timing."""

    parameters: dict[str, dict[str, float | int | bool | str]] = field(default_factory=dict)
    dt: float = 0.01
    stop_time: float = 25.0
    entities: dict[str, str] = field(default_factory=dict)  # component -> scenario entity name
    #: where the loop is known to play differently from ``vei run`` (one sentence each)
    notes: list[str] = field(default_factory=list)

    @property
    def components(self) -> tuple[str, ...]:
        """Every component: ego, cap, sfm (the threat), then the other riders in the scenario's order."""
        return tuple(self.parameters)

    @property
    def riders(self) -> tuple[str, ...]:
        """The e-scooter components: the threat's first."""
        return tuple(c for c in self.parameters if model_of(c) == "sfm")

    @property
    def connections(self) -> tuple[tuple[str, str, str, str], ...]:
        """:data:`CONNECTIONS`, and the ego's pose into every other rider (each is repelled by the ego)."""
        more = [("ego", q, c, f"ego_{q}") for c in self.riders if c != "sfm" for q in ("x", "y", "yaw")]
        return CONNECTIONS + tuple(more)

    @property
    def sequential_order(self) -> tuple[str, ...]:
        """:data:`SEQUENTIAL_ORDER`, the other riders after the threat (each reacts to the ego's new pose)."""
        return SEQUENTIAL_ORDER + tuple(c for c in self.riders if c != "sfm")

    @property
    def steps(self) -> int:
        """Communication steps of vei run's run: it stops at the first step starting after the
        storyboard's stop time."""
        n = 0
        while round(n * self.dt, 9) <= self.stop_time:
            n += 1
        return n


def closed_loop(
    scenario: str | Path, values: dict[str, str] | None = None, dt: float = 0.01, leave_out: tuple[str, ...] = ()
) -> ClosedLoop:
    """The closed loop of ``scenario`` with parameter overrides ``values`` at step ``dt``. A road user
    that is no rider is refused in one line, unless ``leave_out`` names it (``--leave-out``): it only
    replays its track and nothing in the loop reacts to it, so it can be left out, said in a note."""
    from vei_scenario.checks import check_dt
    from vei_scenario.loop import LoopScene, NotALoop

    check_dt(dt)

    try:
        b = LoopScene(scenario, dt)
    except NotALoop as exc:
        raise VeiInputError(scenario, "", f"not a vei-compiled closed loop: {exc}") from None
    # the others only replay their tracks (the loop's reading refuses anything else) and nothing in the
    # loop reacts to them (the planner watches the threat alone, a rider is repelled by the ego alone):
    # the riders among them are in the loop, the other road users are left out, said in a note
    others, left_out = [], []
    for n in b.names:
        if n in (b.ego, b.threat):
            continue
        kind, category, object_type = b.entity_kinds[n]
        what = f"{n} (a {object_type or category or kind})"
        if kind == "vehicle" and (category in RIDER_CATEGORIES or object_type.lower() in SCOOTER_TYPES):
            others.append(n)
        elif n in leave_out:
            left_out.append(what)
        else:
            kind_text = f"a {object_type or category or kind}"
            raise VeiInputError(scenario, n, f"{kind_text} is no rider: the FMU loop holds the ego and riders "
                                f"(it only replays its track: --leave-out {n} leaves it out)")  # fmt: skip
    unknown = sorted(set(leave_out) - set(b.names))
    if unknown:
        raise VeiInputError(scenario, "--leave-out", f"no entity {unknown[0]!r} (entities: {', '.join(b.names)})")
    if values and not b.accepts(values):  # the interpreter's loader says exactly what is wrong with them
        from vei_scenario.interpreter.document import load_scenario

        load_scenario(scenario, values)
        raise VeiInputError(scenario, "--param", f"the values {values} do not make a playable closed loop")
    r = b.resolve([values or {}])
    ego, threat = b.names.index(b.ego), b.names.index(b.threat)
    ego_poly = b.paths[b.ego][0]
    from vei_scenario.models.rider import rider_route

    routes = {n: rider_route(b.paths[n][0]) for n in (b.threat, *others)}
    sizes = [("ego path", len(ego_poly.xs))] + [(f"track of {n}", len(b.paths[n][0].xs)) for n in routes]
    for what, n in sizes:
        if n > MAX_PATH:
            raise VeiInputError(scenario, "", f"the {what} has {n} vertices; the FMUs hold at most {MAX_PATH}")
    for n, route in routes.items():
        if len(route) > MAX_ROUTE:
            raise VeiInputError(scenario, "", f"the route of {n} has {len(route)} waypoints; the FMU holds at most "
                                f"{MAX_ROUTE}")  # fmt: skip
    start = b.behaviour_start_s

    def arrays(prefix: str, seqs: dict[str, list[float]]) -> dict[str, float]:
        return {f"{prefix}_{k}[{i + 1}]": float(v) for k, seq in seqs.items() for i, v in enumerate(seq)}

    ex, ey, eyaw = b.init_pose[b.ego]
    cap_params, sfm_params = b.model_params(values or {})
    cap_props = {k: float(v) for k, v in cap_params.properties().items()}
    sfm_props = {k: float(v) for k, v in sfm_params.properties().items()}
    rider = str(r.rider[0])
    loop = ClosedLoop(dt=dt, stop_time=r.duration, entities={"ego": b.ego, "sfm": b.threat, "cap": b.ego})
    loop.parameters["ego"] = {
        "max_accel_mps2": b.limits.max_accel_mps2,
        "max_decel_mps2": b.limits.max_decel_mps2,
        "jerk_max_mps3": b.limits.jerk_max_mps3,
        "x0": ex,
        "y0": ey,
        "yaw0": eyaw,
        "speed0": float(r.init_speed[b.ego][0]),
        "behaviour_start_s": start,
        "path_n": len(ego_poly.xs),
        **arrays("path", {"x": ego_poly.xs, "y": ego_poly.ys, "h": ego_poly.hs}),
    }
    loop.parameters["cap"] = {
        **cap_props,
        "enabled": bool(r.cap_on[0]),
        "cruise_speed_mps": float(r.cruise_mps[0]),
        "ego_length_m": b.length[ego],
        "ego_width_m": b.width[ego],
        "threat_length_m": b.length[threat],
        "threat_width_m": b.width[threat],
        "behaviour_start_s": start,
    }

    def rider_parameters(name: str, rider_type: str, track=None) -> dict:
        i, (sx, sy, syaw), route = b.names.index(name), b.init_pose[name], routes[name]
        track = b.paths[name][0] if track is None else track
        delay = r.delays.get(name)
        return {
            **sfm_props,
            "rider_type": rider_type,
            "length_m": b.length[i],
            "width_m": b.width[i],
            "ego_length_m": b.length[ego],
            "ego_width_m": b.width[ego],
            "x0": sx,
            "y0": sy,
            "yaw0": syaw,
            "speed0": float(r.init_speed[name][0]),
            "behaviour_start_s": start,
            "time_shift_s": float(delay[0]) if delay is not None else 0.0,
            "track_n": len(track.xs),
            **arrays("track", {"t": track.ts, "x": track.xs, "y": track.ys, "h": track.hs}),
            "route_n": len(route),
            **arrays("route", {"x": [p[0] for p in route], "y": [p[1] for p in route]}),
        }

    # the threat rides only where the scenario activates it; otherwise it replays, as the others do
    loop.parameters["sfm"] = rider_parameters(b.threat, rider if bool(r.sfm_on[0]) else "replay")
    if left_out:
        loop.notes.append(
            f"{', '.join(left_out)}: no rider, replayed in vei run and left out of the loop (nothing in it "
            "reacts to it)"
        )
    # a replayed rider whose track ends before the run: its FMU is given the way vei run drives it on
    shift = {n: float(r.delays[n][0]) if r.delays.get(n) is not None else 0.0 for n in others}
    ending = [n for n in others if b.paths[n][0].ts[-1] + shift[n] < r.duration]
    run = None
    if ending:
        from vei_scenario.interpreter import run_scenario

        run = run_scenario(scenario, values, dt)
    for n in others:
        track = None
        if n in ending:
            from vei_scenario.fmu.replay_tracks import drive_on

            poly = b.paths[n][0]
            track = drive_on((poly.ts, poly.xs, poly.ys, poly.hs), run.traces[n], shift[n], MAX_PATH)
            end = float(poly.ts[-1]) + shift[n]
            if track.cut_s is not None:
                loop.notes.append(
                    f"{n}'s track ends at {end:.2f} s: its FMU follows vei run's way on (along its lane) until "
                    f"{track.cut_s + shift[n]:.2f} s, then goes on straight (the FMU holds {MAX_PATH} track vertices)"
                )
            elif track.tolerance_m > 1e-6:
                loop.notes.append(
                    f"{n}'s track ends at {end:.2f} s: its FMU follows vei run's way on (along its lane) within "
                    f"{track.tolerance_m:g} m (the FMU holds {MAX_PATH} track vertices)"
                )
        loop.parameters[f"sfm_{n}"] = rider_parameters(n, "replay", track)
        loop.entities[f"sfm_{n}"] = n
    return loop


_NS = {
    "ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
    "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
    "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues",
}


def _q(prefix: str, tag: str) -> str:
    return f"{{{_NS[prefix]}}}{tag}"


#: The one name of every component's parameter set: SSP hosts that apply parameter sets by name (ecos:
#: ``init(parameter_set=...)``, or its first set by default) then configure all three components.
PARAMETER_SET = "scenario"


def system_structure(loop: ClosedLoop, name: str = "vei_closed_loop") -> bytes:
    """SystemStructure.ssd (SSP 1.0): the FMUs as components under ``resources/`` (every rider an
    instance of the one e-scooter FMU), their connectors, parameter values bound inline, the connections
    and the default experiment."""
    root = etree.Element(_q("ssd", "SystemStructureDescription"), nsmap=_NS, version="1.0", name=name)
    system = etree.SubElement(root, _q("ssd", "System"), name=name)
    elements = etree.SubElement(system, _q("ssd", "Elements"))
    for comp in loop.components:
        spec = SPECS[model_of(comp)]
        el = etree.SubElement(
            elements,
            _q("ssd", "Component"),
            name=comp,
            type="application/x-fmu-sharedlibrary",
            source=f"resources/{spec.identifier}.fmu",
        )
        connectors = etree.SubElement(el, _q("ssd", "Connectors"))
        for v in spec.variables:
            if v.causality in ("input", "output"):
                c = etree.SubElement(connectors, _q("ssd", "Connector"), name=v.name, kind=v.causality)
                etree.SubElement(c, _q("ssc", v.type))
        bindings = etree.SubElement(el, _q("ssd", "ParameterBindings"))
        binding = etree.SubElement(bindings, _q("ssd", "ParameterBinding"))
        values = etree.SubElement(binding, _q("ssd", "ParameterValues"))
        pset = etree.SubElement(values, _q("ssv", "ParameterSet"), version="1.0", name=PARAMETER_SET)
        params = etree.SubElement(pset, _q("ssv", "Parameters"))
        types = {s.name: s.var.type for s in spec.scalars()}
        for pname, value in loop.parameters[comp].items():
            p = etree.SubElement(params, _q("ssv", "Parameter"), name=pname)
            etree.SubElement(p, _q("ssv", types[pname]), value=xml_value(value))
    conns = etree.SubElement(system, _q("ssd", "Connections"))
    for a, out, b, inp in loop.connections:
        etree.SubElement(
            conns, _q("ssd", "Connection"), startElement=a, startConnector=out, endElement=b, endConnector=inp
        )
    etree.SubElement(
        root, _q("ssd", "DefaultExperiment"), startTime="0.0", stopTime=repr(round(loop.steps * loop.dt, 9))
    )
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


def write_ssp(loop: ClosedLoop, fmus: dict[str, Path], out: Path) -> Path:
    """``out`` (.ssp): SystemStructure.ssd plus the FMUs under resources/."""
    entries = {"SystemStructure.ssd": system_structure(loop)}
    for model, path in fmus.items():
        entries[f"resources/{SPECS[model].identifier}.fmu"] = Path(path).read_bytes()
    write_bytes_atomic(out, zip_bytes(entries))
    return out
