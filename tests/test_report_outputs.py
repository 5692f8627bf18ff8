"""What a reader of the outputs takes at face value: typed parameters and provenance in metrics.json,
units in cosim.csv, a sweep report that does not claim more than its grid can show, plots whose
coinciding series stay visible, and vei probability's documented example."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest

import vei_scenario
from vei_scenario.runner import run_to


@pytest.fixture(scope="module")
def case_xosc(compiled) -> Path:
    return next(p for p in compiled["case_study"].written if p.name == "scenario.xosc")


def test_metrics_json_keeps_declared_types_version_and_file_hashes(case_xosc, tmp_path):
    run_to(case_xosc, tmp_path, {"TimeShift": "2.2", "RiderType": "aggressive", "CapEnabled": "true"}, plots=False)
    doc = json.loads((tmp_path / "metrics.json").read_text())
    p = doc["parameters"]
    assert p["TimeShift"] == 2.2 and isinstance(p["TimeShift"], float)
    assert p["CapEnabled"] is True
    assert p["RiderType"] == "aggressive"
    assert isinstance(p["EgoCruiseSpeed"], float)
    assert doc["vei_version"] == vei_scenario.__version__
    assert doc["scenario_sha256"] == hashlib.sha256(case_xosc.read_bytes()).hexdigest()
    road = case_xosc.with_suffix(".xodr")
    assert doc["road_file"] == road.name
    assert doc["road_sha256"] == hashlib.sha256(road.read_bytes()).hexdigest()


@pytest.fixture(scope="module")
def grid_sweep(case_xosc, tmp_path_factory):
    """The README's sweep: TimeShift every 0.1 s, both SFM riders, planner on and off."""
    from vei_scenario.sweep import run_sweep

    out = tmp_path_factory.mktemp("grid")
    vary = ["TimeShift=-1:5:0.1", "RiderType=normal,aggressive", "CapEnabled=true,false"]
    rep = run_sweep(case_xosc, out, vary, quiet=True)
    return rep, (out / "report.html").read_text(encoding="utf-8")


def _text(page: str) -> str:
    import html
    import re

    page = re.sub(r"<script.*?</script>", " ", page, flags=re.S)
    return html.unescape(re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", page)))


def test_a_grid_without_planner_failures_does_not_claim_there_are_none(grid_sweep, case_xosc):
    """The planner's failure windows (0.03-0.08 s) lie between the 0.1 s grid points: the report says
    what the grid is and where a finer search could find them, with the command to run."""
    rep, page = grid_sweep
    on = [r for r in rep.rows if r["parameters"]["CapEnabled"] == "true"]
    assert on and not any(r["metrics"]["collision"] for r in on)  # (the grid does step over them)
    text = _text(page)
    assert "avoided every collision" not in text
    assert "TimeShift (s): 61 values from -1 to 5, step 0.1" in text
    assert "narrower than the grid step" in text
    assert f"vei risk {case_xosc} --target collision --window=-1:5 --vary RiderType=normal,aggressive" in text
    assert (
        f"vei falsify {case_xosc} --bounds TimeShift=-1:5 --values RiderType=normal,aggressive --param CapEnabled=true"
        in text
    )


def test_a_close_pass_with_the_planner_on_is_flagged(grid_sweep):
    """TimeShift 2.9 with the aggressive rider passes at 0.18 m with the planner on: a near miss of the
    system under test, listed with its gap and the command that replays it."""
    from vei_scenario.metrics import MetricConfig

    rep, page = grid_sweep
    text = _text(page)
    close = [
        r
        for r in rep.rows
        if r["parameters"]["CapEnabled"] == "true" and r["metrics"]["min_gap_m"] < MetricConfig().close_pass_m
    ]
    assert close, "the grid has a pass closer than the near-miss gap with the planner on"
    assert "Near misses with the planner on" in text
    worst = min(close, key=lambda r: r["metrics"]["min_gap_m"])
    assert f"{worst['metrics']['min_gap_m']}" in text
    assert f"--param TimeShift={worst['parameters']['TimeShift']} --param RiderType=aggressive" in text


def test_the_report_states_a_grid_with_nothing_nearby_honestly(case_xosc, tmp_path):
    """Far from the conflict nothing collides and nothing comes close: the report still says that a
    grid shows only its points, without pointing at a search it has no reason for."""
    from vei_scenario.sweep import run_sweep

    run_sweep(case_xosc, tmp_path, ["TimeShift=-6:-5:0.5", "CapEnabled=true,false"], quiet=True)
    text = _text((tmp_path / "report.html").read_text(encoding="utf-8"))
    assert "avoided every collision" not in text
    assert "TimeShift (s): 3 values from -6 to -5, step 0.5" in text
    assert "No collision with the planner on at any of the 3 grid points (TimeShift step 0.5 s)" in text


def test_cosim_csv_has_units_and_the_precision_of_trajectories_csv(case_xosc, tmp_path):
    """Same columns as trajectories.csv: the unit in each name, times to the millisecond, values to six
    decimals, no negative zeros; the values are those vei run writes."""
    import csv
    import re

    from vei_scenario.cli import main

    params = ["--param", "RiderType=aggressive", "--param", "CapEnabled=true"]
    out = tmp_path / "cosim.csv"
    assert main(["fmu", "cosim", str(case_xosc), *params, "-o", str(out)]) == 0
    rows = list(csv.reader(out.read_text().splitlines()))
    quantities = ["x_m", "y_m", "heading_rad", "speed_mps", "acceleration_mps2"]
    assert rows[0] == [
        "time_s",
        *(f"ego.{q}" for q in quantities),
        *(f"sfm.{q}" for q in quantities),
        "cap.a_cmd_mps2",
    ]
    assert all(re.fullmatch(r"\d+\.\d{3}", r[0]) for r in rows[1:])
    assert all(re.fullmatch(r"-?\d+\.\d{6}", v) and v != "-0.000000" for r in rows[1:] for v in r[1:])
    run = tmp_path / "run"
    assert main(["run", str(case_xosc), *params, "-o", str(run), "--no-plots"]) == 0
    traj = [r for r in csv.DictReader((run / "trajectories.csv").read_text().splitlines()) if r["entity"] == "Ego"]
    for k in (0, 500, 1500):
        assert rows[k + 1][0] == traj[k]["time_s"]
        assert rows[k + 1][1:5] == [traj[k][q] for q in quantities[:4]]


def _marked(ax) -> list:
    """The lines of an axes that carry a marker."""
    return [ln for ln in ax.lines if ln.get_marker() not in (None, "None", "", " ")]


@pytest.fixture(scope="module")
def planner_runs(case_xosc):
    """Study configurations 4 and 5 at the conflict shift: the ego brakes alike for both riders."""
    from vei_scenario.interpreter import load_scenario, run_scenario

    shift = load_scenario(case_xosc).parameters["ConflictTimeShift"]
    return [
        (
            f"{n} {rider} SFM + CAP",
            run_scenario(case_xosc, {"TimeShift": shift, "RiderType": rider, "CapEnabled": "true"}),
        )
        for n, rider in ((4, "normal"), (5, "aggressive"))
    ]


def test_the_single_run_gap_ttc_plot_draws_no_unexplained_marker(planner_runs):
    """The square at t = 0 marked whose zone strip it was: with one run there is one strip, nothing to tell."""
    from vei_scenario.metrics import MetricConfig
    from vei_scenario.reports.run_plots import gap_ttc_figure

    fig = gap_ttc_figure(planner_runs[:1], MetricConfig())
    gap_ax, ttc_ax = fig.axes[:2]
    assert [ln.get_marker() for ln in _marked(ttc_ax)] == ["."]  # the TTC's dot per step, nothing else
    several = gap_ttc_figure(planner_runs, MetricConfig())  # with several, each strip is marked and explained
    assert len({ln.get_marker() for ln in _marked(several.axes[1])}) >= 2
    assert "its marker at the left" in several.axes[1].get_title()


def test_speeds_plot_shows_the_ego_acceleration_and_the_planner_mode(planner_runs):
    from vei_scenario.reports.run_plots import speeds_figure

    label, r = planner_runs[0]
    speed_ax, acc_ax, mode_ax = speeds_figure([(label, r)]).axes
    ego = r.traces[r.ego]
    assert "acceleration" in acc_ax.get_ylabel()
    assert any(len(ln.get_ydata()) == ego.accel.size and (ln.get_ydata() == ego.accel).all() for ln in acc_ax.lines)
    states = [t.get_text() for t in mode_ax.get_yticklabels()]
    assert {"cap_cruise", "cap_brake"} <= set(states)
    (mode_line,) = mode_ax.lines
    brake = np.asarray(mode_line.get_ydata()) == states.index("cap_brake")
    assert brake.any() and (np.array(ego.status)[brake] == "cap_brake").all()


def test_coinciding_runs_stay_visible_and_the_legend_says_so(planner_runs):
    """Configuration 5's ego speed lies on configuration 4's: each has its own marker, staggered, and
    the legend names the one it lies on."""
    from vei_scenario.reports.run_plots import speeds_figure

    speed_ax = speeds_figure(planner_runs).axes[0]
    ego_lines = [ln for ln in speed_ax.lines if ln.get_label().split(" (")[0].endswith(": Ego")]
    assert len(ego_lines) == 2
    four, five = ego_lines
    assert four.get_marker() != five.get_marker() and four.get_markevery() != five.get_markevery()
    assert four.get_linewidth() > five.get_linewidth()  # the one below is wider: it shows around the other
    labels = [t.get_text() for t in speed_ax.figure.legends[0].get_texts()]
    assert any(t.startswith("5 aggressive SFM + CAP: Ego (coincides with 4 normal SFM + CAP: Ego") for t in labels)


def test_sweep_plot_groups_with_equal_values_do_not_hide_each_other(grid_sweep):
    """Aggressive and normal rider with the planner on score alike: distinct markers and dashes, and
    the legend says where they are equal."""
    from vei_scenario.reports.sweep_plots import series_figure
    from vei_scenario.sweep.report_html import plot_inputs

    rep, _ = grid_sweep
    x_param, grouped, xlim = plot_inputs(rep.rows, rep.varied)
    fig, _ = series_figure(grouped, x_param, "safety_index", "safety index", xlim)
    ax = fig.axes[0]
    lines = {ln.get_label(): ln for ln in ax.lines if not ln.get_label().startswith("_")}
    assert len(lines) == 4
    assert len({ln.get_marker() for ln in lines.values()}) == 4
    assert len({str(ln.get_linestyle()) for ln in lines.values()}) == 4
    on = [lab for lab in lines if "CapEnabled=true" in lab]
    assert any("coincides with" in lab or "equal to" in lab for lab in on), on


def test_a_sweep_without_the_planner_on_says_it_does_not_test_it(case_xosc, tmp_path):
    from vei_scenario.sweep import run_sweep

    run_sweep(case_xosc, tmp_path, ["TimeShift=1:3:0.5", "CapEnabled=false"], quiet=True)
    text = _text((tmp_path / "report.html").read_text(encoding="utf-8"))
    assert "No variant ran with the planner on (CapEnabled=true)" in text
    assert "No collision with the planner on" not in text and "Near misses with the planner on" not in text


def test_a_stochastic_sample_reports_its_largest_gap_not_a_step(case_xosc, tmp_path):
    """Sampled values are not a grid: what a failure window can hide in is the largest gap."""
    from vei_scenario.sweep.report_html import _grid

    rows = [{"parameters": {"TimeShift": v}} for v in ("0.1", "0.13", "0.5", "0.52")]
    text = _text("".join(_grid(rows, ["TimeShift"])))
    assert "TimeShift (s): 4 values from 0.1 to 0.52, unevenly spaced, largest gap 0.37" in text


def test_interactive_plot_groups_have_their_own_symbol_and_dash(grid_sweep):
    from vei_scenario.reports.interactive import DASHES, SYMBOLS
    from vei_scenario.sweep.report_html import plot_inputs

    rep, page = grid_sweep
    _, grouped, _ = plot_inputs(rep.rows, rep.varied)
    assert len(grouped) == 4
    for k in range(4):
        assert f'"symbol":"{SYMBOLS[k]}"' in page and f'"dash":"{DASHES[k]}"' in page
