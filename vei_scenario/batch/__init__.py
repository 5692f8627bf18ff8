"""Sweeps of vei-compiled closed loops in the compiled core's kernel, many variants at once."""

from vei_scenario.batch.native import NativeBatch

__all__ = ["NativeBatch"]
