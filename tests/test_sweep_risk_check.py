"""Catalogs (vary specs, distribution files, local and Dask executors), risk search and CI checks."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

from conftest import EXAMPLES
from vei_scenario.cli import main
from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter import run_scenario
from vei_scenario.metrics import PairSeries, compute_metrics
from vei_scenario.risk import find_risk
from vei_scenario.sweep import build_variants, run_sweep
from vei_scenario.sweep.evaluate import evaluate_local
from vei_scenario.variation import parse_vary, read_distribution

DECLARED = {"TimeShift": "double", "RiderType": "string", "CapEnabled": "boolean"}


@pytest.fixture(scope="module")
def case_xosc(compiled) -> Path:
    return compiled["case_study"].written[0]


def test_vary_ranges_are_inclusive_and_exact():
    assert parse_vary("TimeShift=-3:3:0.1", DECLARED)[1][:3] == ["-3", "-2.9", "-2.8"]
    name, values = parse_vary("TimeShift=-3:3:0.1", DECLARED)
    assert name == "TimeShift" and len(values) == 61 and values[30] == "0" and values[-1] == "3"
    assert parse_vary("RiderType=normal,aggressive", DECLARED)[1] == ["normal", "aggressive"]


@pytest.mark.parametrize(
    "spec, fragment",
    [
        ("Speed=1:2:1", "unknown parameter 'Speed'"),
        ("TimeShift=3:1:0.1", "empty range"),
        ("TimeShift=0:1:0", "empty range"),
        ("CapEnabled=maybe", "must be true or false"),
        ("TimeShift=a,b", "is not a valid double"),
        ("TimeShift", "is not Name="),
    ],
)
def test_bad_vary_specs(spec, fragment):
    with pytest.raises(VeiInputError, match=fragment):
        parse_vary(spec, DECLARED)


def test_compiled_deterministic_distribution_runs(compiled):
    result = compiled["case_study"]
    dist = next(p for p in result.written if p.name.endswith(".variations.xosc"))
    variants, varied = build_variants(result.written[0], [], dist, None)
    assert len(variants) == 36 and set(varied) == {"TimeShift", "RiderType", "CapEnabled"}
    assert {v["RiderType"] for v in variants} == {"replay", "normal", "aggressive"}


STOCHASTIC = """<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="3" date="2024-01-01T00:00:00" description="stochastic" author="tests"/>
  <ParameterValueDistribution>
    <ScenarioFile filepath="{scenario}"/>
    <Stochastic numberOfTestRuns="400" randomSeed="42">
      <StochasticDistribution parameterName="TimeShift">
        <NormalDistribution expectedValue="2.0" variance="0.25">
          <Range lowerLimit="0" upperLimit="4"/>
        </NormalDistribution>
      </StochasticDistribution>
      <StochasticDistribution parameterName="EgoCruiseSpeed">
        <LogNormalDistribution expectedValue="5.5" variance="0.09"/>
      </StochasticDistribution>
      <StochasticDistribution parameterName="RiderType">
        <ProbabilityDistributionSet>
          <Element value="normal" weight="3"/><Element value="aggressive" weight="1"/>
        </ProbabilityDistributionSet>
      </StochasticDistribution>
      <StochasticDistribution parameterName="ConflictTimeShift">
        <Histogram>
          <Bin weight="1"><Range lowerLimit="0" upperLimit="1"/></Bin>
          <Bin weight="3"><Range lowerLimit="1" upperLimit="2"/></Bin>
        </Histogram>
      </StochasticDistribution>
    </Stochastic>
  </ParameterValueDistribution>
</OpenSCENARIO>
"""


def test_stochastic_distribution_is_seeded_and_has_the_declared_moments(case_xosc, tmp_path, qc_venv):
    from vei_scenario.openscenario.validation import validate_files

    dist = tmp_path / "stochastic.xosc"
    dist.write_text(STOCHASTIC.format(scenario=case_xosc))
    assert validate_files([dist]) == []  # a valid ASAM 1.3 file, written by hand (LogNormal is 1.3+)
    declared = {"TimeShift": "double", "EgoCruiseSpeed": "double", "RiderType": "string", "ConflictTimeShift": "double"}
    a = read_distribution(dist, declared)
    assert a == read_distribution(dist, declared) and a != read_distribution(dist, declared, seed=7)
    shift = np.array([float(v["TimeShift"]) for v in a])
    speed = np.array([float(v["EgoCruiseSpeed"]) for v in a])
    assert shift.min() >= 0 and shift.max() <= 4 and abs(shift.mean() - 2.0) < 0.1 and abs(shift.std() - 0.5) < 0.07
    assert abs(speed.mean() - 5.5) < 0.05 and abs(speed.var() - 0.09) < 0.03
    assert abs(np.mean([v["RiderType"] == "normal" for v in a]) - 0.75) < 0.07
    assert abs(np.mean([float(v["ConflictTimeShift"]) >= 1 for v in a]) - 0.75) < 0.07


def test_sweep_rows_equal_single_runs_and_report_failures(case_xosc, tmp_path, capsys):
    code = main(
        [
            "sweep",
            str(case_xosc),
            "--vary",
            "TimeShift=1.5,2.2,3.5",
            "--vary",
            "EgoCruiseSpeed=5.6,-5",
            "--vary",
            "CapEnabled=true,false",
            "-o",
            str(tmp_path / "cat"),
            "--emit-xosc",
            "--workers",
            "2",
        ]
    )
    # the catalog is written whole, and the exit says it has holes (a script or CI gate must not miss them)
    assert code == 1
    err = capsys.readouterr().err
    why = "needs a non-negative property cruiseSpeed"
    assert "6 of 12 variants failed" in err and why in err and "Traceback" not in err
    doc = json.loads((tmp_path / "cat" / "catalog.json").read_text())
    rows = doc["variants"]
    assert len(rows) == 12
    bogus = [r for r in rows if r["parameters"]["EgoCruiseSpeed"] == "-5"]
    assert len(bogus) == 6 and all(r["status"] == "error" and why in r["error"] for r in bogus)
    for r in [r for r in rows if r["status"] == "ok"][:3]:
        single = compute_metrics(PairSeries.from_run(run_scenario(case_xosc, r["parameters"])))
        assert r["metrics"] == json.loads(json.dumps(single))
        # the emitted scenario is that variant for any tool: its declarations carry the values
        emitted = etree.parse(str(tmp_path / "cat" / r["xosc"])).getroot()
        values = {d.get("name"): d.get("value") for d in emitted.iter("ParameterDeclaration")}
        assert {k: values[k] for k in ("TimeShift", "EgoCruiseSpeed", "CapEnabled")} == {
            k: r["parameters"][k] for k in ("TimeShift", "EgoCruiseSpeed", "CapEnabled")
        }
        assert (tmp_path / "cat" / "variants" / emitted.find(".//LogicFile").get("filepath")).is_file()
    with open(tmp_path / "cat" / "catalog.csv") as fh:
        table = list(csv.DictReader(fh))
    assert len(table) == 12 and {"TimeShift", "status", "collision", "safety_index", "ttc_zones_s.alert"} <= set(
        table[0]
    )
    html = (tmp_path / "cat" / "report.html").read_text()
    assert "Most severe collisions" in html and html.count("<img alt=") == 3
    assert "variants/variant_" in html


def test_report_drawn_in_the_worker_equals_one_drawn_in_process(case_xosc, tmp_path):
    """run_sweep draws the report's plots in forked processes while it writes the catalog; the page
    is the same bytes as drawing them in this process (and two sweeps give the same bytes)."""
    import threading

    from vei_scenario.interpreter.document import load_scenario
    from vei_scenario.reports.plot_worker import PlotWorker
    from vei_scenario.reports.sweep_plots import render_plots
    from vei_scenario.sweep.report_html import plot_inputs, report_html

    vary = ["TimeShift=-1:2:0.5", "RiderType=normal,replay", "CapEnabled=true,false"]
    rep = run_sweep(case_xosc, tmp_path / "a", vary, quiet=True)
    again = run_sweep(case_xosc, tmp_path / "b", vary, quiet=True)
    page = (tmp_path / "a" / "report.html").read_text(encoding="utf-8")
    assert page == (tmp_path / "b" / "report.html").read_text(encoding="utf-8")
    assert (tmp_path / "a" / "catalog.csv").read_bytes() == (tmp_path / "b" / "catalog.csv").read_bytes()
    assert rep.rows == again.rows and page.count("<img alt=") == 3
    meta = {"scenario": str(case_xosc), "dt_s": 0.01, "varied": rep.varied, "count": len(rep.rows)}
    names = list(load_scenario(case_xosc).parameters)
    assert page == report_html(rep.rows, names, rep.varied, meta)
    # the worker itself (the sweep above used it only if this process had no other threads)
    worker = PlotWorker()
    try:
        assert worker._proc is not None or threading.active_count() > 1, "the worker was not used"
        inputs = plot_inputs(rep.rows, rep.varied)
        worker.draw(inputs)
        assert worker.plots() == render_plots(inputs)
    finally:
        worker.close()


def test_dask_local_cluster_gives_the_same_catalog(case_xosc, tmp_path):
    vary = ["TimeShift=1.0:3.0:1.0", "CapEnabled=true,false"]
    local = run_sweep(case_xosc, tmp_path / "local", vary, workers=2, quiet=True)
    dask = run_sweep(case_xosc, tmp_path / "dask", vary, executor="dask", quiet=True)
    assert local.rows == dask.rows
    assert (tmp_path / "local" / "catalog.csv").read_bytes() == (tmp_path / "dask" / "catalog.csv").read_bytes()


def test_risk_interval_agrees_with_a_fine_grid_within_its_step(case_xosc, tmp_path):
    res = find_risk(case_xosc, tmp_path / "risk", "collision", ["RiderType=replay"], tol=0.01)
    ((start, end),) = res[0].intervals
    conflict = float(json.loads(json.dumps(res[0].parameters))["ConflictTimeShift"])
    assert start < conflict < end
    step = 0.05
    grid = np.round(np.arange(start - 0.3, end + 0.3 + 1e-9, step), 6)
    rows = evaluate_local(str(case_xosc), [{**res[0].parameters, "TimeShift": repr(float(s))} for s in grid], 0.01)
    hits = grid[[r["metrics"]["collision"] for r in rows]]
    assert abs(hits.min() - start) <= step and abs(hits.max() - end) <= step
    # every grid point inside the bisected interval collides: one contiguous interval
    assert np.all([r["metrics"]["collision"] for s, r in zip(grid, rows) if start <= s <= end])
    risk = json.loads((tmp_path / "risk" / "risk.json").read_text())
    mid = risk["searches"][0]["intervals"][0]["scenarios"]["mid"]
    assert (tmp_path / "risk" / mid).is_file()


def test_check_suite_passes_fails_and_writes_junit(tmp_path, capsys, case_xosc):
    suite = tmp_path / "suite.toml"
    suite.write_text(f"""
[[case]]
name = "cap avoids"
scenario = "{case_xosc}"
parameters = {{ TimeShift = 2.2, RiderType = "normal", CapEnabled = true }}
expect = ["collision == false", "safety_index >= 0.9", "ttc_zones_s.alert <= 1.5"]

[[case]]
name = "cap avoids but the crossing reaches the alert zone"
scenario = "{case_xosc}"
parameters = {{ TimeShift = 2.2, RiderType = "normal", CapEnabled = true }}
expect = ["ttc_zones_s.alert <= 0.5"]

[[case]]
name = "no cap collides but we expect it not to"
scenario = "{case_xosc}"
parameters = {{ TimeShift = 2.2 }}
expect = ["collision == false", "min_gap_m > 1"]
""")
    junit = tmp_path / "junit.xml"
    code = main(["check", str(suite), "--junit", str(junit)])
    out = capsys.readouterr().out
    assert code == 1 and "1 passed, 2 failed" in out
    assert "expected collision == false, got collision = True" in out
    assert "ttc_zones_s.alert <= 0.5" in out  # the 2-D TTC zones see the crossing (the seed's TTC did not)
    root = etree.parse(str(junit)).getroot()
    ts = root.find("testsuite")
    assert ts.get("tests") == "3" and ts.get("failures") == "2" and ts.get("errors") == "0"
    failing = ts.findall("testcase")[2]
    assert failing.find("failure") is not None and "min_gap_m" in failing.find("failure").text


def test_ci_example_suite_passes(qc_venv, capsys):
    code = main(["check", str(EXAMPLES / "ci" / "suite.toml")])
    assert code == 0, capsys.readouterr().out


@pytest.mark.parametrize(
    "text, fragment",
    [
        ("[[case]\nname='x'", "malformed TOML"),
        ("[[case]]\nname = 'x'\nscenario = 's.xosc'\nexpect = ['colision == false']", "unknown metric 'colision'"),
        ("[[case]]\nname = 'x'\nscenario = 's.xosc'\nexpect = ['collision is false']", "is not 'metric op value'"),
        ("[[case]]\nname = 'x'\nexpect = ['collision == false']", "exactly one of scenario or clip"),
        ("[[case]]\nname = 'x'\nscenario = 's.xosc'\nexpect = []", "non-empty list"),
        ("title = 'x'", "unknown table"),
    ],
)
def test_malformed_suites_are_user_errors(tmp_path, capsys, text, fragment):
    suite = tmp_path / "suite.toml"
    suite.write_text(text)
    code = main(["check", str(suite), "--junit", str(tmp_path / "j.xml")])
    err = capsys.readouterr().err
    assert code == 2 and fragment in err and "suite.toml" in err
    assert not (tmp_path / "j.xml").exists()


def test_sweep_bad_input_is_exit_2_with_no_output(tmp_path, capsys, case_xosc):
    for args in (["--vary", "Nope=1,2"], ["--vary", "TimeShift=5:1:1"], []):
        code = main(["sweep", str(case_xosc), "-o", str(tmp_path / "o"), *args])
        assert code == 2
        assert not (tmp_path / "o").exists()
    err = capsys.readouterr().err
    assert "unknown parameter 'Nope'" in err and "empty range" in err and "nothing to vary" in err


def test_without_schemas_check_and_validate_say_what_they_skipped(tmp_path, capsys, case_xosc, monkeypatch):
    """No ASAM XSDs on the machine: `vei check` still runs but says (and writes into JUnit) that it did
    not validate against them; `vei validate --format json` answers in JSON."""
    from vei_scenario.openscenario import asam_schemas

    monkeypatch.setattr(asam_schemas, "schema_dir", lambda package: None)
    suite = tmp_path / "suite.toml"
    suite.write_text(f'[[case]]\nname = "c"\nscenario = "{case_xosc}"\nexpect = ["collision == false"]\n')
    junit = tmp_path / "junit.xml"
    main(["check", str(suite), "--junit", str(junit)])
    out = capsys.readouterr().out
    assert "warning: XSD validation skipped" in out
    err = etree.parse(str(junit)).getroot().find("testsuite/testcase/system-err")
    assert err is not None and "XSD validation skipped" in err.text
    code = main(["validate", str(case_xosc), "--format", "json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 2 and doc["valid"] is False and "schema" in doc["error"]


@pytest.mark.parametrize("pool_worth_s, fork", [(0.0, True), (1e9, True), (0.0, False)])
def test_an_interpreted_sweep_gives_the_same_rows_on_any_number_of_cores(monkeypatch, pool_worth_s, fork):
    """Worker processes or not (a small sweep stays in one process), forked (Linux) or a pool of
    spawned ones (elsewhere), rows come back in variant order, equal to variant-by-variant runs, with
    a bad value as an error row wherever it stands."""
    from vei_scenario.sweep import evaluate, forked

    if fork and not forked.available():
        pytest.skip("forked workers are used on Linux only")
    monkeypatch.setattr(forked, "available", lambda: fork)

    scenario = str(Path(__file__).parent / "data" / "following_brake.xosc")
    variants = [{"EgoSpeed": "bad", "LeadSpeed": "5"}]
    variants += [{"EgoSpeed": repr(v), "LeadSpeed": repr(w)} for v in (8.0, 12.5, 15.0) for w in (3.0, 6.0)]
    variants.insert(4, {"EgoSpeed": "nan", "LeadSpeed": "5"})
    monkeypatch.setattr(evaluate, "POOL_WORTH_S", pool_worth_s)
    monkeypatch.setattr(evaluate, "SPAWN_WORTH_S", pool_worth_s)
    used: list[int] = []  # (how many variants went to the workers)
    real_pool, real_fork = evaluate._evaluate_pool, forked.run_forked
    monkeypatch.setattr(evaluate, "_evaluate_pool", lambda s, v, *a: used.append(len(v)) or real_pool(s, v, *a))
    monkeypatch.setattr(forked, "run_forked", lambda row, n, *a: used.append(n) or real_fork(row, n, *a))
    seen: list[int] = []
    rows = evaluate_local(scenario, variants, 0.01, workers=2, progress=seen.append)
    single = [evaluate.evaluate_variant(scenario, v, 0.01) for v in variants]
    assert json.dumps(rows) == json.dumps(single)
    assert sum(seen) == len(variants)
    assert used == ([len(variants) - 1] if pool_worth_s == 0.0 else [])  # (the first here: it reads the files)
    assert [r["status"] for r in rows].count("error") == 2 and rows[0]["status"] == rows[4]["status"] == "error"
    gaps = [r["metrics"]["min_gap_m"] for r in rows if r["status"] == "ok"]
    assert len(set(gaps)) > 3  # the variants differ


@pytest.mark.parametrize("n", [2, 5])
def test_a_sweep_of_few_variants_starts_no_worker_processes(monkeypatch, n):
    """Few variants cannot repay a worker (the first reads the files; a process with two variants or
    fewer after it pays more for its first touch of the shared memory than it saves): they run here,
    in order, whatever the number of cores and however long the first took."""
    from vei_scenario.sweep import evaluate, forked

    def no_workers(*args, **kwargs):
        raise AssertionError(f"worker processes were started for {n} variants")

    monkeypatch.setattr(forked, "run_forked", no_workers)
    monkeypatch.setattr(evaluate, "ProcessPoolExecutor", no_workers)
    monkeypatch.setattr(evaluate, "POOL_WORTH_S", 0.0)
    monkeypatch.setattr(evaluate, "SPAWN_WORTH_S", 0.0)
    scenario = str(Path(__file__).parent / "data" / "following_brake.xosc")
    variants = [{"EgoSpeed": repr(8.0 + k), "LeadSpeed": "3.0"} for k in range(n)]
    rows = evaluate_local(scenario, variants, 0.01, workers=2)
    assert [r["metrics"]["min_gap_m"] for r in rows] == [
        evaluate.evaluate_variant(scenario, v, 0.01)["metrics"]["min_gap_m"] for v in variants
    ]
