#!/usr/bin/env python3
"""Time of ``vei compile CLIPS/ -o LIBRARY/`` on a generated dataset, per clip and where it goes.

Generates N clips with ``examples/generate_dataset.py`` and measures:

1. the library compiled on all local cores (wall time, and per clip: wall x cores / N core-seconds);
2. a second run with nothing changed (every clip's row kept);
3. every output checked against the ASAM XSDs (``vei validate``), timed apart;
4. where a clip's time goes: a sample of clips compiled one after another in this process under
   cProfile, attributed to the stages (netconvert: the wait for it in this process plus its own CPU
   time in the child; map crop; reconstruction; conflict analysis and model; OpenDRIVE finishing and
   the lane check; writing XML; the thumbnail);
5. with ``--dask``, the same library on a local Dask cluster, compared byte for byte.

Targets: 1 000 clips in <= 10 min on 2 cores, a rerun in <= 10 s, every output schema-valid, Dask
byte-identical.

    python benchmarks/compile_library.py [--n 20] [--sample 5] [--dask]      (the full figure: --n 1000)
"""

from __future__ import annotations

import argparse
import cProfile
import os
import pstats
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: Stages of a compile and the functions whose cumulative time is theirs (file suffix, function name).
STAGES = [
    ("load and check the clip", "clip/__init__.py", "load_clip"),
    ("crop the map", "roads/osm_region.py", "crop_osm"),
    ("start netconvert", "roads/netconvert.py", "__init__"),
    ("wait for netconvert", "roads/netconvert.py", "result"),
    ("reconstruction (splines, SLERP)", "geometry/reconstruct.py", "reconstruct"),
    ("conflict analysis and model", "scenario/model.py", "build_model"),
    ("OpenDRIVE finishing", "roads/opendrive_output.py", "finalize_opendrive"),
    ("lane check (ego on lanes)", "roads/opendrive_lanes.py", "share_on_lanes"),
    ("lane polygons", "roads/opendrive_lanes.py", "read_lane_areas_from_bytes"),
    ("write OpenSCENARIO XML", "openscenario/scenario_writer.py", "scenario_xml"),
    ("write the variations", "openscenario/distribution_writer.py", "distribution_xml"),
    ("write the files", "atomic_io.py", "commit"),
    ("thumbnail", "library/thumbnail.py", "thumbnail_svg"),
]


def _tree(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def profile_sample(clips: list[Path], out: Path) -> tuple[float, dict[str, float], float]:
    """Compile ``clips`` one by one in this process under cProfile: wall time, seconds per stage,
    netconvert's own CPU seconds (its child processes)."""
    from vei_scenario.compiler import CompileOptions
    from vei_scenario.library.build import Job, compile_job

    jobs = [Job(p.name, str(p), str(out / p.stem), f"scenarios/{p.stem}", None, None, CompileOptions()) for p in clips]
    compile_job(jobs[0])  # (imports and first-touch caches out of the measurement)
    child0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    prof = cProfile.Profile()
    started = time.perf_counter()
    prof.enable()
    for job in jobs[1:]:
        compile_job(job)
    prof.disable()
    wall = time.perf_counter() - started
    child1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    netconvert_cpu = (child1.ru_utime - child0.ru_utime) + (child1.ru_stime - child0.ru_stime)
    stats = pstats.Stats(prof).stats
    stages: dict[str, float] = {}
    for label, suffix, name in STAGES:
        stages[label] = sum(
            ct for (file, _, func), (_, _, _, ct, _) in stats.items() if func == name and file.endswith(suffix)
        )
    return wall, stages, netconvert_cpu


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=20, help="clips in the library (default 20; the target is for 1000)")
    ap.add_argument("--sample", type=int, default=5, help="clips compiled under the profiler (default 5)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--dask", action="store_true", help="also compile on a local Dask cluster and compare bytes")
    ap.add_argument("--no-validate", action="store_true", help="skip the XSD check of every output")
    args = ap.parse_args(argv)
    from vei_scenario.library import compile_library
    from vei_scenario.openscenario.validation import validate_files

    cores = os.cpu_count() or 1
    with tempfile.TemporaryDirectory(prefix="vei-library-bench-") as tmp:
        tmp = Path(tmp)
        gen = [sys.executable, str(ROOT / "examples" / "generate_dataset.py"), "clips", str(tmp / "data")]
        subprocess.run(gen + ["--n", str(args.n), "--seed", str(args.seed)], check=True, capture_output=True)
        clips = tmp / "data" / "clips"

        started = time.perf_counter()
        first = compile_library(clips, tmp / "lib")
        wall = time.perf_counter() - started
        started = time.perf_counter()
        again = compile_library(clips, tmp / "lib")
        rerun = time.perf_counter() - started
        ok = [r for r in first.rows if r["status"] == "ok"]
        print(
            f"library of {args.n} generated clips on {cores} cores: {wall:.1f} s wall, {len(ok)} compiled, "
            f"{len(first.failed)} rows with a reason"
        )
        print(
            f"  per clip: {wall / args.n:.3f} s wall, {wall * cores / args.n:.3f} core-s; "
            f"1000 clips at this rate: {1000 * wall / args.n / 60:.1f} min (target <= 10 min)"
        )
        for r in first.failed[:5]:
            print(f"  could not be compiled: {r['error']}")
        print(
            f"  second run, nothing changed: {rerun:.2f} s ({again.kept} rows kept, {again.compiled} compiled; "
            f"target <= 10 s for 1000: {rerun * 1000 / args.n:.1f} s at this rate)"
        )
        if not args.no_validate:
            files = [tmp / "lib" / r["outputs"][k] for r in ok for k in ("scenario", "road", "variations")]
            started = time.perf_counter()
            problems = validate_files(files)
            print(
                f"  XSD check of {len(files)} outputs: {len(problems)} problems ({time.perf_counter() - started:.1f} s)"
            )
        if args.dask:
            started = time.perf_counter()
            compile_library(clips, tmp / "lib-dask", executor="dask")
            same = _tree(tmp / "lib") == _tree(tmp / "lib-dask")
            print(f"  Dask LocalCluster: {time.perf_counter() - started:.1f} s, byte-identical: {same}")

        sample = sorted(clips.glob("*.json"))[: args.sample + 1]
        s_wall, stages, nc_cpu = profile_sample(sample, tmp / "profiled")
        n = len(sample) - 1
        print(
            f"where a clip's time goes (mean of {n} clips compiled one by one in one process: "
            f"{s_wall / n:.3f} s wall each):"
        )
        for label, sec in stages.items():
            print(f"  {label:<34} {sec / n * 1000:7.1f} ms")
        print(f"  {'netconvert CPU (child process)':<34} {nc_cpu / n * 1000:7.1f} ms  (overlaps the reconstruction)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
