"""Bad input: one clear line naming file, field and reason; exit code 2; no output written."""

from __future__ import annotations

import copy
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import EXAMPLES
from vei_scenario.cli import main

CASE = json.loads((EXAMPLES / "case_study" / "clip.json").read_text())
MAP = EXAMPLES / "maps" / "helsinki_center.osm"


def run_compile(tmp_path: Path, clip_text: str, capsys, extra: list[str] | None = None) -> tuple[int, str, Path]:
    clip = tmp_path / "clip.json"
    clip.write_text(clip_text)
    out = tmp_path / "out"
    code = main(["compile", str(clip), "-o", str(out / "scenario.xosc"), *(extra or [])])
    err = capsys.readouterr().err
    return code, err, out


def with_map(doc: dict) -> dict:
    doc = copy.deepcopy(doc)
    doc["map"] = {"osm": str(MAP)}
    return doc


def mutate(fn) -> str:
    doc = with_map(CASE)
    fn(doc)
    return json.dumps(doc)


def first_frame_with_scooter(doc: dict) -> int:
    return next(i for i, f in enumerate(doc["annotations"]["frames"]) if f["objects"])


CASES = {
    "truncated": (json.dumps(with_map(CASE))[:5000], ["invalid JSON", "line 1 column"]),
    "wrong_type": (
        mutate(lambda d: d["ego"]["samples"][3].__setitem__("lat", "60.1")),
        ["ego.samples[3].lat", "not of type 'number'"],
    ),
    "nan": (
        json.dumps(with_map(CASE), indent=1).replace('"speed_mps": 5.', '"speed_mps": NaN, "x": 5.', 1),
        ["NaN is not a number JSON allows", "line 1"],
    ),
    "infinity": (
        mutate(lambda d: d["ego"]["samples"][2].__setitem__("lon", 0.5)).replace("0.5", "1e400", 1),
        ["ego.samples[2].lon"],
    ),
    "latitude_range": (mutate(lambda d: d["ego"]["samples"][5].__setitem__("lat", 91.0)), ["ego.samples[5].lat", "91"]),
    "time_decreasing": (
        mutate(lambda d: d["ego"]["samples"][10].__setitem__("t", d["ego"]["samples"][8]["t"])),
        ["ego.samples[10].t", "strictly increasing"],
    ),
    "time_duplicate": (
        mutate(lambda d: d["ego"]["samples"][10].__setitem__("t", d["ego"]["samples"][9]["t"])),
        ["ego.samples[10].t", "duplicate"],
    ),
    "annotation_outside_span": (
        mutate(lambda d: d["annotations"].__setitem__("time_offset_s", 100.0)),
        ["annotations.frames[0].t", "outside the ego GPS span"],
    ),
    "single_observation_track": (
        mutate(
            lambda d: [
                f.__setitem__("objects", []) for f in d["annotations"]["frames"][first_frame_with_scooter(d) + 1 :]
            ]
        ),
        ["track 'scooter_1' has 1 observation"],
    ),
    "no_scooter": (
        mutate(lambda d: [f.__setitem__("objects", []) for f in d["annotations"]["frames"]]),
        ["no e-scooter track"],
    ),
    "gps_outlier": (  # (a fix whose longitude lost its sign: the other side of the globe)
        mutate(lambda d: d["ego"]["samples"][40].__setitem__("lon", -d["ego"]["samples"][40]["lon"])),
        ["ego.samples[40]", "no road vehicle moves so"],
    ),
    "lat_lon_swapped": (
        mutate(
            lambda d: d["ego"]["samples"][7].update(
                lat=d["ego"]["samples"][7]["lon"], lon=d["ego"]["samples"][7]["lat"]
            )
        ),
        ["ego.samples[7]", "m from the one before"],
    ),
    "clip_spans_decades": (  # (a first fix on another clock: 0 where the rest are UNIX times)
        mutate(lambda d: d["ego"]["samples"][0].__setitem__("t", 90.0)),
        ["ego.samples[1].t", "a clip spans at most 3600 s"],
    ),
    "extra_field": (mutate(lambda d: d["ego"].__setitem__("colour", "red")), ["ego", "'colour'", "extensions"]),
    "wrong_format": (mutate(lambda d: d.__setitem__("format", "vei-clip/2")), ["format", "vei-clip/1"]),
    "empty_samples": (mutate(lambda d: d["ego"].__setitem__("samples", [])), ["ego.samples"]),
    "missing_osm": (
        mutate(lambda d: d["map"].__setitem__("osm", "nowhere.osm")),
        ["nowhere.osm", "map file not found"],
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_clip_gives_one_line_and_exit_2(tmp_path, capsys, case):
    text, expected = CASES[case]
    code, err, out = run_compile(tmp_path, text, capsys)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("vei: error: "), err
    assert "Traceback" not in err
    if case != "missing_osm":
        assert "clip.json" in lines[0]
    for fragment in expected:
        assert fragment in lines[0], lines[0]
    assert not out.exists() or not any(out.iterdir()), "no output may be written"


def test_a_fix_off_by_gps_error_still_compiles(tmp_path, capsys):
    """A fix 30 m off (multipath) is GPS as recorded, not an outlier to refuse: only jumps no road vehicle
    makes are (100 m/s, the schema's top speed, plus 50 m)."""
    doc = with_map(CASE)
    fix = doc["ego"]["samples"][40]
    fix["lat"] += 30.0 / 111_195.0  # (30 m north)
    code, err, out = run_compile(tmp_path, json.dumps(doc), capsys)
    assert code == 0, err
    assert (out / "scenario.xosc").is_file()


def test_an_e_scooter_seen_once_beside_the_threat_is_skipped_with_a_note(tmp_path, capsys):
    """Only a clip whose every e-scooter is seen once is refused; a second rider glimpsed in one frame
    has no trajectory, so it is left out and the compile says so (the threat still has its path)."""
    doc = with_map(CASE)
    frame = doc["annotations"]["frames"][first_frame_with_scooter(doc) + 3]
    frame["objects"].append({"track_id": "glimpsed", "category": "e-scooter", "x_m": 25.0, "y_m": -6.0})
    (tmp_path / "clip.json").write_text(json.dumps(doc))
    code = main(["compile", str(tmp_path / "clip.json"), "-o", str(tmp_path / "out" / "scenario.xosc")])
    printed = capsys.readouterr()
    assert code == 0, printed.err
    assert "track glimpsed: category 'e-scooter' observed once" in printed.out
    xosc = (tmp_path / "out" / "scenario.xosc").read_text()
    assert "scooter_1" in xosc and "glimpsed" not in xosc


def test_missing_clip_file(tmp_path, capsys):
    code = main(["compile", str(tmp_path / "absent.json"), "-o", str(tmp_path / "o" / "s.xosc")])
    err = capsys.readouterr().err
    assert code == 2 and "absent.json: file not found" in err


@pytest.mark.parametrize(
    "osm_text, expected",
    [
        ("<osm><node id='1' lat='60.1' lon='24.9'/><way id='2'>", "malformed OSM XML"),
        ("<notosm/>", "expected <osm>"),
        ("<osm><node id='1' lat='north' lon='24.9'/></osm>", "lat='north' is not a number"),
        ("<osm><node id='1' lat='10.0' lon='10.0'/></osm>", "no OSM highway within the scenario's region"),
    ],
)
def test_bad_osm_file(tmp_path, capsys, osm_text, expected):
    (tmp_path / "bad.osm").write_text(osm_text)
    doc = copy.deepcopy(CASE)
    doc["map"] = {"osm": "bad.osm"}
    code, err, out = run_compile(tmp_path, json.dumps(doc), capsys)
    assert code == 2 and "bad.osm" in err and expected in err, err
    assert not out.exists()


def test_hostile_osm_entities_are_not_expanded(tmp_path, capsys):
    bomb = (
        '<?xml version="1.0"?><!DOCTYPE osm [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">'
        '<!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;"><!ENTITY x SYSTEM "file:///etc/passwd">]>'
        '<osm><node id="1" lat="60.1" lon="24.9"><tag k="name" v="&c;&x;"/></node></osm>'
    )
    (tmp_path / "bomb.osm").write_text(bomb)
    doc = copy.deepcopy(CASE)
    doc["map"] = {"osm": "bomb.osm"}
    code, err, _ = run_compile(tmp_path, json.dumps(doc), capsys)
    assert code == 2 and "bomb.osm" in err
    assert "root:" not in err  # /etc/passwd never read


def test_netconvert_missing(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("VEI_NETCONVERT", str(tmp_path / "no-netconvert"))
    code, err, out = run_compile(tmp_path, json.dumps(with_map(CASE)), capsys)
    assert code == 2 and "VEI_NETCONVERT" in err and "not an executable" in err
    assert not out.exists()


def test_netconvert_failing(tmp_path, capsys, monkeypatch):
    fake = tmp_path / "netconvert"
    fake.write_text("#!/bin/sh\necho 'Error: Could not open the network' >&2\nexit 1\n")
    fake.chmod(0o755)
    monkeypatch.setenv("VEI_NETCONVERT", str(fake))
    code, err, out = run_compile(tmp_path, json.dumps(with_map(CASE)), capsys)
    assert code == 2
    assert "helsinki_center.osm: netconvert: failed: Error: Could not open the network" in err
    assert not out.exists()


def test_bad_options(tmp_path, capsys):
    code, err, _ = run_compile(tmp_path, json.dumps(with_map(CASE)), capsys, ["--threat", "scooter_9"])
    assert code == 2 and "--threat" in err and "scooter_1" in err
    code, err, _ = run_compile(tmp_path, json.dumps(with_map(CASE)), capsys, ["--rate", "0"])
    assert code == 2 and "--rate" in err


def test_console_script_prints_no_traceback(tmp_path):
    clip = tmp_path / "clip.json"
    clip.write_text('{"format": "vei-clip/1", "id": "x", "ego": ')
    proc = subprocess.run(
        [sys.executable, "-m", "vei_scenario.cli", "compile", str(clip), "-o", str(tmp_path / "o.xosc")],
        capture_output=True,
        text=True,
        env={**os.environ},
    )
    assert proc.returncode == 2
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr
    assert f"{clip}: line 1 column" in proc.stderr


@pytest.mark.parametrize("key, value", [("lanes", "99999"), ("lanes:backward", "1e9"), ("lanes:forward", "inf")])
def test_a_way_with_more_lanes_than_a_road_has_is_refused_before_netconvert(tmp_path, capsys, key, value):
    """netconvert builds what it is told: 99 999 lanes took it past its 120 s limit. The count is
    refused in the OSM file, naming the way and its line."""
    from lxml import etree

    tree = etree.parse(str(MAP))
    highways = [w for w in tree.getroot().iter("way") if any(t.get("k") == "highway" for t in w.iter("tag"))]
    for way in highways:
        etree.SubElement(way, "tag", k=key, v=value)
    osm = tmp_path / "map.osm"
    tree.write(str(osm))
    code, err, out = run_compile(tmp_path, json.dumps(CASE), capsys, ["--osm", str(osm)])
    assert code == 2 and err.count("\n") == 1, err
    named = re.search(r"map\.osm: line \d+: way (\d+): ", err)
    assert named and named.group(1) in {w.get("id") for w in highways}, err
    assert f"{key}={value!r}: more lanes than a road has" in err, err
    assert not out.exists() or not any(out.iterdir())
