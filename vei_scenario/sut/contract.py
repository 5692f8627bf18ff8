"""What a user's controller sees and what it must return.

``step(obs)`` gets an :class:`Observation` and returns the longitudinal acceleration command (m/s²):
a number, or a mapping or object with ``accel_mps2`` (and optionally ``state``, a short text shown in
trajectories.csv's ``controller_state`` column, and ``lateral_offset_m``, where the entity is to be
beside its path or lane: metres to the left, reached at :data:`LATERAL_SPEED_MPS` at most).
Anything else, a non-finite number or a command beyond
:data:`MAX_COMMAND_MPS2` either way is a :class:`ControllerFault`: one line naming the controller, the
step time and the reason. A finite command within that bound is held by the vehicle model to the
entity's Performance (maxAcceleration, maxDeceleration, maxSpeed) and its jerk limit.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy

from vei_scenario.errors import VeiError

#: The largest command, either way, taken as a command at all (m/s², about 10 g): beyond it no road
#: vehicle brakes or accelerates, so the number is a fault in the controller, not a request.
MAX_COMMAND_MPS2 = 100.0

#: The largest lateral offset taken as a command (m, either side): two lanes and more away from its path
#: the entity would be on another road, not beside its own.
MAX_LATERAL_OFFSET_M = 10.0

#: How fast the entity moves sideways towards a commanded offset (m/s): about an evasive lane change's
#: (3.5 m in 2 s), and the same in every run, so the system's lateral wish is comparable across tools.
LATERAL_SPEED_MPS = 1.75


class ControllerFault(VeiError):
    """The user's controller failed: it could not be loaded or constructed, raised in ``step``, or
    returned something that is no command. ``str()`` is one line naming the controller (entity and
    ``file:Class``), the step time where there is one, and the reason."""

    def __init__(self, label: str, reason: str, t_s: float | None = None) -> None:
        self.label, self.reason, self.t_s = label, reason, t_s
        super().__init__(str(self))

    def __reduce__(self):
        """Pickled by its fields, so a fault in a worker process reaches the parent intact."""
        return (type(self), (self.label, self.reason, self.t_s))

    def __str__(self) -> str:
        at = f" at t = {self.t_s:.2f} s" if self.t_s is not None else ""
        return f"controller {self.label}{at}: {self.reason}"


def is_system_fault(error: object) -> bool:
    """Whether a failed run's error line is a :class:`ControllerFault` (the system under test's own
    failure, worded ``controller ENTITY=TARGET ...``) rather than a defect of the scenario or of vei."""
    return str(error).startswith("controller ")


class StepTimeout(BaseException):
    """Raised into a ``step`` that overran its time limit (a BaseException: the user's own
    ``except Exception`` does not swallow it)."""


@dataclass(slots=True)
class ObjectState:
    """One road user as a controller sees it: its bounding box's centre (m) and heading (rad,
    counter-clockwise from +x) in the OpenDRIVE frame, speed along the heading (m/s), acceleration
    (m/s², the last step's), box length and width (m); ``kind`` vehicle, pedestrian or misc."""

    name: str
    kind: str
    x_m: float
    y_m: float
    heading_rad: float
    speed_mps: float
    accel_mps2: float
    length_m: float
    width_m: float


@dataclass(slots=True)
class Observation:
    """What ``step`` sees at the start of a step: simulation time ``t_s`` (s), the step ``dt_s`` (s),
    the controlled entity ``ego``, the scenario's ``threat`` (None without one, or when the controlled
    entity is the threat) and ``objects``: every other entity that is on the road, threat included."""

    t_s: float
    dt_s: float
    ego: ObjectState
    threat: ObjectState | None
    objects: list[ObjectState]


@dataclass(frozen=True, slots=True)
class Command:
    """A checked command: the acceleration (m/s²), the state text for trajectories.csv and the lateral
    offset asked for (m to the left of the path or lane; None: as before)."""

    accel_mps2: float
    state: str
    lateral_offset_m: float | None = None


def command_from(value: object, label: str, t_s: float, default_state: str = "sut") -> Command:
    """The command ``step`` returned, checked; a :class:`ControllerFault` for anything that is not one."""
    state, lateral = default_state, None
    if isinstance(value, bool) or value is None:
        raise ControllerFault(label, f"step returned {value!r}, not an acceleration in m/s² (a number)", t_s)
    if _is_number(value):
        accel = value
    else:
        if isinstance(value, dict):
            if "accel_mps2" not in value:
                raise ControllerFault(label, "step returned a mapping without accel_mps2", t_s)
            accel, given, lateral = value["accel_mps2"], value.get("state"), value.get("lateral_offset_m")
        elif hasattr(value, "accel_mps2"):
            accel, given = value.accel_mps2, getattr(value, "state", None)
            lateral = getattr(value, "lateral_offset_m", None)
        else:
            shown = repr(value) if len(repr(value)) <= 40 else repr(value)[:37] + "..."
            raise ControllerFault(
                label,
                f"step returned {type(value).__name__} {shown}, not an acceleration in m/s² "
                "(a number, or a mapping or object with accel_mps2)",
                t_s,
            )
        if given is not None:
            state = _state_text(given)
        if not _is_number(accel):
            raise ControllerFault(label, f"accel_mps2 is {type(accel).__name__} {accel!r}, not a number", t_s)
    accel = float(accel)
    if not math.isfinite(accel):
        raise ControllerFault(label, f"step returned a non-finite command ({accel})", t_s)
    if abs(accel) > MAX_COMMAND_MPS2:
        raise ControllerFault(
            label, f"step returned {accel:g} m/s², beyond ±{MAX_COMMAND_MPS2:g} m/s² (no vehicle can)", t_s
        )
    if lateral is not None:
        lateral = _lateral(lateral, label, t_s)
    return Command(accel, state, lateral)


def _is_number(value: object) -> bool:
    """A real number: Python's, NumPy's scalars of any width (float32, int64 ...) and 0-d arrays; not a
    bool (True is no acceleration)."""
    if isinstance(value, (bool, numpy.bool_)):
        return False
    if isinstance(value, numbers.Real):
        return True
    return isinstance(value, numpy.ndarray) and value.shape == () and value.dtype.kind in "iuf"


def _lateral(value: object, label: str, t_s: float) -> float:
    if not _is_number(value):
        raise ControllerFault(label, f"lateral_offset_m is {type(value).__name__} {value!r}, not a number", t_s)
    if not math.isfinite(value) or abs(value) > MAX_LATERAL_OFFSET_M:
        raise ControllerFault(
            label, f"step returned lateral_offset_m {value}, not within ±{MAX_LATERAL_OFFSET_M:g} m of its path", t_s
        )
    return float(value)


def _state_text(given: object) -> str:
    """A state for the CSV column: one short line without separators."""
    text = " ".join(str(given).split())[:40]
    return text.replace(",", ";") or "sut"
