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


#: Draws and seed of the stochastic distribution (vei probability's default runs per estimator).
STOCHASTIC_RUNS = 20000
STOCHASTIC_SEED = 1
#: Standard deviation of the rider's timing when the paths never collide (s).
FALLBACK_TIMING_SD_S = 1.0


def timing_spread(model: ScenarioModel) -> tuple[float, float]:
    """Mean and standard deviation (s) of the rider's timing for a stress test of the system under
    test: centred on the conflict shift (where the two would meet), spread by half the collision
    interval's width (so about two draws in three would collide without the planner), or 1 s when
    the paths never lead to contact."""
    mean = float(model.parameter("ConflictTimeShift").default)
    shifts = model.conflicts[model.threat].collision_shifts_s
    sd = (shifts[1] - shifts[0]) / 2 if shifts and shifts[1] > shifts[0] else FALLBACK_TIMING_SD_S
    return round(mean, 3), round(sd, 3)


def stochastic_distribution_xml(model: ScenarioModel, scenario_file: str, minor_version: int = 3) -> bytes:
    """A stochastic ParameterValueDistribution for ``vei probability`` (and ``vei sweep``): TimeShift
    normal (:func:`timing_spread`, truncated to three standard deviations either side), the rider type
    uniform over the rider models; CapEnabled and the rest stay the scenario's (or ``--param``)."""
    mean, sd = timing_spread(model)
    sto = xosc.Stochastic(STOCHASTIC_RUNS, STOCHASTIC_SEED)
    lo, hi = round(mean - 3 * sd, 3), round(mean + 3 * sd, 3)
    sto.add_distribution("TimeShift", xosc.NormalDistribution(mean, round(sd * sd, 6), xosc.Range(lo, hi)))
    riders = xosc.ProbabilityDistributionSet()
    for rider in model.variations()["RiderType"]:
        riders.add_set(str(rider), 1)
    sto.add_distribution("RiderType", riders)
    pvd = xosc.ParameterValueDistribution(
        f"Stochastic variations of {model.name}: TimeShift ~ N({mean:g} s, ({sd:g} s)^2) on [{lo:g}, {hi:g}] s, "
        "rider type uniform",
        AUTHOR,
        scenario_file,
        sto,
        osc_minor_version=minor_version,
    )
    pvd.header.creation_date = header_date(model)
    return render(pvd)


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
