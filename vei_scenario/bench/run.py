"""``vei bench LIBRARY/ -o BENCH/``: a system under test over every scenario of a library: vei's
collision-avoidance planner, or the user's own controller on the ego (``--controller``).

Why: one scenario says little about a system; a dataset's worth of them, each searched around the
timing that turns its recorded interaction into a collision, says where the system fails. For every
compiled scenario of a library (``vei compile CLIPS/ -o LIBRARY/``):

* the seed paper's five configurations (:data:`vei_scenario.study.CONFIGURATIONS`: replay, normal
  and aggressive rider, the planner off and on), each at every TimeShift from the scenario's conflict
  shift minus ``half_width_s`` to plus ``half_width_s`` in steps of ``step_s`` (default ±1.5 s by
  0.01 s: 301 shifts), run through the compiled sweep kernel (the rows of ``vei run``);
* per configuration: the shifts that collide (as intervals), the worst impact speed (relative speed at
  first contact), the lowest 2-D TTC, the longest time in the TTC alert zone, the lowest safety index;
* the system under test drives the ego in the configurations with the planner on (4 and 5): vei's
  planner through the kernel, or the user's controller (:mod:`vei_scenario.bench.systems`) through the
  interpreter, the path a sweep takes for a plugged controller; configurations 1-3 are the scenario
  without any system and run through the kernel either way;
* a scenario **fails** when, in a configuration with the system on, the ego collides while moving
  (``collision_ego_moving``: a road user running into the standing ego is no failure of the system)
  or a run fails (the user's code raised); its worst failure (the highest ego speed at contact) is
  listed with the command that reproduces it, ``--controller`` included.

A scenario that could not be compiled, or whose threat's path never reaches the ego's (no conflict
shift to search around), is a row with its reason.
"""

from __future__ import annotations

import json
import math
import os
import shlex
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, replace
from pathlib import Path

from vei_scenario.bench.systems import PLANNER, System
from vei_scenario.errors import VeiInputError
from vei_scenario.study import CONFIGURATIONS

#: Configurations with the system under test (the planner) switched on.
SUT_CONFIGS = tuple(n for n, _, values in CONFIGURATIONS if values["CapEnabled"] == "true")


@dataclass(frozen=True)
class BenchOptions:
    half_width_s: float = 1.5
    step_s: float = 0.01
    dt: float = 0.01
    workers: int | None = None
    #: the configurations to run, by number (1-5); a scenario fails when one with the planner on collides
    configurations: tuple[int, ...] = tuple(n for n, _, _ in CONFIGURATIONS)

    def check(self) -> None:
        known = {n for n, _, _ in CONFIGURATIONS}
        if not self.configurations or not set(self.configurations) <= known:
            raise VeiInputError(None, "--configurations", f"{self.configurations!r}: choose among 1-5")
        if not set(self.configurations) & set(SUT_CONFIGS):
            raise VeiInputError(None, "--configurations", "none has the planner on (4 or 5): nothing to test")
        if not (math.isfinite(self.half_width_s) and 0 <= self.half_width_s <= 30):
            raise VeiInputError(None, "--half-width", f"{self.half_width_s!r} is outside 0..30 s")
        if not (math.isfinite(self.step_s) and 0.001 <= self.step_s <= 10):
            raise VeiInputError(None, "--step", f"{self.step_s!r} is outside 0.001..10 s")


def shifts(centre: float, opts: BenchOptions) -> list[float]:
    n = int(round(opts.half_width_s / opts.step_s))
    return [round(centre + k * opts.step_s, 6) + 0.0 for k in range(-n, n + 1)]


def _intervals(values: list[float], hit: list[bool], step: float) -> list[list[float]]:
    out: list[list[float]] = []
    for v, h in zip(values, hit):
        if not h:
            continue
        if out and v - out[-1][1] <= step * 1.5:
            out[-1][1] = v
        else:
            out.append([v, v])
    return out


def _r(v, nd: int = 3):
    return None if v is None or not math.isfinite(v) else round(float(v), nd) + 0.0


def _config_summary(values: list[float], rows: list[dict], step: float) -> dict:
    ok = [(s, r["metrics"]) for s, r in zip(values, rows) if r["status"] == "ok"]
    errors = [(s, r["error"]) for s, r in zip(values, rows) if r["status"] != "ok"]
    coll = [bool(m.get("collision")) for _, m in ok]
    moving = [bool(m.get("collision_ego_moving")) for _, m in ok]
    ego_speeds = [m["ego_speed_at_contact_mps"] for _, m in ok if m.get("collision_ego_moving")]
    impacts = [m["impact_speed_mps"] for _, m in ok if m.get("collision") and m.get("impact_speed_mps") is not None]
    ttcs = [m["min_ttc_s"] for _, m in ok if m.get("min_ttc_s") is not None]
    alerts = [m["ttc_zones_s"]["alert"] for _, m in ok if m.get("ttc_zones_s")]
    safety = [m["safety_index"] for _, m in ok if m.get("safety_index") is not None]
    worst = None
    if impacts:
        s, m = max(((s, m) for s, m in ok if m.get("collision")), key=lambda sm: sm[1].get("impact_speed_mps") or 0)
        worst = {"time_shift_s": s, "impact_speed_mps": _r(m.get("impact_speed_mps"))}
    worst_moving = None
    if ego_speeds:
        s, m = max(
            ((s, m) for s, m in ok if m.get("collision_ego_moving")), key=lambda sm: sm[1]["ego_speed_at_contact_mps"]
        )
        worst_moving = {
            "time_shift_s": s,
            "ego_speed_at_contact_mps": _r(m["ego_speed_at_contact_mps"]),
            "impact_speed_mps": _r(m.get("impact_speed_mps")),
        }
    return {
        "runs": len(rows),
        "failed_runs": len(errors),
        **({"first_error": {"time_shift_s": errors[0][0], "error": " ".join(errors[0][1].split())}} if errors else {}),
        "collisions": sum(coll),
        "collision_shifts_s": _intervals([s for s, _ in ok], coll, step),
        "collisions_ego_moving": sum(moving),
        "ego_moving_collision_shifts_s": _intervals([s for s, _ in ok], moving, step),
        "worst_impact_speed_mps": _r(max(impacts)) if impacts else None,
        "worst_ego_speed_at_contact_mps": _r(max(ego_speeds)) if ego_speeds else None,
        "worst_collision": worst,
        "worst_ego_moving_collision": worst_moving,
        "min_ttc_s": _r(min(ttcs)) if ttcs else None,
        "max_alert_s": _r(max(alerts)) if alerts else None,
        "min_safety_index": _r(min(safety)) if safety else None,
    }


def bench_scenario(xosc: Path, centre: float, opts: BenchOptions, controllers: tuple = ()) -> dict:
    """The configurations of one scenario over the shifts around ``centre``; ``controllers``: the
    user's system, driving the ego in the configurations with the planner on (through the
    interpreter); the others, and all of them for vei's planner, through the compiled kernel."""
    from vei_scenario.sweep.evaluate import evaluate_local, release_native

    values = shifts(centre, opts)
    workers = opts.workers or os.cpu_count() or 1
    chosen = [c for c in CONFIGURATIONS if c[0] in opts.configurations]
    plugged = [c for c in chosen if controllers and c[0] in SUT_CONFIGS]
    kernel = [c for c in chosen if c not in plugged]
    rows_of: dict[int, list[dict]] = {}
    try:
        for group, sut in ((kernel, ()), (plugged, controllers)):
            if not group:
                continue
            variants = [{"TimeShift": repr(s), **cfg} for _, _, cfg in group for s in values]
            rows = evaluate_local(str(xosc), variants, opts.dt, workers, controllers=sut)
            for k, (n, _, _) in enumerate(group):
                rows_of[n] = rows[k * len(values) : (k + 1) * len(values)]
    finally:
        release_native(str(xosc), opts.dt)  # (a library's scenes would add up: each is run once)
    return {
        str(n): {"description": name, "parameters": cfg, **_config_summary(values, rows_of[n], opts.step_s)}
        for n, name, cfg in chosen
    }


def reproduce_command(xosc: str, time_shift_s: float, parameters: dict[str, str], controllers: tuple = ()) -> str:
    """The ``vei run`` that plays one run again, with the system under test plugged in as it was."""
    from vei_scenario.sut import reproduce_options, sut_document

    params = " ".join(f"--param {k}={v}" for k, v in [("TimeShift", repr(time_shift_s)), *parameters.items()])
    sut = reproduce_options(sut_document(controllers)) if controllers else ""
    return f"vei run {shlex.quote(xosc)} {params}{sut}"


def read_library(library: str | Path) -> list[dict]:
    """The scenario entries of ``library``'s index, or one line saying why it is not a library."""
    index = Path(library) / "library.json"
    if not index.is_file():
        raise VeiInputError(library, "", "no library.json: make the library with vei compile CLIPS/ -o LIBRARY/")
    try:
        entries = json.loads(index.read_text("utf-8"))["scenarios"]
        assert isinstance(entries, list) and all(isinstance(e, dict) for e in entries)
    except (ValueError, KeyError, TypeError, AssertionError):
        raise VeiInputError(index, "", "not a vei scenario library index") from None
    return entries


def _failure(n: int, c: dict) -> tuple:
    """How bad a failing configuration is: the highest ego speed at contact, then a failed run."""
    return (c["worst_ego_speed_at_contact_mps"] or 0.0, c["failed_runs"], -n)


def with_system(sut: list[tuple[int, dict]]) -> dict:
    """The scenario with the system on (configurations 4 and 5 together): does the ego collide while
    moving, at which shifts, the worst ego speed at contact, the lowest TTC, the longest alert time."""

    def pick(key: str, fn):
        found = [c[key] for _, c in sut if c[key] is not None]
        return fn(found) if found else None

    return {
        "collides_ego_moving": any(c["collisions_ego_moving"] for _, c in sut),
        "ego_moving_collision_shifts_s": {str(n): c["ego_moving_collision_shifts_s"] for n, c in sut},
        "worst_ego_speed_at_contact_mps": pick("worst_ego_speed_at_contact_mps", max),
        "min_ttc_s": pick("min_ttc_s", min),
        "max_alert_s": pick("max_alert_s", max),
        "failed_runs": sum(c["failed_runs"] for _, c in sut),
    }


def plug_error(xosc: Path, opts: BenchOptions, controllers: tuple) -> str | None:
    """Why the user's system cannot be set up in this scenario (an entity it does not have, a property
    the constructor refuses), in one line, or None: a setup fault is no failure of the system."""
    from vei_scenario.sweep.preflight import _build_error

    if not controllers:
        return None
    cfg = next(cfg for n, _, cfg in CONFIGURATIONS if n in SUT_CONFIGS and n in opts.configurations)
    found = _build_error(xosc, dict(cfg), opts.dt, controllers)
    return " ".join(found.split()) if found else None


def bench_entry(library: Path, e: dict, opts: BenchOptions, system: System) -> dict:
    """The row of one library entry: its configurations, whether the system fails it, its worst failure."""
    row = {"file": e.get("file"), "rank": e.get("rank")}
    if e.get("status") != "ok":
        return {**row, "status": "error", "error": f"not compiled: {e.get('error')}"}
    if e.get("conflict_time_shift_s") is None:
        return {
            **row,
            "status": "skipped",
            "error": "the threat's path does not reach the ego's: no conflict to search",
        }
    xosc = library / e["outputs"]["scenario"]
    plug = plug_error(xosc, opts, system.controllers)
    if plug:
        return {**row, "status": "error", "error": f"the system cannot be set up: {plug}", "setup": True}
    try:
        configs = bench_scenario(xosc, float(e["conflict_time_shift_s"]), opts, system.controllers)
    except VeiInputError as exc:
        return {**row, "status": "error", "error": " ".join(str(exc).split())}
    sut = [(n, configs[str(n)]) for n in SUT_CONFIGS if str(n) in configs]
    failing = [(n, c) for n, c in sut if c["collisions_ego_moving"] or c["failed_runs"]]
    row["with_system"] = with_system(sut)
    row.update(
        status="ok",
        scenario=e["outputs"]["scenario"],
        threat=e.get("threat"),
        conflict_time_shift_s=e["conflict_time_shift_s"],
        fails=bool(failing),
        configurations=configs,
    )
    if failing:
        n, c = max(failing, key=lambda nc: _failure(*nc))
        w = c["worst_ego_moving_collision"]
        if w is None:  # (no collision: a run failed, the first one is reproduced)
            w = {**c["first_error"], "ego_speed_at_contact_mps": None, "impact_speed_mps": None}
        row["worst_failure"] = {
            "configuration": n,
            **w,
            "reproduce": reproduce_command(str(xosc), w["time_shift_s"], c["parameters"], system.controllers),
        }
    return row


def bench_entries(library: Path, entries: list[dict], opts: BenchOptions, system: System) -> Iterator[dict]:
    """The rows of ``entries`` in their order. vei's planner: the scenarios the kernel runs side by
    side on ``workers`` threads, each scenario's runs on one thread. The kernel releases the GIL, so
    one thread's Python (reading a scenario, summarising its rows) overlaps the other's kernel runs,
    and no core idles at the end of a scenario waiting for its last batch of runs (a scenario's 1 505
    runs are batches of 500, 500, 500 and 5: on 2 threads the third ran alone, a quarter of a
    scenario's time). A scenario the kernel cannot run, and every scenario of a plugged system, runs
    in the interpreter: scenario after scenario, each on all workers (forked processes)."""
    from vei_scenario.sweep.evaluate import runs_in_kernel

    workers = opts.workers or os.cpu_count() or 1
    if system.controllers or workers == 1 or len(entries) < 2:
        yield from (bench_entry(library, e, opts, system) for e in entries)
        return
    one = replace(opts, workers=1)

    def side_by_side(e: dict) -> dict | None:
        searched = e.get("status") == "ok" and e.get("conflict_time_shift_s") is not None
        if searched and not runs_in_kernel(str(library / e["outputs"]["scenario"]), opts.dt):
            return None  # (for the interpreter, below)
        return bench_entry(library, e, one, system)

    with ThreadPoolExecutor(max_workers=workers) as pool:
        for e, row in zip(entries, pool.map(side_by_side, entries)):
            yield row if row is not None else bench_entry(library, e, opts, system)


def run_bench(
    library: str | Path,
    out_dir: str | Path,
    opts: BenchOptions | None = None,
    progress: Callable[[int], None] | None = None,
    system: System | None = None,
) -> dict:
    """Bench ``system`` (default vei's planner) on every scenario of ``library``; writes bench.json,
    report.html and junit.xml into ``out_dir`` and returns the bench document."""
    from vei_scenario.atomic_io import OutputSet
    from vei_scenario.bench.outputs import bench_html, junit_xml

    opts = opts or BenchOptions()
    opts.check()
    system = system or System(PLANNER)
    library, out_dir = Path(library), Path(out_dir)
    entries = read_library(library)
    results = []
    for row in bench_entries(library, entries, opts, system):
        results.append(row)
        if progress:
            progress(1)
    setup = [r for r in results if r.pop("setup", False)]
    tried = [r for r in results if r["status"] != "skipped" and not r.get("error", "").startswith("not compiled")]
    if setup and len(setup) == len(tried):
        raise VeiInputError(None, "--controller", f"{setup[0]['error']} (in every scenario of {library})")
    benched = [r for r in results if r["status"] == "ok"]
    fails = [r for r in benched if r["fails"]]
    doc = {
        "format": "vei-bench/1",
        "library": str(library),
        "system_under_test": system.name(),
        "system": system.describe(),
        "sut_configurations": [n for n in SUT_CONFIGS if n in opts.configurations],
        "configurations": list(opts.configurations),
        "time_shift_search": {"half_width_s": opts.half_width_s, "step_s": opts.step_s, "dt_s": opts.dt},
        "scenarios": len(results),
        "benched": len(benched),
        "failing": len(fails),
        "failure_share": _r(len(fails) / len(benched), 4) if benched else None,
        "worst": sorted(
            ({"file": r["file"], **r["worst_failure"]} for r in fails),
            key=lambda w: (-(w["ego_speed_at_contact_mps"] or 0.0), w["file"]),
        )[:10],
        "results": results,
    }
    outputs = OutputSet()
    outputs.add(out_dir / "bench.json", json.dumps(doc, indent=1, allow_nan=False) + "\n")
    outputs.add(out_dir / "report.html", bench_html(doc))
    outputs.add(out_dir / "junit.xml", junit_xml(doc))
    outputs.commit()
    return doc
