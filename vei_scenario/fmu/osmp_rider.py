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

Built with pythonfmu: the native C FMU would need a protobuf runtime in C; this one needs a Python with
vei-scenario (and pythonfmu's runtime) where it runs, as ``--backend python`` FMUs do, and like them it
can be instantiated once per process only (``canBeInstantiatedOnlyOncePerProcess``): one ``vei run``
per process, not a study or a sweep.
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

_SCRIPT = '''"""vei's e-scooter rider as an OSMP traffic participant (pythonfmu; needs Python with vei-scenario)."""
from pythonfmu import Fmi2Slave

from vei_scenario.fmu.osmp_rider import OsmpRider


class {identifier}(OsmpRider, Fmi2Slave):
    pass
'''


def _osi_version() -> str:
    from vei_scenario.sut.osmp import host_osi_version

    return ".".join(map(str, host_osi_version()))


def _split(address: int) -> tuple[int, int]:
    lo, hi = address & 0xFFFFFFFF, (address >> 32) & 0xFFFFFFFF
    return (lo - (1 << 32) if lo >= 1 << 31 else lo), (hi - (1 << 32) if hi >= 1 << 31 else hi)


class OsmpRider:
    """The pythonfmu slave's body (the FMU's script mixes it with the ``Fmi2Slave`` of the pythonfmu it
    runs with): OSMP binary variables around :class:`SfmModel`."""

    author = "vei-scenario"
    description = "vei's e-scooter rider (social force model) as an OSMP traffic participant"

    def __init__(self, **kwargs) -> None:
        from pythonfmu import Fmi2Causality, Fmi2Initial, Fmi2Variability, Integer

        super().__init__(**kwargs)
        self.ints = {f"{p}.{r}": 0 for p in ("OSMPSensorViewIn", "OSMPTrafficUpdateOut")
                     for r in ("base.lo", "base.hi", "size")}  # fmt: skip
        self.ints["ego_id"] = 0
        self.kept: list = []
        for name in self.ints:
            out = name.startswith("OSMPTrafficUpdateOut")
            kw = {"initial": Fmi2Initial.exact} if out else {}
            if name == "ego_id":
                causality, variability = Fmi2Causality.parameter, Fmi2Variability.fixed
            else:
                causality, variability = (
                    (Fmi2Causality.output if out else Fmi2Causality.input),
                    Fmi2Variability.discrete,
                )
            self.register_variable(
                Integer(name, causality=causality, variability=variability, start=0, **kw,
                        getter=lambda n=name: self.ints[n], setter=lambda v, n=name: self.ints.__setitem__(n, int(v))),
                nested=False,
            )  # fmt: skip
        self.model = None

    def exit_initialization_mode(self) -> None:
        from vei_scenario.fmu.python_models import SfmModel

        values = json.loads((Path(self.resources) / PARAMETERS_FILE).read_text())
        self.model = SfmModel()
        self.model.values.update(values)
        self.model.initialize()

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
        host, ego = by_id.get(host_id), by_id.get(self.ints["ego_id"])
        if host is None:
            return True
        v = self.model.values
        if ego is not None:
            b = ego.base
            v["ego_x"], v["ego_y"], v["ego_yaw"] = b.position.x, b.position.y, b.orientation.yaw
        self.model.do_step(current_time, step_size)
        update = TrafficUpdate()
        update.version.CopyFrom(view.version)
        t = current_time + step_size
        update.timestamp.seconds, update.timestamp.nanos = divmod(int(round(t * 1e9)), 1_000_000_000)
        moved = update.update.add()
        moved.CopyFrom(host)
        b = moved.base
        c, s = math.cos(v["yaw"]), math.sin(v["yaw"])
        b.position.x, b.position.y = v["x"], v["y"]
        b.orientation.yaw = v["yaw"]
        b.velocity.x, b.velocity.y = v["speed"] * c, v["speed"] * s
        b.acceleration.x, b.acceleration.y = v["accel"] * c, v["accel"] * s
        data = update.SerializeToString()
        buf = ctypes.create_string_buffer(data, len(data))
        self.kept = [*self.kept[-2:], buf]  # (valid until the second doStep after, as OSMP requires)
        lo, hi = _split(ctypes.addressof(buf))
        self.ints.update({"OSMPTrafficUpdateOut.base.lo": lo, "OSMPTrafficUpdateOut.base.hi": hi,
                          "OSMPTrafficUpdateOut.size": len(data)})  # fmt: skip
        return True


def _annotated(md: bytes, osi: str, identifier: str) -> bytes:
    """pythonfmu's modelDescription with OSMP's annotations: the model's, after DefaultExperiment, and
    each binary variable's (name, role, MIME type)."""
    from lxml import etree

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
    root.find("ModelVariables").addprevious(vendor)
    kinds = {"OSMPSensorViewIn": "SensorView", "OSMPTrafficUpdateOut": "TrafficUpdate"}
    for sv in root.iterfind("ModelVariables/ScalarVariable"):
        prefix, _, role = sv.get("name").partition(".")
        if prefix in kinds:
            ann = etree.SubElement(sv, "Annotations")
            t = etree.SubElement(ann, "Tool", name="net.pmsf.osmp", nsmap={"osmp": _NS})
            mime = f"application/x-open-simulation-interface; type={kinds[prefix]}; version={osi}"
            etree.SubElement(t, f"{{{_NS}}}osmp-binary-variable", name=prefix, role=role, **{"mime-type": mime})
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


def build_osmp_rider(scenario: str | Path, out_dir: Path, values: dict[str, str] | None = None) -> Path:
    """``out_dir/vei_sfm_osmp.fmu``: the threat's rider of ``scenario`` (parameter overrides ``values``)
    as an OSMP traffic participant."""
    try:
        import pythonfmu  # noqa: F401
    except ImportError:
        raise VeiInputError(None, "--osmp", "needs pythonfmu: pip install pythonfmu") from None
    from vei_scenario.fmu.packaging import write_fmu
    from vei_scenario.fmu.system import closed_loop

    loop = closed_loop(scenario, values)
    text = json.dumps(loop.parameters["sfm"], sort_keys=True)
    # the model identifier names the scenario's values: pythonfmu's runtime imports the FMU's script by
    # that name, so two of these FMUs hosted in one process would otherwise share (and free) one module
    identifier = f"{IDENTIFIER}_{hashlib.sha256(text.encode()).hexdigest()[:12]}"
    with tempfile.TemporaryDirectory(prefix="vei-osmp-") as tmp:
        script = Path(tmp) / f"{identifier}.py"
        script.write_text(_SCRIPT.format(identifier=identifier))
        params = Path(tmp) / PARAMETERS_FILE
        params.write_text(text)
        # pythonfmu's builder imports the script: in a child process, since importing it in a process
        # that hosts pythonfmu FMUs (vei's tests, a notebook) crashed that process
        command = [sys.executable, "-m", "pythonfmu", "build", "-f", str(script), "-d", str(Path(tmp) / "out")]
        done = subprocess.run([*command, str(params)], capture_output=True, text=True, cwd=tmp)
        if done.returncode != 0:
            why = " ".join((done.stderr or done.stdout).strip().splitlines()[-1:]) or f"exit {done.returncode}"
            raise VeiInputError(None, "--osmp", f"pythonfmu could not build the rider: {why}")
        built = Path(tmp) / "out" / f"{identifier}.fmu"
        with zipfile.ZipFile(io.BytesIO(built.read_bytes())) as zf:
            entries = {n: zf.read(n) for n in zf.namelist() if not n.endswith("/")}
    entries["modelDescription.xml"] = _annotated(entries["modelDescription.xml"], _osi_version(), identifier)
    return write_fmu(Path(out_dir) / f"{IDENTIFIER}.fmu", entries)
