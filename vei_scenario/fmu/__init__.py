"""The models as FMI co-simulation FMUs, the closed loop as an SSP package, and co-simulation.

Library entry points (the ``vei fmu`` commands call them):

- :func:`build_fmus`: native C FMUs (default) or pythonfmu FMUs, FMI 2.0 or 3.0;
- :func:`build_system`: the closed loop of a scenario as SSP 1.0 (``vei fmu system``);
- :func:`cosimulate`: the closed loop in a co-simulation engine, compared with ``vei run``.
"""

from __future__ import annotations

import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

from vei_scenario.errors import VeiInputError
from vei_scenario.fmu.variables import MODELS, SPECS

BACKENDS = ("native", "python")
ENGINES = ("fmpy", "libcosim")


def build_fmus(
    models: list[str],
    out_dir: str | Path,
    backend: str = "native",
    fmi: int = 2,
    scenario: str | Path | None = None,
    values: dict[str, str] | None = None,
) -> dict[str, Path]:
    """Build the FMUs of ``models`` (sfm, cap, ego) into ``out_dir``; returns model -> .fmu path.

    With ``scenario`` (a vei-compiled .xosc, parameter overrides ``values``) every parameter starts at
    the scenario's value (its track, path, route, boxes, planner and rider settings: thousands of
    scalars nobody sets by hand) and the default experiment runs as long as the scenario, so the FMUs
    reproduce it alone or in any co-simulation host without a parameter file."""
    if backend not in BACKENDS:
        raise VeiInputError(None, "--backend", f"{backend!r} is not one of {', '.join(BACKENDS)}")
    if fmi not in (2, 3):
        raise VeiInputError(None, "--fmi", f"FMI version {fmi} is not 2 or 3")
    if backend == "python" and fmi != 2:
        raise VeiInputError(None, "--fmi", "the python backend builds FMI 2.0 FMUs only (pythonfmu)")
    unknown = [m for m in models if m not in MODELS]
    if unknown:
        raise VeiInputError(None, "models", f"unknown model {unknown[0]!r} (choose from {', '.join(MODELS)}, all)")
    specs = {m: SPECS[m] for m in models}
    if scenario is not None:
        if backend != "native":
            raise VeiInputError(None, "--scenario", "per-scenario FMUs are built with the native backend")
        from vei_scenario.fmu.system import closed_loop

        loop = closed_loop(scenario, values)
        specs = {m: SPECS[m].with_starts(loop.parameters[m], loop.steps * loop.dt) for m in models}
    out: dict[str, Path] = {}
    for m in models:
        if backend == "native":
            from vei_scenario.fmu.native import build_native

            out[m] = build_native(specs[m], Path(out_dir), fmi)
        else:
            from vei_scenario.fmu.python_backend import build_python

            out[m] = build_python(SPECS[m], Path(out_dir))
    return out


def build_system(
    scenario: str | Path,
    out: str | Path,
    values: dict[str, str] | None = None,
    dt: float = 0.01,
    backend: str = "native",
    fmi: int = 2,
    leave_out: tuple[str, ...] = (),
) -> Path:
    """The closed loop of ``scenario`` (with parameter overrides) as an SSP package at ``out``;
    ``leave_out``: road users that are no riders, left out of it."""
    from vei_scenario.fmu.system import closed_loop, write_ssp

    loop = closed_loop(scenario, values, dt, tuple(leave_out))
    with tempfile.TemporaryDirectory(prefix="vei-ssp-") as tmp:
        fmus = build_fmus(list(MODELS), tmp, backend, fmi)
        return write_ssp(loop, fmus, Path(out))


@dataclass
class CosimReport:
    engine: str
    coupling: str
    record: dict  # component -> output -> array over communication points
    max_deviation_m: dict[str, float]  # per component: largest position difference to vei run
    steps: int
    loop: object


def cosimulate(
    scenario: str | Path,
    engine: str = "fmpy",
    values: dict[str, str] | None = None,
    dt: float = 0.01,
    coupling: str | None = None,
    backend: str = "native",
    fmi: int = 2,
    fmus: dict[str, Path] | None = None,
    leave_out: tuple[str, ...] = (),
) -> CosimReport:
    """Run the closed loop of ``scenario`` in ``engine`` and compare it with ``vei run`` under the same
    coupling (fmpy: sequential by default, or jacobi; libcosim: jacobi, its fixed-step algorithm).
    ``fmus`` (model -> .fmu) skips building them."""
    from vei_scenario.fmu.cosim import compare_with_run, run_fmpy, run_libcosim
    from vei_scenario.fmu.system import closed_loop, write_ssp
    from vei_scenario.interpreter import run_scenario

    if engine not in ENGINES:
        raise VeiInputError(None, "--engine", f"{engine!r} is not one of {', '.join(ENGINES)}")
    coupling = coupling or ("jacobi" if engine == "libcosim" else "sequential")
    if engine == "libcosim" and coupling != "jacobi":
        raise VeiInputError(None, "--coupling", "libcosim's fixed-step algorithm couples Jacobi-style only")
    loop = closed_loop(scenario, values, dt, tuple(leave_out))
    tmp = Path(tempfile.mkdtemp(prefix="vei-cosim-"))
    try:
        fmus = fmus or build_fmus(list(MODELS), tmp, backend, fmi)
        if engine == "fmpy":
            record = run_fmpy(loop, fmus, coupling)
        else:
            try:
                import libcosimpy  # noqa: F401
            except ImportError:
                raise VeiInputError(None, "--engine libcosim", "needs libcosimpy: pip install libcosimpy") from None
            if fmi != 2:
                raise VeiInputError(None, "--engine libcosim", "libcosim loads FMI 2.0 FMUs; use --fmi 2")
            record = run_libcosim(write_ssp(loop, fmus, tmp / "loop.ssp"), loop)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    run = run_scenario(scenario, values, dt, coupling=coupling)
    return CosimReport(engine, coupling, record, compare_with_run(record, run, loop), loop.steps, loop)


__all__ = ["BACKENDS", "ENGINES", "MODELS", "SPECS", "build_fmus", "build_system", "cosimulate", "CosimReport"]
