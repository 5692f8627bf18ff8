#!/usr/bin/env python3
"""Time of ``vei bench LIBRARY/`` with vei's planner on a generated library, per scenario and where it goes.

Generates N clips with ``examples/generate_dataset.py``, compiles them into a library (``vei compile
CLIPS/ -o LIBRARY/``, timed, and a second time with nothing changed), then runs ``vei bench`` with its
defaults (the five configurations, every TimeShift within 1.5 s of each conflict shift by 0.01 s: 1 505
runs a scenario, through the compiled kernel) as a user would, start-up included, and reports:

1. the bench's wall time, its CPU time, per scenario, and the load average of the machine around it;
2. where a scenario's time goes: a sample of scenarios run one by one on one thread in this process,
   split into reading the scenario (the loop and the kernel's scene), checking the values, preparing
   the kernel's input, the kernel itself, turning its outputs into metric rows and summarising them;
   and writing the outputs (bench.json, report.html, junit.xml) of the whole library;
3. the flawed AEB against vei's planner (``--late K``): the first K clips compiled into a library of
   their own and benched with both systems in one command (``--controller planner --controller
   late=Ego=examples/controllers/aeb.py:AEB --controller-param late:ttc_brake_s=0.6``, the late AEB of
   the guides), configurations 4 and 5 at ``--late-step`` (a Python system runs in the interpreter,
   some 100 times the kernel's cost a run): how many each fails, which the late AEB alone fails.

Target: 1 000 scenarios in <= 10 min on 2 cores; the late AEB fails more scenarios than the planner.

    python benchmarks/bench_library.py [--n 20] [--sample 5] [--late 4] [--work DIR]      (the full figure: --n 1000)

``--work DIR`` keeps the clips, the library and the bench in DIR (a second call reuses the clips and
the compiled library, which then compiles nothing).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
STAGES = ("read the scenario", "check the values", "prepare the kernel's input", "kernel", "metric rows", "summaries")


def _load() -> str:
    return "/".join(f"{x:.2f}" for x in os.getloadavg())


def profile_sample(library: Path, entries: list[dict], step_s: float = 0.01) -> tuple[dict[str, float], int]:
    """Seconds per stage over ``entries``, one scenario after another on one thread, and the runs."""
    from vei_scenario.batch import NativeBatch
    from vei_scenario.bench.run import BenchOptions, _config_summary, shifts
    from vei_scenario.loop import LoopScene
    from vei_scenario.metrics import MetricConfig
    from vei_scenario.study import CONFIGURATIONS

    opts = BenchOptions(step_s=step_s)
    spent = dict.fromkeys(STAGES, 0.0)
    runs = 0

    def timed(stage: str, fn, *args):
        started = time.perf_counter()
        out = fn(*args)
        spent[stage] += time.perf_counter() - started
        return out

    for e in entries:
        xosc = str(library / e["outputs"]["scenario"])
        scene = timed("read the scenario", LoopScene, xosc, opts.dt)
        native = timed("read the scenario", NativeBatch, scene, MetricConfig())
        values = shifts(float(e["conflict_time_shift_s"]), opts)
        variants = [{"TimeShift": repr(s), **cfg} for _, _, cfg in CONFIGURATIONS for s in values]
        accepted = timed("check the values", lambda vs, sc: [sc.kernel_accepts(v) for v in vs], variants, scene)
        ok = [i for i, a in enumerate(accepted) if a]
        rows: list[dict] = [{}] * len(variants)
        for task in native.scene.model_groups(ok, variants, 500):
            prepared = timed("prepare the kernel's input", native.prepare, [variants[i] for i in task])
            out, _ = timed("kernel", native.run, prepared)
            for i, m in zip(task, timed("metric rows", native.rows, out)):
                rows[i] = {"status": "ok", "error": "", "metrics": m}
        runs += len(variants)
        for k in range(len(CONFIGURATIONS)):
            timed("summaries", _config_summary, values, rows[k * len(values) : (k + 1) * len(values)], opts.step_s)
    return spent, runs


def time_outputs(bench_json: Path) -> float:
    """Seconds to write a bench's three outputs again from its document (JSON, the page, JUnit)."""
    from vei_scenario.bench.outputs import bench_html, junit_xml

    doc = json.loads(bench_json.read_text("utf-8"))
    started = time.perf_counter()
    json.dumps(doc, indent=1, allow_nan=False)
    bench_html(doc)
    junit_xml(doc)
    return time.perf_counter() - started


def late_vs_planner(work: Path, clips: list[Path], step_s: float) -> None:
    """The late AEB of the guides and vei's planner on a library of ``clips``, compared."""
    from vei_scenario.library import compile_library

    sub = work / "data" / f"first-{len(clips)}"  # (beside clips/: the clips' maps are at ../maps/)
    sub.mkdir(exist_ok=True)
    for c in clips:
        (sub / c.name).write_bytes(c.read_bytes())
    compile_library(sub, work / f"library-first-{len(clips)}")
    out = work / f"late-vs-planner-{len(clips)}"
    late = f"late=Ego={ROOT / 'examples' / 'controllers' / 'aeb.py'}:AEB"
    started = time.perf_counter()
    r = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "bench", str(work / f"library-first-{len(clips)}"), "-o", str(out),
         "--configurations", "4,5", "--step", str(step_s), "--quiet", "--controller", "planner",
         "--controller", late, "--controller-param", "late:ttc_brake_s=0.6"],
        capture_output=True, text=True,
    )  # fmt: skip
    wall = time.perf_counter() - started
    print(
        f"the late AEB (ttc_brake_s=0.6) against vei's planner, the first {len(clips)} clips, configurations 4 and 5 "
        f"at +-1.5 s by {step_s:g} s ({wall:.0f} s, exit status {r.returncode}; load average {_load()}):"
    )
    for line in r.stdout.splitlines():
        if not line.startswith(("wrote", "  gen-")):
            print(f"  {line.split('; vei run')[0]}")
    c = json.loads((out / "compare.json").read_text("utf-8"))
    print(f"  late AEB only: {', '.join(x['file'] for x in c['only_b']) or 'none'}")
    print(f"  planner only: {', '.join(x['file'] for x in c['only_a']) or 'none'}")


def planner_bench(work: Path, sample_n: int) -> None:
    """``vei bench`` of the library in ``work`` with the defaults, as a user runs it, then where its time goes."""
    print(f"vei bench, the defaults (five configurations, +-1.5 s by 0.01 s); load average {_load()}")
    started = time.perf_counter()
    cmd = [sys.executable, "-m", "vei_scenario", "bench", str(work / "library"), "-o", str(work / "bench")]
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        proc = subprocess.Popen([*cmd, "--quiet"], stdout=out, stderr=err, text=True)
        _, status, usage = os.wait4(proc.pid, 0)  # (its own CPU time and peak memory)
        wall = time.perf_counter() - started
        out.seek(0), err.seek(0)
        stdout, stderr = out.read(), err.read()
    cpu = usage.ru_utime + usage.ru_stime
    if os.waitstatus_to_exitcode(status) not in (0, 1):
        print(stderr, file=sys.stderr)
        return 2
    doc = json.loads((work / "bench" / "bench.json").read_text("utf-8"))
    n = max(doc["benched"], 1)
    runs = sum(c["runs"] for x in doc["results"] if x["status"] == "ok" for c in x["configurations"].values())
    print(f"  {stdout.splitlines()[0]}")
    print(
        f"  wall {wall:.1f} s ({wall / 60:.2f} min; target <= 10 min for 1000), {wall / n:.3f} s a scenario; "
        f"CPU {cpu:.1f} s ({cpu / n:.3f} s a scenario, {cpu / max(runs, 1) * 1e3:.3f} ms a run, {runs} runs); "
        f"peak memory {usage.ru_maxrss / 1024:.0f} MB; load average after {_load()}"
    )
    reasons = Counter(x["error"] for x in doc["results"] if x["status"] != "ok")
    print(f"  {doc['benched']} benched, {doc['failing']} fail; not benched: {dict(reasons) or 'none'}")

    ok = [e for e in json.loads((work / "library" / "library.json").read_text("utf-8"))["scenarios"]]
    ok = [e for e in ok if e.get("status") == "ok" and e.get("conflict_time_shift_s") is not None]
    sample = ok[:sample_n]
    spent, sample_runs = profile_sample(work / "library", sample)
    total = sum(spent.values())
    print(
        f"where a scenario's time goes ({len(sample)} scenarios one by one on one thread: "
        f"{total / max(len(sample), 1):.3f} s each, {sample_runs} runs):"
    )
    for stage, sec in spent.items():
        print(f"  {stage:<28} {sec / max(len(sample), 1) * 1e3:8.1f} ms  {100 * sec / max(total, 1e-9):5.1f} %")
    print(f"  {'writing the outputs':<28} {time_outputs(work / 'bench' / 'bench.json'):8.2f} s for the library")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=20, help="clips in the library (default 20; the target is for 1000)")
    ap.add_argument("--sample", type=int, default=5, help="scenarios timed stage by stage (default 5)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--late", type=int, default=4, help="clips benched with the late AEB and the planner (default 4)")
    ap.add_argument("--late-step", type=float, default=0.1, help="their TimeShift step, s (default 0.1)")
    ap.add_argument("--no-planner", action="store_true", help="skip the planner's bench (with --late K alone)")
    ap.add_argument("--work", type=Path, help="keep clips, library and bench here (default: a temporary folder)")
    args = ap.parse_args(argv)
    from vei_scenario.library import compile_library

    cores = os.cpu_count() or 1
    with tempfile.TemporaryDirectory(prefix="vei-bench-library-") as tmp:
        work = args.work or Path(tmp)
        clips = work / "data" / "clips"
        if not clips.is_dir():
            gen = [sys.executable, str(ROOT / "examples" / "generate_dataset.py"), "clips", str(work / "data")]
            subprocess.run(gen + ["--n", str(args.n), "--seed", str(args.seed)], check=True, capture_output=True)
        print(f"{args.n} generated clips (seed {args.seed}), {cores} cores; load average {_load()} (1/5/15 min)")

        started = time.perf_counter()
        lib = compile_library(clips, work / "library")
        took = time.perf_counter() - started
        print(f"compile: {took:.1f} s ({lib.compiled} compiled, {lib.kept} kept, {len(lib.failed)} with a reason)")
        started = time.perf_counter()
        again = compile_library(clips, work / "library")
        print(f"compile again, nothing changed: {time.perf_counter() - started:.2f} s ({again.kept} kept)")

        if not args.no_planner:
            planner_bench(work, args.sample)
        if args.late:
            late_vs_planner(work, sorted(clips.glob("*.json"))[: args.late], args.late_step)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
