"""The variation set as an OpenSCENARIO ParameterValueDistribution, and its resolved variants."""

from __future__ import annotations

import itertools

from scenariogeneration import xosc
from scenariogeneration.xosc.exceptions import OpenSCENARIOVersionError

from vei_scenario.errors import VeiInputError
from vei_scenario.openscenario.scenario_writer import AUTHOR, header_date, render
from vei_scenario.scenario.model import ScenarioModel
from vei_scenario.scenario.parameters import format_value


def distribution_xml(
    model: ScenarioModel, scenario_file: str, minor_version: int = 3, time_shift: bool = True
) -> bytes:
    """Deterministic distribution: one DistributionSet per varied parameter (their cartesian product);
    without ``time_shift`` for a scenario that declares no ``TimeShift`` (OpenSCENARIO 1.0)."""
    det = xosc.Deterministic()
    for name, values in model.variations().items():
        if name == "TimeShift" and not time_shift:
            continue
        dset = xosc.DistributionSet()
        type_ = model.parameter(name).type
        for v in values:
            dset.add_value(format_value(type_, v))
        det.add_single_distribution(name, dset)
    pvd = xosc.ParameterValueDistribution(
        f"Variations of {model.name}: timing shift, rider type, collision-avoidance planner",
        AUTHOR,
        scenario_file,
        det,
        osc_minor_version=minor_version,
    )
    pvd.header.creation_date = header_date(model)
    try:
        return render(pvd)
    except OpenSCENARIOVersionError as exc:
        raise VeiInputError(
            None, "--osc-version", f"variations not expressible in OpenSCENARIO 1.{minor_version}: {exc}"
        ) from None


def variant_combinations(model: ScenarioModel) -> list[dict[str, object]]:
    """Every combination of the variation set, each a full parameter assignment (defaults elsewhere)."""
    var = model.variations()
    names = list(var)
    out = []
    for combo in itertools.product(*(var[n] for n in names)):
        values = model.defaults()
        values.update(dict(zip(names, combo)))
        out.append(values)
    return out


def variant_filename(index: int, values: dict[str, object]) -> str:
    shift = float(values["TimeShift"])
    cap = "cap" if values["CapEnabled"] else "nocap"
    return f"variant_{index:03d}_shift{shift:+.2f}_{values['RiderType']}_{cap}.xosc"
