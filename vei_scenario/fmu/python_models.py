"""The three FMU models in Python: the same behaviour as the C models under ``fmus/src`` (each step
mirrors ``<model>_model.c``), built on the Python models of :mod:`vei_scenario.models` that ``vei
run`` uses. The pythonfmu backend wraps them; tests run them against vei run and the C FMUs.

A model keeps every FMU variable by name in ``values``; :meth:`initialize` checks the parameters
(raising :class:`FmuModelError`) and sets the initial outputs, :meth:`do_step` advances one step.
"""

from __future__ import annotations

import math
from array import array

from vei_scenario.core import _core
from vei_scenario.fmu.variables import CAP, EGO, MAX_PATH, MAX_ROUTE, SFM, ModelSpec
from vei_scenario.interpreter.entities import Polyline
from vei_scenario.models.cap import BRAKE, CapParameters, CapState, ThreatView, cap_step, threat_in_corridor
from vei_scenario.models.rider import recorded_start_speed
from vei_scenario.models.sfm import RIDER_TYPES, SfmParameters
from vei_scenario.models.vehicle import VehicleLimits


class FmuModelError(ValueError):
    """A parameter or input the model refuses (the FMU answers fmi2Error with this message)."""


class FmuModel:
    spec: ModelSpec

    def __init__(self) -> None:
        self.values: dict[str, float | int | bool | str] = {s.name: s.start for s in self.spec.scalars()}
        self.initialized = False

    def set(self, name: str, value) -> None:
        var = self.spec.variable(name.split("[")[0])
        if var.causality == "output" or (var.causality == "parameter" and self.initialized):
            raise FmuModelError(f"{name} cannot be set now")
        if var.type == "Real" and not math.isfinite(float(value)):
            raise FmuModelError(f"{name} = {value} is not a finite number")
        self.values[name] = value

    def array(self, name: str, n: int) -> list[float]:
        return [float(self.values[f"{name}[{k + 1}]"]) for k in range(n)]

    def straight_ahead(self, h: float) -> None:
        """Before the behaviour starts: keep the Init speed and heading."""
        v = self.values
        v0 = v["speed"]
        v["accel"] = (v["speed"] - v0) / h
        ds = 0.5 * (v0 + v["speed"]) * h
        v["x"] = v["x"] + ds * math.cos(v["yaw"])
        v["y"] = v["y"] + ds * math.sin(v["yaw"])
        return ds

    def started(self, t: float) -> bool:
        return t > self.values["behaviour_start_s"]


class SfmModel(FmuModel):
    spec = SFM

    def initialize(self) -> None:
        v = self.values
        if v["rider_type"] not in RIDER_TYPES:
            raise FmuModelError(f"rider_type {v['rider_type']!r} is not one of replay, normal, aggressive")
        if not v["mass_kg"] > 0 or not v["tau_s"] > 0:
            raise FmuModelError("mass_kg and tau_s must be positive")
        n, nr = int(v["track_n"]), int(v["route_n"])
        if not 2 <= n <= MAX_PATH or not 1 <= nr <= MAX_ROUTE:
            raise FmuModelError(f"track_n must be 2..{MAX_PATH} and route_n 1..{MAX_ROUTE}")
        ts = self.array("track_t", n)
        if any(b <= a for a, b in zip(ts, ts[1:])):
            raise FmuModelError("track_t must increase")
        params = SfmParameters(**{k: float(v[k]) for k in SfmParameters().properties()})
        track = Polyline(self.array("track_x", n), self.array("track_y", n), self.array("track_h", n), ts)
        # the rider agent is the compiled core's (the C FMU and the sweep kernel step the same one)
        self.rider = _core.Rider(
            track.core,
            array("d", self.array("route_x", nr)).tobytes(),
            array("d", self.array("route_y", nr)).tobytes(),
            params.packed,
            v["time_shift_s"],
            ts[0] * 1.0 + v["time_shift_s"],
            recorded_start_speed(track),
            v["rider_type"] != "replay",
            v["rider_type"] == "normal",
        )
        v.update(x=v["x0"], y=v["y0"], yaw=v["yaw0"], speed=v["speed0"], accel=0.0, riding=False, waypoint=0)
        v["vx"], v["vy"] = v["speed"] * math.cos(v["yaw"]), v["speed"] * math.sin(v["yaw"])
        self.initialized = True

    def do_step(self, t: float, h: float) -> None:
        v = self.values
        t_next = t + h
        if not self.started(t):
            self.straight_ahead(h)
        else:
            ego = (v["ego_x"], v["ego_y"], v["ego_yaw"], v["ego_length_m"], v["ego_width_m"])
            x, y, yaw, speed, accel, riding, waypoint, vx, vy = self.rider.step(
                t_next, h, v["x"], v["y"], v["yaw"], v["speed"], v["accel"], ego
            )
            v.update(x=x, y=y, yaw=yaw, speed=speed, accel=accel, riding=riding, vx=vx, vy=vy)
            if riding:
                v["waypoint"] = waypoint
            return
        v["vx"], v["vy"] = v["speed"] * math.cos(v["yaw"]), v["speed"] * math.sin(v["yaw"])


class CapModel(FmuModel):
    spec = CAP

    def initialize(self) -> None:
        v = self.values
        if not v["a_max_mps2"] > 0:
            raise FmuModelError(f"a_max_mps2 must be positive (got {v['a_max_mps2']})")
        if v["cruise_speed_mps"] < 0:
            raise FmuModelError("cruise_speed_mps must not be negative")
        self.params = CapParameters(**{k: float(v[k]) for k in CapParameters().properties()})
        self.state = CapState()
        v.update(a_cmd=0.0, d_safe=self.params.d_safe_m(v["ego_speed"]), time_to_conflict=1e9, mode=0)
        self.initialized = True

    def _view(self, speed: float) -> ThreatView:
        v = self.values
        ego = (v["ego_x"], v["ego_y"], v["ego_yaw"], v["ego_length_m"], v["ego_width_m"])
        threat = (v["threat_x"], v["threat_y"], v["threat_yaw"], v["threat_length_m"], v["threat_width_m"])
        tv = (v["threat_speed"] * math.cos(v["threat_yaw"]), v["threat_speed"] * math.sin(v["threat_yaw"]))
        return threat_in_corridor(ego, speed, self.params.corridor_margin_m, threat, tv)

    def do_step(self, t: float, h: float) -> None:
        v = self.values
        if not v["enabled"] or not self.started(t):
            v["a_cmd"], v["d_safe"] = 0.0, self.params.d_safe_m(v["ego_speed"])
            return
        view = self._view(v["ego_speed"])
        resume = self._view(v["cruise_speed_mps"]) if self.state.mode == BRAKE else None
        self.state, a_cmd, d_safe = cap_step(
            self.state, self.params, v["cruise_speed_mps"], v["ego_speed"], view, h, resume
        )
        ttc = view.time_to_conflict_s
        v.update(a_cmd=a_cmd, d_safe=d_safe, time_to_conflict=ttc if math.isfinite(ttc) else 1e9)
        v["mode"] = 1 if self.state.mode == BRAKE else 0


class EgoModel(FmuModel):
    spec = EGO

    def initialize(self) -> None:
        v = self.values
        n = int(v["path_n"])
        if not 2 <= n <= MAX_PATH:
            raise FmuModelError(f"path_n must be 2..{MAX_PATH}")
        if v["speed0"] < 0 or not v["jerk_max_mps3"] > 0:
            raise FmuModelError("speed0 must not be negative and jerk_max_mps3 must be positive")
        self.limits = VehicleLimits(v["max_accel_mps2"], v["max_decel_mps2"], v["jerk_max_mps3"])
        self.path = Polyline(self.array("path_x", n), self.array("path_y", n), self.array("path_h", n), [None] * n)
        self.on_path, self.s = False, 0.0
        v.update(x=v["x0"], y=v["y0"], yaw=v["yaw0"], speed=v["speed0"], accel=0.0, s=0.0)
        self.initialized = True

    def do_step(self, t: float, h: float) -> None:
        v = self.values
        if not self.started(t):
            v["s"] = v["s"] + self.straight_ahead(h)
            return
        if not self.on_path:
            self.s = self.path.project(v["x"], v["y"])
            self.on_path = True
        lim = self.limits  # the vehicle along its path: the core's vei_ego_drive (the C FMU's and the kernel's)
        self.s, x, y, yaw, speed, accel = self.path.core.drive(
            self.s, v["a_cmd"], lim.max_accel_mps2, lim.max_decel_mps2, lim.jerk_max_mps3, h, v["speed"], v["accel"]
        )
        v.update(x=x, y=y, yaw=yaw, speed=speed, accel=accel, s=self.s)


MODEL_CLASSES = {"sfm": SfmModel, "cap": CapModel, "ego": EgoModel}
