"""``vei``: the command line, a thin layer over the library.

Each sub-command parses its arguments and calls one library function. User errors
(:class:`~vei_scenario.errors.VeiInputError`) print one line ``vei: error: FILE: FIELD: REASON`` and
exit with code 2; validation findings, and a fault of the user's controller while it runs, exit with 1.
"""

from __future__ import annotations

import argparse
import dataclasses
import errno
import json
import math
import os
import sys
import time
from pathlib import Path

from vei_scenario import __version__
from vei_scenario.errors import VeiInputError

EXIT_USER_ERROR = 2
#: A sweep that wrote its catalog but some of whose variants could not be run (their rows say why).
EXIT_VARIANTS_FAILED = 1
#: The user's controller (the system under test) failed while running: raised, or returned no command.
EXIT_CONTROLLER_FAULT = 1


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (``vei: error: ...``, exit 2), as every other user error."""

    def error(self, message: str):  # noqa: D102 (argparse's hook)
        where = self.prog.removeprefix("vei").strip()
        sys.stderr.write(f"vei: error: {where + ': ' if where else ''}{message}\n")
        sys.exit(EXIT_USER_ERROR)


def _number(low: float | None = None, high: float | None = None, *, positive: bool = False, integer: bool = False):
    """An argparse type: a finite number (an integer with ``integer``) within [low, high] (> 0 with
    ``positive``), so that a NaN, an infinity or an absurd value never reaches the library."""

    def parse(text: str):
        shown = text if len(text) <= 40 else text[:37] + "..."
        try:
            value = int(text) if integer else float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{shown!r} is not {'an integer' if integer else 'a number'}") from None
        if not integer and not math.isfinite(value):
            raise argparse.ArgumentTypeError(f"{shown!r} is not a finite number")
        if positive and value <= 0:
            raise argparse.ArgumentTypeError(f"{shown} must be positive")
        if (low is not None and value < low) or (high is not None and value > high):
            lo = "" if low is None else f"{low:g}"
            hi = "" if high is None else f"{high:g}"
            raise argparse.ArgumentTypeError(f"{shown} is outside {lo}..{hi}")
        return value

    parse.__name__ = "integer" if integer else "number"
    return parse


#: The fixed step of every simulating command (s): finer would take hours, coarser breaks the models.
DT = _number(1e-4, 0.5)
WORKERS = _number(1, 1024, integer=True)
SEED = _number(0, 2**63 - 1, integer=True)
FRAME_RATE = _number(0.01, 10_000)
TIME_UNITS = ("s", "ms", "us", "ns")
TIME_UNIT_HELP = "unit of an OpenLABEL clip's timestamps written as numbers (default s; ROS writes ns, nuScenes us)"
FRAME_RATE_HELP = (
    "frame rate of an OpenLABEL clip without timestamps (frame k at k / HZ s; e.g. 10 for KITTI conversions)"
)


def _int_list(text: str) -> tuple[int, ...]:
    try:
        return tuple(sorted({int(v) for v in text.split(",")}))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text[:40]!r} is not a list of numbers like 4,5") from None


def _osc_minor(text: str) -> int:
    parts = text.split(".")
    if len(parts) != 2 or parts[0] != "1" or not parts[1].isdigit():
        raise argparse.ArgumentTypeError(f"expected 1.0, 1.1, 1.2 or 1.3, not {text!r}")
    return int(parts[1])


def _cmd_compile(args: argparse.Namespace) -> int:
    from vei_scenario.compiler import CompileOptions, compile_clip

    opts = CompileOptions(
        rate_hz=args.rate,
        osc_minor_version=args.osc_version,
        osm=Path(args.osm) if args.osm else None,
        osm_fetch=args.osm_fetch,
        no_map=args.no_map,
        threat=args.threat,
        variants_dir=Path(args.variants) if args.variants else None,
        model_parameters=args.model_parameters,
        stochastic=args.stochastic,
        frame_rate_hz=args.frame_rate,
        time_unit=args.time_unit,
    )
    if Path(args.clip).is_dir():
        return _compile_library(args, opts)
    for flag in ("executor", "scheduler", "workers"):
        if getattr(args, flag) is not None:
            raise VeiInputError(None, f"--{flag}", "applies to a folder of clips (vei compile CLIPS/ -o LIBRARY/)")
    from vei_scenario.reports.compile_report import compile_report

    result = compile_clip(args.clip, args.output, opts)
    print(compile_report(result))
    return 0


def _compile_library(args: argparse.Namespace, opts) -> int:
    from tqdm import tqdm

    from vei_scenario.library import compile_library

    files = sum(1 for p in Path(args.clip).iterdir() if p.suffix.lower() == ".json")
    with tqdm(total=files, unit="clip", disable=args.quiet or not sys.stderr.isatty(), leave=False) as bar:
        result = compile_library(
            args.clip, args.output, opts, args.executor or "local", args.scheduler, args.workers, bar.update
        )
    ok = len(result.rows) - len(result.failed)
    print(
        f"{len(result.rows)} clips: {ok} compiled, {len(result.failed)} could not be ({result.compiled} tried in this "
        f"run, {result.kept} unchanged since the last)"
    )
    for r in result.rows[:3]:
        if r["status"] == "ok":
            print(
                f"  #{r['rank']} {r['file']}: threat {r['threat']}, collision margin "
                f"{'-' if r['collision_margin_s'] is None else format(r['collision_margin_s'], '.2f') + ' s'}, "
                f"closest {r['min_centre_distance_m']:.2f} m"
            )
    out = Path(args.output)
    print(f"wrote {out / 'library.json'}, {out / 'library.html'}")
    if result.failed:
        first = result.failed[0]
        print(
            f"vei: {len(result.failed)} of {len(result.rows)} clips could not be compiled; their rows in library.json "
            f"say why (the first: {first['error']})",
            file=sys.stderr,
        )
        return EXIT_VARIANTS_FAILED
    return 0


def _cmd_clip_convert(args: argparse.Namespace) -> int:
    from vei_scenario.clip.openlabel import convert_clip

    path, fmt = convert_clip(args.input, args.output, args.to, args.frame_rate, args.time_unit)
    print(f"wrote {path} ({'ASAM OpenLABEL 1.0' if fmt == 'openlabel' else 'vei-clip/1'})")
    return 0


def _cmd_clip_split(args: argparse.Namespace) -> int:
    from vei_scenario.library.split import SplitOptions, split_drive

    defaults = SplitOptions()
    opts = SplitOptions(
        near_m=args.near,
        horizon_s=args.horizon,
        max_gap_s=args.max_gap,
        pad_before_s=args.pad_before,
        pad_after_s=args.pad_after,
        merge_gap_s=args.merge_gap,
        min_length_s=args.min_length,
        categories=tuple(args.category) if args.category else defaults.categories,
    )
    result = split_drive(args.input, args.output, opts, args.to, args.frame_rate, args.time_unit)
    for part, path in zip(result.interactions, result.written):
        print(
            f"wrote {path}: {part.t_end - part.t_start:.1f} s from {part.t_start - result.t0:.1f} s, "
            f"{', '.join(part.tracks)} (closest {part.closest_m:.1f} m to the ego's path)"
        )
    print(
        f"{len(result.interactions)} interaction(s) in {result.duration_s:.0f} s of {result.source}"
        + (
            ""
            if result.interactions
            else f" (no {'/'.join(opts.categories)} within {opts.near_m:g} m of the ego's path)"
        )
    )
    return 0


def _cmd_bench(args: argparse.Namespace) -> int:
    from tqdm import tqdm

    from vei_scenario.bench import BenchOptions, parse_systems, read_bench, read_library, run_bench, write_compare

    if args.compare:
        if args.library or args.controller or args.controller_param:
            raise VeiInputError(None, "--compare", "compares two bench.json files: give no LIBRARY and no --controller")
        a, b = read_bench(args.compare[0]), read_bench(args.compare[1])
        return _print_compare(write_compare(a, b, args.output), Path(args.output))
    if not args.library:
        raise VeiInputError(None, "LIBRARY", "missing: vei bench LIBRARY -o OUT (or --compare A.json B.json -o OUT)")
    opts = BenchOptions(half_width_s=args.half_width, step_s=args.step, dt=args.dt, workers=args.workers)
    if args.configurations:
        opts = dataclasses.replace(opts, configurations=args.configurations)
    opts.check()
    systems = parse_systems(args.controller, args.controller_param, args.controller_timeout)
    total = len(read_library(args.library))
    out = Path(args.output)
    docs = []
    for system in systems:
        where = out / system.label if len(systems) > 1 else out
        with tqdm(total=total, unit="scenario", disable=args.quiet or not sys.stderr.isatty(), leave=False) as bar:
            started = time.perf_counter()
            doc = run_bench(args.library, where, opts, bar.update, system)
            took = time.perf_counter() - started
        share = "-" if doc["failure_share"] is None else f"{100 * doc['failure_share']:.1f} %"
        print(
            f"{system.label}: {doc['scenarios']} scenarios, {doc['benched']} benched: {doc['failing']} fail ({share}): "
            f"the ego collides while moving with the system on, or a run fails ({took:.1f} s, "
            f"{took / max(doc['benched'], 1):.2f} s a scenario)"
        )
        _print_sut(system.controllers)
        for w in doc["worst"][:3]:
            what = (
                f"ego at {w['ego_speed_at_contact_mps']:.2f} m/s"
                if w["ego_speed_at_contact_mps"] is not None
                else "a run failed"
            )
            print(f"  {w['file']}: {what} at TimeShift {w['time_shift_s']:+.2f} s; {w['reproduce']}")
        print(f"wrote {where / 'bench.json'}, {where / 'report.html'}, {where / 'junit.xml'}")
        docs.append(doc)
    if len(docs) == 2:
        return _print_compare(write_compare(docs[0], docs[1], out), out)
    return 1 if docs[0]["failing"] else 0


def _print_compare(c: dict, out: Path) -> int:
    """What two benchmarks differ in; 1 when the second system fails a scenario the first passes."""
    la, lb = c["a"]["label"], c["b"]["label"]
    print(
        f"{c['compared']} scenarios benched by both: {la} fails {c['a_failing']}, {lb} fails {c['b_failing']}; "
        f"{len(c['only_b'])} fail with {lb} only, {len(c['only_a'])} with {la} only"
    )
    for r in c["only_b"][:5]:
        print(f"  {lb} only: {r['file']}; {r['b']['reproduce']}")
    print(f"wrote {out / 'compare.json'}, {out / 'compare.html'}")
    return 1 if c["only_b"] else 0


def _cmd_examples(args: argparse.Namespace) -> int:
    from vei_scenario.examples import copy_examples

    paths = copy_examples(args.directory, args.force)
    clip = Path(args.directory) / "case_study" / "clip.json"
    print(f"wrote {len(paths)} files under {args.directory}; try: vei compile {clip} -o out/case_study/scenario.xosc")
    return 0


def _cmd_validate(args: argparse.Namespace) -> int:
    from vei_scenario.openscenario.validation import format_problems, validate_files

    files = [Path(f) for f in args.files]
    try:
        problems = validate_files(files)
    except VeiInputError as exc:
        if args.format != "json":
            raise
        print(json.dumps({"valid": False, "files": [str(f) for f in files], "problems": [], "error": str(exc)}))
        return EXIT_USER_ERROR
    print(format_problems(problems, args.format, files))
    return 1 if problems else 0


def _cmd_run(args: argparse.Namespace) -> int:
    from vei_scenario.metrics import MetricConfig
    from vei_scenario.runner import parse_param_overrides, run_to, summary_text
    from vei_scenario.variation import distributed_scenario

    values = parse_param_overrides(args.param)
    controllers = _controllers(args)
    if not args.dist and (base := distributed_scenario(args.scenario)) is not None:  # a distribution alone
        args.scenario, args.dist = base, args.scenario
    if args.dist:  # a variant of a ParameterValueDistribution (esmini's --param_dist/--param_permutation)
        from vei_scenario.interpreter.document import load_scenario
        from vei_scenario.variation import read_distribution

        variants = read_distribution(args.dist, load_scenario(args.scenario).parameter_types, None)
        if not 0 <= args.permutation < len(variants):
            raise VeiInputError(args.dist, "--permutation", f"{args.permutation} is not in 0..{len(variants) - 1}")
        values = {**variants[args.permutation], **values}  # (--param still wins)
    report = run_to(
        args.scenario,
        args.output,
        values,
        args.dt,
        plots=not args.no_plots,
        coupling=args.coupling,
        osi=args.osi,
        cfg=MetricConfig(zone_ttc=args.zone_ttc),
        progress=True,
        controllers=controllers,
    )
    for w in report.metrics.get("warnings", ()):
        print(f"vei: warning: {w}", file=sys.stderr)
    print(summary_text(report.metrics))
    for p in report.written:
        print(f"wrote {p}")
    return 0


def _models(names: list[str]) -> list[str]:
    from vei_scenario.fmu import MODELS

    return list(MODELS) if not names or "all" in names else names


def _cmd_fmu_build(args: argparse.Namespace) -> int:
    from vei_scenario.fmu import build_fmus
    from vei_scenario.runner import parse_param_overrides

    values = parse_param_overrides(args.param) if args.scenario else None
    if args.osmp:
        from vei_scenario.fmu.osmp_native import missing
        from vei_scenario.fmu.osmp_rider import KINDS, build_osmp

        models = _models(args.models)
        if not args.scenario or any(m not in KINDS for m in models):
            raise VeiInputError(None, "--osmp", "builds the rider (sfm) and the planner (cap) from a scenario: "
                                "vei fmu build sfm cap --osmp --scenario XOSC")  # fmt: skip
        if args.fmi != 2:
            raise VeiInputError(None, "--fmi", "OSMP traffic participants are FMI 2.0 FMUs; use --fmi 2")
        backend = args.backend or "native"
        why = missing() if backend == "native" else None
        if why and args.backend is None:  # (asked for nothing in particular: the pythonfmu participant)
            print(f"vei: note: {why}; building pythonfmu participants instead, which need Python with "
                  "vei-scenario where they run", file=sys.stderr)  # fmt: skip
            backend = "python"
        for m in models:
            print(f"wrote {build_osmp(m, args.scenario, Path(args.output), values, backend)}")
        return 0
    built = build_fmus(_models(args.models), args.output, args.backend or "native", args.fmi, args.scenario, values)
    for path in built.values():
        print(f"wrote {path}")
    return 0


def _cmd_fmu_system(args: argparse.Namespace) -> int:
    from vei_scenario.fmu import build_system
    from vei_scenario.runner import parse_param_overrides

    path = build_system(args.scenario, args.output, parse_param_overrides(args.param), args.dt, args.backend, args.fmi,
                        tuple(args.leave_out))  # fmt: skip
    print(f"wrote {path}")
    return 0


def _cmd_fmu_cosim(args: argparse.Namespace) -> int:
    from vei_scenario.fmu import cosimulate
    from vei_scenario.fmu.cosim import write_record_csv
    from vei_scenario.runner import parse_param_overrides

    rep = cosimulate(
        args.scenario, args.engine, parse_param_overrides(args.param), args.dt, args.coupling, args.backend, args.fmi,
        leave_out=tuple(args.leave_out),
    )  # fmt: skip
    dev = ", ".join(f"{k} {v:.3g} m" for k, v in rep.max_deviation_m.items())
    print(f"{args.engine} ({rep.coupling} coupling, {rep.steps} steps): largest deviation from vei run: {dev}")
    for note in rep.loop.notes:
        print(f"note: {note}")
    if args.output:
        print(f"wrote {write_record_csv(rep.record, rep.loop, Path(args.output))}")
    worst = max(rep.max_deviation_m.values())
    return 0 if worst <= args.tolerance else 1


def _cmd_study(args: argparse.Namespace) -> int:
    from vei_scenario.study import run_study, table_text

    zone = "approx" if args.paper else args.zone_ttc
    controllers = _controllers(args)
    report = run_study(
        args.input, args.output, args.dt, args.time_shift, plots=not args.no_plots, zone_ttc=zone,
        controllers=controllers,
    )  # fmt: skip
    print(f"{report.scenario}: five configurations at TimeShift {report.time_shift_s:+.3f} s")
    _print_sut(controllers)
    print(table_text(report.rows))
    print(f"wrote {len(report.written)} files under {args.output}")
    return 0


def _cmd_sweep(args: argparse.Namespace) -> int:
    from vei_scenario.reports.plot_worker import PlotWorker

    controllers = _controllers(args)
    plotter = PlotWorker()  # forked first: it imports matplotlib while this process imports the sweep
    try:
        from vei_scenario.sweep import run_sweep

        report = run_sweep(
            args.scenario,
            args.output,
            args.vary,
            args.dist,
            args.seed,
            args.dt,
            args.executor,
            args.scheduler,
            args.workers,
            args.emit_xosc,
            args.quiet,
            plotter,
            args.osi_traces,
            args.osi_format,
            args.zone_ttc,
            controllers,
        )
    finally:
        plotter.close()
    for w in report.warnings:
        print(f"vei: warning: {w}", file=sys.stderr)
    _print_sut(controllers)
    ok = [r for r in report.rows if r["status"] == "ok"]
    coll = sum(1 for r in ok if r["metrics"].get("collision"))
    moving = sum(1 for r in ok if r["metrics"].get("collision_ego_moving"))
    print(
        f"{len(report.rows)} variants ({', '.join(report.varied)}): {coll} collide ({moving} with the ego moving), "
        f"{len(ok) - coll} do not, {len(report.rows) - len(ok)} failed"
    )
    out = Path(args.output)
    print(f"wrote {out / 'catalog.csv'}, {out / 'catalog.json'}, {out / 'report.html'}")
    failed = [r for r in report.rows if r["status"] != "ok"]
    if failed:  # (a script or CI gate must not take a catalog with holes for a whole one)
        first = failed[0]
        print(
            f"vei: {len(failed)} of {len(report.rows)} variants failed; their rows in catalog.csv say why "
            f"(the first, variant {first['variant']}: {first.get('error') or first['status']})",
            file=sys.stderr,
        )
        return EXIT_VARIANTS_FAILED
    return 0


def _cmd_describe(args: argparse.Namespace) -> int:
    from vei_scenario.language import describe_command

    return describe_command(args)


def _cmd_behaviours(args: argparse.Namespace) -> int:
    from vei_scenario.language.behaviours import BEHAVIOURS

    for name, mod in BEHAVIOURS.items():
        print(f"{name:15s} {mod.AGENT}: {mod.SUMMARY}")
        if args.verbose:
            for p, v in mod.PARAMETERS.items():
                print(f"    {p:18s} default {v.default:g}, {v.low:g}..{v.high:g}: {v.doc}")
            for cls, ranges in mod.PROFILES.items():
                spans = ", ".join(f"{k} {lo:g}..{hi:g}" for k, (lo, hi) in ranges.items())
                print(f"    {cls:18s} {spans}")
    return 0


def _pair(text: str) -> tuple[float, float]:
    parts = text.split(":")
    try:
        lo, hi = float(parts[0]), float(parts[1])
    except (IndexError, ValueError):
        raise argparse.ArgumentTypeError(f"expected LOW:HIGH, not {text!r}") from None
    if not (math.isfinite(lo) and math.isfinite(hi)):
        raise argparse.ArgumentTypeError(f"{text!r}: LOW and HIGH must be finite numbers")
    if len(parts) != 2 or hi < lo:
        raise argparse.ArgumentTypeError(f"expected LOW:HIGH with LOW <= HIGH, not {text!r}")
    return lo, hi


def _cmd_risk(args: argparse.Namespace) -> int:
    from vei_scenario.risk import find_risk

    results = find_risk(
        args.scenario,
        args.output,
        args.target,
        args.vary,
        args.band,
        args.window,
        args.coarse,
        args.tol,
        args.dt,
        args.workers,
        _controllers(args),
    )
    for r in results:
        fixed = ", ".join(f"{k}={v}" for k, v in r.parameters.items() if k in {v.split("=")[0] for v in args.vary})
        spans = "; ".join(f"TimeShift {a:+.3f}..{b:+.3f} s" for a, b in r.intervals) or "none found"
        print(f"{args.target} {('(' + fixed + ') ') if fixed else ''}: {spans} [{r.evaluations} runs]")
        for note in r.open_edges:
            print(f"  note: {note}: widen --window")
    if args.output:
        print(f"wrote {args.output}/risk.json and the critical scenarios")
    failed = [(r, f) for r in results for f in r.failed]
    if failed:
        r, (shift, error) = failed[0]
        runs = sum(r.evaluations for r in results)
        print(f"vei: {len(failed)} of {runs} runs failed in the system under test (the first, TimeShift "
              f"{shift:g}: {error})", file=sys.stderr)  # fmt: skip
        return 1
    return 0


def _cmd_falsify(args: argparse.Namespace) -> int:
    from vei_scenario.falsify import SYSTEM_FAULT, bounds_from_distribution, falsify, parse_bounds
    from vei_scenario.runner import parse_param_overrides

    axes = bounds_from_distribution(args.dist) if args.dist else []
    given = parse_bounds(args.bounds, args.values) if (args.bounds or args.values or not axes) else []
    axes = [a for a in axes if a.name not in {g.name for g in given}] + given  # the command line wins
    result = falsify(
        args.scenario, axes, parse_param_overrides(args.param), args.target, args.slices, args.tol,
        seed=args.seed, dt=args.dt, workers=args.workers, out_dir=args.output, controllers=_controllers(args),
        allow_default_controller=args.allow_default_controller,
    )  # fmt: skip
    print(f"{len(result.regions)} failure region(s) of {args.target} found in {result.runs} runs")
    for r in result.regions:
        fixed = ", ".join(f"{k}={v}" for k, v in r.discrete.items())
        worst = "the system under test failed" if r.worst_robustness <= SYSTEM_FAULT else f"{r.worst_robustness:.3f}"
        print(f"region {r.number}{' (' + fixed + ')' if fixed else ''}: {r.primary} {r.low:+.4f}..{r.high:+.4f} "
              f"over {len(r.windows)} slice(s); worst robustness {worst}")  # fmt: skip
        print(f"  reproduce: {r.reproduce(args.scenario)}")
    if args.output:
        regions = f" and each region's worst scenario under {args.output}/regions/" if result.regions else ""
        print(f"wrote {args.output}/falsify.json{regions}")
    if result.failed_runs:
        values, error = result.failed_runs[0]
        shown = ", ".join(f"{k}={v}" for k, v in values.items())
        print(f"vei: {len(result.failed_runs)} of {result.runs} runs failed in the system under test, counted as "
              f"failures (the first, {shown}: {error})", file=sys.stderr)  # fmt: skip
        return 1
    return 0


def _cmd_probability(args: argparse.Namespace) -> int:
    from vei_scenario.atomic_io import json_text, write_bytes_atomic
    from vei_scenario.probability import estimate_probability, random_seed
    from vei_scenario.runner import parse_param_overrides

    estimators = ("monte-carlo", "importance-sampling") if args.estimator == "both" else (args.estimator,)
    results = estimate_probability(
        args.scenario, args.dist, args.target, estimators, args.runs, parse_param_overrides(args.param),
        args.band, args.seed, args.dt, args.workers, _controllers(args), args.allow_default_controller,
    )  # fmt: skip
    if results:
        how = (
            "--seed"
            if args.seed is not None
            else "the distribution's randomSeed"
            if random_seed(args.dist) is not None
            else "no --seed, no randomSeed in the file"
        )
        print(f"sampling with seed {results[0].seed} ({how})")
    for e in results:
        extra = f", {e.levels} level(s)" if e.estimator == "importance-sampling" else ""
        print(
            f"P({args.target}) = {e.probability:.6g}, 95 % interval [{e.low:.6g}, {e.high:.6g}] "
            f"({e.estimator}: {e.runs} runs{extra}, {e.failures} failing)"
        )
    by = {e.estimator: e for e in results}
    if len(by) == 2 and by["importance-sampling"].width > 0 and by["monte-carlo"].width > 0:
        mc, imp = by["monte-carlo"], by["importance-sampling"]
        needed = mc.runs * (mc.width / imp.width) ** 2  # Monte Carlo's width shrinks as 1/sqrt(runs)
        print(f"for the importance-sampling interval width Monte Carlo needs ~{needed:.3g} runs "
              f"({needed / imp.runs:.1f}x the runs importance sampling took)")  # fmt: skip
    if args.output:
        doc = {"scenario": str(args.scenario), "distribution": str(args.dist), "target": args.target,
               "fixed": parse_param_overrides(args.param), "seed": results[0].seed if results else args.seed,
               "estimates": [e.as_dict() for e in results]}  # fmt: skip
        if args.controller:
            from vei_scenario.sut import sut_document

            doc["system_under_test"] = sut_document(_controllers(args))
        write_bytes_atomic(Path(args.output), (json_text(doc, indent=2) + "\n").encode())
        print(f"wrote {args.output}")
    return 0


def _cmd_view(args: argparse.Namespace) -> int:
    from vei_scenario.reports.viewer import show, view_run_dir, view_scenario, write_animation
    from vei_scenario.runner import parse_param_overrides

    src = Path(args.input)
    if src.is_dir():
        view = view_run_dir(src, args.scenario)
    elif src.is_file():
        view = view_scenario(src, parse_param_overrides(args.param), args.dt, _controllers(args))
    else:
        raise VeiInputError(src, "input", "not found (a .xosc scenario or a directory written by vei run -o)")
    if args.output:
        print(f"wrote {write_animation(view, args.output, args.fps, args.speed, progress=True)}")
    else:
        show(view, args.fps, args.speed)
    return 0


def _cmd_check(args: argparse.Namespace) -> int:
    from vei_scenario.ci_check import run_suite

    results = run_suite(args.suite, args.junit)
    for r in results:
        state = "ERROR" if r.errors else "FAIL" if r.failures else "ok"
        print(f"{state:<6}{r.case.name} ({r.seconds:.2f} s)")
        for line in r.errors + r.failures + [f"warning: {w}" for w in r.warnings]:
            print(f"      {line}")
    bad = sum(1 for r in results if r.errors or r.failures)
    print(f"{len(results) - bad} passed, {bad} failed")
    return 1 if bad else 0


ZONE_TTCS = ("2d", "approx")  # (metrics.series.ZONE_TTCS; not imported here: it would load numpy)
ZONE_HELP = (
    "the TTC that the zones (safe >= 3 s, attention 2-3 s, alert < 2 s) and the safety index use: 2d (default: "
    "the exact time until the boxes touch, right for crossing paths) or approx (the seed paper's gap / ego speed "
    "to a road user ahead in the ego's lane band, blind to crossings); both minima are always reported"
)
BACKEND_HELP = "native: C models compiled into the FMU (default); python: pythonfmu (needs the [fmu] extra)"


CONTROLLER_HELP = (
    "drive ENTITY's speed by your own controller, the system under test, from the start to the end: "
    "ENTITY=path/file.py:Class or ENTITY=package.module:Class (step(obs) returns the acceleration in m/s²; "
    "the entity keeps its path or lane); constructed with the scenario's controller properties of that entity"
)


def _controller_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--controller", action="append", default=[], metavar="ENTITY=TARGET", help=CONTROLLER_HELP)
    p.add_argument(
        "--controller-param",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="a property for the --controller class's constructor (a keyword argument, as text)",
    )
    p.add_argument(
        "--controller-timeout",
        type=_number(1e-3, 1e6),
        metavar="SECONDS",
        help="the longest one step(obs) of the --controller may take (wall clock); a run (a sweep's variant) "
        "over it fails with one line instead of hanging (default: no limit)",
    )


def _controllers(args: argparse.Namespace) -> tuple:
    """The systems under test the command line plugs in, loaded and checked before anything runs."""
    if not args.controller and not args.controller_param and args.controller_timeout is None:
        return ()
    from vei_scenario.sut import parse_controller_options

    if args.controller_timeout is not None and not args.controller:
        raise VeiInputError(None, "--controller-timeout", "given without --controller")
    return parse_controller_options(args.controller, args.controller_param, args.controller_timeout)


def _print_sut(controllers: tuple) -> None:
    """One line per system under test: what the results are of."""
    for s in controllers:
        d = s.describe()
        print(f"system under test on {d['entity']}: {d['controller']} (sha256 {(d['sha256'] or '-')[:12]})")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="vei", description="Annotated vehicle–e-scooter clips → ASAM OpenSCENARIO/OpenDRIVE test scenarios."
    )
    parser.add_argument("--version", action="version", version=f"vei-scenario {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    c = sub.add_parser(
        "compile",
        help="compile an annotated clip (or a folder of clips: a library) into OpenSCENARIO + OpenDRIVE",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Compile one clip into a scenario, or every clip (*.json) of a folder into a library:\n"
        "  LIBRARY/scenarios/NAME/  scenario.xosc, .xodr, .variations.xosc, thumbnail.svg, row.json\n"
        "  LIBRARY/library.json     a row per clip, ranked by closeness to a collision (the smallest timing\n"
        "                           change that makes the boxes touch, then the conflict margin, then the\n"
        "                           closest distance); a clip that could not be compiled is a row with why\n"
        "  LIBRARY/library.html     the same as a page, with map thumbnails\n"
        "A clip whose file, map and options are unchanged since the last run is not compiled again. Exit 1\n"
        "when some clips could not be compiled (the rest are compiled).",
    )
    c.add_argument("clip", help="annotated clip (vei-clip/1 or ASAM OpenLABEL 1.0 JSON), or a folder of them")
    c.add_argument(
        "-o",
        "--output",
        required=True,
        help="scenario file to write (.xosc; .xodr and .variations.xosc go beside it), or the library folder",
    )
    c.add_argument(
        "--rate", type=_number(0.5, 1000), default=10.0, help="output rate of the trajectories in Hz (default 10)"
    )
    c.add_argument("--osc-version", type=_osc_minor, default=3, help="OpenSCENARIO version 1.0..1.3 (default 1.3)")
    c.add_argument("--osm", help="OpenStreetMap XML file (overrides the clip's map.osm)")
    c.add_argument(
        "--osm-fetch", action="store_true", help="download the map by bounding box (needs network and osmnx)"
    )
    c.add_argument("--no-map", action="store_true", help="ignore any map and fit a road to the ego track")
    c.add_argument("--threat", help="track id of the threat scooter (default: smallest conflict margin)")
    c.add_argument("--variants", metavar="DIR", help="also write one fully resolved .xosc per variation into DIR")
    c.add_argument(
        "--model-parameters",
        action="store_true",
        help="also declare the rider's and the planner's model parameters (RiderDesiredSpeed, RiderRepulsion, "
        "PlannerTimeHeadway, PlannerMaxDecel, PlannerStandstillGap) so that sweeps and vei falsify vary them",
    )
    c.add_argument(
        "--stochastic",
        action="store_true",
        help="also write STEM.stochastic.xosc, a stochastic ParameterValueDistribution for vei probability: "
        "TimeShift normal around ConflictTimeShift (standard deviation half the collision interval), the rider "
        "type uniform",
    )
    c.add_argument("--frame-rate", type=FRAME_RATE, metavar="HZ", help=FRAME_RATE_HELP)
    c.add_argument("--time-unit", choices=TIME_UNITS, help=TIME_UNIT_HELP)
    c.add_argument(
        "--executor",
        choices=("local", "dask"),
        help="a folder: local worker processes on all cores (default), or dask: a Dask cluster",
    )
    c.add_argument("--scheduler", help="a folder with --executor dask: the scheduler (default: a LocalCluster)")
    c.add_argument("--workers", type=WORKERS, help="a folder: local worker processes (default: all cores)")
    c.add_argument("--quiet", action="store_true", help="a folder: no progress bar")
    c.set_defaults(func=_cmd_compile)

    ex = sub.add_parser("examples", help="copy the bundled example clips (and their map) into a directory")
    ex.add_argument("directory", help="where to put them (created if needed)")
    ex.add_argument("--force", action="store_true", help="overwrite example files already there")
    ex.set_defaults(func=_cmd_examples)

    cl = sub.add_parser(
        "clip", help="annotated clips: convert between vei-clip/1 and ASAM OpenLABEL 1.0; split a drive into clips"
    )
    clsub = cl.add_subparsers(dest="clip_command", required=True, parser_class=_Parser)
    cv = clsub.add_parser(
        "convert", help="write a clip as ASAM OpenLABEL 1.0, or an OpenLABEL annotation as vei-clip/1"
    )
    cv.add_argument("input", help="vei-clip/1 or OpenLABEL 1.0 JSON file")
    cv.add_argument("-o", "--output", required=True, help="file to write (.json)")
    cv.add_argument("--to", choices=("openlabel", "vei-clip"), help="output format (default: the other one)")
    cv.add_argument("--frame-rate", type=FRAME_RATE, metavar="HZ", help=FRAME_RATE_HELP)
    cv.add_argument("--time-unit", choices=TIME_UNITS, help=TIME_UNIT_HELP)
    cv.set_defaults(func=_cmd_clip_convert)
    sp = clsub.add_parser(
        "split",
        help="cut a long recording into interaction clips (a vulnerable road user near the ego's path)",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Cut a drive into clips where a road user of --category comes within --near m of the ego's\n"
        "path (where the ego is from --horizon s before to --horizon s after; consecutive observations up to\n"
        "--max-gap s apart are joined, so a rider crossing between them counts). A track's near times are one\n"
        "interaction unless more than --max-gap s apart; each starts --pad-before s earlier, ends --pad-after s\n"
        "later and lasts at least --min-length s; interactions that overlap or are less than --merge-gap s\n"
        "apart are one clip. Each clip's extensions.vei_split says where it came from (source file, SHA-256,\n"
        "time range) and by which rules.",
    )
    sp.add_argument("input", help="the recording: vei-clip/1 or OpenLABEL 1.0 JSON (up to 24 h)")
    sp.add_argument("-o", "--output", required=True, help="folder for the clips (ID.NNN.json)")
    sp.add_argument("--near", type=_number(positive=True), default=3.5, help="how near the ego's path, m (3.5)")
    sp.add_argument("--horizon", type=_number(positive=True), default=5.0, help="the ego's path: +-S s (5)")
    sp.add_argument("--max-gap", type=_number(positive=True), default=10.0, help="longest gap bridged, s (10)")
    sp.add_argument("--pad-before", type=_number(0), default=6.0, help="padding before, s (6)")
    sp.add_argument("--pad-after", type=_number(0), default=3.0, help="padding after, s (3)")
    sp.add_argument(
        "--merge-gap", type=_number(0), default=0.0, help="merge clips closer than this, s (0: overlapping)"
    )
    sp.add_argument("--min-length", type=_number(positive=True), default=5.0, help="shortest clip, s (5)")
    sp.add_argument(
        "--category",
        action="append",
        metavar="NAME",
        help="a road-user category to look for (repeatable, any case; default: e-scooter, escooter, e_scooter, "
        "scooter)",
    )
    sp.add_argument("--to", choices=("vei-clip", "openlabel"), default="vei-clip", help="clip format (vei-clip)")
    sp.add_argument("--frame-rate", type=FRAME_RATE, metavar="HZ", help=FRAME_RATE_HELP)
    sp.add_argument("--time-unit", choices=TIME_UNITS, help=TIME_UNIT_HELP)
    sp.set_defaults(func=_cmd_clip_split)

    bn = sub.add_parser(
        "bench",
        help="a system under test (vei's planner or your own) over every scenario of a library, searched "
        "around each conflict; JUnit for CI; two systems compared",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="For every scenario of LIBRARY (vei compile CLIPS/ -o LIBRARY/): the seed paper's five\n"
        "configurations (replay/normal/aggressive rider, planner off/on) at every TimeShift within\n"
        "--half-width s of its conflict shift, every --step s. The system under test drives the ego where\n"
        "the planner is on (4, 5): vei's planner or a native FMU (--controller Ego=planner.fmu) through\n"
        "the compiled sweep kernel, a Python class (Ego=file.py:Class) or a PythonFMU through the\n"
        "interpreter. A scenario fails when, with the system on, the ego collides while moving, or a run\n"
        "fails. Writes bench.json, report.html and junit.xml (one test case per scenario); exit 1 when\n"
        "some scenario fails.\n\n"
        "Two systems: --controller A --controller B (each [LABEL=]ENTITY=TARGET, or planner) bench both\n"
        "into OUT/LABEL/ and write OUT/compare.json and compare.html: the scenarios one fails and the other\n"
        "does not; --compare A/bench.json B/bench.json -o OUT compares two earlier runs. Exit 1 when the\n"
        "second fails a scenario the first passes.",
    )
    bn.add_argument("library", nargs="?", help="a scenario library folder (with library.json)")
    bn.add_argument(
        "-o", "--output", required=True, help="folder for bench.json, report.html, junit.xml (compare.json, .html)"
    )
    bn.add_argument(
        "--compare",
        nargs=2,
        metavar=("A", "B"),
        help="compare two earlier benchmarks (their bench.json or folders) instead of running one",
    )
    bn.add_argument(
        "--half-width", type=_number(0, 30), default=1.5, help="TimeShift search: +-S s around the conflict (1.5)"
    )
    bn.add_argument("--step", type=_number(0.001, 10), default=0.01, help="TimeShift search step, s (0.01)")
    bn.add_argument("--dt", type=DT, default=0.01, help="fixed step in s (default 0.01)")
    bn.add_argument(
        "--configurations",
        type=_int_list,
        metavar="N,N",
        help="the configurations to run (default 1,2,3,4,5; 4 and 5 have the planner on)",
    )
    bn.add_argument(
        "--workers",
        type=WORKERS,
        help="cores: threads of the sweep kernel, worker processes for a plugged --controller (default: all)",
    )
    bn.add_argument("--quiet", action="store_true", help="no progress bar")
    bn.add_argument(
        "--controller",
        action="append",
        default=[],
        metavar="[LABEL=]ENTITY=TARGET",
        help="the system under test instead of vei's planner: ENTITY=path/file.py:Class, ENTITY=package.module:Class "
        "or ENTITY=planner.fmu (labelled by its class or file unless LABEL= is given); planner names vei's; "
        "give it twice to compare two systems",
    )
    bn.add_argument(
        "--controller-param",
        action="append",
        default=[],
        metavar="[LABEL:]NAME=VALUE",
        help="a property for the --controller's constructor (to every plugged system, or to LABEL's)",
    )
    bn.add_argument(
        "--controller-timeout",
        type=_number(1e-3, 1e6),
        metavar="SECONDS",
        help="the longest one step(obs) of the --controller may take (wall clock); a run over it fails",
    )
    bn.set_defaults(func=_cmd_bench)

    r = sub.add_parser("run", help="run a scenario with the built-in interpreter; write trajectories, metrics, plots")
    r.add_argument(
        "scenario", help="OpenSCENARIO file (.xosc), or a ParameterValueDistribution (its ScenarioFile's run)"
    )
    r.add_argument("--param", action="append", default=[], metavar="NAME=VALUE", help="override a parameter")
    r.add_argument("--dt", type=DT, default=0.01, help="fixed step in s (default 0.01)")
    r.add_argument("-o", "--output", help="directory for trajectories.csv, metrics.json and plots")
    r.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    r.add_argument("--zone-ttc", choices=ZONE_TTCS, default="2d", help=ZONE_HELP)
    r.add_argument(
        "--dist", help="take the parameter values from a ParameterValueDistribution (as esmini's --param_dist)"
    )
    r.add_argument(
        "--permutation",
        type=_number(0, 10_000_000, integer=True),
        default=0,
        help="which variant of --dist (or of a distribution given as the scenario) to run, counted from 0 "
        "(as esmini's --param_permutation)",
    )
    r.add_argument(
        "--osi",
        metavar="TRACE",
        help="also write an ASAM OSI 3.8 ground-truth trace, one GroundTruth per step (.mcap, or .osi: "
        "length-prefixed binary)",
    )
    r.add_argument(
        "--coupling",
        choices=("sequential", "jacobi"),
        default="sequential",
        help="how entities see each other within a step: sequential (default) or jacobi (as a co-simulation "
        "master stepping all FMUs on the previous outputs)",
    )
    _controller_options(r)
    r.set_defaults(func=_cmd_run)

    st = sub.add_parser("study", help="the seed paper's five configurations at the collision timing shift")
    st.add_argument("input", help="clip (.json) or compiled scenario (.xosc)")
    st.add_argument("-o", "--output", required=True, help="directory for the study")
    st.add_argument("--dt", type=DT, default=0.01, help="fixed step in s (default 0.01)")
    st.add_argument(
        "--time-shift", type=_number(-3600, 3600), help="TimeShift to use (default: the scenario's ConflictTimeShift)"
    )
    st.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    st.add_argument("--zone-ttc", choices=ZONE_TTCS, default="2d", help=ZONE_HELP)
    st.add_argument(
        "--paper", action="store_true", help="the seed paper's table: zones and safety index from its approximate TTC"
    )
    _controller_options(st)
    st.set_defaults(func=_cmd_study)

    sw = sub.add_parser(
        "sweep",
        help="run a catalog of parameter variants; catalog.csv/json and report.html",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Run every variant (the cartesian product of --vary, or a --dist file) and write:\n"
        "  catalog.csv / catalog.json  one row per variant: its parameters and every metric of vei run\n"
        "  report.html  first the grid (each swept parameter's values and step: a sweep runs its points,\n"
        "      nothing between them); then a table per configuration (the varied parameters but\n"
        "      TimeShift): variants, collisions, whether the planner was on (CapEnabled), the lowest\n"
        "      safety index S, the longest time in the TTC alert zone and the lowest minimum TTC;\n"
        "      configurations that collide with the planner on come first, and every such collision (a\n"
        "      failure of the system under test) is listed with the command that reproduces it. With\n"
        "      none, where the grid shows signs of narrower failure windows (collisions with the planner\n"
        "      off, near misses with it on) it says so and gives the vei risk / vei falsify commands that\n"
        "      search between the points. Near misses with the planner on (no contact; minimum gap under\n"
        "      0.5 m or minimum TTC at most 1.5 s) are listed, the closest first. Then plots over\n"
        "      TimeShift: S (share of the run outside the alert and collision zones; 0 on contact), the\n"
        "      minimum 2-D TTC (time until the boxes touch at constant velocities) and the minimum gap\n"
        "      between the boxes, collision regions shaded, series with equal values in their own marker\n"
        "      and dash with a legend note; then the most severe collisions (by impact speed, the relative\n"
        "      speed at first contact) and the closest passes (by minimum gap, then TTC).",
    )
    sw.add_argument(
        "scenario", help="OpenSCENARIO file (.xosc), or a ParameterValueDistribution alone (its ScenarioFile swept)"
    )
    sw.add_argument(
        "--vary",
        action="append",
        default=[],
        metavar="NAME=A:B:STEP|NAME=V1,V2",
        help="a varied parameter (repeatable; the catalog is their cartesian product)",
    )
    sw.add_argument("--dist", help="take variants from an OpenSCENARIO ParameterValueDistribution file")
    sw.add_argument("--seed", type=SEED, help="seed of stochastic distributions (default: the file's randomSeed)")
    sw.add_argument("-o", "--output", required=True, help="directory for catalog.csv, catalog.json, report.html")
    sw.add_argument("--dt", type=DT, default=0.01, help="fixed step in s (default 0.01)")
    sw.add_argument(
        "--executor",
        choices=("local", "dask"),
        default="local",
        help="local: the compiled kernel on all cores (else worker processes); dask: a Dask cluster",
    )
    sw.add_argument("--scheduler", help="Dask scheduler address (default: a LocalCluster on this machine)")
    sw.add_argument("--workers", type=WORKERS, help="local worker processes (default: all cores)")
    sw.add_argument("--emit-xosc", action="store_true", help="also write one scenario file per variant")
    sw.add_argument("--quiet", action="store_true", help="no progress bar")
    sw.add_argument("--zone-ttc", choices=ZONE_TTCS, default="2d", help=ZONE_HELP)
    sw.add_argument(
        "--osi-traces",
        metavar="WHICH",
        help="also write an ASAM OSI ground-truth trace of chosen variants into traces/: collisions, failures "
        "(collisions with CapEnabled=true), all, or variant numbers 3,17,42",
    )
    sw.add_argument("--osi-format", choices=("mcap", "osi"), default="mcap", help="trace format (default mcap)")
    _controller_options(sw)
    sw.set_defaults(func=_cmd_sweep)

    rk = sub.add_parser(
        "risk",
        help="find the TimeShift intervals of collisions or near misses (exhaustive scan and bisection)",
        description="For each combination of --vary, the TimeShift intervals (s, the rider's delay against the "
        "recording) where the target holds: a collision, or a near miss (minimum 2-D TTC within --band, no "
        "contact). With the compiled kernel the window is scanned at --tol, so no interval as wide as --tol is "
        "missed, and edges are bisected to a quarter of it; [N runs] counts the simulations. risk.json and the "
        "start/middle/end scenario of every interval are written with -o.",
    )
    rk.add_argument("scenario", help="vei-compiled OpenSCENARIO file (.xosc)")
    rk.add_argument(
        "--target",
        choices=("collision", "collision_any", "near-miss"),
        default="collision",
        help="what to find: collisions with the ego moving (default; > 0.1 m/s at the first contact), every "
        "collision (collision_any) or near misses (minimum TTC within --band)",
    )
    rk.add_argument("--vary", action="append", default=[], help="other parameters to search separately")
    rk.add_argument("--band", type=_pair, default=(0.5, 1.5), help="near-miss band of the minimum TTC, s (0.5:1.5)")
    rk.add_argument("--window", type=_pair, help="TimeShift window (default: ConflictTimeShift ± 6 s)")
    rk.add_argument("--coarse", type=_number(1e-3, 60), default=0.5, help="bracketing step, s (default 0.5)")
    rk.add_argument("--tol", type=_number(1e-4, 10), default=0.01, help="edge tolerance, s (default 0.01)")
    rk.add_argument("--dt", type=DT, default=0.01, help="fixed step in s (default 0.01)")
    rk.add_argument("--workers", type=WORKERS, help="worker processes (default: all cores)")
    rk.add_argument("-o", "--output", help="directory for risk.json and the critical scenarios")
    _controller_options(rk)
    rk.set_defaults(func=_cmd_risk)

    fz = sub.add_parser(
        "falsify",
        help="search a box of parameters for the failures of the system under test (clustered, edges refined)",
        description="Search --bounds (NAME=LOW:HIGH, continuous) crossed with --values (NAME=V1,V2, discrete) for "
        "failures: a collision, or a metric target such as min_ttc_s<1.0. One continuous parameter (TimeShift when "
        "searched) is the primary axis: each slice of the others is scanned along it, every dip of the robustness "
        "(the box gap; negative on contact: -(1 + impact speed)) is scanned at --tol, failures are bisected to their "
        "window's edges; windows on neighbouring slices form a region when they overlap or a probe between them "
        "finds the band; each region's extreme edges are refined between slices; its worst run is written as a "
        ".xosc with a reproduce command.",
    )
    fz.add_argument("scenario", help="OpenSCENARIO file (.xosc)")
    fz.add_argument("--bounds", action="append", default=[], metavar="NAME=LOW:HIGH", help="a continuous range")
    fz.add_argument("--values", action="append", default=[], metavar="NAME=V1,V2", help="a discrete set")
    fz.add_argument("--dist", help="take the box from a ParameterValueDistribution (ranges and value sets)")
    fz.add_argument("--param", action="append", default=[], metavar="NAME=VALUE", help="fix a parameter")
    fz.add_argument(
        "--target",
        default="collision",
        help="collision (default: a collision with the ego moving, > 0.1 m/s at the first contact: a failure of "
        "the system that drives it), collision_any (every contact) or METRIC<VALUE, e.g. min_ttc_s<1.0",
    )
    fz.add_argument(
        "--slices", type=_number(2, 200, integer=True), default=7, help="slices per other range (default 7)"
    )
    fz.add_argument(
        "--tol", type=_number(1e-5, 10), default=0.005, help="edge tolerance on the primary axis (default 0.005)"
    )
    fz.add_argument(
        "--seed", type=SEED, default=0, help="seed of the Sobol slices (two or more other ranges; default 0)"
    )
    fz.add_argument("--dt", type=DT, default=0.01, help="fixed step in s (default 0.01)")
    fz.add_argument("--workers", type=WORKERS, help="worker threads or processes (default: all cores)")
    fz.add_argument("-o", "--output", help="directory for falsify.json and the regions' worst scenarios")
    _controller_options(fz)
    fz.add_argument(
        "--allow-default-controller",
        action="store_true",
        help="search although a controller the scenario names is one vei has no model of (it plays as the "
        "default controller; refused otherwise, as the failures found would not be any system's)",
    )
    fz.set_defaults(func=_cmd_falsify)

    pr = sub.add_parser(
        "probability",
        help="P(collision) or P(near miss) under a stochastic distribution: Monte Carlo and importance sampling",
        description="Estimate how likely the target is when the parameters follow the stochastic "
        "ParameterValueDistribution --dist (others fixed by --param or their defaults). monte-carlo: the share "
        "of failing runs among draws from the distribution, Wilson's 95 % interval. importance-sampling: "
        "levels learn where failures are (kernels around the worst runs), then each failure of a fresh sample "
        "is weighted by nominal / proposal density; the interval from the weights' standard error. Both "
        "report their runs; the second needs far fewer for the same width when failures are rare.",
    )
    pr.add_argument("scenario", help="OpenSCENARIO file (.xosc)")
    pr.add_argument("--dist", required=True, help="stochastic ParameterValueDistribution file")
    pr.add_argument(
        "--target",
        choices=("collision", "collision_any", "near-miss"),
        default="collision",
        help="what counts: collision (default: the ego moving at the first contact), collision_any, near-miss",
    )
    pr.add_argument(
        "--estimator",
        choices=("monte-carlo", "importance-sampling", "both"),
        default="both",
        help="which estimate(s) to make (default both, with how many Monte Carlo runs the same width would take)",
    )
    pr.add_argument(
        "--runs", type=_number(100, 10_000_000, integer=True), default=20000, help="runs per estimator (default 20000)"
    )
    pr.add_argument("--param", action="append", default=[], metavar="NAME=VALUE", help="fix a parameter")
    pr.add_argument("--band", type=_pair, default=(0.5, 1.5), help="near-miss band of the minimum TTC, s")
    pr.add_argument("--seed", type=SEED, help="seed of the sampling (default: the distribution's randomSeed, else 0)")
    pr.add_argument("--dt", type=DT, default=0.01, help="fixed step in s (default 0.01)")
    pr.add_argument("--workers", type=WORKERS, help="worker threads or processes (default: all cores)")
    pr.add_argument("-o", "--output", help="write the estimates as JSON here")
    _controller_options(pr)
    pr.add_argument(
        "--allow-default-controller",
        action="store_true",
        help="search although a controller the scenario names is one vei has no model of (it plays as the "
        "default controller; refused otherwise, as the failures found would not be any system's)",
    )
    pr.set_defaults(func=_cmd_probability)

    vw = sub.add_parser("view", help="play a run on its road: moving boxes, trails, TTC zones, the collision")
    vw.add_argument("input", help="scenario (.xosc, run here) or a directory written by vei run -o")
    vw.add_argument("-o", "--output", help="write an animation (.gif, or .mp4 with ffmpeg) instead of a window")
    vw.add_argument("--param", action="append", default=[], metavar="NAME=VALUE", help="override a parameter")
    vw.add_argument("--dt", type=DT, default=0.01, help="fixed step in s of the run (default 0.01)")
    vw.add_argument(
        "--fps", type=_number(0.1, 240), default=10.0, help="frames per second of the animation (default 10)"
    )
    vw.add_argument("--speed", type=_number(0.01, 1000), default=1.0, help="playback speed, × real time (default 1)")
    vw.add_argument("--scenario", help="with a run directory: the scenario, for the road and the boxes")
    _controller_options(vw)
    vw.set_defaults(func=_cmd_view)

    ck = sub.add_parser("check", help="run a suite of scenario expectations (for CI); JUnit XML")
    ck.add_argument("suite", help="suite file (.toml)")
    ck.add_argument("--junit", help="write JUnit XML here")
    ck.set_defaults(func=_cmd_check)

    fm = sub.add_parser("fmu", help="the models as FMI co-simulation FMUs; the closed loop as SSP; co-simulation")
    fsub = fm.add_subparsers(dest="fmu_command", required=True, parser_class=_Parser)
    fb = fsub.add_parser("build", help="build FMUs: sfm (e-scooter), cap (planner), ego (vehicle) or all")
    fb.add_argument("models", nargs="*", metavar="MODEL", help="sfm, cap, ego or all (default: all)")
    fb.add_argument("-o", "--output", default="fmus/dist", help="directory for the .fmu files (default fmus/dist)")
    fb.add_argument("--backend", choices=("native", "python"), default=None, help=BACKEND_HELP)
    fb.add_argument("--fmi", type=int, choices=(2, 3), default=2, help="FMI version (default 2)")
    fb.add_argument(
        "--scenario",
        metavar="XOSC",
        help="vei-compiled scenario whose values become the FMUs' start values (and stop time)",
    )
    fb.add_argument("--param", action="append", default=[], metavar="NAME=VALUE", help="override a scenario parameter")
    fb.add_argument(
        "--osmp",
        action="store_true",
        help="the rider (sfm) or the planner with its vehicle (cap) as an ASAM OSI traffic participant (OSMP: "
        "SensorView in, TrafficUpdate out), with the --scenario's values: native C FMUs that need neither vei nor "
        "Python to run (built with protoc-c and libprotobuf-c); where those are missing, and without --backend "
        "native, pythonfmu FMUs that need Python with vei-scenario to run (--backend python builds those)",
    )
    fb.set_defaults(func=_cmd_fmu_build)
    fs = fsub.add_parser("system", help="the scenario's closed loop (ego + scooter + planner) as an SSP 1.0 package")
    fs.add_argument("scenario", help="vei-compiled OpenSCENARIO file (.xosc)")
    fs.add_argument("-o", "--output", required=True, help="SSP file to write (.ssp)")
    fs.add_argument("--param", action="append", default=[], metavar="NAME=VALUE", help="override a parameter")
    fs.add_argument("--dt", type=DT, default=0.01, help="communication step in s (default 0.01)")
    fs.add_argument("--backend", choices=("native", "python"), default="native", help=BACKEND_HELP)
    fs.add_argument("--fmi", type=int, choices=(2, 3), default=2, help="FMI version of the FMUs (default 2)")
    fs.add_argument(
        "--leave-out",
        action="append",
        default=[],
        metavar="ENTITY",
        help="a road user that is no rider, left out of the loop (it replays its track; nothing in the loop "
        "reacts to it)",
    )
    fs.set_defaults(func=_cmd_fmu_system)
    fc = fsub.add_parser("cosim", help="run the closed loop in a co-simulation engine and compare it with vei run")
    fc.add_argument("scenario", help="vei-compiled OpenSCENARIO file (.xosc)")
    fc.add_argument(
        "--engine",
        choices=("fmpy", "libcosim"),
        default="fmpy",
        help="co-simulation master: fmpy (default) or libcosim (needs the [fmu] extra)",
    )
    fc.add_argument("--coupling", choices=("sequential", "jacobi"), help="fmpy master only (default sequential)")
    fc.add_argument("--param", action="append", default=[], metavar="NAME=VALUE", help="override a parameter")
    fc.add_argument("--dt", type=DT, default=0.01, help="communication step in s (default 0.01)")
    fc.add_argument("--backend", choices=("native", "python"), default="native", help=BACKEND_HELP)
    fc.add_argument("--fmi", type=int, choices=(2, 3), default=2, help="FMI version of the FMUs (default 2)")
    fc.add_argument(
        "--leave-out",
        action="append",
        default=[],
        metavar="ENTITY",
        help="a road user that is no rider, left out of the loop (it replays its track; nothing in the loop "
        "reacts to it)",
    )
    fc.add_argument("--tolerance", type=_number(0, 1e6), default=1e-6, help="exit 1 above this deviation in m (1e-6)")
    fc.add_argument("-o", "--output", help="write the co-simulated trajectories (CSV) here")
    fc.set_defaults(func=_cmd_fmu_cosim)

    d = sub.add_parser("describe", help="scenarios from a description (LinguaSim method): generate, run, score, refine")
    d.add_argument("text", nargs="?", help="the description (quote it); or --layers FILE")
    d.add_argument("-o", "--output", required=True, help="output directory")
    d.add_argument("--layers", help="a layers JSON file (vei-layers/1) instead of a description")
    d.add_argument(
        "--count", type=_number(1, 10_000, integer=True), default=32, help="scenarios to generate (default 32)"
    )
    d.add_argument("--seed", type=SEED, default=0, help="seed of the sampling (default 0); scenario i uses seed*1000+i")
    d.add_argument(
        "--backend",
        choices=("rules", "llm", "local"),
        default="rules",
        help="rules (offline, default), llm (an OpenAI-compatible endpoint) or local (a GGUF model through "
        "llama-cpp-python: pip install vei-scenario[llm-local])",
    )
    d.add_argument("--llm-url", help="OpenAI-compatible endpoint base URL (or VEI_LLM_URL)")
    d.add_argument("--llm-model", help="model name (or VEI_LLM_MODEL); with --backend local a GGUF file")
    d.add_argument("--refine", action="store_true", help="adjust towards the description's intent, up to 5 runs each")
    d.add_argument("--jobs", type=WORKERS, default=None, help="worker processes (default: the CPU count)")
    d.add_argument("--layers-only", action="store_true", help="write the layers JSON of each scenario, run nothing")
    d.set_defaults(func=_cmd_describe)

    b = sub.add_parser("behaviours", help="list the atomic behaviours of vei describe")
    b.add_argument("-v", "--verbose", action="store_true", help="with their parameters and criticality ranges")
    b.set_defaults(func=_cmd_behaviours)

    v = sub.add_parser("validate", help="check .xosc/.xodr files against the ASAM XSDs and VEI's own rules")
    v.add_argument("files", nargs="+", help=".xosc and .xodr files")
    v.add_argument("--format", choices=("text", "json"), default="text", help="text (default) or JSON for other tools")
    v.set_defaults(func=_cmd_validate)
    return parser


def _one_line(text: str) -> str:
    """Messages from libraries (libxml2, compilers) may span lines: one line, control characters shown."""
    return " ".join(text.split()) if any(c in text for c in "\n\r\t") else text.replace("\x00", "\\0")


def _os_error(exc: OSError) -> str:
    """``PATH: reason`` of a file-system error, in words a user can act on."""
    reasons = {
        errno.ENOSPC: "no space left on the device",
        errno.EDQUOT: "disk quota exceeded",
        errno.EACCES: "permission denied",
        errno.EPERM: "operation not permitted",
        errno.EROFS: "read-only file system",
        errno.ENOTDIR: "a path component is a file, not a folder",
        errno.EISDIR: "is a folder, not a file",
        errno.EEXIST: "a file is in the way (a folder is needed there)",
        errno.ENAMETOOLONG: "file name too long",
        errno.ENOENT: "no such file or folder",
    }
    reason = reasons.get(exc.errno, exc.strerror or str(exc) or type(exc).__name__)
    where = exc.filename if exc.filename is not None else ""
    if exc.filename2 is not None:
        where = f"{where} -> {exc.filename2}"
    return _one_line(f"{where}: {reason}" if where != "" else reason)


def main(argv: list[str] | None = None) -> int:
    # vei's numpy work is element-wise; idle OpenBLAS threads would only spin beside the sweep's own
    # worker threads (set before numpy is first imported, which the commands do lazily)
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version (0) or a refused argument (2, said in one line)
        return int(exc.code or 0) if not isinstance(exc.code, str) else EXIT_USER_ERROR
    from vei_scenario.sut.contract import ControllerFault

    try:
        return args.func(args)
    except ControllerFault as exc:  # the user's code: one line; at load (no step time) it is bad input
        print(f"vei: error: {_one_line(str(exc))}", file=sys.stderr)
        return EXIT_USER_ERROR if exc.t_s is None else EXIT_CONTROLLER_FAULT
    except VeiInputError as exc:
        print(f"vei: error: {_one_line(str(exc))}", file=sys.stderr)
        return EXIT_USER_ERROR
    except BrokenPipeError:  # the reader went away (e.g. `vei ... | head`): stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141
    except OSError as exc:  # an output (or input) the file system refused: path and reason, one line
        print(f"vei: error: {_os_error(exc)}", file=sys.stderr)
        return EXIT_USER_ERROR
    except RecursionError:
        print("vei: error: the input is nested too deeply to read", file=sys.stderr)
        return EXIT_USER_ERROR
    except KeyboardInterrupt:
        print("vei: interrupted", file=sys.stderr)
        return 130


def console() -> None:
    """The ``vei`` command: :func:`main`, then the process ends (:func:`~vei_scenario.process_end.end_process`:
    without the finalisers of any FMU library the command loaded)."""
    from vei_scenario.process_end import end_process

    end_process(main())


if __name__ == "__main__":
    console()
