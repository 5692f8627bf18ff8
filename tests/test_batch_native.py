"""The compiled sweep kernel equals ``vei run``: the same metric values for every variant of a sample
(collisions, near misses and clear passes), trajectories within 1e-9 m, and a sweep without a C
compiler falls back to the numpy batch engine with the same catalog."""

from __future__ import annotations

import numpy as np
import pytest

from vei_scenario.batch import BatchScenario
from vei_scenario.batch import native as native_mod
from vei_scenario.batch.native import NativeBatch
from vei_scenario.interpreter import run_scenario
from vei_scenario.metrics import PairSeries, compute_metrics


@pytest.fixture(scope="module")
def xosc(compiled):
    return next(p for p in compiled["case_study"].written if p.name == "scenario.xosc")


def _variants(n: int, seed: int) -> list[dict[str, str]]:
    rng = np.random.default_rng(seed)
    out = [
        {"TimeShift": "2.2", "RiderType": rt, "CapEnabled": cap}
        for rt in ("replay", "normal", "aggressive")
        for cap in ("false", "true")
    ]
    for s, rt, c, v in zip(
        rng.uniform(-3, 6, n),
        rng.choice(["replay", "normal", "aggressive"], n),
        rng.choice(["true", "false"], n),
        rng.uniform(3, 9, n),
    ):
        out.append(
            {
                "TimeShift": repr(round(float(s), 3)),
                "RiderType": str(rt),
                "CapEnabled": str(c),
                "EgoCruiseSpeed": repr(round(float(v), 2)),
            }
        )
    return out


def test_kernel_metrics_equal_vei_run_metrics(xosc):
    variants = _variants(34, 3)
    rows = NativeBatch(BatchScenario(xosc)).metrics(variants, threads=2)
    outcomes = set()
    for v, row in zip(variants, rows):
        single = compute_metrics(PairSeries.from_run(run_scenario(xosc, v)))
        assert row == single, (v, {k: (row[k], single[k]) for k in row if row[k] != single[k]})
        outcomes.add((row["collision"], row["near_miss"], row["pet_s"] is not None))
    assert len(outcomes) >= 3  # collisions, clear passes and defined PETs among the sample


def test_kernel_gap_metrics_match_the_python_definitions_unrounded(xosc):
    """The kernel measures the box gap in one box's frame with one square root (not corner by corner with
    hypot as models.boxes does): the raw values that depend on it stay within 1e-9 (relative) of the
    Python definitions, far below the 4 digits a row keeps (measured: 4e-12 over 10 000 variants)."""
    from vei_scenario.metrics.definitions import act_min_s, drac_max_mps2, min_gap_m
    from vei_scenario.metrics.series import MetricConfig

    variants = _variants(12, 5)
    nb = NativeBatch(BatchScenario(xosc))
    out, _ = nb.run(nb.prepare(variants), threads=1)
    cfg = MetricConfig()
    for i, v in enumerate(variants):
        p = PairSeries.from_run(run_scenario(xosc, v))
        for col, metric in ((2, min_gap_m), (10, act_min_s), (12, drac_max_mps2)):
            want = float(metric(p, cfg))
            if np.isfinite(want):
                assert out[i, col] == pytest.approx(want, rel=1e-9, abs=1e-12), (v, metric.__name__)
            else:
                assert not np.isfinite(out[i, col])


def test_sharing_between_variants_changes_no_output(xosc):
    """The kernel reuses motion between consecutive variants (the ego without the planner, a rider who
    does not react to the ego, the planner's ego before it first brakes): every output and recorded
    state equals the same variant run alone, bit for bit, whatever the order of the variants."""
    grid = [
        {"TimeShift": ts, "RiderType": rt, "CapEnabled": cap}
        for ts in ("-1.5", "0.4", "2.2")
        for rt in ("replay", "aggressive", "normal")
        for cap in ("true", "false")
    ]
    variants = grid + grid[::-1] + [{**g, "EgoCruiseSpeed": "6.5"} for g in grid[:6]]
    nb = NativeBatch(BatchScenario(xosc))
    out, traj = nb.run(nb.prepare(variants), threads=1, record=True)
    for i, v in enumerate(variants):
        alone, alone_traj = nb.run(nb.prepare([v]), threads=1, record=True)
        assert np.array_equal(out[i], alone[0], equal_nan=True), v
        assert np.array_equal(traj[i], alone_traj[0], equal_nan=True), v
    plain, _ = nb.run(nb.prepare(variants), threads=1)  # without recording: rows shared in place
    assert np.array_equal(plain, out, equal_nan=True)


def test_kernel_trajectories_equal_vei_run(xosc):
    variants = _variants(10, 4)
    nb = NativeBatch(BatchScenario(xosc))
    _, traj = nb.run(nb.prepare(variants), threads=2, record=True)
    for i, v in enumerate(variants):
        single = run_scenario(xosc, v)
        for k, name in enumerate(("Ego", "scooter_1")):
            tr = single.traces[name]
            assert traj.shape[2] == tr.x.size
            for q, arr in enumerate((tr.x, tr.y, tr.yaw, tr.speed, tr.accel)):
                np.testing.assert_allclose(traj[i, 5 * k + q], arr, rtol=0, atol=1e-9)


def test_without_a_compiler_sweeps_fall_back_to_numpy_with_the_same_rows(xosc, tmp_path, monkeypatch):
    from vei_scenario.sweep import evaluate

    variants = _variants(4, 5)
    compiled_rows = evaluate.evaluate_local(str(xosc), variants, 0.01, workers=2)
    monkeypatch.setattr(native_mod, "_LIB", [])
    monkeypatch.setattr(evaluate, "_NATIVE", {})
    monkeypatch.setenv("CC", str(tmp_path / "no-such-cc"))
    monkeypatch.setenv("VEI_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("VEI_KERNEL", "cache")  # as if installed from a wheel built without a compiler
    assert native_mod.load_kernel() is None
    assert evaluate._native_engine(str(xosc), 0.01) is None
    assert evaluate.evaluate_local(str(xosc), variants, 0.01, workers=1) == compiled_rows


def test_kernel_built_at_install_is_used_unless_its_sources_changed(xosc, tmp_path, monkeypatch):
    """pip install builds the kernel (setup.py); it is loaded while it matches the C sources shipped
    beside it, and gives the rows of the kernel compiled on demand. Edited sources are compiled anew."""
    from vei_scenario.core.sources import compiler

    try:
        compiler()
    except Exception:
        pytest.skip("no C compiler: the package was installed without its kernel")
    packaged = native_mod.packaged_kernel()
    assert packaged is not None and packaged.is_file(), "setup.py did not build vei_scenario.batch._kernel"
    monkeypatch.setattr(native_mod, "_LIB", [])
    assert native_mod.load_kernel()._name == str(packaged)
    variants = _variants(6, 7)
    rows = NativeBatch(BatchScenario(xosc)).metrics(variants)
    monkeypatch.setattr(native_mod, "_LIB", [])
    monkeypatch.setenv("VEI_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(native_mod, "source_digest", lambda src: "edited sources")
    lib = native_mod.load_kernel()
    assert lib is not None and lib._name != str(packaged) and str(tmp_path / "cache") in lib._name
    assert NativeBatch(BatchScenario(xosc)).metrics(variants) == rows
