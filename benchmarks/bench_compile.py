#!/usr/bin/env python3
"""Compile time and peak memory of ``vei compile``.

Runs each compile as its own process (``python -m vei_scenario.cli compile``), as a user would, and
prints the wall time (start-up included) and the peak resident memory of that process, for the bundled
examples and for a synthetic 30-minute clip with 20 crossing scooters on a fitted road.
Targets (issue #2): case study < 3 s; 30-minute clip ≤ 30 s and ≤ 1 GB.

    python benchmarks/bench_compile.py [--repeat N] [--skip-long]
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def _generator():
    spec = importlib.util.spec_from_file_location("generate_examples", ROOT / "examples" / "generate_examples.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules["generate_examples"] = mod
    spec.loader.exec_module(mod)
    return mod


def synthetic_long_clip(path: Path, minutes: float = 30.0, scooters: int = 20) -> None:
    """A winding 30-minute drive at ~8 m/s, 20 scooters crossing at spread-out times."""
    g = _generator()
    duration = minutes * 60.0
    length = 8.6 * duration + 200
    ego_path = g.curvature_path(
        np.array([0.0, 0.0]),
        0.3,
        length,
        lambda s: 0.004 * np.sin(2 * np.pi * s / 900.0) + 0.002 * np.sin(2 * np.pi * s / 230.0),
    )
    ego = g.Mover(ego_path, 20.0, 8.0, 0.5, 40.0)
    actors = []
    for k in range(scooters):
        t_cross = (k + 0.5) * duration / scooters
        ex, ey, eyaw, _ = ego.state(t_cross)
        side = 1 if k % 2 else -1
        heading = float(eyaw) + side * math.radians(75.0)
        d = np.array([math.cos(heading), math.sin(heading)])
        cp = np.array([float(ex), float(ey)])
        path_k = g.straight_path(cp - 45 * d, cp + 45 * d, 0.0, sway=(0.2, 17.0))
        m = g.Mover(path_k, 0.0, 4.3, 0.3, 9.0)
        m.s0 = g.s_of_point(path_k, cp) - float(m.s(t_cross - 1.5 - 0.1 * k) - m.s0)
        actors.append(g.Actor(f"scooter_{k + 1:02d}", "e-scooter", m))
    spec = g.ClipSpec(
        name="long",
        clip_id="synthetic-30min",
        frame=g.LocalFrame(48.137, 11.575),
        ego=ego,
        actors=actors,
        duration_s=duration,
        y_axis="right",
        time_offset_s=0.2,
        first_frame_s=0.5,
        osm=None,
        seed=5,
    )
    clip, _ = g.build_clip(spec, noise=True)
    path.write_text(json.dumps(clip))


def run_compile(clip: Path, out_dir: Path, extra: list[str] | None = None) -> tuple[float, float, str]:
    """(wall s, peak RSS MiB, stdout) of one compile in a child process."""
    cmd = [
        sys.executable,
        "-c",
        "import resource, sys; from vei_scenario.cli import main; rc = main(sys.argv[1:]); "
        "print('PEAK_KB', resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, file=sys.stderr); sys.exit(rc)",
        "compile",
        str(clip),
        "-o",
        str(out_dir / "scenario.xosc"),
        *(extra or []),
    ]
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        raise SystemExit(f"compile of {clip} failed:\n{proc.stderr}")
    # Peak of the vei process itself; netconvert, its child, stays far below it (~40 MiB here).
    peak_kb = next(int(ln.split()[1]) for ln in proc.stderr.splitlines() if ln.startswith("PEAK_KB"))
    return wall, peak_kb / 1024, proc.stdout


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeat", type=int, default=3, help="runs per example (the best and the median are shown)")
    ap.add_argument("--skip-long", action="store_true", help="skip the 30-minute clip")
    args = ap.parse_args()
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores")
    print(f"{'clip':<28}{'best s':>9}{'median s':>10}{'peak MiB':>10}  notes")
    with tempfile.TemporaryDirectory(prefix="vei-bench-") as tmp:
        tmp = Path(tmp)
        for name in ("case_study", "multi_scooter", "no_map"):
            walls, peaks = [], []
            for i in range(args.repeat):
                w, p, _ = run_compile(ROOT / "examples" / name / "clip.json", tmp / f"{name}{i}")
                walls.append(w)
                peaks.append(p)
            note = "target < 3 s" if name == "case_study" else ""
            print(f"{name:<28}{min(walls):>9.2f}{float(np.median(walls)):>10.2f}{max(peaks):>10.0f}  {note}")
        w, p, _ = run_compile(
            ROOT / "examples" / "case_study" / "clip.json",
            tmp / "variants",
            ["--variants", str(tmp / "variants" / "v")],
        )
        print(f"{'case_study --variants (36)':<28}{w:>9.2f}{w:>10.2f}{p:>10.0f}")
        if not args.skip_long:
            clip = tmp / "long.json"
            t0 = time.perf_counter()
            synthetic_long_clip(clip)
            gen = time.perf_counter() - t0
            w, p, out = run_compile(clip, tmp / "long")
            n_fix = len(json.loads(clip.read_text())["ego"]["samples"])
            print(
                f"{'synthetic 30 min, 20 scoot.':<28}{w:>9.2f}{w:>10.2f}{p:>10.0f}  target ≤ 30 s, ≤ 1024 MiB; "
                f"{n_fix} GPS fixes, {clip.stat().st_size / 1e6:.1f} MB clip (generated in {gen:.1f} s)"
            )
            threat = next((ln for ln in out.splitlines() if ln.startswith("THREAT")), "")
            print(f"  {threat[:110]}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
