"""Build the tiny native FMUs of faulty_fmu.c (``-DFAULT_CRASH``, ``-DFAULT_HANG``, ``-DFAULT_ERROR``,
``-DFAULT_NAN``; each also with its parameter ``enabled`` declared: Gated<Name>) with the system C compiler against fmpy's FMI 2.0 headers, as
``vei fmu build`` compiles vei's own."""

from __future__ import annotations

import subprocess
import zipfile
from pathlib import Path

HERE = Path(__file__).parent
MODEL = """<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="{name}" guid="{{{name}}}" numberOfEventIndicators="0">
  <CoSimulation modelIdentifier="{name}" canHandleVariableCommunicationStepSize="true"/>
  <ModelVariables>
    <ScalarVariable name="ego_speed" valueReference="0" causality="input" variability="continuous">
      <Real start="0"/></ScalarVariable>
    <ScalarVariable name="a_cmd" valueReference="1" causality="output" variability="continuous"><Real/></ScalarVariable>{gate}
  </ModelVariables>
  <ModelStructure><Outputs><Unknown index="2"/></Outputs></ModelStructure>
</fmiModelDescription>
"""


GATE = """
    <ScalarVariable name="enabled" valueReference="2" causality="parameter" variability="fixed">
      <Boolean start="true"/></ScalarVariable>"""
NAMES = {"CRASH": "SegfaultFmu", "HANG": "HangingFmu", "ERROR": "ErrorNativeFmu", "NAN": "NanFmu"}


def build(fault: str, out_dir: Path, gated: bool = False) -> Path:
    """``fault`` CRASH, HANG, ERROR or NAN (``gated``: only where the parameter enabled is true):
    ``out_dir/<Name>.fmu``."""
    from fmpy import __file__ as fmpy_init

    from vei_scenario.core.sources import compiler

    name = ("Gated" if gated else "") + NAMES[fault]
    binary = out_dir / f"{name}.so"
    headers = Path(fmpy_init).parent / "c-code"
    subprocess.run([compiler(), "-shared", "-fPIC", "-O1", "-std=c99", f"-DFAULT_{fault}", "-D_DEFAULT_SOURCE",
                    f"-I{headers}", "-o", str(binary), str(HERE / "faulty_fmu.c")], check=True)  # fmt: skip
    fmu = out_dir / f"{name}.fmu"
    with zipfile.ZipFile(fmu, "w") as z:
        z.writestr("modelDescription.xml", MODEL.format(name=name, gate=GATE if gated else ""))
        z.write(binary, f"binaries/linux64/{name}.so")
    return fmu
