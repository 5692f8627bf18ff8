#!/usr/bin/env python3
"""Time, peak memory and correctness of ``vei clip split`` on a generated drive.

Generates a drive with ``examples/generate_dataset.py`` (default: 30 minutes, 20 e-scooter encounters,
FoV gaps and occlusions, riders and pedestrians beside the path, GPS noise), splits it as a user would
(``python -m vei_scenario clip split``, its own process: start-up included) and prints the wall time,
the peak resident memory of that process, and the clips against the generator's truth: every
encounter in exactly one clip, no clip with two encounters or with none, no road user from beside the
path in a clip. Target: 30 minutes with 20 encounters in <= 10 s and <= 1 GB, every encounter one clip.

    python benchmarks/split_drive.py [--minutes 30] [--encounters 20] [--seed 1]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--minutes", type=float, default=30.0)
    ap.add_argument("--encounters", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="vei-split-bench-") as tmp:
        tmp = Path(tmp)
        gen = [sys.executable, str(ROOT / "examples" / "generate_dataset.py"), "drive", str(tmp)]
        gen += ["--minutes", str(args.minutes), "--encounters", str(args.encounters), "--seed", str(args.seed)]
        subprocess.run(gen, check=True, capture_output=True)
        drive = tmp / "drive.json"
        started = time.perf_counter()
        run = subprocess.run(
            [sys.executable, "-m", "vei_scenario", "clip", "split", str(drive), "-o", str(tmp / "clips")],
            capture_output=True,
            text=True,
        )
        wall = time.perf_counter() - started
        if run.returncode != 0:
            print(run.stderr, file=sys.stderr)
            return 1
        peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024  # (the largest child: the split)
        truth = json.loads((tmp / "drive_truth.json").read_text())
        clips = [json.loads(p.read_text())["extensions"]["vei_split"] for p in sorted((tmp / "clips").glob("*.json"))]
        beside = {b["track_id"] for b in truth["beside"]}
        per_encounter = []
        for enc in truth["encounters"]:
            holding = [
                c
                for c in clips
                if c["t_gps"][0] <= enc["t_gps_rider_at_crossing"] <= c["t_gps"][1]
                and c["t_gps"][0] <= enc["t_gps_ego_at_crossing"] <= c["t_gps"][1]
                and enc["track_id"] in c["tracks"]
            ]
            per_encounter.append(len(holding))
        lost = sum(1 for n in per_encounter if n == 0)
        split_in_two = sum(1 for n in per_encounter if n > 1)
        enc_ids = {e["track_id"] for e in truth["encounters"]}
        merged = sum(1 for c in clips if len(enc_ids & set(c["tracks"])) > 1)
        spurious = sum(1 for c in clips if not enc_ids & set(c["tracks"]))
        with_beside = sum(1 for c in clips if beside & set(c["tracks"]))
        size_mb = drive.stat().st_size / 1e6
        lengths = [c["t_gps"][1] - c["t_gps"][0] for c in clips]
    print(
        f"drive: {args.minutes:g} min, {args.encounters} encounters, {len(beside)} road users beside the path, "
        f"{size_mb:.1f} MB"
    )
    print(f"vei clip split: {wall:.2f} s wall (start-up included), peak RSS {peak_mb:.0f} MB")
    if lengths:
        print(f"clips: {len(clips)}, {min(lengths):.1f}..{max(lengths):.1f} s long")
    print(
        f"against the truth: {args.encounters - lost - split_in_two} of {args.encounters} encounters in exactly one "
        f"clip; lost {lost}, cut in two {split_in_two}, clips merging two encounters {merged}, clips with no "
        f"encounter {spurious}, clips with a road user from beside the path {with_beside}"
    )
    ok = lost == split_in_two == merged == spurious == with_beside == 0 and wall <= 10.0 and peak_mb <= 1024
    print("target (every encounter one clip, <= 10 s, <= 1 GB): " + ("met" if ok else "NOT met"))
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
