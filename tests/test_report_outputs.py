"""What a reader of the outputs takes at face value: typed parameters and provenance in metrics.json,
units in cosim.csv, a sweep report that does not claim more than its grid can show, plots whose
coinciding series stay visible, and vei probability's documented example."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest

import vei_scenario
from vei_scenario.runner import run_to


@pytest.fixture(scope="module")
def case_xosc(compiled) -> Path:
    return next(p for p in compiled["case_study"].written if p.name == "scenario.xosc")


def test_metrics_json_keeps_declared_types_version_and_file_hashes(case_xosc, tmp_path):
    run_to(case_xosc, tmp_path, {"TimeShift": "2.2", "RiderType": "aggressive", "CapEnabled": "true"}, plots=False)
    doc = json.loads((tmp_path / "metrics.json").read_text())
    p = doc["parameters"]
    assert p["TimeShift"] == 2.2 and isinstance(p["TimeShift"], float)
    assert p["CapEnabled"] is True
    assert p["RiderType"] == "aggressive"
    assert isinstance(p["EgoCruiseSpeed"], float)
    assert doc["vei_version"] == vei_scenario.__version__
    assert doc["scenario_sha256"] == hashlib.sha256(case_xosc.read_bytes()).hexdigest()
    road = case_xosc.with_suffix(".xodr")
    assert doc["road_file"] == road.name
    assert doc["road_sha256"] == hashlib.sha256(road.read_bytes()).hexdigest()
