"""The FMUs' variables: one table per model, the single source of the modelDescription.xml (FMI 2 and
3), the generated C header of the native FMUs and the Python backend.

Defaults come from the model parameter dataclasses, so an FMU built without a scenario behaves like
``vei run`` with default properties. Arrays (paths, routes) are fixed-capacity runs of scalars named
``name[1]`` … ``name[N]`` (FMI 2 has no arrays) with an Integer ``name_n`` giving the used length.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from functools import cached_property

from vei_scenario.models.cap import CapParameters
from vei_scenario.models.sfm import SfmParameters
from vei_scenario.models.vehicle import VehicleLimits

#: Capacity of path and track arrays (vertices) and of the rider's route (waypoints).
MAX_PATH = 512
MAX_ROUTE = 128

RIDER_TYPE_CODES = {"replay": 0, "normal": 1, "aggressive": 2}
MODELS = ("sfm", "cap", "ego")


@dataclass(frozen=True)
class Variable:
    name: str
    type: str  # Real | Integer | Boolean | String
    causality: str  # parameter | input | output
    start: float | int | bool | str | tuple | None  # an array: one value for all, or a tuple per element
    unit: str = ""
    description: str = ""
    size: int = 0  # > 0: an array of this many scalars name[1..size]

    @property
    def variability(self) -> str:
        if self.causality == "parameter":
            return "fixed"
        return "continuous" if self.type == "Real" else "discrete"

    @property
    def c_name(self) -> str:
        return self.name.upper().replace(".", "_")


@dataclass(frozen=True)
class Scalar:
    """One scalar of the modelDescription: a variable or an element of an array variable."""

    var: Variable
    name: str
    vr: int
    start: float | int | bool | str | None


@dataclass(frozen=True)
class ModelSpec:
    name: str  # sfm | cap | ego
    identifier: str  # modelIdentifier and file stem
    title: str
    description: str
    variables: tuple[Variable, ...]
    #: Start values that replace the table's, by scalar name (a per-scenario build, see :meth:`with_starts`).
    starts: tuple[tuple[str, float | int | bool | str], ...] = ()
    stop_time: float | None = None  # DefaultExperiment stopTime of a per-scenario build

    def with_starts(self, values: dict[str, float | int | bool | str], stop_time: float | None = None) -> ModelSpec:
        """This model with ``values`` (scalar name -> value, e.g. ``track_t[3]``) as start values."""
        unknown = sorted(set(values) - {sc.name for sc in self.scalars()})
        if unknown:
            raise KeyError(f"{self.identifier} has no variable {unknown[0]!r}")
        return replace(self, starts=tuple(sorted(values.items())), stop_time=stop_time)

    def scalars(self, type_: str | None = None) -> list[Scalar]:
        """Scalars in the order of the modelDescription (``type_`` None) or of one type; value
        references count per type from 0 (FMI 2)."""
        return [s for s in self._scalars if type_ is None or s.var.type == type_]

    @cached_property
    def _scalars(self) -> list[Scalar]:
        out: list[Scalar] = []
        counters: dict[str, int] = {}
        given = dict(self.starts)
        for v in self.variables:
            n = v.size or 1
            for k in range(n):
                vr = counters.get(v.type, 0)
                counters[v.type] = vr + 1
                name = f"{v.name}[{k + 1}]" if v.size else v.name
                start = v.start[k] if isinstance(v.start, tuple) else v.start
                out.append(Scalar(v, name, vr, given.get(name, start)))
        return out

    def vr(self, name: str) -> int:
        """Value reference of a scalar by name (its type's space)."""
        return self._by_name[name].vr

    @cached_property
    def _by_name(self) -> dict[str, Scalar]:
        return {s.name: s for s in self._scalars}

    def first_vr(self, v: Variable) -> int:
        return next(s.vr for s in self.scalars() if s.var is v)

    def variable(self, name: str) -> Variable:
        return next(v for v in self.variables if v.name == name)

    def fmi3_vrs(self) -> dict[str, int]:
        """FMI 3 value references, unique across types: Real first, then Integer, Boolean, String."""
        out: dict[str, int] = {}
        for t in ("Real", "Integer", "Boolean", "String"):
            base = len(out)
            out.update({s.name: base + s.vr for s in self.scalars(t)})
        return out


def _params(dataclass_, units: dict[str, str], prefix: str = "") -> list[Variable]:
    default = dataclass_()
    out = []
    for f in fields(dataclass_):
        unit = units.get(f.name, "")
        out.append(Variable(prefix + f.name, "Real", "parameter", float(getattr(default, f.name)), unit, _doc(f.name)))
    return out


def _doc(name: str) -> str:
    return {
        "v0_mps": "desired cruising speed of the rider",
        "mass_kg": "scooter plus rider mass",
        "tau_s": "relaxation time towards the desired velocity",
        "sigma_m": "smoothing length of the destination term",
        "repulsion_n": "repulsion strength A from the ego",
        "repulsion_range_m": "repulsion range B",
        "waypoint_radius_m": "switch to the next waypoint within this distance",
        "max_speed_mps": "speed limit of the scooter",
        "max_accel_mps2": "acceleration limit",
        "max_decel_mps2": "deceleration limit",
        "a_max_mps2": "saturated emergency deceleration a_max of d_safe",
        "t_h_s": "time headway t_h of d_safe",
        "d0_m": "standstill margin d0 of d_safe",
        "kp": "proportional gain of the cruise speed loop",
        "ki": "integral gain of the cruise speed loop",
        "kd": "derivative gain of the cruise speed loop",
        "max_cruise_decel_mps2": "comfort deceleration limit in cruise",
        "corridor_margin_m": "margin of the path corridor around the ego box",
        "horizon_s": "look-ahead of the conflict prediction",
        "jerk_max_mps3": "jerk limit of the acceleration",
    }.get(name, name)


_SI = {
    "v0_mps": "m/s",
    "mass_kg": "kg",
    "tau_s": "s",
    "sigma_m": "m",
    "repulsion_n": "N",
    "repulsion_range_m": "m",
    "waypoint_radius_m": "m",
    "max_speed_mps": "m/s",
    "max_accel_mps2": "m/s2",
    "max_decel_mps2": "m/s2",
    "a_max_mps2": "m/s2",
    "t_h_s": "s",
    "d0_m": "m",
    "kp": "1/s",
    "ki": "1/s2",
    "kd": "1",
    "max_cruise_decel_mps2": "m/s2",
    "corridor_margin_m": "m",
    "horizon_s": "s",
    "jerk_max_mps3": "m/s3",
}

_START = Variable(
    "behaviour_start_s",
    "Real",
    "parameter",
    0.0,
    "s",
    "the behaviour starts at the first step beginning after this time (the scenario's act start "
    "'SimulationTime > 0'); until then the entity keeps its initial speed and heading",
)


def _pose(what: str) -> list[Variable]:
    return [
        Variable("x0", "Real", "parameter", 0.0, "m", f"initial x of the {what} (scenario frame)"),
        Variable("y0", "Real", "parameter", 0.0, "m", f"initial y of the {what}"),
        Variable("yaw0", "Real", "parameter", 0.0, "rad", f"initial heading of the {what}"),
        Variable("speed0", "Real", "parameter", 0.0, "m/s", f"initial speed of the {what}"),
    ]


def _box(prefix: str, who: str, length: float, width: float) -> list[Variable]:
    return [
        Variable(f"{prefix}length_m", "Real", "parameter", length, "m", f"bounding box length of the {who}"),
        Variable(f"{prefix}width_m", "Real", "parameter", width, "m", f"bounding box width of the {who}"),
    ]


def _outputs_pose(what: str) -> list[Variable]:
    return [
        Variable("x", "Real", "output", 0.0, "m", f"x of the {what}'s reference point (scenario frame)"),
        Variable("y", "Real", "output", 0.0, "m", f"y of the {what}'s reference point"),
        Variable("yaw", "Real", "output", 0.0, "rad", f"heading of the {what}"),
        Variable("speed", "Real", "output", 0.0, "m/s", f"speed of the {what}"),
        Variable("accel", "Real", "output", 0.0, "m/s2", f"longitudinal acceleration of the {what}"),
    ]


_COUNT = tuple(float(k) for k in range(MAX_PATH))  # 0, 1, 2, ...

SFM = ModelSpec(
    "sfm",
    "vei_sfm",
    "vei-scenario e-scooter social force model",
    "E-scooter rider: replays its recorded track until the rider starts, then rides the social force "
    "model towards waypoints of its route with repulsion from the ego (normal) or without (aggressive).",
    (
        *_params(SfmParameters, _SI),
        Variable("rider_type", "String", "parameter", "normal", "", "replay | normal | aggressive"),
        *_box("", "scooter", 1.2, 0.6),
        *_box("ego_", "ego", 4.8, 1.9),
        *_pose("scooter"),
        _START,
        Variable("time_shift_s", "Real", "parameter", 0.0, "s", "timing offset of the recorded track (TimeShift)"),
        Variable("track_n", "Integer", "parameter", 2, "", f"vertices used of the recorded track (2..{MAX_PATH})"),
        # defaults: a track that runs 1 m/s along x, a vertex a second (times must increase)
        Variable("track_t", "Real", "parameter", _COUNT, "s", "recorded track: vertex times", MAX_PATH),
        Variable("track_x", "Real", "parameter", _COUNT, "m", "recorded track: vertex x", MAX_PATH),
        Variable("track_y", "Real", "parameter", 0.0, "m", "recorded track: vertex y", MAX_PATH),
        Variable("track_h", "Real", "parameter", 0.0, "rad", "recorded track: vertex headings", MAX_PATH),
        Variable("route_n", "Integer", "parameter", 1, "", f"waypoints used of the route (1..{MAX_ROUTE})"),
        Variable("route_x", "Real", "parameter", 0.0, "m", "route waypoints: x", MAX_ROUTE),
        Variable("route_y", "Real", "parameter", 0.0, "m", "route waypoints: y", MAX_ROUTE),
        Variable("ego_x", "Real", "input", 0.0, "m", "x of the ego's box centre"),
        Variable("ego_y", "Real", "input", 0.0, "m", "y of the ego's box centre"),
        Variable("ego_yaw", "Real", "input", 0.0, "rad", "heading of the ego"),
        *_outputs_pose("scooter")[:4],
        Variable("vx", "Real", "output", 0.0, "m/s", "velocity of the scooter, x"),
        Variable("vy", "Real", "output", 0.0, "m/s", "velocity of the scooter, y"),
        _outputs_pose("scooter")[4],
        Variable("riding", "Boolean", "output", False, "", "true once the social force model moves the scooter"),
        Variable("waypoint", "Integer", "output", 0, "", "index (from 0) of the route waypoint steered at"),
    ),
)

CAP = ModelSpec(
    "cap",
    "vei_cap",
    "vei-scenario collision-avoidance planner",
    "Ego collision-avoidance planner: PID cruise control, emergency braking when the threat will be in "
    "the ego's path corridor closer than d_safe = v^2/(2 a_max) + v t_h + d0, resume when clear. The "
    "command of a step is computed from the inputs at its start and applies to the next step.",
    (
        *_params(CapParameters, _SI),
        Variable("enabled", "Boolean", "parameter", True, "", "false: the command stays 0 (cruise at the held speed)"),
        Variable("cruise_speed_mps", "Real", "parameter", 5.0, "m/s", "cruise speed of the ego"),
        *_box("ego_", "ego", 4.8, 1.9),
        *_box("threat_", "threat", 1.2, 0.6),
        _START,
        Variable("ego_x", "Real", "input", 0.0, "m", "x of the ego's box centre"),
        Variable("ego_y", "Real", "input", 0.0, "m", "y of the ego's box centre"),
        Variable("ego_yaw", "Real", "input", 0.0, "rad", "heading of the ego"),
        Variable("ego_speed", "Real", "input", 0.0, "m/s", "speed of the ego"),
        Variable("threat_x", "Real", "input", 0.0, "m", "x of the threat's box centre"),
        Variable("threat_y", "Real", "input", 0.0, "m", "y of the threat's box centre"),
        Variable("threat_yaw", "Real", "input", 0.0, "rad", "heading of the threat"),
        Variable("threat_speed", "Real", "input", 0.0, "m/s", "speed of the threat"),
        Variable("a_cmd", "Real", "output", 0.0, "m/s2", "acceleration command for the ego"),
        Variable("d_safe", "Real", "output", 0.0, "m", "safety distance v^2/(2 a_max) + v t_h + d0"),
        Variable(
            "time_to_conflict",
            "Real",
            "output",
            1e9,
            "s",
            "constant-velocity time until the threat meets the path corridor (1e9: never)",
        ),
        Variable("mode", "Integer", "output", 0, "", "planner state: 0 cruise, 1 emergency brake"),
    ),
)

EGO = ModelSpec(
    "ego",
    "vei_ego",
    "vei-scenario ego longitudinal vehicle",
    "Ego vehicle moving along its path (polyline) with a jerk-limited longitudinal model; the "
    "acceleration command comes from the planner.",
    (
        *[
            Variable(f.name, "Real", "parameter", float(getattr(VehicleLimits(), f.name)), _SI[f.name], _doc(f.name))
            for f in fields(VehicleLimits)
        ],
        *_pose("ego"),
        _START,
        Variable("path_n", "Integer", "parameter", 2, "", f"vertices used of the path (2..{MAX_PATH})"),
        Variable("path_x", "Real", "parameter", 0.0, "m", "path: vertex x", MAX_PATH),
        Variable("path_y", "Real", "parameter", 0.0, "m", "path: vertex y", MAX_PATH),
        Variable("path_h", "Real", "parameter", 0.0, "rad", "path: vertex headings", MAX_PATH),
        Variable("a_cmd", "Real", "input", 0.0, "m/s2", "acceleration command"),
        *_outputs_pose("ego"),
        Variable("s", "Real", "output", 0.0, "m", "arc length travelled along the path"),
    ),
)

SPECS = {"sfm": SFM, "cap": CAP, "ego": EGO}
