"""What a long job says on the console: at a run's start how long it may run, then its progress on a
terminal (a run's simulated time, an animation's frames).

Why: a scenario without a stop trigger runs until its stories complete or the time limit, and at a
fine step that is millions of steps; a run that sits silent for minutes looks hung. The note goes to
stderr (stdout keeps the run's summary); the bar only where stderr is a terminal, never in CI or a pipe.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable

#: A run that may take this many steps or more is announced (at 0.01 s: the 600 s limit is 60 000).
LONG_RUN_STEPS = 100_000


def terminal_bar(total: float, unit: str, desc: str, stream=None):
    """A tqdm bar on ``stream`` (stderr) when it is a terminal; None in CI, a pipe or a file."""
    stream = stream or sys.stderr
    if os.environ.get("CI") or not stream.isatty():
        return None
    from tqdm import tqdm

    tqdm.monitor_interval = 0  # (no monitor thread)
    return tqdm(total=total, unit=unit, desc=desc, dynamic_ncols=True, file=stream, leave=False)


class RunProgress:
    """``on_start`` for :func:`~vei_scenario.interpreter.run_scenario`; :meth:`close` ends the bar."""

    def __init__(self, name: str, stream=None) -> None:
        self.name, self.stream, self.bar = name, stream or sys.stderr, None

    def on_start(self, sim) -> Callable[[float], None] | None:
        steps = sim.max_time / sim.dt
        if steps < LONG_RUN_STEPS:
            return None
        stop = sim.storyboard.stop_trigger
        limit = f"the {sim.max_time:g} s time limit, up to {steps:,.0f} steps at dt {sim.dt:g} s"
        if stop is None or not any(stop.groups):
            note = f"{self.name} has no stop trigger: it runs until its stories complete or {limit}"
        else:
            note = f"{self.name} runs until its stop trigger fires, its stories complete or {limit}"
        print(f"vei: note: {note}", file=self.stream, flush=True)
        self.bar = terminal_bar(round(sim.max_time, 3), "s", "simulated", self.stream)
        if self.bar is None:
            return None

        def tick(t: float) -> None:
            self.bar.update(round(t, 3) - self.bar.n)

        return tick

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
            self.bar = None
