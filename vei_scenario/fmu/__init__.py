"""The models as FMI co-simulation FMUs (native C by default, or Python through pythonfmu), the
closed loop as an SSP package, and co-simulation masters to run it."""

from vei_scenario.fmu.variables import MODELS, SPECS

__all__ = ["MODELS", "SPECS"]
