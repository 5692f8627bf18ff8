"""Find the ASAM XSDs on this machine; nothing is downloaded.

The schemas ship inside the ASAM Quality Checker packages (``asam-qc-openscenarioxml``,
``asam-qc-opendrive``). Those pin old numpy/lxml releases, so they usually live in a virtual environment
of their own; vei looks, in this order, in:

1. ``$VEI_ASAM_SCHEMAS``: directories (``os.pathsep``-separated), each a ``site-packages`` holding the
   packages or a ``schema`` directory of one of them;
2. the packages in the current environment (located, not imported);
3. ``$VEI_QC_VENV``: the root of the Quality Checker's virtual environment.
"""

from __future__ import annotations

import glob
import importlib.util
import os
from functools import cache
from pathlib import Path

from vei_scenario.errors import VeiInputError

OSC_PACKAGE = "qc_openscenario"
ODR_PACKAGE = "qc_opendrive"

#: OpenSCENARIO minor version → schema folder of the checker package.
OSC_SCHEMAS = {
    0: "1.0.0/OpenSCENARIO.xsd",
    1: "1.1.1/OpenSCENARIO.xsd",
    2: "1.2.0/OpenSCENARIO.xsd",
    3: "1.3.0/OpenSCENARIO.xsd",
}
#: OpenDRIVE minor version → schema file.
ODR_SCHEMAS = {
    1: "1.1/OpenDRIVE_1.1.xsd",
    2: "1.2/OpenDRIVE_1.2.xsd",
    3: "1.3/OpenDRIVE_1.3.xsd",
    4: "1.4/OpenDRIVE_1.4H.xsd",
    5: "1.5/OpenDRIVE_1.5M.xsd",
    6: "1.6.1/opendrive_16_core.xsd",
    7: "1.7.0/opendrive_17_core.xsd",
    8: "1.8.0/OpenDRIVE_Core.xsd",
}

INSTALL_HINT = (
    "the ASAM XSDs ship in the ASAM Quality Checker packages: install their schema files beside vei with "
    "pip install --no-deps asam-qc-openscenarioxml asam-qc-opendrive (or point VEI_QC_VENV at an environment "
    "that has them)"
)


def _candidate_roots() -> list[Path]:
    roots: list[Path] = []
    for d in filter(None, os.environ.get("VEI_ASAM_SCHEMAS", "").split(os.pathsep)):
        roots.append(Path(d))
    for pkg in (OSC_PACKAGE, ODR_PACKAGE):
        spec = importlib.util.find_spec(pkg)
        if spec and spec.submodule_search_locations:
            roots.append(Path(next(iter(spec.submodule_search_locations))).parent)
    venv = os.environ.get("VEI_QC_VENV")
    if venv:
        venv = str(Path(venv).resolve())
        roots.extend(Path(p) for p in sorted(glob.glob(os.path.join(venv, "lib", "python*", "site-packages"))))
    return roots


@cache
def schema_dir(package: str) -> Path | None:
    """The ``schema`` directory of ``package`` (``qc_openscenario`` or ``qc_opendrive``), if found."""
    for root in _candidate_roots():
        for cand in (root / package / "schema", root / "schema", root):
            if cand.is_dir() and (cand / ("1.3.0" if package == OSC_PACKAGE else "1.4")).is_dir():
                if package == OSC_PACKAGE and not (cand / "1.3.0" / "OpenSCENARIO.xsd").is_file():
                    continue
                return cand
    return None


def xsd_path(kind: str, minor: int) -> Path:
    """XSD for OpenSCENARIO (``kind="xosc"``) or OpenDRIVE (``"xodr"``) 1.``minor``."""
    package, table = (OSC_PACKAGE, OSC_SCHEMAS) if kind == "xosc" else (ODR_PACKAGE, ODR_SCHEMAS)
    if minor not in table:
        raise KeyError(minor)
    base = schema_dir(package)
    if base is None:
        label = "OpenSCENARIO" if kind == "xosc" else "OpenDRIVE"
        raise VeiInputError(None, "ASAM XSD", f"no {label} schema found; {INSTALL_HINT}")
    return base / table[minor]
