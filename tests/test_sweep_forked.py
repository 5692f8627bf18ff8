"""Forked workers of a local sweep (vei_scenario/sweep/forked.py): every result once and in task
order, a worker's exception raised here, a dead or silent worker one line, no worker left behind."""

from __future__ import annotations

import multiprocessing
import os
import signal
import subprocess
import sys
import time

import pytest

from vei_scenario.errors import VeiInputError
from vei_scenario.sweep import forked

pytestmark = pytest.mark.skipif(not forked.available(), reason="forked workers are used on Linux only")


def _gone(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    return False


@pytest.mark.parametrize("count, workers, tickets", [(1, 2, 8192), (7, 2, 8192), (40, 3, 8192), (23, 2, 5)])
def test_results_come_back_in_task_order_from_every_worker(monkeypatch, count, workers, tickets):
    """Each task's result at its index, from this process and the forked ones (dynamic tickets, also
    when a ticket carries several tasks), the progress counted once per task; the workers reaped."""
    monkeypatch.setattr(forked, "_MAX_TICKETS", tickets)
    seen: list[int] = []
    # (with enough tasks, each process holds its first until all have one: on a loaded machine a worker
    # forked last could otherwise find the tickets gone; the fork context's barrier is shared by forks)
    barrier = multiprocessing.get_context("fork").Barrier(workers) if count >= 20 else None
    started: set[int] = set()

    def task(i: int) -> tuple[int, int, list[float]]:
        if barrier is not None and os.getpid() not in started:
            started.add(os.getpid())
            barrier.wait(timeout=60)
        time.sleep(0.002)
        return i, os.getpid(), [i * 0.5, -float(i)]

    out = forked.run_forked(task, count, workers, seen.append)
    assert [r[0] for r in out] == list(range(count))
    assert [r[2] for r in out] == [[i * 0.5, -float(i)] for i in range(count)]
    assert sum(seen) == count and set(seen) == {1}
    pids = {r[1] for r in out}
    if count >= 20:
        assert len(pids) == workers  # (every worker took a share)
    assert all(_gone(p) for p in pids - {os.getpid()})


def test_no_tasks_and_one_worker_fork_nothing(monkeypatch):
    def no_fork():
        raise AssertionError("forked")

    monkeypatch.setattr(os, "fork", no_fork)
    assert forked.run_forked(lambda i: i, 0, 4) == []
    assert forked.run_forked(lambda i: i * 2, 5, 1) == [0, 2, 4, 6, 8]


def test_when_the_system_refuses_a_process_the_others_do_the_work(monkeypatch):
    """A fork that fails (a process limit, no memory) is no error: the workers there are share the
    tasks, down to this process alone."""
    real_fork = os.fork
    forks: list[int] = []

    def second_fork_fails() -> int:
        forks.append(1)
        if len(forks) >= 2:
            raise BlockingIOError(11, "Resource temporarily unavailable")
        return real_fork()

    monkeypatch.setattr(os, "fork", second_fork_fails)
    out = forked.run_forked(lambda i: (time.sleep(0.002), i, os.getpid())[1:], 30, 4)
    assert [r[0] for r in out] == list(range(30))
    assert len({r[1] for r in out}) == 2 and len(forks) == 2

    def no_fork() -> int:
        raise BlockingIOError(11, "Resource temporarily unavailable")

    monkeypatch.setattr(os, "fork", no_fork)
    out = forked.run_forked(lambda i: (i, os.getpid()), 5, 2)
    assert out == [(i, os.getpid()) for i in range(5)]


def test_a_workers_exception_is_raised_here_and_the_others_are_stopped():
    parent = os.getpid()

    def task(i: int) -> int:
        time.sleep(0.005)
        if os.getpid() != parent:
            raise ValueError(f"task {i} refused in a worker")
        return i

    with pytest.raises(ValueError, match=r"task \d+ refused in a worker"):
        forked.run_forked(task, 30, 2)


class _Refusal(Exception):
    """An exception that pickles but cannot be rebuilt from its arguments."""

    def __init__(self, what: str, why: str) -> None:
        super().__init__(f"{what}: {why}")


def test_an_exception_that_cannot_travel_comes_as_its_text():
    parent = os.getpid()

    def task(i: int) -> int:
        time.sleep(0.005)
        if os.getpid() != parent:
            raise _Refusal(f"task {i}", "refused")
        return i

    with pytest.raises(RuntimeError, match=r"_Refusal: task \d+: refused"):
        forked.run_forked(task, 30, 2)


def test_a_worker_that_dies_is_one_line():
    parent = os.getpid()

    def task(i: int) -> int:
        time.sleep(0.005)
        if os.getpid() != parent:
            os.kill(os.getpid(), signal.SIGKILL)
        return i

    with pytest.raises(VeiInputError, match="a worker process died"):
        forked.run_forked(task, 30, 2)


def test_a_silent_worker_stops_the_evaluation_at_the_watchdog():
    parent = os.getpid()

    def task(i: int) -> int:
        if os.getpid() != parent:
            time.sleep(60)
        time.sleep(0.01)
        return i

    a = time.monotonic()
    with pytest.raises(VeiInputError, match="no result from the workers within 0.5 s"):
        forked.run_forked(task, 20, 2, timeout_s=0.5)
    assert time.monotonic() - a < 10


def test_a_worker_ends_without_the_parents_clean_up_and_writes_nothing_twice():
    """Output buffered before the fork is not written again by a worker, neither when a task flushes
    (a warning, a print) nor when the worker ends, and the parent's clean-up (its atexit handlers)
    runs once: a worker ends without it."""
    code = (
        "import atexit, sys, time; sys.stdout.write('before'); "
        "atexit.register(lambda: sys.stdout.write(' atexit')); "
        "from vei_scenario.sweep.forked import run_forked; "
        "r = run_forked(lambda i: (time.sleep(0.01), sys.stdout.flush(), i)[2], 6, 2); "
        "sys.stdout.write(' ' + repr(r))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout == "before [0, 1, 2, 3, 4, 5] atexit"
