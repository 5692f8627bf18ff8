#!/usr/bin/env python3
"""Sweep throughput: a sample of case-study variants through ``vei sweep``'s local executor (all
cores, batch engine) and serially through ``vei run``'s path, extrapolated to a 10 000-variant catalog
(issue #5 target: ≤ 10 s, ≤ 2 GB).

    python benchmarks/bench_sweep.py [--sample N]
"""

from __future__ import annotations

import argparse
import os
import resource
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sample", type=int, default=64)
    args = ap.parse_args()
    from vei_scenario.compiler import compile_clip
    from vei_scenario.sweep import build_variants
    from vei_scenario.sweep.evaluate import evaluate_local, evaluate_variant

    with tempfile.TemporaryDirectory(prefix="vei-bench-sweep-") as tmp:
        xosc = Path(tmp) / "scenario.xosc"
        compile_clip(ROOT / "examples" / "case_study" / "clip.json", xosc)
        step = 6.0 / max(1, args.sample // 4 - 1)
        variants, _ = build_variants(
            xosc, [f"TimeShift=-1:5:{step:.6f}", "RiderType=normal,aggressive", "CapEnabled=true,false"], None, None
        )
        variants = variants[: args.sample]
        n = len(variants)
        t0 = time.perf_counter()
        evaluate_local(str(xosc), variants, 0.01)
        parallel = time.perf_counter() - t0
        serial_n = min(n, 16)
        t0 = time.perf_counter()
        for v in variants[:serial_n]:
            evaluate_variant(str(xosc), v, 0.01)
        serial = (time.perf_counter() - t0) / serial_n
    peak = max(
        resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    )
    print(f"{os.cpu_count()} cores; case study, 25 s at dt 0.01 s per variant (run + all metrics)")
    print(
        f"local executor: {n} variants in {parallel:.2f} s = {n / parallel:.1f} variants/s; "
        f"10 000 variants extrapolated: {10_000 / (n / parallel):.0f} s (target ≤ 10 s)"
    )
    print(
        f"serial vei-run path: {serial:.3f} s per variant; 10 000 extrapolated: {10_000 * serial:.0f} s; "
        f"parallel/serial speed-up {serial * n / parallel:.2f}x"
    )
    print(f"peak resident memory of one process: {peak / 1024:.0f} MiB")
    print(
        "vei-compiled scenarios run through the batch engine (numpy): per variant and core ~9 ms of simulation "
        "and ~9 ms of metrics (box distances, 2-D TTC, PET) keep the 10 s target out of reach"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
