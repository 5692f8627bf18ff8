#!/usr/bin/env python3
"""How often ``vei describe --refine`` reaches the intent a description states.

For every description of a corpus (``vei-language-corpus/1``) that states an intent (collision, near
miss, safe), its first ``--count`` scenarios are written, played and refined, and the scenarios whose
last episode meets the intent are counted, with the runs it took. ``--no-beyond`` refines without probing
around a target profile that a value started in, for comparison.

    python benchmarks/language_intent.py [--corpus FILE] [--count 4] [--no-beyond]
"""

from __future__ import annotations

import argparse
import collections
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--corpus", default=str(ROOT / "tests" / "data" / "language_independent_e.json"))
    ap.add_argument("--count", type=int, default=4, help="scenarios per description")
    ap.add_argument("--no-beyond", action="store_true", help="values stop at the middle of the target profile")
    args = ap.parse_args()
    from vei_scenario.language import refinement
    from vei_scenario.language.corpus_check import load_corpus
    from vei_scenario.language.describe import run_one
    from vei_scenario.language.rules_backend import layers_from_text

    if args.no_beyond:
        refinement._side = lambda *a: 0
    met: collections.Counter = collections.Counter()
    asked: collections.Counter = collections.Counter()
    missed: collections.Counter = collections.Counter()
    runs = 0
    for case in load_corpus(Path(args.corpus)):
        for i in range(args.count):
            layers = layers_from_text(case["text"], i)
            intent = layers.get("intent", "unspecified")
            if intent == "unspecified":
                break
            record = run_one(layers, i, refine=True)
            if record.ok:
                asked[intent] += 1
                met[intent] += bool(record.episodes[-1]["intent_met"])
                if not record.episodes[-1]["intent_met"]:
                    first = layers["adversaries"][0]["behaviour"] if layers["adversaries"] else {}
                    missed[(intent, first.get("behaviour", "sequence"))] += 1
                runs += len(record.episodes)
    for intent in sorted(asked):
        print(f"{intent}: met {met[intent]} of {asked[intent]} ({100 * met[intent] / asked[intent]:.0f} %)")
    worst = ", ".join(f"{i} {b} ({k})" for (i, b), k in missed.most_common(8))
    print(f"missed most (intent, first behaviour): {worst}")
    total = sum(asked.values())
    print(f"all stated intents: met {sum(met.values())} of {total} after {runs} runs")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
