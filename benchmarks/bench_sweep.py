#!/usr/bin/env python3
"""Sweep throughput (issues #5, #12): 10 000 variants of the case-study scenario (25 s at dt 0.01 s, run +
every metric of ``vei run``) through ``vei sweep``'s local executor on all cores, against serial
``vei run`` calls extrapolated from a sample. Target: ≤ 10 s wall, ≤ 2 GB peak memory.

    python benchmarks/bench_sweep.py [--variants N] [--serial-sample N] [--full]

``--full`` also times the whole ``vei sweep`` (catalog.csv/json and report.html written), in this
process and as a command in a new process (``--repeat`` runs; start-up included).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # as the vei command line does

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--variants", type=int, default=10_000)
    ap.add_argument("--serial-sample", type=int, default=16)
    ap.add_argument("--full", action="store_true")
    ap.add_argument("--repeat", type=int, default=5, help="runs of the whole command (with --full)")
    ap.add_argument("--esmini-sample", type=int, default=8, help="esmini runs timed (0: none)")
    args = ap.parse_args()
    from vei_scenario.compiler import compile_clip
    from vei_scenario.conformance.esmini import find_esmini, run_esmini
    from vei_scenario.sweep import build_variants, run_sweep
    from vei_scenario.sweep.evaluate import _native_engine, evaluate_local, evaluate_variant

    with tempfile.TemporaryDirectory(prefix="vei-bench-sweep-") as tmp:
        xosc = Path(tmp) / "scenario.xosc"
        compile_clip(ROOT / "examples" / "case_study" / "clip.json", xosc)
        per_shift = -(-args.variants // 6) + 1
        vary = [
            f"TimeShift=-3:3:{6 / max(1, per_shift - 1):.9f}",
            "RiderType=normal,aggressive,replay",
            "CapEnabled=true,false",
        ]
        t0 = time.perf_counter()
        variants, _ = build_variants(xosc, vary, None, None)
        variants = variants[: args.variants]
        t_build = time.perf_counter() - t0
        engine = "sweep kernel" if _native_engine(str(xosc), 0.01) is not None else "interpreter"
        t0 = time.perf_counter()
        rows = evaluate_local(str(xosc), variants, 0.01)
        t_eval = time.perf_counter() - t0
        assert all(r["status"] == "ok" for r in rows)
        n_serial = min(args.serial_sample, len(variants))
        step = max(1, len(variants) // n_serial)
        t0 = time.perf_counter()
        for v in variants[::step][:n_serial]:
            evaluate_variant(str(xosc), v, 0.01)
        serial = (time.perf_counter() - t0) / n_serial
        # esmini on the same scenario, one process per variant (its library is not built here): the
        # replay variants without the planner, the ones it can play (vei's controllers are its own)
        es_times: list[float] = []
        esmini = find_esmini(str(ROOT.parent / "shared" / "esmini" / "bin" / "esmini"))
        if esmini is not None:
            plain = [v for v in variants if v.get("RiderType") == "replay" and v.get("CapEnabled") == "false"]
            for v in plain[:: max(1, len(plain) // args.esmini_sample)][: args.esmini_sample]:
                es_times.append(run_esmini(esmini, xosc, 0.01, v).seconds)
        t_full = None
        cli: list[tuple[float, float]] = []
        if args.full:
            t0 = time.perf_counter()
            run_sweep(xosc, Path(tmp) / "catalog", vary, quiet=True)
            t_full = time.perf_counter() - t0
            # as a user runs it: a new process, start-up and imports included (wall, CPU of all processes)
            cmd = [sys.executable, "-m", "vei_scenario.cli", "sweep", str(xosc), "-o", str(Path(tmp) / "cli")]
            cmd += [a for v in vary for a in ("--vary", v)] + ["--quiet"]
            for _ in range(args.repeat):
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                t0 = time.perf_counter()
                subprocess.run(cmd, check=True, capture_output=True)
                wall = time.perf_counter() - t0
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
                cli.append((wall, cpu))
    peak = max(
        resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    )
    n = len(variants)
    collisions = sum(1 for r in rows if r["metrics"]["collision"])
    print(f"{os.cpu_count()} cores; case study, 25 s at dt 0.01 s per variant, all metrics; {engine}")
    print(
        f"{n} variants ({collisions} collide): built in {t_build:.2f} s, evaluated in {t_eval:.2f} s "
        f"= {n / t_eval:.0f} variants/s (target ≤ 10 s for 10 000)"
    )
    steps = 2501  # 25 s at 0.01 s
    print(f"{n * steps / t_eval / 1e6:.1f} M variant-steps/s ({steps} steps a variant)")
    if es_times:
        es = sorted(es_times)[len(es_times) // 2]
        print(
            f"esmini 3.6, one process a variant (replay, no planner; median of {len(es_times)}): {es:.3f} s "
            f"= {1 / es:.1f} variants/s; the vei sweep is {es / (t_eval / n):.0f}x faster a variant "
            f"(esmini's library, for many variants in one process, is not built here)"
        )
    print(
        f"serial vei-run path: {serial:.3f} s per variant; {n} extrapolated: {n * serial:.0f} s; "
        f"sweep/serial speed-up {n * serial / t_eval:.0f}x"
    )
    if t_full is not None:
        print(f"whole vei sweep in this process (variants, evaluation, catalog.csv/json, report.html): {t_full:.2f} s")
    if cli:
        walls = sorted(w for w, _ in cli)
        cpus = sorted(c for _, c in cli)
        print(
            f"whole `vei sweep` command, new process (start-up included), {len(cli)} runs: "
            f"median {walls[len(walls) // 2]:.2f} s (min {walls[0]:.2f}, max {walls[-1]:.2f}; target ≤ 2 s), "
            f"CPU {cpus[len(cpus) // 2]:.2f} s of both cores"
        )
    print(f"peak resident memory: {peak / 1024:.0f} MiB (target ≤ 2048 MiB)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
