"""The core's scoring of a recorded run (``vei_batch_score``, what ``vei run`` and ``vei sweep`` use)
against the numpy definitions of every metric: the same bits, on pairs that cross, follow, touch,
stand, and on uneven sample times."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from vei_scenario.core.kernel import load_kernel
from vei_scenario.metrics import MetricConfig, PairSeries, compute_metrics
from vei_scenario.metrics.definitions import METRICS, to_python
from vei_scenario.metrics.scored_in_core import core_metrics, scores
from vei_scenario.metrics.series import Track


def _pair(rng: np.random.Generator, kind: str) -> PairSeries:
    n = int(rng.integers(3, 900))
    dt = float(rng.choice([0.01, 0.02, 0.05, 0.1]))
    t = np.round(np.arange(n) * dt, 9)
    if kind == "uneven":
        t = np.cumsum(rng.uniform(0.2, 1.8, n) * dt)
    ego_v = rng.uniform(0, 25) + rng.normal(0, 0.5, n).cumsum() * (kind != "standing")
    ego_yaw = rng.uniform(-math.pi, math.pi) + rng.normal(0, 0.01, n).cumsum()
    ex = np.concatenate([[0.0], np.cumsum(ego_v[:-1] * np.cos(ego_yaw[:-1]) * np.diff(t))])
    ey = np.concatenate([[0.0], np.cumsum(ego_v[:-1] * np.sin(ego_yaw[:-1]) * np.diff(t))])
    if kind == "following":
        ox, oy, oyaw = ex + 12 * np.cos(ego_yaw), ey + 12 * np.sin(ego_yaw), ego_yaw + rng.normal(0, 0.02, n)
        ov = ego_v - rng.uniform(0, 3)
    else:  # crossing the ego's path, or standing on it
        k = int(rng.integers(0, n))
        heading = ego_yaw[k] + rng.choice([1, -1]) * rng.uniform(0.4, 2.7)
        ov = np.full(n, rng.uniform(0, 8))
        s = (t - t[k]) * ov + rng.normal(0, 1.0)
        ox, oy = ex[k] + s * np.cos(heading), ey[k] + s * np.sin(heading)
        oyaw = np.full(n, heading) + rng.normal(0, 0.05, n)
    ego = Track("ego", rng.uniform(3.5, 5.2), rng.uniform(1.6, 2.1), ex, ey, ego_yaw, ego_v, np.gradient(ego_v, t))
    other = Track("other", rng.uniform(0.5, 4.8), rng.uniform(0.4, 1.9), ox, oy, oyaw, ov, rng.normal(0, 1, n))
    return PairSeries(t, ego, other)


def _raw(pair: PairSeries, cfg: MetricConfig) -> dict[str, float]:
    out = {}
    for name in load_kernel().columns:
        if name.startswith("ttc_zones_s."):
            out[name] = float(METRICS["ttc_zones_s"](pair, cfg)[name.split(".")[1]])
        else:
            out[name] = float(METRICS[name](pair, cfg))
    return out


@pytest.mark.parametrize("kind", ["crossing", "following", "standing", "uneven"])
@pytest.mark.parametrize("zone_ttc", ["2d", "approx"])
def test_the_core_scores_a_run_as_the_definitions_do(kind, zone_ttc):
    rng = np.random.default_rng(len(kind) * 7 + len(zone_ttc))
    cfg = MetricConfig(zone_ttc=zone_ttc)
    contacts = 0
    for _ in range(25):
        pair = _pair(rng, kind)
        e, o = pair.ego, pair.other
        traj = np.array([e.x, e.y, e.yaw, e.speed, e.accel, o.x, o.y, o.yaw, o.speed, o.accel])
        out = scores(pair.t, traj, cfg, (e.length, e.width), (o.length, o.width))
        expected = _raw(pair, cfg)
        for name, column in load_kernel().columns.items():
            a, b = expected[name], float(out[column])
            assert a == b or (math.isnan(a) and math.isnan(b)), (kind, name, a, b)
        contacts += bool(expected["collision"])
        # and the metric dicts vei run writes are the same
        who = (e.name, o.name)
        numpy_dict = {n: to_python(n, METRICS[n](pair, cfg), (), who) for n in METRICS}
        assert json.dumps(core_metrics(pair, cfg)) == json.dumps(numpy_dict)
    if kind in ("crossing", "standing"):
        assert contacts > 0  # the cases reach contact, not only near misses


def test_runs_the_core_does_not_take_go_to_the_definitions():
    rng = np.random.default_rng(3)
    pair = _pair(rng, "crossing")
    pair.ego.speed[5] = np.nan
    assert core_metrics(pair, MetricConfig()) is None
    assert compute_metrics(pair)["min_gap_m"] == to_python("min_gap_m", METRICS["min_gap_m"](pair, MetricConfig()))

    def first_two(tr: Track) -> Track:
        return Track(tr.name, tr.length, tr.width, tr.x[:2], tr.y[:2], tr.yaw[:2], tr.speed[:2], tr.accel[:2])

    two = PairSeries(pair.t[:2], first_two(pair.ego), first_two(pair.other))
    assert core_metrics(two, MetricConfig()) is None and "pet_s" in compute_metrics(two)
