"""The Euro NCAP scenario pack's single executions: which files they are, their base scenario and
their values (Vector's OSC-NCAP-scenarios layout: ``<protocol>/Variations/*.xosc`` beside the base
scenarios, the 2026 pack's in ``Variations/SingleExecution``). Used by the conformance benchmark and
the tests that hold vei to esmini on them."""

from __future__ import annotations

from pathlib import Path


def single_executions(root: Path) -> list[Path]:
    """Every single-parameter-set variation file under ``root`` (the pack's ``OpenSCENARIO/NCAP``):
    the 2023 files not named ``*_Variation_*`` and all of the 2026 ``SingleExecution`` files."""
    files = [p for p in root.glob("*/Variations/*.xosc") if "_Variation_" not in p.name]
    files += list(root.glob("*/Variations/SingleExecution/*.xosc"))
    return sorted(files)


def full_variations(root: Path) -> list[Path]:
    """Every variation file of many parameter sets under ``root``: the 2023 ``*_Variation_*`` files and
    the 2026 ``StandardRange`` and ``ExtendedRange`` files."""
    files = list(root.glob("*/Variations/*_Variation_*.xosc"))
    files += [p for k in ("StandardRange", "ExtendedRange") for p in root.glob(f"*/Variations/{k}/*.xosc")]
    return sorted(files)


def base_scenario(variation: Path) -> Path:
    """The scenario a ParameterValueDistribution file varies (its ``ScenarioFile``)."""
    from vei_scenario.variation import distributed_scenario

    base = distributed_scenario(variation)
    if base is None:
        from vei_scenario.errors import VeiInputError

        raise VeiInputError(variation, "", "not a ParameterValueDistribution file")
    return base


def values_of(variation: Path) -> tuple[Path, dict[str, str]]:
    """(base scenario, the first parameter set of ``variation``)."""
    from vei_scenario.interpreter.document import load_scenario
    from vei_scenario.variation import read_distribution

    base = base_scenario(variation)
    return base, read_distribution(variation, load_scenario(base).parameter_types)[0]
