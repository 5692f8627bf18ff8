"""vei compile CLIPS/ -o LIBRARY/: every clip compiled (bad ones are rows with their reason), ranked
by closeness to a collision, resumable, the same bytes on any executor."""

from __future__ import annotations

import importlib.util
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from test_generate_dataset import load_dataset_generator

from vei_scenario.library import compile_library
from vei_scenario.library.rows import closeness_key
from vei_scenario.openscenario.validation import validate_files

N_GOOD = 3


def _bad_clips(clips: Path) -> dict[str, str]:
    """Bad clips beside the good ones, and a word their row's reason must have."""
    good = json.loads(sorted(clips.glob("*.json"))[0].read_text())
    (clips / "zz_malformed.json").write_text('{"format": "vei-clip/1", "id": ')
    (clips / "zz_deep.json").write_text("[" * 50_000 + "]" * 50_000)
    (clips / "zz_dup.json").write_text(json.dumps(good))  # the same id as the first clip
    none = json.loads(json.dumps(good))
    none["id"] = "no-scooter"
    for f in none["annotations"]["frames"]:
        for o in f["objects"]:
            o["category"] = "pedestrian"
    (clips / "zz_none.json").write_text(json.dumps(none))
    hostile = json.loads(json.dumps(good))
    hostile["id"] = "hostile"
    hostile["map"] = {"osm": "/dev/zero"}
    (clips / "zz_hostile.json").write_text(json.dumps(hostile))
    (clips / "notes.txt").write_text("not a clip")  # (not *.json: not read)
    return {
        "zz_malformed.json": "invalid JSON",
        "zz_deep.json": "nested too deeply",
        "zz_dup.json": "duplicate clip id",
        "zz_none.json": "no e-scooter",
        "zz_hostile.json": "map",
    }


@pytest.fixture(scope="module")
def dataset(tmp_path_factory) -> tuple[Path, dict[str, str]]:
    root = tmp_path_factory.mktemp("dataset")
    load_dataset_generator().write_clips(root, N_GOOD, seed=11)
    return root / "clips", _bad_clips(root / "clips")


@pytest.fixture(scope="module")
def library(dataset, tmp_path_factory):
    clips, _ = dataset
    out = tmp_path_factory.mktemp("lib") / "library"
    r = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "compile", str(clips), "-o", str(out), "--workers", "2"],
        capture_output=True,
        text=True,
    )
    return out, r


def _tree(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_bad_clips_are_rows_with_their_reason_and_the_rest_compile(dataset, library):
    clips, bad = dataset
    out, run = library
    assert run.returncode == 1
    assert f"{len(bad)} of {N_GOOD + len(bad)} clips could not be compiled" in run.stderr
    assert run.stderr.count("\n") == 1 and "Traceback" not in run.stderr
    doc = json.loads((out / "library.json").read_text())
    rows = {r["file"]: r for r in doc["scenarios"]}
    assert set(rows) == {p.name for p in clips.glob("*.json")}
    for name, word in bad.items():
        assert rows[name]["status"] == "error" and word in rows[name]["error"], rows[name]
        assert rows[name]["error"].startswith(name)  # (named by file, one line)
    ok = [r for r in doc["scenarios"] if r["status"] == "ok"]
    assert len(ok) == N_GOOD == doc["compiled"] and doc["failed"] == len(bad)
    files = []
    for r in ok:
        for f in r["outputs"].values():
            assert (out / f).is_file()
        files += [out / r["outputs"]["scenario"], out / r["outputs"]["road"], out / r["outputs"]["variations"]]
    assert validate_files(files) == []
    html = (out / "library.html").read_text()
    assert all(r["outputs"]["thumbnail"] in html for r in ok) and "duplicate clip id" in html


def test_ranked_by_closeness_to_a_collision(library):
    out, _ = library
    rows = json.loads((out / "library.json").read_text())["scenarios"]
    assert rows == sorted(rows, key=closeness_key)
    ok = [r for r in rows if r["status"] == "ok"]
    assert [r["rank"] for r in ok] == list(range(1, len(ok) + 1))
    for r in ok:  # the margin is the distance of TimeShift 0 from the collision interval
        lo, hi = r["collision_shifts_s"]
        assert r["collision_margin_s"] == pytest.approx(0.0 if lo <= 0 <= hi else min(abs(lo), abs(hi)), abs=1e-3)


def test_a_second_run_compiles_only_what_changed(dataset, library, tmp_path):
    clips, _ = dataset
    out, _ = library
    lib = tmp_path / "library"
    shutil.copytree(out, lib)
    before = _tree(lib)
    again = compile_library(clips, lib)
    assert again.compiled == 0 and again.kept == N_GOOD + 2  # (no-scooter, hostile failed in compiling: kept)
    assert _tree(lib) == before
    # one clip changed: only it is compiled again
    shutil.copytree(clips.parent, tmp_path / "dataset")  # (with the map the clips refer to)
    work = tmp_path / "dataset" / "clips"
    first = sorted(work.glob("gen-*.json"))[0]
    doc = json.loads(first.read_text())
    doc["ego"]["width_m"] = 2.0
    first.write_text(json.dumps(doc))
    third = compile_library(work, lib)
    assert third.compiled == 1 and third.kept == N_GOOD + 1


def test_same_bytes_with_one_worker_and_on_dask(dataset, library, tmp_path):
    if importlib.util.find_spec("distributed") is None:  # (not imported here: see below)
        pytest.skip("dask.distributed not installed (pip install 'vei-scenario[dask]')")
    clips, _ = dataset
    out, _ = library
    one = compile_library(clips, tmp_path / "one", workers=1)
    assert one.compiled == N_GOOD + 2
    # (in its own process: distributed changes how this one pickles exceptions, which other tests see)
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "vei_scenario",
            "compile",
            str(clips),
            "-o",
            str(tmp_path / "dask"),
            "--executor",
            "dask",
        ],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 1 and f"{N_GOOD + 2} tried in this run" in run.stdout, run.stderr
    assert _tree(tmp_path / "one") == _tree(out) == _tree(tmp_path / "dask")


def test_folder_options_refused_in_one_line(dataset, tmp_path):
    clips, _ = dataset
    for args in (
        [str(clips), "-o", str(tmp_path / "x"), "--threat", "scooter_1"],
        [str(clips), "-o", str(clips / "lib")],
        [str(sorted(clips.glob("gen-*.json"))[0]), "-o", str(tmp_path / "s.xosc"), "--executor", "dask"],
        [str(tmp_path), "-o", str(tmp_path / "y")],
    ):
        r = subprocess.run([sys.executable, "-m", "vei_scenario", "compile", *args], capture_output=True, text=True)
        assert r.returncode == 2 and r.stderr.count("\n") == 1 and "Traceback" not in r.stderr, r.stderr
