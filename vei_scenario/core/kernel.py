"""The plain C entry points of the compiled core (``src/vei_batch.h``), through ctypes: the sweep
kernel (``vei_batch_run``: variants of a vei-compiled closed loop, simulated and scored) and its scoring
alone (``vei_batch_score``: the metrics of any recorded run, how ``vei run`` scores every scenario).

The structs mirror ``vei_batch.h`` field for field. The shared object is the core's own (``_core``),
loaded a second time for these functions, which take C structs rather than Python objects and release
the GIL while they run.
"""

from __future__ import annotations

import ctypes
import functools

import numpy as np

from vei_scenario.core import _core

D = ctypes.c_double
P = ctypes.POINTER(ctypes.c_double)


class PolylineStruct(ctypes.Structure):
    _fields_ = [("x", P), ("y", P), ("h", P), ("t", P), ("s", P), ("n", ctypes.c_int), ("exit_speed", D)]


def _doubles(names: str) -> list[tuple[str, type]]:
    return [(n, D) for n in names.split()]


class Scene(ctypes.Structure):
    _fields_ = [
        ("t", P),
        ("n_steps", ctypes.c_int),
        *_doubles("dt behaviour_start"),
        ("grad_a", P),
        ("grad_b", P),
        ("grad_c", P),
        *_doubles("grad_dx0 grad_dxn"),
        ("grad_uniform", ctypes.c_int),
        ("grad_h", D),
        ("ego_path", PolylineStruct),
        ("track", PolylineStruct),
        ("route_x", P),
        ("route_y", P),
        ("route_n", ctypes.c_int),
        *_doubles("v_start ego_x0 ego_y0 ego_yaw0 threat_x0 threat_y0 threat_yaw0"),
        *_doubles("ego_length ego_width threat_length threat_width"),
        ("cap", D * 10),
        ("sfm", D * 10),
        ("limits", D * 3),
        *_doubles("metric_dt safe_ttc alert_ttc comfort_accel comfort_jerk near_lo near_hi"),
        ("zone_ttc_2d", ctypes.c_int),
        ("pet_step", ctypes.c_int),
        ("radius_sum", D),
        ("band_reach", D),
    ]


class Variant(ctypes.Structure):
    _fields_ = [
        ("cap_on", ctypes.c_int),
        ("sfm_on", ctypes.c_int),
        ("repulsive", ctypes.c_int),
        *_doubles("cruise offset ego_speed0 threat_speed0"),
    ]


#: Variant's fields and offsets as a numpy structured dtype (for filling many at once)
VARIANT_DTYPE = np.dtype(
    {
        "names": [f[0] for f in Variant._fields_],
        "formats": [np.intc if f[1] is ctypes.c_int else np.float64 for f in Variant._fields_],
        "offsets": [getattr(Variant, f[0]).offset for f in Variant._fields_],
        "itemsize": ctypes.sizeof(Variant),
    }
)


@functools.cache
def load_kernel():
    """The core's shared object with its plain C entry points typed; ``columns``: the output column of
    each metric, by the name of ``vei run``'s metric it holds (vei_batch.h's one list)."""
    lib = ctypes.CDLL(_core.__file__)
    lib.vei_batch_run.argtypes = [ctypes.POINTER(Scene), ctypes.POINTER(Variant), ctypes.c_int, P, P]
    lib.vei_batch_run.restype = ctypes.c_int
    lib.vei_batch_score.argtypes = [ctypes.POINTER(Scene), P, P]
    lib.vei_batch_score.restype = ctypes.c_int
    lib.vei_batch_outputs.restype = ctypes.c_char_p
    lib.columns = {name: k for k, name in enumerate(lib.vei_batch_outputs().decode().rstrip(",").split(","))}
    return lib


def pointer(a: np.ndarray):
    return a.ctypes.data_as(P)


def score(scene: Scene, traj: np.ndarray) -> np.ndarray:
    """The kernel's outputs (``load_kernel().columns``) for one recorded run: ``traj`` (10, n_steps + 1)
    the ego's x, y, yaw, speed, accel, then the other's (box centres); ``scene`` with its time, gradient
    and metric fields and the two boxes' sizes set."""
    traj = np.ascontiguousarray(traj, dtype=float)
    out = np.empty(len(load_kernel().columns))
    if load_kernel().vei_batch_score(ctypes.byref(scene), pointer(traj), pointer(out)):
        raise MemoryError("vei_batch_score: out of memory")
    return out
