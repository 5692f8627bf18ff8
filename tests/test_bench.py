"""vei bench: the planner over a library, each scenario searched around its conflict shift; what it
says about a scenario is what vei run says about the same parameters."""

from __future__ import annotations

import json
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest
from test_generate_dataset import load_dataset_generator

from vei_scenario.bench import BenchOptions, run_bench
from vei_scenario.interpreter import run_scenario
from vei_scenario.library import compile_library
from vei_scenario.metrics import MetricConfig, PairSeries, compute_metrics


@pytest.fixture(scope="module")
def bench(tmp_path_factory):
    root = tmp_path_factory.mktemp("bench")
    load_dataset_generator().write_clips(root / "data", 3, seed=4)
    (root / "data" / "clips" / "zz_bad.json").write_text("{")
    compile_library(root / "data" / "clips", root / "library")
    doc = run_bench(root / "library", root / "out", BenchOptions(half_width_s=0.4, step_s=0.05))
    return root, doc


def _collides(xosc: str, shift: float, params: dict[str, str]) -> bool:
    result = run_scenario(xosc, {"TimeShift": repr(shift), **params}, 0.01)
    return bool(compute_metrics(PairSeries.from_run(result), MetricConfig())["collision"])


def test_rows_say_what_vei_run_says(bench):
    root, doc = bench
    ok = [r for r in doc["results"] if r["status"] == "ok"]
    assert len(ok) == 3 and doc["benched"] == 3
    bad = [r for r in doc["results"] if r["status"] != "ok"]
    assert [r["file"] for r in bad] == ["zz_bad.json"] and "invalid JSON" in bad[0]["error"]
    checked = 0
    for r in ok:
        centre = r["conflict_time_shift_s"]
        for n, c in r["configurations"].items():
            assert c["runs"] == 17
            assert sum(round((b - a) / 0.05) + 1 for a, b in c["collision_shifts_s"]) == c["collisions"]
            if n in ("1", "4"):  # (two configurations, every shift: the interpreter agrees)
                for k in range(-8, 9, 4):
                    s = round(centre + 0.05 * k, 6) + 0.0
                    inside = any(a - 1e-9 <= s <= b + 1e-9 for a, b in c["collision_shifts_s"])
                    assert _collides(str(root / "library" / r["scenario"]), s, c["parameters"]) == inside
                    checked += 1
        assert r["fails"] == any(r["configurations"][n]["collisions"] for n in ("4", "5"))
    assert checked == 3 * 2 * 5


def test_junit_has_one_case_per_scenario_and_fails_where_the_planner_collides(bench):
    root, doc = bench
    suite = ET.parse(root / "out" / "junit.xml").getroot()
    cases = suite.findall("testcase")
    assert [c.get("name") for c in cases] == [r["file"] for r in doc["results"]]
    failed = {c.get("name") for c in cases if c.find("failure") is not None}
    assert failed == {r["file"] for r in doc["results"] if r.get("fails")}
    assert int(suite.get("failures")) == doc["failing"] and int(suite.get("errors")) == 1
    assert json.loads((root / "out" / "bench.json").read_text()) == doc
    assert "Worst" in (root / "out" / "report.html").read_text() or not doc["worst"]


def test_cli_exit_status_and_bad_library(bench, tmp_path):
    root, doc = bench
    r = subprocess.run(
        [
            sys.executable,
            "-m",
            "vei_scenario",
            "bench",
            str(root / "library"),
            "-o",
            str(tmp_path / "b"),
            "--half-width",
            "0.1",
            "--step",
            "0.05",
        ],
        capture_output=True,
        text=True,
    )
    fails = json.loads((tmp_path / "b" / "bench.json").read_text())["failing"]
    assert r.returncode == (1 if fails else 0), r.stderr
    r = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "bench", str(tmp_path), "-o", str(tmp_path / "c")],
        capture_output=True,
        text=True,
    )
    assert r.returncode == 2 and "no library.json" in r.stderr and r.stderr.count("\n") == 1


def test_a_chosen_configuration_alone(bench, tmp_path):
    root, full = bench
    doc = run_bench(root / "library", tmp_path, BenchOptions(half_width_s=0.4, step_s=0.05, configurations=(4,)))
    assert doc["sut_configurations"] == [4]
    for r, f in zip(doc["results"], full["results"]):
        if r["status"] == "ok":
            assert list(r["configurations"]) == ["4"] and r["configurations"]["4"] == f["configurations"]["4"]
            assert r["fails"] == bool(f["configurations"]["4"]["collisions"])
