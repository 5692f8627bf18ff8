"""ASAM OSI ground-truth traces of a run: one ``osi3.GroundTruth`` per step, as ``.mcap`` or ``.osi``.

Why: the AD toolchains vei's users work in exchange ground truth as OSI traces (esmini writes them
with ``--osi_file``); a trace lets a vei run be opened in an OSI viewer or scored by a trace-based
metric tool. The messages are built with the official Python bindings (``osi-python``) and written
with the ``mcap`` library's writer, following the trace-file conventions of OSI 3.8:

* ``.mcap``: one channel (topic ``ground_truth``, schema ``osi3.GroundTruth``) with the channel
  metadata ``net.asam.osi.trace.channel.osi_version``/``protobuf_version``, and the file metadata
  ``net.asam.osi.trace`` (OSI and protobuf versions, a description naming the scenario). No wall-clock
  time is written, so the same run gives the same bytes.
* ``.osi``: the single-channel binary format, each message prefixed by its length (uint32, LE).

Every entity is an object with its id (its index in the scenario's entity order), its bounding box
dimensions, and its pose, velocity and acceleration at the **centre of its bounding box** in the
OpenDRIVE (inertial) frame, as OSI defines ``BaseMoving``. Vehicles and pedestrians are moving
objects (the e-scooter as ``TYPE_STANDUP_SCOOTER``, a bicycle as ``TYPE_BICYCLE``, a car as
``TYPE_MEDIUM_CAR``, as esmini maps them); misc objects are stationary objects, unless they move
(a road user OpenSCENARIO has no class for, replayed from a clip): then moving objects of
``TYPE_OTHER``. The ego is the host vehicle; the map reference is the ``.xodr`` file name and
``proj_string`` its ``geoReference``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from vei_scenario.errors import VeiInputError

#: Trace formats by file suffix.
FORMATS = (".mcap", ".osi")
TOPIC = "ground_truth"

#: OpenSCENARIO vehicleCategory → OSI MovingObject.VehicleClassification.Type name.
VEHICLE_TYPES = {
    "car": "TYPE_MEDIUM_CAR",
    "van": "TYPE_DELIVERY_VAN",
    "truck": "TYPE_HEAVY_TRUCK",
    "trailer": "TYPE_TRAILER",
    "semitrailer": "TYPE_SEMITRAILER",
    "bus": "TYPE_BUS",
    "motorbike": "TYPE_MOTORBIKE",
    "bicycle": "TYPE_BICYCLE",
    "train": "TYPE_TRAIN",
    "tram": "TYPE_TRAM",
    "wheelchair": "TYPE_WHEELCHAIR",
}
#: Object types named by an entity's properties (``objectType``) that OSI has a type for.
SCOOTER_TYPES = frozenset({"e-scooter", "escooter", "e_scooter", "scooter", "standup_scooter", "kick-scooter"})


def osi_type_names(kind: str, category: str, object_type: str) -> tuple[str, str | None]:
    """(MovingObject.Type name, VehicleClassification.Type name or None) of an entity."""
    if kind == "misc":  # (a misc object that moves: a road user OpenSCENARIO has no class for)
        return "TYPE_OTHER", None
    if kind == "pedestrian":
        if category == "animal":
            return "TYPE_ANIMAL", None
        if category == "wheelchair":
            return "TYPE_VEHICLE", "TYPE_WHEELCHAIR"
        return "TYPE_PEDESTRIAN", None
    if object_type.lower() in SCOOTER_TYPES:
        return "TYPE_VEHICLE", "TYPE_STANDUP_SCOOTER"
    return "TYPE_VEHICLE", VEHICLE_TYPES.get(category, "TYPE_UNKNOWN")


def classify_moving(obj, kind: str, category: str, object_type: str, center_x: float) -> None:
    """Set a ``MovingObject``'s type and vehicle classification from the entity (:func:`osi_type_names`),
    and for a vehicle its reference point: the rear axle (OpenSCENARIO), ``center_x`` behind the box
    centre."""
    from osi3 import osi_object_pb2

    mo_cls = osi_object_pb2.MovingObject
    type_name, vehicle_type = osi_type_names(kind, category, object_type)
    obj.type = mo_cls.Type.Value(type_name)
    if vehicle_type is not None:
        obj.vehicle_classification.type = mo_cls.VehicleClassification.Type.Value(vehicle_type)
        obj.vehicle_attributes.bbcenter_to_rear.x = -center_x


def interface_version():
    """The ``osi3.InterfaceVersion`` of the installed OSI bindings: the version of every message vei writes."""
    from osi3 import osi_version_pb2

    return osi_version_pb2.DESCRIPTOR.GetOptions().Extensions[osi_version_pb2.current_interface_version]


def geo_reference(road_file: Path | None) -> str:
    """The ``geoReference`` PROJ string of an OpenDRIVE file ('' when there is none)."""
    if road_file is None or not Path(road_file).is_file():
        return ""
    from vei_scenario.safe_xml import parse_xml

    header = parse_xml(Path(road_file)).getroot().find("header")
    geo = header.find("geoReference") if header is not None else None
    return (geo.text or "").strip() if geo is not None else ""


def _kinematics(tr, t: np.ndarray):
    """Box-centre position, velocity, acceleration and yaw rate of one trace, each step."""
    yaw = np.asarray(tr.yaw, dtype=float)
    c, s = np.cos(yaw), np.sin(yaw)
    cx = tr.center_x
    x = np.asarray(tr.x, dtype=float) + c * cx
    y = np.asarray(tr.y, dtype=float) + s * cx
    # yaw rate by backward differences (0 at the first step); the centre's velocity includes ω × r
    rate = np.zeros_like(yaw)
    if len(t) > 1:
        dyaw = np.arctan2(np.sin(np.diff(yaw)), np.cos(np.diff(yaw)))
        rate[1:] = dyaw / np.diff(t)
    v, a = np.asarray(tr.speed, dtype=float), np.asarray(tr.accel, dtype=float)
    vx = v * c - rate * cx * s
    vy = v * s + rate * cx * c
    ax = a * c - v * rate * s
    ay = a * s + v * rate * c
    return x, y, vx, vy, ax, ay, rate


def _moves(tr) -> bool:
    """Whether an entity's pose changes during the run (a misc object that moves is a moving object)."""
    return bool(np.ptp(tr.x) > 0 or np.ptp(tr.y) > 0 or np.ptp(tr.yaw) > 0) if len(tr.x) else False


def ground_truths(result, host: str | None = None):
    """The run as ``osi3.GroundTruth`` messages, one per recorded step (a generator: a message is
    serialised before the next is built, so a long run needs no more memory than one step)."""
    from osi3 import osi_groundtruth_pb2

    version = interface_version()
    t = np.asarray(result.t, dtype=float)
    names = list(result.traces)
    host = host or result.ego
    proj = geo_reference(result.road_file)
    map_ref = Path(result.road_file).name if result.road_file is not None else ""
    kin = {n: _kinematics(result.traces[n], t) for n in names}
    gt = osi_groundtruth_pb2.GroundTruth()
    gt.version.CopyFrom(version)
    if proj:
        gt.proj_string = proj
    if map_ref:
        gt.map_reference = map_ref
    moving, stationary = [], []
    for i, n in enumerate(names):
        tr = result.traces[n]
        if tr.kind == "misc" and not _moves(tr):
            obj = gt.stationary_object.add()
            stationary.append((n, obj))
        else:
            obj = gt.moving_object.add()
            classify_moving(obj, tr.kind, tr.category, tr.object_type, tr.center_x)
            moving.append((n, obj))
        obj.id.value = i
        obj.base.dimension.length = tr.length
        obj.base.dimension.width = tr.width
        obj.base.dimension.height = tr.height
        obj.base.position.z = 0.5 * tr.height
        if n == host:
            gt.host_vehicle_id.value = i
    # plain lists: indexing them is several times faster than numpy scalars, step after step
    cols = {n: [c.tolist() for c in (*kin[n], np.asarray(result.traces[n].yaw, dtype=float))] for n in names}
    moving_cols = [(obj.base, cols[n]) for n, obj in moving]
    stationary_cols = [(obj.base, cols[n]) for n, obj in stationary]
    stamps = [divmod(int(round(tk * 1e9)), 1_000_000_000) for tk in t.tolist()]
    for k, (sec, nanos) in enumerate(stamps):
        gt.timestamp.seconds, gt.timestamp.nanos = sec, nanos
        for b, (x, y, vx, vy, ax, ay, rate, yaw) in moving_cols:
            b.position.x, b.position.y = x[k], y[k]
            b.orientation.yaw = yaw[k]
            b.velocity.x, b.velocity.y = vx[k], vy[k]
            b.acceleration.x, b.acceleration.y = ax[k], ay[k]
            b.orientation_rate.yaw = rate[k]
        for b, (x, y, *_rest, yaw) in stationary_cols:
            b.position.x, b.position.y = x[k], y[k]
            b.orientation.yaw = yaw[k]
        yield gt


def _check_finite(result) -> None:
    for n, tr in result.traces.items():
        for field in ("x", "y", "yaw", "speed", "accel"):
            if not np.all(np.isfinite(getattr(tr, field))):
                raise VeiInputError(result.scenario, n, f"the run's {field} is not finite: no OSI trace written")


def _file_descriptor_set(message_class) -> bytes:
    """The ``FileDescriptorSet`` of a message's .proto file and its imports (dependencies first): the
    MCAP schema of a protobuf channel."""
    from google.protobuf import descriptor_pb2

    fds = descriptor_pb2.FileDescriptorSet()
    seen: set[str] = set()

    def add(fd) -> None:
        if fd.name in seen:
            return
        seen.add(fd.name)
        for dep in fd.dependencies:
            add(dep)
        fd.CopyToProto(fds.file.add())

    add(message_class.DESCRIPTOR.file)
    return fds.SerializeToString()


def trace_bytes(result, suffix: str = ".mcap", description: str = "") -> bytes:
    """The run's ground truth as the bytes of a trace file: ``.mcap`` (the ``mcap`` library's writer,
    one protobuf channel with the OSI trace metadata) or ``.osi`` (each serialised message after its
    length as a little-endian uint32, OSI's binary trace format)."""
    import io
    import struct

    import google.protobuf
    from osi3 import osi_groundtruth_pb2

    suffix = suffix.lower()
    if suffix not in FORMATS:
        raise VeiInputError(None, "--osi", f"unknown trace format {suffix!r} (use .mcap or .osi)")
    _check_finite(result)
    messages = ground_truths(result)
    if suffix == ".osi":
        parts = []
        for gt in messages:
            data = gt.SerializeToString()
            parts += (struct.pack("<I", len(data)), data)
        return b"".join(parts)

    from mcap.writer import CompressionType, Writer

    v = interface_version()
    osi_version = f"{v.version_major}.{v.version_minor}.{v.version_patch}"
    pb = google.protobuf.__version__
    buf = io.BytesIO()
    writer = Writer(buf, compression=CompressionType.LZ4)
    writer.start(profile="", library="vei-scenario")
    writer.add_metadata(
        "net.asam.osi.trace",
        {
            "version": osi_version,
            "min_osi_version": osi_version,
            "max_osi_version": osi_version,
            "min_protobuf_version": pb,
            "max_protobuf_version": pb,
            "description": description or f"vei run of {Path(result.scenario).name}",
            "data_sources": "vei-scenario interpreter",
        },
    )
    schema = writer.register_schema(
        name="osi3.GroundTruth", encoding="protobuf", data=_file_descriptor_set(osi_groundtruth_pb2.GroundTruth)
    )
    channel = writer.register_channel(
        topic=TOPIC,
        message_encoding="protobuf",
        schema_id=schema,
        metadata={
            "net.asam.osi.trace.channel.osi_version": osi_version,
            "net.asam.osi.trace.channel.protobuf_version": pb,
            "net.asam.osi.trace.channel.description": "ground truth of every entity, each step",
        },
    )
    for gt in messages:
        ns = gt.timestamp.seconds * 1_000_000_000 + gt.timestamp.nanos
        writer.add_message(channel, log_time=ns, data=gt.SerializeToString(), publish_time=ns)
    writer.finish()
    return buf.getvalue()


def write_trace(result, path: str | Path, description: str = "") -> Path:
    """Write the run's ground truth to ``path`` (``.mcap`` or ``.osi``, by its suffix) atomically."""
    from vei_scenario.atomic_io import write_bytes_atomic

    path = Path(path)
    write_bytes_atomic(path, trace_bytes(result, path.suffix, description))
    return path


__all__ = ["FORMATS", "ground_truths", "osi_type_names", "trace_bytes", "write_trace"]
