"""ASAM OpenLABEL 1.0 clips: the bundled clips round-trip and compile to the same bytes; annotations
written another way (sensor frames, Euler angles, ISO times, no exact fixes) compile to the same
scene; bad OpenLABEL is one line naming the JSON path."""

from __future__ import annotations

import copy
import json
import math
import re

import pytest

from conftest import EXAMPLE_NAMES, EXAMPLES
from vei_scenario.cli import main

FILES = ("scenario.xosc", "scenario.xodr", "scenario.variations.xosc")


@pytest.mark.parametrize("name", EXAMPLE_NAMES)
def test_bundled_clip_round_trips_and_compiles_to_identical_bytes(name, tmp_path, capsys):
    ol, back = tmp_path / "clip.openlabel.json", tmp_path / "back.json"
    assert main(["clip", "convert", str(EXAMPLES / name / "clip.json"), "-o", str(ol)]) == 0
    assert main(["clip", "convert", str(ol), "-o", str(back)]) == 0
    doc = json.loads(ol.read_text())
    assert doc["openlabel"]["metadata"]["schema_version"] == "1.0.0"
    for src, out in ((EXAMPLES / name / "clip.json", "a"), (ol, "b"), (back, "c")):
        assert main(["compile", str(src), "-o", str(tmp_path / out / "scenario.xosc")]) == 0
    for f in FILES:
        ref = (tmp_path / "a" / f).read_bytes()
        assert (tmp_path / "b" / f).read_bytes() == ref, f
        assert (tmp_path / "c" / f).read_bytes() == ref, f


def test_openlabel_output_passes_the_schema_independently(tmp_path):
    """Checked with jsonschema against the VCD library's OpenLABEL 1.0 schema, outside vei's code."""
    import jsonschema
    from vcd import schema

    ol = tmp_path / "c.json"
    assert main(["clip", "convert", str(EXAMPLES / "multi_scooter" / "clip.json"), "-o", str(ol)]) == 0
    doc = json.loads(ol.read_text())
    jsonschema.Draft7Validator(schema.openlabel_schema).validate(doc)
    systems = doc["openlabel"]["coordinate_systems"]
    assert systems["vehicle-iso8855"]["parent"] == "odom" and systems["odom"]["type"] == "scene_cs"
    frame = next(f for f in doc["openlabel"]["frames"].values() if "transforms" in f["frame_properties"])
    tr = frame["frame_properties"]["transforms"]["vehicle-iso8855_to_odom"]
    assert len(tr["transform_src_to_dst"]["quaternion"]) == 4


def _foreign(doc: dict) -> dict:
    """The same annotation as another tool might write it: cuboids in a lidar frame 1.5 m ahead of
    the vehicle origin and 1.8 m up, ego poses as Euler angles, ISO 8601 times, a differently
    spelled class, no exact GNSS fixes, the world placed by its origin, no vei metadata."""
    from datetime import datetime, timezone

    d = copy.deepcopy(doc)
    ol = d["openlabel"]
    ol["metadata"] = {"schema_version": "1.0.0", "name": "foreign-annotation"}
    proj = ol["coordinate_systems"]["odom"].pop("geo_reference")["proj"]
    lat0 = float(re.search(r"lat_0=([-0-9.]+)", proj).group(1))
    lon0 = float(re.search(r"lon_0=([-0-9.]+)", proj).group(1))
    ol["coordinate_systems"]["odom"]["geo_reference"] = {"lat_deg": lat0, "lon_deg": lon0}
    ol["coordinate_systems"].pop("vehicle-sae-j670", None)
    ol["coordinate_systems"]["vehicle-iso8855"]["children"] = ["lidar"]
    ol["coordinate_systems"]["lidar"] = {
        "type": "sensor_cs",
        "parent": "vehicle-iso8855",
        "pose_wrt_parent": {"euler_angles": [0.0, 0.0, 0.0], "translation": [1.5, 0.0, 1.8]},
    }
    y_right = doc["openlabel"]["metadata"]["vei_clip"]["annotations"]["y_axis"] == "right"
    for obj in ol["objects"].values():
        obj["type"] = "E-Scooter" if obj["type"] == "e-scooter" else obj["type"]
    for f in ol["frames"].values():
        props = f["frame_properties"]
        props["timestamp"] = datetime.fromtimestamp(props["timestamp"], timezone.utc).isoformat()
        for tr in props.get("transforms", {}).values():
            tr.pop("gnss")
            q = tr["transform_src_to_dst"].pop("quaternion")
            tr["transform_src_to_dst"]["euler_angles"] = [2 * math.atan2(q[2], q[3]), 0.0, 0.0]
            tr["transform_src_to_dst"]["sequence"] = "ZYX"
        for od in f.get("objects", {}).values():
            for c in od["object_data"]["cuboid"]:
                x, y, z = c["val"][:3]
                y = -y if y_right else y
                c["val"][:3] = [x - 1.5, y, z - 1.8]
                c["coordinate_system"] = "lidar"
    return d


def _vertices(xosc, entity):
    from lxml import etree

    root = etree.parse(str(xosc)).getroot()
    out = []
    for traj in root.iter("Trajectory"):
        if traj.get("name", "").startswith(entity):
            for v in traj.iter("Vertex"):
                p = v.find("Position/WorldPosition")
                out.append((float(v.get("time")), float(p.get("x")), float(p.get("y"))))
    return out


def test_annotation_written_another_way_gives_the_same_scene(tmp_path):
    ol = tmp_path / "c.json"
    assert main(["clip", "convert", str(EXAMPLES / "no_map" / "clip.json"), "-o", str(ol)]) == 0
    foreign = tmp_path / "foreign.json"
    foreign.write_text(json.dumps(_foreign(json.loads(ol.read_text()))))
    assert main(["compile", str(EXAMPLES / "no_map" / "clip.json"), "-o", str(tmp_path / "a" / "s.xosc")]) == 0
    assert main(["compile", str(foreign), "-o", str(tmp_path / "b" / "s.xosc")]) == 0
    a, b = _vertices(tmp_path / "a" / "s.xosc", "scooter"), _vertices(tmp_path / "b" / "s.xosc", "scooter")
    assert a and len(a) == len(b)
    worst = max(math.hypot(p[1] - q[1], p[2] - q[2]) for p, q in zip(a, b))
    assert worst < 0.05  # only the ego speed is derived from poses instead of read from the GNSS


def _case_openlabel(tmp_path, name: str = "no_map") -> dict:
    ol = tmp_path / "c.json"
    assert main(["clip", "convert", str(EXAMPLES / name / "clip.json"), "-o", str(ol)]) == 0
    return json.loads(ol.read_text())


def _bad(tmp_path, capsys, doc, *options: str) -> str:
    p = tmp_path / "bad.json"
    p.write_text(json.dumps(doc))
    assert main(["compile", str(p), *options, "-o", str(tmp_path / "out" / "s.xosc")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert not (tmp_path / "out").exists()
    return err


def test_unknown_coordinate_system_names_the_cuboid(tmp_path, capsys):
    doc = _case_openlabel(tmp_path)
    k, f = next((k, f) for k, f in doc["openlabel"]["frames"].items() if f.get("objects"))
    uid = next(iter(f["objects"]))
    f["objects"][uid]["object_data"]["cuboid"][0]["coordinate_system"] = "camera-7"
    err = _bad(tmp_path, capsys, doc)
    assert f"openlabel.frames.{k}.objects.{uid}.object_data.cuboid[0].coordinate_system" in err
    assert "unknown coordinate system 'camera-7'" in err


def test_missing_transforms_are_refused(tmp_path, capsys):
    doc = _case_openlabel(tmp_path)
    for f in doc["openlabel"]["frames"].values():
        f["frame_properties"].pop("transforms", None)
    assert "no ego odometry" in _bad(tmp_path, capsys, doc)


def test_scooter_without_cuboids_is_refused(tmp_path, capsys):
    doc = _case_openlabel(tmp_path)
    for f in doc["openlabel"]["frames"].values():
        for od in f.get("objects", {}).values():
            od["object_data"] = {"num": [{"name": "score", "val": 0.9}]}
    err = _bad(tmp_path, capsys, doc)
    assert "openlabel.objects.0" in err and "no cuboid" in err


def test_missing_pose_and_timestamp_and_schema_errors(tmp_path, capsys):
    doc = _case_openlabel(tmp_path, "stop_and_go")  # (annotated with y to the right: a y-flipped frame)
    doc["openlabel"]["metadata"]["vei_clip"].pop("map", None)
    doc["openlabel"]["coordinate_systems"]["vehicle-sae-j670"].pop("pose_wrt_parent")
    assert "coordinate_systems.vehicle-sae-j670.pose_wrt_parent: missing" in _bad(tmp_path, capsys, doc)
    doc = _case_openlabel(tmp_path)
    first = next(iter(doc["openlabel"]["frames"].values()))
    first["frame_properties"].pop("timestamp")
    assert "frame_properties.timestamp: missing" in _bad(tmp_path, capsys, doc)
    doc = _case_openlabel(tmp_path)
    doc["openlabel"]["objects"]["0"]["name"] = 7
    assert "openlabel.objects.0.name: not valid OpenLABEL 1.0" in _bad(tmp_path, capsys, doc)
    doc = _case_openlabel(tmp_path)
    doc["openlabel"]["metadata"]["schema_version"] = "0.9"
    assert "only OpenLABEL 1.0.0" in _bad(tmp_path, capsys, doc)


def test_times_out_of_order_name_the_openlabel_transform(tmp_path, capsys):
    doc = _case_openlabel(tmp_path)
    frames = [f for f in doc["openlabel"]["frames"].values() if "transforms" in f["frame_properties"]]
    frames[3]["frame_properties"]["timestamp"] = frames[2]["frame_properties"]["timestamp"]
    err = _bad(tmp_path, capsys, doc)
    assert "frame_properties.transforms.vehicle-iso8855_to_odom" in err and "times must increase" in err


def test_a_time_far_off_is_refused_without_numpy_warnings(tmp_path, capsys):
    """A frame stamped 1e308 s late is refused by the clip's time span, naming the transform; the
    speeds worked out on the way say nothing (no overflow warnings on stderr before the line)."""
    import warnings

    doc = _case_openlabel(tmp_path)
    frames = [f for f in doc["openlabel"]["frames"].values() if "transforms" in f["frame_properties"]]
    frames[-1]["frame_properties"]["timestamp"] = 1e308
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # (a warning would stop the compile here: not the refusal asked)
        err = _bad(tmp_path, capsys, doc)
    assert "frame_properties.transforms.vehicle-iso8855_to_odom" in err and "a clip spans at most 3600 s" in err


@pytest.mark.parametrize(
    "where, value",
    [
        (("coordinate_systems", "vehicle-iso8855"), 12),
        (("coordinate_systems", "vehicle-sae-j670", "pose_wrt_parent"), "identity"),
        (("objects", "0"), [1, 2]),
        (("frames", "0", "frame_properties"), 7),
    ],
)
def test_a_part_written_as_a_number_or_text_where_the_schema_means_an_object_is_refused(tmp_path, capsys, where, value):
    """The OpenLABEL 1.0 schema leaves out the types its definitions imply (a coordinate system with
    properties, but no type): vei spells them out, so such a part is refused naming its path."""
    doc = _case_openlabel(tmp_path, "stop_and_go")
    node = doc["openlabel"]
    for key in where[:-1]:
        node = node[key]
    if where[-1] not in node:
        pytest.skip(f"{where} not in this document")
    node[where[-1]] = value
    err = _bad(tmp_path, capsys, doc)
    assert f"openlabel.{'.'.join(where)}: not valid OpenLABEL 1.0" in err, err


def test_the_typed_schema_accepts_what_the_vcd_library_writes():
    """Objects, actions, events, contexts, relations, streams, transforms and frame properties, as VCD
    writes them: the types spelled out reject none of it."""
    import jsonschema
    from vcd import core, types

    from vei_scenario.clip.openlabel import _typed_schema

    v = core.VCD()
    v.add_coordinate_system("odom", types.CoordinateSystemType.scene_cs)
    v.add_coordinate_system(
        "vehicle-iso8855",
        types.CoordinateSystemType.local_cs,
        parent_name="odom",
        pose_wrt_parent=types.PoseData(
            val=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], t_type=types.TransformDataType.matrix_4x4
        ),
    )
    v.add_stream("cam", "uri", "a camera", core.StreamType.camera)
    o = v.add_object("car1", "car", frame_value=(0, 5))
    v.add_object_data(o, types.bbox("box2d", [1, 2, 3, 4]), frame_value=2)
    v.add_object_data(o, types.cuboid("box3d", [1, 2, 3, 0, 0, 0.1, 4, 2, 1.5], "vehicle-iso8855"), frame_value=3)
    v.add_object_data(o, types.num("speed", 3.0), frame_value=3)
    v.add_object_data(o, types.text("colour", "red"))
    v.add_object_data(o, types.boolean("parked", False))
    v.add_object_data(o, types.vec("v", [1, 2, 3]))
    a = v.add_action("brake", "braking", frame_value=(2, 4))
    v.add_event("start", "event", frame_value=1)
    v.add_context("weather", "rain")
    v.add_relation_object_action("", "isSubjectOfAction", object_uid=o, action_uid=a)
    pose = types.PoseData(val=[0, 0, 0, 1, 1, 2, 3], t_type=types.TransformDataType.quat_and_trans_7x1)
    v.add_transform(3, types.Transform("odom", "vehicle-iso8855", transform_src_to_dst=pose))
    v.add_frame_properties(3, timestamp="2024-01-01T00:00:00", properties={"x": 1})
    doc = json.loads(v.stringify(pretty=False))
    assert list(jsonschema.Draft7Validator(_typed_schema()).iter_errors(doc)) == []
    doc["openlabel"]["coordinate_systems"]["odom"] = 5  # (and it does reject)
    assert list(jsonschema.Draft7Validator(_typed_schema()).iter_errors(doc))


def _kitti_style(n: int = 40, stamps: bool = False) -> tuple[dict, list]:
    """An annotation laid out as the VCD library's KITTI-tracking conversions are: no timestamps, the
    ego's odometry as vehicle-iso8855_to_odom matrices, cuboids in the left camera (x right, y down,
    z forward) two sensor frames below the vehicle, a DontCare object with a placeholder cuboid. Also
    the truth: per frame, the scooter in the ego frame (x forward, y left)."""
    import numpy as np

    cam = np.array([[0.0, 0.0, 1.0, 0.27], [-1.0, 0.0, 0.0, 0.0], [0.0, -1.0, 0.0, -0.07], [0, 0, 0, 1.0]])
    velo = np.array([[1.0, 0, 0, 0.76], [0, 1.0, 0, 0], [0, 0, 1.0, 1.73], [0, 0, 0, 1.0]])
    to_cam = np.linalg.inv(velo @ cam)
    cs = {
        "odom": {"type": "scene_cs", "parent": "", "children": ["vehicle-iso8855"]},
        "vehicle-iso8855": {"type": "local_cs", "parent": "odom", "children": ["VELO_TOP"]},
        "VELO_TOP": {"type": "sensor_cs", "parent": "vehicle-iso8855", "children": ["CAM_LEFT"],
                     "pose_wrt_parent": {"matrix4x4": velo.ravel().tolist()}},
        "CAM_LEFT": {"type": "sensor_cs", "parent": "VELO_TOP", "children": [],
                     "pose_wrt_parent": {"matrix4x4": cam.ravel().tolist()}},
    }  # fmt: skip
    frames, truth = {}, []
    for k in range(n):
        t = k / 10
        yaw = 0.02 * t
        pose = np.array([[math.cos(yaw), -math.sin(yaw), 0, 8.0 * t], [math.sin(yaw), math.cos(yaw), 0, 0.1 * t * t],
                         [0, 0, 1, 0], [0, 0, 0, 1.0]])  # fmt: skip
        ego = np.linalg.inv(pose) @ np.array([25.0, -8.0 + 4.0 * t, 0.5, 1.0])  # the scooter crossing from the right
        truth.append((t, ego[0], ego[1]))
        c = to_cam @ ego
        matrix = {"matrix4x4": pose.ravel().tolist()}
        odometry = {"src": "vehicle-iso8855", "dst": "odom", "transform_src_to_dst": matrix}
        props = {"transforms": {"vehicle-iso8855_to_odom": odometry}}
        if stamps:
            props["timestamp"] = t
        frames[str(k)] = {"frame_properties": props, "objects": {
            "-1": {"object_data": {"cuboid": [{"name": "box3D", "coordinate_system": "CAM_LEFT",
                                               "val": [-10.0, 499.0, -1.0, 0, -1.0, 0, -1000.0, -1000.0, -1000.0]}]}},
            "0": {"object_data": {"cuboid": [{"name": "box3D", "coordinate_system": "CAM_LEFT",
                                              "val": [*map(float, c[:3]), 0, -1.57, 0, 1.2, 1.7, 0.6]}]}}}}  # fmt: skip
    objects = {
        "-1": {"name": "DontCare", "type": "DontCare", "frame_intervals": [{"frame_start": 0, "frame_end": n - 1}]},
        "0": {"name": "Scooter0", "type": "e-scooter", "frame_intervals": [{"frame_start": 0, "frame_end": n - 1}]},
    }
    doc = {"openlabel": {"metadata": {"schema_version": "1.0.0"}, "coordinate_systems": cs, "frames": frames,
                         "objects": objects, "frame_intervals": [{"frame_start": 0, "frame_end": n - 1}]}}  # fmt: skip
    return doc, truth


def test_a_clip_without_timestamps_is_read_at_the_frame_rate_given(tmp_path, capsys):
    doc, truth = _kitti_style()
    src = tmp_path / "kitti.json"
    src.write_text(json.dumps(doc))
    err = _bad(tmp_path, capsys, doc)  # without a rate: refused, saying what to give
    assert "frame_properties.timestamp: missing" in err and "--frame-rate HZ" in err
    back = tmp_path / "back.json"
    assert main(["clip", "convert", str(src), "-o", str(back), "--frame-rate", "10"]) == 0
    frames = json.loads(back.read_text())["annotations"]["frames"]
    got = [(f["t"], o["x_m"], o["y_m"]) for f in frames for o in f["objects"] if o["category"] == "e-scooter"]
    assert len(got) == len(truth)
    for (t, x, y), (t0, x0, y0) in zip(got, truth):  # through both sensor frames into the ego frame
        assert t == pytest.approx(t0, abs=1e-12) and math.hypot(x - x0, y - y0) < 1e-9
    # the same clip with its times written out compiles to the same bytes
    stamped = tmp_path / "stamped.json"
    stamped.write_text(json.dumps(_kitti_style(stamps=True)[0]))
    assert main(["compile", str(src), "--frame-rate", "10", "-o", str(tmp_path / "a" / "scenario.xosc")]) == 0
    assert main(["compile", str(stamped), "-o", str(tmp_path / "b" / "scenario.xosc")]) == 0
    for f in FILES:
        a, b = (tmp_path / "a" / f).read_bytes(), (tmp_path / "b" / f).read_bytes()
        assert a.replace(b"kitti", b"stamped") == b, f


@pytest.mark.parametrize(
    "clip, rate, expected",
    [
        ("stamped", "10", "--frame-rate: the clip has timestamps (openlabel.frames.0.frame_properties)"),
        ("vei-clip", "10", "--frame-rate: a vei-clip has its own times"),
        ("kitti", "0", "argument --frame-rate: 0 is outside 0.01..10000"),
        ("kitti", "inf", "argument --frame-rate: 'inf' is not a finite number"),
    ],
)
def test_a_frame_rate_where_it_has_no_place_is_refused(tmp_path, capsys, clip, rate, expected):
    if clip == "vei-clip":
        doc = json.loads((EXAMPLES / "no_map" / "clip.json").read_text())
    else:
        doc = _kitti_style(stamps=clip == "stamped")[0]
    assert expected in _bad(tmp_path, capsys, doc, "--frame-rate", rate)


@pytest.mark.parametrize("unit, scale", [("ms", 10**3), ("us", 10**6), ("ns", 10**9)])
def test_timestamps_in_another_unit_are_read_with_the_unit_given(tmp_path, capsys, unit, scale):
    doc, truth = _kitti_style(stamps=True)
    epoch = 1_317_042_145  # (recorders count from an epoch: big integers)
    for k, f in doc["openlabel"]["frames"].items():
        f["frame_properties"]["timestamp"] = (epoch * 10 + int(k)) * scale // 10
    src = tmp_path / "c.json"
    src.write_text(json.dumps(doc))
    err = _bad(tmp_path, capsys, doc)  # read as seconds, the clip would span days: refused, naming the option
    assert "a clip spans at most" in err and "--time-unit ms, us or ns" in err
    back = tmp_path / "back.json"
    assert main(["clip", "convert", str(src), "-o", str(back), "--time-unit", unit]) == 0
    clip = json.loads(back.read_text())
    times = [s["t"] for s in clip["ego"]["samples"]]
    assert times[0] == pytest.approx(epoch, abs=1e-6)
    assert [t - times[0] for t in times] == pytest.approx([t for t, _, _ in truth], abs=1e-6)


@pytest.mark.parametrize(
    "args, expected",
    [
        (["--time-unit", "ms", "--frame-rate", "10"], "a unit of timestamps and a frame rate exclude each other"),
        (["--time-unit", "min"], "argument --time-unit: invalid choice: 'min'"),
    ],
)
def test_clock_options_that_contradict_are_refused(tmp_path, capsys, args, expected):
    assert expected in _bad(tmp_path, capsys, _kitti_style()[0], *args)
    vei_clip = json.loads((EXAMPLES / "no_map" / "clip.json").read_text())
    assert "--time-unit: a vei-clip's times are seconds" in _bad(tmp_path, capsys, vei_clip, "--time-unit", "s")


@pytest.mark.parametrize(
    "kind, scooter",
    [
        *[
            (k, True)
            for k in (
                "e-scooter",
                "EScooter",
                "kick_scooter",
                "scooter",
                "e_scooter_rider",
                "vru.e-scooter",
                "VRU/EScooterRider",
                "Rider on KickScooter",
                "human.pedestrian.personal_mobility",
                "vehicle.scooter",
                "Scooter Rider",
                "electric scooter",
            )
        ],  # fmt: skip
        *[
            (k, False)
            for k in (
                "motor_scooter",
                "MotorScooter",
                "mobility scooter",
                "moped",
                "Cyclist",
                "vehicle.bicycle",
                "Pedestrian",
                "DontCare",
                "bikescooter",
            )
        ],  # fmt: skip
    ],
)
def test_object_classes_are_e_scooters_as_datasets_spell_them(tmp_path, capsys, kind, scooter):
    doc, _ = _kitti_style()
    doc["openlabel"]["objects"]["0"]["type"] = kind
    src = tmp_path / "c.json"
    src.write_text(json.dumps(doc))
    back = tmp_path / "back.json"
    if not scooter:  # (the clip's only track is then not an e-scooter: refused, with the classes it has)
        assert main(["clip", "convert", str(src), "-o", str(back), "--frame-rate", "10"]) == 2
        err = capsys.readouterr().err
        assert (
            f"no object class names an e-scooter (classes: {', '.join(map(repr, sorted({'DontCare', kind})))})" in err
        )
        doc["openlabel"]["objects"]["-1"]["type"] = "e-scooter"  # (a scooter beside it: it is kept as it is)
        src.write_text(json.dumps(doc))
    assert main(["clip", "convert", str(src), "-o", str(back), "--frame-rate", "10"]) == 0
    kinds = {o["category"] for f in json.loads(back.read_text())["annotations"]["frames"] for o in f["objects"]}
    assert "e-scooter" in kinds
    assert scooter or kind in kinds
