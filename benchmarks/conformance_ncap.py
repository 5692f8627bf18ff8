#!/usr/bin/env python3
"""vei run against esmini on every Euro NCAP single-execution variation in ../shared/osc-ncap.

For each single-parameter-set file (2023 AEB C2C/VRU `*_kph*.xosc` and CA-FC 2026
`Variations/SingleExecution/*.xosc`) the base scenario runs in both players with the file's values;
prints agree / differ / refused per file (agree: every entity within 0.10 m, same collision verdict)
and the counts.

    python benchmarks/conformance_ncap.py [--esmini PATH]
"""

from __future__ import annotations

import argparse
import glob
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NCAP = ROOT.parent / "shared" / "osc-ncap" / "OpenSCENARIO" / "NCAP"


def single_executions() -> list[Path]:
    files = [Path(p) for p in glob.glob(str(NCAP / "*" / "Variations" / "*.xosc")) if "Variation_" not in p]
    files += [Path(p) for p in glob.glob(str(NCAP / "*" / "Variations" / "SingleExecution" / "*.xosc"))]
    return sorted(files)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--esmini", default=str(ROOT.parent / "shared" / "esmini" / "bin" / "esmini"))
    args = ap.parse_args()
    from lxml import etree

    from vei_scenario.conformance.esmini import cross_check, find_esmini
    from vei_scenario.errors import VeiInputError
    from vei_scenario.interpreter.document import load_scenario
    from vei_scenario.variation import read_distribution

    esmini = find_esmini(args.esmini)
    if esmini is None:
        print("esmini not found")
        return 1
    counts = {"agrees": 0, "differs": 0, "refused": 0}
    for v in single_executions():
        base = (v.parent / etree.parse(str(v)).getroot().find(".//ScenarioFile").get("filepath")).resolve()
        try:
            values = read_distribution(v, load_scenario(base).parameter_types)[0]
            c = cross_check(esmini, base, values)
        except VeiInputError as exc:
            counts["refused"] += 1
            print(f"{v.name:45s} refused  {str(exc).split(': ')[-1][:100]}")
            continue
        ok = c.max_deviation_m <= 0.10 and bool(c.vei_collisions) == bool(c.esmini_collisions)
        counts["agrees" if ok else "differs"] += 1
        print(f"{v.name:45s} {'agrees ' if ok else 'differs'}  max {c.max_deviation_m:.3g} m; collisions vei "
              f"{len(c.vei_collisions)} / esmini {len(c.esmini_collisions)}")  # fmt: skip
    print("; ".join(f"{k}: {n}" for k, n in counts.items()) + f" (of {sum(counts.values())})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
