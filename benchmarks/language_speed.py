#!/usr/bin/env python3
"""Seconds per description from text to layers (the rules reader and the sampling), over the
descriptions of every corpus in tests/data/language_*.json taken in turn.

    python benchmarks/language_speed.py [--count 200]    (--count 1000 for the full size)

Prints the median and the slowest time per description (the reader's lookups warm up once).
"""

from __future__ import annotations

import argparse
import itertools
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=200, help="descriptions to read (default 200)")
    args = ap.parse_args()
    from vei_scenario.language.corpus_check import load_corpus
    from vei_scenario.language.rules_backend import layers_from_text

    texts = [c["text"] for f in sorted((ROOT / "tests" / "data").glob("language_*.json")) for c in load_corpus(f)]
    times = []
    for i, text in enumerate(itertools.islice(itertools.cycle(texts), args.count)):
        t0 = time.perf_counter()
        try:
            layers_from_text(text, i)
        except ValueError:
            pass  # (a refusal takes its time too)
        times.append(time.perf_counter() - t0)
    print(
        f"{len(times)} descriptions to layers: median {statistics.median(times) * 1000:.1f} ms, "
        f"slowest {max(times) * 1000:.1f} ms"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
