"""vei's e-scooter rider as an OSMP traffic participant (``vei fmu build sfm --osmp --scenario X``):
an FMI 2.0 co-simulation FMU with ``OSMPSensorViewIn`` and ``OSMPTrafficUpdateOut`` and the
``net.pmsf.osmp`` annotations, that any OSMP host (vei's ``--controller scooter_1=vei_sfm_osmp.fmu``,
openPASS, ...) steps.

Each step it reads, from the SensorView's ground truth, the host (``host_vehicle_id``: itself) and the
ego (the moving object with id ``ego_id``, the ego's place in the scenario's entity order: 0), moves
the rider of the e-scooter FMU (:class:`~vei_scenario.fmu.python_models.SfmModel`: the scenario's
recorded track, route, timing, rider type and social-force parameters, as ``vei fmu build sfm
--scenario`` sets them, carried in ``resources/sfm_parameters.json``) and reports its new pose,
velocity and acceleration in the TrafficUpdate.

:func:`build_osmp` builds it, and the planner, as native C FMUs (:mod:`vei_scenario.fmu.osmp_native`:
no vei, no Python where they run) or, as the fallback where protoc-c and the protobuf-c runtime are
missing, with pythonfmu (this module's :class:`OsmpBody`). Those need a Python with vei-scenario (and
pythonfmu's runtime) where they run, as ``--backend python`` FMUs do, and like them can be
instantiated once per process only (``canBeInstantiatedOnlyOncePerProcess``): one ``vei run`` per
process, or a sweep that spawns a process for each variant; not a study.
"""

from __future__ import annotations

import ctypes
import hashlib
import io
import json
import math
import subprocess
import sys
import tempfile
import uuid
import zipfile
from pathlib import Path

from vei_scenario.errors import VeiInputError

IDENTIFIER = "vei_sfm_osmp"
OSMP_VERSION = "1.5.0"
PARAMETERS_FILE = "sfm_parameters.json"
_NS = "http://xsd.pmsf.net/OSISensorModelPackaging"

_SCRIPT = '''"""vei's {what} as an OSMP traffic participant (pythonfmu; needs Python with vei-scenario)."""
from pythonfmu import Fmi2Slave

from vei_scenario.fmu.osmp_rider import {body}


class {identifier}({body}, Fmi2Slave):
    pass
'''


def _osi_version() -> str:
    from vei_scenario.sut.osmp import host_osi_version

    return ".".join(map(str, host_osi_version()))


def _split(address: int) -> tuple[int, int]:
    lo, hi = address & 0xFFFFFFFF, (address >> 32) & 0xFFFFFFFF
    return (lo - (1 << 32) if lo >= 1 << 31 else lo), (hi - (1 << 32) if hi >= 1 << 31 else hi)


class OsmpBody:
    """The pythonfmu slave's body (the FMU's script mixes it with the ``Fmi2Slave`` of the pythonfmu it
    runs with): OSMP binary variables, the model's values from the FMU's resources, one step of the host
    from the SensorView to the TrafficUpdate. A subclass says which other object it watches (an Integer
    parameter, the object's ground-truth id; the object whose ``source_reference`` names the scenario's
    entity wins where the host gives names) and how it moves."""

    author = "vei-scenario"
    OTHER = ""  # the parameter naming the other object's id
    MODEL = ""  # the participant (osmp_parameters.MODELS)

    def __init__(self, **kwargs) -> None:
        from pythonfmu import Boolean, Fmi2Causality, Fmi2Initial, Fmi2Variability, Integer, Real, String

        from vei_scenario.fmu.osmp_parameters import declared_variables

        super().__init__(**kwargs)
        self.ints = {f"{p}.{r}": 0 for p in ("OSMPSensorViewIn", "OSMPTrafficUpdateOut")
                     for r in ("base.lo", "base.hi", "size")}  # fmt: skip
        self.ints[self.OTHER] = 0
        self.kept: list = []
        for name in self.ints:
            out = name.startswith("OSMPTrafficUpdateOut")
            kw = {"initial": Fmi2Initial.exact} if out else {}
            if name == self.OTHER:
                causality, variability = Fmi2Causality.parameter, Fmi2Variability.fixed
            else:
                causality = Fmi2Causality.output if out else Fmi2Causality.input
                variability = Fmi2Variability.discrete
            self.register_variable(
                Integer(name, causality=causality, variability=variability, start=0, **kw,
                        getter=lambda n=name: self.ints[n], setter=lambda v, n=name: self.ints.__setitem__(n, int(v))),
                nested=False,
            )  # fmt: skip
        # the model's declared parameters, the build's values (its resources) their start values
        built = json.loads((Path(self.resources) / PARAMETERS_FILE).read_text())
        given = built["cap"] if self.MODEL == "cap" else built
        self.params = {}
        for v in declared_variables(self.MODEL):
            kind = {"Real": Real, "Boolean": Boolean, "String": String}[v.type]
            self.params[v.name] = given.get(v.name, v.start)
            self.register_variable(
                kind(v.name, causality=Fmi2Causality.parameter, variability=Fmi2Variability.fixed,
                     getter=lambda n=v.name: self.params[n], setter=lambda x, n=v.name: self.params.__setitem__(n, x)),
                nested=False,
            )  # fmt: skip

    def exit_initialization_mode(self) -> None:
        values = json.loads((Path(self.resources) / PARAMETERS_FILE).read_text())
        self.other_name = values.pop("other_entity", "")
        (values["cap"] if self.MODEL == "cap" else values).update(self.params)  # (as the host set them)
        self.load(values)

    def do_step(self, current_time: float, step_size: float) -> bool:
        from osi3.osi_sensorview_pb2 import SensorView
        from osi3.osi_trafficupdate_pb2 import TrafficUpdate

        lo, hi, size = (self.ints[f"OSMPSensorViewIn.{r}"] for r in ("base.lo", "base.hi", "size"))
        address = ((hi & 0xFFFFFFFF) << 32) | (lo & 0xFFFFFFFF)
        if address == 0 or size <= 0:
            return True  # (no SensorView: no update, as OSMP asks)
        view = SensorView.FromString(ctypes.string_at(address, size))
        gt = view.global_ground_truth
        host_id = view.host_vehicle_id.value if view.HasField("host_vehicle_id") else gt.host_vehicle_id.value
        by_id = {m.id.value: m for m in gt.moving_object}
        named = [m for m in gt.moving_object for r in m.source_reference if self.other_name in r.identifier]
        host, other = by_id.get(host_id), named[0] if named else by_id.get(self.ints[self.OTHER])
        if host is None:
            return True
        x, y, yaw, speed, accel = self.advance(other, current_time, step_size)
        update = TrafficUpdate()
        update.version.CopyFrom(view.version)
        t = current_time + step_size
        update.timestamp.seconds, update.timestamp.nanos = divmod(int(round(t * 1e9)), 1_000_000_000)
        moved = update.update.add()
        moved.CopyFrom(host)
        b = moved.base
        c, s = math.cos(yaw), math.sin(yaw)
        b.position.x, b.position.y = x, y
        b.orientation.yaw = yaw
        b.velocity.x, b.velocity.y = speed * c, speed * s
        b.acceleration.x, b.acceleration.y = accel * c, accel * s
        data = update.SerializeToString()
        buf = ctypes.create_string_buffer(data, len(data))
        self.kept = [*self.kept[-2:], buf]  # (valid until the second doStep after, as OSMP requires)
        lo, hi = _split(ctypes.addressof(buf))
        self.ints.update({"OSMPTrafficUpdateOut.base.lo": lo, "OSMPTrafficUpdateOut.base.hi": hi,
                          "OSMPTrafficUpdateOut.size": len(data)})  # fmt: skip
        return True


class OsmpRider(OsmpBody):
    """The e-scooter rider (:class:`SfmModel`), repelled by the ego (``ego_id``)."""

    description = "vei's e-scooter rider (social force model) as an OSMP traffic participant"
    OTHER = "ego_id"
    MODEL = "sfm"

    def load(self, values: dict) -> None:
        from vei_scenario.fmu.python_models import SfmModel

        self.model = SfmModel()
        self.model.values.update(values)
        self.model.initialize()

    def advance(self, ego, t: float, h: float) -> tuple[float, float, float, float, float]:
        v = self.model.values
        if ego is not None:
            b = ego.base
            v["ego_x"], v["ego_y"], v["ego_yaw"] = b.position.x, b.position.y, b.orientation.yaw
        self.model.do_step(t, h)
        return v["x"], v["y"], v["yaw"], v["speed"], v["accel"]


class OsmpPlanner(OsmpBody):
    """The ego with vei's planner: the collision-avoidance planner (:class:`CapModel`) watching the
    threat (``threat_id``) commands the vehicle on its path (:class:`EgoModel`), as the FMU loop
    couples them (the planner first, on the step's start)."""

    description = "vei's collision-avoidance planner driving its vehicle as an OSMP traffic participant"
    OTHER = "threat_id"
    MODEL = "cap"

    def load(self, values: dict) -> None:
        from vei_scenario.fmu.python_models import CapModel, EgoModel

        self.cap, self.ego = CapModel(), EgoModel()
        self.cap.values.update(values["cap"])
        self.ego.values.update(values["ego"])
        self.ego.initialize()
        e = self.ego.values
        self.cap.values.update(ego_x=e["x"], ego_y=e["y"], ego_yaw=e["yaw"], ego_speed=e["speed"])
        self.cap.initialize()

    def advance(self, threat, t: float, h: float) -> tuple[float, float, float, float, float]:
        c, e = self.cap.values, self.ego.values
        c.update(ego_x=e["x"], ego_y=e["y"], ego_yaw=e["yaw"], ego_speed=e["speed"])
        if threat is not None:
            b = threat.base
            yaw = b.orientation.yaw
            speed = b.velocity.x * math.cos(yaw) + b.velocity.y * math.sin(yaw)
            c.update(threat_x=b.position.x, threat_y=b.position.y, threat_yaw=yaw, threat_speed=speed)
        self.cap.do_step(t, h)
        e["a_cmd"] = c["a_cmd"]
        self.ego.do_step(t, h)
        return e["x"], e["y"], e["yaw"], e["speed"], e["accel"]


def _annotated(md: bytes, osi: str, identifier: str, model: str, starts: dict, record) -> bytes:
    """pythonfmu's modelDescription with OSMP's annotations: the model's, after DefaultExperiment, and
    each binary variable's (name, role, MIME type); vei's ``record`` of the build; the declared
    parameters described and their start values (``starts``) written as the native participant's."""
    from lxml import etree

    from vei_scenario.fmu.osmp_parameters import annotate, declared_variables, start_text
    from vei_scenario.safe_xml import safe_parser

    root = etree.fromstring(md, safe_parser())
    root.attrib.pop("generationDateAndTime", None)
    root.set(
        "guid", "{" + str(uuid.uuid5(uuid.NAMESPACE_URL, f"vei-scenario/{identifier}")) + "}"
    )  # (same build, same bytes)
    # pythonfmu's runtime fails a second instance in one process ("findClass" looks in the wrong module)
    root.find("CoSimulation").set("canBeInstantiatedOnlyOncePerProcess", "true")
    vendor = etree.Element("VendorAnnotations")
    tool = etree.SubElement(vendor, "Tool", name="net.pmsf.osmp", nsmap={"osmp": _NS})
    etree.SubElement(tool, f"{{{_NS}}}osmp", version=OSMP_VERSION, **{"osi-version": osi})
    annotate(vendor, record)
    root.find("ModelVariables").addprevious(vendor)
    kinds = {"OSMPSensorViewIn": "SensorView", "OSMPTrafficUpdateOut": "TrafficUpdate"}
    declared = {v.name: v for v in declared_variables(model)}
    for sv in root.iterfind("ModelVariables/ScalarVariable"):
        v = declared.get(sv.get("name"))
        if v is not None:
            sv.set("description", v.description + (f" ({v.unit})" if v.unit else ""))
            sv[0].set("start", start_text(starts.get(v.name, v.start)))
        prefix, _, role = sv.get("name").partition(".")
        if prefix in kinds:
            ann = etree.SubElement(sv, "Annotations")
            t = etree.SubElement(ann, "Tool", name="net.pmsf.osmp", nsmap={"osmp": _NS})
            mime = f"application/x-open-simulation-interface; type={kinds[prefix]}; version={osi}"
            etree.SubElement(t, f"{{{_NS}}}osmp-binary-variable", name=prefix, role=role, **{"mime-type": mime})
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


#: model -> (what it is, slave body class, file name)
KINDS = {
    "sfm": ("e-scooter rider", "OsmpRider", "vei_sfm_osmp"),
    "cap": ("planner and its vehicle", "OsmpPlanner", "vei_cap_osmp"),
}


def _values(loop, model: str) -> dict:
    """What the FMU carries: the loop's parameters of the rider (the threat), or of the planner and the
    ego vehicle; and the scenario's name of the object it watches."""
    if model == "sfm":
        return {**loop.parameters["sfm"], "other_entity": loop.entities["ego"]}
    return {"cap": loop.parameters["cap"], "ego": loop.parameters["ego"], "other_entity": loop.entities["sfm"]}


BACKENDS = ("native", "python")


def build_osmp(
    model: str, scenario: str | Path, out_dir: Path, values: dict[str, str] | None = None, backend: str = "native"
) -> Path:
    """``out_dir/vei_sfm_osmp.fmu`` (the threat's rider) or ``out_dir/vei_cap_osmp.fmu`` (the planner
    driving the ego) of ``scenario`` (parameter overrides ``values``) as an OSMP traffic participant:
    native C (``backend`` native, :mod:`vei_scenario.fmu.osmp_native`; runs without vei or Python) or
    pythonfmu (python; needs Python with vei-scenario where it runs)."""
    if backend not in BACKENDS:
        raise VeiInputError(None, "--backend", f"{backend!r} is not one of {', '.join(BACKENDS)}")
    if model not in KINDS:
        raise VeiInputError(None, "--osmp", f"{model!r} is not one of {', '.join(KINDS)}")
    from vei_scenario.fmu.osmp_parameters import build_record, osmp_loop

    loop = osmp_loop(scenario, values)

    record = build_record(model, scenario, values, loop)
    if backend == "native":
        from vei_scenario.fmu.osmp_native import build_native_osmp
        from vei_scenario.fmu.variables import SPECS

        models = ("sfm",) if model == "sfm" else ("cap", "ego")
        specs = {m: SPECS[m].with_starts(loop.parameters[m], loop.steps * loop.dt) for m in models}
        other = loop.entities["ego" if model == "sfm" else "sfm"]
        return build_native_osmp(model, specs, other, Path(out_dir), KINDS[model][2], record)
    return _build_python(model, loop, Path(out_dir), record)


def _build_python(model: str, loop, out_dir: Path, record) -> Path:
    """The pythonfmu participant (the fallback where no native one can be built)."""
    what, body, name = KINDS[model]
    try:
        import pythonfmu  # noqa: F401
    except ImportError:
        raise VeiInputError(None, "--osmp", "needs pythonfmu: pip install pythonfmu") from None
    from vei_scenario.fmu.packaging import write_fmu

    text = json.dumps(_values(loop, model), sort_keys=True)
    # the model identifier names the scenario's values: pythonfmu's runtime imports the FMU's script by
    # that name, so two of these FMUs hosted in one process would otherwise share (and free) one module
    identifier = f"{name}_{hashlib.sha256(text.encode()).hexdigest()[:12]}"
    with tempfile.TemporaryDirectory(prefix="vei-osmp-") as tmp:
        script = Path(tmp) / f"{identifier}.py"
        script.write_text(_SCRIPT.format(what=what, body=body, identifier=identifier))
        params = Path(tmp) / PARAMETERS_FILE
        params.write_text(text)
        # pythonfmu's builder imports the script: in a child process, since importing it in a process
        # that hosts pythonfmu FMUs (vei's tests, a notebook) crashed that process
        command = [sys.executable, "-m", "pythonfmu", "build", "-f", str(script), "-d", str(Path(tmp) / "out")]
        done = subprocess.run([*command, str(params)], capture_output=True, text=True, cwd=tmp)
        if done.returncode != 0:
            why = " ".join((done.stderr or done.stdout).strip().splitlines()[-1:]) or f"exit {done.returncode}"
            raise VeiInputError(None, "--osmp", f"pythonfmu could not build the {what}: {why}")
        built = Path(tmp) / "out" / f"{identifier}.fmu"
        with zipfile.ZipFile(io.BytesIO(built.read_bytes())) as zf:
            entries = {n: zf.read(n) for n in zf.namelist() if not n.endswith("/")}
    starts = loop.parameters["cap" if model == "cap" else "sfm"]
    md = entries["modelDescription.xml"]
    entries["modelDescription.xml"] = _annotated(md, _osi_version(), identifier, model, starts, record)
    return write_fmu(Path(out_dir) / f"{name}.fmu", entries)


def build_osmp_rider(
    scenario: str | Path, out_dir: Path, values: dict[str, str] | None = None, backend: str = "native"
) -> Path:
    """:func:`build_osmp` of the rider."""
    return build_osmp("sfm", scenario, out_dir, values, backend)
