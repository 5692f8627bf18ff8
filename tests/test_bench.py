"""vei bench: the planner over a library, each scenario searched around its conflict shift; what it
says about a scenario is what vei run says about the same parameters."""

from __future__ import annotations

import hashlib
import json
import subprocess
import sys
import xml.etree.ElementTree as ET
from dataclasses import replace
from pathlib import Path

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
        assert r["fails"] == any(r["configurations"][n]["collisions_ego_moving"] for n in ("4", "5"))
        w = r["with_system"]
        assert w["collides_ego_moving"] == any(r["configurations"][n]["collisions_ego_moving"] for n in ("4", "5"))
        speeds = [r["configurations"][n]["worst_ego_speed_at_contact_mps"] for n in ("4", "5")]
        assert w["worst_ego_speed_at_contact_mps"] == max((v for v in speeds if v is not None), default=None)
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
            assert r["fails"] == bool(f["configurations"]["4"]["collisions_ego_moving"])


def test_scenarios_side_by_side_give_what_one_after_another_gives_and_keep_no_scene(bench, tmp_path):
    from vei_scenario.sweep import evaluate

    root, full = bench
    opts = BenchOptions(half_width_s=0.4, step_s=0.05)
    alone = run_bench(root / "library", tmp_path / "one", replace(opts, workers=1))
    side = run_bench(root / "library", tmp_path / "two", replace(opts, workers=2))
    assert alone["results"] == side["results"] == full["results"]
    for name in ("bench.json", "report.html", "junit.xml"):
        assert (tmp_path / "one" / name).read_bytes() == (tmp_path / "two" / name).read_bytes()
    assert not [k for k in evaluate._NATIVE if str(root / "library") in k[0]]  # (each scene freed once run)


def test_a_scenario_the_kernel_cannot_run_goes_to_the_interpreter_on_every_worker(bench, tmp_path, monkeypatch):
    import threading

    from vei_scenario.bench import run as bench_run
    from vei_scenario.sweep import evaluate

    root, full = bench
    interpreted = full["results"][0]["scenario"]
    seen: dict[str, tuple[bool, int | None]] = {}
    real_entry, real_kernel = bench_run.bench_entry, evaluate.runs_in_kernel

    def entry(library, e, opts, system):
        seen[e["file"]] = (threading.current_thread() is threading.main_thread(), opts.workers)
        return real_entry(library, e, opts, system)

    monkeypatch.setattr(bench_run, "bench_entry", entry)
    monkeypatch.setattr(evaluate, "runs_in_kernel", lambda x, dt: not x.endswith(interpreted) and real_kernel(x, dt))
    doc = run_bench(root / "library", tmp_path, BenchOptions(half_width_s=0.4, step_s=0.05, workers=2))
    assert doc["results"] == full["results"]
    ok = [r["file"] for r in full["results"] if r["status"] == "ok"]
    assert seen[ok[0]] == (True, 2) and all(seen[f] == (False, 1) for f in ok[1:])


SUT = Path(__file__).parent / "data" / "sut"
LATE = f"late=Ego={SUT / 'aeb_flawed.py'}:LateAEB"


def _vei(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "vei_scenario", *args], capture_output=True, text=True)


@pytest.fixture(scope="module")
def two_systems(bench, tmp_path_factory):
    """vei's planner and the deliberately late AEB on the same library, coarse (7 shifts)."""
    root, _ = bench
    out = tmp_path_factory.mktemp("two")
    r = _vei(
        "bench", str(root / "library"), "-o", str(out), "--half-width", "0.3", "--step", "0.1",
        "--controller", "planner", "--controller", LATE, "--quiet",
    )  # fmt: skip
    planner = json.loads((out / "planner" / "bench.json").read_text())
    late = json.loads((out / "late" / "bench.json").read_text())
    return root, out, r, planner, late


def test_the_flawed_aeb_fails_more_scenarios_than_the_planner_and_the_comparison_says_where(two_systems):
    root, out, r, planner, late = two_systems
    assert late["failing"] > planner["failing"], (planner["failing"], late["failing"])
    fails = {d["system"]["label"]: {x["file"] for x in d["results"] if x.get("fails")} for d in (planner, late)}
    c = json.loads((out / "compare.json").read_text())
    assert [x["file"] for x in c["only_b"]] == sorted(fails["late"] - fails["planner"])
    assert [x["file"] for x in c["only_a"]] == sorted(fails["planner"] - fails["late"])
    assert c["only_b"] and r.returncode == 1, r.stderr  # (the second fails where the first passes)
    page = (out / "compare.html").read_text()
    for x in c["only_b"]:
        assert x["file"] in page and "--controller" in x["b"]["reproduce"]
        assert f"late only: {x['file']}" in r.stdout


def test_the_users_system_is_named_by_file_and_hash_in_every_output(two_systems):
    root, out, _, planner, late = two_systems
    digest = hashlib.sha256((SUT / "aeb_flawed.py").read_bytes()).hexdigest()
    (c,) = late["system"]["controllers"]
    assert (c["entity"], c["sha256"], Path(c["file"])) == ("Ego", digest, SUT / "aeb_flawed.py")
    assert planner["system"]["controllers"] == [] and planner["system"]["label"] == "planner"
    assert digest in (out / "late" / "report.html").read_text()
    suite = ET.parse(out / "late" / "junit.xml").getroot()
    (prop,) = suite.iter("property")
    assert digest in prop.get("value") and "aeb_flawed.py" in prop.get("value")
    failed = [case for case in suite.findall("testcase") if case.find("failure") is not None]
    assert len(failed) == late["failing"] and all("--controller" in f.find("failure").text for f in failed)


def test_the_worst_failure_is_what_vei_run_with_the_controller_says(two_systems):
    """An independent run of the printed command's parameters and controller: same contact, same speed."""
    from vei_scenario.sut import parse_controller_options

    root, _, _, _, late = two_systems
    specs = parse_controller_options([f"Ego={SUT / 'aeb_flawed.py'}:LateAEB"])
    checked = 0
    for row in late["results"]:
        w = row.get("worst_failure")
        if not w:
            continue
        params = row["configurations"][str(w["configuration"])]["parameters"]
        xosc = str(root / "library" / row["scenario"])
        result = run_scenario(xosc, {"TimeShift": repr(w["time_shift_s"]), **params}, 0.01, controllers=specs)
        m = compute_metrics(PairSeries.from_run(result), MetricConfig())
        assert m["collision_ego_moving"] and m["ego_speed_at_contact_mps"] == pytest.approx(
            w["ego_speed_at_contact_mps"], abs=1e-3
        )
        assert f"--param TimeShift={w['time_shift_s']!r}" in w["reproduce"]
        checked += 1
    assert checked == late["failing"]


def test_without_the_planner_the_configurations_are_the_same_for_both_systems(two_systems):
    _, _, _, planner, late = two_systems
    for a, b in zip(planner["results"], late["results"]):
        if a["status"] == "ok":
            assert [a["configurations"][n] for n in "123"] == [b["configurations"][n] for n in "123"]


def test_compare_of_two_reports_is_the_comparison_of_the_run(two_systems, tmp_path):
    _, out, r, _, _ = two_systems
    r2 = _vei("bench", "--compare", str(out / "planner"), str(out / "late" / "bench.json"), "-o", str(tmp_path))
    assert r2.returncode == 1, r2.stderr
    assert (tmp_path / "compare.json").read_bytes() == (out / "compare.json").read_bytes()
    r3 = _vei("bench", "--compare", str(out / "late"), str(out / "planner"), "-o", str(tmp_path / "rev"))
    rev = json.loads((tmp_path / "rev" / "compare.json").read_text())
    forward = json.loads((out / "compare.json").read_text())
    assert [x["file"] for x in rev["only_a"]] == [x["file"] for x in forward["only_b"]]
    assert [x["file"] for x in rev["only_b"]] == [x["file"] for x in forward["only_a"]]
    assert r3.returncode == (1 if rev["only_b"] else 0)


def test_a_controller_that_raises_fails_the_scenario_with_its_message(bench, tmp_path):
    root, _ = bench
    from vei_scenario.bench import parse_systems

    (system,) = parse_systems([f"Ego={SUT / 'faulty.py'}:RaisesAt2s"])
    doc = run_bench(
        root / "library", tmp_path, BenchOptions(half_width_s=0.0, step_s=0.1, configurations=(4,)), None, system
    )
    ok = [x for x in doc["results"] if x["status"] == "ok"]
    assert ok and all(x["fails"] for x in ok)
    for x in ok:
        c = x["configurations"]["4"]
        assert c["failed_runs"] == 1 and "sensor fusion lost track" in c["first_error"]["error"]
        assert "sensor fusion lost track" in x["worst_failure"]["error"]
    page = (tmp_path / "report.html").read_text()  # (the reason is in the report too, not only the JSON)
    assert page.count("run(s) failed (the first: ") == len(ok) and "sensor fusion lost track" in page


@pytest.mark.parametrize(
    "args, says",
    [
        (["--controller", "a=planner", "--controller", "b=planner", "--controller", "c=planner"], "at most two"),
        (["--controller", "planner", "--controller", "planner"], "two systems labelled 'planner'"),
        (["--controller", "Ego=no/such.py:X"], "no/such.py: no such file"),
        (["--controller", "planner", "--controller-param", "x=1"], "vei's planner takes none"),
        (["--controller", LATE, "--controller-param", "other:x=1"], "no system labelled 'other'"),
        (["--controller", f"Egoo={SUT / 'aeb_flawed.py'}:LateAEB"], "no entity 'Egoo'"),
    ],
)
def test_bad_systems_are_one_line_before_anything_runs(bench, tmp_path, args, says):
    root, _ = bench
    r = _vei("bench", str(root / "library"), "-o", str(tmp_path / "o"), *args)
    assert r.returncode == 2 and says in r.stderr and r.stderr.count("\n") == 1, r.stderr
    assert not (tmp_path / "o").exists()


def test_compare_refuses_benchmarks_searched_differently(two_systems, bench, tmp_path):
    root, out, _, _, _ = two_systems
    r = _vei("bench", "--compare", str(out / "planner"), str(tmp_path / "none.json"), "-o", str(tmp_path / "o"))
    assert r.returncode == 2 and "none.json" in r.stderr and r.stderr.count("\n") == 1
    # (the module fixture's benchmark searched 0.05 s steps, the comparison's 0.1 s)
    r = _vei("bench", "--compare", str(root / "out"), str(out / "late"), "-o", str(tmp_path / "o"))
    assert r.returncode == 2 and "searched differently" in r.stderr and r.stderr.count("\n") == 1
    assert not (tmp_path / "o").exists()
