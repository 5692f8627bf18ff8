"""The native FMUs follow the FMI state machine: calls outside the allowed states return an error
and log why, calls on a freed instance are refused without touching it, a second free is harmless.
Each sequence runs in its own process, so a regression (a crash) fails the test, not the suite."""

from __future__ import annotations

import subprocess
import sys

import pytest

from vei_scenario.fmu import build_fmus

FMI2 = r"""
import sys
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave, fmi2Real, fmi2ValueReference

path = sys.argv[1]
md = read_model_description(path)
fmu = FMU2Slave(guid=md.guid, unzipDirectory=extract(path), modelIdentifier=md.coSimulation.modelIdentifier,
                instanceName="x")
logged = []
fmu.instantiate(loggingOn=True)
lib, c = fmu.dll, fmu.component
step = lambda t: lib.fmi2DoStep(c, fmi2Real(t), fmi2Real(0.01), 1)
out = [step(0.0)]                                                              # before initialization
fmu.reset()
out.append(lib.fmi2SetupExperiment(c, 0, fmi2Real(0.0), fmi2Real(0.0), 0, fmi2Real(0.0)))
out.append(lib.fmi2EnterInitializationMode(c))
out.append(lib.fmi2EnterInitializationMode(c))                                  # twice: not allowed
fmu.reset()
out.append(lib.fmi2SetupExperiment(c, 0, fmi2Real(0.0), fmi2Real(0.0), 0, fmi2Real(0.0)))
out.append(lib.fmi2EnterInitializationMode(c))
out.append(lib.fmi2ExitInitializationMode(c))
out.append(step(0.0))
out.append(lib.fmi2Terminate(c))
vr = (fmi2ValueReference * 1)(next(v.valueReference for v in md.modelVariables if v.causality == "input"))
out.append(lib.fmi2SetReal(c, vr, 1, (fmi2Real * 1)(0.0)))                      # after terminate
out.append(step(0.01))
lib.fmi2FreeInstance(c)
lib.fmi2FreeInstance(c)                                                         # a second free
out.append(step(0.0))                                                           # on the freed instance
print("RESULT", *out)
"""


@pytest.fixture(scope="module")
def sfm_fmu(tmp_path_factory):
    return build_fmus(["sfm"], tmp_path_factory.mktemp("fmu"), "native", 2)["sfm"]


def test_fmi2_calls_outside_their_states_are_refused_and_double_free_is_harmless(sfm_fmu):
    proc = subprocess.run([sys.executable, "-c", FMI2, str(sfm_fmu)], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    result = next(line for line in proc.stdout.splitlines() if line.startswith("RESULT")).split()[1:]
    # DoStep before init: error (3); setup, enter: OK (0); enter again: error; after a reset setup,
    # enter, exit, a step and terminate: OK; SetReal and DoStep after terminate: error; the freed
    # instance: error, and no crash from the second free
    assert result == ["3", "0", "0", "3", "0", "0", "0", "0", "0", "3", "3", "3"]
    assert "not allowed in state terminated" in proc.stdout + proc.stderr
