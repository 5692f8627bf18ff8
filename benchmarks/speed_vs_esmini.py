#!/usr/bin/env python3
"""vei run beside esmini, scenario by scenario: is the interpreted run as fast as esmini's process?

    python benchmarks/speed_vs_esmini.py [--esmini PATH] [--repeat N] [--markdown]

    python benchmarks/speed_vs_esmini.py --sweep NCAP_VARIATION.xosc [--sweep ...]
    python benchmarks/speed_vs_esmini.py --sweep-all

For every esmini example and every Euro NCAP single execution that both players play: esmini's whole
process (``--headless --fixed_timestep 0.01 --csv_logger --collision``, as the conformance runs), and
vei's ``run_scenario`` after start-up (reading the scenario, its catalogs and its road, the run, the traces), each the
median of N runs; the ratio vei / esmini, its median and worst. Start-up is the import of what
``vei run`` needs, measured in fresh processes. With ``--sweep``: ``vei sweep``'s evaluation of every
variant of a Euro NCAP variation file (on all cores, as ``vei sweep`` runs it) per variant, against
esmini's process per variant (the median over the first five variants); vei's figure is the median of
five sweeps, each reading the files afresh, in a process of its own for each file (as ``vei sweep``
is one process a file: in one long process the garbage of earlier files, which a sweep leaves to the
end, slows the later ones by up to a fifth). ``--sweep-all``: every variation file of many parameter
sets in the Euro NCAP pack (2023 ``*_Variation_*``, 2026 ``StandardRange`` and ``ExtendedRange``), and
how many reach the target.
"""

from __future__ import annotations

import argparse
import gc
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from vei_scenario.conformance.esmini import find_esmini, run_esmini  # noqa: E402
from vei_scenario.conformance.ncap import full_variations, single_executions, values_of  # noqa: E402
from vei_scenario.errors import VeiInputError  # noqa: E402
from vei_scenario.interpreter import clear_file_caches, run_scenario  # noqa: E402


def startup_s(repeat: int) -> tuple[float, float]:
    """(median import time of vei run's modules, median bare interpreter start) in fresh processes, with
    the bytecode cached as an installed package has it (a first import writes it where
    PYTHONDONTWRITEBYTECODE would have every import compile the sources again)."""
    code = "import time; t = time.perf_counter(); import vei_scenario.runner, vei_scenario.interpreter; "
    code += "print(time.perf_counter() - t)"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    subprocess.run([sys.executable, "-c", code], capture_output=True, env=env, check=True)
    imports = [float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env).stdout)
               for _ in range(max(repeat, 5))]  # fmt: skip
    bare = []
    for _ in range(repeat):
        a = time.perf_counter()
        subprocess.run([sys.executable, "-c", "pass"], check=True)
        bare.append(time.perf_counter() - a)
    return statistics.median(imports), statistics.median(bare)


def cases(esmini_dir: Path, ncap_dir: Path) -> list[tuple[str, Path, dict[str, str]]]:
    out = [(p.name, p, {}) for p in sorted(esmini_dir.glob("*.xosc"))]
    if ncap_dir.is_dir():
        for variation in sorted(single_executions(ncap_dir)):
            base, params = values_of(variation)
            out.append((variation.name, base, params))
    return out


def sweep_figures(esmini: Path, variation: Path) -> tuple[float, str]:
    """vei sweep's evaluation of every variant of ``variation`` against esmini's process per variant:
    (esmini / vei, the line to print)."""
    from vei_scenario.conformance.ncap import base_scenario
    from vei_scenario.sweep import build_variants
    from vei_scenario.sweep.evaluate import evaluate_local

    base = base_scenario(variation)
    variants, _ = build_variants(base, [], variation, None)
    per_variant = []
    for _ in range(5):  # (the median of five sweeps, each reading the files afresh)
        clear_file_caches()
        gc.disable()  # (as vei sweep evaluates: sweep.run_sweep)
        try:
            a = time.perf_counter()
            outcomes = evaluate_local(str(base.resolve()), variants, 0.01, None, None)
            per_variant.append((time.perf_counter() - a) / len(variants))
        finally:
            gc.enable()
    vei = statistics.median(per_variant)
    failed = sum(1 for o in outcomes if isinstance(o, dict) and o.get("error"))
    es = statistics.median(run_esmini(esmini, base, 0.01, {k: str(v) for k, v in p.items()}).seconds
                           for p in variants[:5])  # fmt: skip
    name = "/".join(variation.parts[-2:])
    return es / vei, (
        f"vei sweep {name}: {len(variants)} variants ({failed} failed), {vei * 1e3:.1f} ms per variant; "
        f"esmini {es * 1e3:.1f} ms per process: esmini / vei = {es / vei:.1f} (target ≥ 10)"
    )


def _sweep_in_own_process(esmini: str, variation: Path) -> tuple[float, str]:
    """``sweep_figures`` of one file measured in a fresh process."""
    cmd = [sys.executable, __file__, "--esmini", esmini, "--in-process", "--sweep", str(variation)]
    done = subprocess.run(cmd, capture_output=True, text=True, check=True)
    ratio, line = done.stdout.strip().splitlines()[-1].split("\t", 1)
    return float(ratio), line


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--esmini", default=str(ROOT.parent / "shared" / "esmini" / "bin" / "esmini"))
    ap.add_argument("--examples", default=str(ROOT.parent / "shared" / "esmini" / "xosc"))
    ap.add_argument("--ncap", default=str(ROOT.parent / "shared" / "osc-ncap" / "OpenSCENARIO" / "NCAP"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--sweep", action="append", default=[], help="a Euro NCAP variation file (repeatable)")
    ap.add_argument("--sweep-all", action="store_true", help="every variation file of the Euro NCAP pack")
    ap.add_argument("--in-process", action="store_true", help=argparse.SUPPRESS)  # (one file, this process)
    args = ap.parse_args()
    esmini = find_esmini(args.esmini)
    if esmini is None:
        print(f"esmini not found at {args.esmini}", file=sys.stderr)
        return 2
    sweeps = [Path(v) for v in args.sweep] + (full_variations(Path(args.ncap)) if args.sweep_all else [])
    if sweeps:
        ratios = []
        for variation in sweeps:
            if args.in_process:
                ratio, line = sweep_figures(esmini, variation)
                print(f"{ratio!r}\t{line}")
                return 0
            ratio, line = _sweep_in_own_process(args.esmini, variation)
            ratios.append(ratio)
            print(line, flush=True)
        print(
            f"{len(ratios)} variation files: esmini / vei per variant median {statistics.median(ratios):.1f}, "
            f"worst {min(ratios):.1f}; at or above 10 on {sum(r >= 10 for r in ratios)}"
        )
        return 0
    imports, bare = startup_s(args.repeat)
    print(f"start-up: imports of vei run {imports:.3f} s (target ≤ 0.15 s); a bare python process {bare:.3f} s")
    ratios: list[tuple[float, str]] = []
    for name, path, params in cases(Path(args.examples), Path(args.ncap)):
        try:
            run_scenario(path, params, 0.01)  # warm: file caches, as esmini's repeated runs have them
        except VeiInputError:
            continue  # refused (an esmini controller, a traffic swarm): nothing to compare
        try:
            es = [run_esmini(esmini, path, 0.01, params or None).seconds for _ in range(args.repeat)]
        except RuntimeError:
            continue  # esmini fails on it
        vei = []
        for _ in range(args.repeat):
            clear_file_caches()  # (the road and catalogs read as a fresh process reads them)
            a = time.perf_counter()
            run_scenario(path, params, 0.01)
            vei.append(time.perf_counter() - a)
        e, v = statistics.median(es), statistics.median(vei)
        ratios.append((v / e, name))
        row = (name, f"{v:.3f}", f"{e:.3f}", f"{v / e:.2f}")
        print(
            f"| {' | '.join(row)} |" if args.markdown else f"{row[0]:60s} vei {row[1]} s  esmini {row[2]} s  × {row[3]}"
        )
    values = [r for r, _ in ratios]
    worst = max(ratios)
    print(
        f"{len(ratios)} scenarios: vei run / esmini median {statistics.median(values):.2f}, "
        f"worst {worst[0]:.2f} ({worst[1]}); vei faster or equal on {sum(v <= 1 for v in values)}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
