"""The user's own controller (the system under test) on the ego: the contract, every command, its faults.

The controllers in tests/data/sut/ were written from the contract alone, without reading vei's code
(aeb_good.AEB, aeb_flawed.LateAEB / BlindLeftAEB, faulty.*): they are what a user would bring.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import shlex
from pathlib import Path

import numpy as np
import pytest

from conftest import NO_SHARED, SHARED, native_test_fmus
from vei_scenario.cli import main
from vei_scenario.interpreter import run_scenario
from vei_scenario.sut import ControllerFault, command_from, parse_controller_options

DATA = Path(__file__).parent / "data" / "sut"
PLANNER = "vei_scenario.sut.planner:CollisionAvoidancePlanner"


@pytest.fixture(scope="module")
def scenario(compiled) -> Path:
    return next(p for p in compiled["case_study"].written if p.name == "scenario.xosc")


def _config(rider: str, shift: str = "2.197") -> dict[str, str]:
    return {"RiderType": rider, "CapEnabled": "true", "TimeShift": shift}


@pytest.mark.parametrize("rider", ["normal", "aggressive"])
def test_vei_planner_as_a_plugged_class_reproduces_the_built_in_one(scenario, rider):
    """Study configurations 4 and 5: the planner seen only through the contract drives as the built-in."""
    built_in = run_scenario(scenario, _config(rider))
    plugged = run_scenario(scenario, _config(rider), controllers=parse_controller_options([f"Ego={PLANNER}"]))
    for name, a in built_in.traces.items():
        b = plugged.traces[name]
        assert np.abs(a.x - b.x).max() <= 1e-9 and np.abs(a.y - b.y).max() <= 1e-9
        assert np.abs(a.speed - b.speed).max() <= 1e-9
    assert plugged.traces["Ego"].status == built_in.traces["Ego"].status  # cap_cruise / cap_brake
    assert "cap_brake" in plugged.traces["Ego"].status


def test_a_late_aeb_collides_where_a_good_one_does_not(scenario):
    values = _config("aggressive")
    late = run_scenario(scenario, values, controllers=parse_controller_options([f"Ego={DATA}/aeb_flawed.py:LateAEB"]))
    good = run_scenario(scenario, values, controllers=parse_controller_options([f"Ego={DATA}/aeb_good.py:AEB"]))
    assert [c[1:] for c in late.collisions] == [("Ego", "scooter_1")]
    assert good.collisions == []
    # the command went through the vehicle model: the late AEB's -4 m/s² within the jerk limit
    assert late.traces["Ego"].accel.min() == pytest.approx(-4.0)
    assert set(late.traces["Ego"].status[1:]) == {"sut"}  # (t = 0 is logged before the first step)


def test_the_ego_keeps_its_path_and_its_performance(scenario):
    """A full-throttle controller: the speed rises at the Performance's maxAcceleration (4 m/s²), the
    ego stays on the path the built-in run drives."""
    src = "class Floor:\n    def __init__(self, **kw):\n        pass\n    def step(self, obs):\n        return 50.0\n"
    path = DATA.parent.parent / "_floor_tmp.py"
    try:
        path.write_text(src)
        r = run_scenario(scenario, _config("replay"), controllers=parse_controller_options([f"Ego={path}:Floor"]))
    finally:
        path.unlink()
    ego = r.traces["Ego"]
    assert ego.accel.max() == pytest.approx(4.0)
    assert ego.speed[100] == pytest.approx(5.61 + 4.0 * 1.0 - 4.0**2 / (2 * 50.0), abs=0.05)  # jerk ramp
    base = run_scenario(scenario, {"RiderType": "replay"}).traces["Ego"]
    # same path: every plugged position lies on the polyline the unplugged ego drives
    d = np.hypot(ego.x[:300, None] - base.x[None, :], ego.y[:300, None] - base.y[None, :]).min(axis=1)
    assert d.max() < 0.05


def test_command_forms():
    assert command_from(-2, "E=x", 0.0).accel_mps2 == -2.0
    c = command_from({"accel_mps2": -3.5, "state": "brake,hard"}, "E=x", 0.0)
    assert (c.accel_mps2, c.state) == (-3.5, "brake;hard")

    class Out:
        accel_mps2 = 1.5

    assert command_from(Out(), "E=x", 0.0).accel_mps2 == 1.5
    for bad, says in ((True, "True"), (None, "None"), ("brake", "str 'brake'"), ({"a": 1}, "without accel_mps2"),
                      (float("inf"), "non-finite"), (-1e3, "beyond ±100")):  # fmt: skip
        with pytest.raises(ControllerFault, match=says):
            command_from(bad, "Ego=f.py:C", 1.25)
    with pytest.raises(ControllerFault, match=r"^controller Ego=f.py:C at t = 1.25 s: "):
        command_from("x", "Ego=f.py:C", 1.25)


def _vei(capsys, *argv: str) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    return code, out.out, out.err


FAULTS = {
    # class: (exit code, the one line's tail)
    "RaisesAt2s": (1, "at t = 2.00 s: step raised RuntimeError: sensor fusion lost track"),
    "ReturnsNaN": (1, "at t = 1.00 s: step returned a non-finite command (nan)"),
    "ReturnsAbsurd": (1, "at t = 0.00 s: step returned 1e+06 m/s², beyond ±100 m/s² (no vehicle can)"),
    "BadReturn": (1, "at t = 0.00 s: step returned str 'brake', not an acceleration"),
    "NoStep": (2, ": class NoStep has no step(obs) method"),
    "WrongCtorArgs": (2, ": constructing WrongCtorArgs raised TypeError: "),
    "Missing": (2, "has no class 'Missing' (it has: BadReturn, Hangs, NoStep"),
}


@pytest.mark.parametrize("cls", sorted(FAULTS))
def test_faults_in_the_users_code_are_one_line_naming_it(scenario, tmp_path, capsys, cls):
    code, out, err = _vei(capsys, "run", scenario, "--controller", f"Ego={DATA}/faulty.py:{cls}", "-o", tmp_path / "r")
    want_code, tail = FAULTS[cls]
    assert code == want_code
    assert err.count("\n") == 1 and err.startswith(f"vei: error: controller Ego={DATA}/faulty.py:{cls}")
    assert tail in err
    assert not (tmp_path / "r").exists()  # nothing half-written


def test_a_missing_file_and_an_unknown_entity_are_refused_before_running(scenario, capsys):
    code, _, err = _vei(capsys, "run", scenario, "--controller", "Ego=no/such_file.py:AEB")
    assert code == 2 and err == "vei: error: controller Ego=no/such_file.py:AEB: no/such_file.py: no such file\n"
    code, _, err = _vei(capsys, "run", scenario, "--controller", f"Bob={DATA}/aeb_good.py:AEB")
    assert code == 2 and err.endswith("--controller: no entity 'Bob' (entities: Ego, scooter_1)\n")
    code, _, err = _vei(capsys, "run", scenario, "--controller", "Ego=no_such_package.mod:AEB")
    assert code == 2 and "no module 'no_such_package'" in err


def test_run_names_the_system_under_test_and_logs_its_state(scenario, tmp_path, capsys):
    target = f"{DATA}/aeb_flawed.py:LateAEB"
    code, out, _ = _vei(capsys, "run", scenario, "--param", "CapEnabled=true", "--controller", f"Ego={target}",
                        "--controller-param", "ttc_brake_s=0.8", "-o", tmp_path, "--no-plots")  # fmt: skip
    assert code == 0 and f"system under test on Ego: {target}" in out
    doc = json.loads((tmp_path / "metrics.json").read_text())
    sha = hashlib.sha256((DATA / "aeb_flawed.py").read_bytes()).hexdigest()
    assert doc["system_under_test"] == [
        {"entity": "Ego", "controller": target, "file": str(DATA / "aeb_flawed.py"), "sha256": sha,
         "parameters": {"ttc_brake_s": "0.8"}}
    ]  # fmt: skip
    rows = [r.split(",") for r in (tmp_path / "trajectories.csv").read_text().splitlines()[1:]]
    assert {r[-1] for r in rows[2:] if r[1] == "Ego"} == {"sut"}


def test_a_sweep_with_a_faulty_controller_fails_each_variant_and_finishes(scenario, tmp_path, capsys):
    code, out, err = _vei(capsys, "sweep", scenario, "--vary", "TimeShift=0:2:1", "--workers", "2", "--quiet",
                          "--controller", f"Ego={DATA}/faulty.py:RaisesAt2s", "-o", tmp_path)  # fmt: skip
    assert code == 1 and "3 variants (TimeShift): 0 collide (0 with the ego moving), 0 do not, 3 failed" in out
    assert "vei: 3 of 3 variants failed" in err and "sensor fusion lost track" in err
    catalog = json.loads((tmp_path / "catalog.json").read_text())
    assert [r["status"] for r in catalog["variants"]] == ["error"] * 3
    assert catalog["system_under_test"][0]["controller"].endswith("faulty.py:RaisesAt2s")


def test_falsify_finds_the_late_aebs_failures_and_its_reproduce_command_reproduces(scenario, tmp_path, capsys):
    target = f"Ego={DATA}/aeb_flawed.py:LateAEB"
    code, out, _ = _vei(capsys, "falsify", scenario, "--bounds", "TimeShift=1:4", "--values", "RiderType=replay",
                        "--param", "CapEnabled=true", "--controller", target, "-o", tmp_path / "f")  # fmt: skip
    assert code == 0
    doc = json.loads((tmp_path / "f" / "falsify.json").read_text())
    assert doc["regions"] and doc["system_under_test"][0]["entity"] == "Ego"
    command = doc["regions"][0]["reproduce"]
    assert f"--controller {target}" in command
    argv = shlex.split(command)[1:]
    code, out, _ = _vei(capsys, *argv, "--no-plots")
    assert code == 0 and "COLLISION" in out  # plain vei, the printed options: the same failure


def test_falsify_finds_every_failure_window_of_a_dense_grid_with_a_tenth_of_its_runs(scenario):
    """The late AEB, interpreted: a grid at 0.02 s over TimeShift 1..5 (201 runs; a grid over -1..5 finds
    no ego-moving collision below 1 s) against the search at 0.01 s (--tol 0.01): every window of
    ego-moving collisions the grid finds is a region of the search, its edges within the grid's step,
    in at most a tenth of the runs of a grid at the search's own resolution (401)."""
    from vei_scenario.falsify import Axis, falsify
    from vei_scenario.sweep.evaluate import evaluate_local

    controllers = tuple(parse_controller_options([f"Ego={DATA}/aeb_flawed.py:LateAEB"]))
    step = 0.02
    grid = [{"RiderType": "aggressive", "TimeShift": repr(round(1 + step * i, 2))} for i in range(201)]
    rows = evaluate_local(str(scenario), grid, 0.01, controllers=controllers)
    moving = [float(v["TimeShift"]) for v, r in zip(grid, rows) if r["metrics"]["collision_ego_moving"]]
    windows, start = [], None
    for a, b in zip(moving, moving[1:] + [None]):
        start = a if start is None else start
        if b is None or b - a > 1.5 * step:
            windows.append((start, a))
            start = None
    assert windows  # (the grid sees the late AEB fail)
    result = falsify(scenario, [Axis("TimeShift", 1, 5), Axis("RiderType", values=["aggressive"])], tol=0.01,
                     controllers=controllers)  # fmt: skip
    found = [(r.low, r.high) for r in result.regions]
    for a, b in windows:  # (each inside one region, whose edges are failing points 0.01 s from the grid's)
        assert any(lo <= a and hi >= b and a - lo <= 0.0101 and hi - b <= 0.0101 for lo, hi in found), (windows, found)
    for lo, hi in found:  # (a region no grid window is in: narrower than the grid's step, which steps over it)
        assert any(lo <= a and hi >= b for a, b in windows) or hi - lo < step, (windows, found)
    assert result.runs <= 0.1 * 401, result.runs


def test_a_scenario_controller_with_a_module_property_drives_as_the_storyboard_activates(scenario, tmp_path):
    """CARLA ScenarioRunner's convention: a Controller whose property ``module`` names the class (a file
    found from the scenario's directory), assigned and activated as the scenario says."""
    from lxml import etree

    tree = etree.parse(str(scenario))
    props = tree.find("Entities/ScenarioObject[@name='Ego']/ObjectController/Controller/Properties")
    etree.SubElement(props, "Property", name="module", value="aeb_flawed.py:LateAEB")
    for f in scenario.parent.iterdir():
        if f.suffix == ".xodr":
            (tmp_path / f.name).write_bytes(f.read_bytes())
    (tmp_path / "aeb_flawed.py").write_bytes((DATA / "aeb_flawed.py").read_bytes())
    path = tmp_path / "scenario.xosc"
    tree.write(str(path))
    on = run_scenario(path, _config("aggressive"))
    assert set(on.traces["Ego"].status[1:]) == {"sut"} and on.collisions
    off = run_scenario(path, {**_config("aggressive"), "CapEnabled": "false"})  # never activated: default
    assert "sut" not in off.traces["Ego"].status


def test_a_collision_with_the_ego_standing_is_said_to_be_one(scenario):
    """The rider replayed 3.35 s late runs into the ego the planner has stopped: a collision, not the
    planner's failure. The new metrics read off the trace independently."""
    from vei_scenario.metrics import MetricConfig, PairSeries, compute_metrics

    r = run_scenario(scenario, {"CapEnabled": "true", "RiderType": "replay", "TimeShift": "3.353814"})
    m = compute_metrics(PairSeries.from_run(r), MetricConfig())
    ego = r.traces["Ego"]
    (t_hit, *_), k = r.collisions[0], int(round(r.collisions[0][0] / 0.01))
    assert m["collision"] and not m["collision_ego_moving"]
    assert m["ego_speed_at_contact_mps"] == round(float(ego.speed[k]), 4) == 0.0
    still = np.flatnonzero(ego.speed[: k + 1] > 0.1)[-1] + 1  # the first step of the standstill
    assert m["ego_standing_before_contact_s"] == pytest.approx(t_hit - r.t[still], abs=1e-3)
    assert t_hit - r.t[still] > 0.5
    onset = int(np.flatnonzero(ego.accel <= -1.0)[0])
    assert m["brake_onset_s"] == pytest.approx(r.t[onset])
    assert m["speed_reduction_mps"] == pytest.approx(ego.speed[onset] - ego.speed[k], abs=1e-4)
    # the same run with the late AEB plugged in: the ego still moving at contact, the AEB's own failure
    late = run_scenario(scenario, _config("aggressive"), controllers=parse_controller_options(
        [f"Ego={DATA}/aeb_flawed.py:LateAEB"]))  # fmt: skip
    m = compute_metrics(PairSeries.from_run(late), MetricConfig())
    assert m["collision_ego_moving"] and m["ego_speed_at_contact_mps"] > 2.0 and m["ego_standing_before_contact_s"] == 0
    assert 0 < m["ttc_at_brake_onset_s"] < 0.7  # it brakes at TTC < 0.6 s (one step late)


def test_a_hanging_controller_fails_its_run_within_the_limit_and_a_sweep_goes_on(scenario, tmp_path, capsys):
    import time

    hangs = f"Ego={DATA}/faulty.py:Hangs"  # sleeps an hour in step from t = 1 s
    before = set(_children())  # (what earlier tests left running, a Dask cluster's helpers, is not this sweep's)
    started = time.perf_counter()
    code, _, err = _vei(capsys, "run", scenario, "--controller", hangs, "--controller-timeout", "0.3")
    assert code == 1 and err == (f"vei: error: controller {hangs} at t = 1.00 s: step did not return within 0.3 s "
                                 "(--controller-timeout)\n")  # fmt: skip
    code, out, err = _vei(capsys, "sweep", scenario, "--vary", "TimeShift=0:3:1", "--workers", "2", "--quiet",
                          "--controller", hangs, "--controller-timeout", "0.3", "-o", tmp_path)  # fmt: skip
    assert code == 1 and "4 failed" in out and "vei: 4 of 4 variants failed" in err
    assert time.perf_counter() - started < 20
    deadline = time.monotonic() + 5  # (a worker the pool has told to exit may take a moment to go)
    while set(_children()) - before and time.monotonic() < deadline:
        time.sleep(0.05)
    assert set(_children()) - before == set()  # no worker left behind


def _processes() -> dict[int, list[str]]:
    """Every live process (Linux /proc): its pid and the fields of its stat line after the name (state,
    parent, process group, session ...)."""
    out = {}
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                stat = (d / "stat").read_text()
            except OSError:
                continue
            out[int(d.name)] = stat.rsplit(")", 1)[1].split()
    return out


def _children() -> list[int]:
    """Processes whose parent is this one."""
    import os

    return [pid for pid, fields in _processes().items() if int(fields[1]) == os.getpid()]


def test_falsify_and_probability_refuse_a_controller_vei_has_no_model_of(scenario, tmp_path, capsys):
    typo = tmp_path / "typo.xosc"
    typo.write_text(scenario.read_text().replace('Controller name="CollisionAvoidancePlanner"',
                                                 'Controller name="CollisionAvoidancePlaner"'))  # fmt: skip
    (tmp_path / "scenario.xodr").write_bytes((scenario.parent / "scenario.xodr").read_bytes())
    box = ["--bounds", "TimeShift=2:3", "--values", "RiderType=replay", "--param", "CapEnabled=true", "--tol", "0.05"]
    code, _, err = _vei(capsys, "falsify", typo, *box)
    assert code == 2 and err.count("\n") == 1
    assert "Ego's controller 'CollisionAvoidancePlaner' names no model vei has" in err
    assert _vei(capsys, "falsify", typo, *box, "--allow-default-controller")[0] == 0
    assert _vei(capsys, "falsify", typo, *box, "--controller", f"Ego={DATA}/aeb_good.py:AEB")[0] == 0
    dist = tmp_path / "d.xosc"
    dist.write_text(
        '<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" '
        'description="d" author="t"/><ParameterValueDistribution><ScenarioFile filepath="typo.xosc"/>'
        '<Stochastic numberOfTestRuns="100" randomSeed="1"><StochasticDistribution parameterName="TimeShift">'
        '<UniformDistribution><Range lowerLimit="0" upperLimit="4"/></UniformDistribution></StochasticDistribution>'
        "</Stochastic></ParameterValueDistribution></OpenSCENARIO>"
    )
    code, _, err = _vei(capsys, "probability", typo, "--dist", dist, "--runs", "100", "--estimator", "monte-carlo")
    assert code == 2 and "names no model vei has" in err


needs_fmus = pytest.mark.skipif(
    __import__("sys").platform != "linux", reason="the test FMUs carry linux64 binaries only (pythonfmu)"
)


@needs_fmus
def test_an_fmu_drives_the_ego_through_vei_caps_ports(scenario, tmp_path, capsys):
    """FMUs with vei_cap's eight inputs and a_cmd (pythonfmu, tests/data/sut/fmu_src): the late one
    collides with the ego moving, the good one does not; a declared parameter is set, the scenario's
    planner properties (a_max_mps2, ...) that the FMU does not declare are not pushed onto it."""
    values = _config("aggressive")
    late = run_scenario(scenario, values, controllers=parse_controller_options([f"Ego={DATA}/LateAebFmu.fmu"]))
    good = run_scenario(scenario, values, controllers=parse_controller_options([f"Ego={DATA}/GoodAebFmu.fmu"]))
    assert late.collisions and not good.collisions
    assert late.traces["Ego"].accel.min() == pytest.approx(-4.0)  # its -4 m/s² through the vehicle model
    earlier = run_scenario(scenario, values, controllers=parse_controller_options(
        [f"Ego={DATA}/LateAebFmu.fmu"], ["ttc_brake_s=1.5"]))  # fmt: skip
    assert not earlier.collisions  # braking at TTC 1.5 s instead of 0.6 s avoids it
    code, out, _ = _vei(capsys, "run", scenario, "--controller", f"Ego={DATA}/LateAebFmu.fmu", "-o", tmp_path)
    doc = json.loads((tmp_path / "metrics.json").read_text())
    assert code == 0 and doc["system_under_test"][0]["sha256"] == hashlib.sha256(
        (DATA / "LateAebFmu.fmu").read_bytes()).hexdigest()  # fmt: skip


@needs_fmus
@pytest.mark.parametrize(
    "argv, code, says",
    [
        (["--controller", "Ego={d}/ErrorFmu.fmu"], 1, "ErrorFmu.fmu at t = 1.00 s: the FMU's doStep failed: "
         "fmi2DoStep returned fmi2Discard"),
        (["--controller", "Ego={d}/RaisingFmu.fmu"], 1, "RaisingFmu.fmu at t = 1.00 s: the FMU's doStep failed: "
         "fmi2DoStep returned fmi2"),
        (["--controller", "Ego={d}/WrongPortsFmu.fmu"], 2, "WrongPortsFmu.fmu: input 'x' (Real) is none vei provides"),
        (["--controller", "Ego={d}/LateAebFmu.fmu", "--controller-param", "brake=2"], 2,
         "LateAebFmu.fmu declares no parameter 'brake' (it has: ttc_brake_s)"),
        (["--controller", "Ego={d}/LateAebFmu.fmu", "--controller-param", "ttc_brake_s=soon"], 2,
         "parameter ttc_brake_s='soon' is not a Real value"),
        (["--controller", "Ego={d}/Nothing.fmu"], 2, "Nothing.fmu: no such file"),
    ],
)  # fmt: skip
def test_a_failing_or_mismatched_fmu_is_one_line(scenario, capsys, argv, code, says):
    got, _, err = _vei(capsys, "run", scenario, "--no-plots", *[a.format(d=DATA) for a in argv])
    assert got == code and err.count("\n") == 1 and err.startswith("vei: error: controller Ego=") and says in err


@needs_fmus
def test_a_sweep_with_a_failing_fmu_goes_on_and_leaves_no_worker(scenario, tmp_path, capsys):
    before = set(_children())
    code, out, err = _vei(capsys, "sweep", scenario, "--vary", "TimeShift=0:3:1", "--workers", "2", "--quiet",
                          "--controller", f"Ego={DATA}/ErrorFmu.fmu", "-o", tmp_path)  # fmt: skip
    assert code == 1 and "4 failed" in out and "fmi2Discard" in err
    assert set(_children()) - before == set()


def test_vei_planner_as_a_native_fmu_reproduces_the_built_in_one(scenario, tmp_path):
    """vei fmu build cap (the C planner in an FMU, through fmpy), given the scenario's cruise speed:
    study configurations 4 and 5 as the built-in planner drives them."""
    from vei_scenario.fmu import build_fmus

    fmu = build_fmus(["cap"], tmp_path)["cap"]
    plugged = parse_controller_options([f"Ego={fmu}"], ["cruise_speed_mps=5.61"])
    for rider in ("normal", "aggressive"):
        a, b = run_scenario(scenario, _config(rider)), run_scenario(scenario, _config(rider), controllers=plugged)
        for name, tr in a.traces.items():
            assert np.abs(tr.x - b.traces[name].x).max() <= 1e-9 and np.abs(tr.y - b.traces[name].y).max() <= 1e-9


CPNA = SHARED / "osc-ncap" / "OpenSCENARIO" / "NCAP" / "AEB_VRU_2023" / "Variations"
CPNA = CPNA / "NCAP_AEB_VRU_CPNA-25_50kph_2023.xosc"


@pytest.mark.skipif(not CPNA.is_file(), reason=f"the Euro NCAP pack not found ({NO_SHARED})")
def test_the_users_aeb_on_the_euro_ncap_vut(tmp_path, capsys):
    """Euro NCAP CPNA-25 at 50 km/h: the VUT, which no controller drives in the pack, hits the child as
    the pack plays it; with the example AEB plugged in it stops short, braking at 8 m/s²."""
    code, out, _ = _vei(capsys, "run", CPNA, "--no-plots")
    assert code == 0 and "Ego vs VRU: COLLISION" in out
    aeb = f"Ego={Path(__file__).resolve().parents[1]}/examples/controllers/aeb.py:AEB"
    code, out, _ = _vei(capsys, "run", CPNA, "--controller", aeb, "-o", tmp_path, "--no-plots")
    m = json.loads((tmp_path / "metrics.json").read_text())["metrics"]
    assert code == 0 and not m["collision"] and m["peak_decel_mps2"] == 8.0 and m["brake_onset_s"] is not None


def test_a_check_suite_names_its_system_under_test(scenario, tmp_path, capsys):
    (tmp_path / "aeb.py").write_bytes((DATA / "aeb_flawed.py").read_bytes())
    (tmp_path / "suite.toml").write_text(
        f'[[case]]\nname = "late AEB"\nscenario = "{scenario}"\n'
        'parameters = { TimeShift = 2.197, RiderType = "aggressive" }\ncontroller = "Ego=aeb.py:LateAEB"\n'
        'controller_parameters = { ttc_brake_s = 0.6 }\nexpect = ["collision_ego_moving == false"]\n'
    )
    code, out, _ = _vei(capsys, "check", tmp_path / "suite.toml", "--junit", tmp_path / "j.xml")
    assert code == 1 and "got collision_ego_moving = True" in out
    sha = hashlib.sha256((DATA / "aeb_flawed.py").read_bytes()).hexdigest()
    assert f'name="system_under_test.Ego" value="aeb.py:LateAEB sha256={sha}"' in (tmp_path / "j.xml").read_text()
    (tmp_path / "suite.toml").write_text((tmp_path / "suite.toml").read_text().replace("LateAEB", "Nope"))
    code, _, err = _vei(capsys, "check", tmp_path / "suite.toml")
    assert code == 2 and err.endswith("case[0].controller: controller Ego=aeb.py:Nope: aeb.py has no class 'Nope' "
                                      "(it has: BlindLeftAEB, LateAEB)\n")  # fmt: skip


def test_an_entry_point_of_the_group_vei_controllers_names_a_class(scenario, monkeypatch):
    import importlib.metadata

    class EntryPoint:
        name = "late-aeb"

        def load(self):
            return parse_controller_options([f"Ego={DATA}/aeb_flawed.py:LateAEB"])[0].load()

    def entry_points(group=None):
        return [EntryPoint()] if group == "vei.controllers" else []

    monkeypatch.setattr(importlib.metadata, "entry_points", entry_points)
    late = run_scenario(scenario, _config("aggressive"), controllers=parse_controller_options(["Ego=late-aeb"]))
    assert late.collisions
    with pytest.raises(ControllerFault, match="no FILE.py:CLASS, MODULE:CLASS or entry point"):
        parse_controller_options(["Ego=no-such-entry"])


@pytest.fixture(scope="module")
def native_faults(tmp_path_factory) -> dict[str, Path]:
    """The tiny native FMUs of data/sut/native_src: one segfaults at t >= 1 s, one never returns."""
    build = native_test_fmus().build
    out = tmp_path_factory.mktemp("native_fmus")
    return {fault: build(fault, out) for fault in ("CRASH", "HANG")}


def _descendants() -> set[int]:
    """Every live descendant of this process that is not a zombie."""
    import os

    procs = _processes()
    found, frontier = set(), {os.getpid()}
    while frontier:
        frontier = {pid for pid, fields in procs.items() if int(fields[1]) in frontier and fields[0] != "Z"} - found
        found |= frontier
    return found


@contextlib.contextmanager
def _adopting_orphans():
    """Make this process the child subreaper (Linux prctl) while the block runs, so that a process its
    children leave behind is re-parented here rather than to init, and ``_descendants`` still sees it.
    Counting descendants, not the whole session, keeps other jobs of the same session out of the count."""
    import ctypes

    prctl = ctypes.CDLL(None, use_errno=True).prctl
    pr_set_child_subreaper = 36
    if prctl(pr_set_child_subreaper, 1, 0, 0, 0) != 0:
        pytest.skip("prctl(PR_SET_CHILD_SUBREAPER) is not available here")
    try:
        yield
    finally:
        prctl(pr_set_child_subreaper, 0, 0, 0, 0)


@pytest.mark.parametrize(
    ("fault", "options", "reason"),
    [
        ("CRASH", [], "SegfaultFmu.fmu crashed (SIGSEGV) in doStep"),
        ("HANG", ["--controller-timeout", "0.3"], "step did not return within 0.3 s (--controller-timeout)"),
    ],
)
def test_a_native_fmu_that_crashes_or_hangs_fails_its_run_alone(scenario, tmp_path, capsys, native_faults, fault,
                                                                 options, reason):  # fmt: skip
    with _adopting_orphans():
        _fails_alone(scenario, tmp_path, capsys, native_faults[fault], options, reason)


def _fails_alone(scenario, tmp_path, capsys, fmu, options, reason):
    import time

    before = _descendants()
    target = f"Ego={fmu}"
    started = time.perf_counter()
    code, _, err = _vei(capsys, "run", scenario, "--controller", target, *options, "-o", tmp_path / "run")
    assert (code, err) == (1, f"vei: error: controller {target} at t = 1.00 s: {reason}\n")
    assert not (tmp_path / "run").exists()  # nothing written for a failed run
    code, out, err = _vei(capsys, "sweep", scenario, "--vary", "TimeShift=0:3:1", "--workers", "2", "--quiet",
                          "--controller", target, *options, "-o", tmp_path / "sweep")  # fmt: skip
    assert code == 1 and "4 failed" in out and "vei: 4 of 4 variants failed" in err
    catalog = json.loads((tmp_path / "sweep" / "catalog.json").read_text())
    assert all(reason in v["error"] for v in catalog["variants"])
    assert time.perf_counter() - started < 30
    assert _descendants() - before == set()  # no process left behind (an orphan is adopted here)


SWERVE = '''
class Swerve:
    """Holds its speed; from t = at asks to be `offset` metres left of its path or lane."""

    def __init__(self, offset="2.0", at="1.0", **_):
        self.offset, self.at = float(offset), float(at)

    def step(self, obs):
        return {"accel_mps2": 0.0, "lateral_offset_m": self.offset if obs.t_s >= self.at - 1e-9 else 0.0}
'''


def _sideways(a, b, k: int) -> tuple[float, float]:
    """(left, ahead) of run ``a``'s ego from run ``b``'s at row ``k``, in ``b``'s heading."""
    dx, dy, h = a.x[k] - b.x[k], a.y[k] - b.y[k], b.yaw[k]
    return -dx * np.sin(h) + dy * np.cos(h), dx * np.cos(h) + dy * np.sin(h)


def test_a_lateral_offset_command_moves_the_ego_beside_its_path_at_the_documented_rate(scenario, tmp_path):
    """lateral_offset_m: the ego moves left of its path at LATERAL_SPEED_MPS until it is there, heads
    where it moves (atan of sideways over forward speed), and keeps its along-path progress."""
    from vei_scenario.sut.contract import LATERAL_SPEED_MPS

    (tmp_path / "swerve.py").write_text(SWERVE)
    runs = {}
    for offset in ("2.0", "-1.0", "0"):
        (spec,) = parse_controller_options([f"Ego={tmp_path / 'swerve.py'}:Swerve"], [f"offset={offset}"])
        runs[offset] = run_scenario(scenario, {"TimeShift": "-3"}, controllers=(spec,)).traces["Ego"]
    straight = runs["0"]
    dt = 0.01
    for offset, sign in (("2.0", 1.0), ("-1.0", -1.0)):
        tr = runs[offset]
        k0 = int(round(1.0 / dt))  # the first command to move sideways drives the step from t = 1 s
        for k, want in ((k0, 0.0), (k0 + 10, 0.1 * LATERAL_SPEED_MPS), (k0 + 50, 0.5 * LATERAL_SPEED_MPS)):
            left, ahead = _sideways(tr, straight, k)
            assert left == pytest.approx(sign * want, abs=1e-9) and ahead == pytest.approx(0.0, abs=1e-9), (k, left)
        turned = tr.yaw[k0 + 10] - straight.yaw[k0 + 10]
        assert turned == pytest.approx(sign * np.arctan2(LATERAL_SPEED_MPS, straight.speed[k0 + 10]), abs=1e-9)
        left, _ = _sideways(tr, straight, k0 + 300)
        assert left == pytest.approx(float(offset), abs=1e-9)
        assert tr.yaw[k0 + 300] == pytest.approx(straight.yaw[k0 + 300], abs=1e-12)


def test_a_lateral_offset_command_moves_a_lane_driving_ego_within_its_road(tmp_path):
    """On a lane (no path): the offset is the lane offset, to the left of its direction of travel."""
    from roads import straight_500m

    (tmp_path / "swerve.py").write_text(SWERVE)
    xosc = tmp_path / "lane.xosc"
    text = (Path(__file__).parent / "data" / "following_brake.xosc").read_text()
    assert "<RoadNetwork/>" in text
    xosc.write_text(
        text.replace("<RoadNetwork/>", f'<RoadNetwork><LogicFile filepath="{straight_500m()}"/></RoadNetwork>')
    )
    (spec,) = parse_controller_options([f"Ego={tmp_path / 'swerve.py'}:Swerve"], ["offset=1.2"])
    (plain,) = parse_controller_options([f"Ego={tmp_path / 'swerve.py'}:Swerve"], ["offset=0"])
    moved = run_scenario(xosc, {}, controllers=(spec,)).traces["Ego"]
    kept = run_scenario(xosc, {}, controllers=(plain,)).traces["Ego"]
    k = int(round(3.0 / 0.01))
    left, ahead = _sideways(moved, kept, k)
    assert left == pytest.approx(1.2, abs=1e-6) and abs(ahead) < 1e-6


@pytest.mark.parametrize(
    "command, needle",
    [
        ({"accel_mps2": 0.0, "lateral_offset_m": float("nan")}, "lateral_offset_m nan"),
        ({"accel_mps2": 0.0, "lateral_offset_m": 30.0}, "not within ±10 m"),
        ({"accel_mps2": 0.0, "lateral_offset_m": "left"}, "lateral_offset_m is str 'left', not a number"),
    ],
)
def test_a_bad_lateral_command_is_the_controllers_fault(command, needle):
    with pytest.raises(ControllerFault, match=needle):
        command_from(command, "Ego=x.py:X", 1.0)


def test_fmu_call_failures_name_the_status_in_the_fmus_own_version():
    from vei_scenario.sut.fmu import _call_failure, status_name

    class Failed(Exception):
        def __init__(self, text, status):
            super().__init__(text)
            self.status = status

    assert _call_failure(Failed("fmi2DoStep failed with status 3 (error).", 3)) == "fmi2DoStep returned fmi2Error"
    assert _call_failure(Failed("fmi3DoStep failed with status 4 (fatal).", 4)) == "fmi3DoStep returned fmi3Fatal"
    assert status_name("fmi2DoStep", 5) == "fmi2Pending" and status_name("fmi3DoStep", 5) == "status 5"


@pytest.mark.parametrize(
    "fmi3, kind, value, setter",
    [
        (False, "Real", "1.5", ("setReal", 1.5)),
        (False, "Integer", "7", ("setInteger", 7)),
        (False, "Enumeration", "2", ("setInteger", 2)),
        (True, "Float64", "1.5", ("setFloat64", 1.5)),
        (True, "Float32", "1.5", ("setFloat32", 1.5)),
        (True, "Int64", "9007199254740993", ("setInt64", 9007199254740993)),
        (True, "UInt8", "200", ("setUInt8", 200)),
        (True, "Enumeration", "3", ("setInt64", 3)),
        (True, "Boolean", "true", ("setBoolean", True)),
    ],
)
def test_fmu_parameters_are_set_with_the_setter_of_their_type(fmi3, kind, value, setter):
    """Each declared type through its own setter (an FMI 3.0 Int64 through setInt32 would be cut)."""
    from vei_scenario.sut.fmu import FmuController, _typed

    calls = []

    class Recorder:
        def __getattr__(self, name):
            return lambda vrs, values: calls.append((name, values[0]))

    ctrl = FmuController.__new__(FmuController)
    ctrl.fmu, ctrl.ports = Recorder(), type("P", (), {"fmi3": fmi3})()
    ctrl._set(kind, 1, _typed(kind, value, "p", "Ego=x.fmu"))
    assert calls == [setter]


CRASHY = '''
class Crashy:
    """Brakes when the threat is within 12 m; raises when it is within 6 m (a bug of its own)."""

    def __init__(self, **_):
        pass

    def step(self, obs):
        if obs.threat is None:
            return 0.0
        d = ((obs.threat.x_m - obs.ego.x_m) ** 2 + (obs.threat.y_m - obs.ego.y_m) ** 2) ** 0.5
        if d < 6.0:
            raise ZeroDivisionError("division by zero")
        return -6.0 if d < 12.0 else 0.0
'''


def test_a_search_goes_on_past_the_systems_faults_and_counts_them(scenario, tmp_path, capsys):
    """falsify and risk: a run the system under test fails is a failure of the system (the worst), the
    search goes on, the outputs list the failed runs and the command exits 1 with the count."""
    (tmp_path / "crashy.py").write_text(CRASHY)
    plug = ["--controller", f"Ego={tmp_path / 'crashy.py'}:Crashy"]
    code = main(["falsify", str(scenario), "--bounds", "TimeShift=0:4", "--values", "RiderType=aggressive",
                 "--tol", "0.05", *plug, "-o", str(tmp_path / "fz")])  # fmt: skip
    out, err = capsys.readouterr()
    doc = json.loads((tmp_path / "fz" / "falsify.json").read_text())
    failed = doc["failed_runs"]
    assert code == 1 and 0 < len(failed) < doc["runs"], (code, err)
    assert err.count("\n") == 1 and f"{len(failed)} of {doc['runs']} runs failed in the system under test" in err
    assert all("step raised ZeroDivisionError: division by zero" in f["error"] for f in failed)
    assert "worst robustness the system under test failed" in out and doc["regions"]
    failing = {float(f["values"]["TimeShift"]) for f in failed}
    assert all(any(lo <= t <= hi for lo, hi in (g["edges"] for g in doc["regions"])) for t in failing)
    assert doc["regions"][0]["worst"]["robustness"] == -1e9
    code = main(["risk", str(scenario), "--window", "0:4", "--coarse", "0.2", "--tol", "0.05", *plug,
                 "-o", str(tmp_path / "rk")])  # fmt: skip
    _, err = capsys.readouterr()
    doc = json.loads((tmp_path / "rk" / "risk.json").read_text())
    assert code == 1 and "runs failed in the system under test" in err and err.count("\n") == 1, err
    assert any(s.get("failed_runs") for s in doc["searches"])


@pytest.mark.parametrize(
    "value", [np.float32(-1.5), np.float64(-1.5), np.int64(-2), np.array(-1.5), {"accel_mps2": np.float32(-1.5)}]
)
def test_numpy_numbers_are_commands(value):
    """An AEB computed with NumPy returns NumPy scalars or 0-d arrays: numbers, as the contract says."""
    cmd = command_from(value, "Ego=x.py:X", 1.0)
    assert isinstance(cmd.accel_mps2, float) and cmd.accel_mps2 in (-1.5, -2.0)


@pytest.mark.parametrize("value", [np.bool_(True), np.array([1.0]), np.array("1")])
def test_numpy_values_that_are_no_number_are_refused(value):
    with pytest.raises(ControllerFault, match="not an acceleration"):
        command_from(value, "Ego=x.py:X", 1.0)


def test_a_sweep_report_with_a_plugged_system_does_not_speak_of_vei_s_planner(scenario, tmp_path, capsys):
    code, _, _ = _vei(capsys, "sweep", scenario, "--vary", "TimeShift=2,2.5", "--vary", "CapEnabled=false",
                      "--quiet", "--controller", f"Ego={DATA}/aeb_flawed.py:LateAEB", "-o", tmp_path)  # fmt: skip
    assert code == 0
    page = (tmp_path / "report.html").read_text()
    assert "Your system under test drives the ego in every variant" in page
    assert "planner on (CapEnabled=true)" not in page and "<td>plugged</td>" in page and "<td>off</td>" not in page
