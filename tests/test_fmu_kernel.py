"""A native FMU on the ego stepped by the compiled sweep kernel: the same rows as the built-in planner
and as the interpreter's plugged FMU, and its faults failing their variants alone in forked children."""

from __future__ import annotations

import json
import math
import os
import sys
from pathlib import Path

import pytest

from conftest import native_test_fmus
from vei_scenario.cli import main
from vei_scenario.sut import parse_controller_options
from vei_scenario.sweep.evaluate import _kernel_fmu, evaluate_local, evaluate_variant

DATA = Path(__file__).parent / "data" / "sut"
CRUISE = "cruise_speed_mps=5.61"  # (the case study's EgoCruiseSpeed: vei_cap names it otherwise)


@pytest.fixture(scope="module")
def scenario(compiled) -> Path:
    return next(p for p in compiled["case_study"].written if p.name == "scenario.xosc")


@pytest.fixture(scope="module")
def cap_fmu(tmp_path_factory) -> Path:
    from vei_scenario.fmu import build_fmus

    return build_fmus(["cap"], tmp_path_factory.mktemp("cap"))["cap"]


@pytest.fixture(scope="module")
def faulty(tmp_path_factory) -> dict[str, Path]:
    """The tiny native FMUs of data/sut/native_src, each failing at t >= 1 s where CapEnabled is true."""
    build = native_test_fmus().build
    out = tmp_path_factory.mktemp("faulty")
    return {fault: build(fault, out, gated=True) for fault in ("ERROR", "NAN", "CRASH", "HANG")}


def _vei(capsys, *argv) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    got = capsys.readouterr()
    return code, got.out, got.err


def _children() -> set[int]:
    """Live processes whose parent is this one (Linux /proc; zombies included: unreaped is left behind)."""
    out = set()
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                fields = (d / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == os.getpid():
                out.add(int(d.name))
    return out


def test_the_kernel_steps_a_native_fmu_and_leaves_a_python_one_to_the_interpreter(scenario, cap_fmu):
    from vei_scenario.batch.fmu_ego import not_for_kernel

    s = str(scenario.resolve())
    assert _kernel_fmu(s, 0.01, "2d", parse_controller_options([f"Ego={cap_fmu}"], [CRUISE])) is not None
    python_fmu = parse_controller_options([f"Ego={DATA}/GoodAebFmu.fmu"])
    assert not_for_kernel(python_fmu[0].load()) == "a PythonFMU (its binary runs Python)"
    assert _kernel_fmu(s, 0.01, "2d", python_fmu) is None
    assert _kernel_fmu(s, 0.01, "2d", parse_controller_options([f"Ego={DATA}/aeb_good.py:AEB"])) is None


def test_vei_planner_as_a_kernel_fmu_reproduces_the_built_in_sweep(scenario, cap_fmu, tmp_path, capsys):
    """1 000 variants of the case study (TimeShift x RiderType, planner on): the catalog with vei_cap.fmu
    on the ego is the built-in planner's, but for the field naming the system under test."""
    vary = ["--vary", "TimeShift=-1:3.995:0.01", "--vary", "RiderType=normal,aggressive", "--vary", "CapEnabled=true"]
    code, out, _ = _vei(capsys, "sweep", scenario, *vary, "--quiet", "-o", tmp_path / "built_in")
    assert code == 0 and out.startswith("1000 variants")
    code, _, _ = _vei(capsys, "sweep", scenario, *vary, "--quiet", "--controller", f"Ego={cap_fmu}",
                      "--controller-param", CRUISE, "-o", tmp_path / "fmu")  # fmt: skip
    assert code == 0
    a = json.loads((tmp_path / "built_in" / "catalog.json").read_text())
    b = json.loads((tmp_path / "fmu" / "catalog.json").read_text())
    assert b.pop("system_under_test")[0]["controller"] == str(cap_fmu)
    assert a == b
    assert (tmp_path / "built_in" / "catalog.csv").read_bytes() == (tmp_path / "fmu" / "catalog.csv").read_bytes()


def test_vei_cap_fmu_takes_the_scenarios_cruise_speed_per_variant(scenario, cap_fmu, tmp_path, capsys):
    """Without --controller-param, vei_cap.fmu's cruise_speed_mps is the scenario's cruiseSpeed property
    ($EgoCruiseSpeed, varied here): in the kernel and in vei run, as the built-in planner cruises."""
    vary = ["--vary", "TimeShift=0,2.197", "--vary", "EgoCruiseSpeed=4,7.5", "--vary", "CapEnabled=true"]
    code, _, _ = _vei(capsys, "sweep", scenario, *vary, "--quiet", "-o", tmp_path / "built_in")
    assert code == 0
    code, _, _ = _vei(capsys, "sweep", scenario, *vary, "--quiet", "--controller", f"Ego={cap_fmu}", "-o",
                      tmp_path / "fmu")  # fmt: skip
    assert code == 0
    assert (tmp_path / "built_in" / "catalog.csv").read_bytes() == (tmp_path / "fmu" / "catalog.csv").read_bytes()
    from vei_scenario.interpreter import run_scenario

    (plugged,) = parse_controller_options([f"Ego={cap_fmu}"])
    params = {"TimeShift": "2.197", "EgoCruiseSpeed": "7.5", "CapEnabled": "true"}
    ego = run_scenario(scenario, params, controllers=(plugged,)).traces["Ego"]
    assert ego.speed[300] == pytest.approx(7.5, abs=0.05)  # (cruising at the scenario's speed, not 5 m/s)


@pytest.fixture(scope="module")
def cap_fmu3(tmp_path_factory) -> Path:
    from vei_scenario.fmu import build_fmus

    return build_fmus(["cap"], tmp_path_factory.mktemp("cap3"), fmi=3)["cap"]


@pytest.mark.parametrize("fmi", [2, 3])
def test_kernel_and_interpreter_give_the_same_rows_for_the_same_fmu(scenario, cap_fmu, cap_fmu3, fmi):
    """Study configurations 4 and 5 (TimeShift 2.197, normal and aggressive rider, planner on) and others,
    the planner switched off through the FMU's parameter enabled among them; FMI 2.0 and 3.0."""
    s = str(scenario.resolve())
    plugged = parse_controller_options([f"Ego={cap_fmu if fmi == 2 else cap_fmu3}"], [CRUISE])
    assert _kernel_fmu(s, 0.01, "2d", plugged) is not None
    variants = [{"TimeShift": ts, "RiderType": r, "CapEnabled": on} for ts in ("2.197", "0.4", "3.35")
                for r in ("normal", "aggressive", "replay") for on in ("true", "false")]  # fmt: skip
    kernel = evaluate_local(s, variants, 0.01, 2, controllers=plugged)
    built_in = evaluate_local(s, variants, 0.01, 2)
    for v, k, b in zip(variants, kernel, built_in):
        assert k == evaluate_variant(s, v, 0.01, controllers=plugged), v
        if v["CapEnabled"] == "true":
            assert k == b, v


@pytest.mark.parametrize(
    ("fault", "options", "reason"),
    [
        ("ERROR", [], "the FMU's doStep failed: fmi2DoStep returned fmi2Error"),
        ("NAN", [], "step returned a non-finite command (nan)"),
        ("CRASH", [], "GatedSegfaultFmu.fmu crashed (SIGSEGV) in doStep"),
        ("HANG", ["--controller-timeout", "0.3"], "step did not return within 0.3 s (--controller-timeout)"),
    ],
)
def test_a_faulty_kernel_fmu_fails_its_variants_alone(scenario, faulty, tmp_path, capsys, fault, options, reason):
    """The FMU fails at t = 1 s where the planner's switch (its parameter enabled) is on: those variants
    fail with vei run's line, the others are scored, the sweep exits 1 with the count, no process is
    left behind."""
    target = f"Ego={faulty[fault]}"
    code, _, err = _vei(capsys, "run", scenario, "--param", "CapEnabled=true", "--controller", target, *options,
                        "--no-plots", "-o", tmp_path / "run")  # fmt: skip
    line = f"controller {target} at t = 1.00 s: {reason}"
    assert (code, err) == (1, f"vei: error: {line}\n")
    before = _children()
    vary = ["--vary", "TimeShift=0:3:1", "--vary", "CapEnabled=true,false"]
    code, out, err = _vei(capsys, "sweep", scenario, *vary, "--workers", "2", "--quiet", "--controller", target,
                          *options, "-o", tmp_path / "sweep")  # fmt: skip
    assert code == 1 and "4 failed" in out and "vei: 4 of 8 variants failed" in err
    assert _children() - before == set()
    rows = json.loads((tmp_path / "sweep" / "catalog.json").read_text())["variants"]
    assert [r["error"] for r in rows if r["parameters"]["CapEnabled"] == "true"] == [line] * 4
    assert all(r["status"] == "ok" and "min_gap_m" in r["metrics"] for r in rows
               if r["parameters"]["CapEnabled"] == "false")  # fmt: skip


def test_a_crash_pinpoints_its_variant_among_many(scenario, faulty):
    """A chunk of variants in one child: the crash fails the variant it happened in, the rest of the chunk
    goes on in a new child."""
    s = str(scenario.resolve())
    plugged = parse_controller_options([f"Ego={faulty['CRASH']}"])
    variants = [{"TimeShift": f"{0.1 * k:.1f}", "CapEnabled": "true" if k % 7 == 3 else "false"} for k in range(40)]
    rows = evaluate_local(s, variants, 0.01, 2, controllers=plugged)
    failed = [k for k, r in enumerate(rows) if r["status"] != "ok"]
    assert failed == [k for k in range(40) if k % 7 == 3]
    assert all("crashed (SIGSEGV) in doStep" in rows[k]["error"] for k in failed)


def test_a_hang_without_a_timeout_is_bounded_in_a_sweep(scenario, faulty, monkeypatch):
    from vei_scenario.batch import fmu_ego

    monkeypatch.setattr(fmu_ego, "CALL_BOUND_S", 0.3)
    s = str(scenario.resolve())
    plugged = parse_controller_options([f"Ego={faulty['HANG']}"])
    rows = evaluate_local(s, [{"CapEnabled": "true"}, {"CapEnabled": "false"}], 0.01, 2, controllers=plugged)
    assert rows[0]["error"] == (f"controller Ego={faulty['HANG']} at t = 1.00 s: step did not return within 0.3 s "
                                "(a sweep's bound of one call without --controller-timeout)")  # fmt: skip
    assert rows[1]["status"] == "ok"


def test_a_death_outside_the_fmu_is_found_by_running_the_rest_one_at_a_time():
    """A child that dies where its page names no call into the FMU: the rest of its chunk runs one
    variant a child, and only the variant whose own run kills its process fails."""
    import signal

    from vei_scenario.sweep.contained import run_contained

    def rows(indices, page):
        if 7 in indices:
            os.kill(os.getpid(), signal.SIGSEGV)
        return [{"status": "ok", "i": i} for i in indices]

    def death_row(how, t, call, timed_out):
        return {"status": "error", "how": how, "call": call, "timed_out": timed_out}

    before = _children()
    got = run_contained(rows, [list(range(20))], 2, death_row)
    assert _children() - before == set()
    assert sorted(got) == list(range(20))
    assert got[7] == {"status": "error", "how": "crashed (SIGSEGV)", "call": -1, "timed_out": False}
    assert all(got[i] == {"status": "ok", "i": i} for i in range(20) if i != 7)


def _children_of(pid: int) -> set[int]:
    out = set()
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                if int((d / "stat").read_text().rsplit(")", 1)[1].split()[1]) == pid:
                    out.add(int(d.name))
            except (OSError, IndexError):
                continue
    return out


def _killed_while_hanging(argv: list[str], n_children: int, how) -> None:
    """Start ``vei``, wait until ``n_children`` children hang in the FMU, kill it with ``how``: none of
    the children may be left (a hung doStep reads no end-of-file from its dead parent)."""
    import subprocess
    import time

    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 60
        while len(_children_of(proc.pid)) < n_children and time.monotonic() < deadline:
            time.sleep(0.1)
        time.sleep(2.0)  # (at t = 1 s of their first variant they hang)
        kids = _children_of(proc.pid)
        assert len(kids) >= n_children
    finally:
        proc.send_signal(how)
        proc.wait()
    deadline = time.monotonic() + 5
    while any(Path(f"/proc/{k}").exists() for k in kids) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not any(Path(f"/proc/{k}/stat").exists() and " Z " not in Path(f"/proc/{k}/stat").read_text() for k in kids)


def test_the_fmu_children_die_with_the_sweep(scenario, faulty, tmp_path):
    """The sweep killed while its children hang in the FMU: none of them is left."""
    import signal

    vary = ["--vary", "TimeShift=0:3:1", "--vary", "CapEnabled=true"]
    argv = [sys.executable, "-m", "vei_scenario", "sweep", str(scenario), *vary, "--workers", "2", "--quiet",
            "--controller", f"Ego={faulty['HANG']}", "-o", str(tmp_path)]  # fmt: skip
    _killed_while_hanging(argv, 2, signal.SIGKILL)


@pytest.mark.parametrize("how", ["SIGTERM", "SIGKILL"])
def test_the_fmu_child_of_a_run_dies_with_it(scenario, faulty, tmp_path, how):
    """vei run steps a native FMU in a child of its own; killed while that child hangs in doStep (no
    --controller-timeout), the child goes too."""
    import signal

    argv = [sys.executable, "-m", "vei_scenario", "run", str(scenario), "--param", "CapEnabled=true", "--no-plots",
            "--controller", f"Ego={faulty['HANG']}", "-o", str(tmp_path)]  # fmt: skip
    _killed_while_hanging(argv, 1, getattr(signal, how))


def test_an_exception_of_vei_in_a_child_stops_the_evaluation():
    from vei_scenario.sweep.contained import run_contained

    def rows(indices, page):
        raise ValueError("a bug of vei's own")

    before = _children()
    with pytest.raises(ValueError, match="a bug of vei's own"):
        run_contained(rows, [list(range(10))], 2, lambda *a: {})
    assert _children() - before == set()


def test_every_input_reaches_a_kernel_fmu_as_the_interpreter_gives_it(scenario, tmp_path):
    """A C FMU that reads all 15 inputs (the threat's acceleration, the box sizes, the time ...) into its
    command: the kernel's rows are the interpreter's, and the riders' differences reach the ego."""
    s = str(scenario.resolve())
    plugged = parse_controller_options([f"Ego={native_test_fmus().build_all_inputs(tmp_path)}"])
    assert _kernel_fmu(s, 0.01, "2d", plugged) is not None
    variants = [{"TimeShift": ts, "RiderType": r} for ts in ("0.5", "3.3") for r in ("normal", "aggressive", "replay")]
    rows = evaluate_local(s, variants, 0.01, 2, controllers=plugged)
    assert rows == [evaluate_variant(s, v, 0.01, controllers=plugged) for v in variants]
    assert len({r["metrics"]["peak_decel_mps2"] for r in rows[3:]}) == 3


@pytest.mark.parametrize(
    ("how", "t", "call", "timed_out", "says"),
    [
        ("crashed (SIGSEGV)", math.nan, 0, False, ": vei_cap.fmu crashed (SIGSEGV) while instantiating it"),
        ("crashed (SIGSEGV)", 1.0, 7, False, " at t = 1.00 s: vei_cap.fmu crashed (SIGSEGV) in doStep"),
        ("crashed (SIGABRT)", 24.99, 9, False, " at t = 24.99 s: vei_cap.fmu crashed (SIGABRT) in fmi2Terminate"),
        ("ended with exit status 3", 2.0, 8, False, " at t = 2.00 s: vei_cap.fmu ended with exit status 3 in fmi2GetReal"),  # noqa: E501
        ("", math.nan, 2, True, ": instantiating vei_cap.fmu did not return within 60 s (a sweep's bound"),
        ("", 2.0, 3, True, " at t = 2.00 s: step did not return within 60 s (a sweep's bound"),
    ],
)  # fmt: skip
def test_a_workers_death_is_said_by_the_call_it_happened_in(scenario, cap_fmu, how, t, call, timed_out, says):
    k = _kernel_fmu(str(scenario.resolve()), 0.01, "2d", parse_controller_options([f"Ego={cap_fmu}"], [CRUISE]))
    assert k.death_line(how, t, call, timed_out).startswith(f"controller Ego={cap_fmu}{says}")
