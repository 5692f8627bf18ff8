"""Other authors' scenarios, broken: esmini's examples and the Euro NCAP pack with an element removed,
an attribute dropped or a value no reader expects. Each plays or is refused in one line naming the
file and the line, whatever was broken (a mutation search over them found the cases below; the last
test keeps searching with Hypothesis)."""

from __future__ import annotations

import copy
import math
from pathlib import Path

import pytest
from lxml import etree

from conftest import NO_SHARED, SHARED
from vei_scenario.errors import VeiError, VeiInputError
from vei_scenario.interpreter import run_scenario

ESMINI_XOSC = SHARED / "esmini" / "xosc"
NCAP = SHARED / "osc-ncap" / "OpenSCENARIO" / "NCAP"


def _source(name: str) -> Path:
    path = (NCAP if "/" in name else ESMINI_XOSC) / name
    if not path.is_file():
        pytest.skip(f"{path.name} not found ({NO_SHARED})")
    return path


def _absolute(tree, source: Path) -> None:
    """Point the copy's road and catalog paths at the original's files (the copy lives elsewhere)."""
    for el in tree.getroot().iter("LogicFile", "Directory"):
        if el.get("filepath"):
            el.set("filepath", str((source.parent / el.get("filepath")).resolve()))
        if el.get("path"):
            el.set("path", str((source.parent / el.get("path")).resolve()))


def _broken(tmp_path: Path, name: str, change) -> Path:
    source = _source(name)
    tree = etree.parse(str(source))
    _absolute(tree, source)
    change(tree.getroot())
    out = tmp_path / f"broken_{source.name}"
    tree.write(str(out))
    return out


def _refusal(path: Path, named: Path | None = None) -> str:
    """The one-line refusal of ``path``, naming ``named`` (default: ``path``) and a line."""
    with pytest.raises(VeiInputError) as info:
        run_scenario(path, max_time_s=5.0, dt=0.05)
    text = str(info.value)
    assert "\n" not in text and text.startswith(f"{named or path}: line "), text
    return text


def _first(root, tag):
    return next(root.iter(tag))


def _remove(root, tag):
    el = _first(root, tag)
    el.getparent().remove(el)


@pytest.mark.parametrize(
    "name, tag",
    [
        ("pedestrian_collision.xosc", "SpeedActionTarget"),
        ("traffic_lights.xosc", "SpeedActionDynamics"),
        ("keep_lateral_distance.xosc", "LaneChangeActionDynamics"),
        ("cut-in_cr.xosc", "LaneOffsetTarget"),
        ("pedestrian.xosc", "Actors"),
    ],
)
def test_a_missing_required_element_is_refused_with_the_schemas_words(tmp_path, name, tag):
    """The interpreter took these children for granted; the ASAM XSD names what is missing, and where."""
    text = _refusal(_broken(tmp_path, name, lambda root: _remove(root, tag)))
    assert "cannot be played" in text and f"( {tag} )" in text and "[xsd]" in text, text


def test_a_road_user_without_its_box_is_refused_naming_the_catalog_file(tmp_path):
    source = _source("cut-in.xosc")
    vehicles = source.parent.parent / "xosc" / "Catalogs" / "Vehicles"
    if not vehicles.is_dir():
        pytest.skip(f"esmini's vehicle catalog not found ({NO_SHARED})")
    catalogs = tmp_path / "Vehicles"
    catalogs.mkdir()
    for f in vehicles.glob("*.xosc"):
        tree = etree.parse(str(f))
        for box in tree.getroot().iter("BoundingBox"):
            box.remove(box.find("Dimensions"))
        tree.write(str(catalogs / f.name))

    def change(root):
        _first(root, "VehicleCatalog").find("Directory").set("path", str(catalogs))

    used = _first(etree.parse(str(source)).getroot(), "ScenarioObject").find("CatalogReference").get("catalogName")
    text = _refusal(_broken(tmp_path, "cut-in.xosc", change), catalogs / f"{used}.xosc")
    assert "needs a BoundingBox with Dimensions" in text, text


@pytest.mark.parametrize("lane", ["-1-1", "abc", "-1.5", "", "1e300"])
def test_a_lane_id_that_is_no_whole_number_is_refused(tmp_path, lane):
    def change(root):
        _first(root, "LanePosition").set("laneId", lane)

    text = _refusal(_broken(tmp_path, "cut-in_simple.xosc", change))
    assert f"laneId={lane!r} is not a lane id" in text, text


def test_a_lane_id_written_as_a_whole_double_plays_as_that_lane(tmp_path):
    """A double parameter substituted into laneId reads "-3.0": lane -3, as esmini's integer reading."""
    plain = _broken(tmp_path, "cut-in_simple.xosc", lambda root: None)

    def change(root):
        for pos in root.iter("LanePosition"):
            pos.set("laneId", f"{float(pos.get('laneId')):.1f}")

    doubled = _broken(tmp_path, "cut-in_simple.xosc", change)
    a, b = run_scenario(plain, max_time_s=3.0), run_scenario(doubled, max_time_s=3.0)
    for name, tr in a.traces.items():
        assert list(tr.y) == list(b.traces[name].y)


def test_a_rule_from_a_parameter_that_is_no_rule_is_refused_when_built(tmp_path):
    """The XSD sees "$R"; after substitution the rule is "bogus", refused before anything runs."""

    def change(root):
        decls = root.find("ParameterDeclarations")
        etree.SubElement(decls, "ParameterDeclaration", name="R", parameterType="string", value="bogus")
        _first(root, "SimulationTimeCondition").set("rule", "$R")

    text = _refusal(_broken(tmp_path, "cut-in_simple.xosc", change))
    assert "rule 'bogus' is not one of greaterThan" in text, text


def test_a_nurbs_spanning_too_far_or_with_no_parameter_range_is_refused(tmp_path):
    def far(root):
        _first(_first(root, "Nurbs"), "WorldPosition").set("x", "99999999")

    assert "control polygon" in _refusal(_broken(tmp_path, "truck_with_rotating_axle.xosc", far))

    def flat(root):  # (a knot vector that does not decrease but never grows either)
        for k in _first(root, "Nurbs").findall("Knot"):
            k.set("value", "0.5")

    assert "no parameter range" in _refusal(_broken(tmp_path, "truck_with_rotating_axle.xosc", flat))


def test_a_junction_lane_link_that_is_no_lane_id_is_refused_naming_the_road_file(tmp_path):
    source = _source("routing-test.xosc")
    road = (source.parent / _first(etree.parse(str(source)).getroot(), "LogicFile").get("filepath")).resolve()
    tree = etree.parse(str(road))
    _first(tree.getroot(), "laneLink").set("to", "$nope")
    broken_road = tmp_path / "road.xodr"
    tree.write(str(broken_road))
    scenario = _broken(
        tmp_path, "routing-test.xosc", lambda root: _first(root, "LogicFile").set("filepath", str(broken_road))
    )
    with pytest.raises(VeiInputError) as info:
        run_scenario(scenario, max_time_s=5.0, dt=0.05)
    assert str(info.value).startswith(str(broken_road)) and "'$nope'" in str(info.value), str(info.value)


def test_a_connecting_road_without_the_lane_is_a_dead_end_not_a_crash(tmp_path):
    """A junction's connecting road without lanes: the car stops at the junction, as at a road's end."""
    name = "CA-FC_2026/CBNAO.xosc"
    source = _source(name)
    road = (source.parent / _first(etree.parse(str(source)).getroot(), "LogicFile").get("filepath")).resolve()
    tree = etree.parse(str(road))
    emptied = 0
    for r in tree.getroot().iter("road"):
        if r.get("junction") not in (None, "-1"):
            lanes = r.find("lanes")
            for sec in lanes.findall("laneSection"):
                lanes.remove(sec)
            emptied += 1
    assert emptied
    broken_road = tmp_path / "road.xodr"
    tree.write(str(broken_road))
    scenario = _broken(tmp_path, name, lambda root: _first(root, "LogicFile").set("filepath", str(broken_road)))
    try:
        result = run_scenario(scenario, max_time_s=20.0, dt=0.05)
    except VeiInputError as exc:  # (a refusal is an answer too, if it is one line)
        assert "\n" not in str(exc)
        return
    for tr in result.traces.values():
        assert all(math.isfinite(v) for v in tr.x)


def test_without_the_xsds_a_reading_failure_is_one_line_that_says_how_to_find_the_fault(tmp_path, monkeypatch):
    """A user who installed vei without the ASAM schemas gets what failed and where the XSDs come from."""
    from vei_scenario.openscenario import asam_schemas

    monkeypatch.setattr(asam_schemas, "schema_dir", lambda package: None)
    path = _broken(tmp_path, "pedestrian_collision.xosc", lambda root: _remove(root, "SpeedActionTarget"))
    with pytest.raises(VeiInputError) as info:
        run_scenario(path, max_time_s=5.0, dt=0.05)
    text = str(info.value)
    assert "\n" not in text and text.startswith(f"{path}: cannot be played: reading it failed"), text
    assert "asam-qc-openscenarioxml" in text and "vei bug" in text, text


# --- the search itself, kept running ----------------------------------------------------------------
hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

BASES = ("cut-in_simple.xosc", "pedestrian_collision.xosc", "ltap-od.xosc", "synchronize.xosc",
         "lane_change_simple.xosc", "trailers.xosc", "AEB_VRU_2023/NCAP_AEB_VRU_CPNA_2023.xosc")  # fmt: skip
ODD_VALUES = ["nan", "inf", "-1", "0", "", "abc", "1e308", "-1e308", "$nope", "${1/0}", "-0", "true", "none", "1e400"]
MUTATION = st.tuples(st.integers(0, 10_000), st.sampled_from(["drop", "set", "unset", "twice"]),
                     st.integers(0, 50), st.sampled_from(ODD_VALUES))  # fmt: skip


@settings(
    max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture]
)
@given(st.sampled_from(BASES), st.lists(MUTATION, min_size=1, max_size=3))
def test_mutated_scenarios_play_or_are_refused_in_one_line(tmp_path, base, mutations):
    def change(root):
        for where, op, which, value in mutations:
            els = [e for e in root.iter() if isinstance(e.tag, str)]
            el = els[where % len(els)]
            parent = el.getparent()
            if op == "drop" and parent is not None:
                parent.remove(el)
            elif op == "twice" and parent is not None:
                parent.insert(parent.index(el), copy.deepcopy(el))
            elif el.attrib:
                name = sorted(el.attrib)[which % len(el.attrib)]
                if op == "unset":
                    del el.attrib[name]
                else:
                    el.set(name, value)

    path = _broken(tmp_path, base, change)
    try:
        result = run_scenario(path, max_time_s=5.0, dt=0.05)
    except VeiError as exc:
        assert "\n" not in str(exc), str(exc)
        return
    for tr in result.traces.values():
        assert all(math.isfinite(v) for v in (*tr.x, *tr.y, *tr.speed)), tr.name
