#!/usr/bin/env python3
"""Falsification against a dense grid, and collision probability against crude Monte Carlo.

1. Ground truth: a grid through the compiled kernel over TimeShift x EgoCruiseSpeed x RiderType, the
   planner on (at least 100 000 points). Its failure regions: per rider type, maximal runs of failing
   points along TimeShift on each cruise row, linked across adjacent rows when they overlap. The
   search (`vei falsify`) must find every one (a search region of the same rider overlapping it), with
   at most 5 % of the grid's runs, and each region's TimeShift edges within 0.005 s of the grid's.
   Every contact counts here (target collision_any: most of the planner's are the rider running into
   the ego it has stopped), as the search machinery is what is measured.
2. P(collision) of the case study under a stochastic distribution (TimeShift normal, rider type
   uniform, planner on): crude Monte Carlo with --mc-runs (>= 10^6 for the acceptance) and importance
   sampling; the latter must lie inside the former's 95 % interval and need >= 10x fewer runs for the
   same interval width.

    python benchmarks/bench_falsify.py [--mc-runs 1000000] [--quick]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def grid_regions(scenario: str, ts: np.ndarray, cruise: np.ndarray, riders: list[str]) -> tuple[list[dict], int]:
    from vei_scenario.sweep.evaluate import evaluate_local

    regions = []
    runs = 0
    step = ts[1] - ts[0]
    for rider in riders:
        rows = []
        for c in cruise:
            variants = [{"TimeShift": repr(round(float(t), 6)), "EgoCruiseSpeed": repr(round(float(c), 6)),
                         "RiderType": rider, "CapEnabled": "true"} for t in ts]  # fmt: skip
            out = evaluate_local(scenario, variants, 0.01)
            runs += len(out)
            fail = np.array([bool(o["metrics"]["collision"]) for o in out])
            windows, k = [], 0
            while k < len(ts):
                if fail[k]:
                    j = k
                    while j + 1 < len(ts) and fail[j + 1]:
                        j += 1
                    windows.append((ts[k], ts[j]))
                    k = j + 1
                else:
                    k += 1
            rows.append(windows)
        # components: windows linked across adjacent rows when they overlap (within a grid step)
        nodes = [(i, w) for i, ws in enumerate(rows) for w in ws]
        parent = list(range(len(nodes)))

        def find(a: int, parent=parent) -> int:
            while parent[a] != a:
                parent[a] = parent[parent[a]]
                a = parent[a]
            return a

        for a, (i, (s0, e0)) in enumerate(nodes):
            for b, (j, (s1, e1)) in enumerate(nodes):
                if j == i + 1 and s0 <= e1 + step and s1 <= e0 + step:
                    parent[find(a)] = find(b)
        groups: dict[int, list] = {}
        for a, node in enumerate(nodes):
            groups.setdefault(find(a), []).append(node)
        for g in groups.values():
            regions.append({"rider": rider, "low": min(w[0] for _, w in g), "high": max(w[1] for _, w in g),
                            "rows": len(g)})  # fmt: skip
    return regions, runs


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--mc-runs", type=int, default=1_000_000)
    ap.add_argument("--quick", action="store_true", help="a smaller grid and 10^5 Monte Carlo runs")
    args = ap.parse_args()
    from vei_scenario.compiler import compile_clip
    from vei_scenario.falsify import Axis, falsify
    from vei_scenario.probability import estimate_probability

    with tempfile.TemporaryDirectory(prefix="vei-bench-falsify-") as tmp:
        xosc = Path(tmp) / "scenario.xosc"
        compile_clip(ROOT / "examples" / "case_study" / "clip.json", xosc)
        scenario = str(xosc)
        riders = ["replay", "normal", "aggressive"]
        ts_lo, ts_hi, c_lo, c_hi = 2.0, 4.0, 5.5, 5.7
        ts = np.round(np.arange(ts_lo, ts_hi + 1e-9, 0.002 if args.quick else 0.001), 6)
        cruise = np.round(np.linspace(c_lo, c_hi, 11 if args.quick else 51), 6)
        t0 = time.perf_counter()
        truth, grid_runs = grid_regions(scenario, ts, cruise, riders)
        t_grid = time.perf_counter() - t0
        print(f"grid: {len(ts)} TimeShift x {len(cruise)} EgoCruiseSpeed x {len(riders)} riders = {grid_runs} runs "
              f"({t_grid:.1f} s); {len(truth)} failure region(s)")  # fmt: skip
        t0 = time.perf_counter()
        result = falsify(
            scenario,
            [Axis("TimeShift", ts_lo, ts_hi), Axis("EgoCruiseSpeed", c_lo, c_hi), Axis("RiderType", values=riders)],
            {"CapEnabled": "true"},
            "collision_any",  # (every contact, as the grid counts them: the search machinery is measured)
            slices=7,
            tol=0.001,
        )
        t_search = time.perf_counter() - t0
        print(f"search: {result.runs} runs ({100 * result.runs / grid_runs:.2f} % of the grid, {t_search:.1f} s); "
              f"{len(result.regions)} region(s)")  # fmt: skip
        worst_edge, missed = 0.0, 0
        for g in truth:
            match = [r for r in result.regions if r.discrete["RiderType"] == g["rider"] and r.low <= g["high"] + 0.005
                     and g["low"] <= r.high + 0.005]  # fmt: skip
            if not match:
                missed += 1
                print(f"  MISSED grid region {g}")
                continue
            low, high = min(r.low for r in match), max(r.high for r in match)
            err = max(abs(low - g["low"]), abs(high - g["high"]))
            worst_edge = max(worst_edge, err)
            print(f"  {g['rider']:10s} grid {g['low']:.4f}..{g['high']:.4f} ({g['rows']} rows) | search "
                  f"{low:.4f}..{high:.4f} | edge error {err:.4f} s")  # fmt: skip
        ok = missed == 0 and result.runs <= 0.05 * grid_runs and worst_edge <= 0.005
        print(f"found {len(truth) - missed} of {len(truth)}; worst edge error {worst_edge:.4f} s; "
              f"acceptance {'met' if ok else 'NOT met'}")  # fmt: skip

        dist = Path(tmp) / "dist.xosc"
        dist.write_text(
            """<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-05-14T00:00:00" description="" author=""/>
<ParameterValueDistribution><ScenarioFile filepath="scenario.xosc"/><Stochastic numberOfTestRuns="1" randomSeed="1">
<StochasticDistribution parameterName="TimeShift"><NormalDistribution expectedValue="2.6" variance="0.36">
<Range lowerLimit="-1" upperLimit="6"/></NormalDistribution></StochasticDistribution>
<StochasticDistribution parameterName="RiderType"><ProbabilityDistributionSet><Element value="replay" weight="1"/>
<Element value="normal" weight="1"/><Element value="aggressive" weight="1"/></ProbabilityDistributionSet>
</StochasticDistribution></Stochastic></ParameterValueDistribution></OpenSCENARIO>"""
        )
        mc_runs = 100_000 if args.quick else args.mc_runs
        t0 = time.perf_counter()
        (mc,) = estimate_probability(scenario, dist, "collision_any", estimators=("monte-carlo",), runs=mc_runs,
                                     fixed={"CapEnabled": "true"}, seed=11)  # fmt: skip
        t_mc = time.perf_counter() - t0
        t0 = time.perf_counter()
        (imp,) = estimate_probability(scenario, dist, "collision_any", estimators=("importance-sampling",),
                                      runs=20_000, fixed={"CapEnabled": "true"}, seed=12)  # fmt: skip
        t_is = time.perf_counter() - t0
        needed = mc.runs * (mc.width / imp.width) ** 2
        print(f"P(collision): Monte Carlo {mc.probability:.5f} [{mc.low:.5f}, {mc.high:.5f}] ({mc.runs} runs, "
              f"{t_mc:.1f} s)")  # fmt: skip
        print(f"              importance sampling {imp.probability:.5f} [{imp.low:.5f}, {imp.high:.5f}] ({imp.runs} "
              f"runs, {imp.levels} levels, {t_is:.1f} s)")  # fmt: skip
        inside = mc.low <= imp.probability <= mc.high
        print(f"  inside the Monte Carlo interval: {'yes' if inside else 'NO'}; Monte Carlo needs ~{needed:.3g} runs "
              f"for the importance-sampling width: {needed / imp.runs:.1f}x")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
