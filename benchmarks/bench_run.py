#!/usr/bin/env python3
"""Run time of the built-in interpreter and of the five-configuration study.

Prints: start-up (imports), one 25 s case-study run at dt 0.01 s (best and median of N, after
start-up; target ≤ 0.3 s), the same with metrics, and the whole ``vei study`` (compile + 5 runs +
plots) as a user runs it.

    python benchmarks/bench_run.py [--repeat N]
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    t0 = time.perf_counter()
    from vei_scenario.compiler import compile_clip
    from vei_scenario.interpreter import run_scenario
    from vei_scenario.metrics import PairSeries, compute_metrics

    startup = time.perf_counter() - t0
    with tempfile.TemporaryDirectory(prefix="vei-bench-run-") as tmp:
        xosc = Path(tmp) / "scenario.xosc"
        result = compile_clip(ROOT / "examples" / "case_study" / "clip.json", xosc)
        shift = repr(result.model.conflicts[result.model.threat].time_shift_s)
        print(f"python {sys.version.split()[0]}; imports {startup:.2f} s")
        for label, params in [
            ("replay, no CAP", {"TimeShift": shift}),
            ("aggressive SFM + CAP", {"TimeShift": shift, "RiderType": "aggressive", "CapEnabled": "true"}),
        ]:
            runs, with_metrics = [], []
            for _ in range(args.repeat):
                a = time.perf_counter()
                r = run_scenario(xosc, params, 0.01)
                b = time.perf_counter()
                compute_metrics(PairSeries.from_run(r))
                c = time.perf_counter()
                runs.append(b - a)
                with_metrics.append(c - a)
            print(
                f"25 s run at dt 0.01 ({len(r.t)} steps), {label:<22}: best {min(runs):.3f} s, "
                f"median {statistics.median(runs):.3f} s (target ≤ 0.3 s); with metrics "
                f"{statistics.median(with_metrics):.3f} s"
            )
        a = time.perf_counter()
        proc = subprocess.run(
            [
                sys.executable,
                "-m",
                "vei_scenario.cli",
                "study",
                str(ROOT / "examples" / "case_study" / "clip.json"),
                "-o",
                str(Path(tmp) / "study"),
            ],
            capture_output=True,
            text=True,
        )
        wall = time.perf_counter() - a
        if proc.returncode != 0:
            raise SystemExit(proc.stderr)
        print(f"vei study examples/case_study/clip.json (compile + 5 runs + plots, new process): {wall:.2f} s")
        # one whole `vei run --no-plots` process against esmini playing the same variant (issue #12)
        values = {"TimeShift": shift, "RiderType": "aggressive", "CapEnabled": "true"}
        params = [a for k, v in values.items() for a in ("--param", f"{k}={v}")]
        vei = [sys.executable, "-m", "vei_scenario.cli", "run", str(xosc), "--no-plots", "-o", str(Path(tmp) / "r")]
        vei_times = [_wall(vei + params) for _ in range(args.repeat)]
        line = f"whole `vei run --no-plots` process, aggressive SFM + CAP: median {statistics.median(vei_times):.3f} s"
        from vei_scenario.conformance.esmini import find_esmini, run_esmini

        esmini = find_esmini(str(ROOT.parent / "shared" / "esmini" / "bin" / "esmini"))
        if esmini is not None:  # its process only (the variant's file is written beforehand)
            es = statistics.median(run_esmini(esmini, xosc, 0.01, values).seconds for _ in range(args.repeat))
            line += f"; esmini 3.6 on the same variant {es:.3f} s ({statistics.median(vei_times) / es:.1f}x)"
        print(line + " (target: no slower than esmini)")
    return 0


def _wall(cmd: list[str]) -> float:
    a = time.perf_counter()
    subprocess.run(cmd, check=True, capture_output=True)
    return time.perf_counter() - a
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
