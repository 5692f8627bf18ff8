"""Where the map comes from: the clip's map.osm, --osm, --no-map, or --osm-fetch (online)."""

from __future__ import annotations

import shutil
import sys
import types

import pytest

from conftest import EXAMPLES
from vei_scenario.cli import main
from vei_scenario.compiler import CompileOptions, compile_clip

CLIP = EXAMPLES / "case_study" / "clip.json"
MAP = EXAMPLES / "maps" / "helsinki_center.osm"


def test_no_map_fits_a_road_even_when_the_clip_has_one(tmp_path):
    result = compile_clip(CLIP, tmp_path / "s.xosc", CompileOptions(no_map=True))
    assert result.road_source == "fitted" and result.ego_on_lanes == 1.0


def test_osm_option_overrides_the_clip_map(tmp_path):
    other = tmp_path / "copy.osm"
    shutil.copy(MAP, other)
    result = compile_clip(CLIP, tmp_path / "s.xosc", CompileOptions(osm=other))
    assert result.road_source == "osm:copy.osm" and result.ego_on_lanes >= 0.95


def _fake_osmnx(monkeypatch, download):
    """Stand-in for osmnx: the tests never touch the network."""
    calls = []

    def graph_from_bbox(bbox, network_type, simplify):
        calls.append(bbox)
        return download(bbox)

    def save_graph_xml(graph, filepath):
        shutil.copy(graph, filepath)

    fake = types.ModuleType("osmnx")
    fake.settings = types.SimpleNamespace(all_oneway=False)
    fake.graph_from_bbox = graph_from_bbox
    fake.io = types.SimpleNamespace(save_graph_xml=save_graph_xml)
    monkeypatch.setitem(sys.modules, "osmnx", fake)
    return calls


def test_osm_fetch_downloads_the_scene_box_and_uses_it(tmp_path, monkeypatch):
    calls = _fake_osmnx(monkeypatch, lambda bbox: MAP)
    result = compile_clip(CLIP, tmp_path / "s.xosc", CompileOptions(osm_fetch=True))
    west, south, east, north = calls[0]
    # The box (west, south, east, north) surrounds the Annankatu × Bulevardi crossing.
    assert west < 24.939421 < east and south < 60.1650799 < north
    assert result.road_source == "osm:map.osm" and (tmp_path / "map.osm").is_file()


def test_osm_fetch_without_network_is_a_clear_error(tmp_path, monkeypatch, capsys):
    def offline(bbox):
        raise ConnectionError("Max retries exceeded with url: /api/interpreter")

    _fake_osmnx(monkeypatch, offline)
    code = main(["compile", str(CLIP), "-o", str(tmp_path / "o" / "s.xosc"), "--osm-fetch"])
    err = capsys.readouterr().err
    assert code == 2 and "--osm-fetch: could not download OpenStreetMap data" in err
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("version", ["2.0", "1.4", "one"])
def test_unknown_osc_version_is_a_usage_error(tmp_path, version, capsys):
    try:
        code = main(["compile", str(CLIP), "-o", str(tmp_path / "s.xosc"), "--osc-version", version])
    except SystemExit as exc:  # rejected by the argument parser
        code = exc.code
    assert code == 2
    assert "--osc-version" in capsys.readouterr().err
    assert not (tmp_path / "s.xosc").exists()
