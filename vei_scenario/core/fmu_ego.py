"""The compiled core's native FMU on the ego (``src/vei_fmu_ego.h``), through ctypes: the FMU's shared
library opened in this process (``open_library``) and the sweep kernel run with it driving the ego
(``run``). The struct mirrors ``VeiFmuEgo`` field for field.
"""

from __future__ import annotations

import ctypes
import functools

import numpy as np

from vei_scenario.core.kernel import P, Scene, Variant, load_kernel, pointer

INTS = ctypes.POINTER(ctypes.c_int)
#: per variant in ``faults``: kind, step time, call, status or command (VEI_FMU_FAULT_FIELDS)
FAULT_FIELDS = 4
OK, STATUS, NULL, NONFINITE, ABSURD = range(5)
#: the shared progress slot: calls so far, step time, call (-1 between calls), variant
PROGRESS = 4


class FmuEgoStruct(ctypes.Structure):
    _fields_ = [
        ("lib", ctypes.c_void_p),
        ("instance_name", ctypes.c_char_p),
        ("guid", ctypes.c_char_p),
        ("resource_uri", ctypes.c_char_p),
        ("n_in", ctypes.c_int),
        ("in_vr", INTS),
        ("in_which", INTS),
        ("out_vr", ctypes.c_int),
        ("n_par", ctypes.c_int),
        ("par_vr", INTS),
        ("par_kind", INTS),
        ("par_values", P),
        ("max_speed", ctypes.c_double),
        ("max_command", ctypes.c_double),
        ("faults", P),
        ("progress", P),
    ]


@functools.cache
def _lib():
    lib = load_kernel()
    lib.vei_fmu_open.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_int]
    lib.vei_fmu_open.restype = ctypes.c_void_p
    lib.vei_fmu_calls.argtypes = [ctypes.c_int]
    lib.vei_fmu_calls.restype = ctypes.c_char_p
    lib.vei_batch_run_fmu.argtypes = [
        ctypes.POINTER(Scene), ctypes.POINTER(Variant), ctypes.c_int, P, P, ctypes.POINTER(FmuEgoStruct)
    ]  # fmt: skip
    lib.vei_batch_run_fmu.restype = ctypes.c_int
    return lib


@functools.cache
def calls(fmi3: bool = False) -> tuple[str, ...]:
    """The FMI calls (of FMI 3.0 with ``fmi3``) by the index ``faults`` and ``progress`` give."""
    return tuple(_lib().vei_fmu_calls(int(fmi3)).decode().split(","))


_OPEN: dict[str, int] = {}


def open_library(path: str, fmi3: bool = False) -> int:
    """The FMU's shared library opened (once per process) with its fmi2 (``fmi3``: fmi3) functions
    resolved; OSError with the loader's reason otherwise."""
    if path not in _OPEN:
        err = ctypes.create_string_buffer(512)
        handle = _lib().vei_fmu_open(path.encode(), int(fmi3), err, len(err))
        if not handle:
            raise OSError(err.value.decode(errors="replace"))
        _OPEN[path] = handle
    return _OPEN[path]


def _ints(values) -> np.ndarray:
    return np.ascontiguousarray(np.asarray(values, dtype=np.intc))


def run(
    scene: Scene,
    variants: ctypes.Array,
    handle: int,
    ports: dict,
    par_values: np.ndarray,
    progress: np.ndarray | None,
    record: bool = False,
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """(outputs (V, columns), faults (V, FAULT_FIELDS), trajectories or None) of ``variants`` with the FMU
    on the ego (``handle``: :func:`open_library`'s). ``ports``: ``guid``, ``resource_uri`` (FMI 3.0: the
    instantiation token and the resource directory's path), ``inputs`` [(value reference, input index)],
    ``output`` (a_cmd's value reference), ``parameters`` [(value reference, kind 0/1/2)], ``max_speed``,
    ``max_command``; ``par_values`` (V, parameters)."""
    lib = _lib()
    n = len(variants)
    out = np.empty((n, len(lib.columns)))
    faults = np.zeros((n, FAULT_FIELDS))
    traj = np.empty((n, 10, scene.n_steps + 1)) if record else None
    in_vr, in_which = _ints([vr for vr, _ in ports["inputs"]]), _ints([k for _, k in ports["inputs"]])
    par_vr, par_kind = _ints([vr for vr, _ in ports["parameters"]]), _ints([k for _, k in ports["parameters"]])
    values = np.ascontiguousarray(par_values, dtype=float).reshape(n, len(par_vr))
    cfg = FmuEgoStruct(
        handle, b"sut", ports["guid"].encode(), ports["resource_uri"].encode(),
        len(in_vr), in_vr.ctypes.data_as(INTS), in_which.ctypes.data_as(INTS), ports["output"],
        len(par_vr), par_vr.ctypes.data_as(INTS), par_kind.ctypes.data_as(INTS), pointer(values),
        ports["max_speed"], ports["max_command"], pointer(faults),
        pointer(progress) if progress is not None else None,
    )  # fmt: skip
    if lib.vei_batch_run_fmu(
        ctypes.byref(scene), variants, n, pointer(out), pointer(traj) if traj is not None else None, ctypes.byref(cfg)
    ):
        raise MemoryError("vei_batch_run_fmu: out of memory")
    return out, faults, traj
