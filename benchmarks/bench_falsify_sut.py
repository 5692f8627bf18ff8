#!/usr/bin/env python3
"""Falsification of a user's system against a dense grid at the same resolution, in the interpreter.

The deliberately late AEB of the tests (``tests/data/sut/aeb_flawed.py:LateAEB``) on the case study's
ego, TimeShift over -1..5 s: a grid at ``--step`` (a ``vei sweep`` with the same controller) and
``vei falsify --tol STEP`` over the same box. The grid's windows of ego-moving collisions (maximal runs
of failing grid points per rider type) must each be a region of the search, edges within one step, in
at most 10 % of the grid's runs.

    python benchmarks/bench_falsify_sut.py            # the aggressive rider: a 601-run grid (~1 min)
    python benchmarks/bench_falsify_sut.py --full     # the three rider types: 1 803 runs (~3 min)
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--full", action="store_true", help="all three rider types")
    ap.add_argument("--step", type=float, default=0.01, help="grid step and falsify --tol, s (default 0.01)")
    args = ap.parse_args()
    from vei_scenario.compiler import CompileOptions, compile_clip
    from vei_scenario.falsify import Axis, falsify
    from vei_scenario.sut import parse_controller_options
    from vei_scenario.sweep.evaluate import evaluate_local

    riders = ["replay", "normal", "aggressive"] if args.full else ["aggressive"]
    controllers = tuple(parse_controller_options([f"Ego={ROOT}/tests/data/sut/aeb_flawed.py:LateAEB"]))
    with tempfile.TemporaryDirectory() as tmp:
        scenario = Path(tmp) / "scenario.xosc"
        compile_clip(ROOT / "examples/case_study/clip.json", scenario, CompileOptions())
        n = round(6 / args.step) + 1
        grid = [{"RiderType": r, "TimeShift": repr(round(-1 + args.step * i, 6))} for r in riders for i in range(n)]
        t0 = time.perf_counter()
        rows = evaluate_local(str(scenario), grid, 0.01, controllers=controllers)
        t_grid = time.perf_counter() - t0
        windows: dict[str, list[tuple[float, float]]] = {r: [] for r in riders}
        for rider in riders:
            fail = [float(v["TimeShift"]) for v, row in zip(grid, rows)
                    if v["RiderType"] == rider and row["metrics"]["collision_ego_moving"]]  # fmt: skip
            start = None
            for a, b in zip(fail, fail[1:] + [None]):
                start = a if start is None else start
                if b is None or b - a > 1.5 * args.step:
                    windows[rider].append((start, a))
                    start = None
        t0 = time.perf_counter()
        result = falsify(scenario, [Axis("TimeShift", -1, 5), Axis("RiderType", values=riders)], tol=args.step,
                         controllers=controllers)  # fmt: skip
        t_search = time.perf_counter() - t0
    near = args.step * 1.01
    found = all(
        any(r.discrete["RiderType"] == rider and abs(r.low - a) <= near and abs(r.high - b) <= near
            for r in result.regions)
        for rider, ws in windows.items() for a, b in ws
    )  # fmt: skip
    print(f"grid at {args.step:g} s: {len(grid)} runs, {t_grid:.0f} s; windows {windows}")
    regions = [(r.discrete["RiderType"], r.low, r.high) for r in result.regions]
    share = 100 * result.runs / len(grid)
    print(f"falsify --tol {args.step:g}: {result.runs} runs ({share:.1f} % of the grid), {t_search:.0f} s; {regions}")
    ok = found and result.runs <= 0.1 * len(grid)
    print("every grid window found, <= 10 % of its runs:", "yes" if ok else "NO")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
