"""The simulation clock: step ``k`` happens at ``round(k * dt, 9)`` (rounded to the nanosecond, so that
times add up as written: 0.1 + 0.2 is 0.3, and a condition at 0.3 s fires at step 30).

The times are worked out once per process for each step size and shared: a run asks for the time of
every step, a stretch of quiet steps for many at once, and a sweep for the same times in every variant.
"""

from __future__ import annotations

import array
import bisect

#: Steps whose times are kept (per step size); later ones are worked out when asked for.
KEPT_STEPS = 1 << 17

_tables: dict[float, list[float]] = {}
_packed: dict[float, bytes] = {}  # the same times as C doubles, for the core


def step_time(k: int, dt: float) -> float:
    """The time of step ``k``."""
    return round(k * dt, 9)


def _table(stop: int, dt: float) -> list[float]:
    """The kept times of step size ``dt``, at least ``stop`` (<= KEPT_STEPS) of them."""
    table = _tables.get(dt)
    if table is None or len(table) < stop:
        size = min(KEPT_STEPS, max(stop, 2 * len(table) if table else 4096))
        table = _tables[dt] = [round(k * dt, 9) for k in range(size)]
    return table


def step_times(first: int, stop: int, dt: float) -> list[float]:
    """The times of steps ``first`` to ``stop`` (exclusive), as :func:`step_time` gives them."""
    if stop > KEPT_STEPS:
        return [round(k * dt, 9) for k in range(first, stop)]
    return _table(stop, dt)[first:stop]


def packed_step_times(first: int, stop: int, dt: float) -> bytes:
    """:func:`step_times` as C doubles (the core's clock for a stretch), cut from one packed table."""
    if stop > KEPT_STEPS:
        return array.array("d", step_times(first, stop, dt)).tobytes()
    packed = _packed.get(dt)
    if packed is None or len(packed) < 8 * stop:
        packed = _packed[dt] = array.array("d", _table(stop, dt)).tobytes()
    return packed[8 * first : 8 * stop]


def count_at_or_before(first: int, stop: int, dt: float, limit: float) -> int:
    """How many of the times of steps ``first`` to ``stop`` are at or before ``limit`` (they grow)."""
    if stop > KEPT_STEPS:
        return bisect.bisect_right(step_times(first, stop, dt), limit)
    return bisect.bisect_right(_table(stop, dt), limit, first, stop) - first
