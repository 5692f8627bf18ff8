"""A native FMU on the ego of a vei-compiled closed loop, stepped by the sweep kernel (``--controller
Ego=planner.fmu`` in a sweep, a search or a bench): the FMU's shared library is opened in the process
that runs the variants and its fmi2 functions are called from C, each variant with an instance of its
own, as ``vei run``'s plugged controller steps it (:class:`~vei_scenario.sut.fmu.FmuController`): the
same inputs at the step's start, ``doStep(t, dt)``, ``a_cmd`` checked and driven through the vehicle
model within the ego's Performance along its path; parameters only where the FMU declares them (the
ego's controller properties of the variant, ``--controller-param`` over them).

Which FMUs (:func:`kernel_fmu`): one FMI 2.0 or 3.0 co-simulation FMU on the ego with a binary for this
platform, vei's port set (:data:`~vei_scenario.sut.fmu.INPUTS`, ``a_cmd``), parameters to set of type
Real, Integer, Boolean or Enumeration, instantiable more than once per process, and not a PythonFMU
(its binary runs a Python interpreter of its own: it stays in a process of its own per run); on a
loop whose behaviour starts at the first step. Anything else plays in the interpreter, as before.

A fault of the FMU (a call returning fmi2Discard or worse, a non-finite or absurd command) fails its
variant with the line ``vei run`` gives. A crash or a hang inside its binary cannot be caught in the
process that runs it: :mod:`vei_scenario.sweep.contained` runs these variants in forked children.
"""

from __future__ import annotations

import math
import os
import sys
import zipfile
from pathlib import Path

import numpy as np

from vei_scenario.batch.native import NativeBatch
from vei_scenario.core import fmu_ego
from vei_scenario.loop import LoopScene
from vei_scenario.sut.contract import MAX_COMMAND_MPS2, ControllerFault
from vei_scenario.sut.fmu import INPUTS, FmuPorts, _typed, _unzipped, fmu_properties, status_name

#: The longest one call into the FMU may take in a sweep without ``--controller-timeout`` (s): a hang then
#: fails its variant instead of holding up the sweep (no step of a driving function takes a minute).
CALL_BOUND_S = 60.0
#: the calls (vei_fmu_calls' indices) up to the end of initialisation
_LAST_INIT_CALL = 6
#: the calls of a step: inputs set, doStep, a_cmd read
_STEP_CALLS = (3, 7, 8)
#: parameter kinds the kernel sets (the rest, strings, in the interpreter)
_KINDS = {"Real": 0, "Float64": 0, "Integer": 1, "Int32": 1, "Enumeration": 1, "Boolean": 2}
#: where an FMI 2.0 and an FMI 3.0 FMU keep their binary for this platform
_PLATFORM = {"linux": ("linux64", "x86_64-linux", ".so")}


def binary_path(ports: FmuPorts) -> str | None:
    """The archive's path of the FMU's binary for this platform, None without one."""
    import platform

    where = _PLATFORM.get(sys.platform)
    if where is None or sys.maxsize <= 2**32 or platform.machine() not in ("x86_64", "AMD64"):
        return None
    return f"binaries/{where[1 if ports.fmi3 else 0]}/{ports.identifier}{where[2]}"


def not_for_kernel(ports: FmuPorts) -> str | None:
    """Why the kernel does not step this FMU (it plays in the interpreter), or None."""
    binary = binary_path(ports)
    if binary is None:
        return f"no native FMU in the kernel on {sys.platform}"
    with zipfile.ZipFile(ports.path) as z:
        names = set(z.namelist())
        md = z.read("modelDescription.xml").decode("utf-8", "replace")
    if binary not in names:
        return f"no {binary} in the FMU"
    if "resources/slavemodule.txt" in names or 'generationTool="PythonFMU' in md:
        return "a PythonFMU (its binary runs Python)"
    if 'canBeInstantiatedOnlyOncePerProcess="true"' in md:
        return "instantiable only once per process"
    kinds = {kind for _, kind in ports.parameters.values()}
    if kinds - set(_KINDS) - {"String"} or (ports.fmi3 and "Enumeration" in kinds):  # (FMI 3.0's is an Int64)
        return "parameters of a type the kernel does not set"
    return None


class KernelFmu:
    """The kernel with the FMU of ``spec`` on the ego of ``native``'s loop. Build with :func:`kernel_fmu`."""

    def __init__(self, native: NativeBatch, spec, ports: FmuPorts) -> None:
        self.native, self.spec, self.ports = native, spec, ports
        self.scene: LoopScene = native.scene
        self.label = spec.label
        self.name = ports.path.name
        self.given = dict(spec.parameters)
        unzip = Path(_unzipped(ports.path))  # (extracted by this process, removed at its exit)
        self.library = str(unzip / binary_path(ports))
        self.layout = {
            "guid": ports.guid,
            # (FMI 2.0 a file URI; FMI 3.0 a path with its separator at the end, as fmpy gives them)
            "resource_uri": str(unzip / "resources") + os.sep if ports.fmi3 else (unzip / "resources").as_uri(),
            "inputs": [(vr, list(INPUTS).index(n)) for n, vr in ports.inputs],
            "output": ports.output,
            "max_speed": self.scene.max_speed,
            "max_command": MAX_COMMAND_MPS2,
        }

    def properties(self, values: dict[str, str]) -> dict[str, str]:
        """The properties the FMU is given in a variant: the ego's controller properties resolved, the
        ``--controller-param`` ones over them."""
        return fmu_properties({**self.scene.ego_properties(values), **self.given})

    def parameters(self, variants: list[dict[str, str]]) -> tuple[list, np.ndarray, list[str | None]]:
        """(value references and kinds of the parameters set, values (V, P), per variant the fault line
        of a value that is not of its parameter's type, else None). The parameters set are those the
        FMU declares among the properties, in their order (none of type String: :func:`kernel_fmu`)."""
        props = [self.properties(v) for v in variants]
        names = [n for n in dict.fromkeys(k for p in props for k in p) if n in self.ports.parameters]
        layout = [(self.ports.parameters[n][0], _KINDS[self.ports.parameters[n][1]]) for n in names]
        values = np.zeros((len(variants), len(names)))
        errors: list[str | None] = [None] * len(variants)
        for i, p in enumerate(props):
            try:
                for j, n in enumerate(names):
                    values[i, j] = float(_typed(self.ports.parameters[n][1], p[n], n, self.label))
            except ControllerFault as fault:
                errors[i] = str(fault)
        return layout, values, errors

    def rows(self, variants: list[dict[str, str]], page: np.ndarray | None = None) -> list[dict]:
        """The rows of variants that share their model parameters (:meth:`LoopScene.model_groups`), in
        this process: the FMU's binary runs here (``page``: where the kernel notes each call into it,
        :mod:`vei_scenario.sweep.contained`)."""
        handle = fmu_ego.open_library(self.library, self.ports.fmi3)
        layout, values, errors = self.parameters(variants)
        scene, arr = self.native.prepare(variants)
        out, faults, _ = fmu_ego.run(scene, arr, handle, {**self.layout, "parameters": layout}, values, page)
        metrics = self.native.rows(out)
        rows = []
        for i in range(len(variants)):
            reason = errors[i] or (self.fault_line(faults[i]) if faults[i][0] else None)
            rows.append({"status": "error", "error": reason, "metrics": {}} if reason else
                        {"status": "ok", "error": "", "metrics": metrics[i]})  # fmt: skip
        return rows

    def fault_line(self, fault: np.ndarray) -> str:
        """The one line ``vei run`` gives for the same fault."""
        kind, t, call, value = fault
        at = None if math.isnan(t) else float(t)
        name = fmu_ego.calls(self.ports.fmi3)[int(call)]
        if kind == fmu_ego.NULL:
            reason = f"instantiating {self.name} failed: {name} returned NULL"
        elif kind == fmu_ego.STATUS:
            said = f"{name} returned {status_name(name, int(value))}"
            reason = f"instantiating {self.name} failed: {said}" if at is None else f"the FMU's doStep failed: {said}"
        elif kind == fmu_ego.NONFINITE:
            reason = f"step returned a non-finite command ({float(value)})"
        else:
            reason = f"step returned {float(value):g} m/s², beyond ±{MAX_COMMAND_MPS2:g} m/s² (no vehicle can)"
        return str(ControllerFault(self.label, reason, at))

    @property
    def call_bound_s(self) -> float:
        """The longest one call into the FMU may take: ``--controller-timeout``, else :data:`CALL_BOUND_S`."""
        return self.spec.step_timeout_s or CALL_BOUND_S

    def death_line(self, how: str, t: float, call: int, timeout: bool) -> str:
        """The line of a variant whose process died (``how``) or overran in call number ``call`` into
        the FMU (-1: between calls) at step time ``t`` (NaN while instantiating), as the isolated FMU of
        ``vei run`` says it."""
        at = None if math.isnan(t) else float(t)
        name = fmu_ego.calls(self.ports.fmi3)[call] if call >= 0 else ""
        instantiating = at is None and 0 <= call <= _LAST_INIT_CALL
        stepping = at is not None and call in _STEP_CALLS
        if timeout:
            what = f"instantiating {self.name}" if instantiating else ("step" if stepping or not name else name)
            limit = (
                f"{self.spec.step_timeout_s:g} s (--controller-timeout)"
                if self.spec.step_timeout_s
                else f"{CALL_BOUND_S:g} s (a sweep's bound of one call without --controller-timeout)"
            )
            return str(ControllerFault(self.label, f"{what} did not return within {limit}", at))
        if instantiating:
            where = " while instantiating it"
        elif "DoStep" in name:
            where = " in doStep"
        else:  # (in fmi2SetReal, fmi2Terminate ..., or between calls: a worker run alone with its variant)
            where = f" in {name}" if name else ""
        return str(ControllerFault(self.label, f"{self.name} {how}{where}", at))


def kernel_fmu(native: NativeBatch | None, controllers: tuple) -> KernelFmu | None:
    """The kernel with the plugged FMU on the ego, when the scenario is a loop the kernel plays
    (``native``) and the one controller is a native FMU it steps (:func:`not_for_kernel`), else None."""
    if native is None or len(controllers) != 1:
        return None
    spec = controllers[0]
    scene = native.scene
    if spec.kind != "fmu" or spec.entity != scene.ego or spec.osmp or fmu_ego_blocked(scene):
        return None
    ports = spec.load()
    if not isinstance(ports, FmuPorts) or not_for_kernel(ports):
        return None
    k = KernelFmu(native, spec, ports)
    declared = [n for n in k.properties({}) if n in ports.parameters]
    if any(ports.parameters[n][1] not in _KINDS for n in declared):
        return None  # (a String parameter to set)
    return k


def fmu_ego_blocked(scene: LoopScene) -> bool:
    """Whether the loop is one the kernel cannot drive a plugged ego in: the behaviour starting after the
    first step (before it the plugged ego keeps to its lane, which the kernel does not model), or the
    ego's properties coming from elsewhere than its ObjectController."""
    return not scene.behaviour_start_s < 0 or scene.ego_props_raw is None
