"""vei's rider and planner as native C OSMP traffic participants (``vei fmu build sfm cap --osmp``):
hosted back in ``vei run`` they are the built-in models; they declare what OSMP requires; they run in a
process where vei cannot be imported (fmpy, the test partners' own host) and in a C host with no Python
at all; their output buffers stay valid as OSMP requires.

They need protoc-c and the protobuf-c runtime (Debian: protobuf-c-compiler, libprotobuf-c-dev); where
those are missing the tests skip with the line ``vei fmu build --osmp`` prints."""

from __future__ import annotations

import ctypes
import json
import math
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest
from osmp_plugs import BUILT_FOR, PLUGS

from vei_scenario.cli import main
from vei_scenario.fmu import osmp_native
from vei_scenario.fmu.osmp_rider import build_osmp
from vei_scenario.interpreter import run_scenario
from vei_scenario.study import CONFIGURATIONS
from vei_scenario.sut import parse_controller_options
from vei_scenario.sut.osmp import merge_address, read_osmp_ports, split_address

MISSING = osmp_native.missing()
pytestmark = pytest.mark.skipif(MISSING is not None, reason=MISSING or "")


def _deviation(a, b) -> float:
    """The largest distance between any entity's positions in two runs."""
    return max(float(np.max(np.hypot(a.traces[n].x - b.traces[n].x, a.traces[n].y - b.traces[n].y))) for n in a.traces)


def _built(scenario: Path, out: Path, values: dict, models=("sfm", "cap")) -> dict[str, Path]:
    return {m: build_osmp(m, scenario, out, values) for m in models}


@pytest.mark.parametrize(("number", "values"), [(n, v) for n, _, v in BUILT_FOR])
def test_the_native_osmp_models_reproduce_the_built_in_ones_on_the_studys_configurations(case_study, tmp_path, number,
                                                                                          values):  # fmt: skip
    values = {**values, "TimeShift": "2.197"}
    fmus = _built(case_study, tmp_path, values)
    ref = run_scenario(case_study, values)
    for plugs in PLUGS.values():  # (several instances in one process: the native FMUs allow it)
        options = [f"{entity}={fmus[model]}" for entity, model in plugs.items()]
        got = run_scenario(case_study, values, controllers=parse_controller_options(options))
        assert _deviation(ref, got) <= 1e-6, (number, plugs)
        for entity in plugs:
            assert set(got.traces[entity].status[1:]) == {"osmp"}
        assert bool(ref.collisions) == bool(got.collisions)


def test_the_native_osmp_models_reproduce_multi_scooter(multi, tmp_path):
    values = {"RiderType": "normal", "CapEnabled": "true", "TimeShift": "1.41"}
    fmus = _built(multi, tmp_path, values)
    plugs = [f"Ego={fmus['cap']}", f"scooter_2={fmus['sfm']}"]
    got = run_scenario(multi, values, controllers=parse_controller_options(plugs))
    assert _deviation(run_scenario(multi, values), got) <= 1e-6


def test_the_native_participants_declare_what_osmp_requires(case_study, tmp_path, capsys):
    from fmpy.validation import validate_fmu

    assert main(["fmu", "build", "sfm", "cap", "--osmp", "--scenario", str(case_study), "-o", str(tmp_path)]) == 0
    assert "note:" not in capsys.readouterr().err  # (built natively: nothing to fall back from)
    for model, other in (("sfm", "ego_id"), ("cap", "threat_id")):
        fmu = tmp_path / f"vei_{model}_osmp.fmu"
        ports = read_osmp_ports(fmu, "t")  # (the host's own checks of the annotations and MIME types)
        assert ports.sensor_view.mime.endswith("type=SensorView; version=3.8.0")
        assert ports.traffic_update.mime.endswith("type=TrafficUpdate; version=3.8.0")
        assert ports.traffic_command is None and ports.osmp_version == "1.5.0"
        assert not ports.once_per_process and ports.parameters[other][1] == "Integer"
        assert validate_fmu(str(fmu)) == []
        names = zipfile.ZipFile(fmu).namelist()
        assert names == ["binaries/linux64/" + f"vei_{model}_osmp.so", "modelDescription.xml"]
        md = zipfile.ZipFile(fmu).read("modelDescription.xml").decode()
        assert md.index("<VendorAnnotations>") < md.index("<ModelVariables>")
    first = (tmp_path / "vei_sfm_osmp.fmu").read_bytes()
    assert main(["fmu", "build", "sfm", "--osmp", "--scenario", str(case_study), "-o", str(tmp_path)]) == 0
    assert (tmp_path / "vei_sfm_osmp.fmu").read_bytes() == first  # (the same build, the same bytes)


def test_without_the_toolchain_it_says_what_to_install_and_builds_the_pythonfmu_one(case_study, tmp_path, capsys,
                                                                                     monkeypatch):  # fmt: skip
    pytest.importorskip("pythonfmu", reason="the fallback is a pythonfmu FMU: pip install pythonfmu")
    why = f"a native OSMP FMU needs protoc-c (Debian/Ubuntu: {osmp_native.INSTALL})"
    monkeypatch.setattr(osmp_native, "missing", lambda: why)
    argv = ["fmu", "build", "sfm", "--osmp", "--scenario", str(case_study), "-o", str(tmp_path)]
    assert main([*argv, "--backend", "native"]) == 2
    err = capsys.readouterr().err
    assert err.strip().splitlines() == [f"vei: error: --osmp: {why}"] and not list(tmp_path.iterdir())
    assert main(argv) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"vei: note: {why}; building pythonfmu participants instead")
    assert read_osmp_ports(tmp_path / "vei_sfm_osmp.fmu", "t").once_per_process  # (pythonfmu's)


def _record(case_study: Path, fmu: Path, values: dict, steps: int, entity: str = "scooter_1"):
    """The first ``steps`` SensorViews vei gives the participant on ``entity`` in a hosted run and the
    TrafficUpdates it returns: (views, updates), serialised."""
    from vei_scenario.sut import osmp as host

    views, updates = [], []
    step = host.OsmpParticipant.step

    def recording(self, view, command, host_id, t, dt, names=None):
        moved = step(self, view, command, host_id, t, dt, names)
        if len(views) < steps:
            lo, hi, size = self.fmu.getInteger([self.ports.traffic_update.lo, self.ports.traffic_update.hi,
                                                self.ports.traffic_update.size])  # fmt: skip
            views.append(view)
            updates.append(ctypes.string_at(merge_address(lo, hi), size))
        return moved

    host.OsmpParticipant.step = recording
    try:
        run_scenario(case_study, values, controllers=parse_controller_options([f"{entity}={fmu}"]))
    finally:
        host.OsmpParticipant.step = step
    return views, updates


#: In a process where vei_scenario cannot be imported: fmpy steps the FMU through the
#: recorded SensorViews (t = 0.01 k) and prints each TrafficUpdate's host position, or the failure.
_ALONE = r"""
import ctypes, importlib.abc, json, sys
class NoVei(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] == "vei_scenario":
            raise ModuleNotFoundError(f"No module named {name!r} (blocked)")
sys.meta_path.insert(0, NoVei())
for gone in [m for m in sys.modules if m.split(".")[0] == "vei_scenario"]:
    del sys.modules[gone]
try:
    import vei_scenario  # noqa
    sys.exit("vei_scenario is importable")
except ModuleNotFoundError:
    pass
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from osi3.osi_trafficupdate_pb2 import TrafficUpdate
fmu, views = sys.argv[1], json.load(open(sys.argv[2]))
md = read_model_description(fmu)
vr = {v.name: v.valueReference for v in md.modelVariables}
slave = FMU2Slave(guid=md.guid, unzipDirectory=extract(fmu), modelIdentifier=md.coSimulation.modelIdentifier,
                  instanceName="alone")
slave.instantiate(); slave.setupExperiment(startTime=0.0); slave.enterInitializationMode()
slave.exitInitializationMode()
out, kept = [], []
try:
    for k, hexed in enumerate(views):
        buf = ctypes.create_string_buffer(bytes.fromhex(hexed), len(hexed) // 2)
        kept = [*kept[-1:], buf]
        a = ctypes.addressof(buf)
        lo, hi = [(x - (1 << 32) if x >= 1 << 31 else x) for x in (a & 0xFFFFFFFF, a >> 32)]
        slave.setInteger([vr["OSMPSensorViewIn.base.lo"], vr["OSMPSensorViewIn.base.hi"], vr["OSMPSensorViewIn.size"]],
                         [lo, hi, len(buf)])
        slave.doStep(currentCommunicationPoint=0.01 * k, communicationStepSize=0.01)
        lo, hi, size = slave.getInteger([vr["OSMPTrafficUpdateOut.base.lo"], vr["OSMPTrafficUpdateOut.base.hi"],
                                         vr["OSMPTrafficUpdateOut.size"]])
        u = TrafficUpdate.FromString(ctypes.string_at(((hi & 0xFFFFFFFF) << 32) | (lo & 0xFFFFFFFF), size))
        out.append([u.update[0].base.position.x, u.update[0].base.position.y])
    print(json.dumps({"positions": out}))
except Exception as exc:
    print(json.dumps({"failed": f"{type(exc).__name__}: {exc}"}))
"""


def test_the_native_rider_runs_where_vei_cannot_be_imported(case_study, tmp_path):
    from osi3.osi_trafficupdate_pb2 import TrafficUpdate

    values = {"RiderType": "normal", "CapEnabled": "true", "TimeShift": "2.197"}
    fmu = build_osmp("sfm", case_study, tmp_path, values)
    views, updates = _record(case_study, fmu, values, steps=600)  # (the rider rides from 3.84 s)
    (tmp_path / "views.json").write_text(json.dumps([v.hex() for v in views]))
    done = subprocess.run([sys.executable, "-c", _ALONE, str(fmu), str(tmp_path / "views.json")], capture_output=True,
                          text=True, timeout=120)  # fmt: skip
    assert done.returncode == 0, done.stderr[-1500:]
    got = json.loads(done.stdout)
    want = [[u.update[0].base.position.x, u.update[0].base.position.y] for u in map(TrafficUpdate.FromString, updates)]
    assert got == {"positions": want}  # (the same positions, bit for bit, as hosted in vei run)
    assert len(set(map(tuple, want))) > 200  # (it rides)


def test_the_pythonfmu_rider_does_not_run_where_vei_cannot_be_imported(case_study, tmp_path):
    """The check above can fail: the pythonfmu participant, given the same SensorView, cannot step."""
    pytest.importorskip("pythonfmu", reason="the fallback is a pythonfmu FMU: pip install pythonfmu")
    values = {"RiderType": "normal", "CapEnabled": "true", "TimeShift": "2.197"}
    native = build_osmp("sfm", case_study, tmp_path / "native", values)
    views, _ = _record(case_study, native, values, steps=1)
    (tmp_path / "views.json").write_text(json.dumps([v.hex() for v in views]))
    fmu = build_osmp("sfm", case_study, tmp_path, values, backend="python")
    done = subprocess.run([sys.executable, "-c", _ALONE, str(fmu), str(tmp_path / "views.json")], capture_output=True,
                          text=True, timeout=120)  # fmt: skip
    assert done.returncode != 0 or "failed" in done.stdout or "positions" not in done.stdout


def _slave(fmu: Path):
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    md = read_model_description(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    slave = FMU2Slave(guid=md.guid, unzipDirectory=extract(str(fmu)), modelIdentifier=md.coSimulation.modelIdentifier,
                      instanceName="buffers")  # fmt: skip
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.exitInitializationMode()
    return slave, vr


def test_an_update_stays_valid_until_the_second_step_after_and_owes_nothing_to_the_view(case_study, tmp_path):
    """OSMP: the output buffer is valid until the second doStep after the one that wrote it; the input
    is the host's again once doStep returns (here overwritten with zeros right after)."""
    values = {"RiderType": "aggressive", "CapEnabled": "false", "TimeShift": "2.197"}
    fmu = build_osmp("sfm", case_study, tmp_path, values)
    views, updates = _record(case_study, fmu, values, steps=6)
    slave, vr = _slave(fmu)
    sv = [vr[f"OSMPSensorViewIn.{r}"] for r in ("base.lo", "base.hi", "size")]
    tu = [vr[f"OSMPTrafficUpdateOut.{r}"] for r in ("base.lo", "base.hi", "size")]
    written: list[tuple[int, int, bytes]] = []
    for k, view in enumerate(views):
        buf = ctypes.create_string_buffer(view, len(view))
        slave.setInteger(sv, [*split_address(ctypes.addressof(buf)), len(view)])
        slave.doStep(currentCommunicationPoint=0.01 * k, communicationStepSize=0.01)
        ctypes.memset(buf, 0, len(view))
        lo, hi, size = slave.getInteger(tu)
        at = merge_address(lo, hi)
        assert ctypes.string_at(at, size) == updates[k]
        for before_at, before_size, before in written[-1:]:  # (written one step before: still as written)
            assert ctypes.string_at(before_at, before_size) == before
        written.append((at, size, ctypes.string_at(at, size)))
    assert len({at for at, _, _ in written[-3:]}) == 3  # (three buffers in turn)
    slave.terminate()
    slave.freeInstance()


def test_bytes_that_are_no_sensor_view_fail_the_step_in_one_line(case_study, tmp_path, capfd):
    from fmpy.fmi1 import FMICallException

    fmu = build_osmp("sfm", case_study, tmp_path, {})
    slave, vr = _slave(fmu)
    junk = ctypes.create_string_buffer(b"\xff\xff\xff\xff\x0f", 5)
    sv = [vr[f"OSMPSensorViewIn.{r}"] for r in ("base.lo", "base.hi", "size")]
    slave.setInteger(sv, [*split_address(ctypes.addressof(junk)), 5])
    capfd.readouterr()
    with pytest.raises(FMICallException):
        slave.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.01)
    lines = [line for line in capfd.readouterr().out.splitlines() if "SensorView" in line]
    assert len(lines) == 1
    assert lines[0].endswith("doStep at t = 0 s: OSMPSensorViewIn: 5 bytes that are no osi3.SensorView")
    slave.freeInstance()


#: The OSMP host the test partners were written with (tests/data/osmp/host_alone.py: fmpy and osi3,
#: written from the OSMP specification alone), in a process where vei_scenario cannot be imported:
#: it checks the annotations, hosts the rider (id 1) beside a car (id 0) and checks each update's
#: buffer is intact until the second doStep after it; prints the rider's positions.
_PARTNER_HOST = r"""
import importlib.abc, json, sys
class NoVei(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] == "vei_scenario":
            raise ModuleNotFoundError(f"No module named {name!r} (blocked)")
sys.meta_path.insert(0, NoVei())
sys.path.insert(0, sys.argv[2])
import host_alone as h
rider = h.Obj(id=1, x=float(sys.argv[3]), y=float(sys.argv[4]), yaw=float(sys.argv[5]), speed=0.0)
car = h.Obj(id=0, x=rider.x - 40.0, y=rider.y - 30.0, yaw=0.0, speed=5.0)
samples = h.simulate(sys.argv[1], rider, [car], t_end=float(sys.argv[6]), dt=0.01)
print(json.dumps([[s.x, s.y] for s in samples[1:]]))
"""


def test_the_partners_own_host_runs_the_native_rider_as_vei_does(case_study, tmp_path):
    """A replaying rider does not depend on the car: hosted by the partners' host, away from vei, its
    TrafficUpdates hold the positions they hold in vei run (within rounding: that host's step times
    are k·dt, vei's its own sums), and that host's own lifetime check of the output buffers passes."""
    from osi3.osi_trafficupdate_pb2 import TrafficUpdate

    values = {"RiderType": "replay", "CapEnabled": "false", "TimeShift": "2.197"}
    fmu = build_osmp("sfm", case_study, tmp_path, values)
    _, updates = _record(case_study, fmu, values, steps=500)
    want = [[u.update[0].base.position.x, u.update[0].base.position.y] for u in map(TrafficUpdate.FromString, updates)]
    first = TrafficUpdate.FromString(updates[0]).update[0].base
    argv = [sys.executable, "-c", _PARTNER_HOST, str(fmu), str(Path(__file__).parent / "data" / "osmp"),
            repr(first.position.x), repr(first.position.y), repr(first.orientation.yaw), "5.0"]  # fmt: skip
    done = subprocess.run(argv, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-1500:]
    got = np.asarray(json.loads(done.stdout))
    assert got.shape == (500, 2) and np.max(np.hypot(*(got - np.asarray(want)).T)) < 1e-9
    assert len({tuple(p) for p in want}) > 100  # (it moves: the replayed track)


def test_a_runtime_that_does_not_link_into_a_shared_object_is_said_in_one_line(tmp_path, monkeypatch):
    """The probe links the runtime as the build does: an archive of code that is not position-
    independent (built here with -fno-pic) is refused before anything is built."""
    from vei_scenario.core.sources import compiler

    (tmp_path / "fake.c").write_text('static char v[] = "1.4.1";\nconst char *protobuf_c_version(void) { return v; }\n')
    subprocess.run([compiler(), "-c", "-O2", "-fno-pic", "-fno-pie", "fake.c"], cwd=tmp_path, check=True)
    subprocess.run(["ar", "rcs", "libprotobuf-c.a", "fake.o"], cwd=tmp_path, check=True)
    monkeypatch.setattr(osmp_native, "_runtime_archive", lambda cc: tmp_path / "libprotobuf-c.a")
    why = osmp_native.missing()
    assert why is not None and "\n" not in why
    assert why.startswith(f"{tmp_path / 'libprotobuf-c.a'} does not link into a shared object (")
    monkeypatch.undo()
    assert osmp_native.missing() is None


@pytest.mark.parametrize(("model", "entity"), [("sfm", "scooter_1"), ("cap", "Ego")])
def test_a_c_host_with_no_python_in_it_steps_the_native_participants(case_study, tmp_path, model, entity):
    """tests/data/osmp_host/c_host.c loads the participant's binary with dlopen and steps it through
    recorded SensorViews: the TrafficUpdates it gets back are vei run's (within rounding of the step
    times: k·0.01 there)."""
    import struct

    from osi3.osi_trafficupdate_pb2 import TrafficUpdate

    from vei_scenario.core.sources import compiler
    from vei_scenario.fmu.native import fmi_header_dir

    values = {"RiderType": "aggressive", "CapEnabled": "true", "TimeShift": "2.197"}
    fmu = build_osmp(model, case_study, tmp_path, values)
    views, updates = _record(case_study, fmu, values, steps=600, entity=entity)
    (tmp_path / "views.bin").write_bytes(b"".join(struct.pack("<I", len(v)) + v for v in views))
    host = tmp_path / "c_host"
    source = Path(__file__).parent / "data" / "osmp_host" / "c_host.c"
    subprocess.run([compiler(), "-O2", "-std=c99", f"-I{fmi_header_dir()}", "-o", str(host), str(source), "-ldl"],
                   check=True)  # fmt: skip
    zipfile.ZipFile(fmu).extractall(tmp_path / "fmu")
    binary = tmp_path / "fmu" / "binaries" / "linux64" / f"vei_{model}_osmp.so"
    guid = read_osmp_ports(fmu, "t").guid
    done = subprocess.run([str(host), str(binary), guid, str(tmp_path / "views.bin"), str(tmp_path / "out.bin")],
                          capture_output=True, text=True, timeout=60, env={})  # fmt: skip
    assert done.returncode == 0, done.stderr[-1500:]
    data, got = (tmp_path / "out.bin").read_bytes(), []
    while data:
        (n,) = struct.unpack("<I", data[:4])
        got.append(TrafficUpdate.FromString(data[4 : 4 + n]).update[0].base)
        data = data[4 + n :]
    want = [TrafficUpdate.FromString(u).update[0].base for u in updates]
    assert len(got) == len(want) == 600
    assert max(math.hypot(a.position.x - b.position.x, a.position.y - b.position.y) for a, b in zip(got, want)) < 1e-9
    assert len({(b.position.x, b.position.y) for b in want}) > 100  # (it rides)


@pytest.fixture(scope="module")
def defaults_built(case_study, tmp_path_factory) -> dict[str, Path]:
    """The participants built ONCE, with the scenario's default parameter values."""
    return _built(case_study, tmp_path_factory.mktemp("defaults"), {})


@pytest.mark.parametrize("shift", ["2.197", "1.5", "3.0"])
@pytest.mark.parametrize(("number", "values"), [(n, v) for n, _, v in CONFIGURATIONS])
def test_participants_built_with_the_defaults_take_the_runs_parameters(case_study, defaults_built, number, values,
                                                                        shift):  # fmt: skip
    values = {**values, "TimeShift": shift}
    ref = run_scenario(case_study, values)
    options = [f"{entity}={defaults_built[model]}" for entity, model in PLUGS["both"].items()]
    got = run_scenario(case_study, values, controllers=parse_controller_options(options))
    assert _deviation(ref, got) <= 1e-6, (number, shift)
    assert bool(ref.collisions) == bool(got.collisions)


def test_the_participants_declare_the_models_parameters_with_the_scenarios_values(case_study, defaults_built):
    from lxml import etree

    for model, expected in (("cap", {"enabled": ("Boolean", "false"), "cruise_speed_mps": ("Real", "5.61"),
                                     "a_max_mps2": ("Real", "6.0")}),
                            ("sfm", {"rider_type": ("String", "replay"), "time_shift_s": ("Real", "0.0"),
                                     "v0_mps": ("Real", "4.36")})):  # fmt: skip
        with zipfile.ZipFile(defaults_built[model]) as z:
            root = etree.fromstring(z.read("modelDescription.xml"))
        declared = {sv.get("name"): sv for sv in root.iterfind("ModelVariables/ScalarVariable")
                    if sv.get("causality") == "parameter"}  # fmt: skip
        for name, (kind, start) in expected.items():
            assert declared[name].get("variability") == "fixed", name
            assert declared[name][0].tag == kind and declared[name][0].get("start") == start, name


def test_a_run_that_changes_what_the_participant_holds_fixed_is_refused_in_one_line(case_study, defaults_built):
    from vei_scenario.sut import ControllerFault

    options = [f"Ego={defaults_built['cap']}"]
    with pytest.raises(ControllerFault) as err:  # (EgoCruiseSpeed is also the ego's Init speed: baked in)
        run_scenario(case_study, {"EgoCruiseSpeed": "4.0"}, controllers=parse_controller_options(options))
    text = str(err.value)
    assert "\n" not in text and "EgoCruiseSpeed=4.0" in text and "EgoCruiseSpeed=5.61" in text


def test_a_sweep_with_participants_built_once_gives_the_built_in_sweeps_rows(case_study, defaults_built, tmp_path):
    from vei_scenario.sweep import run_sweep

    vary = ["TimeShift=1.0:3.0:1.0", "RiderType=normal,aggressive", "CapEnabled=true"]
    options = [f"{entity}={defaults_built[model]}" for entity, model in PLUGS["both"].items()]
    ref = run_sweep(case_study, tmp_path / "ref", vary, quiet=True)
    got = run_sweep(case_study, tmp_path / "got", vary, quiet=True, controllers=parse_controller_options(options))
    assert len(ref.rows) == len(got.rows) == 6 and len({r["metrics"]["min_gap_m"] for r in got.rows}) > 1
    for a, b in zip(ref.rows, got.rows):
        assert a["parameters"] == b["parameters"] and a["status"] == b["status"] == "ok"
        assert a["metrics"].keys() == b["metrics"].keys()
        for k, v in a["metrics"].items():  # (the catalog's rounding: equal up to its last digit)
            same = abs(v - b["metrics"][k]) <= 1e-3 if isinstance(v, float) else v == b["metrics"][k]
            assert same, (k, a["parameters"], v, b["metrics"][k])


def test_the_declared_parameters_are_read_and_set_before_initialization_ends_only(defaults_built, capfd):
    from fmpy import extract, read_model_description
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi2 import FMU2Slave

    fmu = defaults_built["sfm"]
    md = read_model_description(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    slave = FMU2Slave(guid=md.guid, unzipDirectory=extract(str(fmu)), modelIdentifier=md.coSimulation.modelIdentifier,
                      instanceName="params")  # fmt: skip
    slave.instantiate()
    assert slave.getReal([vr["v0_mps"], vr["time_shift_s"]]) == [4.36, 0.0]
    assert slave.getString([vr["rider_type"]]) == [b"replay"]
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.setReal([vr["time_shift_s"]], [-2.197])
    slave.setString([vr["rider_type"]], ["aggressive"])
    with pytest.raises(FMICallException):  # (the model's own 64-character strings)
        slave.setString([vr["rider_type"]], ["x" * 64])
    lines = [line for line in capfd.readouterr().out.splitlines() if "rider_type" in line]
    assert len(lines) == 1 and lines[0].endswith("fmi2SetString: rider_type: longer than 63 characters")
    slave.freeInstance()
    slave = FMU2Slave(guid=md.guid, unzipDirectory=extract(str(fmu)), modelIdentifier=md.coSimulation.modelIdentifier,
                      instanceName="params")  # fmt: skip
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.setReal([vr["time_shift_s"]], [-2.197])
    slave.exitInitializationMode()
    assert slave.getReal([vr["time_shift_s"]]) == [-2.197]
    with pytest.raises(FMICallException):
        slave.setReal([vr["v0_mps"]], [5.0])
    lines = [line for line in capfd.readouterr().out.splitlines() if "v0_mps" in line]
    assert len(lines) == 1 and lines[0].endswith(
        "fmi2SetReal: v0_mps is a fixed parameter, set before initialization ends"
    )
    slave.freeInstance()


def test_multi_scooters_participants_built_with_the_defaults_take_the_runs_parameters(multi, tmp_path):
    fmus = _built(multi, tmp_path, {})
    values = {"RiderType": "normal", "CapEnabled": "true", "TimeShift": "1.41"}
    got = run_scenario(multi, values, controllers=parse_controller_options([f"Ego={fmus['cap']}",
                                                                            f"scooter_2={fmus['sfm']}"]))  # fmt: skip
    assert _deviation(run_scenario(multi, values), got) <= 1e-6


def test_a_participant_built_from_another_scenario_is_refused_in_one_line(multi, defaults_built):
    from vei_scenario.sut import ControllerFault

    with pytest.raises(ControllerFault) as err:
        run_scenario(multi, {}, controllers=parse_controller_options([f"Ego={defaults_built['cap']}"]))
    assert str(err.value).endswith("vei_cap_osmp.fmu was built from another scenario (what it holds fixed differs "
                                   "from scenario.xosc's): build it from this one")  # fmt: skip
