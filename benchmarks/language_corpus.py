#!/usr/bin/env python3
"""How much of a description corpus the language backend understands and turns into faithful layers.

Reads ``tests/data/language_corpus.json`` (or ``--corpus FILE``), prints every case that is refused or
unfaithful with the reasons, then the figures: understood, faithful (every expectation met on seeds
0-2), and the words most often refused.

    python benchmarks/language_corpus.py [--corpus FILE] [--quiet] [--played] [--backend local] [--limit N]
    python benchmarks/language_corpus.py --all [--played]

``--all`` prints one line per corpus of tests/data (understood, faithful, played) beside the figures
first measured on the independently written ones, before the reader was changed for them.

With ``--played`` every description's scenario (seed 0) is also played, and the trajectories are
checked for what the layers say each adversary does (a stop ends standing, a cut-in ends ahead in
the ego's lane, a crossing passes the ego's path ...).
"""

from __future__ import annotations

import argparse
import collections
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: Corpora written by people who never saw the reader: (cases, understood, faithful, played or None)
#: first measured, before any change was made for them, and on what.
FIRST = {
    "language_independent_a.json": ((59, 41, 5, None), "measured when written"),
    "language_independent_b.json": ((63, 53, 3, None), "held out, measured when written"),
    "language_independent_c.json": ((65, 65, 26, 59), "sealed, measured when written"),
    "language_independent_d.json": ((56, 56, 4, 43), "sealed, measured when written"),
    "language_independent_e.json": ((70, 70, 16, 55), "sealed, measured once before a pass of reader work"),
    "language_independent_f.json": ((60, 60, 32, 58), "measured when written"),
    "language_independent_g.json": ((60, 60, 24, 56), "sealed until the reader's last change"),
    "language_independent_h.json": ((50, 50, 30, 43), "measured when written"),
    "language_independent_i.json": ((50, 50, 12, 38), "measured when written"),
    "language_independent_j.json": ((45, 45, 27, 38), "sealed until the reader's last change"),
    "language_independent_k.json": ((45, 45, 24, 41), "sealed until the reader's last change"),
    "language_independent_l.json": ((50, 50, 23, 44), "measured when written"),
    "language_independent_m.json": ((50, 50, 19, 41), "measured when written"),
    "language_independent_n.json": ((45, 45, 9, 32), "sealed until the reader's last change"),
    "language_independent_o.json": ((45, 45, 8, 34), "sealed until the reader's last change"),
    "language_independent_p.json": ((45, 45, 18, 41), "sealed until the reader's last change"),
    "language_independent_q.json": ((45, 45, 17, 41), "sealed until the reader's last change"),
    "language_independent_r.json": ((50, 50, 8, 41), "measured when written"),
    "language_independent_s.json": ((50, 50, 22, 47), "measured when written"),
    "language_independent_t.json": ((45, 44, 15, 40), "sealed until the reader's last change"),
    "language_independent_u.json": ((45, 45, 21, 42), "sealed until the reader's last change"),
    "language_independent_v.json": ((50, 50, 13, 47), "sealed for two rounds of reader work"),
    "language_independent_w.json": ((50, 49, 19, 48), "sealed for two rounds of reader work"),
    "language_independent_x.json": ((50, 49, 15, 45), "sealed for two rounds of reader work"),
    "language_independent_y.json": ((50, 50, 18, 47), "sealed for two rounds of reader work"),
    "language_independent_z3.json": ((50, 50, 8, 46), "sealed for two rounds of reader work"),
    "language_independent_z4.json": ((50, 50, 5, 50), "sealed for two rounds of reader work"),
    "language_independent_z5.json": ((50, 50, 9, 45), "sealed for a round of reader work"),
    "language_independent_z6.json": ((50, 50, 11, 46), "sealed for a round of reader work"),
    "language_independent_z7.json": ((50, 50, 10, 46), "sealed for a round of reader work"),
    "language_independent_z8.json": ((50, 50, 7, 46), "sealed for a round of reader work"),
    "language_independent_z9.json": ((50, 50, 23, 47), "sealed for a round of reader work"),
    "language_independent_z10.json": ((50, 50, 7, 46), "sealed for a round of reader work"),
    "language_independent_z11.json": ((50, 50, 15, 48), "sealed for a round of reader work"),
    "language_independent_z12.json": ((50, 50, 10, 48), "sealed for a round of reader work"),
    "language_independent_z13.json": ((50, 50, 1, 46), "sealed for a round of reader work"),
    "language_independent_z14.json": ((50, 50, 22, 48), "sealed for a round of reader work"),
    "language_independent_z15.json": ((50, 50, 7, 46), "sealed for two rounds of reader work"),
    "language_independent_z16.json": ((50, 50, 11, 48), "sealed for two rounds of reader work"),
    "language_independent_z17.json": ((50, 50, 6, 47), "sealed for two rounds of reader work"),
    "language_independent_z18.json": ((50, 50, 10, 46), "sealed for two rounds of reader work"),
    "language_independent_z19.json": ((50, 50, 3, 42), "sealed for two rounds of reader work"),
    "language_independent_z20.json": ((50, 50, 23, 49), "sealed for two rounds of reader work"),
    "language_independent_z21.json": ((50, 50, 9, 45), "sealed for two rounds of reader work"),
    "language_independent_z22.json": ((50, 50, 14, 46), "sealed for two rounds of reader work"),
    "language_independent_z23.json": ((50, 50, 7, 40), "sealed for a round of reader work"),
    "language_independent_z24.json": ((50, 50, 7, 43), "sealed for a round of reader work"),
    "language_independent_z25.json": ((50, 50, 17, 48), "sealed for a round of reader work"),
    "language_independent_z26.json": ((50, 50, 15, 48), "sealed for a round of reader work"),
    "language_independent_z27.json": ((50, 50, 9, 47), "sealed for a round of reader work"),
    "language_independent_z28.json": ((50, 50, 11, 40), "sealed for a round of reader work"),
    "language_independent_z29.json": ((50, 50, 5, 41), "sealed for a round of reader work"),
    "language_independent_z30.json": ((50, 49, 3, 46), "sealed for a round of reader work"),
    "language_independent_z31.json": ((50, 50, 11, 45), "sealed for a round of reader work"),
    "language_independent_z32.json": ((50, 50, 4, 43), "sealed for a round of reader work"),
    "language_independent_z33.json": ((50, 50, 12, 48), "sealed for a round of reader work"),
    "language_independent_z34.json": ((50, 50, 2, 44), "sealed for a round of reader work"),
    "language_independent_z35.json": ((50, 49, 9, 44), "sealed for a round of reader work"),
    "language_independent_z36.json": ((50, 50, 17, 48), "sealed for a round of reader work"),
    "language_independent_z37.json": ((50, 49, 11, 44), "sealed for a round of reader work"),
    "language_independent_z38.json": ((50, 50, 3, 47), "sealed for a round of reader work"),
    "language_independent_z39.json": ((50, 50, 11, 49), "sealed for a round of reader work"),
    "language_independent_z40.json": ((50, 50, 4, 43), "sealed for a round of reader work"),
    "language_independent_z41.json": ((50, 50, 7, 45), "measured when written"),
    "language_independent_z42.json": ((50, 50, 19, 49), "measured when written"),
    "language_independent_z43.json": ((50, 50, 8, 48), "measured when written"),
    "language_independent_z44.json": ((50, 50, 15, 47), "measured when written"),
    "language_independent_z45.json": ((50, 50, 11, 47), "measured when written"),
    "language_independent_z46.json": ((50, 50, 19, 45), "measured when written"),
    "language_independent_z47.json": ((50, 50, 4, 46), "measured when written"),
    "language_independent_z48.json": ((50, 50, 15, 43), "measured when written"),
    "language_independent_z49.json": ((50, 50, 12, 45), "measured when written"),
    "language_independent_z50.json": ((50, 50, 7, 44), "measured when written"),
    "language_independent_z51.json": ((50, 50, 15, 43), "measured when written"),
    "language_independent_z52.json": ((50, 50, 12, 49), "measured when written"),
    "language_independent_z53.json": ((50, 50, 12, 45), "measured when written"),
    "language_independent_z54.json": ((50, 50, 7, 43), "measured when written"),
    "language_independent_z55.json": ((50, 50, 15, 46), "measured when written"),
    "language_independent_z56.json": ((50, 50, 11, 46), "measured when written"),
    "language_independent_z57.json": ((50, 50, 14, 46), "measured when written"),
    "language_independent_z58.json": ((50, 50, 11, 46), "measured when written"),
    "language_independent_z59.json": ((50, 50, 12, 48), "measured when written"),
    "language_independent_z60.json": ((50, 50, 13, 48), "measured when written"),
    "language_independent_z61.json": ((50, 50, 1, 39), "measured when written"),
    "language_independent_z62.json": ((50, 50, 11, 43), "measured when written"),
    "language_independent_z63.json": ((50, 50, 1, 48), "measured when written"),
    "language_independent_z64.json": ((50, 50, 6, 41), "measured when written"),
    "language_independent_z65.json": ((48, 48, 6, 43), "measured when written"),
    "language_independent_z66.json": ((48, 48, 3, 42), "measured when written"),
    "language_independent_z67.json": ((48, 48, 17, 46), "measured when written"),
    "language_independent_z68.json": ((48, 48, 6, 48), "held out: measured before the round and once after it"),
    "language_independent_z69.json": ((48, 48, 12, 43), "measured when written"),
    "language_independent_z70.json": ((48, 48, 2, 36), "held out: measured before the round and once after it"),
}


def _played(cases: list, results: list, make) -> list[list[str]]:
    """Each understood description's scenario (seed 0) played and checked: what did not happen as its
    layers say (empty: all did); a refused one has nothing to play and is ``None``."""
    import tempfile

    from vei_scenario.language.corpus_check import play_case

    with tempfile.TemporaryDirectory() as tmp:
        return [play_case(c, make, Path(tmp)) if r.understood else None for c, r in zip(cases, results)]


def _pct(k: int | None, n: int) -> str:
    return "-" if k is None else f"{k} ({100 * k / n:.0f} %)"


def all_corpora(played: bool) -> int:
    """One line per corpus of tests/data: what it gives now and, for the independent ones, first."""
    from vei_scenario.language.corpus_check import check_corpus, load_corpus
    from vei_scenario.language.rules_backend import layers_from_text

    head = f"{'corpus':32} {'n':>3}  {'understood':>10} {'faithful':>10} {'played':>10}"
    print(head + "   first: understood / faithful / played")
    by_name = lambda p: [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", p.stem)]  # noqa: E731 (z9 before z10)
    for path in sorted((ROOT / "tests" / "data").glob("language_*.json"), key=by_name):
        cases = load_corpus(path)
        results = check_corpus(cases, layers_from_text)
        n = len(results)
        done = None
        if played:
            done = sum(problems == [] for problems in _played(cases, results, layers_from_text))
        (fn, fu, ff, fp), how = FIRST.get(path.name, ((n, None, None, None), ""))
        first = f"{_pct(fu, fn)} / {_pct(ff, fn)} / {_pct(fp, fn)} ({how})" if how else "(the project's own)"
        understood = sum(r.understood for r in results)
        faithful = sum(r.faithful for r in results)
        print(f"{path.stem:32} {n:>3}  {understood:>10} {faithful:>10} {'-' if done is None else done:>10}   {first}")
    return 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--corpus", default=str(ROOT / "tests" / "data" / "language_corpus.json"))
    ap.add_argument("--quiet", action="store_true", help="figures only")
    ap.add_argument("--played", action="store_true", help="also play each scenario and check what happened")
    ap.add_argument("--backend", choices=("rules", "local"), default="rules", help="local: the GGUF model")
    ap.add_argument("--limit", type=int, default=0, help="only the first N descriptions")
    ap.add_argument("--all", action="store_true", help="every corpus of tests/data, one line each")
    args = ap.parse_args()
    if args.all:
        return all_corpora(args.played)
    from vei_scenario.language.corpus_check import check_corpus, load_corpus
    from vei_scenario.language.rules_backend import layers_from_text

    make = layers_from_text
    if args.backend == "local":
        from vei_scenario.language.local_llm import layers_from_local_model as make
    cases = load_corpus(Path(args.corpus))
    cases = cases[: args.limit] if args.limit else cases
    results = check_corpus(cases, make, seeds=(0,) if args.backend == "local" else (0, 1, 2))
    refused_words: collections.Counter = collections.Counter()
    for r in results:
        if not r.understood:
            refused_words.update(re.findall(r"'([^']+)'", r.problems[0].split(" (the words")[0]))
        if not args.quiet and not r.faithful:
            print(f"{'REFUSED ' if not r.understood else 'UNFAITHFUL'} {r.text}\n    " + "\n    ".join(r.problems))
    n = len(results)
    understood = sum(r.understood for r in results)
    faithful = sum(r.faithful for r in results)
    print(
        f"{n} descriptions: understood {understood} ({100 * understood / n:.0f} %), faithful {faithful} "
        f"({100 * faithful / n:.0f} %)"
    )
    print("most refused words: " + ", ".join(f"{w} ({k})" for w, k in refused_words.most_common(25)))
    if args.played:
        played = _played(cases, results, make)  # (a refused one: nothing to play, counted as not done)
        done = sum(problems == [] for problems in played)
        for case, problems in zip(cases, played):
            if problems and not args.quiet:
                print(f"PLAYED   {case['text']}\n    " + "\n    ".join(problems))
        print(f"played: {done} of {n} ({100 * done / n:.0f} %) did what their layers say")
    return 0


if __name__ == "__main__":
    sys.exit(main())
