"""vei describe on the LinguaSim evaluation's six descriptions: 32 scenarios each, generated, run
closed loop and scored (plus the Dangerous batch refined), with the time each batch takes.

    python benchmarks/bench_describe.py [--count 32] [--jobs 2]

Prints one row per batch: crash rate, mean minimum ACT, mean comfort, mean maximum EI, seconds;
the paper's figures beside the cut-in rows. The README's table comes from here.
"""

from __future__ import annotations

import argparse
import time

from vei_scenario.language.describe import describe_batch
from vei_scenario.language.paper import DESCRIPTIONS, PAPER
from vei_scenario.language.rules_backend import layers_from_text


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--count", type=int, default=32)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    batches = [(name, False) for name in DESCRIPTIONS] + [("Dangerous", True)]
    head = f"{'batch':22s} {'CR %':>6s} {'ACT s':>7s} {'comfort':>8s} {'EI m/s':>7s} {'runs':>5s} {'s':>5s}"
    print(head + "   paper (ACT, comfort, CR)")
    for name, refine in batches:
        text = DESCRIPTIONS[name]
        t0 = time.perf_counter()
        _, doc = describe_batch(
            lambda i, text=text: layers_from_text(text, args.seed * 1000 + i),
            args.count,
            None,
            text,
            "rules",
            args.seed,
            refine,
            args.jobs,
        )
        seconds = time.perf_counter() - t0
        s = doc["summary"]
        label = f"{name}, refined" if refine else name
        paper = PAPER.get(label)
        ref = "" if paper is None else f"   {paper[0]} s, {paper[1]}, {100 * paper[2]:.1f} %"
        print(
            f"{label:22s} {100 * s['crash_rate']:6.1f} {s['mean_min_act_s']:7.3f} {s['mean_comfort']:8.3f} "
            f"{s['mean_max_ei_mps']:7.2f} {s['episodes_run']:5d} {seconds:5.2f}{ref}"
        )


if __name__ == "__main__":
    main()
