"""Road networks: the ego lies on the lanes, one metric frame with the scenario, exact geometry."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from lxml import etree

from conftest import EXAMPLE_NAMES, EXAMPLES
from vei_scenario.roads.opendrive_lanes import read_lane_areas, share_on_lanes
from vei_scenario.roads.opendrive_repair import parampoly3_arc_length
from vei_scenario.roads.osm_region import crop_osm


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_ego_track_lies_on_driving_lanes(compiled, name):
    result = compiled[name]
    assert result.ego_on_lanes >= 0.95
    # Independently of the compiler's own figure: re-read the written file.
    xodr = next(p for p in result.written if p.suffix == ".xodr")
    rec = result.reconstruction
    assert share_on_lanes(read_lane_areas(xodr), rec.ego.x, rec.ego.y) >= 0.95


def test_opendrive_shares_the_scenario_frame(compiled):
    """The OSM node where Annankatu meets Bulevardi, projected with the scenario's projection, lies on
    a lane of the netconvert road network: both files use one metric frame."""
    result = compiled["case_study"]
    xodr = next(p for p in result.written if p.suffix == ".xodr")
    header = etree.parse(str(xodr)).getroot().find("header")
    assert header.find("geoReference").text.strip() == result.model.proj_string
    x, y = result.reconstruction.projection.forward(60.1650799, 24.939421)
    surface = shapely.union_all([a.polygon for a in read_lane_areas(xodr)])
    assert surface.distance(shapely.Point(float(x), float(y))) < 0.5


def test_fitted_road_is_continuous_and_centres_the_ego_in_the_right_lane(compiled):
    result = compiled["no_map"]
    xodr = next(p for p in result.written if p.suffix == ".xodr")
    root = etree.parse(str(xodr)).getroot()
    assert result.road_source == "fitted" and len(root.findall("road")) == 1
    areas = read_lane_areas(xodr)
    right = next(a for a in areas if a.lane_id == -1).polygon
    left = next(a for a in areas if a.lane_id == 1).polygon
    rec = result.reconstruction
    pts = shapely.points(rec.ego.x, rec.ego.y)
    assert shapely.contains(right, pts).all() and not shapely.contains(left, pts).any()
    # Geometry pieces join without gaps: each piece's end is the next one's start.
    geoms = root.findall("road/planView/geometry")
    for g0, g1 in zip(geoms, geoms[1:]):
        p = g0.find("paramPoly3")
        c = {k: float(p.get(k)) for k in ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV")}
        u, v = c["aU"] + c["bU"] + c["cU"] + c["dU"], c["aV"] + c["bV"] + c["cV"] + c["dV"]
        h = float(g0.get("hdg"))
        x1 = float(g0.get("x")) + np.cos(h) * u - np.sin(h) * v
        y1 = float(g0.get("y")) + np.sin(h) * u + np.cos(h) * v
        assert np.hypot(x1 - float(g1.get("x")), y1 - float(g1.get("y"))) < 1e-6
        assert float(g1.get("s")) == pytest.approx(float(g0.get("s")) + float(g0.get("length")), abs=1e-6)


def test_parampoly3_lengths_equal_the_arc_length(compiled):
    """netconvert writes lengths off by centimetres; the written file must carry the true arc length
    (checked here by a dense polyline, independent of the quadrature used to repair them)."""
    xodr = next(p for p in compiled["case_study"].written if p.suffix == ".xodr")
    worst = 0.0
    for pp in etree.parse(str(xodr)).getroot().iter("paramPoly3"):
        c = {k: float(pp.get(k)) for k in ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV")}
        p = np.linspace(0, 1, 200_001)
        u = c["aU"] + c["bU"] * p + c["cU"] * p**2 + c["dU"] * p**3
        v = c["aV"] + c["bV"] * p + c["cV"] * p**2 + c["dV"] * p**3
        dense = np.hypot(np.diff(u), np.diff(v)).sum()
        worst = max(worst, abs(dense - float(pp.getparent().get("length"))))
        assert parampoly3_arc_length(pp) == pytest.approx(dense, abs=1e-6)
    assert worst < 1e-6


def test_crop_keeps_whole_highways_touching_the_box():
    box = (60.1648, 24.9390, 60.1653, 24.9398)  # a few metres around the Annankatu × Bulevardi node
    region = crop_osm(EXAMPLES / "maps" / "helsinki_center.osm", box)
    root = etree.fromstring(region.xml)
    names = {t.get("v") for t in root.iter("tag") if t.get("k") == "name"}
    assert {"Annankatu", "Bulevardi"} <= names
    nodes = {n.get("id") for n in root.iter("node")}
    assert all(nd.get("ref") in nodes for nd in root.iter("nd"))  # every kept way is complete
    assert all(any(t.get("k") == "highway" for t in w.iter("tag")) for w in root.iter("way"))
