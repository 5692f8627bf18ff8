#!/usr/bin/env python3
"""What an ASAM OSI ground-truth trace adds to ``vei run``.

Times whole ``vei run`` processes on the case study (aggressive rider, planner on, 25 s at 100 Hz) in
new processes, median of N: with plots (the default) and with ``--no-plots``, each without a trace and
with ``--osi trace.mcap`` / ``trace.osi``. Target: a trace adds ≤ 20 % to ``vei run``'s time.

    python benchmarks/bench_osi.py [--repeat N]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: as a user's shell has it: modules compiled to bytecode once (some environments disable that)
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def _time(cmd: list[str], repeat: int) -> float:
    runs = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, capture_output=True, env=ENV)
        runs.append(time.perf_counter() - t0)
    return statistics.median(runs)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    vei = [sys.executable, "-m", "vei_scenario"]
    with tempfile.TemporaryDirectory(prefix="vei-bench-osi-") as tmp:
        xosc = Path(tmp) / "scenario.xosc"
        subprocess.run(vei + ["compile", str(ROOT / "examples/case_study/clip.json"), "-o", str(xosc)], check=True,
                       capture_output=True)  # fmt: skip
        run = vei + ["run", str(xosc), "--param", "TimeShift=2.2", "--param", "RiderType=aggressive",
                     "--param", "CapEnabled=true", "-o", str(Path(tmp) / "run")]  # fmt: skip
        print(f"vei run, case study, whole process, median of {args.repeat}")
        for label, extra in (("with plots", []), ("--no-plots", ["--no-plots"])):
            base = _time(run + extra, args.repeat)
            line = f"  {label:11s} {base:.3f} s"
            for suffix in (".mcap", ".osi"):
                t = _time(run + extra + ["--osi", str(Path(tmp) / f"trace{suffix}")], args.repeat)
                line += f" | + {suffix} {t:.3f} s ({100 * (t - base) / base:+.0f} %)"
            print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
