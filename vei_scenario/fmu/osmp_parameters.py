"""What vei's OSMP participants declare as FMU parameters, and the record of what they were built for.

A participant is built from a scenario's closed loop for one set of parameter values. The model
parameters a run or a sweep's variant may change (the planner's ``enabled``, ``cruise_speed_mps`` and
settings; the rider's ``rider_type``, ``time_shift_s`` and social-force settings) are FMU parameters
(causality parameter, variability fixed: set before initialisation ends), named as the plain vei FMUs
name them, the build's values their start values. The rest (the ego's path, Init pose and speed, the
rider's recorded track and route, the behaviour's start, the boxes) is held fixed in the binary; the
FMU records, in a vendor annotation, the scenario's parameter values it was built for and a digest
of what it holds fixed, and names :func:`run_values`, which vei's host calls for each run: the
declared parameters as the built-in models get them in that run, or one line refusing a run whose
values change what the participant holds fixed (rather than run it silently with the build's).
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import fields
from functools import lru_cache
from pathlib import Path

from vei_scenario.errors import VeiInputError
from vei_scenario.models.cap import CapParameters
from vei_scenario.models.sfm import SfmParameters
from vei_scenario.sut.contract import ControllerFault
from vei_scenario.sut.osmp import BUILD, BuildRecord

#: participant -> its FMU models and the one whose parameters it declares
MODELS = {"sfm": ("sfm",), "cap": ("cap", "ego")}
#: participant -> the names of the parameters it declares (those of its first model)
DECLARED = {
    "sfm": (*(f.name for f in fields(SfmParameters)), "rider_type", "time_shift_s"),
    "cap": (*(f.name for f in fields(CapParameters)), "enabled", "cruise_speed_mps"),
}
#: the vendor annotation's tool name; the function a host calls for a run's values (:func:`run_values`)
TOOL = "net.vei-scenario"


def declared_variables(model: str):
    """The participant's declared parameters as the variables of its model's table, in its order."""
    from vei_scenario.fmu.variables import SPECS

    names = DECLARED[model]
    return [v for v in SPECS[MODELS[model][0]].variables if v.name in names]


def start_text(value) -> str:
    """A start value as the modelDescription writes it (and the host sets it: the same text)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value + 0.0)  # (-0.0 as 0.0)
    return str(value)


def declared_values(model: str, loop) -> dict[str, str]:
    """The declared parameters' values in ``loop`` (a :class:`~vei_scenario.fmu.system.ClosedLoop`)."""
    given = loop.parameters[MODELS[model][0]]
    return {v.name: start_text(given.get(v.name, v.start)) for v in declared_variables(model)}


def fixed_digest(model: str, loop) -> str:
    """A digest of what the participant holds fixed for ``loop``: every value of its models but the
    declared parameters, and the entity it watches."""
    declared = set(DECLARED[model])
    held = {m: {k: v for k, v in sorted(loop.parameters[m].items()) if k not in declared} for m in MODELS[model]}
    held["other"] = loop.entities["ego" if model == "sfm" else "sfm"]
    return hashlib.sha256(json.dumps(held, sort_keys=True).encode()).hexdigest()


def build_record(model: str, scenario, values: dict[str, str] | None, loop) -> BuildRecord:
    """The record of a build of ``model`` from ``scenario`` with ``values`` over its defaults."""
    from vei_scenario.interpreter.document import load_scenario

    resolved = load_scenario(scenario, values or {}).parameters
    params = tuple((k, str(v)) for k, v in resolved.items())
    return BuildRecord(f"{__name__}:run_values", model, fixed_digest(model, loop), params)


def annotate(vendor, record: BuildRecord) -> None:
    """Add the record to a modelDescription's ``<VendorAnnotations>`` element."""
    from lxml import etree

    tool = etree.SubElement(vendor, "Tool", name=TOOL)
    build = etree.SubElement(tool, BUILD, resolver=record.resolver, model=record.model, fixed=record.digest)
    for name, value in record.parameters:
        etree.SubElement(build, "Parameter", name=name, value=value)


def osmp_loop(scenario: str | Path, values: dict[str, str] | None = None):
    """The scenario's FMU loop as the participants carry it: the threat's rider, the planner and the
    ego; the other road users are the host's to show, none of them is packed."""
    from vei_scenario.fmu.system import closed_loop
    from vei_scenario.loop import LoopScene, NotALoop

    try:
        names = tuple(LoopScene(scenario).names)
    except NotALoop:
        names = ()  # (closed_loop says why)
    return closed_loop(scenario, values, leave_out=names)


@lru_cache(maxsize=8)
def _loop(scenario: str, stamp: int, values: tuple[tuple[str, str], ...]):
    """The scenario's closed loop as the participants carry it, for ``values`` (cached per file
    version, ``stamp`` its modification time, and values: a run's participants share one)."""
    return osmp_loop(scenario, dict(values))


def _builds(scenario: Path, built: dict[str, str], record: BuildRecord) -> bool:
    """Whether ``scenario`` with the build's values gives what the participant holds fixed (else it
    was built from another scenario, or this one has changed since)."""
    try:
        loop = _loop(str(scenario.resolve()), scenario.stat().st_mtime_ns, tuple(sorted(built.items())))
    except VeiInputError:
        return False
    return fixed_digest(record.model, loop) == record.digest


def run_values(fmu: str, record: BuildRecord, scenario: Path, values: dict[str, str], label: str) -> dict[str, str]:
    """The declared parameters of the participant ``fmu`` (its file name) with ``record``, for the run
    of ``scenario`` with the parameter values ``values``: as the built-in models get them, from the
    scenario's closed loop resolved for the run. What it holds fixed must be what the run would give
    it too; else one :class:`ControllerFault` line names the values that differ from the build's."""
    try:
        loop = _loop(str(scenario.resolve()), scenario.stat().st_mtime_ns, tuple(sorted(values.items())))
    except VeiInputError as exc:
        raise ControllerFault(label, f"{fmu} was built by vei for a closed loop: {exc.reason}") from None
    if fixed_digest(record.model, loop) != record.digest:
        built = dict(record.parameters)
        changed = [k for k in values if k in built and values[k] != built[k]]
        if not changed or not _builds(scenario, built, record):
            raise ControllerFault(label, f"{fmu} was built from another scenario (what it holds fixed differs from "
                                  f"{scenario.name}'s): build it from this one")  # fmt: skip
        run = ", ".join(f"{k}={values[k]}" for k in changed)
        then = ", ".join(f"{k}={built[k]}" for k in changed)
        fix = " ".join(f"--param {k}={values[k]}" for k in changed)
        raise ControllerFault(label, f"{fmu} was built for {then}; this run's {run} changes what it holds fixed "
                              "(the ego's path, Init pose and speed; the rider's track, route and start): build it "
                              f"for these values (vei fmu build {record.model} --osmp --scenario {scenario} "
                              f"{fix})")  # fmt: skip
    return declared_values(record.model, loop)
