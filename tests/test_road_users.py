"""Every annotated road user of a clip is in the compiled scenario, replayed as recorded and typed by
its category (OpenSCENARIO element and category, OSI object type), whether or not vei has a behaviour
model for it; the e-scooters alone are candidate threats. The multi-scooter clip has a pedestrian."""

from __future__ import annotations

import numpy as np
import pytest

from vei_scenario.cli import main
from vei_scenario.safe_xml import parse_xml
from vei_scenario.scenario.road_users import road_user_class

PED = "ped_1"


@pytest.fixture(scope="module")
def multi(compiled):
    return compiled["multi_scooter"]


def _scenario_object(path, name):
    root = parse_xml(path).getroot()
    return next(o for o in root.iterfind("Entities/ScenarioObject") if o.get("name") == name), root


def test_the_pedestrian_is_a_pedestrian_that_replays_its_track(multi):
    assert not [n for n in multi.notes if PED in n and "skipped" in n]
    assert PED in [e.name for e in multi.model.entities]
    obj, root = _scenario_object(multi.written[0], PED)
    ped = obj.find("Pedestrian")
    assert ped is not None and ped.get("pedestrianCategory") == "pedestrian"
    assert obj.find("ObjectController") is None  # no behaviour model: it replays
    groups = [g for g in root.iter("ManeuverGroup") if g.find("Actors/EntityRef").get("entityRef") == PED]
    (fta,) = [a for g in groups for a in g.iter("FollowTrajectoryAction")]
    times = [float(v.get("time")) for v in fta.iter("Vertex")]
    assert len(times) > 10 and np.all(np.diff(times) > 0)
    assert fta.find("TimeReference/Timing").get("domainAbsoluteRelative") == "absolute"


def test_the_pedestrian_is_no_threat_and_no_conflict(multi, tmp_path):
    from conftest import EXAMPLES
    from vei_scenario.compiler import CompileOptions, compile_clip
    from vei_scenario.errors import VeiInputError

    assert multi.model.threat.startswith("scooter_")
    assert PED not in multi.model.conflicts
    with pytest.raises(VeiInputError, match="no e-scooter track 'ped_1'"):
        compile_clip(EXAMPLES / "multi_scooter" / "clip.json", tmp_path / "s.xosc", CompileOptions(threat=PED))
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("minor", [0, 1, 2, 3])
def test_the_scenario_with_its_pedestrian_is_valid_against_the_asam_schema(multi, minor, tmp_path):
    import shutil

    from vei_scenario.openscenario.scenario_writer import scenario_xml
    from vei_scenario.openscenario.validation import validate_file

    data = scenario_xml(multi.model, minor)
    assert b"<Pedestrian " in data
    shutil.copy(multi.written[0].with_suffix(".xodr"), tmp_path / "scenario.xodr")
    (tmp_path / "scenario.xosc").write_bytes(data)
    assert validate_file(tmp_path / "scenario.xosc") == []


def test_vei_run_plays_the_pedestrian_through_its_keyframes(multi):
    from vei_scenario.interpreter import run_scenario

    track = multi.reconstruction.others[PED]
    result = run_scenario(multi.written[0], {}, 0.01)
    tr = result.traces[PED]
    inside = (track.key_t >= 0) & (track.key_t <= tr.t[-1])
    x = np.interp(track.key_t[inside], tr.t, tr.x)
    y = np.interp(track.key_t[inside], tr.t, tr.y)
    err = np.hypot(x - track.key_x[inside], y - track.key_y[inside])
    assert err.max() < 0.3, err  # (the smoothing spline's fit of the annotations, not the player)
    moved = np.hypot(tr.x[-1] - tr.x[0], tr.y[-1] - tr.y[0])
    assert moved > 5.0


def test_vei_run_and_esmini_play_the_pedestrian_alike(multi, esmini):
    from vei_scenario.conformance.esmini import cross_check

    params = {"TimeShift": "0", "RiderType": "replay", "CapEnabled": "false"}
    c = cross_check(esmini, multi.written[0], params, 0.01)
    (ped,) = [e for e in c.entities if e.entity == PED]
    assert ped.samples > 100
    assert ped.max_deviation_m <= 0.05, ped


def test_the_osi_trace_types_the_pedestrian(multi, tmp_path):
    betterosi = pytest.importorskip("betterosi")
    trace = tmp_path / "trace.mcap"
    assert main(["run", str(multi.written[0]), "--no-plots", "-o", str(tmp_path / "run"), "--osi", str(trace)]) == 0
    gt = next(iter(betterosi.read(trace)))
    index = [e.name for e in multi.model.entities].index(PED)
    (mo,) = [m for m in gt.moving_object if m.id.value == index]
    assert mo.type.name.endswith("PEDESTRIAN")
    assert mo.base.dimension.height == pytest.approx(1.8)


def test_the_sweep_kernel_holds_the_pedestrian_as_a_replayed_road_user(multi):
    from vei_scenario.batch.native import NativeBatch
    from vei_scenario.interpreter import run_scenario
    from vei_scenario.loop import LoopScene
    from vei_scenario.metrics import PairSeries, compute_metrics

    scene = LoopScene(multi.written[0])
    assert PED in scene.names
    variants = [{"TimeShift": "1.41", "RiderType": "aggressive", "CapEnabled": "true"}]
    (row,) = NativeBatch(scene).metrics(variants)
    assert row == compute_metrics(PairSeries.from_run(run_scenario(multi.written[0], variants[0])))


def test_the_fmu_loop_refuses_the_scenario_with_more_road_users_in_one_line(multi, tmp_path, capsys):
    code = main(["fmu", "system", str(multi.written[0]), "-o", str(tmp_path / "loop.ssp")])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err and len(err.strip().splitlines()) == 1
    assert PED in err


@pytest.mark.parametrize(
    "category, kind, osc",
    [
        ("pedestrian", "pedestrian", "pedestrian"),
        ("Person", "pedestrian", "pedestrian"),
        ("human.pedestrian.adult", "pedestrian", "pedestrian"),
        ("wheelchair", "pedestrian", "wheelchair"),
        ("dog", "pedestrian", "animal"),
        ("cyclist", "vehicle", "bicycle"),
        ("truck", "vehicle", "truck"),
        ("e-scooter", "vehicle", "bicycle"),
        ("shopping trolley", "misc", "none"),
    ],
)
def test_categories_map_to_openscenario_classes(category, kind, osc):
    cls = road_user_class(category)
    assert (cls.kind, cls.category) == (kind, osc)


@pytest.mark.parametrize(
    "category, element, osi_type",
    [("cyclist", "Vehicle", "VEHICLE"), ("shopping trolley", "MiscObject", "OTHER")],
)
def test_other_categories_are_typed_in_openscenario_and_osi(tmp_path, category, element, osi_type):
    import json

    from conftest import EXAMPLES

    betterosi = pytest.importorskip("betterosi")
    doc = json.loads((EXAMPLES / "multi_scooter" / "clip.json").read_text())
    for frame in doc["annotations"]["frames"]:
        for obj in frame["objects"]:
            if obj["track_id"] == PED:
                obj["category"] = category
    clip = tmp_path / "clip.json"
    clip.write_text(json.dumps(doc))
    xosc = tmp_path / "out" / "scenario.xosc"
    assert main(["compile", str(clip), "--no-map", "-o", str(xosc)]) == 0
    obj, _ = _scenario_object(xosc, PED)
    el = obj.find(element)
    assert el is not None
    assert {p.get("name"): p.get("value") for p in el.iterfind("Properties/Property")}["objectType"] == category
    trace = tmp_path / "trace.mcap"
    assert main(["run", str(xosc), "--no-plots", "-o", str(tmp_path / "run"), "--osi", str(trace)]) == 0
    gt = next(iter(betterosi.read(trace)))
    names = [o.get("name") for o in parse_xml(xosc).getroot().iterfind("Entities/ScenarioObject")]
    (mo,) = [m for m in gt.moving_object if m.id.value == names.index(PED)]
    assert mo.type.name == osi_type  # (betterosi drops the TYPE_ prefix)


def test_a_road_user_seen_once_is_reported_not_replayed(tmp_path, capsys):
    """One observation gives no trajectory to follow: the compile says so and goes on."""
    import json

    from conftest import EXAMPLES

    doc = json.loads((EXAMPLES / "multi_scooter" / "clip.json").read_text())
    for frame in doc["annotations"]["frames"]:
        frame["objects"] = [o for o in frame["objects"] if o["track_id"] != PED]
    doc["annotations"]["frames"][3]["objects"].append({"track_id": "dog_1", "category": "dog", "x_m": 12.0, "y_m": 4.0})
    clip = tmp_path / "clip.json"
    clip.write_text(json.dumps(doc))
    xosc = tmp_path / "out" / "scenario.xosc"
    assert main(["compile", str(clip), "--no-map", "-o", str(xosc)]) == 0
    out = capsys.readouterr().out
    assert "track dog_1: category 'dog' observed once: no trajectory to replay; skipped" in out
    names = [o.get("name") for o in parse_xml(xosc).getroot().iterfind("Entities/ScenarioObject")]
    assert "dog_1" not in names and PED not in names


def test_the_compile_report_counts_the_other_road_users(multi):
    from vei_scenario.reports.compile_report import compile_report

    first = compile_report(multi).splitlines()[0]
    assert "ego + 3 e-scooter track(s) + 1 other road user(s) replayed as recorded" in first
    notes = "\n".join(multi.notes)
    assert "track ped_1: category 'pedestrian' replayed as recorded (a Pedestrian" in notes
