"""``run_sweep``: evaluate a catalog of variants and write catalog.csv, catalog.json and report.html."""

from __future__ import annotations

import gc
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path

from vei_scenario.atomic_io import OutputSet
from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter.document import load_scenario
from vei_scenario.metrics.series import MetricConfig
from vei_scenario.reports.plot_worker import PlotWorker
from vei_scenario.sweep.catalog import catalog_csv, catalog_json, variant_xosc
from vei_scenario.sweep.evaluate import evaluate_dask, evaluate_local, iter_rows
from vei_scenario.sweep.preflight import preflight
from vei_scenario.sweep.report_html import planner_on, plot_inputs, report_html
from vei_scenario.variation import cartesian, distributed_scenario, parse_vary, read_distribution

#: At most this many traces per sweep (each is a full interpreted run and ~0.4 MB).
MAX_TRACES = 1000


def trace_selection(rows: list[dict], which: str) -> list[dict]:
    """The rows whose variants get an OSI trace: ``collisions`` (every variant that collides),
    ``failures`` (collisions with the planner on, CapEnabled=true, and the ego moving), ``all``, or variant numbers
    ``3,17,42``."""
    ok = [r for r in rows if r["status"] == "ok"]
    if which == "all":
        chosen = ok
    elif which == "collisions":
        chosen = [r for r in ok if r["metrics"].get("collision")]
    elif which == "failures":
        chosen = [r for r in ok if r["metrics"].get("collision_ego_moving") and planner_on(r)]
    else:
        try:
            wanted = {int(v) for v in which.split(",") if v.strip()}
        except ValueError:
            raise VeiInputError(
                None, "--osi-traces", f"{which!r} is not collisions, failures, all or variant numbers (3,17)"
            ) from None
        by_number = {r["variant"]: r for r in ok}
        missing = sorted(wanted - set(by_number))
        if missing:
            raise VeiInputError(None, "--osi-traces", f"no successful variant numbered {missing[0]}")
        chosen = [by_number[k] for k in sorted(wanted)]
    if len(chosen) > MAX_TRACES:
        raise VeiInputError(
            None, "--osi-traces", f"{len(chosen)} traces asked for; at most {MAX_TRACES} (choose variants)"
        )
    return chosen


def _add_traces(
    files: OutputSet, out: Path, scenario: Path, rows, which: str, fmt: str, dt: float, controllers: tuple = ()
) -> None:
    from vei_scenario.interpreter import run_scenario
    from vei_scenario.reports.osi_trace import trace_bytes

    for r in trace_selection(rows, which):
        rel = f"traces/variant_{r['variant']:05d}.{fmt}"
        result = run_scenario(scenario, r["parameters"], dt, controllers=controllers)
        files.add(out / rel, trace_bytes(result, "." + fmt, f"vei sweep variant {r['variant']} of {scenario.name}"))
        r["osi_trace"] = rel


@dataclass
class SweepReport:
    rows: list[dict]
    written: list[Path]
    varied: list[str]
    #: what ``vei run`` would say it plays in its own way (a controller without a model, Init actions
    #: reading each other in a circle), for the first variant: said once, not per variant
    warnings: list[str] = field(default_factory=list)


def scenario_warnings(scenario: Path, values: dict[str, str], dt: float, controllers: tuple = ()) -> list[str]:
    """The warnings building the scenario with ``values`` gives (the simulation is set up, not run);
    none when it cannot be built (the variants' rows say why)."""
    from vei_scenario.errors import VeiError
    from vei_scenario.interpreter import Simulation

    try:
        return list(Simulation(load_scenario(scenario, values), dt, controllers=controllers).ctx.warnings)
    except (VeiError, ValueError, ArithmeticError):
        return []


def _progress_bar(total: int, quiet: bool):
    """A tqdm bar with rate and ETA on a terminal; nothing in CI or when piped."""
    if quiet or os.environ.get("CI") or not sys.stderr.isatty():
        return None
    from tqdm import tqdm

    tqdm.monitor_interval = 0  # no monitor thread: the local executor forks worker processes
    return tqdm(total=total, unit="variant", dynamic_ncols=True, file=sys.stderr)


def build_variants(
    scenario: Path, vary: list[str], dist: Path | None, seed: int | None
) -> tuple[list[dict], list[str]]:
    doc = load_scenario(scenario)
    declared = doc.parameter_types
    defaults = dict(doc.parameters)
    axes = [parse_vary(v, declared) for v in vary]
    if dist is not None:
        extra = read_distribution(dist, declared, seed)
        base = cartesian(axes, defaults) if axes else [dict(defaults)]
        variants = [{**b, **e} for e in extra for b in base]
        varied = list(dict.fromkeys([a[0] for a in axes] + [k for e in extra for k in e]))
    else:
        if not axes:
            raise VeiInputError(None, "--vary", "nothing to vary: give --vary or --dist")
        variants = cartesian(axes, defaults)
        varied = [a[0] for a in axes]
    return _follow_derived(scenario, variants, varied), varied


def _follow_derived(scenario: Path, variants: list[dict], varied: list[str]) -> list[dict]:
    """Parameters declared from others (``_speed = ${$speed_kph/3.6}``) take each variant's values,
    not the defaults' (unless varied themselves)."""
    from vei_scenario.interpreter.document import derived_parameters, redeclare

    decls, derived = derived_parameters(scenario)
    if not derived or derived.issubset(varied):
        return variants
    out = []
    for v in variants:
        scope, _ = redeclare(scenario, decls, {n: str(v[n]) for n in varied if n in v})
        out.append({**v, **{k: scope[k] for k in derived if k not in varied and k in scope}})
    return out


def run_sweep(
    scenario: str | Path,
    out_dir: str | Path,
    vary: list[str] | None = None,
    dist: str | Path | None = None,
    seed: int | None = None,
    dt: float = 0.01,
    executor: str = "local",
    scheduler: str | None = None,
    workers: int | None = None,
    emit_xosc: bool = False,
    quiet: bool = False,
    plotter: PlotWorker | None = None,
    osi_traces: str | None = None,
    osi_format: str = "mcap",
    zone_ttc: str = "2d",
    controllers: tuple = (),
) -> SweepReport:
    """Evaluate the variants and write the catalog and report. ``plotter``: a plot worker forked
    earlier (the command line forks it before importing this package); ended here either way.
    ``osi_traces``: which variants also get an ASAM OSI ground-truth trace (see :func:`trace_selection`),
    each run again in the interpreter and written to ``traces/variant_NNNNN.<osi_format>``.
    ``controllers``: the systems under test (:class:`~vei_scenario.sut.ControllerSpec`), named in the
    catalog and the report; their variants run in the interpreter."""
    from vei_scenario.checks import check_dt

    scenario = Path(scenario)
    out = Path(out_dir)
    check_dt(dt)
    if dist is None and not vary and (base := distributed_scenario(scenario)) is not None:
        scenario, dist = base, scenario  # (a distribution alone: the scenario it names, its variants)
    if workers is not None and not (isinstance(workers, int) and 1 <= workers <= 1024):
        raise VeiInputError(None, "--workers", f"{workers!r} is not a number of workers in 1..1024")
    if seed is not None and not (isinstance(seed, int) and seed >= 0):
        raise VeiInputError(None, "--seed", f"{seed!r} is not a non-negative integer")
    MetricConfig(zone_ttc=zone_ttc)  # (refuses an unknown zone TTC before anything runs)
    if osi_format not in ("mcap", "osi"):
        raise VeiInputError(None, "--osi-format", f"{osi_format!r} is not mcap or osi")
    if plotter is None:
        plotter = PlotWorker()  # before the evaluation's threads: it imports matplotlib meanwhile
    # variants and rows are many small acyclic objects that the cyclic collector would scan again and
    # again while they are built (~5 % of a 10 000-variant sweep): it waits until the files are rendered
    collecting = gc.isenabled()
    gc.disable()
    try:
        variants, varied = build_variants(scenario, vary or [], Path(dist) if dist else None, seed)
        preflight(scenario, variants, varied, dt, controllers, "--vary" if vary else "--dist")
        bar = _progress_bar(len(variants), quiet)
        tick = bar.update if bar is not None else None
        try:
            if executor == "dask":
                outcomes = evaluate_dask(str(scenario.resolve()), variants, dt, scheduler, tick, zone_ttc, controllers)
            elif executor == "local":
                outcomes = evaluate_local(str(scenario.resolve()), variants, dt, workers, tick, zone_ttc, controllers)
            else:
                raise VeiInputError(None, "--executor", f"{executor!r} is not local or dask")
        finally:
            if bar is not None:
                bar.close()
        rows = iter_rows(variants, outcomes)
        inputs = plot_inputs(rows, varied)
        plotter.draw(inputs)  # drawn in the worker while the catalog is written
        names = list(load_scenario(scenario).parameters)
        files = OutputSet()
        if emit_xosc:
            for r in rows:
                rel = f"variants/variant_{r['variant']:05d}.xosc"
                files.add(out / rel, variant_xosc(scenario, r["parameters"], out / "variants"))
                r["xosc"] = rel
        if osi_traces:
            _add_traces(files, out, scenario, rows, osi_traces, osi_format, dt, controllers)
        meta = {"scenario": str(scenario), "dt_s": dt, "varied": varied, "count": len(rows), "ttc_zones_use": zone_ttc}
        if controllers:
            from vei_scenario.sut import sut_document

            meta["system_under_test"] = sut_document(controllers)
        warnings = scenario_warnings(scenario, variants[0], dt, controllers) if variants else []
        if warnings:  # (only when there are: a sweep without any writes what it always wrote)
            meta["warnings"] = warnings
        files.add(out / "catalog.csv", catalog_csv(rows, names))
        files.add(out / "catalog.json", catalog_json(rows, meta))
        files.add(out / "report.html", report_html(rows, names, varied, meta, plots=plotter.plots(), inputs=inputs))
    finally:
        plotter.close()
        if collecting:
            gc.enable()
    files.commit()
    return SweepReport(rows, files.paths, varied, warnings)
