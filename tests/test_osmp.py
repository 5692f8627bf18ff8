"""OSMP traffic participants (ASAM OSI Sensor Model Packaging FMUs) as the controller of an entity.

The partners in tests/data/osmp/ (the bad ones) and examples/osmp/ (StraightLine, SimpleAebOsmp) were
written from the OSMP specification and the OSI messages alone, without reading vei's code (their
sources, build script, README with the expected reports and their own minimal host are beside them):
what an integrator would bring. examples/osmp/TrajectoryFollower, which acts on the TrafficCommand,
was written later from the OSI messages on their shared base.
"""

from __future__ import annotations

import ctypes
import math
import os
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest

from vei_scenario.cli import main
from vei_scenario.interpreter import run_scenario
from vei_scenario.sut import ControllerFault, parse_controller_options

DATA = Path(__file__).parent / "data" / "osmp"  # (the bad partners, their build script and own host)
GOOD = Path(__file__).parents[1] / "examples" / "osmp"  # (the partners that behave: the guide's examples)
STANDING = DATA / "standing_car.xosc"


@pytest.fixture(scope="module")
def scenario(compiled) -> Path:
    return next(p for p in compiled["case_study"].written if p.name == "scenario.xosc")


def _vei(capsys, *argv) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    return code, out.out, out.err


def _standing(gap_m: float, lateral_m: float = 0.0, yaw: float = 0.4, speed: float = 20.0, end: float = 3.0):
    """The parameters that put the standing car ``gap_m`` ahead of the ego's front (box to box) and
    ``lateral_m`` to its left, both at heading ``yaw`` (the cars are 4.5 m long)."""
    along = gap_m + 4.5
    c, s = math.cos(yaw), math.sin(yaw)
    return {"EgoSpeed": speed, "EgoYaw": yaw, "LeadX": along * c - lateral_m * s, "LeadY": along * s + lateral_m * c,
            "EndTime": end}  # fmt: skip


@pytest.mark.parametrize("speed", [None, "7.5"])
def test_straight_line_goes_its_speed_along_its_first_heading(scenario, speed):
    """Analytic: after T s the host is speed_mps·T further along its initial heading, yaw unchanged."""
    specs = parse_controller_options([f"Ego={GOOD}/StraightLine.fmu"], [f"speed_mps={speed}"] if speed else None)
    r = run_scenario(scenario, controllers=specs)
    tr, t = r.traces["Ego"], np.asarray(r.t)
    v = float(speed or 10.0)
    yaw0 = tr.yaw[0]
    assert t[-1] > 20
    assert np.max(np.abs(np.asarray(tr.yaw) - yaw0)) == 0.0
    err = np.hypot(tr.x - (tr.x[0] + v * t * math.cos(yaw0)), tr.y - (tr.y[0] + v * t * math.sin(yaw0)))
    assert err.max() < 1e-9
    assert np.allclose(tr.speed[1:], v, atol=1e-12)


def test_simple_aeb_brakes_where_the_partners_analysis_says():
    """v0 = 20 m/s, gap 60.1 m, dt 0.02 s: braking starts at the first step k with gap0 − v0·dt·k <
    2·v0 (k = 51, t = 1.02 s); at 6 m/s² the speed 1.00 s later is 14.00 m/s."""
    specs = parse_controller_options([f"Ego={GOOD}/SimpleAebOsmp.fmu"])
    r = run_scenario(STANDING, _standing(60.1), dt=0.02, controllers=specs)
    tr, t = r.traces["Ego"], np.asarray(r.t)
    v = np.asarray(tr.speed)
    first = int(np.argmax(v < 20.0))  # the first sample after a braking step
    assert t[first - 1] == pytest.approx(1.02, abs=1e-12)
    j = np.arange(first - 1, first + 50)  # 1 s of braking at 6 m/s²
    assert np.max(np.abs(v[j] - (20.0 - 6.0 * (t[j] - 1.02)))) < 1e-9
    assert v[first + 49] == pytest.approx(14.0, abs=1e-9)
    # before braking, 20 m/s along the heading 0.4 rad from the origin
    d = np.hypot(tr.x[:first], tr.y[:first])
    assert np.max(np.abs(d - 20.0 * t[:first])) < 1e-9
    assert np.max(np.abs(np.arctan2(tr.y[1:first], tr.x[1:first]) - 0.4)) < 1e-12


@pytest.mark.parametrize(("lateral", "brakes"), [(2.0, True), (2.1, False), (-2.0, True)])
def test_simple_aeb_corridor_edge(lateral, brakes):
    """The corridor is the host's width + 0.5 m: a parallel car overlaps it iff |offset| ≤ 2.05 m;
    otherwise it keeps 20 m/s exactly (60 m in 3 s)."""
    specs = parse_controller_options([f"Ego={GOOD}/SimpleAebOsmp.fmu"])
    r = run_scenario(STANDING, _standing(60.1, lateral), dt=0.02, controllers=specs)
    tr = r.traces["Ego"]
    assert bool(min(tr.speed) < 20.0) is brakes
    if not brakes:
        k = int(np.argmin(np.abs(np.asarray(r.t) - 3.0)))
        assert math.hypot(tr.x[k], tr.y[k]) == pytest.approx(60.0, abs=1e-9)


BAD = {
    # partner: (exit code, the whole line after "vei: error: controller Ego=<path>")
    "WrongMime": (2, ": WrongMime.fmu: modelDescription.xml line 16: OSMPSensorViewIn: MIME type says "
                     "type=SensorData, OSMP requires type=SensorView for this variable"),
    "ZeroSize": (1, " at t = 0.00 s: no TrafficUpdate produced (OSMPTrafficUpdateOut has size 0)"),
    "WrongId": (1, " at t = 0.00 s: the TrafficUpdate is for id 1 (scooter_1), not the host's id 0 (Ego)"),
    "NeverWrites": (1, " at t = 0.00 s: no TrafficUpdate produced (OSMPTrafficUpdateOut has a null address)"),
}  # fmt: skip


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_partners_are_one_line_and_nothing_is_written(scenario, tmp_path, capsys, name):
    code, out, err = _vei(capsys, "run", scenario, "--controller", f"Ego={DATA}/{name}.fmu", "-o", tmp_path / "r")
    want_code, tail = BAD[name]
    assert (code, err) == (want_code, f"vei: error: controller Ego={DATA}/{name}.fmu{tail}\n")
    assert not (tmp_path / "r").exists()


@pytest.mark.parametrize("name", ["ZeroSize", "WrongId", "NeverWrites"])
def test_a_study_of_a_clip_with_a_bad_partner_writes_nothing(tmp_path, capsys, name):
    """The clip is compiled for the study, but its scenario joins the outputs only once every
    configuration has run: a partner failing in configuration 4 leaves no folder behind."""
    clip = Path(__file__).parents[1] / "examples" / "case_study" / "clip.json"
    code, out, err = _vei(capsys, "study", clip, "--controller", f"Ego={DATA}/{name}.fmu", "-o", tmp_path / "s")
    assert (code, err) == (1, f"vei: error: controller Ego={DATA}/{name}.fmu{BAD[name][1]}\n")
    assert not (tmp_path / "s").exists()


def _repacked(tmp_path: Path, source: Path, old: str, new: str) -> Path:
    """A copy of ``source`` whose modelDescription.xml has ``old`` replaced by ``new``."""
    out = tmp_path / source.name
    with zipfile.ZipFile(source) as zin, zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as zout:
        for item in zin.infolist():
            data = zin.read(item)
            if item.filename == "modelDescription.xml":
                assert old.encode() in data
                data = data.replace(old.encode(), new.encode())
            zout.writestr(item, data)
    return out


@pytest.mark.parametrize(
    ("version", "reason"),
    [("4.0.0", "OSI 4.0.0, this host speaks OSI 3."), ("3.99.0", "OSI 3.99.0 is newer than this host's OSI 3.")],
)
def test_an_osi_version_this_host_cannot_speak_is_refused_at_load(tmp_path, version, reason):
    fmu = _repacked(tmp_path, GOOD / "StraightLine.fmu", "type=SensorView; version=3.7.0",
                    f"type=SensorView; version={version}")  # fmt: skip
    with pytest.raises(ControllerFault, match="OSMPSensorViewIn: " + reason.replace(".", r"\.")):
        parse_controller_options([f"Ego={fmu}"])


def test_a_model_without_the_osmp_model_annotation_is_no_participant(tmp_path):
    fmu = _repacked(tmp_path, GOOD / "StraightLine.fmu", 'osi-version="3.7.0"', 'osi-version="3.7.0" x="net.pmsf.osmp"')
    assert parse_controller_options([f"Ego={fmu}"])[0].osmp  # (the annotation is what counts, not the text)
    fmu2 = tmp_path / "b" / "StraightLine.fmu"
    fmu2.parent.mkdir()
    ns = 'xmlns:osmp="http://xsd.pmsf.net/OSISensorModelPackaging">'
    fmu2 = _repacked(fmu2.parent, GOOD / "StraightLine.fmu", f"{ns}<osmp:osmp ", f"{ns}<osmp:other ")
    with pytest.raises(ControllerFault, match=r"no <VendorAnnotations><Tool name=\"net.pmsf.osmp\">"):
        parse_controller_options([f"Ego={fmu2}"])


def test_a_malformed_traffic_update_is_one_line(monkeypatch, scenario):
    """The output's bytes must decode as osi3.TrafficUpdate (a stub FMU hands out garbage)."""
    from vei_scenario.sut import osmp

    garbage = ctypes.create_string_buffer(b"\xff\xff\xff\xff\xff", 5)
    lo, hi = osmp.split_address(ctypes.addressof(garbage))

    class Stub:
        def setInteger(self, vrs, values):
            pass

        def doStep(self, **kw):
            pass

        def getInteger(self, vrs):
            return [lo, hi, 5]

        def terminate(self):
            pass

        def freeInstance(self):
            pass

    specs = parse_controller_options([f"Ego={GOOD}/StraightLine.fmu"])
    real_init = osmp.OsmpParticipant.__init__

    def init(self, *a, **kw):
        real_init(self, *a, **kw)
        self.fmu.terminate()
        self.fmu.freeInstance()
        self.fmu = Stub()

    monkeypatch.setattr(osmp.OsmpParticipant, "__init__", init)
    with pytest.raises(ControllerFault, match=r"at t = 0.00 s: OSMPTrafficUpdateOut: 5 bytes that are no osi3\.Tr"):
        run_scenario(scenario, controllers=specs)


def _recorded(monkeypatch, scenario, parameters=None, entity="Ego"):
    """(SensorViews, TrafficCommands) given to StraightLine over a run, decoded."""
    from osi3.osi_sensorview_pb2 import SensorView
    from osi3.osi_trafficcommand_pb2 import TrafficCommand

    from vei_scenario.sut import osmp

    views, commands = [], []
    real_step = osmp.OsmpParticipant.step

    def step(self, view, command, *a, **kw):
        views.append(SensorView.FromString(view))
        commands.append(TrafficCommand.FromString(command) if command is not None else None)
        return real_step(self, view, command, *a, **kw)

    monkeypatch.setattr(osmp.OsmpParticipant, "step", step)
    r = run_scenario(scenario, parameters, controllers=parse_controller_options([f"{entity}={GOOD}/StraightLine.fmu"]))
    return r, views, commands


def test_the_sensor_view_holds_every_object_with_its_osi_type(monkeypatch, scenario):
    from osi3.osi_object_pb2 import MovingObject

    r, views, _ = _recorded(monkeypatch, scenario)
    first = views[0]
    gt = first.global_ground_truth
    assert first.host_vehicle_id.value == gt.host_vehicle_id.value == 0
    by_id = {m.id.value: m for m in gt.moving_object}
    assert sorted(by_id) == [0, 1]
    scooter = by_id[1]
    assert scooter.type == MovingObject.TYPE_VEHICLE
    assert scooter.vehicle_classification.type == MovingObject.VehicleClassification.TYPE_STANDUP_SCOOTER
    assert by_id[0].vehicle_classification.type == MovingObject.VehicleClassification.TYPE_MEDIUM_CAR
    assert gt.map_reference.endswith(".xodr")
    # the host at each step's start is where the run recorded it (box centre)
    tr = r.traces["Ego"]
    for k in (0, 100, 1000):
        host = next(m for m in views[k].global_ground_truth.moving_object if m.id.value == 0)
        cx = tr.x[k] + math.cos(tr.yaw[k]) * tr.center_x
        assert host.base.position.x == pytest.approx(cx, abs=1e-9)
        assert views[k].timestamp.seconds + views[k].timestamp.nanos * 1e-9 == pytest.approx(r.t[k], abs=1e-9)


def test_the_traffic_command_carries_the_storyboards_speed_actions(monkeypatch):
    """following_brake.xosc: Ego's Init sets 10 m/s (a step); at a gap of 20 m the story asks for 5 m/s
    over 2 s (linear), 0.5 s after that for 4 m/s (a step)."""
    from osi3.osi_trafficcommand_pb2 import TrafficAction

    _, _, commands = _recorded(monkeypatch, Path(__file__).parent / "data" / "following_brake.xosc")
    told = [(k, a.speed_action) for k, c in enumerate(commands) for a in c.action if a.HasField("speed_action")]
    assert [(a.absolute_target_speed, a.dynamics_shape, a.duration) for _, a in told] == [
        (10.0, TrafficAction.DYNAMICS_SHAPE_STEP, 0.0),
        (5.0, TrafficAction.DYNAMICS_SHAPE_LINEAR, 2.0),
        (4.0, TrafficAction.DYNAMICS_SHAPE_STEP, 0.0),
    ]
    assert [a.action_header.action_id.value for _, a in told] == [1, 2, 3]
    assert all(c.traffic_participant_id.value == 0 for c in commands)
    assert told[0][0] == 0


def test_a_sweep_hosts_the_participant_in_every_variant(scenario, tmp_path, capsys):
    code, out, err = _vei(capsys, "sweep", scenario, "--vary", "TimeShift=0:1:1", "--workers", "2", "--quiet",
                          "--controller", f"Ego={GOOD}/StraightLine.fmu", "-o", tmp_path)  # fmt: skip
    assert code == 0 and "2 variants (TimeShift): 0 collide (0 with the ego moving), 2 do not, 0 failed" in out


def test_the_partners_own_host_agrees(tmp_path):
    """The partners' own minimal host (host_alone.py) passes its analytic checks on this machine."""
    shutil.copytree(DATA, tmp_path / "p")
    for fmu in GOOD.glob("*.fmu"):  # (its host finds every partner beside it)
        shutil.copy(fmu, tmp_path / "p")
    done = subprocess.run([sys.executable, "host_alone.py"], cwd=tmp_path / "p", capture_output=True, text=True,
                          timeout=300)  # fmt: skip
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]


def test_the_same_run_gives_the_same_bytes(scenario, tmp_path, capsys):
    for out in ("a", "b"):
        code, _, _ = _vei(capsys, "run", scenario, "--controller", f"Ego={GOOD}/SimpleAebOsmp.fmu",
                          "--param", "TimeShift=2.197", "-o", tmp_path / out, "--no-plots")  # fmt: skip
        assert code == 0
    a, b = ((tmp_path / o / "trajectories.csv").read_bytes() for o in ("a", "b"))
    assert a == b and b",osmp\n" in a


def test_risk_hosts_the_participant(scenario, capsys):
    """The AEB keeps its first speed and brakes at TTC < 2 s on its own speed: against the crossing
    rider it collides where the rider comes late enough."""
    code, out, _ = _vei(capsys, "risk", scenario, "--controller", f"Ego={GOOD}/SimpleAebOsmp.fmu",
                        "--window", "1:3", "--coarse", "0.5", "--tol", "0.1", "--workers", "1")  # fmt: skip
    assert code == 0 and "collision : TimeShift +2.000..+3.000 s" in out


def test_a_scenario_controller_naming_a_participant_drives_as_the_storyboard_activates(scenario, tmp_path):
    """A Controller whose property ``module`` names an OSMP FMU (found from the scenario's directory):
    in charge of both domains once activated (the case study activates the ego's with CapEnabled)."""
    from lxml import etree

    tree = etree.parse(str(scenario))
    props = tree.find("Entities/ScenarioObject[@name='Ego']/ObjectController/Controller/Properties")
    etree.SubElement(props, "Property", name="module", value="StraightLine.fmu")
    etree.SubElement(props, "Property", name="speed_mps", value="4")
    for f in scenario.parent.iterdir():
        if f.suffix == ".xodr":
            (tmp_path / f.name).write_bytes(f.read_bytes())
    shutil.copy(GOOD / "StraightLine.fmu", tmp_path)
    path = tmp_path / "scenario.xosc"
    tree.write(str(path))
    on = run_scenario(path, {"CapEnabled": "true"})
    ego = on.traces["Ego"]
    steps = [k for k, s in enumerate(ego.status) if s == "osmp"]
    assert steps and np.allclose(np.asarray(ego.speed)[steps], 4.0, atol=1e-12)
    off = run_scenario(path, {"CapEnabled": "false"})  # never activated: the default controller drives
    assert "osmp" not in off.traces["Ego"].status


@pytest.mark.parametrize("name", sorted(BAD))
def test_a_scenario_controller_naming_a_bad_partner_is_one_line_naming_its_entity(scenario, tmp_path, capsys, name):
    """The same lines as with --controller, the controller named by its entity and module."""
    from lxml import etree

    tree = etree.parse(str(scenario))
    props = tree.find("Entities/ScenarioObject[@name='Ego']/ObjectController/Controller/Properties")
    etree.SubElement(props, "Property", name="module", value=f"{name}.fmu")
    for f in scenario.parent.iterdir():
        if f.suffix == ".xodr":
            (tmp_path / f.name).write_bytes(f.read_bytes())
    shutil.copy(DATA / f"{name}.fmu", tmp_path)
    tree.write(str(tmp_path / "scenario.xosc"))
    code, out, err = _vei(capsys, "run", tmp_path / "scenario.xosc", "--param", "CapEnabled=true",
                          "-o", tmp_path / "r", "--no-plots")  # fmt: skip
    want_code, tail = BAD[name]
    assert (code, err) == (want_code, f"vei: error: controller Ego={name}.fmu{tail}\n")
    assert not (tmp_path / "r").exists()


def test_the_sensor_view_holds_the_roads_lanes(monkeypatch, scenario):
    """One OSI lane per OpenDRIVE lane and lane section (counted in the .xodr itself), ids after the
    objects' and unique, centre lines sampled at most 2 m apart along the reference line (the points
    counted from the .xodr's section lengths), neighbours each other's."""
    from lxml import etree

    _, views, _ = _recorded(monkeypatch, scenario)
    gt = views[0].global_ground_truth
    xodr = next(scenario.parent.glob("*.xodr"))
    lanes, points = 0, 0
    for road in etree.parse(str(xodr)).getroot().iterfind("road"):
        sections = road.findall("lanes/laneSection")
        starts = [float(sec.get("s")) for sec in sections] + [float(road.get("length"))]
        for k, sec in enumerate(sections):
            n = sum(1 for lane in sec.iterfind("*/lane") if int(lane.get("id")) != 0)
            lanes += n
            points += n * (
                max(1, math.ceil((starts[k + 1] - starts[k] - (1e-9 if k + 1 < len(sections) else 0)) / 2.0)) + 1
            )
    assert len(gt.lane) == lanes > 100
    assert sum(len(lane.classification.centerline) for lane in gt.lane) == points
    ids = [lane.id.value for lane in gt.lane]
    assert len(set(ids)) == len(ids) and min(ids) == len(gt.moving_object) + len(gt.stationary_object)
    by_id = {lane.id.value: lane for lane in gt.lane}
    for lane in gt.lane:
        for left in lane.classification.left_adjacent_lane_id:
            assert lane.id.value in [r.value for r in by_id[left.value].classification.right_adjacent_lane_id]
    assert views[1].global_ground_truth.lane[5] == gt.lane[5]  # (the same every step)


#: trajectory_car.xosc's vertices (trajectory time, x, y, heading) and Ego's box centre ahead of its
#: reference point (Center.x 0, the rear axle 1.4 m behind)
TURN = np.array([(0.0, 0.0, 0.0, 0.0), (1.0, 10.0, 0.0, 0.0), (3.0, 20.0, 0.0, 0.0), (4.0, 20.0, 10.0, math.pi / 2)])
CENTRE_X = 1.4


def _centres(trace) -> tuple[np.ndarray, np.ndarray]:
    return trace.x + np.cos(trace.yaw) * CENTRE_X, trace.y + np.sin(trace.yaw) * CENTRE_X


def _follower_commands(monkeypatch, scenario, parameters=None):
    """The run of TrajectoryFollower on Ego and the TrafficCommands it was given, decoded."""
    from osi3.osi_trafficcommand_pb2 import TrafficCommand

    from vei_scenario.sut import osmp

    commands = []
    real_step = osmp.OsmpParticipant.step

    def step(self, view, command, *a, **kw):
        commands.append(TrafficCommand.FromString(command))
        return real_step(self, view, command, *a, **kw)

    monkeypatch.setattr(osmp.OsmpParticipant, "step", step)
    specs = parse_controller_options([f"Ego={GOOD}/TrajectoryFollower.fmu"])
    return run_scenario(scenario, parameters, controllers=specs), commands


@pytest.mark.parametrize("offset", [0.0, -0.5])
def test_a_timed_trajectory_is_told_as_trajectory_points_and_followed(monkeypatch, offset):
    """The FollowTrajectoryAction arrives at the first step as follow_trajectory_action: one point per
    vertex, at the simulation time its timing plays it (trajectory time − offset), posed at the box
    centre; the participant acting on it (linear in time between the points) puts Ego's box centre
    on the line between the points at every step until the last point's time."""
    from osi3.osi_trafficcommand_pb2 import TrafficAction

    r, commands = _follower_commands(monkeypatch, DATA / "trajectory_car.xosc", {"Offset": offset})
    told = [(k, a.follow_trajectory_action) for k, c in enumerate(commands) for a in c.action
            if a.HasField("follow_trajectory_action")]  # fmt: skip
    assert [k for k, _ in told] == [0]
    a = told[0][1]
    assert a.following_mode == TrafficAction.FOLLOWING_MODE_POSITION and a.constrain_orientation
    assert a.action_header.action_id.value == 2  # (after the Init's speed)
    ts = TURN[:, 0] - offset
    cx, cy = TURN[:, 1] + CENTRE_X * np.cos(TURN[:, 3]), TURN[:, 2] + CENTRE_X * np.sin(TURN[:, 3])
    got = np.array([(p.timestamp.seconds + p.timestamp.nanos * 1e-9, p.position.x, p.position.y, p.orientation.yaw)
                    for p in a.trajectory_point])  # fmt: skip
    assert np.allclose(got, np.column_stack([ts, cx, cy, TURN[:, 3]]), atol=1e-12, rtol=0)
    tr, t = r.traces["Ego"], np.asarray(r.t)
    k = (t > ts[0]) & (t <= ts[-1] + 1e-9)
    x, y = _centres(tr)
    assert np.max(np.hypot(x[k] - np.interp(t[k], ts, cx), y[k] - np.interp(t[k], ts, cy))) < 1e-9
    assert np.max(np.abs(tr.yaw[k] - np.interp(t[k], ts, TURN[:, 3]))) < 1e-9
    assert set(tr.status[1:]) == {"osmp"}


def test_an_untimed_trajectory_is_told_as_path_points_and_followed(monkeypatch):
    """Without timing the vertices arrive as follow_path_action (no times); the participant drives
    them at its commanded 10 m/s: its box centre is 10·t along the polyline of the points."""
    r, commands = _follower_commands(monkeypatch, DATA / "path_car.xosc")
    told = [a.follow_path_action for c in commands for a in c.action if a.HasField("follow_path_action")]
    assert len(told) == 1 and not any(a.HasField("follow_trajectory_action") for c in commands for a in c.action)
    pts = np.array([(p.position.x, p.position.y) for p in told[0].path_point])
    cx, cy = TURN[:, 1] + CENTRE_X * np.cos(TURN[:, 3]), TURN[:, 2] + CENTRE_X * np.sin(TURN[:, 3])
    assert np.allclose(pts, np.column_stack([cx, cy]), atol=1e-12, rtol=0)
    assert not told[0].path_point[0].HasField("timestamp")
    s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(cx), np.diff(cy)))])
    tr, t = r.traces["Ego"], np.asarray(r.t)
    k = 10.0 * t <= s[-1]
    x, y = _centres(tr)
    assert np.max(np.hypot(x[k] - np.interp(10.0 * t[k], s, cx), y[k] - np.interp(10.0 * t[k], s, cy))) < 1e-9


def test_a_misc_object_that_moves_is_a_moving_object_in_the_sensor_view_as_in_the_trace(monkeypatch):
    """misc_objects.xosc: two hand carts (MiscObjects replayed from t = 0 and from t = 1 s) are moving
    objects of TYPE_OTHER in every SensorView, the cone that stays is a stationary object: the same
    split, ids and types as vei's OSI trace of the run."""
    from osi3.osi_object_pb2 import MovingObject

    from vei_scenario.reports.osi_trace import ground_truths

    r, views, _ = _recorded(monkeypatch, DATA / "misc_objects.xosc")
    traced = [(sorted((m.id.value, m.type) for m in gt.moving_object), sorted(s.id.value for s in gt.stationary_object))
              for gt in ground_truths(r)]  # fmt: skip
    other = MovingObject.TYPE_OTHER
    assert traced[0] == ([(0, MovingObject.TYPE_VEHICLE), (1, MovingObject.TYPE_VEHICLE), (2, other), (3, other)], [4])
    for k, v in enumerate(views):
        gt = v.global_ground_truth
        shown = (
            sorted((m.id.value, m.type) for m in gt.moving_object),
            sorted(s.id.value for s in gt.stationary_object),
        )
        assert shown == traced[k]
    cart = next(m for m in views[150].global_ground_truth.moving_object if m.id.value == 2)
    assert (cart.base.velocity.x, cart.base.velocity.y) == pytest.approx((0.0, 1.2), abs=1e-9)


def _trace_poses(path: Path) -> list[dict[str, tuple[float, float, float]]]:
    """Each message of an OSI trace, read by the OSI project's own reader (asam-osi-utilities): the
    reference point (x, y) and yaw of every object by its source id (the rear axle of a vehicle:
    box centre + bbcenter_to_rear, turned by the yaw; the box centre of any other object)."""
    tracefile = pytest.importorskip("osi_utilities.tracefile")
    reader = tracefile.create_reader(path)
    assert reader.open(path)
    out = []
    while reader.has_next():
        res = reader.read_message()
        if res is None or res.message is None:
            break
        gt = res.message
        poses = {}
        for obj in (*gt.moving_object, *gt.stationary_object):
            b, yaw = obj.base, obj.base.orientation.yaw
            vehicle = "vehicle_attributes" in obj.DESCRIPTOR.fields_by_name and obj.HasField("vehicle_attributes")
            rear = obj.vehicle_attributes.bbcenter_to_rear if vehicle else None
            dx, dy = (rear.x, rear.y) if rear is not None else (0.0, 0.0)
            poses[obj.id.value] = (b.position.x + dx * math.cos(yaw) - dy * math.sin(yaw),
                                   b.position.y + dx * math.sin(yaw) + dy * math.cos(yaw), yaw)  # fmt: skip
        out.append(poses)
    reader.close()
    return out


@pytest.mark.parametrize("case", ["multi_scooter", "misc_objects"])
def test_the_trace_of_a_run_with_hosted_participants_reads_back_as_trajectories_csv(compiled, tmp_path, capsys, case):
    """A run with OSMP participants hosted (multi_scooter: the ego following its path, one rider
    going straight; misc_objects: the ego going straight among replayed carts and a cone) writes its
    OSI trace; the OSI project's reader gives every object of every step, the hosted ones too, at the
    pose of trajectories.csv (written to 1e-6 m and rad) within 1e-6 m, and its heading within 1e-6 rad."""
    import csv

    if case == "multi_scooter":
        scenario = next(p for p in compiled["multi_scooter"].written if p.name == "scenario.xosc")
        hosted = {"Ego": "TrajectoryFollower", "scooter_1": "StraightLine"}
    else:
        scenario, hosted = DATA / "misc_objects.xosc", {"Ego": "StraightLine"}
    options = [a for n, fmu in hosted.items() for a in ("--controller", f"{n}={GOOD}/{fmu}.fmu")]
    code, _, err = _vei(capsys, "run", scenario, *options, "-o", tmp_path / "r", "--no-plots",
                        "--osi", tmp_path / "trace.mcap")  # fmt: skip
    assert code == 0, err
    with (tmp_path / "r" / "trajectories.csv").open() as f:
        rows = list(csv.DictReader(f))
    names = list(dict.fromkeys(r["entity"] for r in rows))
    poses = _trace_poses(tmp_path / "trace.mcap")
    assert len(poses) * len(names) == len(rows)
    for n in hosted:
        assert {r["controller_state"] for r in rows if r["entity"] == n} - {"default"} == {"osmp"}
    worst_m = worst_rad = 0.0
    for k, row in enumerate(rows):
        x, y, yaw = poses[k // len(names)][names.index(row["entity"])]
        worst_m = max(worst_m, math.hypot(x - float(row["x_m"]), y - float(row["y_m"])))
        worst_rad = max(worst_rad, abs(math.remainder(yaw - float(row["heading_rad"]), math.tau)))
    assert worst_m <= 1e-6 and worst_rad <= 1e-6, (worst_m, worst_rad)


def _ld_files(tmp_path, name, *argv) -> tuple[subprocess.CompletedProcess, str]:
    """``python -m vei_scenario ARGV`` with the dynamic loader's file log (glibc's LD_DEBUG=files)."""
    log = tmp_path / f"{name}.ld"
    env = dict(os.environ, LD_DEBUG="files", LD_DEBUG_OUTPUT=str(log))
    done = subprocess.run([sys.executable, "-m", "vei_scenario", *map(str, argv)], env=env, capture_output=True,
                          text=True, timeout=300)  # fmt: skip
    text = "".join(p.read_text(errors="replace") for p in tmp_path.glob(f"{name}.ld*"))
    return done, text


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc's loader log (LD_DEBUG) is Linux-only")
def test_a_command_that_hosted_a_pythonfmu_partner_ends_without_its_finaliser(scenario, tmp_path):
    """StraightLine.fmu (built with PythonFMU) reads freed memory in its library finaliser when run at the
    exit of a Python host; the command's success must not hang on it, so the process ends after Python's
    own exit work (the extracted FMU removed) without calling the library's fini."""
    plain, plain_log = _ld_files(tmp_path, "plain", "validate", scenario)
    if "calling fini" not in plain_log:
        pytest.skip("this loader does not log its finalisers")
    assert plain.returncode == 0 and "calling fini" in plain_log  # (no FMU: an ordinary exit)
    done, log = _ld_files(tmp_path, "hosted", "run", scenario, "--controller", f"Ego={GOOD}/StraightLine.fmu",
                          "--controller-param", "speed_mps=6", "-o", tmp_path / "run", "--no-plots")  # fmt: skip
    assert done.returncode == 0, done.stderr[-2000:]
    assert (tmp_path / "run" / "metrics.json").is_file()
    loaded = re.findall(r"file=(\S*StraightLine\.so)", log)
    assert loaded, "the loader log shows the partner's library loaded"
    assert not re.search(r"calling fini: \S*StraightLine\.so", log)
    assert not Path(loaded[0]).exists()  # (the atexit handler removed the extracted FMU)
