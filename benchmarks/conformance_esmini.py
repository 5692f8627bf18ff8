"""vei run against esmini 3.6 on esmini's own example scenarios: which run, and how close they play.

    python benchmarks/conformance_esmini.py [--esmini PATH] [--examples DIR] [--markdown]

For every example: vei's verdict (runs, or its one-line refusal), and for those that run the largest
distance between the two players' reference points over the whole run, per scenario, with the
collision verdicts. Examples that need an esmini-specific controller are listed as such.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from vei_scenario.conformance.esmini import compare_runs, find_esmini, run_esmini  # noqa: E402
from vei_scenario.errors import VeiInputError  # noqa: E402
from vei_scenario.interpreter import run_scenario  # noqa: E402
from vei_scenario.safe_xml import parse_xml  # noqa: E402

ESMINI_CONTROLLERS = {
    "interactiveDriver", "sloppyDriver", "SloppyDriverController", "ALKS_R157SM_Controller",
    "followGhost", "followReference", "offroadFollower", "NaturalDriver", "SumoController", "sumoController",
    "externalController", "InteractiveController", "ExternalController",
}  # fmt: skip


def esmini_specific(path: Path) -> set[str]:
    root = parse_xml(path).getroot()
    names = {c.get("entryName") for c in root.iter("CatalogReference") if c.get("catalogName") == "ControllerCatalog"}
    names |= {c.get("name") for c in root.iter("Controller")}
    names |= {p.get("value") for p in root.iter("Property") if p.get("name") == "esminiController"}
    return {n for n in names if n in ESMINI_CONTROLLERS}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--esmini", default=str(ROOT.parent / "shared" / "esmini" / "bin" / "esmini"))
    ap.add_argument("--examples", default=str(ROOT.parent / "shared" / "esmini" / "xosc"))
    ap.add_argument("--tolerance", type=float, default=0.10, help="agreement threshold in m (default 0.10)")
    ap.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = ap.parse_args()
    esmini = find_esmini(args.esmini)
    if esmini is None:
        print(f"esmini not found at {args.esmini}", file=sys.stderr)
        return 2
    rows = []
    for path in sorted(Path(args.examples).glob("*.xosc")):
        special = esmini_specific(path)
        try:
            es = run_esmini(esmini, path, 0.01)
        except Exception as exc:  # noqa: BLE001 - a conformance table reports every failure
            rows.append((path.name, "esmini fails", str(exc).splitlines()[0][:160], special))
            continue
        start = time.perf_counter()
        try:
            result = run_scenario(path, {}, 0.01)
        except VeiInputError as exc:
            rows.append((path.name, "refused", str(exc).split(": ", 1)[-1], special))
            continue
        except Exception as exc:  # noqa: BLE001
            rows.append((path.name, "error", f"{type(exc).__name__}: {exc}", special))
            continue
        vei_s = time.perf_counter() - start
        c = compare_runs(result, es)
        worst = max(c.entities, key=lambda e: e.max_deviation_m) if c.entities else None
        verdict = "agrees" if worst and worst.max_deviation_m <= args.tolerance and c.same_verdict else "differs"
        detail = (
            f"max {worst.max_deviation_m:.3g} m ({worst.entity} at {worst.at_time_s:.2f} s); "
            f"collisions vei {len(c.vei_collisions)} / esmini {len(c.esmini_collisions)}; "
            f"vei {vei_s:.2f} s, esmini {es.seconds:.2f} s"
        )
        rows.append((path.name, verdict, detail, special))
    counts: dict[str, int] = {}
    for name, verdict, detail, special in rows:
        counts[verdict] = counts.get(verdict, 0) + 1
        tag = f" [esmini controller: {', '.join(sorted(special))}]" if special else ""
        if args.markdown:
            print(f"| {name} | {verdict} | {detail}{tag} |")
        else:
            print(f"{name:48s} {verdict:8s} {detail}{tag}")
    print("; ".join(f"{v}: {n}" for v, n in sorted(counts.items())), f"(of {len(rows)})")
    plain = [r for r in rows if not r[3] and r[1] != "esmini fails"]
    agree = sum(1 for r in plain if r[1] == "agrees")
    print(f"of the {len(plain)} examples esmini plays without an esmini-specific controller: {agree} agree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
