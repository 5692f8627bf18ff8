"""Shared code of the OSMP traffic-participant test partners (pythonfmu, FMI 2.0 CS).

Written from the OSMP specification (ASAM OSI Sensor Model Packaging 1.5/1.6,
"Binary variables", "Sensor view inputs", "Traffic command inputs",
"Traffic update outputs"), not from any host's code.

Notional binary variables (each is three fmi2Integer variables):
  OSMPSensorViewIn.base.lo/.base.hi/.size       input,  discrete, start 0  (osi3::SensorView)
  OSMPTrafficCommandIn.base.lo/.base.hi/.size   input,  discrete, start 0  (osi3::TrafficCommand, optional)
  OSMPTrafficUpdateOut.base.lo/.base.hi/.size   output, discrete, initial exact, start 0 (osi3::TrafficUpdate)

Pointer convention: address = (hi as uint32) << 32 | (lo as uint32); each half is the
uint32 reinterpreted as a signed int32.  A merged address of 0 or a size <= 0 means
"no valid buffer" and is handled safely (no read).

Output lifetime: the buffer of the TrafficUpdate computed in doStep k stays valid (same
address, same bytes) at least until the beginning of doStep k+2; we keep the last
OUTPUT_RING buffers alive (double buffering plus slack).
"""
import ctypes
import math

from pythonfmu import Fmi2Causality, Fmi2Initial, Fmi2Slave, Fmi2Variability, Integer, Real

from osi3.osi_sensorview_pb2 import SensorView
from osi3.osi_trafficcommand_pb2 import TrafficCommand
from osi3.osi_trafficupdate_pb2 import TrafficUpdate

OSI_VERSION = (3, 7, 0)
OUTPUT_RING = 3


def split_address(addr):
    """64-bit address -> (lo, hi) as signed int32 (bit pattern unchanged)."""
    lo = addr & 0xFFFFFFFF
    hi = (addr >> 32) & 0xFFFFFFFF
    if lo >= 0x80000000:
        lo -= 0x100000000
    if hi >= 0x80000000:
        hi -= 0x100000000
    return lo, hi


def merge_address(lo, hi):
    return ((int(hi) & 0xFFFFFFFF) << 32) | (int(lo) & 0xFFFFFFFF)


def read_binary(lo, hi, size):
    """Bytes of a notional binary input, or None if no valid buffer is present."""
    addr = merge_address(lo, hi)
    if addr == 0 or int(size) <= 0:
        return None
    return ctypes.string_at(addr, int(size))


def find_host(sv):
    """(host MovingObject, list of the other MovingObjects) from a SensorView's ground truth."""
    if not sv.HasField("global_ground_truth"):
        return None, []
    gt = sv.global_ground_truth
    if sv.HasField("host_vehicle_id"):
        hid = sv.host_vehicle_id.value
    elif gt.HasField("host_vehicle_id"):
        hid = gt.host_vehicle_id.value
    else:
        return None, []
    host, others = None, []
    for mo in gt.moving_object:
        if mo.id.value == hid and host is None:
            host = mo
        else:
            others.append(mo)
    return host, others


class OsmpTrafficParticipant(Fmi2Slave):
    """Base class: OSMP variables, input decoding, double-buffered output.

    Subclasses implement compute(sv, tc, t, dt) -> TrafficUpdate or None
    (None = leave the output unchanged this step).
    """

    author = "vei OSMP test partners"
    description = "OSMP traffic participant test partner"
    with_traffic_command = True

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._ints = {}
        self._out_ring = []  # keeps the last OUTPUT_RING ctypes buffers alive
        self.last_error = ""
        self._register_binary("OSMPSensorViewIn", Fmi2Causality.input)
        if self.with_traffic_command:
            self._register_binary("OSMPTrafficCommandIn", Fmi2Causality.input)
        self._register_binary("OSMPTrafficUpdateOut", Fmi2Causality.output)

    # ---- variables -------------------------------------------------------------------
    def _register_binary(self, prefix, causality):
        for role in ("base.lo", "base.hi", "size"):
            name = f"{prefix}.{role}"
            self._ints[name] = 0
            kw = dict(causality=causality, variability=Fmi2Variability.discrete, start=0,
                      getter=(lambda n=name: self._ints[n]),
                      setter=(lambda v, n=name: self._ints.__setitem__(n, int(v))))
            if causality == Fmi2Causality.output:
                kw["initial"] = Fmi2Initial.exact
            self.register_variable(Integer(name, **kw), nested=False)

    def _binary_in(self, prefix):
        return read_binary(self._ints[f"{prefix}.base.lo"], self._ints[f"{prefix}.base.hi"],
                           self._ints[f"{prefix}.size"])

    def write_output(self, data: bytes, size_override=None):
        buf = ctypes.create_string_buffer(data, max(len(data), 1))
        self._out_ring.append(buf)
        del self._out_ring[:-OUTPUT_RING]
        lo, hi = split_address(ctypes.addressof(buf))
        self._ints["OSMPTrafficUpdateOut.base.lo"] = lo
        self._ints["OSMPTrafficUpdateOut.base.hi"] = hi
        self._ints["OSMPTrafficUpdateOut.size"] = len(data) if size_override is None else size_override

    # ---- FMI ---------------------------------------------------------------------------
    def do_step(self, current_time, step_size):
        raw = self._binary_in("OSMPSensorViewIn")
        sv = None
        if raw is not None:
            sv = SensorView()
            try:
                sv.ParseFromString(raw)
            except Exception as exc:  # undecodable input: report, keep going
                self.log(f"cannot decode OSMPSensorViewIn ({len(raw)} bytes): {exc}")
                sv = None
        tc = None
        if self.with_traffic_command:
            raw_tc = self._binary_in("OSMPTrafficCommandIn")
            if raw_tc is not None:
                tc = TrafficCommand()
                try:
                    tc.ParseFromString(raw_tc)
                except Exception as exc:
                    self.log(f"cannot decode OSMPTrafficCommandIn: {exc}")
                    tc = None
        tu = self.compute(sv, tc, current_time, step_size)
        if tu is not None:
            self.emit(tu)
        return True

    def emit(self, tu):
        self.write_output(tu.SerializeToString())

    def compute(self, sv, tc, t, dt):
        raise NotImplementedError


def new_traffic_update(sv, t_next):
    tu = TrafficUpdate()
    tu.version.version_major, tu.version.version_minor, tu.version.version_patch = OSI_VERSION
    sec = math.floor(t_next + 1e-12)
    tu.timestamp.seconds = int(sec)
    tu.timestamp.nanos = min(int(round((t_next - sec) * 1e9)), 999_999_999)
    return tu


def fill_pose(mo_out, host, x, y, yaw, speed, accel=0.0):
    """Write the host's new pose into a TrafficUpdate MovingObject."""
    mo_out.id.value = host.id.value
    b = mo_out.base
    if host.base.HasField("dimension"):
        b.dimension.CopyFrom(host.base.dimension)
    b.position.x = x
    b.position.y = y
    b.position.z = host.base.position.z
    b.orientation.roll = host.base.orientation.roll
    b.orientation.pitch = host.base.orientation.pitch
    b.orientation.yaw = yaw
    c, s = math.cos(yaw), math.sin(yaw)
    b.velocity.x = speed * c
    b.velocity.y = speed * s
    b.velocity.z = 0.0
    b.acceleration.x = accel * c
    b.acceleration.y = accel * s
    b.acceleration.z = 0.0
    if host.HasField("type"):
        mo_out.type = host.type
    return mo_out


def host_speed(host):
    """Speed of the host along its heading (world velocity projected on yaw), >= 0."""
    v = host.base.velocity
    yaw = host.base.orientation.yaw
    return max(0.0, v.x * math.cos(yaw) + v.y * math.sin(yaw))


def straight_line_update(sv, t, dt, speed, reported_id=None):
    """TrafficUpdate moving the host speed*dt along its current heading (None if no host)."""
    host, _ = find_host(sv) if sv is not None else (None, [])
    if host is None:
        return None
    yaw = host.base.orientation.yaw
    x = host.base.position.x + speed * dt * math.cos(yaw)
    y = host.base.position.y + speed * dt * math.sin(yaw)
    tu = new_traffic_update(sv, t + dt)
    mo = fill_pose(tu.update.add(), host, x, y, yaw, speed)
    if reported_id is not None:
        mo.id.value = reported_id
    return tu


def box_corners_in_host_frame(host, mo):
    """Corners of mo's bounding box (x forward, y left) relative to the host's centre."""
    hx, hy, hyaw = host.base.position.x, host.base.position.y, host.base.orientation.yaw
    ch, sh = math.cos(hyaw), math.sin(hyaw)
    ox, oy, oyaw = mo.base.position.x, mo.base.position.y, mo.base.orientation.yaw
    co, so = math.cos(oyaw), math.sin(oyaw)
    hl, hw = 0.5 * mo.base.dimension.length, 0.5 * mo.base.dimension.width
    out = []
    for a, b in ((hl, hw), (hl, -hw), (-hl, hw), (-hl, -hw)):
        wx = ox + a * co - b * so
        wy = oy + a * so + b * co
        dx, dy = wx - hx, wy - hy
        out.append((ch * dx + sh * dy, -sh * dx + ch * dy))
    return out


def aeb_gap(host, others, lateral_margin=0.5):
    """Smallest gap (m, from the host's front bumper) to any other moving object that lies
    ahead (centre ahead of the host's centre) and whose box overlaps the path corridor of
    total width host_width + lateral_margin; None if there is none."""
    half_len = 0.5 * host.base.dimension.length
    half_corr = 0.5 * (host.base.dimension.width + lateral_margin)
    hx, hy, hyaw = host.base.position.x, host.base.position.y, host.base.orientation.yaw
    best = None
    for mo in others:
        dx, dy = mo.base.position.x - hx, mo.base.position.y - hy
        if math.cos(hyaw) * dx + math.sin(hyaw) * dy <= 0.0:
            continue
        pts = box_corners_in_host_frame(host, mo)
        ys = [p[1] for p in pts]
        if max(ys) < -half_corr or min(ys) > half_corr:
            continue
        gap = max(0.0, min(p[0] for p in pts) - half_len)
        best = gap if best is None else min(best, gap)
    return best


def speed_param(slave, name="speed_mps", default=10.0, description=""):
    setattr(slave, name, default)
    slave.register_variable(Real(name, causality=Fmi2Causality.parameter,
                                 variability=Fmi2Variability.tunable, start=default,
                                 description=description))
