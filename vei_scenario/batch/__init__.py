"""Batch engine: many variants of a vei-compiled scenario at once, as arrays."""

from vei_scenario.batch.engine import BatchResult, BatchScenario, batch_pair

__all__ = ["BatchResult", "BatchScenario", "batch_pair"]
