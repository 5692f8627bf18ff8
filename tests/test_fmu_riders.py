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
from vei_scenario.fmu.variables import MAX_PATH
from vei_scenario.interpreter import run_scenario


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
def test_every_rider_reproduces_vei_run_over_the_whole_run(multi, fmus, values, coupling):
    """Within 1e-6 m, every rider over the whole run: the ego and the threat, and each other rider also
    after its recorded track ends (at 10.3 and 9.3 s), where vei run drives it on along its lane
    (esmini's default) and its FMU follows that way on, given with its track."""
    rep = cosimulate(multi, "fmpy", values, 0.01, coupling, fmus=fmus, leave_out=("ped_1",))
    assert max(rep.max_deviation_m.values()) <= 1e-6, rep.max_deviation_m
    run = run_scenario(multi, values, 0.01, coupling=coupling)
    t = np.asarray(run.t)
    for comp in ("sfm_scooter_1", "sfm_scooter_3"):
        tr, rec = run.traces[rep.loop.entities[comp]], rep.record[comp]
        n = min(t.size, rec["x"].size)
        assert t[n - 1] >= 25.0 - 1e-9  # (compared to the end of the run, well past the tracks' ends)
        assert np.max(np.hypot(tr.x[:n] - rec["x"][:n], tr.y[:n] - rec["y"][:n])) <= 1e-6
        assert rep.loop.parameters[comp]["track_n"] <= MAX_PATH
    assert not any("track ends" in n for n in rep.loop.notes), rep.loop.notes
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


def test_the_way_on_keeps_only_the_vertices_interpolation_needs():
    """A straight, uniformly timed way on is two vertices; on an arc of radius 1 km at 5 m/s, every
    sample the FMU is asked for stays within the tolerance of the kept vertices' interpolation; a
    budget too small for the coarsest tolerance is cut, and says from when."""
    from types import SimpleNamespace

    from vei_scenario.fmu.replay_tracks import drive_on, thin

    t = np.arange(0.0, 10.0, 0.01)
    line = thin(t, 3.0 * t, -t, np.full(t.size, np.arctan2(-1, 3)), 1e-9)
    assert line == [0, t.size - 1]
    a = 0.005 * t
    x, y, h = 1000 * np.sin(a), 1000 - 1000 * np.cos(a), a
    keep = thin(t, x, y, h, 1e-5)
    assert 2 < len(keep) < t.size
    k = np.asarray(keep)
    xi, yi = np.interp(t, t[k], x[k]), np.interp(t, t[k], y[k])
    assert np.max(np.hypot(xi - x, yi - y)) <= 1e-5
    track = (np.array([-1.0, 0.0]), np.array([-5.0, 0.0]), np.array([0.0, 0.0]), np.array([0.0, 0.0]))
    trace = SimpleNamespace(t=t, x=x, y=y, yaw=h)
    fits = drive_on(track, trace, 0.0, 512)
    assert fits.cut_s is None and fits.ts.size <= 512 < 1 + len(thin(t, x, y, h, 1e-6))
    assert fits.tolerance_m == 1e-5  # (the finest that fits)
    cut = drive_on(track, trace, 0.0, 3)
    assert cut.ts.size == 3 and cut.cut_s is not None and cut.cut_s < 9.99
