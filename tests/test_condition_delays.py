"""A delayed condition through a quiet stretch: what the core's stretch assumes of the evaluations it
skips (``ConditionRunner.delayed``, ``first_true``, ``skip``) equals evaluating them one by one.

The reference is the runner's own ``evaluate``, called once per step as the engine calls it (twice at
t = 0, as the engine's settling and first step do), on random histories: step sizes that are and are
not exact in binary, delays that are and are not multiples of the step, shorter than the rounding, and
values that change."""

from __future__ import annotations

import copy
import random
from collections import deque
from types import SimpleNamespace

import pytest

from vei_scenario.interpreter.clock import step_time
from vei_scenario.interpreter.cruise import StepTimes
from vei_scenario.interpreter.storyboard import ConditionRunner


def _runner(delay: float, values: dict) -> ConditionRunner:
    """A runner whose raw test reads the step's value from ``values`` (a step -> bool table)."""
    r = ConditionRunner.__new__(ConditionRunner)
    r.edge, r.delay, r.prev = "none", delay, None
    r.history = deque()
    r.condition = SimpleNamespace(test=lambda ctx: values[ctx.step])
    r._test = r.edged = r.condition.test
    return r


def _evaluated(r: ConditionRunner, dt: float, steps) -> list[bool]:
    out = []
    for k in steps:
        out.append(r.evaluate(SimpleNamespace(step=k, t=step_time(k, dt), dt=dt)))
    return out


def _case(seed: int):
    rng = random.Random(seed)
    dt = rng.choice([0.01, 0.05, 0.1, 1 / 3, 0.001, 0.025, 0.02])
    delay = rng.choice([1.0, 3.0, 0.3, dt, 2 * dt, 2.5 * dt, 7 * dt + 1e-10, 1e-10, 0.015, 0.999 * dt])
    before = rng.randrange(0, 400)
    flips = sorted(rng.sample(range(max(1, before)), k=min(before, rng.randrange(0, 4))))
    value, values = rng.random() < 0.5, {}
    for k in range(before + 1):
        if k in flips:
            value = not value
        values[k] = value
    held = rng.random() < 0.6
    n = rng.randrange(1, 600)
    for k in range(before + 1, before + 1 + n):
        values[k] = held
    return dt, delay, before, held, n, values


@pytest.mark.parametrize("seed", range(300))
def test_a_skipped_stretch_equals_evaluating_each_step(seed):
    dt, delay, before, held, n, values = _case(seed)
    r = _runner(delay, values)
    _evaluated(r, dt, [0] + list(range(before + 1)))  # (t = 0 twice: settling, then the first step)
    stepped = copy.deepcopy(r)
    reference = _evaluated(stepped, dt, range(before + 1, before + 1 + n))
    times = StepTimes(before, dt, n)
    assert list(r.delayed(times, held)) == reference
    assert r.first_true(times, held) == (reference.index(True) if True in reference else n)
    r.skip(times, held)
    assert list(map(list, r.history)) == list(map(list, stepped.history))
    # and the runs go on as the steps do after the stretch
    values[before + n + 1] = not held
    assert _evaluated(r, dt, [before + n + 1]) == _evaluated(stepped, dt, [before + n + 1])


def test_the_cases_cover_values_coming_true_late_early_and_never():
    seen = set()
    for seed in range(300):
        dt, delay, before, held, n, values = _case(seed)
        r = _runner(delay, values)
        _evaluated(r, dt, [0] + list(range(before + 1)))
        first = r.first_true(StepTimes(before, dt, n), held)
        seen.add("never" if first == n else "at once" if first == 0 else "later")
    assert seen == {"never", "at once", "later"}


@pytest.mark.parametrize("seed", range(100))
def test_values_due_at_once_give_the_last_of_them(seed):
    """Runs that come due in one evaluation (values at one time, as the engine's two evaluations at
    t = 0 leave): the evaluation gives the last, in first_true as in the walk of ``delayed``."""
    rng = random.Random(seed)
    dt, delay = 0.01, rng.choice([0.05, 0.1, 0.3])
    r = _runner(delay, {})
    k = 0
    for _ in range(rng.randrange(1, 6)):
        k += rng.randrange(0, 3)  # (0: a run at the same step as the one before)
        r.history.append([k, k + 1, rng.random() < 0.5])
    held = rng.random() < 0.5
    times = StepTimes(k, dt, rng.randrange(1, 60))
    walked = list(r.delayed(times, held))
    assert r.first_true(times, held) == (walked.index(True) if True in walked else len(times))
