#!/usr/bin/env python3
"""vei's rider and planner as OSMP participants (``vei fmu build sfm cap --osmp``), hosted back in
``vei run``: the largest position difference to the built-in models and what a step costs.

Each hosted run is a process of its own (a pythonfmu FMU can be instantiated once per process). Per
run: the largest distance between any entity's position with and without the FMUs, the run's wall
time per step with the FMUs and without, and the time inside the FMUs' ``fmi2DoStep`` per step (best
of ``--repeat`` runs of the hosted scenario in that process, the first run for the pythonfmu FMUs).

    python benchmarks/bench_osmp_models.py [--backend native|python] [--full]

Default: the case study's configuration 5 (aggressive rider, planner on) with both FMUs plugged;
``--full``: the study's five configurations with the rider, the planner and both, and multi_scooter.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

_ONE = r"""
import json, os, sys, time, timeit
from pathlib import Path
import numpy as np
from vei_scenario.fmu.osmp_rider import build_osmp
from vei_scenario.interpreter import run_scenario
from vei_scenario.sut import parse_controller_options
from vei_scenario.sut import osmp as host
scenario, plugs, out, values, backend, repeat = sys.argv[1], json.loads(sys.argv[2]), Path(sys.argv[3]), \
    json.loads(sys.argv[4]), sys.argv[5], int(sys.argv[6])
options = [f"{e}={build_osmp(m, scenario, out, values, backend=backend)}" for e, m in plugs.items()]
spent = [0.0]
step = host.OsmpParticipant.step
def timed(self, *a, **k):  # (fmi2DoStep alone: the FMU's own work, not the host's messages)
    do = self.fmu.doStep
    def do_timed(*x, **y):
        t0 = time.perf_counter(); r = do(*x, **y); spent[0] += time.perf_counter() - t0; return r
    self.fmu.doStep = do_timed
    try:
        return step(self, *a, **k)
    finally:
        self.fmu.doStep = do
host.OsmpParticipant.step = timed
t_ref = min(timeit.repeat(lambda: run_scenario(scenario, values), number=1, repeat=repeat))
once = backend == "python"
runs = []
for _ in range(1 if once else repeat):
    spent[0] = 0.0
    t0 = time.perf_counter()
    b = run_scenario(scenario, values, controllers=parse_controller_options(options))
    runs.append((time.perf_counter() - t0, spent[0]))
a = run_scenario(scenario, values)
steps = len(a.traces[next(iter(a.traces))].x) - 1
d = max(float(np.max(np.hypot(a.traces[n].x - b.traces[n].x, a.traces[n].y - b.traces[n].y))) for n in a.traces)
wall, fmu = min(runs)
print(json.dumps({"deviation_m": d, "steps": steps, "run_us": 1e6 * wall / steps, "builtin_us": 1e6 * t_ref / steps,
                  "dostep_us": 1e6 * fmu / steps / len(plugs)}), flush=True)
os._exit(0)
"""

PLUGS = {"rider": {"scooter_1": "sfm"}, "planner": {"Ego": "cap"}, "both": {"Ego": "cap", "scooter_1": "sfm"}}
CONFIGS = {1: ("replay", "false"), 2: ("normal", "false"), 3: ("aggressive", "false"), 4: ("normal", "true"),
           5: ("aggressive", "true")}  # fmt: skip


def one(scenario: Path, plugs: dict, values: dict, backend: str, repeat: int) -> dict:
    with tempfile.TemporaryDirectory(prefix="vei-bench-osmp-") as tmp:
        argv = [sys.executable, "-c", _ONE, str(scenario), json.dumps(plugs), tmp, json.dumps(values), backend,
                str(repeat)]  # fmt: skip
        done = subprocess.run(argv, capture_output=True, text=True, timeout=900)
    if done.returncode != 0:
        raise SystemExit(done.stderr[-2000:])
    return json.loads(done.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--backend", choices=("native", "python"), default="native")
    ap.add_argument("--full", action="store_true", help="five configurations x three plugs, and multi_scooter")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    from vei_scenario.compiler import compile_clip

    with tempfile.TemporaryDirectory(prefix="vei-bench-osmp-") as tmp:
        cs, ms = Path(tmp) / "cs" / "scenario.xosc", Path(tmp) / "ms" / "scenario.xosc"
        compile_clip(ROOT / "examples/case_study/clip.json", cs)
        cases = [(cs, "both", 5, {"RiderType": "aggressive", "CapEnabled": "true", "TimeShift": "2.197"})]
        if args.full:
            cases = [(cs, p, n, {"RiderType": r, "CapEnabled": c, "TimeShift": "2.197"})
                     for n, (r, c) in CONFIGS.items() for p in PLUGS]  # fmt: skip
            compile_clip(ROOT / "examples/multi_scooter/clip.json", ms)
            cases.append((ms, "multi", 0, {"RiderType": "normal", "CapEnabled": "true", "TimeShift": "1.41"}))
        print(f"backend {args.backend}")
        print(f"{'scenario':<12} {'cfg':>3} {'plugged':<8} {'deviation m':>12} {'run us/step':>12} "
              f"{'built-in':>9} {'doStep us':>10}")  # fmt: skip
        worst = 0.0
        for scenario, plug, n, values in cases:
            plugs = {"Ego": "cap", "scooter_2": "sfm"} if plug == "multi" else PLUGS[plug]
            got = one(scenario, plugs, values, args.backend, args.repeat)
            worst = max(worst, got["deviation_m"])
            name = scenario.parent.name.replace("cs", "case_study").replace("ms", "multi_scooter")
            print(f"{name:<12} {n:>3} {plug:<8} {got['deviation_m']:>12.3g} {got['run_us']:>12.1f} "
                  f"{got['builtin_us']:>9.1f} {got['dostep_us']:>10.1f}", flush=True)  # fmt: skip
        print(f"largest deviation {worst:.3g} m over {len(cases)} runs")


if __name__ == "__main__":
    main()
