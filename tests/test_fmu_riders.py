"""Every rider of the scenario in the FMU loop (``vei fmu system``/``cosim``), not only the threat:
multi_scooter's three scooters, the threat riding or replaying, the two others replaying."""

from __future__ import annotations

import zipfile
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

from vei_scenario.fmu import MODELS, build_fmus, build_system, cosimulate
from vei_scenario.fmu.system import closed_loop
from vei_scenario.interpreter import run_scenario


@pytest.fixture(scope="module")
def multi(compiled) -> Path:
    return next(p for p in compiled["multi_scooter"].written if p.name == "scenario.xosc")


@pytest.fixture(scope="module")
def fmus(tmp_path_factory) -> dict[str, Path]:
    return build_fmus(list(MODELS), tmp_path_factory.mktemp("fmus"))


def test_the_loop_holds_every_rider(multi):
    loop = closed_loop(multi, leave_out=("ped_1",))
    assert loop.components == ("ego", "cap", "sfm", "sfm_scooter_1", "sfm_scooter_3")
    assert loop.entities["sfm"] == "scooter_2" and loop.entities["sfm_scooter_1"] == "scooter_1"
    assert loop.parameters["sfm_scooter_1"]["rider_type"] == "replay"
    assert ("ego", "x", "sfm_scooter_3", "ego_x") in loop.connections
    assert loop.sequential_order == ("cap", "ego", "sfm", "sfm_scooter_1", "sfm_scooter_3")
    assert loop.notes[0] == (
        "ped_1 (a pedestrian): no rider, replayed in vei run and left out of the loop (nothing in it reacts to it)"
    )


def test_the_ssp_package_has_a_component_per_rider(multi, tmp_path):
    ssp = build_system(multi, tmp_path / "loop.ssp", leave_out=("ped_1",))
    with zipfile.ZipFile(ssp) as z:
        root = etree.fromstring(z.read("SystemStructure.ssd"))
        names = sorted(n for n in z.namelist() if n.startswith("resources/"))
    ns = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription"}
    comps = {c.get("name"): c.get("source") for c in root.iterfind(".//ssd:Component", ns)}
    assert comps == {"ego": "resources/vei_ego.fmu", "cap": "resources/vei_cap.fmu", "sfm": "resources/vei_sfm.fmu",
                     "sfm_scooter_1": "resources/vei_sfm.fmu", "sfm_scooter_3": "resources/vei_sfm.fmu"}  # fmt: skip
    assert names == ["resources/vei_cap.fmu", "resources/vei_ego.fmu", "resources/vei_sfm.fmu"]


@pytest.mark.parametrize(
    ("values", "coupling"),
    [({}, "sequential"), ({"RiderType": "aggressive", "CapEnabled": "true"}, "sequential"),
     ({"RiderType": "normal", "CapEnabled": "true"}, "jacobi")],
)  # fmt: skip
def test_every_rider_reproduces_vei_run_while_it_plays_its_track(multi, fmus, values, coupling):
    """Within 1e-6 m: the ego and the threat over the whole run; each other rider while vei run plays
    its recorded track. After it, vei run drives it on along its lane (esmini's default), which the
    rider FMU does not model: the loop says so in its notes."""
    rep = cosimulate(multi, "fmpy", values, 0.01, coupling, fmus=fmus, leave_out=("ped_1",))
    assert rep.max_deviation_m["ego"] <= 1e-6 and rep.max_deviation_m["sfm"] <= 1e-6, rep.max_deviation_m
    run = run_scenario(multi, values, 0.01, coupling=coupling)
    t = np.asarray(run.t)
    for comp, end in (("sfm_scooter_1", 10.3), ("sfm_scooter_3", 9.3)):
        tr, rec = run.traces[rep.loop.entities[comp]], rep.record[comp]
        k = t <= end + 1e-9
        assert np.max(np.hypot(tr.x[k] - rec["x"][: t.size][k], tr.y[k] - rec["y"][: t.size][k])) <= 1e-6
        assert any(n.startswith(f"{rep.loop.entities[comp]}'s track ends at {end:.2f} s") for n in rep.loop.notes)
    if values.get("RiderType") == "aggressive":  # (the threat rides: it is not a replay)
        assert rep.loop.parameters["sfm"]["rider_type"] == "aggressive"


def test_a_road_user_that_is_no_rider_is_refused_unless_left_out(multi):
    from vei_scenario.errors import VeiInputError

    with pytest.raises(VeiInputError, match=r"ped_1: a pedestrian is no rider: .* --leave-out ped_1 leaves it out"):
        closed_loop(multi)
    with pytest.raises(VeiInputError, match=r"--leave-out: no entity 'bob'"):
        closed_loop(multi, leave_out=("ped_1", "bob"))


def test_the_case_study_loop_is_unchanged(compiled):
    case = next(p for p in compiled["case_study"].written if p.name == "scenario.xosc")
    loop = closed_loop(case)
    assert loop.components == ("ego", "cap", "sfm") and loop.notes == []
