"""A scenario file is read and checked once per process (interpreter.document's template) and every
load resolves a copy of it, visiting only the elements that name parameters, hold catalog references or
declare parameters of their own, and checking again only the numbers that parameters gave. Nothing of
that may show: each load is what resolving the whole file afresh gives (the reference below: every
element visited, every number checked), a file changed on disk is read again, the loads of different
values do not see each other's, and a refusal names the line a fresh reading names."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from conftest import NO_SHARED, SHARED
from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter import clear_file_caches, load_scenario
from vei_scenario.interpreter import document as doc_module
from vei_scenario.openscenario.numeric_attributes import check_numbers
from vei_scenario.safe_xml import parse_xml

ESMINI_XOSC = SHARED / "esmini" / "xosc"
NCAP = SHARED / "osc-ncap" / "OpenSCENARIO" / "NCAP"


def _reference(path: Path, values: dict) -> bytes:
    """The file resolved as before templates: parsed afresh, every element visited, every number checked."""
    tree = parse_xml(path)
    root = tree.getroot()
    etree.strip_elements(root, etree.Comment, etree.ProcessingInstruction, with_tail=False)
    scope: dict[str, str] = {}
    types: dict[str, str] = {}
    top = root.find("ParameterDeclarations")
    if top is not None:
        doc_module._declare(path, top, scope, types)
    values = {k: doc_module.parameter_text(v) for k, v in values.items()}
    scope.update(values)
    if values:
        scope, types = doc_module.redeclare(path, top, values)
    doc_module._substitute(path, root, scope, types, doc_module.Catalogs(path, root))
    check_numbers(path, root)
    return etree.tostring(root)


def _files() -> list[Path]:
    found = sorted(ESMINI_XOSC.glob("*.xosc"))[::3] + sorted(NCAP.glob("*/*.xosc"))[::2]
    return [f for f in found if "ParameterValueDistribution" not in f.read_text(errors="replace")[:4000]]


@pytest.mark.skipif(
    not ESMINI_XOSC.is_dir() or not NCAP.is_dir(),
    reason=f"esmini's examples or the Euro NCAP pack not found ({NO_SHARED})",
)
def test_loads_equal_resolving_the_whole_file_afresh():
    """esmini's examples and the Euro NCAP pack, each loaded three times (its defaults, then numeric
    parameters moved), against the reference: the same XML, byte for byte."""
    compared = 0
    for path in _files():
        try:
            plain = load_scenario(path)
        except VeiInputError:
            with pytest.raises(VeiInputError):
                _reference(path, {})
            continue
        numeric = [n for n, t in plain.parameter_types.items() if t == "double"][:3]
        for values in ({}, {n: float(plain.parameters[n]) + 0.25 for n in numeric}, {}):
            assert etree.tostring(load_scenario(path, values).root) == _reference(path, values), path.name
            compared += 1
    assert compared >= 60


def _scenario(tmp_path, speed: str = "10", extra_story: str = "", decl_speed: str = "12.5") -> Path:
    path = tmp_path / "s.xosc"
    path.write_text(
        f"""<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterDeclarations><ParameterDeclaration name="Speed" parameterType="double" value="{decl_speed}"/>
<ParameterDeclaration name="Gap" parameterType="double" value="${{$Speed * 2}}"/></ParameterDeclarations>
<RoadNetwork/><Entities><ScenarioObject name="Ego"><Vehicle name="car" vehicleCategory="car">
<BoundingBox><Center x="1.4" y="0" z="0.7"/><Dimensions width="1.8" length="4.5" height="1.4"/></BoundingBox>
<Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/>
<Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.6" positionX="2.8" positionZ="0.3"/>
<RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0" positionZ="0.3"/></Axles>
<Properties/></Vehicle></ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="Ego"><PrivateAction><TeleportAction><Position><WorldPosition
x="$Gap" y="0" h="0"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction>
<SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget>
<AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>
</Private></Actions></Init>{extra_story}<StopTrigger><ConditionGroup><Condition name="end" delay="0"
conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1" rule="greaterThan"/></ByValueCondition>
</Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    )
    return path


def _gap(doc) -> str:
    return doc.root.find(".//TeleportAction/Position/WorldPosition").get("x")


def test_loads_of_other_values_do_not_see_each_other(tmp_path):
    path = _scenario(tmp_path)
    first = load_scenario(path, {"Speed": 1.5})
    second = load_scenario(path, {"Speed": 4})
    assert (_gap(first), _gap(second), _gap(load_scenario(path))) == ("3", "8", "25")
    assert first.parameters["Speed"] == "1.5" and load_scenario(path).parameters["Speed"] == "12.5"


def test_a_scenario_changed_on_disk_is_read_again(tmp_path):
    path = _scenario(tmp_path, decl_speed="12.5")
    assert _gap(load_scenario(path)) == "25"
    _scenario(tmp_path, decl_speed="17.5")  # (same size)
    assert _gap(load_scenario(path)) == "35"
    path.unlink()
    with pytest.raises(VeiInputError, match="not found"):
        load_scenario(path)


def _line_of(path: Path, text: str) -> int:
    return next(i for i, line in enumerate(path.read_text().splitlines(), 1) if text in line)


def test_a_number_written_out_is_refused_on_every_load(tmp_path):
    path = _scenario(tmp_path, speed="fast")
    for values in ({}, {"Speed": 3}):
        with pytest.raises(VeiInputError, match=f"line {_line_of(path, 'fast')}.*not a number"):
            load_scenario(path, values)


def test_a_number_a_parameter_gives_is_refused_where_it_stands(tmp_path):
    """A parameter whose value is no number, named before a number written out wrongly: the first in
    the file is named, as a fresh reading names it (and once the parameter is a number, the other)."""
    story = '<Story name="later"><Act name="a"><ManeuverGroup name="g" maximumExecutionCount="-1.5"/></Act></Story>'
    path = _scenario(tmp_path, extra_story=story)
    path.write_text(path.read_text().replace('x="$Gap"', 'x="$Gap" z="$Name"').replace(
        '<ParameterDeclarations>', '<ParameterDeclarations><ParameterDeclaration name="Name" parameterType="string" '
        'value="abc"/>', 1))  # fmt: skip
    line = _line_of(path, 'z="$Name"')
    with pytest.raises(VeiInputError, match=f"line {line}.*abc.*not a number"):
        load_scenario(path)
    with pytest.raises(VeiInputError, match=f"line {_line_of(path, 'later')}.*-1.5"):
        load_scenario(path, {"Name": "2"})


def test_declarations_nobody_reads_are_still_checked(tmp_path):
    """A Story declaring a parameter of a wrong type is refused though nothing names it (the
    elements with declarations of their own are visited)."""
    story = (
        '<Story name="s"><ParameterDeclarations><ParameterDeclaration name="N" parameterType="int" value="x"/>'
        '</ParameterDeclarations><Act name="a"/></Story>'
    )
    path = _scenario(tmp_path, extra_story=story)
    line = _line_of(path, 'name="N"')
    with pytest.raises(VeiInputError, match=f"line {line}.*N = 'x'"):
        load_scenario(path)


def test_integers_written_as_decimals_are_rewritten_in_every_load(tmp_path):
    story = '<Story name="s"><Act name="a"><ManeuverGroup name="g" maximumExecutionCount="2.0"/></Act></Story>'
    path = _scenario(tmp_path, extra_story=story)
    for values in ({}, {"Speed": 3}, {}):
        assert load_scenario(path, values).root.find(".//ManeuverGroup").get("maximumExecutionCount") == "2"


def test_the_template_is_never_changed_by_a_load(tmp_path):
    path = _scenario(tmp_path)
    clear_file_caches()
    load_scenario(path, {"Speed": 2})
    template = doc_module._template(str(path), doc_module.content_key(path))
    before = etree.tostring(template.root)
    doc = load_scenario(path, {"Speed": 3})
    doc.root.find(".//WorldPosition").set("x", "999")
    assert etree.tostring(template.root) == before and b'x="$Gap"' in before
    assert _gap(load_scenario(path, {"Speed": 3})) == "6"


def test_a_catalog_file_added_to_a_directory_is_found(tmp_path):
    path = _scenario(tmp_path)
    text = path.read_text().replace("<RoadNetwork/>", '<CatalogLocations><VehicleCatalog><Directory path="cat"/>'
                                    "</VehicleCatalog></CatalogLocations><RoadNetwork/>")  # fmt: skip
    vehicle = text[text.index("<Vehicle ") : text.index("</Vehicle>") + len("</Vehicle>")]
    path.write_text(text.replace(vehicle, '<CatalogReference catalogName="VehicleCatalog" entryName="car"/>'))
    (tmp_path / "cat").mkdir()
    with pytest.raises(VeiInputError, match="catalog entry VehicleCatalog/car not found"):
        load_scenario(path)
    catalog = f'<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" \
description="" author=""/><Catalog name="VehicleCatalog">{vehicle}</Catalog></OpenSCENARIO>'
    (tmp_path / "cat" / "vehicles.xosc").write_text(catalog)
    assert load_scenario(path).root.find(".//ScenarioObject/Vehicle").get("name") == "car"


def test_numbers_parameters_give_are_checked_in_every_load(tmp_path):
    """Every number written out is right: only the values parameters put in can be wrong."""
    path = _scenario(tmp_path)
    line = _line_of(path, 'x="$Gap"')
    assert _gap(load_scenario(path, {"Speed": 2})) == "4"
    with pytest.raises(VeiInputError, match=f"line {line}: <WorldPosition x=.*out of range"):
        load_scenario(path, {"Speed": 1e300})
    assert _gap(load_scenario(path, {"Speed": 3})) == "6"
    path.write_text(path.read_text().replace('parameterType="double" value="${$Speed * 2}"',
                                             'parameterType="string" value="far"'))  # fmt: skip
    with pytest.raises(VeiInputError, match=f'line {line}: <WorldPosition x="far">: not a number'):
        load_scenario(path)
