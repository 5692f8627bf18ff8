"""Play a scenario in esmini (the reference OpenSCENARIO player) and compare it with ``vei run``.

esmini is not a dependency: give its binary explicitly or through ``VEI_ESMINI``. It has no option to
override a parameter, so a run with parameters plays a copy of the file with those declarations
changed (and its relative file references made absolute); esmini evaluates the expressions itself.

Compared per entity on the common time grid: the reference point (esmini logs the entity position,
which is the reference point in both players), and the collision verdict with its onset time.
"""

from __future__ import annotations

import csv
import os
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from vei_scenario.errors import VeiInputError
from vei_scenario.safe_xml import parse_xml


def find_esmini(explicit: str | Path | None = None) -> Path | None:
    """The esmini binary: ``explicit``, else ``$VEI_ESMINI``, else ``esmini`` on the PATH; None if absent."""
    for candidate in (explicit, os.environ.get("VEI_ESMINI"), shutil.which("esmini")):
        if candidate and Path(candidate).is_file() and os.access(candidate, os.X_OK):
            return Path(candidate).resolve()
    return None


@dataclass
class Track:
    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    h: np.ndarray
    speed: np.ndarray


@dataclass
class EsminiRun:
    tracks: dict[str, Track]
    collisions: list[tuple[float, str, str]]  # onset time and the two entities
    seconds: float = 0.0


@dataclass
class EntityComparison:
    entity: str
    max_deviation_m: float
    at_time_s: float
    compared_until_s: float
    samples: int


@dataclass
class Comparison:
    entities: list[EntityComparison]
    vei_collisions: list[tuple[float, str, str]]
    esmini_collisions: list[tuple[float, str, str]]
    notes: list[str] = field(default_factory=list)
    vei_end_s: float = float("nan")  # last logged time of each player
    esmini_end_s: float = float("nan")

    @property
    def end_time_difference_s(self) -> float:
        return abs(self.vei_end_s - self.esmini_end_s)

    @property
    def max_deviation_m(self) -> float:
        return max((e.max_deviation_m for e in self.entities), default=0.0)

    def collision_time_difference_s(self) -> float | None:
        """|Δ onset| of the first collision when both players see one, else None."""
        if self.vei_collisions and self.esmini_collisions:
            return abs(self.vei_collisions[0][0] - self.esmini_collisions[0][0])
        return None

    @property
    def same_verdict(self) -> bool:
        return bool(self.vei_collisions) == bool(self.esmini_collisions)


_PATH_ATTRS = (("LogicFile", "filepath"), ("SceneGraphFile", "filepath"), ("Directory", "path"))


def _prepared_copy(xosc: Path, parameters: dict[str, str], workdir: Path) -> Path:
    """A copy of ``xosc`` in ``workdir`` with parameter defaults overridden and file references absolute."""
    tree = parse_xml(xosc)
    root = tree.getroot()
    known = set()
    for decl in root.iterfind("ParameterDeclarations/ParameterDeclaration"):
        known.add(decl.get("name"))
        if decl.get("name") in parameters:
            decl.set("value", str(parameters[decl.get("name")]))
    unknown = set(parameters) - known
    if unknown:
        raise VeiInputError(xosc, "--param", f"unknown parameter(s) {', '.join(sorted(unknown))}")
    decls = {d.get("name"): d for d in root.iterfind("ParameterDeclarations/ParameterDeclaration")}
    for tag, attr in _PATH_ATTRS:
        for el in root.iter(tag):
            value = el.get(attr)
            target, key = el, attr
            if value and value.startswith("$") and value[1:] in decls:  # a path given by a parameter
                target, key = decls[value[1:]], "value"
                value = target.get("value")
            if value and not value.startswith("$") and not Path(value).is_absolute():
                target.set(key, str((xosc.parent / value).resolve()))
    out = workdir / xosc.name
    tree.write(str(out), xml_declaration=True, encoding="UTF-8")
    return out


def read_esmini_csv(path: Path) -> EsminiRun:
    """esmini's ``--csv_logger`` file: one row per step, a block of columns per entity. An entity that
    is deleted during the run drops out of the rows after it (the blocks of the others move up), so
    each row is read block by block by the entity name it carries."""
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    head = next(i for i, r in enumerate(rows) if r and r[0].strip().startswith("Index"))
    header = [c.strip() for c in rows[head]]
    first = next(i for i, c in enumerate(header) if c.startswith("#"))
    fields: dict[str, int] = {}  # column of each field within an entity's block
    for i, name in enumerate(header[first:], start=first):
        k, _, rest = name[1:].partition(" ")
        if name.startswith("#") and k == "1":
            fields[rest.split(" [")[0]] = i - first
    width = max(fields.values()) + 1
    wanted = ("World_Position_X", "World_Position_Y", "World_Heading_Angle", "Current_Speed")
    samples: dict[str, list[list[float]]] = {}
    ids: dict[str, str] = {}
    present: list[tuple[float, list[tuple[str, str]]]] = []  # per row: (time, [(entity, collision ids)])
    for r in rows[head + 1 :]:
        if len(r) <= first:
            continue
        r = [c.strip() for c in r]
        time = float(r[1])
        here = []
        for start in range(first, len(r) - width + 1, width):
            block = r[start : start + width]
            name = block[fields["Entity_Name"]]
            if not name:
                continue
            ids.setdefault(block[fields["Entity_ID"]], name)
            samples.setdefault(name, []).append([time] + [float(block[fields[k]]) for k in wanted])
            here.append((name, block[fields["collision_ids"]]))
        present.append((time, here))
    tracks = {}
    for name, rows_ in samples.items():
        a = np.array(rows_)
        tracks[name] = Track(a[:, 0], a[:, 1], a[:, 2], a[:, 3], a[:, 4])
    colliding: set[frozenset] = set()
    collisions: list[tuple[float, str, str]] = []
    for time, here in present:
        now = set()
        for me, others in here:
            for other in others.split():
                if other in ids and ids[other] != me:
                    now.add(frozenset((me, ids[other])))
        for pair in now - colliding:
            a_, c = sorted(pair)
            collisions.append((time, a_, c))
        colliding = now
    return EsminiRun(tracks, collisions)


def run_esmini(
    esmini: Path,
    xosc: str | Path,
    dt: float = 0.01,
    parameters: dict[str, str] | None = None,
    timeout_s: float = 120.0,
) -> EsminiRun:
    """Play ``xosc`` headless at the fixed step ``dt`` with collision detection; its logged tracks."""
    import time

    xosc = Path(xosc).resolve()
    with tempfile.TemporaryDirectory(prefix="vei-esmini-") as tmp:
        work = Path(tmp)
        played = _prepared_copy(xosc, parameters, work) if parameters else xosc
        log = work / "log.csv"
        cmd = [str(esmini), "--headless", "--osc", str(played), "--fixed_timestep", repr(dt), "--csv_logger"]
        cmd += [str(log), "--collision", "--disable_stdout", "--disable_log"]
        start = time.perf_counter()
        proc = subprocess.run(cmd, cwd=work, capture_output=True, text=True, timeout=timeout_s)
        seconds = time.perf_counter() - start
        if proc.returncode != 0 or not log.is_file():
            tail = (proc.stdout + proc.stderr).strip().splitlines()[-3:]
            raise RuntimeError(f"esmini failed on {xosc.name} (exit {proc.returncode}): {' | '.join(tail)}")
        run = read_esmini_csv(log)
    run.seconds = seconds
    return run


def compare_runs(vei_result, esmini_run: EsminiRun, until: dict[str, float] | None = None) -> Comparison:
    """Largest distance between the two players' reference points per entity, on the common time grid
    (up to ``until[entity]`` where given), and both collision lists."""
    until = until or {}
    out: list[EntityComparison] = []
    notes: list[str] = []
    for name, trace in vei_result.traces.items():
        es = esmini_run.tracks.get(name)
        if es is None:
            notes.append(f"{name}: not in esmini's log")
            continue
        keys = {round(float(t), 6): i for i, t in enumerate(es.t)}
        limit = until.get(name, float("inf"))
        pairs = [(i, keys[round(float(t), 6)]) for i, t in enumerate(trace.t) if round(float(t), 6) in keys]
        pairs = [(i, j) for i, j in pairs if trace.t[i] <= limit + 1e-9]
        if not pairs:
            notes.append(f"{name}: no common time steps")
            continue
        vi, ej = np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])
        d = np.hypot(trace.x[vi] - es.x[ej], trace.y[vi] - es.y[ej])
        k = int(np.argmax(d))
        out.append(EntityComparison(name, float(d[k]), float(trace.t[vi[k]]), float(trace.t[vi[-1]]), len(pairs)))
    vei_coll = [(float(t), *sorted((a, b))) for t, a, b in vei_result.collisions]
    # esmini adds entities of its own (a truck's trailer "Truck+"): their collisions are not comparable
    known = set(vei_result.traces)
    es_coll = [c for c in esmini_run.collisions if c[1] in known and c[2] in known]
    if len(es_coll) < len(esmini_run.collisions):
        notes.append("esmini collisions with entities vei does not model were left out")
    es_end = max((float(tr.t[-1]) for tr in esmini_run.tracks.values() if len(tr.t)), default=float("nan"))
    vei_end = float(vei_result.t[-1]) if len(vei_result.t) else float("nan")
    return Comparison(out, vei_coll, es_coll, notes, vei_end, es_end)


def recording_ends(xosc: str | Path, parameters: dict[str, str] | None = None) -> dict[str, float]:
    """Simulation time at which each entity's timed trajectory ends (its recording, for a compiled
    scenario), read from the scenario with ``parameters`` applied: ``(t_last - offset) / scale``."""
    from vei_scenario.interpreter.document import load_scenario

    doc = load_scenario(xosc, parameters)
    ends: dict[str, float] = {}

    def note(actor: str, fta) -> None:
        timing = fta.find("TimeReference/Timing")
        times = [v.get("time") for v in fta.iter("Vertex")]
        if timing is None or timing.get("domainAbsoluteRelative") != "absolute" or not times or None in times:
            return
        scale, offset = float(timing.get("scale", "1")), float(timing.get("offset", "0"))
        ends[actor] = max(ends.get(actor, float("-inf")), (float(times[-1]) - offset) / scale)

    for private in doc.root.iterfind("Storyboard/Init/Actions/Private"):
        for fta in private.iter("FollowTrajectoryAction"):
            note(private.get("entityRef"), fta)
    for group in doc.root.iter("ManeuverGroup"):
        for ref in group.iterfind("Actors/EntityRef"):
            for fta in group.iter("FollowTrajectoryAction"):
                note(ref.get("entityRef"), fta)
    return ends


def cross_check(
    esmini: Path, xosc: str | Path, parameters: dict[str, str] | None = None, dt: float = 0.01
) -> Comparison:
    """``vei run`` and esmini on the same file and parameters; timed entities compared up to the end
    of their trajectory (what a player does afterwards is its own default behaviour)."""
    from vei_scenario.interpreter import run_scenario

    parameters = parameters or {}
    result = run_scenario(xosc, parameters, dt)
    return compare_runs(result, run_esmini(esmini, xosc, dt, parameters), recording_ends(xosc, parameters))
