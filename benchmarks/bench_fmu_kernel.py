#!/usr/bin/env python3
"""Sweep throughput with a native FMU on the ego: vei's planner built as an FMU (``vei fmu build cap``)
and plugged in with ``--controller Ego=vei_cap.fmu``, against the built-in planner, on the case study.

Three ways, the same variants (TimeShift x RiderType normal/aggressive, planner on), ``evaluate_local``
on all cores:

* ``built-in``: vei's planner in the compiled sweep kernel;
* ``FMU, kernel``: the FMU's binary stepped from the kernel, in forked children;
* ``FMU, interpreter``: the FMU stepped through fmpy in a process of its own per run, by the
  interpreter (what every plugged FMU took before; a subset, it is slow).

It also checks what the figures are of: the FMU's rows equal the built-in planner's, and the ego's and
the rider's trajectories (recorded by the kernel, both ways) agree within 1e-9 m.

    python benchmarks/bench_fmu_kernel.py           # 200 variants (20 through the interpreter)
    python benchmarks/bench_fmu_kernel.py --full    # 1 000 variants (100 through the interpreter)
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--full", action="store_true", help="1 000 variants (100 through the interpreter)")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    args = ap.parse_args()

    from vei_scenario.batch.fmu_ego import kernel_fmu
    from vei_scenario.core import fmu_ego
    from vei_scenario.fmu import build_fmus
    from vei_scenario.sut import parse_controller_options
    from vei_scenario.sweep.evaluate import _loop_batch, evaluate_local

    n_shift = 500 if args.full else 100
    with tempfile.TemporaryDirectory() as tmp:
        scenario = Path(tmp) / "case_study" / "scenario.xosc"
        subprocess.run([sys.executable, "-m", "vei_scenario", "compile", str(ROOT / "examples/case_study/clip.json"),
                        "-o", str(scenario)], check=True, capture_output=True)  # fmt: skip
        fmu = build_fmus(["cap"], Path(tmp) / "fmus")["cap"]
        s = str(scenario.resolve())
        plugged = parse_controller_options([f"Ego={fmu}"], ["cruise_speed_mps=5.61"])
        variants = [{"TimeShift": f"{-1 + 0.01 * k:.2f}", "RiderType": r, "CapEnabled": "true"}
                    for k in range(n_shift) for r in ("normal", "aggressive")]  # fmt: skip
        subset = variants[::10]

        def timed(vs, controllers=()):
            started = time.perf_counter()
            rows = evaluate_local(s, vs, 0.01, args.workers, controllers=controllers)
            return rows, time.perf_counter() - started

        evaluate_local(s, variants[:4], 0.01, 1)  # (files read, kernel loaded: not timed)
        built_in, t_built_in = timed(variants)
        kernel, t_kernel = timed(variants, plugged)
        from vei_scenario.sweep import evaluate

        chosen = evaluate._kernel_fmu
        evaluate._kernel_fmu = lambda *a: None  # (the path every plugged FMU took before)
        try:
            interp, t_interp = timed(subset, plugged)
        finally:
            evaluate._kernel_fmu = chosen

        # the trajectories, recorded by the kernel with the planner and with the FMU
        native = _loop_batch(s, 0.01)
        k = kernel_fmu(native, plugged)
        layout, values, _ = k.parameters(variants)
        prepared = native.prepare(variants)
        steps = prepared[0].n_steps
        _, ref = native.run(prepared, record=True)
        handle = fmu_ego.open_library(k.library, k.ports.fmi3)
        _, faults, got = fmu_ego.run(*prepared, handle, {**k.layout, "parameters": layout}, values, None, record=True)
        # (x, y of the ego and the rider: rows 0, 1, 5, 6)
        worst = float(np.abs(got[:, [0, 1, 5, 6]] - ref[:, [0, 1, 5, 6]]).max())

    n = len(variants)
    same = sum(a == b for a, b in zip(built_in, kernel))
    agree = sum(a == b for a, b in zip(interp, kernel[::10]))
    lines = [
        f"python benchmarks/bench_fmu_kernel.py{' --full' if args.full else ''}   ({args.workers} workers, "
        f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores)",
        f"case study, TimeShift x RiderType (normal, aggressive), planner on: {n} variants",
        f"{'engine':<32}{'variants':>9}{'s':>9}{'variants/s':>12}",
        f"{'built-in planner, kernel':<32}{n:>9}{t_built_in:>9.2f}{n / t_built_in:>12.0f}",
        f"{'vei_cap.fmu, kernel':<32}{n:>9}{t_kernel:>9.2f}{n / t_kernel:>12.0f}",
        f"{'vei_cap.fmu, interpreter':<32}{len(subset):>9}{t_interp:>9.2f}{len(subset) / t_interp:>12.1f}",
        f"FMU in the kernel: {t_built_in / t_kernel:.2f} of the built-in planner's throughput, "
        f"{(n / t_kernel) / (len(subset) / t_interp):.0f}x the interpreter path's",
        f"rows equal to the built-in planner's: {same} of {n}; kernel rows equal to the interpreter's: "
        f"{agree} of {len(subset)}; failed in the kernel: {int((faults[:, 0] != 0).sum())}",
        f"largest difference of the ego's and the rider's x, y (kernel, FMU against planner): {worst:.3g} m",
        f"the FMU beyond the built-in planner: {(t_kernel - t_built_in) * args.workers / (n * steps) * 1e6:.2f} µs "
        f"per step and core ({steps} steps a variant)",
    ]
    print("\n".join(lines))


if __name__ == "__main__":
    main()
