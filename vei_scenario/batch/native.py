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
import math
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from vei_scenario.core.kernel import (
    VARIANT_DTYPE,
    D,
    PolylineStruct,
    Scene,
    Variant,
    load_kernel,
    pointer,
)
from vei_scenario.interpreter.clock import step_time
from vei_scenario.loop import LoopScene, NotALoop
from vei_scenario.metrics.scored_in_core import metric_fields, metric_rows
from vei_scenario.metrics.series import MetricConfig
from vei_scenario.models.rider import recorded_start_speed, rider_route


class NativeBatch:
    """A :class:`LoopScene` run by the kernel: ``metrics(variants)`` gives ``vei run``'s metric dicts,
    ``run(prepare(variants), record=True)`` also the ego's and the threat's recorded states."""

    def __init__(self, scene: LoopScene, cfg: MetricConfig | None = None) -> None:
        self.scene, self.cfg = scene, cfg or MetricConfig()
        self.lib = load_kernel()
        self._keep: list = []
        self._scene_cache: dict[tuple, Scene] = {}
        self._scene_lock = threading.Lock()  # prepare() may run on several threads

    def _arr(self, values) -> np.ndarray:
        a = np.ascontiguousarray(np.asarray(values, float))
        self._keep.append(a)
        return a

    def _polyline(self, poly, timed: bool) -> PolylineStruct:
        x, y, h, s = (self._arr(v) for v in (poly.xs, poly.ys, poly.hs, poly.s))
        t = self._arr(poly.ts) if timed else None
        exit_speed = math.nan if poly.exit_speed is None else poly.exit_speed
        return PolylineStruct(
            pointer(x),
            pointer(y),
            pointer(h),
            pointer(t) if t is not None else None,
            pointer(s),
            len(poly.xs),
            exit_speed,
        )

    def _scene(self, duration: float, model: tuple = (), params=None) -> Scene:
        """The scene of a duration and a set of model parameters (``model``: LoopScene.model_key)."""
        with self._scene_lock:
            return self._scene_cache.get((duration, model)) or self._build_scene(duration, model, params)

    def _build_scene(self, duration: float, model: tuple = (), params=None) -> Scene:
        b, cfg, dt = self.scene, self.cfg, self.scene.dt
        if not duration >= 0:
            raise NotALoop("negative duration")
        times = [0.0]
        while not times[-1] > duration and times[-1] < 600.0 - 1e-9:
            times.append(step_time(len(times), dt))
        ie, it = b.names.index(b.ego), b.names.index(b.threat)
        sizes = (b.length[ie], b.width[ie]), (b.length[it], b.width[it])
        fields, keep = metric_fields(np.array(times), cfg, *sizes)
        self._keep += keep
        ego, threat = b.ego, b.threat
        ego_poly, track = b.paths[ego][0], b.paths[threat][0]
        route = np.array(rider_route(track))
        rx, ry = self._arr(route[:, 0]), self._arr(route[:, 1])
        scene = Scene(
            **fields,
            dt=dt,
            behaviour_start=b.behaviour_start_s,
            ego_path=self._polyline(ego_poly, False),
            track=self._polyline(track, True),
            route_x=pointer(rx),
            route_y=pointer(ry),
            route_n=route.shape[0],
            v_start=recorded_start_speed(track),
            **dict(zip(("ego_x0", "ego_y0", "ego_yaw0"), b.init_pose[ego])),
            **dict(zip(("threat_x0", "threat_y0", "threat_yaw0"), b.init_pose[threat])),
            cap=(D * 10)(*(params[0] if params else b.cap_params).properties().values()),
            sfm=(D * 10)(*(params[1] if params else b.sfm_params).properties().values()),
            limits=(D * 3)(b.limits.max_accel_mps2, b.limits.max_decel_mps2, b.limits.jerk_max_mps3),
        )
        self._scene_cache[(duration, model)] = scene
        return scene

    def prepare(self, variants: list[dict[str, str]]) -> tuple[Scene, ctypes.Array]:
        """The kernel's input for ``variants`` (Python work: do it before handing runs to threads); they
        share their model parameters (see LoopScene.model_groups)."""
        b = self.scene
        r = b.resolve(variants)
        model, params = b.shared_model(variants)
        arr = (Variant * len(variants))()
        # filled column by column through a numpy view of the struct array (the C layout)
        view = np.frombuffer(arr, dtype=VARIANT_DTYPE)
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
        base = ctypes.cast(ctypes.byref(arr, lo * ctypes.sizeof(Variant)), ctypes.POINTER(Variant))
        o = out[lo:hi]
        tr = traj[lo:hi] if traj is not None else None
        if self.lib.vei_batch_run(
            ctypes.byref(scene), base, hi - lo, pointer(o), pointer(tr) if tr is not None else None
        ):
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
