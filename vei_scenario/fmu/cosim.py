"""Co-simulation masters for the closed loop: a plain fmpy master (sequential or Jacobi) and
libcosim (Open Simulation Platform, through libcosimpy) loading the SSP package.

Both return the same record: per component, arrays of its outputs at every communication point
t = 0, dt, 2 dt, … — what :func:`compare_with_run` holds against ``vei run``'s trajectories.
"""

from __future__ import annotations

import ctypes
import math
import shutil
import tempfile
from pathlib import Path

import numpy as np

from vei_scenario.errors import VeiInputError
from vei_scenario.fmu.system import ClosedLoop, model_of
from vei_scenario.fmu.variables import SPECS
from vei_scenario.process_end import note_native_library

RECORDED = {"ego": ("x", "y", "yaw", "speed", "accel"), "sfm": ("x", "y", "yaw", "speed", "accel"), "cap": ("a_cmd",)}


def recorded(comp: str) -> tuple[str, ...]:
    """The outputs recorded of a component (every rider's as the threat's)."""
    return RECORDED[model_of(comp)]


COUPLINGS = ("sequential", "jacobi")


class FmuInstance:
    """One FMU instance driven through fmpy's FMI 2 / FMI 3 bindings, with prebuilt ctypes buffers
    (the master calls it ~10 times per step)."""

    def __init__(self, comp: str, fmu: Path, params: dict, workdir: Path) -> None:
        from fmpy import extract, read_model_description

        self.comp, self.spec = comp, SPECS[model_of(comp)]
        md = read_model_description(str(fmu))
        self.fmi3 = md.fmiVersion.startswith("3")
        unzip = extract(str(fmu), unzipdir=str(workdir / comp))
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        if self.fmi3:
            from fmpy.fmi3 import FMU3Slave

            self.fmu = FMU3Slave(
                guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier, instanceName=comp
            )
            note_native_library(str(fmu))  # (loaded: this process ends without its finalisers)
            self.fmu.instantiate()
            self.fmu.enterInitializationMode(startTime=0.0)
        else:
            from fmpy.fmi2 import FMU2Slave

            self.fmu = FMU2Slave(
                guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier, instanceName=comp
            )
            note_native_library(str(fmu))  # (loaded: this process ends without its finalisers)
            self.fmu.instantiate()
            self.fmu.setupExperiment(startTime=0.0)
            self.fmu.enterInitializationMode()
        types = {v.name: v.type for v in md.modelVariables}
        by_type: dict[str, tuple[list[int], list, list[str]]] = {}
        for name, value in params.items():
            if types[name] in ("Real", "Float64") and not math.isfinite(float(value)):
                raise VeiInputError(None, f"{comp}.{name}", f"{value!r} is not a finite number")
            vrs, vals, names = by_type.setdefault(types[name], ([], [], []))
            vrs.append(self.vr[name])
            vals.append(value)
            names.append(name)
        from fmpy.fmi1 import FMICallException

        for t, (vrs, vals, names) in by_type.items():
            try:
                if t in ("Real", "Float64"):
                    self._set_real(vrs, vals)
                elif t in ("Integer", "Int32"):
                    (self.fmu.setInt32 if self.fmi3 else self.fmu.setInteger)(vrs, [int(v) for v in vals])
                elif t == "Boolean":
                    self.fmu.setBoolean(vrs, [bool(v) for v in vals])
                else:
                    self.fmu.setString(vrs, [str(v) for v in vals])
            except FMICallException as exc:  # name what was being set, not only the status
                shown = ", ".join(f"{n}={v!r}" for n, v in list(zip(names, vals))[:6])
                more = f" and {len(names) - 6} more" if len(names) > 6 else ""
                raise VeiInputError(None, comp, f"the FMU refused the parameters {shown}{more}: {exc}") from None
        self.fmu.exitInitializationMode()
        self.inputs = [v.name for v in self.spec.variables if v.causality == "input"]
        self.outputs = [v.name for v in self.spec.variables if v.causality == "output" and v.type == "Real"]
        self._in_vr = (ctypes.c_uint * len(self.inputs))(*[self.vr[n] for n in self.inputs])
        self._in_val = (ctypes.c_double * len(self.inputs))()
        self._out_vr = (ctypes.c_uint * len(self.outputs))(*[self.vr[n] for n in self.outputs])
        self._out_val = (ctypes.c_double * len(self.outputs))()
        self.out_index = {n: i for i, n in enumerate(self.outputs)}
        self.in_index = {n: i for i, n in enumerate(self.inputs)}
        f = self.fmu
        if self.fmi3:
            self._raw_get = lambda: f.fmi3GetFloat64(
                f.component, self._out_vr, len(self.outputs), self._out_val, len(self.outputs)
            )
            self._raw_set = lambda: f.fmi3SetFloat64(
                f.component, self._in_vr, len(self.inputs), self._in_val, len(self.inputs)
            )
            flags = [ctypes.c_bool() for _ in range(3)]
            last = ctypes.c_double()
            self._raw_step = lambda t, h: f.fmi3DoStep(
                f.component,
                t,
                h,
                True,
                ctypes.byref(flags[0]),
                ctypes.byref(flags[1]),
                ctypes.byref(flags[2]),
                ctypes.byref(last),
            )
        else:
            self._raw_get = lambda: f.fmi2GetReal(f.component, self._out_vr, len(self.outputs), self._out_val)
            self._raw_set = lambda: f.fmi2SetReal(f.component, self._in_vr, len(self.inputs), self._in_val)
            self._raw_step = lambda t, h: f.fmi2DoStep(f.component, t, h, 1)

    def _set_real(self, vrs, vals) -> None:
        (self.fmu.setFloat64 if self.fmi3 else self.fmu.setReal)(vrs, [float(v) for v in vals])

    def get(self) -> ctypes.Array:
        self._raw_get()
        return self._out_val

    def set(self) -> None:
        if self.inputs:
            self._raw_set()

    def step(self, t: float, h: float) -> None:
        self._raw_step(t, h)

    def close(self) -> None:
        self.fmu.terminate()
        self.fmu.freeInstance()


def run_fmpy(
    loop: ClosedLoop, fmus: dict[str, Path], coupling: str = "sequential", timings: dict | None = None
) -> dict[str, dict[str, np.ndarray]]:
    """The closed loop through fmpy: ``sequential`` steps planner, ego, rider in turn, each on the
    newest outputs (vei run's default coupling); ``jacobi`` steps all on the previous outputs.
    ``timings`` receives ``load_s`` (extract, read modelDescription, instantiate, set parameters)
    and ``run_s`` (the steps)."""
    import time

    t_load = time.perf_counter()
    if coupling not in COUPLINGS:
        raise ValueError(f"coupling must be one of {', '.join(COUPLINGS)}")
    from fmpy.fmi1 import FMICallException

    work = Path(tempfile.mkdtemp(prefix="vei-cosim-"))
    slaves: dict[str, FmuInstance] = {}
    comp = ""
    try:
        for comp in loop.components:
            slaves[comp] = FmuInstance(comp, fmus[model_of(comp)], loop.parameters[comp], work)
        links = [
            (slaves[a], slaves[a].out_index[o], slaves[b], slaves[b].in_index[i]) for a, o, b, i in loop.connections
        ]
        into: dict[str, list] = {c: [x for x in links if x[2].comp == c] for c in slaves}
        n, h = loop.steps, loop.dt
        rec = {c: {q: np.empty(n + 1) for q in recorded(c)} for c in slaves}
        idx = {c: [(q, slaves[c].out_index[q]) for q in recorded(c)] for c in slaves}

        def record(k: int, c: str, out) -> None:
            for q, i in idx[c]:
                rec[c][q][k] = out[i]

        for c, s in slaves.items():
            record(0, c, s.get())
        t_run = time.perf_counter()
        for k in range(n):
            t = round(k * h, 9)
            if coupling == "jacobi":
                for c in slaves:
                    for a, ia, b, ib in into[c]:
                        b._in_val[ib] = a._out_val[ia]
                for s in slaves.values():
                    s.set()
                    s.step(t, h)
                for c, s in slaves.items():
                    record(k + 1, c, s.get())
            else:
                for c in loop.sequential_order:
                    s = slaves[comp := c]
                    for a, ia, b, ib in into[c]:
                        b._in_val[ib] = a._out_val[ia]
                    s.set()
                    s.step(t, h)
                    record(k + 1, c, s.get())
        if timings is not None:
            timings.update(load_s=t_run - t_load, run_s=time.perf_counter() - t_run)
        return rec
    except FMICallException as exc:  # the FMU logged why (through fmpy's logger) and refused
        raise VeiInputError(None, f"{comp or 'FMU'}", f"the FMU refused: {exc}") from None
    finally:
        for s in slaves.values():
            s.close()
        shutil.rmtree(work, ignore_errors=True)


def run_libcosim(ssp: Path, loop: ClosedLoop) -> dict[str, dict[str, np.ndarray]]:
    """The SSP package through libcosim's fixed-step (Jacobi) algorithm."""
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver

    log_output_level(CosimLogLevel.WARNING)  # its debug log prints every XML element it parses

    ex = CosimExecution.from_ssp_file(str(ssp), step_size=round(loop.dt * 1e9))  # ns
    obs = CosimObserver.create_last_value()
    ex.add_observer(obs)
    index = {c: ex.slave_index_from_instance_name(c) for c in loop.components}
    refs = {c: [SPECS[model_of(c)].vr(q) for q in recorded(c)] for c in index}
    n = loop.steps
    rec = {c: {q: np.empty(n + 1) for q in recorded(c)} for c in index}
    initial = {"x": "x0", "y": "y0", "yaw": "yaw0", "speed": "speed0"}
    for c in ("ego", *loop.riders):
        for q in recorded(c):
            rec[c][q][0] = loop.parameters[c].get(initial.get(q, ""), 0.0)
    rec["cap"]["a_cmd"][0] = 0.0
    for k in range(n):
        ex.step()
        for c, i in index.items():
            for q, v in zip(recorded(c), obs.last_real_values(i, refs[c])):
                rec[c][q][k + 1] = v
    ex.stop()
    return rec


def compare_with_run(rec: dict[str, dict[str, np.ndarray]], run, loop: ClosedLoop) -> dict[str, float]:
    """Largest position difference (m) per moving component (ego and every rider) between a
    co-simulation record and a ``vei run`` :class:`RunResult`, over their common communication points."""
    out = {}
    for comp in ("ego", *loop.riders):
        tr = run.traces[loop.entities[comp]]
        n = min(tr.x.size, rec[comp]["x"].size)
        out[comp] = float(np.max(np.hypot(tr.x[:n] - rec[comp]["x"][:n], tr.y[:n] - rec[comp]["y"][:n])))
    return out


#: The unit of each recorded output, appended to its column name as trajectories.csv names them.
COLUMN_NAMES = {
    "x": "x_m",
    "y": "y_m",
    "yaw": "heading_rad",
    "speed": "speed_mps",
    "accel": "acceleration_mps2",
    "a_cmd": "a_cmd_mps2",
}


def record_csv(rec: dict[str, dict[str, np.ndarray]], dt: float) -> str:
    """The co-simulated trajectories as CSV: ``time_s``, then ``component.quantity_unit`` columns (the
    ego, every rider, the planner), with the precision of trajectories.csv (times to the millisecond, or
    as many decimals as ``dt`` needs; values to six decimals, no negative zeros)."""
    riders = [c for c in rec if model_of(c) == "sfm"]
    cols = [(c, q) for c in ("ego", *riders, "cap") for q in recorded(c)]
    n = rec["ego"]["x"].size
    t_digits = max(3, -math.floor(math.log10(dt) + 1e-9)) if dt > 0 else 3
    lines = ["time_s," + ",".join(f"{c}.{COLUMN_NAMES[q]}" for c, q in cols)]
    for k in range(n):
        lines.append(f"{k * dt:.{t_digits}f}," + ",".join(f"{rec[c][q][k]:.6f}" for c, q in cols))
    return ("\n".join(lines) + "\n").replace(",-0.000000", ",0.000000")


def write_record_csv(rec: dict[str, dict[str, np.ndarray]], loop: ClosedLoop, path: Path) -> Path:
    """Write :func:`record_csv` to ``path`` (atomically)."""
    from vei_scenario.atomic_io import write_bytes_atomic

    write_bytes_atomic(path, record_csv(rec, loop.dt).encode())
    return path
