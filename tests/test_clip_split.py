"""vei clip split: a long recording cut into interaction clips, checked against the generator's truth
(examples/generate_dataset.py) and against hand-made drives whose answer is known."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest
from pyproj import Geod
from test_generate_dataset import load_dataset_generator

from vei_scenario.cli import main
from vei_scenario.clip import load_clip
from vei_scenario.library.split import SplitOptions, find_interactions, load_drive, split_drive

GEOD = Geod(ellps="WGS84")
LAT0, LON0 = 60.1650799, 24.939421
T0 = 1_700_000_000.0


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    """Two generated drives (seeds 5 and 6, GPS noise on): 5 min with 4 encounters each."""
    gen = load_dataset_generator()
    out = {}
    for seed in (5, 6):
        d = tmp_path_factory.mktemp(f"drive{seed}")
        out[seed] = (gen.write_drive(d, minutes=5.0, encounters=4, seed=seed), d)
    return out


def _provenance(path: Path) -> dict:
    return json.loads(path.read_text())["extensions"]["vei_split"]


@pytest.mark.parametrize("seed", [5, 6])
def test_every_encounter_is_one_clip_and_every_clip_one_encounter(generated, tmp_path, seed):
    drive, folder = generated[seed]
    truth = json.loads((folder / "drive_truth.json").read_text())
    result = split_drive(drive, tmp_path / "clips")
    clips = [_provenance(p) for p in result.written]
    assert len(clips) == len(truth["encounters"]) == 4
    beside = {b["track_id"] for b in truth["beside"]}
    assert beside  # (the drive has road users beside the path, which must give no clip)
    for enc in truth["encounters"]:
        holding = [
            c
            for c in clips
            if c["t_gps"][0] <= enc["t_gps_rider_at_crossing"] <= c["t_gps"][1]
            and c["t_gps"][0] <= enc["t_gps_ego_at_crossing"] <= c["t_gps"][1]
        ]
        assert len(holding) == 1, enc
        assert holding[0]["tracks"] == [enc["track_id"]]
    for c in clips:
        assert not set(c["tracks"]) & beside


def test_clips_are_valid_compilable_and_say_where_they_came_from(generated, tmp_path):
    from vei_scenario.compiler import compile_clip

    drive, folder = generated[5]
    out = tmp_path / "clips"
    result = split_drive(drive, out)
    src = load_drive(drive)[0]
    for path, part in zip(result.written, result.interactions):
        clip = load_clip(path)
        prov = clip.extensions["vei_split"]
        assert prov["source"] == "drive.json" and prov["source_id"] == src.id
        assert len(prov["source_sha256"]) == 64
        assert prov["t_gps"] == [round(part.t_start, 6), round(part.t_end, 6)]
        assert prov["t_from_source_start_s"][0] == pytest.approx(part.t_start - src.ego.t[0])
        assert clip.ego.t[0] <= part.t_start and clip.ego.t[-1] >= part.t_end
        assert part.t_end - part.t_start >= SplitOptions().min_length_s
        assert clip.osm_path == src.osm_path  # (re-anchored: relative to the new place)
    r = compile_clip(result.written[0], tmp_path / "s" / "scenario.xosc")
    assert r.model.threat == result.interactions[0].tracks[0]


def test_same_drive_same_bytes(generated, tmp_path):
    drive, _ = generated[6]
    a = split_drive(drive, tmp_path / "a").written
    b = split_drive(drive, tmp_path / "b").written
    assert [p.name for p in a] == [p.name for p in b]
    assert [p.read_bytes() for p in a] == [p.read_bytes() for p in b]


def test_openlabel_drive_gives_the_same_interactions(tmp_path):
    drive = load_dataset_generator().write_drive(tmp_path, minutes=1.5, encounters=2, seed=8)
    ol = tmp_path / "drive.openlabel.json"
    assert main(["clip", "convert", str(drive), "-o", str(ol)]) == 0
    a = split_drive(drive, tmp_path / "a").interactions
    b = split_drive(ol, tmp_path / "b").interactions
    assert [p.tracks for p in a] == [p.tracks for p in b]
    for p, q in zip(a, b):
        assert q.t_start == pytest.approx(p.t_start, abs=1e-3) and q.t_end == pytest.approx(p.t_end, abs=1e-3)
    written = split_drive(drive, tmp_path / "c", to="openlabel").written  # (and OpenLABEL clips out)
    for path, part in zip(written, a):
        assert "openlabel" in json.loads(path.read_text())
        clip = load_clip(path)
        assert set(part.tracks) <= set(clip.annotations.tracks())


# --- hand-made drives: the ego east along a straight road at 10 m/s, riders crossing it northward ---


def _drive(
    tmp_path: Path, riders: list[tuple[str, str, float]], seconds: float = 80.0, name="hand", lead_s: float = 2.0
) -> Path:
    """The ego at 10 m/s due east from (LAT0, LON0); each rider ``(track, category, t_cross)`` rides
    north at 4 m/s across the ego's path where the ego is at ``t_cross + lead_s`` (that far ahead of it),
    annotated at 2 Hz while it is 2-70 m ahead within 55 degrees."""
    samples = []
    for i in range(int(seconds * 10) + 1):
        t = i / 10
        lon, lat, _ = GEOD.fwd(LON0, LAT0, 90.0, 10.0 * t)
        samples.append({"t": T0 + t, "lat": lat, "lon": lon, "heading_deg": 90.0, "speed_mps": 10.0})
    frames = []
    for k in range(int(seconds * 2)):
        t = 0.25 + k / 2
        objs = []
        for tid, cat, tc in riders:
            x = 10.0 * (tc + lead_s) - 10.0 * t
            y = 4.0 * (t - tc)
            if 2.0 < x < 70.0 and abs(math.degrees(math.atan2(y, x))) < 55.0:
                objs.append({"track_id": tid, "category": cat, "x_m": round(x, 3), "y_m": round(y, 3)})
        frames.append({"t": T0 + t, "objects": objs})
    doc = {
        "format": "vei-clip/1",
        "id": name,
        "ego": {"samples": samples},
        "annotations": {"y_axis": "left", "frames": frames},
    }
    path = tmp_path / f"{name}.json"
    path.write_text(json.dumps(doc))
    return path


def _spans(path: Path, **opts) -> list[tuple[tuple[str, ...], float, float]]:
    clip, _ = load_drive(path)
    return [(p.tracks, p.t_start - T0, p.t_end - T0) for p in find_interactions(clip, SplitOptions(**opts))]


def test_padding_and_the_near_rule(tmp_path):
    """A rider crossing the path at 20 s at 4 m/s, annotated at 2 Hz (19.25 s: 3 m right of it, 19.75 s:
    1 m, 20.25 s: 1 m left ...), the ego there at 22 s: within 3.5 m at 19.25..20.75 s; the lines to the
    observations before and after (5 m away) come within 3.5 m too, so its near times are
    18.75..21.25 s, and the ego passes at 22 s: the clip is 18.75..22 s, 6 s earlier and 3 s later.
    Within 0.5 m only the line from 19.75 to 20.25 s is near."""
    spans = _spans(_drive(tmp_path, [("s1", "e-scooter", 20.0)]))
    assert spans == [(("s1",), pytest.approx(12.75), pytest.approx(25.0))]
    spans = _spans(_drive(tmp_path, [("s1", "e-scooter", 20.0)]), near_m=0.5, pad_before_s=2, pad_after_s=1)
    assert spans == [(("s1",), pytest.approx(17.75), pytest.approx(23.0))]


def test_overlapping_interactions_merge_and_separate_ones_do_not(tmp_path):
    path = _drive(tmp_path, [("a", "e-scooter", 20.0), ("b", "scooter", 27.0), ("c", "e-scooter", 50.0)])
    assert [s[0] for s in _spans(path)] == [("a", "b"), ("c",)]
    assert [s[0] for s in _spans(path, pad_before_s=1, pad_after_s=1)] == [("a",), ("b",), ("c",)]
    assert [s[0] for s in _spans(path, pad_before_s=1, pad_after_s=1, merge_gap_s=30)] == [("a", "b", "c")]


def test_minimum_length_and_the_ends_of_the_recording(tmp_path):
    path = _drive(tmp_path, [("a", "e-scooter", 2.0), ("b", "e-scooter", 40.0)], seconds=50)
    spans = _spans(path, pad_before_s=0, pad_after_s=0, min_length_s=8)
    assert spans[0][1:] == (pytest.approx(0.0), pytest.approx(8.0))  # (widened forward from the start)
    assert spans[1][2] - spans[1][1] == pytest.approx(8.0)
    assert spans[1][1] < 40.0 < spans[1][2]


def test_categories_choose_who_counts(tmp_path):
    path = _drive(tmp_path, [("p", "pedestrian", 20.0), ("s", "e-scooter", 50.0)])
    assert [s[0] for s in _spans(path)] == [("s",)]
    assert [s[0] for s in _spans(path, categories=("Pedestrian", "e-scooter"))] == [("p",), ("s",)]


def test_a_rider_crossing_unseen_between_sparse_observations_counts(tmp_path):
    """Observed 6 m either side of the path and nowhere between: the line joining them crosses it."""
    path = _drive(tmp_path, [("s", "e-scooter", 20.0)], lead_s=4.0)
    doc = json.loads(path.read_text())
    for f in doc["annotations"]["frames"]:
        f["objects"] = [o for o in f["objects"] if abs(o["y_m"]) > 5.0]
    path.write_text(json.dumps(doc))
    assert [s[0] for s in _spans(path)] == [("s",)]
    assert _spans(path, max_gap_s=1.0) == []


def test_cli_writes_clips_and_refuses_bad_input_in_one_line(tmp_path):
    path = _drive(tmp_path, [("s", "e-scooter", 20.0)])
    r = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "clip", "split", str(path), "-o", str(tmp_path / "c")],
        capture_output=True,
        text=True,
    )
    assert r.returncode == 0, r.stderr
    assert "wrote" in r.stdout and "1 interaction(s)" in r.stdout
    assert (tmp_path / "c" / "hand.001.json").is_file()
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "vei-clip/1", "id": "x", "ego": {"samples": []}, "annotations": {"frames": []}}')
    for args in ([str(bad)], [str(path), "--near", "0"], [str(path), "--pad-after", "nan"]):
        r = subprocess.run(
            [sys.executable, "-m", "vei_scenario", "clip", "split", *args, "-o", str(tmp_path / "d")],
            capture_output=True,
            text=True,
        )
        assert r.returncode == 2 and r.stderr.count("\n") == 1 and "Traceback" not in r.stderr, r.stderr
    assert not (tmp_path / "d").exists()
