#!/usr/bin/env python3
"""Time per scenario of ``vei bench`` with the user's Python controller, against vei's planner.

A small generated library (``examples/generate_dataset.py`` clips, compiled) is benched three ways,
each with the configurations with the planner on only (4 and 5, ``--configurations 4,5``) so the
figures are of the system under test alone:

* ``planner``: vei's planner through the compiled sweep kernel;
* ``AEB``: ``tests/data/sut/aeb_good.py:AEB`` on the ego, through the interpreter;
* ``LateAEB``: ``tests/data/sut/aeb_flawed.py:LateAEB`` on the ego, through the interpreter.

Then one run of one scenario, in this process, to say where a plugged run's time goes: the
interpreter with the built-in planner (no user code), and the same run with each controller.

    python benchmarks/bench_plugged.py                 # 4 clips, +-0.5 s by 0.05 s (21 shifts)
    python benchmarks/bench_plugged.py --full          # 20 clips, +-1.5 s by 0.01 s (301 shifts)
"""

from __future__ import annotations

import argparse
import importlib.util
import sys
import tempfile
import time
import timeit
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SUT = ROOT / "tests" / "data" / "sut"


def _best(fn, repeat: int = 3) -> float:
    """The fastest of ``repeat`` calls of ``fn``, in s."""
    return min(timeit.repeat(fn, number=1, repeat=repeat))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--full", action="store_true", help="20 clips and the default search (+-1.5 s by 0.01 s)")
    ap.add_argument("--clips", type=int, help="how many clips (default 4, 20 with --full)")
    ap.add_argument("--workers", type=int, default=None, help="worker processes/threads (default: all cores)")
    args = ap.parse_args()

    from vei_scenario.bench import BenchOptions, parse_systems, run_bench
    from vei_scenario.interpreter import run_scenario
    from vei_scenario.library import compile_library

    spec = importlib.util.spec_from_file_location("generate_dataset", ROOT / "examples" / "generate_dataset.py")
    gen = importlib.util.module_from_spec(spec)
    sys.modules["generate_dataset"] = gen
    spec.loader.exec_module(gen)
    n = args.clips or (20 if args.full else 4)
    opts = BenchOptions(
        half_width_s=1.5 if args.full else 0.5,
        step_s=0.01 if args.full else 0.05,
        configurations=(4, 5),
        workers=args.workers,
    )
    shifts = 2 * round(opts.half_width_s / opts.step_s) + 1
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        gen.write_clips(root / "data", n, seed=4)
        compile_library(root / "data" / "clips", root / "library")
        print(f"{n} clips, configurations 4 and 5, {shifts} TimeShifts each: {2 * shifts} runs a scenario")
        print(f"{'system':<10} {'s total':>8} {'s/scenario':>11} {'ms/run':>8} {'failing':>8}")
        systems = [("planner", ())] + [
            (label, parse_systems([target])[0].controllers)
            for label, target in (
                ("AEB", f"Ego={SUT / 'aeb_good.py'}:AEB"),
                ("LateAEB", f"Ego={SUT / 'aeb_flawed.py'}:LateAEB"),
            )
        ]
        from vei_scenario.bench import System

        one = None
        for label, controllers in systems:
            t0 = time.perf_counter()
            doc = run_bench(root / "library", root / "out" / label, opts, None, System(label, controllers))
            took = time.perf_counter() - t0
            benched = max(doc["benched"], 1)
            print(
                f"{label:<10} {took:8.2f} {took / benched:11.3f} {1e3 * took / (benched * 2 * shifts):8.2f} "
                f"{doc['failing']:>4} of {doc['benched']}"
            )
            one = one or next((r for r in doc["results"] if r["status"] == "ok"), None)
        if one is None:
            return
        xosc = str(root / "library" / one["scenario"])
        values = {"TimeShift": repr(one["conflict_time_shift_s"]), **one["configurations"]["4"]["parameters"]}
        print(f"\none run in this process ({one['file']}, best of 3):")
        t = _best(lambda: run_scenario(xosc, values, 0.01))
        print(f"  interpreter, built-in planner       {1e3 * t:7.1f} ms")
        for label, controllers in systems[1:]:
            t = _best(lambda c=controllers: run_scenario(xosc, values, 0.01, controllers=c))
            print(f"  interpreter, {label:<22} {1e3 * t:7.1f} ms")


if __name__ == "__main__":
    main()
