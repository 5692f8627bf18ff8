"""An FMI 2.0 or 3.0 co-simulation FMU as the system under test (``--controller Ego=planner.fmu``),
through fmpy, behind the same contract as a Python class.

Ports are matched by name. Inputs vei sets each step, from the observation at the step's start
(:data:`INPUTS`: vei_cap's own set, ``ego_x ego_y ego_yaw ego_speed threat_x threat_y threat_yaw
threat_speed``, plus accelerations, box sizes and the time); positions are box centres in the
OpenDRIVE frame, headings in rad. Output ``a_cmd`` (m/s²): read after ``doStep(t, dt)``, it drives the
step from t to t + dt. Without a threat its inputs keep their start values. Parameters are set only
where the FMU declares them: the scenario's controller properties silently where a name matches (the
planner's ``cruiseSpeed`` also as vei_cap's ``cruise_speed_mps``: :data:`PROPERTY_ALIASES`),
``--controller-param`` names that the FMU does not declare are refused. An input vei does not provide,
or no ``a_cmd`` output, is refused before anything runs; a ``doStep`` that does not return fmi2OK
(warning aside) fails the run with one line.
"""

from __future__ import annotations

import atexit
import hashlib
import math
import os
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

from vei_scenario.process_end import note_native_library
from vei_scenario.sut.contract import ControllerFault, Observation

#: Input name -> (which state, which field); ``time`` is the step's start time.
INPUTS = {
    **{
        f"{who}_{port}": (who, field)
        for who in ("ego", "threat")
        for port, field in (
            ("x", "x_m"),
            ("y", "y_m"),
            ("yaw", "heading_rad"),
            ("speed", "speed_mps"),
            ("accel", "accel_mps2"),
            ("length", "length_m"),
            ("width", "width_m"),
        )  # fmt: skip
    },
    "time": ("", "t_s"),
}
OUTPUT = "a_cmd"
_STATUS = {1: "Warning", 2: "Discard", 3: "Error", 4: "Fatal", 5: "Pending"}  # (FMI 3.0 has no Pending)


def status_name(call: str, status: int) -> str:
    """``fmi2Error`` / ``fmi3Error`` ...: a status named in the version of the ``call`` that returned it."""
    prefix = call[:4] if call[:4] in ("fmi2", "fmi3") else "fmi2"
    if status not in _STATUS or (prefix == "fmi3" and status == 5):
        return f"status {status}"
    return prefix + _STATUS[status]


@dataclass(frozen=True)
class FmuPorts:
    """What vei reads of the FMU's modelDescription."""

    path: Path
    fmi3: bool
    guid: str
    identifier: str
    inputs: tuple[tuple[str, int], ...]  # (name, value reference) of the inputs vei sets
    output: int  # value reference of a_cmd
    parameters: dict[str, tuple[int, str]]  # name -> (value reference, type)


def read_ports(path: Path, label: str) -> FmuPorts:
    """The FMU's ports, checked against what vei provides: one :class:`ControllerFault` line otherwise."""
    from fmpy import read_model_description

    if not path.is_file():
        raise ControllerFault(label, f"{path}: no such file")
    try:
        md = read_model_description(str(path))
    except Exception as exc:  # noqa: BLE001 (a broken archive or modelDescription: the file's fault)
        raise ControllerFault(label, f"{path}: not a readable FMU ({' '.join(str(exc).split())})") from None
    if md.coSimulation is None:
        raise ControllerFault(label, f"{path}: not a co-simulation FMU (no <CoSimulation>)")
    real = ("Real", "Float64")
    inputs, output, params = [], None, {}
    for v in md.modelVariables:
        if v.causality == "input":
            if v.name not in INPUTS or v.type not in real:
                offered = ", ".join(INPUTS)
                raise ControllerFault(label, f"{path.name}: input {v.name!r} ({v.type}) is none vei provides "
                                      f"(Real inputs by name: {offered})")  # fmt: skip
            inputs.append((v.name, v.valueReference))
        elif v.causality == "output" and v.name == OUTPUT:
            if v.type not in real:
                raise ControllerFault(label, f"{path.name}: output {OUTPUT} is {v.type}, not Real")
            output = v.valueReference
        elif v.causality == "parameter":
            params[v.name] = (v.valueReference, v.type)
    if output is None:
        outs = ", ".join(v.name for v in md.modelVariables if v.causality == "output") or "none"
        raise ControllerFault(
            label, f"{path.name}: no output {OUTPUT} (the acceleration command, m/s²; it has: {outs})"
        )
    fmi3 = md.fmiVersion.startswith("3")
    return FmuPorts(path, fmi3, md.guid, md.coSimulation.modelIdentifier, tuple(inputs), output, params)


def check_parameters(ports: FmuPorts, given: dict[str, str], label: str) -> None:
    """``--controller-param`` names must be parameters the FMU declares, their values of its type."""
    for name, value in given.items():
        if name not in ports.parameters:
            have = ", ".join(ports.parameters) or "none"
            raise ControllerFault(label, f"{ports.path.name} declares no parameter {name!r} (it has: {have})")
        _typed(ports.parameters[name][1], value, name, label)


#: FMU parameter name -> the scenario property that gives it where the FMU is not given it by its own
#: name: vei-compiled scenarios name the planner's cruise speed ``cruiseSpeed`` and the rider's type
#: ``riderType`` (esmini's controllers' style), vei's FMUs ``cruise_speed_mps`` and ``rider_type``
#: (their other parameters are named alike in both).
PROPERTY_ALIASES = {"cruise_speed_mps": "cruiseSpeed", "rider_type": "riderType"}


def fmu_properties(properties: dict[str, str]) -> dict[str, str]:
    """``properties`` with the aliased parameters (:data:`PROPERTY_ALIASES`) added where missing."""
    out = dict(properties)
    for parameter, prop in PROPERTY_ALIASES.items():
        if parameter not in out and prop in out:
            out[parameter] = out[prop]
    return out


#: Parameter types set as numbers: FMI 2.0's and FMI 3.0's.
FLOAT_KINDS = ("Real", "Float64", "Float32")
INT_KINDS = ("Integer", "Enumeration") + tuple(f"{u}Int{n}" for u in ("", "U") for n in (8, 16, 32, 64))


def _typed(kind: str, value: str, name: str, label: str):
    try:
        if kind in FLOAT_KINDS:
            v = float(value)
            if not math.isfinite(v):
                raise ValueError
            return v
        if kind in INT_KINDS:
            return int(value)
        if kind == "Boolean":
            if value.strip().lower() not in ("true", "false", "1", "0"):
                raise ValueError
            return value.strip().lower() in ("true", "1")
        return value
    except ValueError:
        raise ControllerFault(label, f"parameter {name}={value!r} is not a {kind} value") from None


_EXTRACTED: dict[str, str] = {}


def _unzipped(path: Path) -> str:
    """The FMU extracted once per process and content (removed when the process ends)."""
    from fmpy import extract

    key = hashlib.sha256(path.read_bytes()).hexdigest()
    if key not in _EXTRACTED:
        if not _EXTRACTED:
            atexit.register(_remove, os.getpid())
        _EXTRACTED[key] = extract(str(path), unzipdir=tempfile.mkdtemp(prefix="vei_fmu_"))
    return _EXTRACTED[key]


def _remove(owner: int) -> None:
    """Remove the extracted FMUs, in the process that extracted them (not in a child that inherited them)."""
    if os.getpid() == owner:
        for d in _EXTRACTED.values():
            shutil.rmtree(d, ignore_errors=True)


class FmuController:
    """One instance of the FMU for one run, stepped at vei's step."""

    def __init__(self, ports: FmuPorts, label: str, properties: dict[str, str]) -> None:
        self.ports, self.label = ports, label
        self.inputs = [(INPUTS[n], vr) for n, vr in ports.inputs]
        unzip = _unzipped(ports.path)
        try:
            if ports.fmi3:
                from fmpy.fmi3 import FMU3Slave

                self.fmu = FMU3Slave(guid=ports.guid, unzipDirectory=unzip, modelIdentifier=ports.identifier,
                                     instanceName="sut")  # fmt: skip
                note_native_library(str(ports.path))  # (loaded: this process ends without its finalisers)
                self.fmu.instantiate()
                self.fmu.enterInitializationMode(startTime=0.0)
            else:
                from fmpy.fmi2 import FMU2Slave

                self.fmu = FMU2Slave(guid=ports.guid, unzipDirectory=unzip, modelIdentifier=ports.identifier,
                                     instanceName="sut")  # fmt: skip
                note_native_library(str(ports.path))  # (loaded: this process ends without its finalisers)
                self.fmu.instantiate()
                self.fmu.setupExperiment(startTime=0.0)
                self.fmu.enterInitializationMode()
            for name, value in fmu_properties(properties).items():  # only what it declares
                if name in ports.parameters:
                    vr, kind = ports.parameters[name]
                    self._set(kind, vr, _typed(kind, value, name, label))
            self.fmu.exitInitializationMode()
        except ControllerFault:
            raise
        except Exception as exc:  # noqa: BLE001 (the FMU's failure)
            raise ControllerFault(label, f"instantiating {ports.path.name} failed: {_call_failure(exc)}") from None
        self.live = True

    def _set(self, kind: str, vr: int, value) -> None:
        f = self.fmu
        if not self.ports.fmi3:
            setter = {"Real": f.setReal, "Integer": f.setInteger, "Enumeration": f.setInteger}.get(kind)
        elif kind == "Enumeration":
            setter = f.setInt64  # (an FMI 3.0 enumeration is an Int64)
        else:  # (FMI 3.0: a setter per type, named as the type)
            setter = getattr(f, f"set{kind}", None) if kind not in ("Boolean", "String") else None
        if setter is not None:
            setter([vr], [value])
        elif kind == "Boolean":
            f.setBoolean([vr], [value])
        else:
            f.setString([vr], [value])

    def inputs_of(self, obs: Observation) -> tuple[list[int], list[float]]:
        """The (value references, values) of the inputs ``obs`` gives (without a threat, none of its)."""
        vrs, values = [], []
        for (who, field), vr in self.inputs:
            state = obs if not who else (obs.ego if who == "ego" else obs.threat)
            if state is not None:
                vrs.append(vr)
                values.append(float(getattr(state, field)))
        return vrs, values

    def step(self, obs: Observation) -> float:
        vrs, values = self.inputs_of(obs)
        return self.step_values(vrs, values, obs.t_s, obs.dt_s)

    def step_values(self, vrs: list[int], values: list[float], t_s: float, dt_s: float) -> float:
        """Set the inputs, ``doStep(t_s, dt_s)``, read ``a_cmd``."""
        f = self.fmu
        try:
            if self.ports.fmi3:
                if vrs:
                    f.setFloat64(vrs, values)
                f.doStep(currentCommunicationPoint=t_s, communicationStepSize=dt_s)
                return f.getFloat64([self.ports.output])[0]
            if vrs:
                f.setReal(vrs, values)
            f.doStep(currentCommunicationPoint=t_s, communicationStepSize=dt_s)
            return f.getReal([self.ports.output])[0]
        except Exception as exc:  # noqa: BLE001
            self.close(getattr(exc, "status", None))
            raise ControllerFault(self.label, f"the FMU's doStep failed: {_call_failure(exc)}", t_s) from None

    def close(self, status: int | None = None) -> None:
        """End the instance after the run, or after a call that returned ``status`` (:func:`end_instance`)."""
        if not getattr(self, "live", False):
            return
        self.live = False
        end_instance(self.fmu, status)


def end_instance(fmu, status: int | None = None) -> None:
    """End an FMI 2.0 instance after the run, or after a call that returned ``status``: as the standard
    allows, nothing more after fmi2Fatal (the instance is corrupt), only fmi2FreeInstance after
    fmi2Error, fmi2Terminate then fmi2FreeInstance otherwise."""
    if status == 4:
        return
    if status != 3:
        try:
            fmu.terminate()
        except Exception:  # noqa: BLE001, S110 (an instance that failed may refuse to terminate)
            pass
    try:
        fmu.freeInstance()
    except Exception:  # noqa: BLE001, S110
        pass


def _call_failure(exc: BaseException) -> str:
    """fmpy's 'fmi2DoStep failed with status 3 (error).' as 'fmi2DoStep returned fmi2Error'."""
    text = " ".join(str(exc).split())
    status = getattr(exc, "status", None)
    if isinstance(status, int) and status in _STATUS:
        call = text.split(" ", 1)[0] if text else "the call"
        return f"{call} returned {status_name(call, status)}"
    return text or type(exc).__name__
