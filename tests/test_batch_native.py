"""The sweep kernel equals ``vei run``: the same metric values for every variant of a sample (collisions,
near misses and clear passes), with one scooter or several, trajectories within 1e-9 m; scenarios of
another structure are left to the interpreter."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from vei_scenario.batch.native import NativeBatch
from vei_scenario.interpreter import run_scenario
from vei_scenario.loop import LoopScene, NotALoop
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
    rows = NativeBatch(LoopScene(xosc)).metrics(variants, threads=2)
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
    nb = NativeBatch(LoopScene(xosc))
    out, _ = nb.run(nb.prepare(variants), threads=1)
    cfg = MetricConfig()
    for i, v in enumerate(variants):
        p = PairSeries.from_run(run_scenario(xosc, v))
        for metric in (min_gap_m, act_min_s, drac_max_mps2):
            col = nb.lib.columns[metric.__name__]  # (the kernel's own list of its outputs, by name)
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
    nb = NativeBatch(LoopScene(xosc))
    out, traj = nb.run(nb.prepare(variants), threads=1, record=True)
    for i, v in enumerate(variants):
        alone, alone_traj = nb.run(nb.prepare([v]), threads=1, record=True)
        assert np.array_equal(out[i], alone[0], equal_nan=True), v
        assert np.array_equal(traj[i], alone_traj[0], equal_nan=True), v
    plain, _ = nb.run(nb.prepare(variants), threads=1)  # without recording: rows shared in place
    assert np.array_equal(plain, out, equal_nan=True)


def test_kernel_trajectories_equal_vei_run(xosc):
    variants = _variants(10, 4)
    nb = NativeBatch(LoopScene(xosc))
    _, traj = nb.run(nb.prepare(variants), threads=2, record=True)
    for i, v in enumerate(variants):
        single = run_scenario(xosc, v)
        for k, name in enumerate(("Ego", "scooter_1")):
            tr = single.traces[name]
            assert traj.shape[2] == tr.x.size
            for q, arr in enumerate((tr.x, tr.y, tr.yaw, tr.speed, tr.accel)):
                np.testing.assert_allclose(traj[i, 5 * k + q], arr, rtol=0, atol=1e-9)


def test_a_loop_with_more_road_users_runs_in_the_kernel_with_vei_runs_rows(compiled):
    """The multi-scooter clip: the planner's threat and two more scooters that only replay their tracks
    (they act on neither the ego nor the threat, and a row scores the pair)."""
    xosc = next(p for p in compiled["multi_scooter"].written if p.name == "scenario.xosc")
    scene = LoopScene(xosc)
    assert len(scene.names) > 2
    variants = [
        {"TimeShift": ts, "RiderType": rt, "CapEnabled": cap}
        for ts in ("-1", "0.5", "2")
        for rt in ("replay", "normal", "aggressive")
        for cap in ("true", "false")
    ]
    rows = NativeBatch(scene).metrics(variants, threads=2)
    for v, row in zip(variants, rows):
        assert row == compute_metrics(PairSeries.from_run(run_scenario(xosc, v))), v
    assert 0 < sum(r["collision"] for r in rows) < len(rows)


def test_other_structures_are_refused(compiled):
    from vei_scenario.sweep.evaluate import _native_engine

    with pytest.raises(NotALoop, match="no CollisionAvoidancePlanner"):  # (known from its text alone)
        LoopScene(Path(__file__).parent / "data" / "following_brake.xosc")
    # a planner that also watches another scooter: that one would act on the ego
    xosc = next(p for p in compiled["multi_scooter"].written if p.name == "scenario.xosc")
    scene = LoopScene(xosc)
    other = next(n for n in scene.names if n not in (scene.ego, scene.threat))
    watch = f'<Property name="watchEntities" value="{other}"/><Property name="threatEntity"'
    watched = xosc.parent / "watched.xosc"  # (beside its road network)
    watched.write_text(xosc.read_text().replace('<Property name="threatEntity"', watch, 1))
    try:
        with pytest.raises(NotALoop, match="watch the threat alone"):
            LoopScene(watched)
        assert _native_engine(str(watched), 0.01) is None  # its sweep runs the interpreter
    finally:
        watched.unlink()


def test_the_text_probe_refuses_only_files_that_cannot_hold_the_loop(tmp_path):
    from vei_scenario.loop.scene import _cannot_be_a_loop

    def probe(text: str) -> bool:
        f = tmp_path / "s.xosc"
        f.write_text(text)
        return _cannot_be_a_loop(f)

    both = (
        '<Controller name="CollisionAvoidancePlanner"/><Controller name="x"><Properties>'
        '<Property name="esminiController" value="SocialForceModel"/></Properties></Controller>'
    )
    assert not probe(both)  # (a kind named by esminiController counts as by the name)
    assert not probe(
        '<ParameterDeclaration name="k" value="SocialForceModel"/><Controller name="$k"/>'
        '<Controller name="CollisionAvoidancePlanner"/>'
    )
    assert probe('<Controller name="SocialForceModel"/>')  # the planner is missing
    assert probe('<Controller name="ACCController"/>')
    # controllers from a catalog: only the full reading can tell
    assert not probe('<ControllerCatalog><Directory path="c"/></ControllerCatalog>')
    assert not _cannot_be_a_loop(tmp_path / "missing.xosc")  # (the full reading says what is wrong)


def test_an_ego_that_runs_out_of_its_path_stands_at_its_end_in_both(xosc):
    """A recorded path ends where the recording did: an ego faster than the recorded one reaches its
    end within the run and stands there, speed and acceleration 0 (a held position at a kept speed
    would count as moving), in the kernel as in vei run."""
    variants = [
        {"TimeShift": "-3", "RiderType": rt, "CapEnabled": cap, "EgoCruiseSpeed": "12"}
        for rt in ("replay", "aggressive")
        for cap in ("true", "false")
    ]
    nb = NativeBatch(LoopScene(xosc))
    _, traj = nb.run(nb.prepare(variants), threads=1, record=True)
    for i, v in enumerate(variants):
        tr = run_scenario(xosc, v).traces["Ego"]
        moved = np.hypot(np.diff(tr.x), np.diff(tr.y))
        end = int(np.argmax(moved == 0.0)) + 1  # (the first step that leaves it where it was)
        assert moved[end - 1] == 0.0 and np.all(moved[end - 1 :] == 0.0), v  # it stands from there on
        assert np.all(tr.speed[end - 1 :] == 0.0) and np.all(tr.accel[end - 1 :] == 0.0), v
        assert tr.speed[end - 3] > 11.0, v  # (it ran there at its cruise speed)
        for q, arr in enumerate((tr.x, tr.y, tr.yaw, tr.speed, tr.accel)):
            np.testing.assert_allclose(traj[i, q], arr, rtol=0, atol=1e-9, err_msg=str((v, q)))
