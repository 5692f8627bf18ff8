"""What people read: file modes, the run summary's wording, no negative zeros."""

from __future__ import annotations

import math
import os
import stat
import subprocess
import sys
from types import SimpleNamespace

import numpy as np
import pytest

from vei_scenario.metrics.definitions import peak_decel_mps2
from vei_scenario.runner import summary_text


@pytest.mark.parametrize("umask, mode", [(0o022, 0o644), (0o027, 0o640)])
def test_outputs_get_the_mode_of_a_new_file_under_the_umask(tmp_path, umask, mode):
    """Temporary files are created 0600; the renamed outputs must not stay private to their owner."""
    code = (
        "import os, sys\n"
        f"os.umask({umask})\n"
        "from pathlib import Path\n"
        "from vei_scenario.atomic_io import OutputSet, write_bytes_atomic\n"
        "d = Path(sys.argv[1])\n"
        "write_bytes_atomic(d / 'one.txt', b'1')\n"
        "s = OutputSet(); s.add(d / 'two.txt', 'two'); s.commit()\n"
    )
    subprocess.run([sys.executable, "-c", code, str(tmp_path)], check=True)
    for name in ("one.txt", "two.txt"):
        assert stat.S_IMODE(os.stat(tmp_path / name).st_mode) == mode, name


def _doc(metrics_overrides: dict, collisions: list) -> dict:
    metrics = {
        "collision": False,
        "collision_time_s": None,
        "min_gap_m": 4.2,
        "min_ttc_s": None,
        "min_ttc_approx_s": None,
        "act_min_s": None,
        "pet_s": None,
        "safety_index": 1.0,
        "ttc_zones_s": {"safe": 25.0, "attention": 0.0, "alert": 0.0, "collision": 0.0},
        "ei_max_mps": 0.0,
        "drac_max_mps2": 0.0,
        "peak_decel_mps2": 0.0,
        "max_jerk_mps3": 0.0,
        "comfort_score": 1.0,
        **metrics_overrides,
    }
    return {
        "scenario": "s.xosc",
        "parameters": {},
        "duration_s": 25.0,
        "dt_s": 0.01,
        "end_reason": "time limit 25 s",
        "ego": "Ego",
        "threat": "scooter_1",
        "metrics": metrics,
        "collisions": collisions,
    }


def test_summary_says_what_a_missing_time_means_and_lists_every_collision():
    text = summary_text(_doc({}, [{"time_s": 8.86, "entities": ["scooter_2", "scooter_3"]}]))
    assert "None" not in text
    assert "min TTC none (never on a collision course)" in text
    # the ego and its threat did not collide, two other road users did: the summary says so
    assert "no collision" in text and "collisions (1): scooter_2 and scooter_3 at 8.86 s" in text
    calm = summary_text(_doc({"min_ttc_s": 1.55, "act_min_s": 1.2, "pet_s": 1.5}, []))
    assert "min TTC 1.55 s" in calm and "ACT 1.2 s" in calm and "collisions: none between any entities" in calm


def test_peak_deceleration_of_an_ego_that_never_brakes_is_plus_zero():
    p = SimpleNamespace(ego=SimpleNamespace(accel=np.array([0.0, 0.0, 0.5])))
    value = float(peak_decel_mps2(p, None))
    assert value == 0.0 and math.copysign(1.0, value) == 1.0 and repr(value) == "0.0"


def test_every_command_line_option_says_what_it_does():
    import argparse

    from vei_scenario.cli import build_parser

    def walk(parser, path):
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    yield from walk(sub, f"{path} {name}")
            elif not isinstance(action, (argparse._HelpAction, argparse._VersionAction)):
                yield f"{path} {'/'.join(action.option_strings) or action.dest}", action.help

    missing = [name for name, text in walk(build_parser(), "vei") if not text]
    assert not missing, missing


def test_sweep_names_the_files_it_wrote(tmp_path, capsys, monkeypatch):
    from vei_scenario import cli

    report = SimpleNamespace(rows=[], varied=["TimeShift"], warnings=[])
    monkeypatch.setattr("vei_scenario.sweep.run_sweep", lambda *a, **k: report)
    cli.main(["sweep", "s.xosc", "--vary", "TimeShift=0:1:1", "-o", f"{tmp_path}/catalog/"])
    out = capsys.readouterr().out
    assert f"{tmp_path}/catalog/catalog.csv" in out and "//" not in out


def test_run_scenario_takes_python_booleans_and_numbers(compiled):
    from vei_scenario.interpreter import run_scenario

    xosc = compiled["case_study"].written[0]
    typed = run_scenario(xosc, {"CapEnabled": True, "TimeShift": 1.5, "RiderType": "normal"})
    texts = run_scenario(xosc, {"CapEnabled": "true", "TimeShift": "1.5", "RiderType": "normal"})
    assert typed.parameters["CapEnabled"] == "true" and typed.parameters["TimeShift"] == "1.5"
    assert np.array_equal(typed.traces["Ego"].x, texts.traces["Ego"].x)


def test_api_example_runs_as_written_without_the_xsds():
    """The Python API page's first block, in a fresh interpreter with no VEI_QC_VENV (a user's machine)."""
    from conftest import ROOT

    text = (ROOT / "docs" / "reference" / "api.md").read_text()
    block = text.split("```python\n", 1)[1].split("```", 1)[0]
    env = {k: v for k, v in os.environ.items() if k not in ("VEI_QC_VENV", "VEI_ASAM_SCHEMAS")}
    proc = subprocess.run([sys.executable, "-c", block], cwd=ROOT, env=env, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "scooter_1" in proc.stdout


def test_ci_workflow_example_installs_from_the_checkout_and_annotates_junit():
    """No package index has vei-scenario: the example workflow must install it from the checkout, run the
    suite that tests/test_sweep_risk_check.py shows passing, and turn its JUnit file into annotations."""
    import yaml

    from conftest import ROOT

    wf = yaml.safe_load((ROOT / "examples" / "ci" / "vei-check.yml").read_text())
    steps = next(iter(wf["jobs"].values()))["steps"]
    runs = "\n".join(s.get("run", "") for s in steps)
    assert "pip install vei-scenario" not in runs and ".venv/bin/pip install ." in runs
    check = next(s["run"] for s in steps if "vei check" in s.get("run", ""))
    suite = check.split("vei check", 1)[1].split()[0]
    junit = check.split("--junit", 1)[1].split()[0]
    assert (ROOT / suite).is_file()
    report = next(s for s in steps if "junit-report" in s.get("uses", ""))
    assert report["with"]["report_paths"] == junit and report.get("if") == "always()"


def _row(i: int, shift: float, **m) -> dict:
    metrics = {"collision": False, "near_miss": False, "min_gap_m": 5.0, "min_ttc_s": None, "safety_index": 1.0}
    metrics.update(m)
    return {"variant": i, "parameters": {"TimeShift": repr(shift), "RiderType": "normal"}, "status": "ok",
            "error": "", "metrics": metrics}  # fmt: skip


def test_report_ranks_collisions_by_impact_speed_and_shows_what_s_hides():
    import re

    from vei_scenario.sweep.report_html import report_html

    zero = {"min_gap_m": 0.0, "min_ttc_s": 0.0, "safety_index": 0.0, "collision": True}
    rows = [
        _row(0, -1.0, impact_speed_mps=2.0, **zero),
        _row(1, -0.5, impact_speed_mps=8.0, **zero),
        _row(2, 0.0, impact_speed_mps=5.0, **zero),
        _row(3, 0.5, min_gap_m=0.15, min_ttc_s=2.5, near_miss=False),  # a close pass that S scores 1.0
        _row(4, 1.0, min_gap_m=3.0, min_ttc_s=1.0, near_miss=True, safety_index=0.9),
        _row(5, 1.5),  # never on a collision course: no TTC
    ]
    text = report_html(rows, ["TimeShift", "RiderType"], ["TimeShift", "RiderType"], {"scenario": "s", "dt_s": 0.01})
    collisions = text.split("Most severe collisions", 1)[1].split("Closest passes", 1)[0]
    assert re.findall(r"<tr><td>(\d+)</td>", collisions) == ["1", "2", "0"]  # 8, 5, 2 m/s
    passes = text.split("Closest passes", 1)[1].split("What the safety index hides", 1)[0]
    assert re.findall(r"<tr><td>(\d+)</td>", passes) == ["3", "4", "5"]  # by minimum gap
    assert "1 near misses by TTC" in passes
    assert "1 variants score S ≥ 0.99 while passing within 0.5 m" in text
    assert "TimeShift (s)" in text and "1 variants have no TTC" in text


def _figures(monkeypatch):
    from vei_scenario.reports import run_plots

    figs = []
    monkeypatch.setattr(run_plots, "_png", lambda fig: figs.append(fig) or b"")
    return run_plots, figs


@pytest.mark.parametrize("shift, collides", [("0", False), ("conflict", True)])
def test_run_plots_say_whether_there_was_a_collision_and_mark_time_on_the_paths(compiled, monkeypatch, shift, collides):
    from vei_scenario.interpreter import load_scenario, run_scenario
    from vei_scenario.metrics.series import MetricConfig

    xosc = compiled["case_study"].written[0]
    value = load_scenario(xosc).parameters["ConflictTimeShift"] if shift == "conflict" else shift
    run = run_scenario(xosc, {"TimeShift": value, "RiderType": "replay", "CapEnabled": False})
    assert bool(run.collisions) == collides
    run_plots, figs = _figures(monkeypatch)
    run_plots.trajectories_png([("run", run)], run.road_file)
    ax = figs[-1].axes[0]
    title = ax.get_title()
    assert ("× first collision" in title) == collides and ("no collision" in title) != collides
    # where each road user was 4 s in: a label on each path, at its position then
    k = int(np.argmin(np.abs(run.t - 4.0)))
    labels = [a for a in ax.texts if a.get_text() == "4 s"]
    spots = {(round(a.xy[0], 6), round(a.xy[1], 6)) for a in labels}
    for name in (run.ego, run.threat):
        assert (round(run.traces[name].x[k], 6), round(run.traces[name].y[k], 6)) in spots
    run_plots.gap_ttc_png([("run", run)], MetricConfig())
    legend = [t.get_text() for t in figs[-1].axes[1].get_legend().get_texts()]
    assert legend == ["2-D TTC (zones)", "headway TTC (not used for zones)"]


def test_getting_started_run_example_prints_what_the_page_shows(compiled):
    """The lines under `$ vei run ...` in Getting started, against the command run on the compiled case
    study."""
    from conftest import ROOT

    text = (ROOT / "docs" / "getting-started.md").read_text()
    block = text.split("$ vei run out/case_study/scenario.xosc", 1)[1].split("\n$ ", 1)[0].split("\n```", 1)[0]
    args, *shown = block.strip("\n").splitlines()
    params = args.split(" -o ")[0].split()
    xosc = compiled["case_study"].written[0]
    out = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "run", str(xosc), *params, "--no-plots"],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, out.stderr
    printed = out.stdout.splitlines()
    for line in shown:
        assert line in printed, (line, printed)


def test_a_replayed_scooter_stands_until_first_seen_then_moves_on_never_back(compiled):
    """Before its first sighting the scooter stands where it is first seen (speed 0, no motion); from
    then on it replays forward: no step of its log goes against its direction of travel."""
    from vei_scenario.interpreter import run_scenario

    run = run_scenario(compiled["case_study"].written[0], {"RiderType": "replay", "CapEnabled": False})
    tr = run.traces[run.threat]
    first_seen = compiled["case_study"].model.entities[1].trajectory.t[0]
    before = run.t < first_seen - 1e-9
    assert before.sum() > 10 and np.ptp(tr.x[before]) == 0.0 and np.all(tr.speed[before] == 0.0)
    step = np.hypot(np.diff(tr.x), np.diff(tr.y))
    along = np.diff(tr.x) * np.cos(tr.yaw[1:]) + np.diff(tr.y) * np.sin(tr.yaw[1:])
    assert np.all(along >= -1e-9) and step.max() < 0.1  # never back, never a jump (4.7 m/s · 0.01 s)


def test_package_metadata_uses_an_spdx_license_string():
    """setuptools ≥ 77 deprecates the table form `license = { text = ... }` (a warning on every build)."""
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib

    from conftest import ROOT

    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert meta["project"]["license"] == "Apache-2.0"
    assert any(r.replace(" ", "").startswith("setuptools>=77") for r in meta["build-system"]["requires"])
