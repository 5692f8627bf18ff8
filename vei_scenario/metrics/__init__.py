"""Safety and comfort metrics of a run: one function per metric, one signature, a registry by name.

Every metric takes a :class:`~vei_scenario.metrics.series.PairSeries` (the ego and one other entity
over time, with the derived gap and TTC series) and a :class:`~vei_scenario.metrics.series.MetricConfig`
and reduces over time; ``compute_metrics`` scores one run. They are the metrics' definitions and the
one vectorised form kept (numpy over a run's steps, or over variants and steps). A whole run is scored
by the compiled core (:mod:`vei_scenario.metrics.scored_in_core`: the sweep kernel's scoring, in C,
operation for operation as defined here), 10x quicker; tests/test_metrics_core.py holds the two equal
bit for bit.
"""

from __future__ import annotations

from vei_scenario.metrics.definitions import METRICS, to_python
from vei_scenario.metrics.series import MetricConfig, PairSeries


def _selected(names: list[str] | None) -> list[str]:
    selected = names or list(METRICS)
    unknown = [n for n in selected if n not in METRICS]
    if unknown:
        raise KeyError(f"unknown metric(s) {', '.join(unknown)}; known: {', '.join(METRICS)}")
    return selected


def compute_metrics(pair: PairSeries, cfg: MetricConfig | None = None, names: list[str] | None = None) -> dict:
    """Metrics of one run (arrays of shape (T,)), as JSON-ready values."""
    cfg = cfg or MetricConfig()
    if names is None:
        from vei_scenario.metrics.scored_in_core import core_metrics

        scored = core_metrics(pair, cfg)
        if scored is not None:
            return scored
    who = (pair.ego.name, pair.other.name)
    return {n: to_python(n, METRICS[n](pair, cfg), (), who) for n in _selected(names)}


__all__ = ["METRICS", "MetricConfig", "PairSeries", "compute_metrics"]
