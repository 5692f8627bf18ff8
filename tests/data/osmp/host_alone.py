#!/usr/bin/env python
"""Minimal OSMP host (fmpy + osi3) for the traffic-participant test partners in this folder.

Independent of any other host: written from the OSMP specification only.

What it does, per FMU:
  load   - reads modelDescription.xml, checks the net.pmsf.osmp VendorAnnotation and the
           osmp-binary-variable annotations: OSMPSensorViewIn (type=SensorView) and
           OSMPTrafficUpdateOut (type=TrafficUpdate) must each have exactly one base.lo,
           base.hi and size Integer with matching causality, discrete variability, and one
           MIME type; OSMPTrafficCommandIn (type=TrafficCommand) is optional.
  step   - builds an osi3::SensorView (global_ground_truth with the host vehicle and the other
           objects, host_vehicle_id set in the SensorView and the GroundTruth), serializes it
           into a ctypes buffer that stays alive until after the doStep, sets
           OSMPSensorViewIn.base.lo/.base.hi/.size (address split into signed int32 halves),
           calls doStep(t, dt), reads OSMPTrafficUpdateOut.*, merges the address,
           ctypes.string_at(addr, size), parses osi3::TrafficUpdate and applies the update for
           the host id (position x/y, yaw, velocity -> speed along the heading).
  errors - OsmpError(kind, message, t) for: bad annotations (kind "annotation", at load),
           null/size-0 output ("no-output"), undecodable output ("decode"), update without the
           host id or with a foreign id ("wrong-id"), output buffer changed/freed before the
           beginning of the second doStep after it was produced ("lifetime").

Run `python host_alone.py` to execute the analytic checks for StraightLine and
SimpleAebOsmp and the detection of the four bad partners; exits non-zero on any failure.
"""
import ctypes
import math
import os
import shutil
import sys
import xml.etree.ElementTree as ET
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from osi3.osi_sensorview_pb2 import SensorView
from osi3.osi_trafficcommand_pb2 import TrafficCommand
from osi3.osi_trafficupdate_pb2 import TrafficUpdate

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parents[2] / "examples" / "osmp"  # (the good partners are vei's examples)


def partner(fmu):
    """The partner FMU of that name: beside this script, else among the examples."""
    fmu = Path(fmu)
    if fmu.is_absolute():
        return fmu
    return HERE / fmu if (HERE / fmu).is_file() else EXAMPLES / fmu
OSMP_NS = "http://xsd.pmsf.net/OSISensorModelPackaging"
OSI_MIME = "application/x-open-simulation-interface"
ROLES = ("base.lo", "base.hi", "size")


class OsmpError(Exception):
    def __init__(self, kind, message, t=None):
        self.kind, self.t = kind, t
        super().__init__(f"[{kind}]" + (f" t={t:.3f}s" if t is not None else " (load)") + f": {message}")


# ---------------------------------------------------------------- address helpers
def split_address(addr):
    lo, hi = addr & 0xFFFFFFFF, (addr >> 32) & 0xFFFFFFFF
    return (lo - (1 << 32) if lo >= 1 << 31 else lo), (hi - (1 << 32) if hi >= 1 << 31 else hi)


def merge_address(lo, hi):
    return ((hi & 0xFFFFFFFF) << 32) | (lo & 0xFFFFFFFF)


def parse_mime(mime):
    parts = [p.strip() for p in mime.split(";")]
    params = {}
    for p in parts[1:]:
        if "=" in p:
            k, v = p.split("=", 1)
            params[k.strip().lower()] = v.strip().strip('"')
    return parts[0].lower(), params


# ---------------------------------------------------------------- annotations
def read_osmp_annotations(fmu_path):
    """{'osmp': {version, osi-version}, 'binary': {prefix: {role: (var_name, causality,
    variability, mime)}}} from modelDescription.xml (namespace-aware)."""
    with zipfile.ZipFile(fmu_path) as z:
        root = ET.fromstring(z.read("modelDescription.xml"))
    out = {"osmp": None, "binary": {}}
    va = root.find("VendorAnnotations")
    if va is not None:
        for tool in va.findall("Tool"):
            if tool.get("name") == "net.pmsf.osmp":
                el = tool.find(f"{{{OSMP_NS}}}osmp")
                if el is not None:
                    out["osmp"] = dict(el.attrib)
    for sv in root.find("ModelVariables"):
        for tool in sv.findall("Annotations/Tool"):
            if tool.get("name") != "net.pmsf.osmp":
                continue
            for el in tool.findall(f"{{{OSMP_NS}}}osmp-binary-variable"):
                d = out["binary"].setdefault(el.get("name"), {})
                if el.get("role") in d:
                    raise OsmpError("annotation", f"{el.get('name')}: role {el.get('role')} twice")
                d[el.get("role")] = (sv.get("name"), sv.get("causality"), sv.get("variability"),
                                     el.get("mime-type", "application/octet-stream"))
    return out


def check_osmp(fmu_path, md):
    ann = read_osmp_annotations(fmu_path)
    if ann["osmp"] is None:
        raise OsmpError("annotation", "no <Tool name=\"net.pmsf.osmp\"><osmp:osmp .../> in VendorAnnotations")
    osi_default = ann["osmp"].get("osi-version")
    types = {v.name: v.type for v in md.modelVariables}
    expect = {"OSMPSensorViewIn": ("SensorView", "input", True),
              "OSMPTrafficCommandIn": ("TrafficCommand", "input", False),
              "OSMPTrafficUpdateOut": ("TrafficUpdate", "output", True)}
    for prefix, (typ, caus, required) in expect.items():
        roles = ann["binary"].get(prefix)
        if roles is None:
            if required:
                raise OsmpError("annotation", f"no notional binary variable {prefix}")
            continue
        if set(roles) != set(ROLES):
            raise OsmpError("annotation", f"{prefix}: roles {sorted(roles)} != {list(ROLES)}")
        mimes = {r[3] for r in roles.values()}
        if len(mimes) != 1:
            raise OsmpError("annotation", f"{prefix}: differing MIME types {sorted(mimes)}")
        base, params = parse_mime(mimes.pop())
        if base != OSI_MIME:
            raise OsmpError("annotation", f"{prefix}: MIME base {base!r} is not {OSI_MIME}")
        if params.get("type") != typ:
            raise OsmpError("annotation", f"{prefix}: MIME type={params.get('type')!r}, expected type={typ}")
        if not (params.get("version") or osi_default):
            raise OsmpError("annotation", f"{prefix}: no OSI version (MIME or osi-version)")
        for role, (vname, vcaus, vvar, _) in roles.items():
            if vname != f"{prefix}.{role}":
                raise OsmpError("annotation", f"{prefix}: role {role} on variable {vname}")
            if types.get(vname) != "Integer" or vcaus != caus or vvar != "discrete":
                raise OsmpError("annotation", f"{vname}: must be a discrete Integer {caus}")
    return ann


# ---------------------------------------------------------------- world
@dataclass
class Obj:
    id: int
    x: float
    y: float
    yaw: float
    speed: float
    length: float = 4.5
    width: float = 1.8


@dataclass
class Sample:
    t: float
    x: float
    y: float
    yaw: float
    speed: float
    gap: float  # host front bumper -> nearest point of the first other object, along heading


def gap_ahead(h, o):
    """Longitudinal gap from h's front bumper to o's box (host frame, o's corners)."""
    c, s = math.cos(h.yaw), math.sin(h.yaw)
    co, so = math.cos(o.yaw), math.sin(o.yaw)
    xs = []
    for a, b in ((1, 1), (1, -1), (-1, 1), (-1, -1)):
        wx = o.x + a * o.length / 2 * co - b * o.width / 2 * so
        wy = o.y + a * o.length / 2 * so + b * o.width / 2 * co
        xs.append(c * (wx - h.x) + s * (wy - h.y))
    return min(xs) - h.length / 2


def place(host, fwd, left, **kw):
    """An object at (fwd, left) in the host frame with the host's yaw (unless given)."""
    c, s = math.cos(host.yaw), math.sin(host.yaw)
    kw.setdefault("yaw", host.yaw)
    return Obj(x=host.x + fwd * c - left * s, y=host.y + fwd * s + left * c, **kw)


# ---------------------------------------------------------------- host
class OsmpHost:
    def __init__(self, fmu_path, params=None, instance="partner"):
        self.path = Path(fmu_path)
        self.md = read_model_description(str(self.path))
        self.ann = check_osmp(self.path, self.md)  # raises OsmpError("annotation")
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.has_tc = "OSMPTrafficCommandIn.size" in self.vr
        self.unzipdir = extract(str(self.path))
        self.fmu = FMU2Slave(guid=self.md.guid, unzipDirectory=self.unzipdir,
                             modelIdentifier=self.md.coSimulation.modelIdentifier,
                             instanceName=instance)
        self.fmu.instantiate()
        self.fmu.setupExperiment(startTime=0.0)
        self.fmu.enterInitializationMode()
        for k, val in (params or {}).items():
            self.fmu.setReal([self.vr[k]], [float(val)])
        self.fmu.exitInitializationMode()
        self._keep_in = []      # input buffers, kept alive across the doStep
        self._prev_out = []     # [(step index, addr, size, bytes)] for the lifetime check
        self.step_index = 0

    def close(self):
        try:
            self.fmu.terminate()
            self.fmu.freeInstance()
        finally:
            shutil.rmtree(self.unzipdir, ignore_errors=True)

    def _set_binary(self, prefix, data):
        if data is None:
            vals = [0, 0, 0]
        else:
            buf = ctypes.create_string_buffer(data, max(1, len(data)))
            self._keep_in.append(buf)
            lo, hi = split_address(ctypes.addressof(buf))
            vals = [lo, hi, len(data)]
        self.fmu.setInteger([self.vr[f"{prefix}.{r}"] for r in ROLES], vals)

    @staticmethod
    def sensor_view(t, host, others):
        sv = SensorView()
        sv.version.version_major, sv.version.version_minor, sv.version.version_patch = 3, 7, 0
        sv.timestamp.seconds = int(math.floor(t + 1e-12))
        sv.timestamp.nanos = min(999_999_999, int(round((t - math.floor(t + 1e-12)) * 1e9)))
        sv.host_vehicle_id.value = host.id
        gt = sv.global_ground_truth
        gt.version.CopyFrom(sv.version)
        gt.timestamp.CopyFrom(sv.timestamp)
        gt.host_vehicle_id.value = host.id
        for o in [host] + list(others):
            mo = gt.moving_object.add()
            mo.id.value = o.id
            mo.type = mo.TYPE_VEHICLE
            b = mo.base
            b.dimension.length, b.dimension.width, b.dimension.height = o.length, o.width, 1.5
            b.position.x, b.position.y, b.position.z = o.x, o.y, 0.0
            b.orientation.yaw = o.yaw
            b.velocity.x, b.velocity.y = o.speed * math.cos(o.yaw), o.speed * math.sin(o.yaw)
        return sv

    def step(self, t, dt, host, others, traffic_command=None):
        """One co-simulation step; returns the host's TrafficUpdate MovingObject."""
        self._keep_in = []  # inputs of the previous step: their lifetime ended with that doStep
        self._set_binary("OSMPSensorViewIn", self.sensor_view(t, host, others).SerializeToString())
        if self.has_tc:
            self._set_binary("OSMPTrafficCommandIn",
                             None if traffic_command is None else traffic_command.SerializeToString())
        # lifetime: an output of doStep k must still be intact before doStep k+2 begins
        for (k, addr, size, data) in self._prev_out:
            if ctypes.string_at(addr, size) != data:
                raise OsmpError("lifetime", f"output of step {k} changed before doStep {self.step_index}", t)
        self._prev_out = [p for p in self._prev_out if p[0] >= self.step_index - 1]
        status = self.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=dt)
        if status not in (0, None):
            raise OsmpError("fmi", f"doStep returned {status}", t)
        lo, hi, size = self.fmu.getInteger([self.vr[f"OSMPTrafficUpdateOut.{r}"] for r in ROLES])
        addr = merge_address(lo, hi)
        if addr == 0 or size <= 0:
            raise OsmpError("no-output", f"OSMPTrafficUpdateOut has no valid buffer "
                                         f"(address 0x{addr:x}, size {size})", t)
        data = ctypes.string_at(addr, size)
        self._prev_out.append((self.step_index, addr, size, data))
        self.step_index += 1
        tu = TrafficUpdate()
        try:
            tu.ParseFromString(data)
        except Exception as exc:
            raise OsmpError("decode", f"TrafficUpdate does not decode: {exc}", t)
        ids = [u.id.value for u in tu.update]
        if host.id not in ids:
            raise OsmpError("wrong-id", f"TrafficUpdate ids {ids} do not contain host id {host.id}", t)
        foreign = [i for i in ids if i != host.id]
        if foreign:
            raise OsmpError("wrong-id", f"TrafficUpdate also updates ids {foreign} (host is {host.id})", t)
        return tu.update[ids.index(host.id)]


def simulate(fmu, host, others, t_end, dt, params=None, traffic_command=None):
    """Run fmu as the host's traffic participant; others move at constant velocity.
    Returns [Sample] with the state at t=0, dt, ..., n*dt."""
    h = OsmpHost(partner(fmu), params)
    try:
        n = int(round(t_end / dt))
        out = [Sample(0.0, host.x, host.y, host.yaw, host.speed, gap_ahead(host, others[0]) if others else math.inf)]
        for k in range(n):
            t = k * dt
            u = h.step(t, dt, host, others, traffic_command)
            b = u.base
            host.x, host.y, host.yaw = b.position.x, b.position.y, b.orientation.yaw
            host.speed = b.velocity.x * math.cos(host.yaw) + b.velocity.y * math.sin(host.yaw)
            for o in others:
                o.x += o.speed * dt * math.cos(o.yaw)
                o.y += o.speed * dt * math.sin(o.yaw)
            out.append(Sample((k + 1) * dt, host.x, host.y, host.yaw, host.speed,
                              gap_ahead(host, others[0]) if others else math.inf))
        return out
    finally:
        h.close()


# ---------------------------------------------------------------- scenarios / checks
YAW = 0.4  # non-zero heading so that frame errors show


def new_host(speed=0.0, x=5.0, y=-3.0, yaw=YAW):
    return Obj(id=1, x=x, y=y, yaw=yaw, speed=speed)


def check_straight_line(speed=None, dt=0.02, t_end=2.0, with_command=False):
    host = new_host(speed=3.0)
    x0, y0 = host.x, host.y
    other = place(host, 30.0, 8.0, id=2, speed=0.0)  # off to the side, irrelevant
    tc = None
    if with_command:
        tc = TrafficCommand()
        tc.traffic_participant_id.value = 1
    params = None if speed is None else {"speed_mps": speed}
    v = 10.0 if speed is None else speed
    tr = simulate("StraightLine.fmu", host, [other], t_end, dt, params, tc)
    d = v * t_end
    ex, ey = x0 + d * math.cos(YAW), y0 + d * math.sin(YAW)
    last = tr[-1]
    err = math.hypot(last.x - ex, last.y - ey)
    assert err < 1e-6, f"StraightLine: at t={last.t} pos ({last.x:.6f},{last.y:.6f}) expected ({ex:.6f},{ey:.6f})"
    assert all(abs(s.yaw - YAW) < 1e-12 for s in tr), "StraightLine changed its heading"
    assert all(abs(s.speed - v) < 1e-9 for s in tr[1:]), "StraightLine reported another speed"
    return f"StraightLine v={v} dt={dt}: after {t_end}s moved {d} m along yaw {YAW} (err {err:.1e} m)"


def aeb_run(v0, gap0, left=0.0, t_end=6.0, dt=0.02, other_speed=0.0):
    host = new_host(speed=v0)
    fwd = host.length / 2 + gap0 + 4.5 / 2
    other = place(host, fwd, left, id=2, speed=other_speed)
    return simulate("SimpleAebOsmp.fmu", host, [other], t_end, dt)


def onset_index(tr):
    """Index k of the first step (doStep at t=k*dt) that braked."""
    for k in range(len(tr) - 1):
        if tr[k + 1].speed < tr[k].speed - 1e-12:
            return k
    return None


def check_aeb_clear(left=3.5, v0=20.0, t_end=3.0, dt=0.02):
    tr = aeb_run(v0, 20.0, left=left, t_end=t_end, dt=dt)
    assert onset_index(tr) is None, f"AEB braked for an object {left} m to the side"
    d = math.hypot(tr[-1].x - tr[0].x, tr[-1].y - tr[0].y)
    assert abs(d - v0 * t_end) < 1e-6, f"AEB without threat moved {d}, expected {v0 * t_end}"
    return f"SimpleAebOsmp object {left} m left of path: no braking, {d:.6f} m in {t_end}s"


def check_aeb_corridor_edge(v0=20.0, dt=0.02):
    """Corridor = host width (1.8) + 0.5 m -> half 1.15 m; object half width 0.9 m:
    an object parallel to the host overlaps the corridor iff |left| <= 2.05 m."""
    tr = aeb_run(v0, 30.0, left=2.0, t_end=0.1, dt=dt)  # TTC 1.5 s, edge 0.05 m inside
    assert onset_index(tr) == 0, "AEB ignored an object overlapping the corridor edge by 0.05 m"
    tr = aeb_run(v0, 30.0, left=-2.0, t_end=0.1, dt=dt)
    assert onset_index(tr) == 0, "AEB ignored an object (right side) overlapping the corridor by 0.05 m"
    tr = aeb_run(v0, 30.0, left=2.1, t_end=0.1, dt=dt)
    assert onset_index(tr) is None, "AEB braked for an object 0.05 m outside the corridor"
    return "SimpleAebOsmp corridor edge: brakes for |left|=2.0 m (inside), not for 2.1 m (outside)"


def check_no_input_is_safe(fmu="StraightLine.fmu"):
    """OSMPSensorViewIn left at 0/0/0: the partner must not crash and publish nothing."""
    h = OsmpHost(partner(fmu))
    try:
        h.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.02)
        vals = h.fmu.getInteger([h.vr[f"OSMPTrafficUpdateOut.{r}"] for r in ROLES])
        assert list(vals) == [0, 0, 0], f"{fmu} published {vals} without any SensorView"
    finally:
        h.close()
    return f"{fmu}: no SensorView -> doStep OK, OSMPTrafficUpdateOut stays 0/0/0"


def check_aeb_brakes_and_stops(v0=20.0, gap0=60.1, dt=0.02):
    tr = aeb_run(v0, gap0, t_end=12.0, dt=dt)
    k = onset_index(tr)
    # analytic onset: first k with gap0 - v0*dt*k < 2*v0
    k_exp = math.floor((gap0 - 2 * v0) / (v0 * dt)) + 1
    assert k == k_exp, f"AEB onset at step {k}, expected {k_exp} (t={k_exp * dt:.2f}s)"
    assert abs(tr[k].gap - (gap0 - v0 * dt * k)) < 1e-6
    # constant 6 m/s^2 while TTC < 2 s: for v0 >= 12 it holds at least (v0-12)/3 s after onset
    n_hold = int(min(1.0, (v0 - 12.0) / 3.0) / dt)
    assert abs(tr[k + n_hold].speed - (v0 - 6.0 * n_hold * dt)) < 1e-9, "AEB not braking at 6 m/s^2"
    speeds = [s.speed for s in tr]
    assert all(b <= a + 1e-12 for a, b in zip(speeds, speeds[1:])), "AEB speed increased"
    assert all(abs((a - b) - 6.0 * dt) < 1e-9 or abs(a - b) < 1e-12 or b == 0.0
               for a, b in zip(speeds, speeds[1:])), "speed change is neither 0 nor 6*dt"
    gmin = min(s.gap for s in tr)
    assert gmin > 0.0, f"SimpleAebOsmp hit the stationary object (min gap {gmin})"
    return (f"SimpleAebOsmp v0={v0} gap0={gap0}: brakes at t={k * dt:.2f}s (gap {tr[k].gap:.2f} m), "
            f"v={tr[k + n_hold].speed:.2f} after {n_hold * dt:.2f}s, min gap {gmin:.2f} m, "
            f"v(12s)={tr[-1].speed:.3f}")


def check_aeb_too_fast(v0=30.0, gap0=80.1, dt=0.02):
    """v0 >= 24: stop distance v0^2/12 > 2 v0, so braking holds until contact."""
    tr = aeb_run(v0, gap0, t_end=6.0, dt=dt)
    k = onset_index(tr)
    k_exp = math.floor((gap0 - 2 * v0) / (v0 * dt)) + 1
    assert k == k_exp, f"onset {k} != {k_exp}"
    gap_b = tr[k].gap
    hit = next(i for i, s in enumerate(tr) if s.gap <= 0.0)
    v_imp = math.sqrt(v0 * v0 - 2 * 6.0 * gap_b)
    assert abs(tr[hit].speed - v_imp) < 6.0 * dt + 1e-6, f"contact speed {tr[hit].speed} vs {v_imp}"
    assert abs(tr[k + 100].speed - (v0 - 12.0)) < 1e-9
    return (f"SimpleAebOsmp v0={v0} gap0={gap0}: brakes at t={k * dt:.2f}s, contact at "
            f"t={tr[hit].t:.2f}s with {tr[hit].speed:.2f} m/s (analytic {v_imp:.2f})")


def check_bad(fmu, kind, at_load=False):
    host = new_host(speed=5.0)
    other = place(host, 30.0, 8.0, id=2, speed=0.0)
    try:
        simulate(fmu, host, [other], 0.2, 0.02)
    except OsmpError as e:
        assert e.kind == kind, f"{fmu}: got {e}, expected kind {kind}"
        assert (e.t is None) == at_load, f"{fmu}: {e} (expected {'load' if at_load else 't=0'})"
        assert at_load or e.t == 0.0, f"{fmu}: detected late: {e}"
        return f"{fmu}: {e}"
    raise AssertionError(f"{fmu}: no error reported")


BAD = {"WrongMime.fmu": ("annotation", True), "ZeroSize.fmu": ("no-output", False),
       "WrongId.fmu": ("wrong-id", False), "NeverWrites.fmu": ("no-output", False)}


def main():
    checks = [lambda: check_straight_line(),
              lambda: check_straight_line(speed=7.5, dt=0.05, t_end=3.0, with_command=True),
              lambda: check_aeb_clear(3.5), lambda: check_aeb_clear(2.1),
              lambda: check_aeb_corridor_edge(),
              lambda: check_no_input_is_safe("StraightLine.fmu"),
              lambda: check_no_input_is_safe("SimpleAebOsmp.fmu"),
              lambda: check_aeb_brakes_and_stops(),
              lambda: check_aeb_too_fast()]
    checks += [lambda f=f, k=k: check_bad(f, *k) for f, k in BAD.items()]
    ok = True
    for c in checks:
        try:
            print("PASS", c())
        except AssertionError as e:
            ok = False
            print("FAIL", e)
    return 0 if ok else 1


if __name__ == "__main__":
    # End without running the loaded libraries' finalisers: a PythonFMU-built partner (StraightLine.fmu)
    # finalises its embedded interpreter from the library's fini, which at the exit of a Python host
    # reads memory the host already freed (valgrind: invalid read in finalizePythonInterpreter under
    # _dl_fini) and now and then aborts with "corrupted double-linked list" after every check passed.
    code = main()
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
