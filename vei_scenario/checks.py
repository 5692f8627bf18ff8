"""Checks every number that enters through the library's entry points: finite and in range.

Why here: the command line checks its arguments, but the library is used directly too (FMPy's
habit: anything the CLI does, one import does), so each entry point checks what it is given with
these helpers and raises the same one-line :class:`VeiInputError`.
"""

from __future__ import annotations

import math

from vei_scenario.errors import VeiInputError

#: The fixed step of every simulation (s): finer would take hours and memory, coarser breaks the models.
DT_RANGE_S = (1e-4, 0.5)


def finite(value: object, where: str, low: float | None = None, high: float | None = None, file=None) -> float:
    """``value`` as a finite float within [low, high], else a VeiInputError naming ``where``."""
    try:
        v = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise VeiInputError(file, where, f"{value!r} is not a number") from None
    if not math.isfinite(v):
        raise VeiInputError(file, where, f"{value!r} is not a finite number")
    if (low is not None and v < low) or (high is not None and v > high):
        lo = "" if low is None else f"{low:g}"
        hi = "" if high is None else f"{high:g}"
        raise VeiInputError(file, where, f"{value!r} is outside {lo}..{hi}")
    return v


def check_dt(dt: object, where: str = "--dt") -> float:
    """A simulation step within :data:`DT_RANGE_S`."""
    return finite(dt, where, *DT_RANGE_S)
