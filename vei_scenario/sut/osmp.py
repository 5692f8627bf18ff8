"""An ASAM OSI traffic participant packaged as OSMP (OSI Sensor Model Packaging) FMU as the controller
of an entity (``--controller ENTITY=participant.fmu``).

An FMU is taken for an OSMP participant when its modelDescription carries the ``net.pmsf.osmp`` tool
annotation. Its notional binary variables (each the integer triple ``NAME.base.lo``, ``NAME.base.hi``,
``NAME.size``, declared by ``osmp-binary-variable`` annotations with their MIME type) are, by the
OSMP names of a traffic participant: ``OSMPSensorViewIn`` (``osi3::SensorView``, required),
``OSMPTrafficCommandIn`` (``osi3::TrafficCommand``, optional) and ``OSMPTrafficUpdateOut``
(``osi3::TrafficUpdate``, required). Everything the packaging says is checked when the controller is
loaded, before anything runs: one line naming the file, the variable and its line in
modelDescription.xml otherwise (a wrong MIME type, an OSI major version other than this host's, or a
minor version newer than it, which may carry fields this host cannot fill).

Each step (:meth:`OsmpParticipant.step`): the SensorView and TrafficCommand are serialised into
buffers the host owns; the address is split into two signed 32-bit halves as OSMP defines, set with
the size, and each buffer is kept alive until the second ``fmi2DoStep`` after the one it was given to
(OSMP's rule for the guest's outputs, applied to the host's inputs as well). After ``doStep(t, dt)``
the output triple is read: a null address or a size of 0 or less is no TrafficUpdate (a fault, not an
empty message, which would decode as a valid empty one); the ``size`` bytes at the address must decode
as ``osi3::TrafficUpdate`` and carry exactly one update, for the host's id. Each is a
:class:`~vei_scenario.sut.ControllerFault` line naming the step time.
"""

from __future__ import annotations

import ctypes
import math
import zipfile
from dataclasses import dataclass
from pathlib import Path

from vei_scenario.process_end import note_native_library
from vei_scenario.sut.contract import ControllerFault

OSMP_TOOL = "net.pmsf.osmp"
OSMP_NS = "http://xsd.pmsf.net/OSISensorModelPackaging"
OSI_MIME = "application/x-open-simulation-interface"
ROLES = ("base.lo", "base.hi", "size")
#: notional variable -> (OSI message type its MIME type must name, causality, required)
VARIABLES = {
    "OSMPSensorViewIn": ("SensorView", "input", True),
    "OSMPTrafficCommandIn": ("TrafficCommand", "input", False),
    "OSMPTrafficUpdateOut": ("TrafficUpdate", "output", True),
}
#: how many of its last input buffers the host keeps alive (the one of this doStep and the one before)
KEPT_BUFFERS = 2


def host_osi_version() -> tuple[int, int, int]:
    """The OSI version of the installed bindings (the messages this host writes)."""
    from vei_scenario.reports.osi_trace import interface_version

    v = interface_version()
    return v.version_major, v.version_minor, v.version_patch


@dataclass(frozen=True)
class Binary:
    """One notional binary variable: the value references of its lo/hi/size integers, its MIME type."""

    name: str
    lo: int
    hi: int
    size: int
    mime: str
    osi_version: tuple[int, int, int]


#: the element of a build record in a ``<VendorAnnotations><Tool>`` of the modelDescription
BUILD = "Build"


@dataclass(frozen=True)
class BuildRecord:
    """What a participant built by a tool says it was built for (``<Tool name=...><Build resolver=
    "MODULE:FUNCTION" model=... fixed=DIGEST><Parameter name= value=/>...``): the function that gives
    its declared parameters for a run (vei's :func:`vei_scenario.fmu.osmp_parameters.run_values`),
    its model, a digest of what it holds fixed, the scenario's parameter values of the build."""

    resolver: str
    model: str
    digest: str
    parameters: tuple[tuple[str, str], ...]


def read_record(root) -> BuildRecord | None:
    """The build record in a parsed modelDescription, if a tool wrote one."""
    el = root.find(f"VendorAnnotations/Tool/{BUILD}[@resolver]")
    if el is None:
        return None
    params = tuple((p.get("name", ""), p.get("value", "")) for p in el.iterfind("Parameter"))
    return BuildRecord(el.get("resolver", ""), el.get("model", ""), el.get("fixed", ""), params)


@dataclass(frozen=True)
class OsmpPorts:
    """What vei reads of an OSMP participant's modelDescription."""

    path: Path
    guid: str
    identifier: str
    osmp_version: str
    sensor_view: Binary
    traffic_update: Binary
    traffic_command: Binary | None
    parameters: dict[str, tuple[int, str]]  # name -> (value reference, type)
    fmi3: bool = False
    once_per_process: bool = False  # canBeInstantiatedOnlyOncePerProcess
    record: BuildRecord | None = None  # what a vei-built participant was built for


def is_osmp(path: Path) -> bool:
    """Whether the FMU at ``path`` declares itself an OSMP model (the ``net.pmsf.osmp`` tool annotation)."""
    try:
        with zipfile.ZipFile(path) as z:
            text = z.read("modelDescription.xml")
    except (OSError, KeyError, zipfile.BadZipFile):
        return False
    return OSMP_TOOL.encode() in text


def _mime(text: str) -> tuple[str, dict[str, str]]:
    """``application/x-open-simulation-interface; type=SensorView; version=3.7.0`` -> (base, params)."""
    base, *rest = (p.strip() for p in text.split(";"))
    params = {}
    for p in rest:
        k, _, v = p.partition("=")
        params[k.strip().lower()] = v.strip().strip('"')
    return base.lower(), params


def _version(text: str) -> tuple[int, int, int] | None:
    parts = text.split(".")
    if len(parts) != 3 or not all(p.isdigit() for p in parts):
        return None
    return int(parts[0]), int(parts[1]), int(parts[2])


def read_osmp_ports(path: Path, label: str) -> OsmpPorts:
    """The OSMP participant's ports from its modelDescription, checked against the OSMP rules for a
    traffic participant and this host's OSI version: one :class:`ControllerFault` line otherwise."""
    from lxml import etree

    from vei_scenario.safe_xml import safe_parser

    name = path.name
    try:
        with zipfile.ZipFile(path) as z:
            root = etree.fromstring(z.read("modelDescription.xml"), safe_parser())
    except Exception as exc:  # noqa: BLE001 (a broken archive or modelDescription: the file's fault)
        raise ControllerFault(label, f"{path}: not a readable FMU ({' '.join(str(exc).split())})") from None

    def fault(reason: str, line: int | None = None) -> ControllerFault:
        where = f"{name}: modelDescription.xml" + (f" line {line}" if line else "")
        return ControllerFault(label, f"{where}: {reason}")

    if not root.get("fmiVersion", "").startswith("2."):
        raise fault(f"fmiVersion {root.get('fmiVersion')!r}: vei hosts OSMP participants of FMI 2.0")
    cs = root.find("CoSimulation")
    if cs is None:
        raise fault("not a co-simulation FMU (no <CoSimulation>); OSMP models are co-simulation FMUs")
    tool = root.find(f"VendorAnnotations/Tool[@name='{OSMP_TOOL}']")
    top = tool.find(f"{{{OSMP_NS}}}osmp") if tool is not None else None
    if top is None:
        raise fault(f'no <VendorAnnotations><Tool name="{OSMP_TOOL}"><osmp:osmp .../> (OSMP\'s model annotation)')
    default_osi = _version(top.get("osi-version", "")) if top.get("osi-version") else None
    host = host_osi_version()
    found: dict[str, dict[str, tuple]] = {}
    params: dict[str, tuple[int, str]] = {}
    for sv in root.iterfind("ModelVariables/ScalarVariable"):
        kind_el = next((c for c in sv if c.tag in ("Real", "Integer", "Boolean", "String", "Enumeration")), None)
        kind = kind_el.tag if kind_el is not None else ""
        if sv.get("causality") == "parameter":
            params[sv.get("name", "")] = (int(sv.get("valueReference")), kind)
        ann = sv.find(f"Annotations/Tool[@name='{OSMP_TOOL}']/{{{OSMP_NS}}}osmp-binary-variable")
        if ann is None:
            continue
        prefix, role, mime = ann.get("name", ""), ann.get("role", ""), ann.get("mime-type", "")
        if prefix not in VARIABLES:
            continue  # (a notional variable of another kind of OSMP model: not a participant's)
        if role not in ROLES:
            raise fault(f"{sv.get('name')}: OSMP role {role!r} is none of {', '.join(ROLES)}", sv.sourceline)
        if kind != "Integer":
            raise fault(f"{sv.get('name')}: {kind} variable, OSMP binary variables are Integer", sv.sourceline)
        msg, causality, _ = VARIABLES[prefix]
        if sv.get("causality") != causality:
            raise fault(f"{sv.get('name')}: causality {sv.get('causality')!r}, {prefix} is an {causality}",
                        sv.sourceline)  # fmt: skip
        if role in found.setdefault(prefix, {}):
            raise fault(f"{prefix}: two variables with role {role}", sv.sourceline)
        found[prefix][role] = (int(sv.get("valueReference")), mime, sv.sourceline)
    binaries: dict[str, Binary] = {}
    for prefix, (msg, _causality, required) in VARIABLES.items():
        roles = found.get(prefix, {})
        if not roles:
            if required:
                raise fault(f"no OSMP binary variable {prefix} (a traffic participant needs "
                            f"{prefix}.base.lo, .base.hi and .size, type={msg})")  # fmt: skip
            continue
        missing = [r for r in ROLES if r not in roles]
        if missing:
            raise fault(f"{prefix}: no {' or '.join(f'{prefix}.{r}' for r in missing)}")
        mimes = {m for _, m, _ in roles.values()}
        line = roles["base.lo"][2]
        if len(mimes) != 1:
            raise fault(f"{prefix}: its variables declare different MIME types", line)
        base, mp = _mime(mimes.pop())
        if base != OSI_MIME:
            raise fault(f"{prefix}: MIME type {base!r}, OSMP requires {OSI_MIME!r}", line)
        if mp.get("type") != msg:
            raise fault(f"{prefix}: MIME type says type={mp.get('type', '')}, OSMP requires type={msg} "
                        "for this variable", line)  # fmt: skip
        version = _version(mp["version"]) if "version" in mp else default_osi
        if version is None:
            raise fault(f"{prefix}: no OSI version (MIME version= or osmp:osmp osi-version=)", line)
        shown = ".".join(map(str, version))
        here = ".".join(map(str, host))
        if version[0] != host[0]:
            raise fault(f"{prefix}: OSI {shown}, this host speaks OSI {here} (another major version)", line)
        if version[1] > host[1]:
            raise fault(f"{prefix}: OSI {shown} is newer than this host's OSI {here}", line)
        binaries[prefix] = Binary(prefix, roles["base.lo"][0], roles["base.hi"][0], roles["size"][0],
                                  f"{base}; type={msg}; version={shown}", version)  # fmt: skip
    return OsmpPorts(
        path,
        root.get("guid", ""),
        cs.get("modelIdentifier", ""),
        top.get("version", ""),
        binaries["OSMPSensorViewIn"],
        binaries["OSMPTrafficUpdateOut"],
        binaries.get("OSMPTrafficCommandIn"),
        params,
        once_per_process=cs.get("canBeInstantiatedOnlyOncePerProcess") == "true",
        record=read_record(root),
    )


def split_address(address: int) -> tuple[int, int]:
    """A 64-bit address as OSMP passes it: (lo, hi), each 32 bits read as a signed int32."""
    lo, hi = address & 0xFFFFFFFF, (address >> 32) & 0xFFFFFFFF
    return (lo - (1 << 32) if lo >= 1 << 31 else lo), (hi - (1 << 32) if hi >= 1 << 31 else hi)


def merge_address(lo: int, hi: int) -> int:
    return ((int(hi) & 0xFFFFFFFF) << 32) | (int(lo) & 0xFFFFFFFF)


#: The FMUs declared instantiable only once per process that this process has instantiated.
_INSTANTIATED: set[Path] = set()


class OsmpParticipant:
    """One instance of the OSMP FMU for one run: serialised messages in, the checked update out."""

    def __init__(self, ports: OsmpPorts, label: str, properties: dict[str, str]) -> None:
        from fmpy.fmi2 import FMU2Slave

        from vei_scenario.sut.fmu import _call_failure, _typed, _unzipped

        self.ports, self.label = ports, label
        self._kept: list[ctypes.Array] = []
        if ports.once_per_process:
            if ports.path.resolve() in _INSTANTIATED:
                once = "(canBeInstantiatedOnlyOncePerProcess): host it in one run per process"
                raise ControllerFault(label, f"{ports.path.name} can be instantiated only once per process {once}")
            _INSTANTIATED.add(ports.path.resolve())
        try:
            self.fmu = FMU2Slave(guid=ports.guid, unzipDirectory=_unzipped(ports.path),
                                 modelIdentifier=ports.identifier, instanceName="osmp")  # fmt: skip
            note_native_library(str(ports.path))  # (loaded: this process ends without its finalisers)
            self.fmu.instantiate()
            self.fmu.setupExperiment(startTime=0.0)
            self.fmu.enterInitializationMode()
            for name, value in properties.items():  # only what it declares
                if name in ports.parameters:
                    vr, kind = ports.parameters[name]
                    v = _typed(kind, value, name, label)
                    if kind == "Real":
                        self.fmu.setReal([vr], [v])
                    elif kind in ("Integer", "Enumeration"):
                        self.fmu.setInteger([vr], [v])
                    elif kind == "Boolean":
                        self.fmu.setBoolean([vr], [v])
                    else:
                        self.fmu.setString([vr], [v])
            self.fmu.exitInitializationMode()
        except ControllerFault:
            raise
        except Exception as exc:  # noqa: BLE001 (the FMU's failure)
            raise ControllerFault(label, f"instantiating {ports.path.name} failed: {_call_failure(exc)}") from None
        self.live = True

    def _give(self, binary: Binary, data: bytes) -> tuple[list[int], list[int]]:
        buf = ctypes.create_string_buffer(data, max(len(data), 1))
        self._kept.append(buf)
        lo, hi = split_address(ctypes.addressof(buf))
        return [binary.lo, binary.hi, binary.size], [lo, hi, len(data)]

    def step(self, sensor_view: bytes, traffic_command: bytes | None, host_id: int, t_s: float, dt_s: float,
             names: dict[int, str] | None = None):  # fmt: skip
        """One ``doStep(t_s, dt_s)``; the host's update (an ``osi3.MovingObject``) of the TrafficUpdate.
        ``names``: the entity of each id, for the messages."""
        names = names or {}

        def who(i: int) -> str:
            return f"{i} ({names[i]})" if i in names else str(i)

        from google.protobuf.message import DecodeError
        from osi3.osi_trafficupdate_pb2 import TrafficUpdate

        from vei_scenario.sut.fmu import _call_failure

        p = self.ports
        vrs, values = self._give(p.sensor_view, sensor_view)
        if p.traffic_command is not None and traffic_command is not None:
            more_vrs, more = self._give(p.traffic_command, traffic_command)
            vrs, values = vrs + more_vrs, values + more
        del self._kept[: -KEPT_BUFFERS * 2]  # (this doStep's and the previous one's stay valid)
        out = p.traffic_update
        try:
            self.fmu.setInteger(vrs, values)
            self.fmu.doStep(currentCommunicationPoint=t_s, communicationStepSize=dt_s)
            lo, hi, size = self.fmu.getInteger([out.lo, out.hi, out.size])
        except Exception as exc:  # noqa: BLE001
            self.close(getattr(exc, "status", None))
            raise ControllerFault(self.label, f"the FMU's doStep failed: {_call_failure(exc)}", t_s) from None
        address = merge_address(lo, hi)
        if address == 0 or size <= 0:  # (the address itself is left out: it differs run to run)
            why = "a null address" if address == 0 else f"size {size}"
            raise ControllerFault(self.label, f"no TrafficUpdate produced ({out.name} has {why})", t_s)
        data = ctypes.string_at(address, size)
        update = TrafficUpdate()
        try:
            update.ParseFromString(data)
        except (DecodeError, RuntimeError, ValueError) as exc:
            raise ControllerFault(self.label, f"{out.name}: {size} bytes that are no osi3.TrafficUpdate "
                                  f"({' '.join(str(exc).split()) or 'malformed protobuf'})", t_s) from None  # fmt: skip
        if update.HasField("version") and update.version.version_major != p.traffic_update.osi_version[0]:
            v = update.version
            raise ControllerFault(self.label, f"TrafficUpdate of OSI {v.version_major}.{v.version_minor}."
                                  f"{v.version_patch}, declared {out.mime}", t_s)  # fmt: skip
        ids = [u.id.value for u in update.update]
        if not ids:
            raise ControllerFault(self.label, "the TrafficUpdate holds no update (no MovingObject)", t_s)
        if ids != [host_id]:
            other = next(i for i in ids if i != host_id) if any(i != host_id for i in ids) else host_id
            what = f"is for id {who(other)}" if len(ids) == 1 else f"holds {len(ids)} updates (ids {ids})"
            raise ControllerFault(self.label, f"the TrafficUpdate {what}, not the host's id {who(host_id)}", t_s)
        moved = update.update[0]
        b = moved.base
        if not b.HasField("position"):
            raise ControllerFault(self.label, "the TrafficUpdate's update has no base.position", t_s)
        values = (b.position.x, b.position.y, b.orientation.yaw, b.velocity.x, b.velocity.y)
        if not all(math.isfinite(v) for v in values):
            raise ControllerFault(self.label, f"the TrafficUpdate's pose or velocity is not finite {values}", t_s)
        return moved

    def close(self, status: int | None = None) -> None:
        """End the instance (:func:`~vei_scenario.sut.fmu.end_instance`) and let its buffers go."""
        if not getattr(self, "live", False):
            return
        self.live = False
        from vei_scenario.sut.fmu import end_instance

        end_instance(self.fmu, status)
        self._kept.clear()
