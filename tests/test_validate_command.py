"""``vei validate``: each VEI rule fires on a file that breaks it, with the line; hostile XML is inert."""

from __future__ import annotations

import json
import shutil

import pytest

from vei_scenario.cli import main


@pytest.fixture()
def scenario_dir(compiled, tmp_path):
    src = compiled["case_study"].written[0].parent
    for name in ("scenario.xosc", "scenario.xodr", "scenario.variations.xosc"):
        shutil.copy(src / name, tmp_path / name)
    return tmp_path


def _line_of(text: str, needle: str) -> int:
    return text[: text.index(needle)].count("\n") + 1


def _validate(capsys, *args) -> tuple[int, str]:
    code = main(["validate", *map(str, args)])
    return code, capsys.readouterr().out


def test_clean_files_exit_0(scenario_dir, capsys, qc_venv):
    code, out = _validate(capsys, *sorted(scenario_dir.iterdir()))
    assert code == 0 and out.strip().endswith("3 file(s) checked: valid")


RULE_CASES = {
    "parameter.undeclared": ('offset="${-$TimeShift}"', 'offset="${-$Shift2}"'),
    # (on the scooter's timed path: the ego's is followed without a Timing, its times are not read)
    "trajectory.vertex-time": ('<Trajectory name="scooter_1_route"', '<Vertex time="1.8">', '<Vertex time="1.7">'),
    "reference.dangling": ('<EntityRef entityRef="scooter_1"/>', '<EntityRef entityRef="scooter_7"/>'),
    "file.missing": ('<LogicFile filepath="scenario.xodr"/>', '<LogicFile filepath="missing.xodr"/>'),
}


@pytest.mark.parametrize("rule", sorted(RULE_CASES))
def test_each_rule_reports_file_line_and_reason(scenario_dir, capsys, qc_venv, rule):
    *anchor, old, new = RULE_CASES[rule]
    path = scenario_dir / "scenario.xosc"
    text = path.read_text()
    at = text.index(anchor[0]) if anchor else 0  # (the first occurrence after the anchor)
    assert old in text[at:]
    where = text.index(old, at)
    path.write_text(text[:where] + new + text[where + len(old) :])
    code, out = _validate(capsys, path)
    assert code == 1
    hits = [ln for ln in out.splitlines() if f"[{rule}]" in ln]
    assert hits, out
    assert hits[0].startswith(f"{path}:{text[:where].count(chr(10)) + 1}: ")


def test_distribution_naming_an_unknown_parameter(scenario_dir, capsys, qc_venv):
    path = scenario_dir / "scenario.variations.xosc"
    text = path.read_text().replace('parameterName="RiderType"', 'parameterName="Rider"')
    path.write_text(text)
    code, out = _validate(capsys, path, "--format", "json")
    report = json.loads(out)
    assert code == 1 and not report["valid"]
    assert [p["rule"] for p in report["problems"]] == ["distribution.unknown-parameter"]
    assert "'Rider'" in report["problems"][0]["message"]


def test_xsd_violation_is_reported_with_line(scenario_dir, capsys, qc_venv):
    path = scenario_dir / "scenario.xosc"
    text = path.read_text().replace("<CatalogLocations/>", "<CatalogLocations/><Bogus/>", 1)
    path.write_text(text)
    code, out = _validate(capsys, path)
    assert code == 1 and "[xsd]" in out and "Bogus" in out


def test_broken_xml(tmp_path, capsys):
    path = tmp_path / "broken.xosc"
    path.write_text('<?xml version="1.0"?>\n<OpenSCENARIO>\n  <FileHeader revMajor="1"\n')
    code, out = _validate(capsys, path)
    assert code == 1 and out.startswith(f"{path}:") and "[xml.syntax]" in out


LAUGHS = '<!ENTITY a "aaaaaaaaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">'


@pytest.mark.parametrize(
    "dtd, attr, rule",
    [
        (LAUGHS, "&b;", "[xml.dtd]"),  # entity expansion: refused, never expanded
        ('<!ENTITY x SYSTEM "file:///etc/passwd">', "&x;", "[xml.syntax]"),  # external entity: never read
    ],
)
def test_hostile_xml_is_refused(tmp_path, capsys, dtd, attr, rule):
    path = tmp_path / "hostile.xosc"
    path.write_text(
        f'<?xml version="1.0"?><!DOCTYPE OpenSCENARIO [{dtd}]>'
        f'<OpenSCENARIO><FileHeader revMajor="1" revMinor="3" description="{attr}"/></OpenSCENARIO>'
    )
    code, out = _validate(capsys, path)
    assert code == 1 and rule in out, out
    assert "aaaaaaaaaaaaaaaa" not in out and "root:" not in out


def test_missing_file_is_a_user_error(tmp_path, capsys):
    code = main(["validate", str(tmp_path / "nope.xosc")])
    assert code == 2 and "nope.xosc: file not found" in capsys.readouterr().err


def test_missing_schemas_are_a_clear_user_error(scenario_dir, capsys, monkeypatch):
    from vei_scenario.openscenario import asam_schemas

    monkeypatch.setenv("VEI_QC_VENV", str(scenario_dir / "no-venv"))
    monkeypatch.setenv("VEI_ASAM_SCHEMAS", "")
    monkeypatch.setattr(asam_schemas.importlib.util, "find_spec", lambda name: None)
    asam_schemas.schema_dir.cache_clear()
    try:
        code = main(["validate", str(scenario_dir / "scenario.xosc")])
        err = capsys.readouterr().err
        assert code == 2 and "no OpenSCENARIO schema found" in err and "asam-qc-openscenarioxml" in err
    finally:
        asam_schemas.schema_dir.cache_clear()


def _declare(text: str, name: str, value: str) -> str:
    """``text`` with a top-level string parameter ``name`` declared first."""
    decl = f'<ParameterDeclaration name="{name}" parameterType="string" value="{value}"/>'
    return text.replace("<ParameterDeclarations>", "<ParameterDeclarations>" + decl, 1)


def test_what_players_do_not_need_is_not_a_problem(scenario_dir, capsys, qc_venv):
    """A missing 3D model (SceneGraphFile), a catalog parameter assigned by name, a declared name with
    esmini's leading $, esmini's qualified element reference, the times of a path followed untimed:
    none stops a run (vei's or esmini's), so none fails the check; a road file given by a parameter
    that names a missing file does."""
    path = scenario_dir / "scenario.xosc"
    text = path.read_text()
    assert "<RoadNetwork>" in text and "</Storyboard>" in text
    logic_end = text.index("/>", text.index("<LogicFile")) + 2
    text = text[:logic_end] + '<SceneGraphFile filepath="models/absent.osgb"/>' + text[logic_end:]
    text = _declare(text, "$owner", "x")
    path.write_text(text)
    code, out = _validate(capsys, path)
    assert code == 0, out
    # a road given by a parameter whose value names no file
    start = text.index("<LogicFile")
    end = text.index("/>", start) + 2
    text = text[:start] + '<LogicFile filepath="$Road"/>' + text[end:]
    text = _declare(text, "Road", "gone.xodr")
    path.write_text(text)
    code, out = _validate(capsys, path)
    assert code == 1 and "[file.missing]" in out and "(gone.xodr)" in out, out


def test_a_catalogs_entity_references_are_the_using_scenarios(tmp_path, capsys, qc_venv):
    """A maneuver catalog names the entities of the scenarios that use it: not dangling in the file."""
    path = tmp_path / "maneuvers.xosc"
    path.write_text(
        '<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" '
        'description="c" author="t"/><Catalog name="ManeuverCatalog"><Maneuver name="brake"><Event name="e" '
        'priority="overwrite"><Action name="a"><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics '
        'dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="0"/>'
        "</SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Action><StartTrigger><ConditionGroup>"
        '<Condition name="c" delay="0" conditionEdge="rising"><ByEntityCondition><TriggeringEntities '
        'triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/></TriggeringEntities><EntityCondition>'
        '<SpeedCondition value="10" rule="greaterThan"/></EntityCondition></ByEntityCondition></Condition>'
        "</ConditionGroup></StartTrigger></Event></Maneuver></Catalog></OpenSCENARIO>"
    )
    code, out = _validate(capsys, path)
    assert code == 0, out
