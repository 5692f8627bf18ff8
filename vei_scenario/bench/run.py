"""``vei bench LIBRARY/ -o BENCH/``: vei's collision-avoidance planner over every scenario of a library.

Why: one scenario says little about a system; a dataset's worth of them, each searched around the
timing that turns its recorded interaction into a collision, says where the system fails. For every
compiled scenario of a library (``vei compile CLIPS/ -o LIBRARY/``):

* the seed paper's five configurations (:data:`vei_scenario.study.CONFIGURATIONS`: replay, normal
  and aggressive rider, the planner off and on), each at every TimeShift from the scenario's conflict
  shift minus ``half_width_s`` to plus ``half_width_s`` in steps of ``step_s`` (default ±1.5 s by
  0.01 s: 301 shifts), run through the compiled sweep kernel (the rows of ``vei run``);
* per configuration: the shifts that collide (as intervals), the worst impact speed (relative speed at
  first contact), the lowest 2-D TTC, the longest time in the TTC alert zone, the lowest safety index;
* the system under test is the planner: a scenario **fails** when a configuration with the planner on
  collides at some shift, and its worst such run is listed with the command that reproduces it.

A scenario that could not be compiled, or whose threat's path never reaches the ego's (no conflict
shift to search around), is a row with its reason.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

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
    coll = [bool(m.get("collision")) for _, m in ok]
    impacts = [m["impact_speed_mps"] for _, m in ok if m.get("collision") and m.get("impact_speed_mps") is not None]
    ttcs = [m["min_ttc_s"] for _, m in ok if m.get("min_ttc_s") is not None]
    alerts = [m["ttc_zones_s"]["alert"] for _, m in ok if m.get("ttc_zones_s")]
    safety = [m["safety_index"] for _, m in ok if m.get("safety_index") is not None]
    worst = None
    if impacts:
        s, m = max(((s, m) for s, m in ok if m.get("collision")), key=lambda sm: sm[1].get("impact_speed_mps") or 0)
        worst = {"time_shift_s": s, "impact_speed_mps": _r(m.get("impact_speed_mps"))}
    return {
        "runs": len(rows),
        "failed_runs": len(rows) - len(ok),
        "collisions": sum(coll),
        "collision_shifts_s": _intervals([s for s, _ in ok], coll, step),
        "worst_impact_speed_mps": _r(max(impacts)) if impacts else None,
        "worst_collision": worst,
        "min_ttc_s": _r(min(ttcs)) if ttcs else None,
        "max_alert_s": _r(max(alerts)) if alerts else None,
        "min_safety_index": _r(min(safety)) if safety else None,
    }


def bench_scenario(xosc: Path, centre: float, opts: BenchOptions) -> dict:
    """The configurations of one scenario over the shifts around ``centre``."""
    from vei_scenario.sweep.evaluate import evaluate_local

    values = shifts(centre, opts)
    chosen = [c for c in CONFIGURATIONS if c[0] in opts.configurations]
    variants = [{"TimeShift": repr(s), **cfg} for _, _, cfg in chosen for s in values]
    rows = evaluate_local(str(xosc), variants, opts.dt, opts.workers or os.cpu_count() or 1)
    configs = {}
    for k, (n, name, cfg) in enumerate(chosen):
        part = rows[k * len(values) : (k + 1) * len(values)]
        configs[str(n)] = {"description": name, "parameters": cfg, **_config_summary(values, part, opts.step_s)}
    return configs


def reproduce_command(xosc: str, time_shift_s: float, parameters: dict[str, str]) -> str:
    params = " ".join(f"--param {k}={v}" for k, v in [("TimeShift", repr(time_shift_s)), *parameters.items()])
    return f"vei run {xosc} {params}"


def run_bench(
    library: str | Path,
    out_dir: str | Path,
    opts: BenchOptions | None = None,
    progress: Callable[[int], None] | None = None,
) -> dict:
    """Bench every scenario of ``library``; writes bench.json, report.html and junit.xml into
    ``out_dir`` and returns the bench document."""
    from vei_scenario.atomic_io import OutputSet
    from vei_scenario.bench.outputs import bench_html, junit_xml

    opts = opts or BenchOptions()
    opts.check()
    library, out_dir = Path(library), Path(out_dir)
    index = library / "library.json"
    if not index.is_file():
        raise VeiInputError(library, "", "no library.json: make the library with vei compile CLIPS/ -o LIBRARY/")
    try:
        lib = json.loads(index.read_text("utf-8"))
        entries = lib["scenarios"]
        assert isinstance(entries, list)
    except (ValueError, KeyError, TypeError, AssertionError):
        raise VeiInputError(index, "", "not a vei scenario library index") from None
    results = []
    for e in entries:
        row = {"file": e.get("file"), "rank": e.get("rank")}
        if e.get("status") != "ok":
            row.update(status="error", error=f"not compiled: {e.get('error')}")
        elif e.get("conflict_time_shift_s") is None:
            row.update(status="skipped", error="the threat's path does not reach the ego's: no conflict to search")
        else:
            xosc = library / e["outputs"]["scenario"]
            try:
                configs = bench_scenario(xosc, float(e["conflict_time_shift_s"]), opts)
            except VeiInputError as exc:
                row.update(status="error", error=" ".join(str(exc).split()))
            else:
                sut = [(n, configs[str(n)]) for n in SUT_CONFIGS if str(n) in configs]
                failing = [(n, c) for n, c in sut if c["collisions"]]
                row.update(
                    status="ok",
                    scenario=e["outputs"]["scenario"],
                    threat=e.get("threat"),
                    conflict_time_shift_s=e["conflict_time_shift_s"],
                    fails=bool(failing),
                    configurations=configs,
                )
                if failing:
                    n, c = max(failing, key=lambda nc: nc[1]["worst_impact_speed_mps"] or 0.0)
                    w = c["worst_collision"]
                    row["worst_failure"] = {
                        "configuration": n,
                        **w,
                        "reproduce": reproduce_command(str(xosc), w["time_shift_s"], c["parameters"]),
                    }
        results.append(row)
        if progress:
            progress(1)
    benched = [r for r in results if r["status"] == "ok"]
    fails = [r for r in benched if r["fails"]]
    doc = {
        "format": "vei-bench/1",
        "library": str(library),
        "system_under_test": "vei's collision-avoidance planner (CapEnabled=true)",
        "sut_configurations": [n for n in SUT_CONFIGS if n in opts.configurations],
        "configurations": list(opts.configurations),
        "time_shift_search": {"half_width_s": opts.half_width_s, "step_s": opts.step_s, "dt_s": opts.dt},
        "scenarios": len(results),
        "benched": len(benched),
        "failing": len(fails),
        "failure_share": _r(len(fails) / len(benched), 4) if benched else None,
        "worst": sorted(
            ({"file": r["file"], **r["worst_failure"]} for r in fails),
            key=lambda w: (-(w["impact_speed_mps"] or 0.0), w["file"]),
        )[:10],
        "results": results,
    }
    outputs = OutputSet()
    outputs.add(out_dir / "bench.json", json.dumps(doc, indent=1, allow_nan=False) + "\n")
    outputs.add(out_dir / "report.html", bench_html(doc))
    outputs.add(out_dir / "junit.xml", junit_xml(doc))
    outputs.commit()
    return doc
