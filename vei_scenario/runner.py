"""``run_to``: run a scenario file and write its trajectories, metrics and plots.

The library behind ``vei run``: interpreter → metrics → outputs, everything rendered first and
written together (temporary files and renames), so a failed run leaves nothing half-written.
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from vei_scenario.atomic_io import OutputSet, json_text
from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter import RunResult, run_scenario
from vei_scenario.metrics import MetricConfig, PairSeries, compute_metrics


@dataclass
class RunReport:
    result: RunResult
    metrics: dict
    written: list[Path]


def parse_param_overrides(items: list[str]) -> dict[str, str]:
    """``Name=Value`` strings of ``--param`` into a dict."""
    out: dict[str, str] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise VeiInputError(None, "--param", f"{item!r} is not Name=Value")
        out[name.strip()] = value.strip()
    return out


#: trajectories.csv's columns, each named with its unit.
TRAJECTORY_COLUMNS = (
    "time_s", "entity", "x_m", "y_m", "heading_rad", "speed_mps", "acceleration_mps2", "controller_state",
)  # fmt: skip


def trajectories_csv(result: RunResult) -> str:
    """One row per entity and step, positions to the micrometre (the reference point in the OpenDRIVE
    frame). Written with a CSV writer, so entity names with commas or quotes stay one field."""
    import csv

    buf = io.StringIO()
    out = csv.writer(buf, lineterminator="\n")
    out.writerow(TRAJECTORY_COLUMNS)
    names = list(result.traces)
    plain = {n: n.isidentifier() for n in names}  # names that need no quoting (the common case)
    for i, t in enumerate(result.t):
        for n in names:
            tr = result.traces[n]
            row = (
                f"{t:.3f}", n, f"{tr.x[i]:.6f}", f"{tr.y[i]:.6f}", f"{tr.yaw[i]:.6f}", f"{tr.speed[i]:.6f}",
                f"{tr.accel[i]:.6f}", tr.status[i],
            )  # fmt: skip
            if plain[n]:
                buf.write(",".join(row) + "\n")
            else:
                out.writerow(row)
    # (a value that rounds to zero from below is written as zero: no "-0.000000")
    return buf.getvalue().replace(",-0.000000", ",0.000000")


SERIES_COLUMNS = ("time_s", "gap_m", "closing_rate_mps", "ttc_2d_s", "ttc_approx_s", "zone")


def series_csv(result: RunResult, cfg: MetricConfig) -> str:
    """series.csv: the ego against its threat, every step: the box gap, its closing rate, both TTCs
    (empty where the boxes never meet: infinite) and the zone that step counts in (by ``cfg.zone_ttc``),
    so people can plot what the zones and the safety index are made of."""
    import csv

    from vei_scenario.metrics.definitions import ZONES

    pair = PairSeries.from_run(result)
    zones = pair.zones(cfg)
    buf = io.StringIO()
    out = csv.writer(buf, lineterminator="\n")
    out.writerow(SERIES_COLUMNS)

    def num(v: float, digits: str) -> str:
        return format(float(v), digits) if np.isfinite(v) else ""

    for k, t in enumerate(result.t):
        out.writerow(
            (
                f"{t:.3f}",
                num(pair.gap[k], ".6f"),
                num(pair.closing_rate[k], ".6f"),
                num(pair.ttc_2d[k], ".6f"),
                num(pair.ttc_approx[k], ".6f"),
                ZONES[int(zones[k])],
            )
        )
    return buf.getvalue()


def typed_parameters(result: RunResult) -> dict[str, str | float | int | bool]:
    """The run's parameters as their declared types (a double a number, a boolean true/false)."""
    from vei_scenario.interpreter.document import typed_value

    types = result.parameter_types
    return {k: typed_value(types.get(k, "string"), v) for k, v in result.parameters.items()}


def _sha256(path: Path) -> str:
    import hashlib

    return hashlib.sha256(path.read_bytes()).hexdigest()


def provenance(result: RunResult) -> dict[str, str]:
    """Which vei and which files made the run: the version and the sha256 of the scenario and of the
    road file it played on, so a metrics.json can be matched to its inputs later."""
    from vei_scenario import __version__

    doc = {"vei_version": __version__}
    scenario = Path(result.scenario)
    if scenario.is_file():
        doc["scenario_sha256"] = _sha256(scenario)
    road = result.road_file
    if road is not None and Path(road).is_file():
        doc["road_file"] = Path(road).name
        doc["road_sha256"] = _sha256(Path(road))
    return doc


def metrics_document(result: RunResult, cfg: MetricConfig) -> dict:
    """metrics.json: the ego against its threat, plus every contact between any two entities."""
    metrics = compute_metrics(PairSeries.from_run(result), cfg) if result.threat else {}
    doc = {
        "scenario": Path(result.scenario).name,
        **provenance(result),
        "parameters": typed_parameters(result),
        "dt_s": result.dt,
        "duration_s": round(float(result.t[-1]), 3),
        "end_reason": result.end_reason,
        "ego": result.ego,
        "threat": result.threat,
        "metrics": metrics,
        "collisions": [{"time_s": round(t, 3), "entities": [a, b]} for t, a, b in result.collisions],
        "ttc_zones_use": cfg.zone_ttc,
        # the boxes (centre ahead of the logged reference point): what `vei view RUN_DIR` draws
        "entities": {
            n: {"category": tr.category, "length_m": tr.length, "width_m": tr.width, "center_x_m": tr.center_x}
            for n, tr in result.traces.items()
        },
    }
    if result.controllers:  # the user's system on an entity: which code, by file and hash
        from vei_scenario.sut import sut_document

        doc["system_under_test"] = sut_document(result.controllers)
    if result.warnings:  # (only when there are: a run without any writes what it always wrote)
        doc["warnings"] = list(result.warnings)
    return doc


def _seconds(value, none: str) -> str:
    """A time in s, or what its absence means (a metric is None when the event never happens)."""
    return none if value is None else f"{value} s"


def summary_text(doc: dict) -> str:
    from vei_scenario.interpreter.document import parameter_text

    m = doc["metrics"]
    params = ", ".join(f"{k}={parameter_text(v)}" for k, v in doc["parameters"].items())
    lines = [f"{doc['scenario']} ({params}); {doc['duration_s']:.2f} s at dt {doc['dt_s']} s ({doc['end_reason']})"]
    for s in doc.get("system_under_test", ()):
        lines.append(f"system under test on {s['entity']}: {s['controller']} (sha256 {(s['sha256'] or '-')[:12]})")
    if m:
        coll = f"COLLISION at {m['collision_time_s']} s" if m["collision"] else "no collision"
        z = m["ttc_zones_s"]
        never = "none (never on a collision course)"
        lines += [
            f"{doc['ego']} vs {doc['threat']}: {coll}; min gap {m['min_gap_m']} m; "
            f"min TTC {_seconds(m['min_ttc_s'], never)} (approx {_seconds(m['min_ttc_approx_s'], never)}); "
            f"ACT {_seconds(m['act_min_s'], 'none (never closing)')}; "
            f"PET {_seconds(m['pet_s'], 'none (paths do not cross)')}",
            f"safety index {m['safety_index']} (safe {z['safe']} s, attention {z['attention']} s, "
            f"alert {z['alert']} s, collision {z['collision']} s); EI max {m['ei_max_mps']} m/s; "
            f"DRAC max {m['drac_max_mps2']} m/s²",
            f"ego: peak deceleration {m['peak_decel_mps2']} m/s², max jerk {m['max_jerk_mps3']} m/s³, "
            f"comfort {m['comfort_score']}",
        ]
    # every pair that touched, not only the ego and its threat (road users also collide with each other)
    hits = doc.get("collisions") or []
    if hits:
        listed = "; ".join(f"{' and '.join(c['entities'])} at {c['time_s']} s" for c in hits)
        lines.append(f"collisions ({len(hits)}): {listed}")
    else:
        lines.append("collisions: none between any entities")
    return "\n".join(lines)


def run_files(result: RunResult, doc: dict, cfg: MetricConfig, plots: bool = True) -> dict[str, bytes | str]:
    """The files of one run, by name: trajectories.csv, metrics.json and (with ``plots``) PNGs."""
    files: dict[str, bytes | str] = {
        "trajectories.csv": trajectories_csv(result),
        "metrics.json": json_text(doc, indent=2) + "\n",
    }
    if result.threat:
        files["series.csv"] = series_csv(result, cfg)
    if plots:
        from vei_scenario.reports import run_plots

        runs = [("run", result)]
        files["trajectories.png"] = run_plots.trajectories_png(runs, result.road_file)
        files["speeds.png"] = run_plots.speeds_png(runs)
        files["gap_ttc.png"] = run_plots.gap_ttc_png(runs, cfg)
    return files


def _check_positions(result: RunResult) -> None:
    """A position that is not a number is a defect vei could not play: one line naming the entity and
    when, rather than files of NaN (or a plotting error about axis limits)."""
    import numpy as np

    for name, tr in result.traces.items():
        for field in ("x", "y"):
            bad = ~np.isfinite(np.asarray(getattr(tr, field), dtype=float))
            if bad.any():
                t = float(np.asarray(result.t)[int(np.argmax(bad))])
                raise VeiInputError(
                    result.scenario, name, f"its position is not a number from t = {t:g} s: vei cannot play it"
                )


def run_to(
    scenario: str | Path,
    out_dir: str | Path | None,
    parameters: dict[str, str] | None = None,
    dt: float = 0.01,
    plots: bool = True,
    cfg: MetricConfig | None = None,
    coupling: str = "sequential",
    osi: str | Path | None = None,
    progress: bool = False,
    controllers: tuple = (),
) -> RunReport:
    """Run ``scenario`` and, with ``out_dir``, write its files there; with ``osi``, also an ASAM OSI
    ground-truth trace (``.mcap`` or ``.osi``) at that path. All or nothing. With ``progress``, a run
    that may be long says so on stderr at its start, and shows a progress bar on a terminal.
    ``controllers``: the systems under test (:class:`~vei_scenario.sut.ControllerSpec`)."""
    from vei_scenario.checks import check_dt

    check_dt(dt)
    if osi is not None:
        from vei_scenario.reports.osi_trace import FORMATS

        if Path(osi).suffix.lower() not in FORMATS:
            raise VeiInputError(osi, "--osi", f"unknown trace format {Path(osi).suffix!r} (use .mcap or .osi)")
    cfg = cfg or MetricConfig()
    if progress:
        from vei_scenario.reports.run_progress import RunProgress

        shown = RunProgress(Path(scenario).name)
        try:
            result = run_scenario(
                scenario, parameters, dt, coupling=coupling, on_start=shown.on_start, controllers=controllers
            )
        finally:
            shown.close()
    else:
        result = run_scenario(scenario, parameters, dt, coupling=coupling, controllers=controllers)
    _check_positions(result)
    doc = metrics_document(result, cfg)
    written: list[Path] = []
    files = OutputSet()
    if out_dir is not None:
        for name, data in run_files(result, doc, cfg, plots).items():
            files.add(Path(out_dir) / name, data)
    if osi is not None:
        from vei_scenario.reports.osi_trace import trace_bytes

        files.add(Path(osi), trace_bytes(result, Path(osi).suffix))
    if files.paths:
        files.commit()
        written = files.paths
    return RunReport(result, doc, written)
