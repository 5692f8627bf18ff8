"""vei's e-scooter rider and its planner (driving the ego) as pythonfmu OSMP traffic participants (``vei
fmu build sfm cap --osmp --backend python``, the fallback of the native ones: test_osmp_native.py),
hosted back in ``vei run`` as such (``--controller scooter_1=vei_sfm_osmp.fmu``, ``--controller
Ego=vei_cap_osmp.fmu``, or both): the built-in models' run again.

The FMUs can be instantiated once per process: each hosted run is a process."""

from __future__ import annotations

import json
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from osmp_plugs import BUILT_FOR, PLUGS

from vei_scenario.cli import main
from vei_scenario.study import CONFIGURATIONS
from vei_scenario.sut import ControllerFault, parse_controller_options
from vei_scenario.sut.osmp import read_osmp_ports

#: Builds the rider for the values, runs the scenario with the built-in rider and with the FMU on the
#: entity, prints the largest position difference over every entity and whether each collides.
_COMPARE = """
import json, os, sys
from pathlib import Path
import numpy as np
from vei_scenario.fmu.osmp_rider import build_osmp
from vei_scenario.interpreter import run_scenario
from vei_scenario.sut import parse_controller_options
scenario, plugs, out, values = sys.argv[1], json.loads(sys.argv[2]), Path(sys.argv[3]), json.loads(sys.argv[4])
options = [f"{entity}={build_osmp(model, scenario, out, values, backend='python')}" for entity, model in plugs.items()]
a = run_scenario(scenario, values)
b = run_scenario(scenario, values, controllers=parse_controller_options(options))
entity = list(plugs)[-1]
d = max(float(np.max(np.hypot(a.traces[n].x - b.traces[n].x, a.traces[n].y - b.traces[n].y))) for n in a.traces)
print(json.dumps({"deviation_m": d, "collides": [bool(a.collisions), bool(b.collisions)],
                  "status": sorted(set(b.traces[entity].status[1:]))}), flush=True)
os._exit(0)  # (without interpreter teardown, where pythonfmu's embedded runtime can crash)
"""


def _compare(scenario: Path, plugs: dict[str, str], out: Path, values: dict) -> dict:
    """``plugs``: entity -> model (sfm, cap) whose OSMP FMU drives it."""
    argv = [sys.executable, "-c", _COMPARE, str(scenario), json.dumps(plugs), str(out), json.dumps(values)]
    done = subprocess.run(argv, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("plugs", sorted(PLUGS))
@pytest.mark.parametrize(("number", "values"), [(n, v) for n, _, v in BUILT_FOR])
def test_the_osmp_models_reproduce_the_built_in_ones_on_the_studys_configurations(case_study, tmp_path, number, values,
                                                                                   plugs):  # fmt: skip
    got = _compare(case_study, PLUGS[plugs], tmp_path, {**values, "TimeShift": "2.197"})
    assert got["deviation_m"] <= 1e-6 and got["status"] == ["osmp"]
    assert got["collides"][0] == got["collides"][1]


def test_the_osmp_models_reproduce_multi_scooter(multi, tmp_path):
    got = _compare(multi, {"Ego": "cap", "scooter_2": "sfm"}, tmp_path,
                   {"RiderType": "normal", "CapEnabled": "true", "TimeShift": "1.41"})  # fmt: skip
    assert got["deviation_m"] <= 1e-6


def test_the_osmp_rider_declares_what_osmp_requires(case_study, tmp_path, capsys):
    py = ["--backend", "python"]
    code = main(["fmu", "build", "sfm", "--osmp", *py, "--scenario", str(case_study), "-o", str(tmp_path)])
    assert code == 0
    fmu = tmp_path / "vei_sfm_osmp.fmu"
    ports = read_osmp_ports(fmu, "t")  # (the host's own checks of the annotations)
    assert ports.sensor_view.mime.endswith("type=SensorView; version=3.8.0") and ports.traffic_command is None
    assert ports.once_per_process
    from fmpy.validation import validate_fmu

    assert validate_fmu(str(fmu)) == []
    first = fmu.read_bytes()
    assert main(["fmu", "build", "sfm", "--osmp", *py, "--scenario", str(case_study), "-o", str(tmp_path)]) == 0
    assert fmu.read_bytes() == first  # (the same build, the same bytes)
    md = zipfile.ZipFile(fmu).read("modelDescription.xml").decode()
    assert md.index("<VendorAnnotations>") < md.index("<ModelVariables>")
    code = main(["fmu", "build", "cap", "--osmp", *py, "--scenario", str(case_study), "-o", str(tmp_path)])
    assert code == 0 and read_osmp_ports(tmp_path / "vei_cap_osmp.fmu", "t").parameters["threat_id"][1] == "Integer"
    assert validate_fmu(str(tmp_path / "vei_cap_osmp.fmu")) == []
    code = main(["fmu", "build", "ego", "--osmp", "--scenario", str(case_study), "-o", str(tmp_path)])
    assert code == 2 and "vei fmu build sfm cap --osmp --scenario XOSC" in capsys.readouterr().err


def test_a_second_instance_in_one_process_is_refused_in_one_line(case_study, tmp_path):
    """What the FMU declares (canBeInstantiatedOnlyOncePerProcess) the host keeps to: the second run in
    a process is refused with one line, not left to the FMU's runtime."""
    script = f"""
import sys
from vei_scenario.fmu.osmp_rider import build_osmp_rider
from vei_scenario.interpreter import run_scenario
from vei_scenario.sut import ControllerFault, parse_controller_options
fmu = build_osmp_rider({str(case_study)!r}, __import__("pathlib").Path({str(tmp_path)!r}), backend="python")
spec = parse_controller_options([f"scooter_1={{fmu}}"])
run_scenario({str(case_study)!r}, controllers=spec)
try:
    run_scenario({str(case_study)!r}, controllers=spec)
except ControllerFault as exc:
    print(exc, flush=True)
__import__("os")._exit(0)
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert done.stdout.strip().endswith(
        "vei_sfm_osmp.fmu can be instantiated only once per process (canBeInstantiatedOnlyOncePerProcess): "
        "host it in one run per process"
    ), done.stderr[-1500:]
    assert ControllerFault and parse_controller_options  # (the names the script uses)


#: Runs the scenario with the built-in models and with the given participants (entity -> FMU), prints
#: the largest position difference over every entity and whether each collides.
_HOSTED = """
import json, os, sys
import numpy as np
from vei_scenario.interpreter import run_scenario
from vei_scenario.sut import parse_controller_options
scenario, plugs, values = sys.argv[1], json.loads(sys.argv[2]), json.loads(sys.argv[3])
a = run_scenario(scenario, values)
b = run_scenario(scenario, values, controllers=parse_controller_options([f"{e}={f}" for e, f in plugs.items()]))
d = max(float(np.max(np.hypot(a.traces[n].x - b.traces[n].x, a.traces[n].y - b.traces[n].y))) for n in a.traces)
print(json.dumps({"deviation_m": d, "collides": [bool(a.collisions), bool(b.collisions)]}), flush=True)
os._exit(0)
"""


@pytest.fixture(scope="module")
def defaults_built(case_study, tmp_path_factory) -> dict[str, Path]:
    """The pythonfmu participants built ONCE, with the scenario's default parameter values."""
    from vei_scenario.fmu.osmp_rider import build_osmp

    out = tmp_path_factory.mktemp("defaults")
    return {m: build_osmp(m, case_study, out, {}, backend="python") for m in ("sfm", "cap")}


@pytest.mark.parametrize(("shift", "number", "values"), [("2.197", n, v) for n, _, v in CONFIGURATIONS]
                         + [(s, n, v) for s in ("1.5", "3.0") for n, _, v in CONFIGURATIONS[-2:]])  # fmt: skip
def test_pythonfmu_participants_built_with_the_defaults_take_the_runs_parameters(case_study, defaults_built, shift,
                                                                                  number, values):  # fmt: skip
    plugs = {"Ego": str(defaults_built["cap"]), "scooter_1": str(defaults_built["sfm"])}
    argv = [
        sys.executable,
        "-c",
        _HOSTED,
        str(case_study),
        json.dumps(plugs),
        json.dumps({**values, "TimeShift": shift}),
    ]
    done = subprocess.run(argv, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    got = json.loads(done.stdout.strip().splitlines()[-1])
    assert got["deviation_m"] <= 1e-6 and got["collides"][0] == got["collides"][1], (number, shift)


def test_the_pythonfmu_participants_declare_what_the_native_ones_do(case_study, defaults_built):
    from lxml import etree

    from vei_scenario.fmu.osmp_parameters import DECLARED

    for model, path in defaults_built.items():
        with zipfile.ZipFile(path) as z:
            root = etree.fromstring(z.read("modelDescription.xml"))
        variables = root.iterfind("ModelVariables/ScalarVariable")
        declared = {sv.get("name"): (sv.get("variability"), sv[0].tag, sv[0].get("start"))
                    for sv in variables if sv.get("causality") == "parameter"}  # fmt: skip
        assert set(declared) == {*DECLARED[model], "ego_id" if model == "sfm" else "threat_id"}
        assert declared.get("enabled", ("fixed", "Boolean", "false")) == ("fixed", "Boolean", "false")
        assert declared.get("time_shift_s", ("fixed", "Real", "0.0")) == ("fixed", "Real", "0.0")
        assert declared.get("rider_type", ("fixed", "String", "replay")) == ("fixed", "String", "replay")


def test_a_sweep_hosts_each_variant_of_a_pythonfmu_participant_in_a_process_of_its_own(case_study, defaults_built):
    """A participant instantiable once per process still serves a sweep: every variant runs (none is
    refused as a second instance) and each row is the built-in models' row for the same values."""
    from vei_scenario.sut import parse_controller_options
    from vei_scenario.sweep.evaluate import evaluate_local

    controllers = tuple(
        parse_controller_options([f"Ego={defaults_built['cap']}", f"scooter_1={defaults_built['sfm']}"])
    )
    values = (("1.5", "normal"), ("2.197", "aggressive"), ("3.0", "aggressive"))
    variants = [{"TimeShift": s, "RiderType": r, "CapEnabled": "true"} for s, r in values]
    hosted = evaluate_local(str(case_study), variants, 0.01, workers=2, controllers=controllers)
    built_in = evaluate_local(str(case_study), variants, 0.01, workers=1)
    assert [r["status"] for r in hosted] == ["ok"] * 3, [r["error"] for r in hosted]
    for h, b in zip(hosted, built_in):
        assert h["metrics"]["min_gap_m"] == pytest.approx(b["metrics"]["min_gap_m"], abs=1e-6)


def test_a_variant_whose_process_dies_is_an_error_row_and_the_others_keep_their_order(case_study, tmp_path):
    """One process a variant: a system under test that kills its process (here it aborts in its first
    step) makes those variants' rows errors that say so; without it, the rows are the in-process ones,
    in variant order."""
    from vei_scenario.sut import parse_controller_options
    from vei_scenario.sweep.evaluate import _evaluate_one_per_process, evaluate_local

    crashing = tmp_path / "crashing.py"
    crashing.write_text(
        "import os\n\n\nclass Crash:\n    def __init__(self, **properties):\n        pass\n\n"
        "    def step(self, *args, **kwargs):\n        os.abort()\n"
    )
    variants = [{"TimeShift": s, "CapEnabled": "true"} for s in ("1.5", "2.197", "3.0")]
    aborting = tuple(parse_controller_options([f"Ego={crashing}:Crash"]))
    dead = _evaluate_one_per_process(str(case_study), variants[:2], 0.01, 2, None, controllers=aborting)
    assert [r["status"] for r in dead] == ["error", "error"]
    assert all("ended without its row" in r["error"] for r in dead), dead
    rows = _evaluate_one_per_process(str(case_study), variants, 0.01, 2, None)
    assert rows == evaluate_local(str(case_study), variants, 0.01, workers=1)
