"""Safety and comfort metrics of a run: one function per metric, one signature, a registry by name.

Every metric takes a :class:`~vei_scenario.metrics.series.PairSeries` (the ego and one other entity
over time, with the derived gap and TTC series) and a :class:`~vei_scenario.metrics.series.MetricConfig`
and returns a JSON-ready value. ``compute_metrics`` evaluates a selection by name.
"""

from __future__ import annotations

from vei_scenario.metrics.definitions import METRICS
from vei_scenario.metrics.series import MetricConfig, PairSeries


def compute_metrics(pair: PairSeries, cfg: MetricConfig | None = None, names: list[str] | None = None) -> dict:
    cfg = cfg or MetricConfig()
    selected = names or list(METRICS)
    unknown = [n for n in selected if n not in METRICS]
    if unknown:
        raise KeyError(f"unknown metric(s) {', '.join(unknown)}; known: {', '.join(METRICS)}")
    return {n: METRICS[n](pair, cfg) for n in selected}


__all__ = ["METRICS", "MetricConfig", "PairSeries", "compute_metrics"]
