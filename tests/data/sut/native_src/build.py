"""Build the tiny native FMUs of all_inputs_fmu.c (:func:`build_all_inputs`) and of faulty_fmu.c
(``-DFAULT_CRASH``, ``-DFAULT_HANG``, ``-DFAULT_ERROR``, ``-DFAULT_NAN``; each also with its parameter
``enabled`` declared: Gated<Name>) with the system C compiler against fmpy's FMI 2.0 headers, as
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


def _compile(name: str, source: str, out_dir: Path, defines: list[str], model: str) -> Path:
    from fmpy import __file__ as fmpy_init

    from vei_scenario.core.sources import compiler

    binary = out_dir / f"{name}.so"
    headers = Path(fmpy_init).parent / "c-code"
    subprocess.run([compiler(), "-shared", "-fPIC", "-O1", "-std=c99", *defines, "-D_DEFAULT_SOURCE",
                    f"-I{headers}", f"-I{HERE}", "-o", str(binary), str(HERE / source), "-lm"], check=True)  # fmt: skip
    fmu = out_dir / f"{name}.fmu"
    with zipfile.ZipFile(fmu, "w") as z:
        z.writestr("modelDescription.xml", model)
        z.write(binary, f"binaries/linux64/{name}.so")
    return fmu


def build_all_inputs(out_dir: Path) -> Path:
    """``out_dir/AllInputsFmu.fmu``: every input vei provides (vr 0-14), a_cmd (vr 15)."""
    from vei_scenario.sut.fmu import INPUTS

    ports = [
        f'<ScalarVariable name="{n}" valueReference="{k}" causality="input" variability="continuous">'
        '<Real start="0"/></ScalarVariable>'
        for k, n in enumerate(INPUTS)
    ]
    ports.append('<ScalarVariable name="a_cmd" valueReference="15" causality="output" variability="continuous">'
                 "<Real/></ScalarVariable>")  # fmt: skip
    model = (
        '<?xml version="1.0" encoding="UTF-8"?>\n<fmiModelDescription fmiVersion="2.0" modelName="AllInputsFmu" '
        'guid="{AllInputsFmu}" numberOfEventIndicators="0">\n  <CoSimulation modelIdentifier="AllInputsFmu"/>\n'
        "  <ModelVariables>\n    " + "\n    ".join(ports) + "\n  </ModelVariables>\n"
        '  <ModelStructure><Outputs><Unknown index="16"/></Outputs></ModelStructure>\n</fmiModelDescription>\n'
    )
    return _compile("AllInputsFmu", "all_inputs_fmu.c", out_dir, [], model)


def build(fault: str, out_dir: Path, gated: bool = False) -> Path:
    """``fault`` CRASH, HANG, ERROR or NAN (``gated``: only where the parameter enabled is true):
    ``out_dir/<Name>.fmu``."""
    name = ("Gated" if gated else "") + NAMES[fault]
    model = MODEL.format(name=name, gate=GATE if gated else "")
    return _compile(name, "faulty_fmu.c", out_dir, [f"-DFAULT_{fault}"], model)
