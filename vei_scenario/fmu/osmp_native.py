"""vei's rider and planner as native OSMP traffic participants: FMI 2.0 FMUs in C that need neither
vei nor Python where they run.

The binary holds the FMU model(s) of vei's FMU loop (``sfm_model.c``; ``cap_model.c`` with the
``ego_model.c`` it drives), compiled with the scenario's values as start values, behind an OSMP
wrapper (``c_sources/osmp_wrapper.c``) that decodes the ``osi3::SensorView`` and encodes the
``osi3::TrafficUpdate`` with protobuf-c. The C code for OSI's messages is generated at build time by
``protoc-c`` from the file descriptors of the installed OSI Python bindings (``osi3.*_pb2``: the same
schema vei's host writes), so no ``.proto`` file is needed; the protobuf-c runtime is linked in
statically and its names kept inside the binary (Debian's ``libprotobuf-c.a`` is position-independent
code for executables, which a shared object may hold when none of its names is exported).

Why protobuf-c: an OSMP participant must read a whole SensorView (any number of objects and lanes)
and write back the host's object as it came, unknown fields and all. protobuf-c's generated code
decodes any message into allocated structures and re-encodes it; nanopb would need a size limit on
every repeated field of OSI or callbacks for each. The generator and the runtime are Debian packages
(``protobuf-c-compiler``, ``libprotobuf-c-dev``); PyPI's nanopb has no C runtime.

Where they are missing :func:`missing` says what to install in one line; ``vei fmu build --osmp``
then builds the pythonfmu participant (:mod:`vei_scenario.fmu.osmp_rider`) instead.
"""

from __future__ import annotations

import hashlib
import shutil
import subprocess
import tempfile
import uuid
from pathlib import Path

from vei_scenario.core.sources import compiler, source_dir
from vei_scenario.errors import VeiInputError
from vei_scenario.fmu.native import START_VALUES_UNIT, c_source_dir, fmi_header_dir, variables_header
from vei_scenario.fmu.osmp_parameters import BuildRecord, annotate, declared_variables, start_text
from vei_scenario.fmu.packaging import write_fmu
from vei_scenario.fmu.variables import SPECS, ModelSpec

INSTALL = "apt-get install protobuf-c-compiler libprotobuf-c-dev"
OSMP_VERSION = "1.5.0"
_NS = "http://xsd.pmsf.net/OSISensorModelPackaging"
#: the names each model's objects prefix (osmp_model.h): the model's own and those of fmu_common.c
_RENAMED = (
    "model_initialize", "model_do_step", "vei_set_start_values", "vei_fail", "vei_register", "vei_unregister",
    "vei_is_live", "vei_require", "vei_settable", "osmp_model_new", "osmp_model_free", "osmp_model_reals",
    "osmp_model_bools", "osmp_model_string", "osmp_model_string_capacity", "osmp_model_initialize",
    "osmp_model_do_step",
)  # fmt: skip
#: the real variables the wrapper reads or writes, per model (osmp_config.h: <MODEL>_<NAME>)
_REALS = {
    "sfm": ("ego_x", "ego_y", "ego_yaw", "x", "y", "yaw", "speed", "accel"),
    "cap": ("ego_x", "ego_y", "ego_yaw", "ego_speed", "threat_x", "threat_y", "threat_yaw", "threat_speed", "a_cmd"),
    "ego": ("a_cmd", "x", "y", "yaw", "speed", "accel"),
}
#: participant -> (models in its binary, its Integer parameter naming the other object, description)
PARTICIPANTS = {
    "sfm": (("sfm",), "ego_id", "vei's e-scooter rider (social force model) as an OSMP traffic participant"),
    "cap": (("cap", "ego"), "threat_id",
            "vei's collision-avoidance planner driving its vehicle as an OSMP traffic participant"),
}  # fmt: skip
# (-ffp-contract=off: no fused multiply-add, the same rounding as vei run's models)
_CFLAGS = ("-O2", "-std=c99", "-fPIC", "-fvisibility=hidden", "-ffp-contract=off", "-pthread")
#: fmu_common.c holds the start values (thousands of assignments of the scenario's recorded tracks) and
#: the instance registry, none of it on the stepping path: unoptimised it compiles in a tenth of a
#: second instead of seconds, and assigns the same values.
_START_VALUES_CFLAGS = ("-O0", *_CFLAGS[1:])


def _runtime_archive(cc: str) -> Path | None:
    """The static protobuf-c runtime where the compiler finds it."""
    done = subprocess.run([cc, "-print-file-name=libprotobuf-c.a"], capture_output=True, text=True)
    path = Path(done.stdout.strip())
    return path if done.returncode == 0 and path.is_absolute() and path.is_file() else None


def missing() -> str | None:
    """None where a native OSMP FMU can be built here; else, in one line, what is missing and what
    to install."""
    try:
        cc = compiler()
    except VeiInputError as exc:
        return f"a native OSMP FMU needs a C compiler: {exc.reason}"
    lacking = []
    if shutil.which("protoc-c") is None:
        lacking.append("protoc-c")
    if _runtime_archive(cc) is None:
        lacking.append("libprotobuf-c.a")
    try:
        import osi3  # noqa: F401
    except ImportError:
        return "a native OSMP FMU needs the OSI Python bindings for OSI's schema: pip install osi-python"
    if lacking:
        return f"a native OSMP FMU needs {' and '.join(lacking)} (Debian/Ubuntu: {INSTALL})"
    return _links(cc)


def _links(cc: str) -> str | None:
    """None where the static protobuf-c runtime links into a shared object (position-independent
    code, as Debian's, built for executables, is once its names are kept inside); else why not."""
    archive = _runtime_archive(cc)
    with tempfile.TemporaryDirectory(prefix="vei-osmp-probe-") as tmp:
        (Path(tmp) / "probe.c").write_text(
            "#include <protobuf-c/protobuf-c.h>\nconst char *probe(void) { return protobuf_c_version(); }\n"
        )
        cmd = [cc, "-shared", "-fPIC", "-o", "probe.so", "probe.c", str(archive), "-Wl,--exclude-libs,ALL"]
        done = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True)
    if done.returncode == 0:
        return None
    last = " ".join(done.stderr.strip().splitlines()[-1:])
    return f"{archive} does not link into a shared object ({last}); a native OSMP FMU needs a position-independent one"


#: what the participant reads of a SensorView: (message, its fields); the rest stays undecoded
VIEW_FILE = "vei_osmp_view.proto"
_VIEW_FIELDS = {
    "SensorView": ("version", "timestamp", "global_ground_truth", "host_vehicle_id"),
    "GroundTruth": ("version", "timestamp", "host_vehicle_id", "moving_object"),
}


def osi_descriptor_set() -> bytes:
    """The schema the participant's C code is generated from, as a serialised ``FileDescriptorSet``:
    OSI's TrafficUpdate and the files it imports, from the installed bindings, and a reading view of
    the SensorView (``vei_osmp.SensorView``: OSI's SensorView and GroundTruth with only the fields the
    participant reads, their numbers and types OSI's, moving objects as OSI's MovingObject). Decoded
    with it a SensorView's other fields (the road's lanes: most of its bytes) are skipped, not parsed
    into thousands of messages each step.

    Messages with a field named ``base`` (OSI's objects) get protobuf-c's ``base_field_name`` option,
    as protobuf-c names its own header field ``base`` too; names never reach the wire."""
    from google.protobuf import descriptor_pb2
    from osi3 import osi_groundtruth_pb2, osi_sensorview_pb2, osi_trafficupdate_pb2

    files: dict[str, descriptor_pb2.FileDescriptorProto] = {}

    def add(fd) -> None:
        if fd.name in files:
            return
        for dep in fd.dependencies:
            add(dep)
        proto = descriptor_pb2.FileDescriptorProto()
        fd.CopyToProto(proto)
        files[fd.name] = proto

    add(osi_trafficupdate_pb2.DESCRIPTOR)
    view = descriptor_pb2.FileDescriptorProto(name=VIEW_FILE, package="vei_osmp", syntax="proto2")
    for message in (osi_sensorview_pb2.SensorView.DESCRIPTOR, osi_groundtruth_pb2.GroundTruth.DESCRIPTOR):
        full = descriptor_pb2.DescriptorProto()
        message.CopyToProto(full)
        kept = descriptor_pb2.DescriptorProto(name=full.name)
        for f in full.field:
            if f.name in _VIEW_FIELDS[full.name]:
                field = kept.field.add()
                field.CopyFrom(f)
                if f.type_name == ".osi3.GroundTruth":
                    field.type_name = ".vei_osmp.GroundTruth"
                for dep in (message.fields_by_name[f.name].message_type,):
                    if dep is not None and dep.file.name not in (VIEW_FILE,) and dep.full_name != "osi3.GroundTruth":
                        add(dep.file)
                        if dep.file.name not in view.dependency:
                            view.dependency.append(dep.file.name)
        view.message_type.append(kept)
    files[VIEW_FILE] = view
    option = _field(1019, _field(3, b"pb_header"))  # MessageOptions (pb_c_msg).base_field_name

    def rename(messages) -> None:
        for m in messages:
            if any(f.name == "base" for f in m.field):
                m.options.MergeFromString(option)
            rename(m.nested_type)

    for proto in files.values():
        rename(proto.message_type)
    return descriptor_pb2.FileDescriptorSet(file=list(files.values())).SerializeToString(deterministic=True)


def _varint(n: int) -> bytes:
    out = bytearray()
    while True:
        n, low = n >> 7, n & 0x7F
        out.append(low | (0x80 if n else 0))
        if not n:
            return bytes(out)


def _field(number: int, payload: bytes) -> bytes:
    """A length-delimited protobuf field."""
    return _varint(number << 3 | 2) + _varint(len(payload)) + payload


def _c_string(text: str) -> str:
    """``text`` as a C string literal (every byte outside printable ASCII as an octal escape)."""
    out = []
    for byte in text.encode():
        ch = chr(byte)
        out.append(ch if 32 <= byte < 127 and ch not in '"\\?' else f"\\{byte:03o}")
    return '"' + "".join(out) + '"'


def _config(model: str, guid: str, identifier: str, other_entity: str, osi: tuple[int, int, int]) -> str:
    models, other_parameter, _ = PARTICIPANTS[model]
    lines = [
        "/* osmp_config.h: generated by vei_scenario.fmu.osmp_native; do not edit. */",
        f"#define OSMP_IDENTIFIER {_c_string(identifier)}",
        f"#define OSMP_GUID {_c_string(guid)}",
        f"#define OSMP_OTHER_ENTITY {_c_string(other_entity)}",
        f"#define OSMP_OTHER_PARAMETER {_c_string(other_parameter)}",
        f"#define OSMP_PLANNER {1 if model == 'cap' else 0}",
        *(f"#define OSMP_OSI_{k} {v}" for k, v in zip(("MAJOR", "MINOR", "PATCH"), osi)),
    ]
    for m in models:
        spec = SPECS[m]
        lines += [f"#define {m.upper()}_{n.upper()} {spec.first_vr(spec.variable(n))}" for n in _REALS[m]]
    spec = SPECS[models[0]]  # the declared parameters: FMU value reference (per type, from 0) -> the model's
    for kind in ("Real", "Boolean", "String"):
        declared = [v for v in declared_variables(model) if v.type == kind]
        vrs = ", ".join(str(spec.first_vr(v)) for v in declared) or "-1"
        names = ", ".join(_c_string(v.name) for v in declared) or '""'
        kind = kind.upper()
        lines += [f"#define OSMP_N_{kind}_PARAMS {len(declared)}", f"#define OSMP_{kind}_PARAMS {{{vrs}}}",
                  f"#define OSMP_{kind}_NAMES {{{names}}}"]  # fmt: skip
    return "\n".join(lines) + "\n"


def declare_parameters(variables, model: str, starts: dict) -> None:
    """Append the participant's declared parameters to ``<ModelVariables>``: Real, Boolean and String,
    value references from 0 in each type, fixed, the build's values (``starts``) their start values."""
    from lxml import etree

    vrs: dict[str, int] = {}
    for v in declared_variables(model):
        vr = vrs[v.type] = vrs.get(v.type, -1) + 1
        unit = f" ({v.unit})" if v.unit else ""
        sv = etree.SubElement(variables, "ScalarVariable", name=v.name, valueReference=str(vr), causality="parameter",
                              variability="fixed", description=v.description + unit)  # fmt: skip
        etree.SubElement(sv, v.type, start=start_text(starts.get(v.name, v.start)))


def model_description(model: str, identifier: str, guid: str, osi: str, stop_time: float | None = None,
                      starts: dict | None = None, record: BuildRecord | None = None) -> bytes:  # fmt: skip
    """The participant's modelDescription: FMI 2.0 co-simulation, the scenario's length as default
    experiment, OSMP's model annotation and its binary variables (each annotated with its name, role
    and MIME type), the other object's id, the model's declared parameters (``starts``: the build's
    values) and vei's ``record`` of the build."""
    from lxml import etree

    _, other, description = PARTICIPANTS[model]
    root = etree.Element("fmiModelDescription", fmiVersion="2.0", modelName=identifier, guid=guid,
                         description=description, author="vei-scenario", generationTool="vei-scenario",
                         variableNamingConvention="structured", numberOfEventIndicators="0")  # fmt: skip
    etree.SubElement(root, "CoSimulation", modelIdentifier=identifier, canHandleVariableCommunicationStepSize="true",
                     canBeInstantiatedOnlyOncePerProcess="false", canNotUseMemoryManagementFunctions="true",
                     canGetAndSetFMUstate="false", canSerializeFMUstate="false")  # fmt: skip
    cats = etree.SubElement(root, "LogCategories")
    for name in ("logStatusWarning", "logStatusError"):
        etree.SubElement(cats, "Category", name=name)
    if stop_time is not None:
        etree.SubElement(root, "DefaultExperiment", startTime="0.0", stopTime=repr(float(stop_time)))
    vendor = etree.SubElement(root, "VendorAnnotations")
    tool = etree.SubElement(vendor, "Tool", name="net.pmsf.osmp", nsmap={"osmp": _NS})
    etree.SubElement(tool, f"{{{_NS}}}osmp", version=OSMP_VERSION, **{"osi-version": osi})
    if record is not None:
        annotate(vendor, record)
    variables = etree.SubElement(root, "ModelVariables")
    vr = 0
    for prefix, kind, causality in (("OSMPSensorViewIn", "SensorView", "input"),
                                    ("OSMPTrafficUpdateOut", "TrafficUpdate", "output")):  # fmt: skip
        for role in ("base.lo", "base.hi", "size"):
            extra = {"initial": "exact"} if causality == "output" else {}
            sv = etree.SubElement(variables, "ScalarVariable", name=f"{prefix}.{role}", valueReference=str(vr),
                                  causality=causality, variability="discrete", **extra)  # fmt: skip
            etree.SubElement(sv, "Integer", start="0")
            ann = etree.SubElement(etree.SubElement(sv, "Annotations"), "Tool", name="net.pmsf.osmp",
                                   nsmap={"osmp": _NS})  # fmt: skip
            mime = f"application/x-open-simulation-interface; type={kind}; version={osi}"
            etree.SubElement(ann, f"{{{_NS}}}osmp-binary-variable", name=prefix, role=role, **{"mime-type": mime})
            vr += 1
    sv = etree.SubElement(variables, "ScalarVariable", name=other, valueReference=str(vr), causality="parameter",
                          variability="fixed", description="the ground-truth id of the object it watches where "
                          "no object's source_reference names the scenario's entity")  # fmt: skip
    etree.SubElement(sv, "Integer", start="0")
    declare_parameters(variables, model, starts or {})
    outputs = etree.SubElement(etree.SubElement(root, "ModelStructure"), "Outputs")
    for index in (4, 5, 6):
        etree.SubElement(outputs, "Unknown", index=str(index))
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


def _run(cmd: list[str], cwd: Path, what: str) -> None:
    done = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if done.returncode != 0:
        last = " ".join((done.stderr or done.stdout).strip().splitlines()[-3:]) or f"exit {done.returncode}"
        raise VeiInputError(None, "--osmp", f"{what} failed: {last}")


_SHARED_SOURCES = ("vei_models.c", "vei_models.h", "fmu_instance.h", "fmu_common.c", "osmp_model.c", "osmp_model.h",
                   "osmp_wrapper.c", "fmi2_unsupported.h")  # fmt: skip


def _sources(models: tuple[str, ...]) -> dict[str, bytes]:
    """The C the binary is compiled from (path in the build folder -> content): the core's models,
    the FMU models' glue, the OSMP wrapper, FMI's headers; each model's own files in its folder."""
    src, core, fmi = c_source_dir(), source_dir(), fmi_header_dir()
    files = {n: ((core if (core / n).is_file() else src) / n).read_bytes() for n in _SHARED_SOURCES}
    files.update({h: (fmi / h).read_bytes() for h in ("fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h")})
    for m in models:
        files[f"{m}/model.h"] = f'#include "{m}_model.h"\n'.encode()
        for n in (f"{m}_model.h", f"{m}_model.c"):
            files[f"{m}/{n}"] = (src / n).read_bytes()
    return files


#: OSI's generated C compiled once per process: it depends on the OSI version, the compiler and the
#: flags only, not on the scenario, and is most of a build's time (a sweep or a test builds many).
_GENERATED_OBJECTS: dict[str, dict[str, bytes]] = {}


def _generated_key(build: Path, cc: str, generated: list[str]) -> str:
    """What OSI's generated objects are compiled from: the compiler, the flags, the generated code."""
    digest = hashlib.sha256(f"{cc}\0{_CFLAGS}\0".encode())
    for unit in generated:
        digest.update(unit.encode() + b"\0" + (build / unit).read_bytes() + b"\0")
    for header in sorted((build / "gen").rglob("*.h")):
        digest.update(str(header.relative_to(build)).encode() + b"\0" + header.read_bytes() + b"\0")
    return digest.hexdigest()


def _compile(build: Path, cc: str, models: tuple[str, ...], binary: str) -> None:
    """OSI's C code generated from ``build/osi.pb``, every unit compiled, the participant linked."""
    from google.protobuf import descriptor_pb2

    protos = [f.name for f in descriptor_pb2.FileDescriptorSet.FromString((build / "osi.pb").read_bytes()).file]
    (build / "gen").mkdir()
    _run(["protoc-c", "--descriptor_set_in=osi.pb", "--c_out=gen", *protos], build, "protoc-c (OSI's C code)")
    objects: list[str] = []
    for m in models:  # each model alone, its names prefixed (osmp_model.h)
        renames = [f"-D{n}={m}_{n}" for n in _RENAMED]
        for unit in (f"{m}/{m}_model.c", "fmu_common.c", "osmp_model.c"):
            obj = f"{m}/{Path(unit).stem}.o"
            flags = _CFLAGS if unit != START_VALUES_UNIT else _START_VALUES_CFLAGS
            _run([cc, *flags, "-Wall", *renames, f"-I{m}", "-I.", "-c", unit, "-o", obj], build, f"compiling {unit}")
            objects.append(obj)
    generated = sorted(str(p.relative_to(build)) for p in (build / "gen").rglob("*.c"))
    key = _generated_key(build, cc, generated)
    kept = _GENERATED_OBJECTS.get(key, {})
    for unit in ("vei_models.c", "osmp_wrapper.c", *generated):
        obj = unit[:-2] + ".o"
        if obj in kept:
            (build / obj).write_bytes(kept[obj])
        else:
            warn = "-w" if unit.startswith("gen") else "-Wall"  # (protoc-c's code as it comes: its warnings not ours)
            _run([cc, *_CFLAGS, warn, "-I.", "-Igen", "-c", unit, "-o", obj], build, f"compiling {unit}")
        objects.append(obj)
    if not kept:
        _GENERATED_OBJECTS[key] = {unit[:-2] + ".o": (build / (unit[:-2] + ".o")).read_bytes() for unit in generated}
    link = [cc, "-shared", "-s", "-pthread", "-o", binary, *objects, str(_runtime_archive(cc)),
            "-Wl,--exclude-libs,ALL", "-lm"]  # fmt: skip
    _run(link, build, "linking the participant")


def build_native_osmp(model: str, specs: dict[str, ModelSpec], other_entity: str, out_dir: Path, name: str,
                      record: BuildRecord | None = None) -> Path:  # fmt: skip
    """``out_dir/<name>.fmu``: the participant ``model`` (sfm or cap) with ``specs`` (each model of
    its binary with the scenario's start values) watching ``other_entity``; ``record``: what it was
    built for (in its modelDescription)."""
    why = missing()
    if why:
        raise VeiInputError(None, "--osmp", why)
    from vei_scenario.sut.osmp import host_osi_version

    osi_tuple = host_osi_version()
    osi = ".".join(map(str, osi_tuple))
    models = PARTICIPANTS[model][0]
    files = {"osi.pb": osi_descriptor_set(), **_sources(models)}
    files.update({f"{m}/vei_{m}_variables.h": variables_header(specs[m], "{osmp}").encode() for m in models})
    digest = hashlib.sha256(f"{model}\0{other_entity}\0{osi}\0".encode())
    for path in sorted(files):  # (the GUID names what the binary is made of)
        digest.update(path.encode() + b"\0" + files[path] + b"\0")
    digest.update(repr(record).encode())
    guid = "{" + str(uuid.uuid5(uuid.NAMESPACE_URL, f"vei-scenario/osmp/{digest.hexdigest()}")) + "}"
    files["osmp_config.h"] = _config(model, guid, name, other_entity, osi_tuple).encode()
    with tempfile.TemporaryDirectory(prefix="vei-osmp-native-") as tmp:
        build = Path(tmp)
        for path, data in files.items():
            (build / path).parent.mkdir(parents=True, exist_ok=True)
            (build / path).write_bytes(data)
        _compile(build, compiler(), models, f"{name}.so")
        entries = {
            "modelDescription.xml": model_description(
                model, name, guid, osi, specs[models[0]].stop_time, dict(specs[models[0]].starts), record
            ),
            f"binaries/linux64/{name}.so": (build / f"{name}.so").read_bytes(),
        }
    return write_fmu(Path(out_dir) / f"{name}.fmu", entries)
