"""Where the core's C sources are and which compiler builds them on demand (the FMU builder compiles
the models into each FMU's binary)."""

from __future__ import annotations

import os
import shutil
from importlib import resources
from pathlib import Path

from vei_scenario.errors import VeiInputError


def source_dir() -> Path:
    """The core's C sources (``vei_scenario/core/src``: package data in an installed vei-scenario)."""
    return Path(str(resources.files("vei_scenario.core") / "src"))


def compiler() -> str:
    """The C compiler: $CC if set, else cc or gcc on the PATH."""
    wanted = os.environ.get("CC")
    cc = shutil.which(wanted) if wanted else (shutil.which("cc") or shutil.which("gcc"))
    if not cc:
        what = f"CC={wanted!r} is not an executable" if wanted else "no C compiler found (install gcc or set CC)"
        raise VeiInputError(None, "vei fmu build", what)
    return cc
