"""``vei fmu build --backend python``: the models as pythonfmu FMUs (FMI 2.0 co-simulation).

pythonfmu packs the slave script and its runtime library; we then replace its modelDescription.xml
with the one generated from the same variable table as the native FMUs (units, descriptions,
InitialUnknowns, a reproducible GUID; pythonfmu numbers value references across all types, so the
table is written with those numbers) and re-pack the archive reproducibly.
"""

from __future__ import annotations

import io
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

from vei_scenario.errors import VeiInputError
from vei_scenario.fmu import model_description
from vei_scenario.fmu.packaging import write_fmu
from vei_scenario.fmu.variables import ModelSpec

_SCRIPT = '''"""pythonfmu slave of the {title} (vei-scenario).

Edit the model in vei_scenario.fmu.python_models; this FMU needs Python with vei-scenario installed.
"""
from vei_scenario.fmu.python_slave import VeiSlave


class {identifier}(VeiSlave):
    model_name = "{name}"
'''


def build_python(spec: ModelSpec, out_dir: Path) -> Path:
    try:
        import pythonfmu  # noqa: F401
    except ImportError:
        raise VeiInputError(None, "--backend python", "needs pythonfmu: pip install pythonfmu") from None
    with tempfile.TemporaryDirectory(prefix="vei-pyfmu-") as tmp:
        script = Path(tmp) / f"{spec.identifier}.py"
        script.write_text(_SCRIPT.format(title=spec.title, identifier=spec.identifier, name=spec.name))
        # in a child process: pythonfmu's builder imports the script and its own package, and in a process
        # that has hosted a pythonfmu FMU those can be the FMU's copies (without the binaries to pack)
        out = Path(tmp) / "out"
        command = [sys.executable, "-m", "pythonfmu", "build", "-f", str(script), "-d", str(out)]
        done = subprocess.run(command, capture_output=True, text=True, cwd=tmp)
        if done.returncode != 0:
            why = " ".join((done.stderr or done.stdout).strip().splitlines()[-1:]) or f"exit {done.returncode}"
            raise VeiInputError(None, "--backend python", f"pythonfmu could not build {spec.identifier}: {why}")
        built = out / f"{spec.identifier}.fmu"
        with zipfile.ZipFile(io.BytesIO(built.read_bytes())) as zf:
            entries = {n: zf.read(n) for n in zf.namelist() if not n.endswith("/")}
    guid = model_description.guid(spec, "python-fmi2")
    entries["modelDescription.xml"] = model_description.fmi2(
        spec,
        guid,
        None,
        global_value_references=True,
        canNotUseMemoryManagementFunctions="true",
        # pythonfmu's runtime finds the slave class by module name: a second extraction of the same
        # FMU in one process fails to instantiate
        once_per_process="true",
    )
    return write_fmu(Path(out_dir) / f"{spec.identifier}.fmu", entries)
