"""The batch engine equals ``vei run`` variant by variant (trajectories within 1e-9 m, identical
collision onsets), and refuses scenarios it cannot run as arrays."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from vei_scenario.batch import BatchScenario
from vei_scenario.interpreter import run_scenario
from vei_scenario.loop import NotALoop

DATA = Path(__file__).parent / "data"


def test_batch_trajectories_equal_vei_run(compiled):
    xosc = compiled["case_study"].written[0]
    rng = np.random.default_rng(5)
    variants = [
        {"TimeShift": "2.2", "RiderType": rt, "CapEnabled": cap}
        for rt in ("replay", "normal", "aggressive")
        for cap in ("false", "true")
    ]
    variants += [
        {
            "TimeShift": repr(round(float(s), 3)),
            "RiderType": str(rt),
            "CapEnabled": str(c),
            "EgoCruiseSpeed": repr(round(float(v), 2)),
        }
        for s, rt, c, v in zip(
            rng.uniform(-2, 5, 6),
            rng.choice(["replay", "normal", "aggressive"], 6),
            rng.choice(["true", "false"], 6),
            rng.uniform(4, 8, 6),
        )
    ]
    batch = BatchScenario(xosc).run(variants)
    assert any(batch.collision_onsets) and not all(batch.collision_onsets)  # both outcomes are present
    for i, v in enumerate(variants):
        single = run_scenario(xosc, v)
        assert np.array_equal(single.t, batch.t)
        for k, name in enumerate(batch.names):
            tr = single.traces[name]
            for q in ("x", "y", "yaw", "speed"):
                np.testing.assert_allclose(getattr(batch, q)[k, i], getattr(tr, q), rtol=0, atol=1e-9)
        assert batch.collision_onsets[i] == single.collisions, v


def test_other_structures_are_refused():
    with pytest.raises(NotALoop):
        BatchScenario(DATA / "following_brake.xosc")


def test_batch_metrics_equal_vei_run_metrics(compiled):
    from vei_scenario.batch import batch_pair
    from vei_scenario.metrics import PairSeries, compute_metrics, compute_metrics_batch

    xosc = compiled["case_study"].written[0]
    variants = [
        {"TimeShift": ts, "RiderType": rt, "CapEnabled": cap}
        for ts in ("0", "2.2")
        for rt in ("replay", "aggressive")
        for cap in ("false", "true")
    ]
    rows = compute_metrics_batch(batch_pair(BatchScenario(xosc).run(variants)))
    for v, row in zip(variants, rows):
        assert row == compute_metrics(PairSeries.from_run(run_scenario(xosc, v))), v
