"""The simulation clock: step ``k`` happens at ``round(k * dt, 9)`` (rounded to the nanosecond, so that
times add up as written: 0.1 + 0.2 is 0.3, and a condition at 0.3 s fires at step 30).

The times are worked out once per process for each step size and shared: a run asks for the time of
every step, a stretch of quiet steps for many at once, and a sweep for the same times in every variant.
"""

from __future__ import annotations

#: Steps whose times are kept (per step size); later ones are worked out when asked for.
KEPT_STEPS = 1 << 17

_tables: dict[float, list[float]] = {}


def step_time(k: int, dt: float) -> float:
    """The time of step ``k``."""
    return round(k * dt, 9)


def step_times(first: int, stop: int, dt: float) -> list[float]:
    """The times of steps ``first`` to ``stop`` (exclusive), as :func:`step_time` gives them."""
    if stop > KEPT_STEPS:
        return [round(k * dt, 9) for k in range(first, stop)]
    table = _tables.get(dt)
    if table is None or len(table) < stop:
        size = min(KEPT_STEPS, max(stop, 2 * len(table) if table else 4096))
        table = _tables[dt] = [round(k * dt, 9) for k in range(size)]
    return table[first:stop]
