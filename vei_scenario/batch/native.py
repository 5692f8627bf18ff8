"""The sweep kernel (``core/src/vei_batch.c``, part of the compiled core): every variant of a vei-compiled
closed loop simulated and scored in C, several variants at a time on threads.

What it runs is the loop as :class:`~vei_scenario.loop.LoopScene` reads it: the ego on its path with
the planner and the rider on its track with the social force model, through the core's agents
(``vei_ego_drive``, ``vei_rider_step``) and models, and the metric functions of
:mod:`vei_scenario.metrics.definitions` operation for operation, so its rows equal ``vei run``'s
(tests/test_batch_native.py). Other road users of the scenario only replay their trajectories: the
planner watches the threat alone and the rider is repelled by the ego alone (LoopScene refuses loops
where it is otherwise), and a row scores the ego and the threat, so they cannot change a row and the
kernel leaves them out. There is no second, numpy engine: the kernel is built with the core, without
which nothing runs.
"""

from __future__ import annotations

import ctypes
import functools
import math
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from vei_scenario.core import _core
from vei_scenario.loop import LoopScene, NotALoop
from vei_scenario.metrics.definitions import DIGITS, METRICS, ZONES
from vei_scenario.metrics.series import MetricConfig, median
from vei_scenario.models.rider import recorded_start_speed, rider_route

_D = ctypes.c_double
_P = ctypes.POINTER(ctypes.c_double)


class _Polyline(ctypes.Structure):
    _fields_ = [("x", _P), ("y", _P), ("h", _P), ("t", _P), ("s", _P), ("n", ctypes.c_int), ("exit_speed", _D)]


def _doubles(names: str) -> list[tuple[str, type]]:
    return [(n, _D) for n in names.split()]


class _Scene(ctypes.Structure):
    _fields_ = [
        ("t", _P),
        ("n_steps", ctypes.c_int),
        *_doubles("dt behaviour_start"),
        ("grad_a", _P),
        ("grad_b", _P),
        ("grad_c", _P),
        *_doubles("grad_dx0 grad_dxn"),
        ("grad_uniform", ctypes.c_int),
        ("grad_h", _D),
        ("ego_path", _Polyline),
        ("track", _Polyline),
        ("route_x", _P),
        ("route_y", _P),
        ("route_n", ctypes.c_int),
        *_doubles("v_start ego_x0 ego_y0 ego_yaw0 threat_x0 threat_y0 threat_yaw0"),
        *_doubles("ego_length ego_width threat_length threat_width"),
        ("cap", _D * 10),
        ("sfm", _D * 10),
        ("limits", _D * 3),
        *_doubles("metric_dt safe_ttc alert_ttc comfort_accel comfort_jerk near_lo near_hi"),
        ("zone_ttc_2d", ctypes.c_int),
        ("pet_step", ctypes.c_int),
        ("radius_sum", _D),
        ("band_reach", _D),
    ]


class _Variant(ctypes.Structure):
    _fields_ = [
        ("cap_on", ctypes.c_int),
        ("sfm_on", ctypes.c_int),
        ("repulsive", ctypes.c_int),
        *_doubles("cruise offset ego_speed0 threat_speed0"),
    ]


#: _Variant's fields and offsets as a numpy structured dtype (for filling many at once)
_VARIANT_DTYPE = np.dtype(
    {
        "names": [f[0] for f in _Variant._fields_],
        "formats": [np.intc if f[1] is ctypes.c_int else np.float64 for f in _Variant._fields_],
        "offsets": [getattr(_Variant, f[0]).offset for f in _Variant._fields_],
        "itemsize": ctypes.sizeof(_Variant),
    }
)


@functools.cache
def load_kernel():
    """The sweep kernel: ``vei_batch.c`` is part of the compiled core, whose shared object is loaded
    a second time through ctypes for its plain C entry points (the kernel's structs, no Python objects)."""
    lib = ctypes.CDLL(_core.__file__)
    lib.vei_batch_run.argtypes = [ctypes.POINTER(_Scene), ctypes.POINTER(_Variant), ctypes.c_int, _P, _P]
    lib.vei_batch_run.restype = ctypes.c_int
    lib.vei_batch_outputs.restype = ctypes.c_char_p
    # the kernel's output columns by the name of the metric each holds (vei_batch.h's one list)
    lib.columns = {name: k for k, name in enumerate(lib.vei_batch_outputs().decode().rstrip(",").split(","))}
    return lib


def _ptr(a: np.ndarray):
    return a.ctypes.data_as(_P)


class NativeBatch:
    """A :class:`LoopScene` run by the kernel: ``metrics(variants)`` gives ``vei run``'s metric dicts,
    ``run(prepare(variants), record=True)`` also the ego's and the threat's recorded states."""

    def __init__(self, scene: LoopScene, cfg: MetricConfig | None = None) -> None:
        self.scene, self.cfg = scene, cfg or MetricConfig()
        self.lib = load_kernel()
        self._keep: list = []
        self._scene_cache: dict[tuple, _Scene] = {}
        self._scene_lock = threading.Lock()  # prepare() may run on several threads

    def _arr(self, values) -> np.ndarray:
        a = np.ascontiguousarray(np.asarray(values, float))
        self._keep.append(a)
        return a

    def _polyline(self, poly, timed: bool) -> _Polyline:
        x, y, h, s = (self._arr(v) for v in (poly.xs, poly.ys, poly.hs, poly.s))
        t = self._arr(poly.ts) if timed else None
        exit_speed = math.nan if poly.exit_speed is None else poly.exit_speed
        return _Polyline(
            _ptr(x), _ptr(y), _ptr(h), _ptr(t) if t is not None else None, _ptr(s), len(poly.xs), exit_speed
        )

    def _scene(self, duration: float, model: tuple = (), params=None) -> _Scene:
        """The scene of a duration and a set of model parameters (``model``: LoopScene.model_key)."""
        with self._scene_lock:
            return self._scene_cache.get((duration, model)) or self._build_scene(duration, model, params)

    def _build_scene(self, duration: float, model: tuple = (), params=None) -> _Scene:
        b, cfg, dt = self.scene, self.cfg, self.scene.dt
        if not duration >= 0:
            raise NotALoop("negative duration")
        times = [0.0]
        while not times[-1] > duration and times[-1] < 600.0 - 1e-9:
            times.append(round(len(times) * dt, 9))
        t = self._arr(times)
        n = t.size
        diffs = np.diff(t)
        uniform = bool((diffs == diffs[0]).all())
        dx1, dx2 = diffs[:-1], diffs[1:]
        ga = self._arr(-(dx2) / (dx1 * (dx1 + dx2)))
        gb = self._arr((dx2 - dx1) / (dx1 * dx2))
        gc = self._arr(dx1 / (dx2 * (dx1 + dx2)))
        ego, threat = b.ego, b.threat
        ego_poly, track = b.paths[ego][0], b.paths[threat][0]
        route = np.array(rider_route(track))
        rx, ry = self._arr(route[:, 0]), self._arr(route[:, 1])
        ie, it = b.names.index(ego), b.names.index(threat)
        el, ew, tl, tw = b.length[ie], b.width[ie], b.length[it], b.width[it]
        metric_dt = median(diffs) if n > 1 else 0.0
        scene = _Scene(
            _ptr(t),
            n - 1,
            dt,
            b.behaviour_start_s,
            _ptr(ga),
            _ptr(gb),
            _ptr(gc),
            diffs[0],
            diffs[-1],
            int(uniform),
            diffs[0],
            self._polyline(ego_poly, False),
            self._polyline(track, True),
            _ptr(rx),
            _ptr(ry),
            route.shape[0],
            recorded_start_speed(track),
            *b.init_pose[ego],
            *b.init_pose[threat],
            el,
            ew,
            tl,
            tw,
            (_D * 10)(*(params[0] if params else b.cap_params).properties().values()),
            (_D * 10)(*(params[1] if params else b.sfm_params).properties().values()),
            (_D * 3)(b.limits.max_accel_mps2, b.limits.max_decel_mps2, b.limits.jerk_max_mps3),
            metric_dt,
            cfg.safe_ttc_s,
            cfg.alert_ttc_s,
            cfg.comfort_accel_mps2,
            cfg.comfort_jerk_mps3,
            cfg.near_miss_ttc_s[0],
            cfg.near_miss_ttc_s[1],
            int(cfg.zone_ttc != "approx"),
            max(1, int(round(0.05 / metric_dt))) if metric_dt > 0 else 1,
            0.5 * (math.hypot(el, ew) + math.hypot(tl, tw)),
            (0.5 * ew + 0.5 * math.hypot(tl, tw)) * (1.0 + 1e-9) + 1e-12,
        )
        self._scene_cache[(duration, model)] = scene
        return scene

    def prepare(self, variants: list[dict[str, str]]) -> tuple[_Scene, ctypes.Array]:
        """The kernel's input for ``variants`` (Python work: do it before handing runs to threads); they
        share their model parameters (see LoopScene.model_groups)."""
        b = self.scene
        r = b.resolve(variants)
        model, params = b.shared_model(variants)
        arr = (_Variant * len(variants))()
        # filled column by column through a numpy view of the struct array (the C layout)
        view = np.frombuffer(arr, dtype=_VARIANT_DTYPE)
        view["cap_on"], view["sfm_on"], view["repulsive"] = r.cap_on, r.sfm_on, r.rider == "normal"
        view["cruise"], view["offset"] = r.cruise_mps, r.delays[b.threat]
        view["ego_speed0"], view["threat_speed0"] = r.init_speed[b.ego], r.init_speed[b.threat]
        return self._scene(r.duration, model, params), arr

    def run(self, prepared, threads: int = 1, record: bool = False):
        """(outputs (V, 19), trajectories (V, 10, T) or None) of prepared variants, on ``threads``
        threads (the kernel releases the GIL)."""
        scene, arr = prepared
        n = len(arr)
        out = np.empty((n, len(self.lib.columns)))
        traj = np.empty((n, 10, scene.n_steps + 1)) if record else None
        bounds = np.linspace(0, n, max(1, min(threads, n)) + 1).astype(int)
        if len(bounds) == 2:
            self._run(scene, arr, 0, n, out, traj)
        else:
            with ThreadPoolExecutor(max_workers=len(bounds) - 1) as pool:
                jobs = [
                    pool.submit(self._run, scene, arr, bounds[k], bounds[k + 1], out, traj)
                    for k in range(len(bounds) - 1)
                ]
                for job in jobs:
                    job.result()
        return out, traj

    def _run(self, scene, arr, lo: int, hi: int, out: np.ndarray, traj: np.ndarray | None) -> None:
        base = ctypes.cast(ctypes.byref(arr, lo * ctypes.sizeof(_Variant)), ctypes.POINTER(_Variant))
        o = out[lo:hi]
        tr = traj[lo:hi] if traj is not None else None
        if self.lib.vei_batch_run(ctypes.byref(scene), base, hi - lo, _ptr(o), _ptr(tr) if tr is not None else None):
            raise MemoryError("vei_batch_run: out of memory")

    def metrics(self, variants: list[dict[str, str]], threads: int = 1) -> list[dict]:
        """``vei run``'s metrics of every variant (the same dicts as :func:`compute_metrics`)."""
        rows: list[dict | None] = [None] * len(variants)
        for task in self.scene.model_groups(list(range(len(variants))), variants, len(variants) or 1):
            out, _ = self.run(self.prepare([variants[i] for i in task]), threads)
            for i, m in zip(task, self.rows(out)):
                rows[i] = m
        return rows

    def rows(self, out: np.ndarray) -> list[dict]:
        return metric_rows(out, (self.scene.ego, self.scene.threat), self.lib.columns)


def metric_rows(out: np.ndarray, who: tuple[str, str], index: dict[str, int]) -> list[dict]:
    """The kernel's outputs as ``vei run``'s metric dicts (:func:`to_python` applied to each value),
    built column by column from Python floats: 10 000 rows in ~0.05 s instead of ~0.3 s. ``index``:
    the column of each metric, by name (the kernel's own list)."""
    cols = out.T.tolist()

    def number(name: str, digits_of: str | None = None) -> list:
        digits = DIGITS.get(digits_of or name, 4)
        return [round(v, digits) if math.isfinite(v) else None for v in cols[index[name]]]

    hit = [v != 0 for v in cols[index["collision"]]]
    zones = [number(f"ttc_zones_s.{z}", "ttc_zones_s") for z in ZONES]
    numbers = {name: number(name) for name in index if name not in ("collision", "near_miss") and "." not in name}
    values = {
        "collision": hit,
        "collision_entities": [list(who) if h else [] for h in hit],
        **numbers,
        "ttc_zones_s": [dict(zip(ZONES, z)) for z in zip(*zones)],
        "near_miss": [v != 0 for v in cols[index["near_miss"]]],
    }
    columns = {name: values[name] for name in METRICS}  # in vei run's order (KeyError: a metric missing)
    names = list(columns)
    return [dict(zip(names, values)) for values in zip(*columns.values())]
