"""modelDescription.xml for FMI 2.0 and FMI 3.0 co-simulation FMUs, from the variable tables."""

from __future__ import annotations

import hashlib
import uuid

from lxml import etree

from vei_scenario import __version__
from vei_scenario.fmu.packaging import xml_value
from vei_scenario.fmu.variables import ModelSpec

#: SI base-unit exponents of the units the variables use.
UNITS = {
    "m": {"m": 1},
    "m/s": {"m": 1, "s": -1},
    "m/s2": {"m": 1, "s": -2},
    "m/s3": {"m": 1, "s": -3},
    "s": {"s": 1},
    "rad": {"rad": 1},
    "kg": {"kg": 1},
    "N": {"kg": 1, "m": 1, "s": -2},
    "1/s": {"s": -1},
    "1/s2": {"s": -2},
    "1": {},
}


def guid(spec: ModelSpec, flavour: str) -> str:
    """A GUID (FMI 2) / instantiation token (FMI 3) that changes with the variable table and the
    flavour (native / python, FMI version), and is the same on every build of the same inputs."""
    text = repr((spec.identifier, flavour, [(s.name, s.vr, s.var.type, s.var.causality) for s in spec.scalars()]))
    return "{" + str(uuid.UUID(hashlib.sha256(text.encode()).hexdigest()[:32])) + "}"


def _units(spec: ModelSpec, parent, fmi3: bool) -> None:
    used = sorted({v.unit for v in spec.variables if v.unit} | ({"s"} if fmi3 else set()))
    if not used:
        return
    defs = etree.SubElement(parent, "UnitDefinitions")
    for u in used:
        unit = etree.SubElement(defs, "Unit", name=u)
        etree.SubElement(unit, "BaseUnit", {k: str(e) for k, e in UNITS[u].items()})


def fmi2(
    spec: ModelSpec,
    guid_: str,
    source_files: list[str] | None,
    step_size: float = 0.01,
    global_value_references: bool = False,
    **cs_attrs,
) -> bytes:
    """FMI 2.0 modelDescription.xml; value references count per type (the C FMUs) or across all
    types (``global_value_references``: pythonfmu's numbering). Outputs are ``initial="calculated"``
    (set from the parameters on leaving initialization) and listed as InitialUnknowns; they have no
    direct feedthrough (the models compute them in doStep), hence empty Output dependencies."""
    root = etree.Element(
        "fmiModelDescription",
        fmiVersion="2.0",
        modelName=spec.identifier,
        guid=guid_,
        description=spec.description,
        generationTool=f"vei-scenario {__version__}",
        variableNamingConvention="structured",
        numberOfEventIndicators="0",
    )
    cs = etree.SubElement(
        root,
        "CoSimulation",
        modelIdentifier=spec.identifier,
        canHandleVariableCommunicationStepSize="true",
        canBeInstantiatedOnlyOncePerProcess=cs_attrs.pop("once_per_process", "false"),
        **cs_attrs,
    )
    if source_files:
        files = etree.SubElement(cs, "SourceFiles")
        for f in source_files:
            etree.SubElement(files, "File", name=f)
    _units(spec, root, False)
    cats = etree.SubElement(root, "LogCategories")
    etree.SubElement(cats, "Category", name="logStatusError", description="errors of the FMU")
    experiment = {"startTime": "0.0", "stepSize": repr(step_size)}
    if spec.stop_time is not None:  # a per-scenario build runs as long as the scenario
        experiment["stopTime"] = repr(float(spec.stop_time))
    etree.SubElement(root, "DefaultExperiment", experiment)
    mv = etree.SubElement(root, "ModelVariables")
    outputs: list[int] = []
    for index, s in enumerate(spec.scalars(), start=1):
        v = s.var
        vr = index - 1 if global_value_references else s.vr
        attrs = {"name": s.name, "valueReference": str(vr), "causality": v.causality, "variability": v.variability}
        if v.description:
            attrs["description"] = v.description
        if v.causality == "output":
            attrs["initial"] = "calculated"
            outputs.append(index)
        sv = etree.SubElement(mv, "ScalarVariable", attrs)
        tattrs = {}
        if v.causality != "output":
            tattrs["start"] = xml_value(s.start)
        if v.unit and v.type == "Real":
            tattrs["unit"] = v.unit
        etree.SubElement(sv, v.type, tattrs)
    ms = etree.SubElement(root, "ModelStructure")
    out = etree.SubElement(ms, "Outputs")
    for i in outputs:
        etree.SubElement(out, "Unknown", index=str(i), dependencies="")
    init = etree.SubElement(ms, "InitialUnknowns")
    for i in outputs:
        etree.SubElement(init, "Unknown", index=str(i))
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


_FMI3_TYPES = {"Real": "Float64", "Integer": "Int32", "Boolean": "Boolean", "String": "String"}


def fmi3(spec: ModelSpec, token: str, step_size: float = 0.01) -> bytes:
    """FMI 3.0 modelDescription.xml (co-simulation). Value references are unique across types
    (:meth:`ModelSpec.fmi3_vrs`); arrays stay runs of scalars so the FMI 2 and 3 FMUs look alike."""
    root = etree.Element(
        "fmiModelDescription",
        fmiVersion="3.0",
        modelName=spec.identifier,
        instantiationToken=token,
        description=spec.description,
        generationTool=f"vei-scenario {__version__}",
        variableNamingConvention="structured",
    )
    etree.SubElement(
        root,
        "CoSimulation",
        modelIdentifier=spec.identifier,
        canHandleVariableCommunicationStepSize="true",
        canBeInstantiatedOnlyOncePerProcess="false",
        providesIntermediateUpdate="false",
        hasEventMode="false",
    )
    _units(spec, root, True)
    cats = etree.SubElement(root, "LogCategories")
    etree.SubElement(cats, "Category", name="logStatusError", description="errors of the FMU")
    experiment = {"startTime": "0.0", "stepSize": repr(step_size)}
    if spec.stop_time is not None:  # a per-scenario build runs as long as the scenario
        experiment["stopTime"] = repr(float(spec.stop_time))
    etree.SubElement(root, "DefaultExperiment", experiment)
    mv = etree.SubElement(root, "ModelVariables")
    etree.SubElement(
        mv,
        "Float64",
        name="time",
        valueReference=str(len(spec.scalars())),
        causality="independent",
        variability="continuous",
        unit="s",
        description="simulation time",
    )
    outputs: list[int] = []
    vrs = spec.fmi3_vrs()
    for s in sorted(spec.scalars(), key=lambda s: vrs[s.name]):
        v = s.var
        vr = vrs[s.name]
        attrs = {"name": s.name, "valueReference": str(vr), "causality": v.causality, "variability": v.variability}
        if v.description:
            attrs["description"] = v.description
        if v.causality == "output":
            attrs["initial"] = "calculated"
            outputs.append(vr)
        else:
            if v.type != "String":
                attrs["start"] = xml_value(s.start)
        if v.unit and v.type == "Real":
            attrs["unit"] = v.unit
        el = etree.SubElement(mv, _FMI3_TYPES[v.type], attrs)
        if v.type == "String" and v.causality != "output":
            etree.SubElement(el, "Start", value=str(s.start))
    ms = etree.SubElement(root, "ModelStructure")
    for vr in outputs:
        etree.SubElement(ms, "Output", valueReference=str(vr), dependencies="")
    for vr in outputs:
        etree.SubElement(ms, "InitialUnknown", valueReference=str(vr))
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)
