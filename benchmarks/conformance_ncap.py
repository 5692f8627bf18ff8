#!/usr/bin/env python3
"""vei run against esmini on every Euro NCAP single-execution variation in ../shared/osc-ncap.

For each single-parameter-set file (2023 AEB C2C/VRU `*_kph*.xosc` and CA-FC 2026
`Variations/SingleExecution/*.xosc`) the base scenario runs in both players with the file's values;
prints per file agree / differ / refused with the largest distance between the players' entities,
the collision verdicts and the end times, then the counts. Agree: every entity within 0.10 m over
the whole run, the same collision verdict, the end within one step. With ``--all-variants`` every
parameter set of every variation file in the pack runs (1 171 runs; a summary per file and the
differing variants are printed).

    python benchmarks/conformance_ncap.py [--esmini PATH] [--tolerance M] [--all-variants [--files GLOB]]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NCAP = ROOT.parent / "shared" / "osc-ncap" / "OpenSCENARIO" / "NCAP"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--esmini", default=str(ROOT.parent / "shared" / "esmini" / "bin" / "esmini"))
    ap.add_argument("--tolerance", type=float, default=0.10, help="largest distance that agrees (m)")
    ap.add_argument("--all-variants", action="store_true", help="every parameter set of every variation file")
    ap.add_argument(
        "--files", default="*/Variations/**/*.xosc", help="with --all-variants: the variation files (a glob below NCAP)"
    )
    args = ap.parse_args()
    from vei_scenario.conformance.esmini import cross_check, find_esmini
    from vei_scenario.conformance.ncap import single_executions, values_of
    from vei_scenario.errors import VeiInputError

    esmini = find_esmini(args.esmini)
    if esmini is None:
        print("esmini not found")
        return 1
    dt = 0.01
    if args.all_variants:
        return _all_variants(esmini, args.tolerance, dt, args.files)
    counts = {"agrees": 0, "differs": 0, "refused": 0}
    for v in single_executions(NCAP):
        try:
            base, values = values_of(v)
            c = cross_check(esmini, base, values, dt)
        except VeiInputError as exc:
            counts["refused"] += 1
            print(f"{v.name:45s} refused  {str(exc).split(': ')[-1][:100]}")
            continue
        ok = c.max_deviation_m <= args.tolerance and c.same_verdict and c.end_time_difference_s <= dt + 1e-9
        counts["agrees" if ok else "differs"] += 1
        worst = max(c.entities, key=lambda e: e.max_deviation_m, default=None)
        where = f" ({worst.entity} at {worst.at_time_s:.2f} s)" if worst else ""
        print(
            f"{v.name:45s} {'agrees ' if ok else 'differs'}  max {c.max_deviation_m:.3g} m{where}; collisions vei "
            f"{len(c.vei_collisions)} / esmini {len(c.esmini_collisions)}; end vei {c.vei_end_s:.2f} s / "
            f"esmini {c.esmini_end_s:.2f} s"
        )
    print("; ".join(f"{k}: {n}" for k, n in counts.items()) + f" (of {sum(counts.values())})")
    return 0


def _all_variants(esmini, tolerance: float, dt: float, files: str = "*/Variations/**/*.xosc") -> int:
    """Every parameter set of every variation file: one line per file, then each differing variant."""
    from vei_scenario.conformance.esmini import cross_check
    from vei_scenario.conformance.ncap import base_scenario
    from vei_scenario.errors import VeiInputError
    from vei_scenario.interpreter.document import load_scenario
    from vei_scenario.variation import read_distribution

    totals = {"agrees": 0, "differs": 0, "refused": 0}
    differing: list[str] = []
    for v in sorted(NCAP.glob(files)):
        base = base_scenario(v)
        sets = read_distribution(v, load_scenario(base).parameter_types)
        counts = {"agrees": 0, "differs": 0, "refused": 0}
        worst = 0.0
        for k, values in enumerate(sets):
            try:
                c = cross_check(esmini, base, values, dt)
            except (VeiInputError, RuntimeError) as exc:  # (RuntimeError: esmini itself failed)
                counts["refused"] += 1
                differing.append(f"{v.relative_to(NCAP)} #{k}: not compared: {str(exc)[:100]}")
                continue
            ok = c.max_deviation_m <= tolerance and c.same_verdict and c.end_time_difference_s <= dt + 1e-9
            counts["agrees" if ok else "differs"] += 1
            worst = max(worst, c.max_deviation_m)
            if not ok:
                differing.append(
                    f"{v.relative_to(NCAP)} #{k}: max {c.max_deviation_m:.3g} m, collisions vei "
                    f"{len(c.vei_collisions)} / esmini {len(c.esmini_collisions)}, end vei {c.vei_end_s:.2f} s / "
                    f"esmini {c.esmini_end_s:.2f} s  {values}"
                )
        for key in totals:
            totals[key] += counts[key]
        print(
            f"{str(v.relative_to(NCAP)):70s} {len(sets):3d} sets: "
            + ", ".join(f"{n} {k}" for k, n in counts.items())
            + f"; largest {worst:.3g} m",
            flush=True,
        )
    print("\n".join(differing))
    print("; ".join(f"{k}: {n}" for k, n in totals.items()) + f" (of {sum(totals.values())} variants)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
