"""ASAM OSI ground-truth traces: read back with an independent reader (betterosi, its own generated
classes and MCAP decoder), compared with trajectories.csv and the scenario's entities."""

from __future__ import annotations

import csv
import math
import struct

import pytest

from vei_scenario.cli import main

betterosi = pytest.importorskip("betterosi")


def _csv_rows(path):
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    out: dict[str, list[dict]] = {}
    for r in rows:
        out.setdefault(r["entity"], []).append(r)
    return out


@pytest.fixture(scope="module")
def case_run(compiled, tmp_path_factory):
    out = tmp_path_factory.mktemp("osi")
    scenario = compiled["case_study"].written[0]
    args = ["run", str(scenario), "--param", "TimeShift=2.2", "--param", "RiderType=aggressive"]
    args += ["--param", "CapEnabled=true", "--no-plots", "-o", str(out / "run")]
    assert main(args + ["--osi", str(out / "trace.mcap")]) == 0
    assert main(args + ["--osi", str(out / "trace.osi")]) == 0
    return out


def test_mcap_trace_has_every_step_and_the_csv_poses(case_run):
    msgs = list(betterosi.read(case_run / "trace.mcap"))
    rows = _csv_rows(case_run / "run" / "trajectories.csv")
    names = list(rows)  # Ego, scooter_1: ids follow the scenario's entity order
    assert len(msgs) == len(rows["Ego"]) == 2502  # t = 0 .. 25.01 s at 100 Hz
    worst = 0.0
    for k, gt in enumerate(msgs):
        assert gt.host_vehicle_id.value == 0
        ns = gt.timestamp.seconds * 1_000_000_000 + gt.timestamp.nanos
        assert abs(ns * 1e-9 - float(rows["Ego"][k]["time_s"])) < 1e-9
        for mo in gt.moving_object:
            r = rows[names[mo.id.value]][k]
            # compiled entities: the reference point is the box centre, which OSI positions
            worst = max(worst, abs(mo.base.position.x - float(r["x_m"])), abs(mo.base.position.y - float(r["y_m"])))
            dyaw = mo.base.orientation.yaw - float(r["heading_rad"])
            assert abs(math.atan2(math.sin(dyaw), math.cos(dyaw))) < 1e-6
            v = math.hypot(mo.base.velocity.x, mo.base.velocity.y)
            assert v == pytest.approx(abs(float(r["speed_mps"])), abs=1e-5)
    assert worst <= 1e-6


def test_scooter_is_a_standup_scooter_and_the_map_is_referenced(case_run):
    gt = next(iter(betterosi.read(case_run / "trace.mcap")))
    types = {mo.id.value: (str(mo.type), str(mo.vehicle_classification.type)) for mo in gt.moving_object}
    assert "STANDUP_SCOOTER" in types[1][1] and "VEHICLE" in types[1][0]
    assert "CAR" in types[0][1]
    scooter = gt.moving_object[1]
    assert (scooter.base.dimension.length, scooter.base.dimension.width) == pytest.approx((1.2, 0.6))
    assert gt.map_reference == "scenario.xodr" and gt.proj_string.startswith("+proj=tmerc")
    assert (gt.version.version_major, gt.version.version_minor) == (3, 8)


def test_mcap_carries_the_osi_trace_metadata(case_run):
    meta = {m["name"]: m["data"] for m in betterosi.read_file_metadata(case_run / "trace.mcap")}
    osi = meta["net.asam.osi.trace"]
    assert osi["version"].startswith("3.8") and osi["min_osi_version"] and osi["max_protobuf_version"]
    assert "creation_time" not in osi  # no wall clock: the same run gives the same bytes
    channels = betterosi.read_channel_metadata(case_run / "trace.mcap")
    assert channels["ground_truth"]["net.asam.osi.trace.channel.osi_version"].startswith("3.8")


def test_binary_trace_is_length_prefixed_ground_truth(case_run):
    data = (case_run / "trace.osi").read_bytes()
    count, pos = 0, 0
    while pos < len(data):
        (n,) = struct.unpack_from("<I", data, pos)
        pos += 4 + n
        count += 1
    assert pos == len(data) and count == 2502
    msgs = list(betterosi.read(case_run / "trace.osi", osi_message_type="GroundTruth"))
    mcap = list(betterosi.read(case_run / "trace.mcap"))
    assert msgs[1234].moving_object[1].base.position == mcap[1234].moving_object[1].base.position


def test_same_run_same_trace_bytes(case_run, compiled, tmp_path):
    scenario = compiled["case_study"].written[0]
    args = ["run", str(scenario), "--param", "TimeShift=2.2", "--param", "RiderType=aggressive"]
    assert main(args + ["--param", "CapEnabled=true", "--osi", str(tmp_path / "again.mcap")]) == 0
    assert (tmp_path / "again.mcap").read_bytes() == (case_run / "trace.mcap").read_bytes()


def test_box_centre_velocity_and_pedestrian_type(tmp_path):
    """A third-party scenario: a car whose reference point is its rear axle (box centre 1.4 m ahead)
    and a pedestrian; OSI positions the box centre and types the pedestrian."""
    xosc = tmp_path / "walk.xosc"
    xosc.write_text(
        """<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork/>
<Entities>
 <ScenarioObject name="Car"><Vehicle name="Car" vehicleCategory="car"><ParameterDeclarations/>
  <BoundingBox><Center x="1.4" y="0" z="0.8"/><Dimensions width="2" length="5" height="1.6"/></BoundingBox>
  <Performance maxSpeed="60" maxAcceleration="5" maxDeceleration="9"/>
  <Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.7" positionX="2.8" positionZ="0.4"/>
  <RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.7" positionX="0" positionZ="0.4"/></Axles>
  <Properties/></Vehicle></ScenarioObject>
 <ScenarioObject name="Walker"><Pedestrian name="Walker" mass="80" pedestrianCategory="pedestrian">
  <BoundingBox><Center x="0" y="0" z="0.9"/><Dimensions width="0.5" length="0.5" height="1.8"/></BoundingBox>
  <Properties/></Pedestrian></ScenarioObject>
</Entities>
<Storyboard><Init><Actions>
 <Private entityRef="Car">
  <PrivateAction><TeleportAction><Position><WorldPosition x="0" y="0" h="0.5"/></Position>
  </TeleportAction></PrivateAction>
  <PrivateAction><LongitudinalAction><SpeedAction>
   <SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/>
   <SpeedActionTarget><AbsoluteTargetSpeed value="10"/></SpeedActionTarget>
   </SpeedAction></LongitudinalAction></PrivateAction>
 </Private>
 <Private entityRef="Walker">
  <PrivateAction><TeleportAction><Position><WorldPosition x="30" y="-5" h="1.5708"/></Position>
  </TeleportAction></PrivateAction>
  <PrivateAction><LongitudinalAction><SpeedAction>
   <SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/>
   <SpeedActionTarget><AbsoluteTargetSpeed value="1.5"/></SpeedActionTarget>
   </SpeedAction></LongitudinalAction></PrivateAction>
 </Private>
</Actions></Init>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising"><ByValueCondition>
 <SimulationTimeCondition value="2" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""
    )
    assert main(["run", str(xosc), "--no-plots", "-o", str(tmp_path / "r"), "--osi", str(tmp_path / "t.mcap")]) == 0
    rows = _csv_rows(tmp_path / "r" / "trajectories.csv")
    msgs = list(betterosi.read(tmp_path / "t.mcap"))
    car, walker = msgs[50].moving_object
    r = rows["Car"][50]
    h = float(r["heading_rad"])
    assert car.base.position.x == pytest.approx(float(r["x_m"]) + 1.4 * math.cos(h), abs=1e-6)
    assert car.base.position.y == pytest.approx(float(r["y_m"]) + 1.4 * math.sin(h), abs=1e-6)
    assert car.vehicle_attributes.bbcenter_to_rear.x == pytest.approx(-1.4)
    assert (car.base.velocity.x, car.base.velocity.y) == pytest.approx((10 * math.cos(0.5), 10 * math.sin(0.5)))
    assert "PEDESTRIAN" in str(walker.type)
    assert walker.base.velocity.y == pytest.approx(1.5, abs=1e-3)


def test_unknown_trace_suffix_is_refused_before_running(compiled, tmp_path, capsys):
    scenario = compiled["case_study"].written[0]
    assert main(["run", str(scenario), "--osi", str(tmp_path / "trace.txt")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "unknown trace format '.txt'" in err
    assert not any(tmp_path.iterdir())


def test_sweep_writes_traces_of_the_collisions(compiled, tmp_path):
    scenario = compiled["case_study"].written[0]
    args = ["sweep", str(scenario), "--vary", "TimeShift=0:3:1.5", "--vary", "RiderType=replay", "--quiet"]
    assert main(args + ["--osi-traces", "collisions", "-o", str(tmp_path / "s")]) == 0
    import json

    rows = json.loads((tmp_path / "s" / "catalog.json").read_text())["variants"]
    collided = {r["variant"] for r in rows if r["metrics"]["collision"]}
    traced = {int(p.stem.split("_")[1]) for p in (tmp_path / "s" / "traces").iterdir()}
    assert collided and traced == collided
    assert main(args + ["--osi-traces", "x,y", "-o", str(tmp_path / "bad")]) == 2


def test_osi_project_reader_accepts_the_mcap(case_run):
    """The OSI project's own trace reader (asam-osi-utilities) decodes the channel by its schema."""
    tracefile = pytest.importorskip("osi_utilities.tracefile")
    reader = tracefile.create_reader(case_run / "trace.mcap")
    assert reader.open(case_run / "trace.mcap")
    count, last = 0, None
    while reader.has_next():
        res = reader.read_message()
        if res is None or res.message is None:
            break
        count, last = count + 1, res.message
    reader.close()
    assert count == 2502 and type(last).__name__ == "GroundTruth"
    assert len(last.moving_object) == 2 and last.host_vehicle_id.value == 0
