"""What vei's OSMP participants declare as FMU parameters, and the record of what they were built for.

A participant is built from a scenario's closed loop for one set of parameter values. The model
parameters a run or a sweep's variant may change (the planner's ``enabled``, ``cruise_speed_mps`` and
settings; the rider's ``rider_type``, ``time_shift_s`` and social-force settings) are FMU parameters
(causality parameter, variability fixed: set before initialisation ends), named as the plain vei FMUs
name them, the build's values their start values. The rest (the ego's path, Init pose and speed, the
rider's recorded track and route, the behaviour's start, the boxes) is held fixed in the binary; the
FMU records, in a vendor annotation, the scenario's parameter values it was built for and a digest
of what it holds fixed, so a host can tell a run it would silently get wrong (:func:`fixed_digest`).
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, fields

from vei_scenario.models.cap import CapParameters
from vei_scenario.models.sfm import SfmParameters

#: participant -> its FMU models and the one whose parameters it declares
MODELS = {"sfm": ("sfm",), "cap": ("cap", "ego")}
#: participant -> the names of the parameters it declares (those of its first model)
DECLARED = {
    "sfm": (*(f.name for f in fields(SfmParameters)), "rider_type", "time_shift_s"),
    "cap": (*(f.name for f in fields(CapParameters)), "enabled", "cruise_speed_mps"),
}
#: the vendor annotation's tool name and element
TOOL = "net.vei-scenario"
BUILD = "Build"


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


@dataclass(frozen=True)
class BuildRecord:
    """What a vei-built participant says it was built for."""

    model: str  # sfm | cap
    digest: str  # :func:`fixed_digest` of the build's loop
    parameters: tuple[tuple[str, str], ...]  # the scenario's parameter values of the build


def build_record(model: str, scenario, values: dict[str, str] | None, loop) -> BuildRecord:
    """The record of a build of ``model`` from ``scenario`` with ``values`` over its defaults."""
    from vei_scenario.interpreter.document import load_scenario

    resolved = load_scenario(scenario, values or {}).parameters
    return BuildRecord(model, fixed_digest(model, loop), tuple((k, str(v)) for k, v in resolved.items()))


def annotate(vendor, record: BuildRecord) -> None:
    """Add the record to a modelDescription's ``<VendorAnnotations>`` element."""
    from lxml import etree

    tool = etree.SubElement(vendor, "Tool", name=TOOL)
    build = etree.SubElement(tool, BUILD, model=record.model, fixed=record.digest)
    for name, value in record.parameters:
        etree.SubElement(build, "Parameter", name=name, value=value)


def read_record(root) -> BuildRecord | None:
    """The record in a parsed modelDescription, if a vei build wrote one."""
    el = root.find(f"VendorAnnotations/Tool[@name='{TOOL}']/{BUILD}")
    if el is None or el.get("model") not in MODELS:
        return None
    params = tuple((p.get("name", ""), p.get("value", "")) for p in el.iterfind("Parameter"))
    return BuildRecord(el.get("model"), el.get("fixed", ""), params)
