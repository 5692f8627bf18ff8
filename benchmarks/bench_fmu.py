#!/usr/bin/env python3
"""FMU costs: per-step cost of each native and Python FMU, and the wall time of the case study's
25 s closed loop (config 5, dt 0.01 s, 2501 steps) in each engine (issue #4 target for the native
loop through fmpy: ≤ 0.3 s).

    python benchmarks/bench_fmu.py

Python FMUs run in a child process of their own (pythonfmu instantiates a given Python FMU from one
extraction per process).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _loop(scenario: Path):
    from vei_scenario.fmu.system import closed_loop
    from vei_scenario.interpreter import load_scenario

    shift = load_scenario(scenario).parameters["ConflictTimeShift"]
    values = {"RiderType": "aggressive", "CapEnabled": "true", "TimeShift": shift}
    return values, closed_loop(scenario, values)


def measure(scenario: Path, backend: str) -> dict:
    """Per-step cost per model and closed-loop wall times for one backend (one process)."""
    from vei_scenario.fmu import MODELS, build_fmus
    from vei_scenario.fmu.cosim import FmuInstance, run_fmpy, run_libcosim
    from vei_scenario.fmu.system import write_ssp

    values, loop = _loop(scenario)
    out: dict = {"backend": backend, "per_step_us": {}, "loop_s": {}}
    with tempfile.TemporaryDirectory(prefix="vei-bench-fmu-") as tmp:
        fmus = build_fmus(list(MODELS), Path(tmp) / "fmus", backend)
        if backend == "native":  # a Python FMU may be instantiated once per process: loops only
            for m in MODELS:
                s = FmuInstance(m, fmus[m], loop.parameters[m], Path(tmp) / "step")
                n = loop.steps
                t0 = time.perf_counter()
                for k in range(n):
                    s.step(round(k * loop.dt, 9), loop.dt)
                out["per_step_us"][m] = (time.perf_counter() - t0) / n * 1e6
                s.close()
        for coupling in ("sequential", "jacobi") if backend == "native" else ("sequential",):
            t0 = time.perf_counter()
            parts: dict = {}
            run_fmpy(loop, fmus, coupling, parts)
            out["loop_s"][f"fmpy {coupling}"] = time.perf_counter() - t0
            out["loop_s"][f"  of which the 2501 steps ({coupling})"] = parts["run_s"]
        if backend == "native":
            ssp = write_ssp(loop, fmus, Path(tmp) / "loop.ssp")
            t0 = time.perf_counter()
            run_libcosim(ssp, loop)
            out["loop_s"]["libcosim jacobi"] = time.perf_counter() - t0
            from vei_scenario.interpreter import run_scenario

            t0 = time.perf_counter()
            run_scenario(scenario, values, loop.dt)
            out["loop_s"]["vei run (reference)"] = time.perf_counter() - t0
    return out


def python_per_step(scenario: Path) -> dict:
    """Per-step cost of each Python FMU, one model per child process."""
    out = {}
    for m in ("sfm", "cap", "ego"):
        r = subprocess.run(
            [sys.executable, __file__, "--python-step", m, "--scenario", str(scenario)],
            capture_output=True,
            text=True,
            check=True,
        )
        out[m] = float(r.stdout.strip().splitlines()[-1])
    return out


def _python_step(model: str, scenario: Path) -> float:
    from vei_scenario.fmu import build_fmus
    from vei_scenario.fmu.cosim import FmuInstance

    _, loop = _loop(scenario)
    with tempfile.TemporaryDirectory(prefix="vei-bench-pyfmu-") as tmp:
        fmu = build_fmus([model], Path(tmp), "python")[model]
        s = FmuInstance(model, fmu, loop.parameters[model], Path(tmp) / "x")
        t0 = time.perf_counter()
        for k in range(loop.steps):
            s.step(round(k * loop.dt, 9), loop.dt)
        return (time.perf_counter() - t0) / loop.steps * 1e6


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--python-step", help=argparse.SUPPRESS)
    ap.add_argument("--python-loop", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--scenario", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.python_step:
        print(_python_step(args.python_step, Path(args.scenario)))
        return 0
    if args.python_loop:
        print(json.dumps(measure(Path(args.scenario), "python")))
        return 0
    from vei_scenario.compiler import compile_clip

    with tempfile.TemporaryDirectory(prefix="vei-bench-fmu-") as tmp:
        scenario = Path(tmp) / "scenario.xosc"
        compile_clip(ROOT / "examples" / "case_study" / "clip.json", scenario)
        native = measure(scenario, "native")
        py = json.loads(
            subprocess.run(
                [sys.executable, __file__, "--python-loop", "--scenario", str(scenario)],
                capture_output=True,
                text=True,
                check=True,
            )
            .stdout.strip()
            .splitlines()[-1]
        )
        py["per_step_us"] = python_per_step(scenario)
    print("per-step cost of one FMU (doStep only, µs):")
    for m in ("sfm", "cap", "ego"):
        print(f"  {m:4s} native {native['per_step_us'][m]:7.2f}   python {py['per_step_us'][m]:8.1f}")
    print("closed loop, case study config 5, 2501 steps (extract + instantiate + run, s):")
    for k, v in native["loop_s"].items():
        print(f"  native {k:36s} {v:6.3f}")
    for k, v in py["loop_s"].items():
        print(f"  python {k:36s} {v:6.3f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
