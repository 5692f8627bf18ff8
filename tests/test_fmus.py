"""The FMUs: standard conformance (fmpy validate, fmutool -check, the SSP XSD), the C models against
the numpy models, a host without Python, refused parameters, and the closed loop in third-party
co-simulation engines against ``vei run``."""

from __future__ import annotations

import ctypes
import math
import os
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest

from vei_scenario.core.sources import source_dir
from vei_scenario.fmu import MODELS, SPECS, build_fmus, cosimulate
from vei_scenario.fmu.native import fmi_header_dir
from vei_scenario.interpreter import run_scenario
from vei_scenario.models.boxes import time_to_contact
from vei_scenario.study import CONFIGURATIONS

HERE = Path(__file__).parent
N = 10_000


@pytest.fixture(scope="session")
def fmu_sets(tmp_path_factory) -> dict[str, dict[str, Path]]:
    out = tmp_path_factory.mktemp("fmus")
    return {
        "native-fmi2": build_fmus(list(MODELS), out / "fmi2"),
        "native-fmi3": build_fmus(list(MODELS), out / "fmi3", fmi=3),
        "python-fmi2": build_fmus(list(MODELS), out / "python", backend="python"),
    }


@pytest.fixture(scope="session")
def conflict_shift(case_study) -> str:
    """The compile's conflict TimeShift, where the study runs its configurations."""
    from vei_scenario.interpreter import load_scenario

    return load_scenario(case_study).parameters["ConflictTimeShift"]


# --- conformance ---------------------------------------------------------------------------------
def test_every_fmu_passes_fmpy_validate(fmu_sets):
    from concurrent.futures import ThreadPoolExecutor

    fmpy = Path(sys.executable).parent / "fmpy"
    paths = [p for fmus in fmu_sets.values() for p in fmus.values()]
    with ThreadPoolExecutor(max_workers=2) as pool:  # fmpy validate parses every variable name: ~4 s per FMU
        outs = list(
            pool.map(lambda p: subprocess.run([str(fmpy), "validate", str(p)], capture_output=True, text=True), paths)
        )
    for p, out in zip(paths, outs):
        assert out.returncode == 0 and "No problems found" in out.stdout, (p, out.stdout, out.stderr)


def test_every_fmu_simulates_with_its_own_default_start_values(fmu_sets):
    """A host that sets nothing (fmpy's simulate_fmu, the Reference FMUs' fmusim) must be able to run
    each FMU: the default track of the scooter FMU runs 1 m/s along x, its times increasing."""
    from fmpy import simulate_fmu

    for flavour, fmus in fmu_sets.items():
        for model, path in fmus.items():
            if flavour.startswith("python"):
                # a pythonfmu FMU embeds an interpreter: in a Python host it is run out of process, which
                # leaves without interpreter teardown (where pythonfmu crashes)
                code = (
                    "import os, sys, numpy as np; from fmpy import simulate_fmu\n"
                    "r = simulate_fmu(sys.argv[1], stop_time=2.0, step_size=0.01, output_interval=0.01)\n"
                    "print(r['time'][-1], all(np.all(np.isfinite(r[n])) for n in r.dtype.names "
                    "if r[n].dtype.kind == 'f'), flush=True)\n"
                    "os._exit(0)"
                )
                out = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True)
                assert out.returncode == 0 and out.stdout.split() == ["2.0", "True"], (model, out.stderr[-500:])
                continue
            res = simulate_fmu(str(path), stop_time=2.0, step_size=0.01, output_interval=0.01)
            assert res["time"][-1] == pytest.approx(2.0), (flavour, model)
            assert all(np.all(np.isfinite(res[n])) for n in res.dtype.names if res[n].dtype.kind == "f")
            if model == "sfm":  # a replay of the default track: x = t
                replay = {"rider_type": "replay"}
                res = simulate_fmu(str(path), stop_time=2.0, step_size=0.01, output_interval=0.01, start_values=replay)
                k = int(np.argmin(np.abs(res["time"] - 1.5)))
                assert res["x"][k] == pytest.approx(1.5, abs=1e-9) and res["speed"][k] == pytest.approx(1.0)


def test_a_c_host_that_sets_nothing_runs_every_native_fmu(fmu_sets, loader, tmp_path):
    """As the Reference FMUs' fmusim does by default (fmusim itself is not on a package index here):
    instantiate, initialise with the start values, step 2 s, with no parameter set."""
    for model, path in fmu_sets["native-fmi2"].items():
        cmds = ["init", *(f"step {k * 0.01!r} 0.01" for k in range(200)), "free"]
        out = _host(loader, path, tmp_path / model, cmds)
        assert "init 0" in out, (model, out[:5])
        assert sum(1 for line in out if line.startswith("step 0")) == 200, (model, out[-5:])


def test_a_per_scenario_build_reproduces_the_scenario_alone(case_study, conflict_shift, tmp_path):
    """`vei fmu build --scenario`: the scenario's thousands of values are the start values, so the
    scooter FMU run by a host that sets nothing replays the scooter exactly as `vei run` does."""
    values = {"TimeShift": conflict_shift, "RiderType": "replay", "CapEnabled": "false"}
    fmus = build_fmus(["sfm", "ego"], tmp_path, scenario=case_study, values=values)
    with zipfile.ZipFile(fmus["sfm"]) as zf:
        assert (
            '<DefaultExperiment startTime="0.0" stepSize="0.01" stopTime="25.01"/>'
            in zf.read("modelDescription.xml").decode()
        )
    run = run_scenario(case_study, values)
    # simulated by a fresh process with nothing but fmpy and the FMU (a host that sets nothing)
    code = (
        "import sys, numpy as np; from fmpy import simulate_fmu\n"
        "r = simulate_fmu(sys.argv[1], step_size=0.01, output_interval=0.01)\n"
        "np.savez(sys.argv[2], time=r['time'], x=r['x'], y=r['y'])"
    )
    out = tmp_path / "sim.npz"
    subprocess.run([sys.executable, "-c", code, str(fmus["sfm"]), str(out)], check=True)
    res = np.load(out)
    trace = run.traces[run.threat]
    t = np.round(res["time"], 6)
    k = np.searchsorted(np.round(trace.t, 6), t)
    assert np.array_equal(np.round(trace.t[k], 6), t) and t[-1] == pytest.approx(25.01)
    assert np.max(np.hypot(res["x"] - trace.x[k], res["y"] - trace.y[k])) <= 1e-6
    with pytest.raises(Exception, match="native backend"):
        build_fmus(["sfm"], tmp_path / "py", backend="python", scenario=case_study)


def test_every_fmu_passes_fmutool_check(fmu_sets, tmp_path):
    fmutool = Path(sys.executable).parent / "fmutool"
    for kind, fmus in fmu_sets.items():
        for model, path in fmus.items():
            out = subprocess.run([str(fmutool), "-input", str(path), "-check"], capture_output=True, text=True)
            text = out.stdout + out.stderr
            assert "seems to be compliant" in text and "No semantic error" in text, (kind, model, text)
            assert "ERROR" not in text, (kind, model, text)
    # the check can fail: an output without a start value declared initial="exact" is refused
    broken = tmp_path / "broken.fmu"
    with zipfile.ZipFile(fmu_sets["native-fmi2"]["cap"]) as src, zipfile.ZipFile(broken, "w") as dst:
        for name in src.namelist():
            data = src.read(name)
            if name == "modelDescription.xml":
                data = data.replace(
                    b'causality="output" variability="discrete"', b'causality="output" variability="fixed"'
                )
            dst.writestr(name, data)
    out = subprocess.run([str(fmutool), "-input", str(broken), "-check"], capture_output=True, text=True)
    assert "No semantic error" not in out.stdout + out.stderr


def test_native_fmus_are_self_contained_and_reproducible(fmu_sets, tmp_path):
    again = build_fmus(["sfm"], tmp_path)["sfm"]
    assert again.read_bytes() == fmu_sets["native-fmi2"]["sfm"].read_bytes()
    with zipfile.ZipFile(again) as zf:
        names = set(zf.namelist())
    assert "binaries/linux64/vei_sfm.so" in names
    assert {"sources/vei_models.c", "sources/sfm_model.c", "sources/fmi2_wrapper.c", "sources/fmi2Functions.h"} <= names
    assert not any(n.endswith(".py") for n in names)  # no Python at run time


def test_fmu_sources_rebuild_on_the_importers_side(fmu_sets, tmp_path):
    """An importer rebuilds the binary from sources/ alone (the SourceFiles of the modelDescription)."""

    fmu = fmu_sets["native-fmi2"]["ego"]
    with zipfile.ZipFile(fmu) as zf:
        zf.extractall(tmp_path)
    from lxml import etree

    files = [f.get("name") for f in etree.parse(str(tmp_path / "modelDescription.xml")).iterfind(".//SourceFiles/File")]
    assert len(files) == 4
    subprocess.run(["gcc", "-shared", "-fPIC", "-o", "rebuilt.so", *files, "-lm"], cwd=tmp_path / "sources", check=True)
    assert (tmp_path / "sources" / "rebuilt.so").stat().st_size > 0


def test_the_ssp_package_validates_against_the_ssp_schema(case_study, tmp_path):
    from fmpy.ssp.ssd import read_ssd

    from vei_scenario.fmu import build_system

    ssp = build_system(case_study, tmp_path / "loop.ssp", {"RiderType": "normal", "CapEnabled": "true"})
    ssd = read_ssd(str(ssp), validate=True)
    assert sorted(e.name for e in ssd.system.elements) == ["cap", "ego", "sfm"]
    assert len(ssd.system.connections) == 12
    with zipfile.ZipFile(ssp) as zf:
        assert {"resources/vei_sfm.fmu", "resources/vei_cap.fmu", "resources/vei_ego.fmu"} <= set(zf.namelist())


# --- the C boxes against the numpy boxes (the metrics' vectorised form) ----------------------------------
class CBox(ctypes.Structure):
    _fields_ = [(n, ctypes.c_double) for n in ("x", "y", "yaw", "length", "width")]


@pytest.fixture(scope="session")
def c_models(tmp_path_factory):
    """vei_models.c (the FMUs' numerical core) as a shared library, compiled as the FMUs are."""
    out = tmp_path_factory.mktemp("cmodels") / "libvei_models.so"
    subprocess.run(
        [
            "gcc",
            "-shared",
            "-fPIC",
            "-O2",
            "-std=c99",
            "-ffp-contract=off",
            "-o",
            str(out),
            str(source_dir() / "vei_models.c"),
            "-lm",
        ],
        check=True,
    )
    lib = ctypes.CDLL(str(out))
    lib.vei_time_to_contact.restype = ctypes.c_double
    lib.vei_cap_step.restype = ctypes.c_double
    return lib


def _close(a, b) -> None:
    a, b = np.asarray(a, float), np.asarray(b, float)
    finite = np.isfinite(b)
    assert np.array_equal(np.isfinite(a), finite)
    assert np.all(a[~finite] == b[~finite])
    assert np.all(np.abs(a[finite] - b[finite]) <= 1e-12 * np.maximum(1.0, np.abs(b[finite])))


def test_c_time_to_contact_equals_the_numpy_model_on_random_states(c_models):
    rng = np.random.default_rng(7)
    a = [
        rng.uniform(-20, 20, N),
        rng.uniform(-20, 20, N),
        rng.uniform(-4, 4, N),
        rng.uniform(1, 6, N),
        rng.uniform(0.5, 2.5, N),
    ]
    b = [
        rng.uniform(-20, 20, N),
        rng.uniform(-20, 20, N),
        rng.uniform(-4, 4, N),
        rng.uniform(0.5, 3, N),
        rng.uniform(0.3, 1, N),
    ]
    va, vb = rng.uniform(-10, 10, (2, N)), rng.uniform(-10, 10, (2, N))
    va[:, ::31] = vb[:, ::31]  # no relative motion
    ref = time_to_contact(*a[:5], va[0], va[1], *b[:5], vb[0], vb[1])
    got = np.array(
        [
            c_models.vei_time_to_contact(
                ctypes.byref(CBox(*(q[i] for q in a))),
                ctypes.c_double(va[0, i]),
                ctypes.c_double(va[1, i]),
                ctypes.byref(CBox(*(q[i] for q in b))),
                ctypes.c_double(vb[0, i]),
                ctypes.c_double(vb[1, i]),
            )
            for i in range(N)
        ]
    )
    assert np.isfinite(ref).sum() > N // 50 and (ref == 0).sum() > 0
    _close(got, ref)


# --- a host without Python, and refused parameters ------------------------------------------------------
@pytest.fixture(scope="session")
def loader(tmp_path_factory) -> Path:
    exe = tmp_path_factory.mktemp("loader") / "fmu_loader"
    subprocess.run(
        [
            "gcc",
            "-std=c99",
            "-D_POSIX_C_SOURCE=200809L",
            "-I",
            str(fmi_header_dir()),
            "-o",
            str(exe),
            str(HERE / "data" / "fmu_loader.c"),
            "-ldl",
        ],
        check=True,
    )
    return exe


def _host(loader: Path, fmu: Path, tmp: Path, commands: list[str]) -> list[str]:
    from fmpy import read_model_description

    with zipfile.ZipFile(fmu) as zf:
        zf.extractall(tmp)
    md = read_model_description(str(fmu))
    so = tmp / "binaries" / "linux64" / f"{md.coSimulation.modelIdentifier}.so"
    out = subprocess.run(
        [str(loader), str(so), md.guid], input="\n".join(commands) + "\n", capture_output=True, text=True, timeout=60
    )
    assert out.returncode == 0, out.stderr  # the host survives whatever the FMU was given
    return out.stdout.splitlines()


def test_a_c_host_steps_the_native_ego_fmu_like_the_python_model(fmu_sets, loader, tmp_path):
    from vei_scenario.fmu.python_models import EgoModel

    spec = SPECS["ego"]
    params = {
        "path_n": 3,
        "path_x[1]": 0.0,
        "path_x[2]": 20.0,
        "path_x[3]": 20.0,
        "path_y[1]": 0.0,
        "path_y[2]": 0.0,
        "path_y[3]": 30.0,
        "path_h[1]": 0.0,
        "path_h[2]": 0.0,
        "path_h[3]": math.pi / 2,
        "speed0": 8.0,
        "yaw0": 0.0,
    }
    cmds = [("int" if k == "path_n" else "real") + f" {spec.vr(k)} {v!r}" for k, v in params.items()]
    cmds.append("init")
    model = EgoModel()
    for k, v in params.items():
        model.set(k, v)
    model.initialize()
    a_cmd = [(-3.0 if 100 <= k < 160 else 1.0) for k in range(400)]
    for k, a in enumerate(a_cmd):
        cmds += [f"real {spec.vr('a_cmd')} {a!r}", f"step {k * 0.01!r} 0.01"]
        model.set("a_cmd", a)
        model.do_step(k * 0.01, 0.01)
    cmds += [f"get {spec.vr(q)}" for q in ("x", "y", "yaw", "speed", "s")]
    lines = _host(loader, fmu_sets["native-fmi2"]["ego"], tmp_path, cmds)
    assert lines[0] == "instantiate 0" and not any(ln.startswith("log") for ln in lines)
    assert all(ln.endswith(" 0") for ln in lines if not ln.startswith("value"))
    values = [float(ln.split()[1]) for ln in lines if ln.startswith("value")]
    expected = [model.values[q] for q in ("x", "y", "yaw", "speed", "s")]
    assert values == pytest.approx(expected, rel=1e-12, abs=1e-12)
    assert values[1] > 1.0  # it went round the corner


@pytest.mark.parametrize(
    ("model", "commands", "message"),
    [
        ("sfm", ["real {mass_kg} -95", "init"], "mass_kg must be positive"),
        ("sfm", ["string {rider_type} reckless", "init"], "rider_type 'reckless' is not one of"),
        ("sfm", ["real {ego_x} nan"], "ego_x = nan is not a finite number"),
        ("cap", ["real {a_max_mps2} 0", "init"], "a_max_mps2 must be positive"),
        ("ego", ["int {path_n} 5000", "init"], "path_n must be 2..512"),
        ("ego", ["init", "real {x0} 3"], "cannot be set now"),
    ],
)
def test_bad_parameters_give_fmi2error_with_a_logged_message(fmu_sets, loader, tmp_path, model, commands, message):
    spec = SPECS[model]
    names = {v.name: spec.first_vr(v) for v in spec.variables}
    cmds = [c.format(**names) for c in commands] + ["step 0 0.01"]
    lines = _host(loader, fmu_sets["native-fmi2"][model], tmp_path, cmds)
    logs = [ln for ln in lines if ln.startswith("log 3 logStatusError")]
    assert any(message in ln for ln in logs), lines
    statuses = [ln for ln in lines if not ln.startswith(("log", "value"))]
    assert statuses[-1] == "step 3"  # the failed instance refuses to step, the host carries on


def test_bad_parameters_are_refused_by_the_fmi3_and_python_fmus(fmu_sets, capfd):
    """The native FMI 3 FMU answers fmi3Error; pythonfmu's runtime turns the model's exception into
    fmi2Fatal. Both log the reason and leave the host running."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave
    from fmpy.fmi3 import FMU3Slave

    # the pythonfmu FMU in a process of its own: its embedded interpreter corrupts the host's heap
    code = (
        "import os, sys; from fmpy import extract, read_model_description; from fmpy.fmi2 import FMU2Slave\n"
        "md = read_model_description(sys.argv[1]); vr = {v.name: v.valueReference for v in md.modelVariables}\n"
        "fmu = FMU2Slave(guid=md.guid, unzipDirectory=extract(sys.argv[1]), modelIdentifier='vei_sfm',"
        " instanceName='bad')\n"
        "fmu.instantiate(loggingOn=True); fmu.setupExperiment(); fmu.enterInitializationMode()\n"
        "fmu.setReal([vr['mass_kg']], [-1.0])\n"
        "try:\n    fmu.exitInitializationMode(); print('accepted')\n"
        "except Exception as e:\n    print('refused:', e)\n"
        "sys.stdout.flush(); os._exit(0)"
    )
    out = subprocess.run(
        [sys.executable, "-c", code, str(fmu_sets["python-fmi2"]["sfm"])], capture_output=True, text=True
    )
    assert "refused:" in out.stdout and "4 (fatal)" in out.stdout, out.stdout + out.stderr
    assert "mass_kg and tau_s must be positive" in out.stdout + out.stderr
    for kind, status, reason in (("native-fmi3", "3 (error)", "mass_kg must be positive (got -1)"),):
        path = fmu_sets[kind]["sfm"]
        md = read_model_description(str(path))
        vr = {v.name: v.valueReference for v in md.modelVariables}
        cls = FMU3Slave if kind.endswith("fmi3") else FMU2Slave
        fmu = cls(guid=md.guid, unzipDirectory=extract(str(path)), modelIdentifier="vei_sfm", instanceName="bad")
        fmu.instantiate(loggingOn=True)  # pythonfmu forwards log messages only with logging on
        if kind.endswith("fmi3"):
            fmu.enterInitializationMode()
            fmu.setFloat64([vr["mass_kg"]], [-1.0])
        else:
            fmu.setupExperiment()
            fmu.enterInitializationMode()
            fmu.setReal([vr["mass_kg"]], [-1.0])
        with pytest.raises(Exception, match=re.escape(status)):
            fmu.exitInitializationMode()
        assert reason in capfd.readouterr().out
        fmu.freeInstance()


# --- the closed loop in co-simulation engines -----------------------------------------------------
def _config(number: int) -> dict[str, str]:
    return next(p for n, _, p in CONFIGURATIONS if n == number)


@pytest.mark.parametrize("config", [2, 3, 4, 5])
@pytest.mark.parametrize(("engine", "coupling"), [("fmpy", "sequential"), ("fmpy", "jacobi"), ("libcosim", "jacobi")])
def test_closed_loop_in_an_engine_matches_vei_run(fmu_sets, case_study, conflict_shift, config, engine, coupling):
    values = {**_config(config), "TimeShift": conflict_shift}
    rep = cosimulate(case_study, engine, values, 0.01, coupling, fmus=fmu_sets["native-fmi2"])
    assert rep.steps == 2501
    assert max(rep.max_deviation_m.values()) <= 1e-6, rep.max_deviation_m
    # the scooter rides the model and the loop is closed: it is not the recording replayed
    assert rep.record["sfm"]["speed"].std() > 0.05
    if config >= 4:
        assert rep.record["cap"]["a_cmd"].min() < -2.9  # the planner brakes


def test_fmi3_fmus_close_the_loop_like_vei_run(fmu_sets, case_study, conflict_shift):
    values = {**_config(5), "TimeShift": conflict_shift}
    rep = cosimulate(case_study, "fmpy", values, 0.01, None, fmus=fmu_sets["native-fmi3"])
    assert max(rep.max_deviation_m.values()) <= 1e-6, rep.max_deviation_m


def test_python_fmus_close_the_loop_like_vei_run(case_study, conflict_shift, tmp_path):
    """Through the command line, in a fresh process: pythonfmu's runtime instantiates a given Python
    FMU from one extraction per process (declared canBeInstantiatedOnlyOncePerProcess)."""
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "vei_scenario",
            "fmu",
            "cosim",
            str(case_study),
            "--backend",
            "python",
            "--param",
            "RiderType=aggressive",
            "--param",
            "CapEnabled=true",
            "--param",
            f"TimeShift={conflict_shift}",
            "-o",
            str(tmp_path / "loop.csv"),
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert out.returncode == 0, out.stdout + out.stderr
    assert "largest deviation from vei run: ego 0 m, sfm 0 m" in out.stdout
    rows = (tmp_path / "loop.csv").read_text().splitlines()
    assert rows[0].startswith("time_s,ego.x_m,ego.y_m") and len(rows) == 2503


def test_the_ssp_runs_in_ecos_like_vei_run_jacobi(case_study, conflict_shift, tmp_path):
    """A third SSP host: ecos applies a parameter set by name, so every component's set carries one name.
    Stepped on the previous outputs (Jacobi), it must reproduce `vei run --coupling jacobi`."""
    try:
        import ecospy  # noqa: F401
    except ImportError:
        pytest.skip("ecospy is not installed (pip install ecospy)")
    except OSError as exc:  # its native library needs Intel TBB
        pytest.skip(f"ecos cannot load ({exc}): apt-get install libtbb12")
    from vei_scenario.fmu import build_system

    params = {"RiderType": "aggressive", "CapEnabled": "true", "TimeShift": conflict_shift}
    ssp = build_system(case_study, tmp_path / "loop.ssp", params)
    run = run_scenario(case_study, params, 0.01, coupling="jacobi")
    code = (
        "import sys, numpy as np; from ecospy import EcosSimulation\n"
        "sim = EcosSimulation(step_size=0.01, ssp_path=sys.argv[1]); sim.init(parameter_set='scenario')\n"
        "rec = []\n"
        "for _ in range(int(sys.argv[3])):\n"
        "    sim.step(); rec.append([sim.get_real(n) for n in ('ego::x', 'ego::y', 'sfm::x', 'sfm::y')])\n"
        "sim.terminate(); sim.free(); np.save(sys.argv[2], np.array(rec))"
    )
    out = tmp_path / "ecos.npy"
    proc = subprocess.run(
        [sys.executable, "-c", code, str(ssp), str(out), str(run.t.size - 1)], capture_output=True, text=True
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    rec = np.load(out)
    ego, scooter = run.traces[run.ego], run.traces[run.threat]
    assert np.hypot(rec[:, 0] - ego.x[1:], rec[:, 1] - ego.y[1:]).max() <= 1e-6
    assert np.hypot(rec[:, 2] - scooter.x[1:], rec[:, 3] - scooter.y[1:]).max() <= 1e-6
    assert np.ptp(rec[:, 2]) > 10.0  # the scooter moved: its parameters (track, route) were applied


def test_the_coupling_scheme_matters(case_study, conflict_shift):
    """Jacobi and sequential coupling give different runs, so matching each engine's scheme is needed."""
    values = {**_config(5), "TimeShift": conflict_shift}
    a = run_scenario(case_study, values, 0.01, coupling="sequential").traces["Ego"]
    b = run_scenario(case_study, values, 0.01, coupling="jacobi").traces["Ego"]
    assert np.max(np.hypot(a.x - b.x, a.y - b.y)) > 1e-3


def test_fmu_commands_report_user_errors_in_one_line(case_study, tmp_path):
    bad = HERE / "data" / "following_brake.xosc"
    out = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "fmu", "system", str(bad), "-o", str(tmp_path / "x.ssp")],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and "not a vei-compiled closed loop" in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1 and not (tmp_path / "x.ssp").exists()
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "vei_scenario",
            "fmu",
            "cosim",
            str(case_study),
            "--engine",
            "libcosim",
            "--coupling",
            "sequential",
        ],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and "Jacobi" in out.stderr
    if shutil.which("gcc"):
        out = subprocess.run(
            [
                sys.executable,
                "-m",
                "vei_scenario",
                "fmu",
                "build",
                "sfm",
                "-o",
                str(tmp_path / "d"),
                "--backend",
                "python",
                "--fmi",
                "3",
            ],
            capture_output=True,
            text=True,
        )
        assert out.returncode == 2 and "FMI 2.0 FMUs only" in out.stderr
    out = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "fmu", "build", "ego", "-o", str(tmp_path / "e")],
        capture_output=True,
        text=True,
        env={**os.environ, "CC": "/nonexistent/cc"},
    )
    assert out.returncode == 2 and "CC='/nonexistent/cc' is not an executable" in out.stderr
    assert not (tmp_path / "e").exists() or not any((tmp_path / "e").iterdir())
    out = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "fmu", "cosim", str(case_study), "--param", "EgoCruiseSpeed=-1"],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and out.stderr.strip() == (
        "vei: error: ego: the FMU refused: fmi2ExitInitializationMode failed with status 3 (error)."
    )
    assert "speed0 must not be negative (got -1)" in out.stdout  # the FMU's own log line
