"""The closed loop (ego + planner, rider + social force) of a vei-compiled scenario, read once for the
sweep engines, the FMU system and the SSP writer."""

from vei_scenario.loop.scene import LoopScene, NotALoop, Resolved

__all__ = ["LoopScene", "NotALoop", "Resolved"]
