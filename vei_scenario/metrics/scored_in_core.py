"""``vei run``'s metrics scored by the compiled core: the per-step metrics of any recorded run in one
C call (``vei_batch_score``, the sweep kernel's own scoring), and the kernel's output columns as
metric dicts.

The numpy definitions (:mod:`vei_scenario.metrics.definitions`) are the kept vectorised form: they
score what the core does not take (a batch of variants as arrays, a run of fewer than three samples or
with non-finite values, a subset of the metrics), and tests/test_metrics_core.py holds the two equal.
"""

from __future__ import annotations

import math

import numpy as np

from vei_scenario.core.kernel import load_kernel, score
from vei_scenario.metrics.definitions import DIGITS, METRICS, ZONES
from vei_scenario.metrics.series import MetricConfig, PairSeries


def core_metrics(pair: PairSeries, cfg: MetricConfig) -> dict | None:
    """Every metric of one run (arrays (T,)) from the core, or None when it is not the core's to score."""
    t = pair.t
    if t.ndim != 1 or t.size < 3:
        return None
    e, o = pair.ego, pair.other
    traj = np.array([e.x, e.y, e.yaw, e.speed, e.accel, o.x, o.y, o.yaw, o.speed, o.accel], dtype=float)
    if traj.shape != (10, t.size) or not (np.isfinite(traj).all() and np.isfinite(t).all()):
        return None
    if not (np.diff(t) > 0).all():
        return None
    out = score(t, traj, cfg, (e.length, e.width), (o.length, o.width))
    return metric_rows(out[None, :], (e.name, o.name), load_kernel().columns)[0]


def metric_rows(out: np.ndarray, who: tuple[str, str], index: dict[str, int]) -> list[dict]:
    """The kernel's outputs as ``vei run``'s metric dicts (:func:`to_python` applied to each value),
    built column by column from Python floats: 10 000 rows in ~0.05 s instead of ~0.3 s. ``index``:
    the column of each metric, by name (the kernel's own list)."""
    cols = out.T.tolist()

    def number(name: str, digits_of: str | None = None) -> list:
        digits = DIGITS.get(digits_of or name, 4)
        return [round(v, digits) if math.isfinite(v) else None for v in cols[index[name]]]

    hit = [v != 0 for v in cols[index["collision"]]]
    zones = [number(f"ttc_zones_s.{z}", "ttc_zones_s") for z in ZONES]
    numbers = {name: number(name) for name in index if name not in ("collision", "near_miss") and "." not in name}
    values = {
        "collision": hit,
        "collision_entities": [list(who) if h else [] for h in hit],
        **numbers,
        "ttc_zones_s": [dict(zip(ZONES, z)) for z in zip(*zones)],
        "near_miss": [v != 0 for v in cols[index["near_miss"]]],
    }
    columns = {name: values[name] for name in METRICS}  # in vei run's order (KeyError: a metric missing)
    names = list(columns)
    return [dict(zip(names, values)) for values in zip(*columns.values())]
