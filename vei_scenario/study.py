"""``run_study``: the seed paper's five-configuration study of one interaction.

1 replay, no CAP; 2 normal SFM rider, no CAP; 3 aggressive SFM rider, no CAP; 4 normal + CAP;
5 aggressive + CAP, all at the collision timing shift the compiler found (``ConflictTimeShift``).
Input: a clip (compiled first, into ``out/scenario/``) or a compiled scenario.
"""

from __future__ import annotations

import csv
import io
import tempfile
from dataclasses import dataclass
from pathlib import Path

from vei_scenario.atomic_io import OutputSet, json_text
from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter import run_scenario
from vei_scenario.interpreter.document import load_scenario
from vei_scenario.metrics import MetricConfig
from vei_scenario.runner import metrics_document, run_files
from vei_scenario.sut import sut_document

CONFIGURATIONS = (
    (1, "replay, no CAP", {"RiderType": "replay", "CapEnabled": "false"}),
    (2, "normal SFM, no CAP", {"RiderType": "normal", "CapEnabled": "false"}),
    (3, "aggressive SFM, no CAP", {"RiderType": "aggressive", "CapEnabled": "false"}),
    (4, "normal SFM + CAP", {"RiderType": "normal", "CapEnabled": "true"}),
    (5, "aggressive SFM + CAP", {"RiderType": "aggressive", "CapEnabled": "true"}),
)
TABLE_COLUMNS = (
    "config",
    "description",
    "collision",
    "collision_time_s",
    "min_gap_m",
    "min_ttc_s",
    "min_ttc_approx_s",
    "act_min_s",
    "alert_s",
    "safety_index",
)


@dataclass
class StudyReport:
    scenario: Path
    time_shift_s: float
    rows: list[dict]
    written: list[Path]


def _scenario_for(input_path: Path, staging: Path) -> tuple[Path, list[Path]]:
    """The scenario to study: a compiled one as given, a clip compiled into ``staging`` (its files
    join the study's outputs only once every configuration has run: a failed run leaves nothing)."""
    if input_path.suffix == ".json":
        from vei_scenario.compiler import compile_clip

        target = staging / "scenario" / "scenario.xosc"
        result = compile_clip(input_path, target)
        return target, list(result.written)
    if input_path.suffix != ".xosc":
        raise VeiInputError(input_path, "", "vei study takes a clip (.json) or a compiled scenario (.xosc)")
    return input_path, []


#: (header, row key, width, number format) of the printed table.
_TABLE = (
    ("#", "config", 3, None),
    ("configuration", "description", 24, None),
    ("collision", "collision", 10, None),
    ("t_coll s", "collision_time_s", 10, ".2f"),
    ("min gap m", "min_gap_m", 11, ".2f"),
    ("min TTC s", "min_ttc_s", 11, ".2f"),
    ("TTC≈ s", "min_ttc_approx_s", 9, ".2f"),
    ("ACT s", "act_min_s", 8, ".2f"),
    ("alert s", "alert_s", 9, ".2f"),
    ("S", "safety_index", 7, ".2f"),
)


def table_text(rows: list[dict]) -> str:
    def cell(value, width: int, spec: str | None, left: bool) -> str:
        if isinstance(value, bool):
            text = "yes" if value else "no"
        elif value is None:
            text = "-"
        else:
            text = format(value, spec) if spec else str(value)
        return text.ljust(width) if left else text.rjust(width)

    head = "".join(cell(h, w, None, i < 2) for i, (h, _, w, _) in enumerate(_TABLE))
    out = [head, "-" * len(head)]
    for r in rows:
        out.append("".join(cell(r[k], w, spec, i < 2) for i, (_, k, w, spec) in enumerate(_TABLE)))
    return "\n".join(out)


def run_study(
    input_path: str | Path,
    out_dir: str | Path,
    dt: float = 0.01,
    time_shift_s: float | None = None,
    plots: bool = True,
    zone_ttc: str = "2d",
    controllers: tuple = (),
) -> StudyReport:
    """The five configurations; ``zone_ttc``: the TTC the zones and the safety index use ("2d", or
    "approx" for the seed paper's table: ``vei study --paper``). Both TTCs are in the table.
    ``controllers``: the systems under test (:class:`~vei_scenario.sut.ControllerSpec`): they take the
    planner's place in configurations 4 and 5 (``+ SUT``); 1-3 run without any system, as before."""
    from vei_scenario.checks import check_dt, finite

    check_dt(dt)
    if time_shift_s is not None:
        finite(time_shift_s, "--time-shift", -3600, 3600)
    out = Path(out_dir)
    with tempfile.TemporaryDirectory(prefix="vei-study-") as staging:
        return _study(Path(input_path), out, Path(staging), dt, time_shift_s, plots, zone_ttc, controllers)


def _study(input_path: Path, out: Path, staging: Path, dt: float, time_shift_s: float | None, plots: bool,
           zone_ttc: str, controllers: tuple) -> StudyReport:  # fmt: skip
    scenario, compiled = _scenario_for(input_path, staging)
    shown = out / scenario.relative_to(staging) if compiled else scenario  # (where it is once written)
    declared = load_scenario(scenario).parameters
    for name in ("TimeShift", "RiderType", "CapEnabled"):
        if name not in declared:
            raise VeiInputError(scenario, "ParameterDeclarations", f"a vei study needs the parameter {name}")
    if time_shift_s is None:
        if "ConflictTimeShift" not in declared:
            raise VeiInputError(scenario, "ParameterDeclarations", "no ConflictTimeShift; give --time-shift")
        time_shift_s = float(declared["ConflictTimeShift"])
    cfg = MetricConfig(zone_ttc=zone_ttc)  # (refuses an unknown zone TTC)
    files = OutputSet()
    rows, runs = [], []
    for number, description, params in CONFIGURATIONS:
        values = {**params, "TimeShift": repr(float(time_shift_s))}
        plugged = controllers if params["CapEnabled"] == "true" else ()
        if plugged:
            description = description.replace("+ CAP", "+ SUT")
        result = run_scenario(scenario, values, dt, controllers=plugged)
        doc = metrics_document(result, cfg)
        for name, data in run_files(result, doc, cfg, plots=False).items():
            files.add(out / f"config{number}" / name, data)
        m = {**doc["metrics"], "alert_s": doc["metrics"]["ttc_zones_s"]["alert"]}
        rows.append({"config": number, "description": description, **{k: m.get(k) for k in TABLE_COLUMNS[2:]}})
        runs.append((f"{number} {description}", result))
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=list(TABLE_COLUMNS), lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    files.add(out / "study.csv", buf.getvalue())
    files.add(
        out / "study.json",
        json_text(
            {
                "scenario": str(shown),
                "time_shift_s": time_shift_s,
                "dt_s": dt,
                "ttc_zones_use": zone_ttc,
                "configurations": rows,
                **({"system_under_test": sut_document(controllers)} if controllers else {}),
            },
            indent=2,
        )
        + "\n",
    )
    if plots:
        from vei_scenario.reports import run_plots

        files.add(out / "trajectories.png", run_plots.trajectories_png(runs, runs[0][1].road_file))
        files.add(out / "speeds.png", run_plots.speeds_png(runs))
        files.add(out / "gap_ttc.png", run_plots.gap_ttc_png(runs, cfg))
    for path in compiled:
        files.add(out / path.relative_to(staging), path.read_bytes())
    files.commit()
    return StudyReport(shown, float(time_shift_s), rows, files.paths)
