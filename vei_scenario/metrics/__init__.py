"""Safety and comfort metrics of a run: one function per metric, one signature, a registry by name.

Every metric takes a :class:`~vei_scenario.metrics.series.PairSeries` (the ego and one other entity
over time, with the derived gap and TTC series) and a :class:`~vei_scenario.metrics.series.MetricConfig`
and reduces over time. ``compute_metrics`` scores one run, ``compute_metrics_batch`` a batch of
variants with the same code; both report through one converter, so their values are identical.
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
    who = (pair.ego.name, pair.other.name)
    return {n: to_python(n, METRICS[n](pair, cfg), (), who) for n in _selected(names)}


def compute_metrics_batch(
    pair: PairSeries, cfg: MetricConfig | None = None, names: list[str] | None = None
) -> list[dict]:
    """Metrics of every variant of a batch (arrays of shape (V, T)), one dict per variant."""
    cfg = cfg or MetricConfig()
    who = (pair.ego.name, pair.other.name)
    raw = {n: METRICS[n](pair, cfg) for n in _selected(names)}
    count = pair.gap.shape[0]
    return [{n: to_python(n, r, (i,), who) for n, r in raw.items()} for i in range(count)]


__all__ = ["METRICS", "MetricConfig", "PairSeries", "compute_metrics", "compute_metrics_batch"]
