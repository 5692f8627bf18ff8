"""The written OpenSCENARIO/OpenDRIVE files: standards, content and determinism."""

from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

from conftest import EXAMPLE_NAMES, EXAMPLES, site_packages
from vei_scenario.compiler import CompileOptions, compile_clip
from vei_scenario.openscenario.validation import validate_files


def outputs(result) -> list[Path]:
    return [p for p in result.written if p.suffix in (".xosc", ".xodr")]


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_outputs_pass_vei_validate_and_asam_xsd(compiled, qc_venv, name):
    files = outputs(compiled[name])
    assert len(files) >= 3
    assert validate_files(files) == []


def test_every_osc_version_validates(tmp_path, qc_venv):
    for minor in range(4):
        out = tmp_path / f"v1{minor}" / "scenario.xosc"
        result = compile_clip(
            EXAMPLES / "multi_scooter" / "clip.json",
            out,
            CompileOptions(osc_minor_version=minor, variants_dir=out.parent / "variants"),
        )
        header = etree.parse(str(out)).getroot().find("FileHeader")
        assert header.get("revMinor") == str(minor)
        assert validate_files(outputs(result)) == [], minor


def _xsd_errors(xsd: Path, doc: Path) -> list[str]:
    """Independent of vei's validator: lxml against the ASAM file directly."""
    schema = etree.XMLSchema(etree.parse(str(xsd)))
    ok = schema.validate(etree.parse(str(doc)))
    return [] if ok else [str(e) for e in schema.error_log]


def test_asam_xsd_directly(compiled, qc_venv):
    sp = site_packages(qc_venv)
    osc = sp / "qc_openscenario" / "schema" / "1.3.0" / "OpenSCENARIO.xsd"
    for name in EXAMPLE_NAMES:
        for f in outputs(compiled[name]):
            if f.suffix == ".xosc":
                assert _xsd_errors(osc, f) == [], f
    odr14 = sp / "qc_opendrive" / "schema" / "1.4" / "OpenDRIVE_1.4H.xsd"
    odr17 = sp / "qc_opendrive" / "schema" / "1.7.0" / "opendrive_17_core.xsd"
    assert _xsd_errors(odr14, next(p for p in compiled["case_study"].written if p.suffix == ".xodr")) == []
    assert _xsd_errors(odr17, next(p for p in compiled["no_map"].written if p.suffix == ".xodr")) == []


def _run_quality_checker(qc_venv: Path, tool: str, bundle: str, file: Path, tmp: Path) -> etree._Element:
    result = tmp / f"{file.name}.xqar"
    config = tmp / f"{file.name}.config.xml"
    config.write_text(
        f'<?xml version="1.0" encoding="UTF-8"?><Config><Param name="InputFile" value="{file}"/>'
        f'<CheckerBundle application="{bundle}"><Param name="resultFile" value="{result}"/></CheckerBundle></Config>'
    )
    subprocess.run([str(qc_venv / "bin" / tool), "-c", str(config)], capture_output=True, check=True, cwd=tmp)
    return etree.parse(str(result)).getroot()  # the exit code is always 0: read the result file


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_asam_quality_checker_finds_no_errors(compiled, qc_venv, tmp_path, name):
    checked = 0
    for f in outputs(compiled[name]):
        if f.parent.name == "variants":
            continue
        tool, bundle = ("qc_openscenario", "xoscBundle") if f.suffix == ".xosc" else ("qc_opendrive", "xodrBundle")
        root = _run_quality_checker(qc_venv, tool, bundle, f, tmp_path)
        statuses = [c.get("status") for c in root.iter("Checker")]
        assert statuses and "error" not in statuses, statuses
        errors = [i.get("description") for i in root.iter("Issue") if i.get("level") == "1"]
        assert errors == [], (f.name, errors[:5])
        checked += 1
    assert checked == 3


def test_fitted_road_gets_the_full_quality_check(compiled, qc_venv, tmp_path):
    xodr = next(p for p in compiled["no_map"].written if p.suffix == ".xodr")
    root = _run_quality_checker(qc_venv, "qc_opendrive", "xodrBundle", xodr, tmp_path)
    completed = [c for c in root.iter("Checker") if c.get("status") == "completed"]
    assert len(completed) >= 20  # OpenDRIVE 1.7: (almost) every rule applies
    assert [i for i in root.iter("Issue") if i.get("level") in ("1", "2")] == []


def test_compile_is_byte_for_byte_deterministic(tmp_path):
    digests = []
    for run in ("a", "b"):
        out = tmp_path / run / "scenario.xosc"
        compile_clip(EXAMPLES / "multi_scooter" / "clip.json", out, CompileOptions(variants_dir=out.parent / "v"))
        digests.append(
            {p.relative_to(out.parent): p.read_bytes() for p in sorted(out.parent.rglob("*")) if p.is_file()}
        )
    assert digests[0].keys() == digests[1].keys() and len(digests[0]) > 10
    assert digests[0] == digests[1]


def _polyline(root, entity: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    group = next(g for g in root.iter("ManeuverGroup") if g.find("Actors/EntityRef").get("entityRef") == entity)
    verts = group.findall(".//Polyline/Vertex")
    t = np.array([float(v.get("time")) for v in verts])
    x = np.array([float(v.find("Position/WorldPosition").get("x")) for v in verts])
    y = np.array([float(v.find("Position/WorldPosition").get("y")) for v in verts])
    return t, x, y


def test_trajectories_are_polylines_with_scenario_times(compiled):
    result = compiled["case_study"]
    root = etree.parse(str(result.written[0])).getroot()
    for e in result.model.entities:
        t, x, y = _polyline(root, e.name)
        assert np.all(np.diff(t) > 0)
        assert np.allclose(t, e.trajectory.t, atol=5e-4)
        assert np.hypot(x - e.trajectory.x, y - e.trajectory.y).max() < 1e-3
    ego_t, ex, ey = _polyline(root, "Ego")
    assert ego_t[0] == 0.0 and ego_t[-2] == pytest.approx(25.0)
    # past its recording the ego's path runs straight on, far enough for the whole run at cruise speed
    h = result.model.entities[0].trajectory.yaw[-2]
    across = np.cos(h) * (ey[-1] - ey[-2]) - np.sin(h) * (ex[-1] - ex[-2])
    assert across == pytest.approx(0.0, abs=1e-3)
    cruise = float(result.model.parameter("EgoCruiseSpeed").default)
    length = np.hypot(np.diff(ex), np.diff(ey)).sum()
    assert length >= cruise * 25.0 + 9.9


def test_threat_timing_offset_is_minus_the_timeshift_parameter(compiled):
    root = etree.parse(str(compiled["case_study"].written[0])).getroot()
    timings = {
        g.find("Actors/EntityRef").get("entityRef"): g.find(".//Timing")
        for g in root.iter("ManeuverGroup")
        if g.find(".//Timing") is not None
    }
    assert timings["scooter_1"].get("offset") == "${-$TimeShift}"  # esmini: trajectory time t + offset
    assert "Ego" not in timings  # the ego follows its path at $EgoCruiseSpeed, no timing
    ego_init = next(p for p in root.iter("Private") if p.get("entityRef") == "Ego")
    assert ego_init.find(".//AbsoluteTargetSpeed").get("value") == "$EgoCruiseSpeed"
    assert all(t.get("domainAbsoluteRelative") == "absolute" and float(t.get("scale")) == 1 for t in timings.values())
    declared = {d.get("name"): d for d in root.iter("ParameterDeclaration")}
    assert {"TimeShift", "RiderType", "CapEnabled", "EgoCruiseSpeed"} <= declared.keys()
    assert declared["EgoCruiseSpeed"].get("value") == "5.61"  # median recorded speed
    controllers = {c.get("name"): c for c in root.iter("Controller")}
    assert controllers["SocialForceModel"].find("Properties/Property[@name='riderType']").get("value") == "$RiderType"
    assert (
        controllers["CollisionAvoidancePlanner"].find("Properties/Property[@name='threatEntity']").get("value")
        == "scooter_1"
    )


def test_distribution_covers_the_seed_method_variations(compiled):
    result = compiled["case_study"]
    dist = next(p for p in result.written if p.name.endswith(".variations.xosc"))
    root = etree.parse(str(dist)).getroot()
    values = {
        d.get("parameterName"): [e.get("value") for e in d.iter("Element")]
        for d in root.iter("DeterministicSingleParameterDistribution")
    }
    shift = result.model.conflicts["scooter_1"].time_shift_s
    assert values["RiderType"] == ["replay", "normal", "aggressive"]
    assert values["CapEnabled"] == ["false", "true"]
    shifts = [float(v) for v in values["TimeShift"]]
    assert 0.0 in shifts and min(abs(s - shift) for s in shifts) < 1e-3
    assert root.find(".//ScenarioFile").get("filepath") == "scenario.xosc"


def test_resolved_variants_have_no_parameters(compiled):
    variants = sorted(p for p in compiled["case_study"].written if p.parent.name == "variants")
    assert len(variants) == 6 * 3 * 2
    for v in variants:
        text = v.read_text()
        assert "$" not in text and "ParameterCondition" not in text and "<ParameterDeclaration " not in text
        root = etree.fromstring(text.encode())
        activations = {e.get("name") for e in root.iter("Event") if e.get("name").startswith("Activate")}
        assert ("ActivateSocialForce" in activations) == ("_replay_" not in v.name)
        assert ("ActivateCollisionAvoidance" in activations) == ("_cap" in v.name)
        assert (v.parent / root.find(".//LogicFile").get("filepath")).is_file()
