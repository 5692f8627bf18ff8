"""Results of many independent tasks on all local cores, through forked worker processes (Linux).

Why not a ``ProcessPoolExecutor``: an interpreted sweep's variant costs a few milliseconds, and on a
2-core machine the pool's own work (its manager thread and queues, starting and joining its
workers) cost 4.5 ms more than plain ``fork`` for an 11-variant Euro NCAP file: a third of the whole
sweep, which then ran no faster than in one process. Here the workers are forked when the parent has
read the scenario's files, so they start with them read; they take tasks from one pipe of tickets
as they finish the last (a slow variant holds up no other) and send each result back on their own
pipe as soon as it is done, so a progress bar moves. The parent is one of the workers: it takes
tickets too, and reads the others' pipes between its own tasks.

A task's exception (one its own code did not turn into a result) stops the whole evaluation and is
raised here, as a pool raises it; a worker that dies without a word (killed, out of memory) or a
silence longer than the watchdog is one line.
"""

from __future__ import annotations

import os
import pickle
import select
import signal
import struct
import sys
from collections.abc import Callable

from vei_scenario.errors import VeiInputError

#: A result frame's header: the task's index (or one of the codes below) and the payload's length.
_HEADER = struct.Struct("<iI")
_DONE, _FAILED = -1, -2
#: A ticket is the first index of a run of tasks; at most this many tickets, so that they all fit
#: into the pipe before any worker reads (Linux pipes hold 64 KiB).
_MAX_TICKETS = 8192
_TICKET = struct.Struct("<I")


def available() -> bool:
    """Whether forked workers can be used here: Linux (on macOS, fork without exec is unsafe with
    the system's frameworks, which is why Python spawns there; Windows has no fork)."""
    return sys.platform.startswith("linux") and hasattr(os, "fork")


def run_forked(
    task: Callable[[int], object],
    count: int,
    workers: int,
    progress: Callable[[int], None] | None = None,
    timeout_s: float = 6 * 3600.0,
) -> list:
    """``[task(0), ..., task(count - 1)]`` computed by this process and ``workers - 1`` forked ones
    (fewer when the system refuses more processes: the tasks are shared among those there are). The
    caller runs no threads that hold locks (a forked child would inherit them held)."""
    if count == 0:
        return []
    workers = max(1, min(workers, count))
    size = -(-count // _MAX_TICKETS)  # tasks per ticket
    tickets_r, tickets_w = os.pipe()
    os.write(tickets_w, b"".join(_TICKET.pack(i) for i in range(0, count, size)))
    os.close(tickets_w)  # (the workers read to the end of the pipe: no more tickets)
    children: dict[int, int] = {}  # result pipe's read end -> worker's pid
    try:
        for _ in range(workers - 1):
            out_r, out_w = os.pipe()
            try:
                pid = os.fork()
            except OSError:  # (a process limit, no memory for another: the ones there are do the work)
                os.close(out_r)
                os.close(out_w)
                break
            if pid == 0:  # a worker: it never returns from here
                _work(task, count, size, tickets_r, out_w, [out_r, *children])
            os.close(out_w)
            children[out_r] = pid
        results = _Results(children, count, progress, timeout_s)
        for i in _tasks(tickets_r, size, count):  # this process is a worker as well
            results.put(i, task(i))
            results.drain()  # (as it goes: a full pipe would stall its worker)
        return results.all()
    finally:
        os.close(tickets_r)
        for fd, pid in children.items():
            _end(fd, pid)


def _work(task, count: int, size: int, tickets: int, out: int, inherited: list[int]) -> None:
    """A worker's life: tasks by ticket, each result framed on ``out``; then done, or the exception."""
    code = 1
    try:
        for fd in inherited:  # (the parent's ends of the other workers' pipes)
            os.close(fd)
        for i in _tasks(tickets, size, count):
            payload = pickle.dumps(task(i), pickle.HIGHEST_PROTOCOL)
            _write_all(out, _HEADER.pack(i, len(payload)) + payload)
        _write_all(out, _HEADER.pack(_DONE, 0))
        code = 0
    except BaseException as exc:  # noqa: BLE001 (any failure goes to the parent, which raises it)
        try:
            payload = pickle.dumps(exc, pickle.HIGHEST_PROTOCOL)
            pickle.loads(payload)  # (some exceptions pickle but cannot be rebuilt from their arguments)
        except Exception:  # noqa: BLE001 (an exception that cannot travel: its text)
            payload = pickle.dumps(RuntimeError(f"{type(exc).__name__}: {exc}"))
        try:
            _write_all(out, _HEADER.pack(_FAILED, len(payload)) + payload)
        except BaseException:  # noqa: BLE001 (the parent is gone: nothing to tell)
            pass
    finally:
        os._exit(code)  # (never the parent's clean-up: its atexit handlers, its buffered output)


def _tasks(tickets: int, size: int, count: int):
    """The indices of the tasks this process takes: ``size`` for each ticket it reads, until none is left."""
    while ticket := _read_exactly(tickets, _TICKET.size):
        (first,) = _TICKET.unpack(ticket)
        yield from range(first, min(first + size, count))


class _Results:
    """The tasks' results as they come: this process's own, and the workers' read from their pipes."""

    def __init__(self, children: dict[int, int], count: int, progress, timeout_s: float) -> None:
        self.values: list = [_MISSING] * count
        self.progress = progress
        self.timeout_s = timeout_s
        self.buffers = {fd: bytearray() for fd in children}
        self.open = set(children)
        self.done: set[int] = set()
        self.poll = select.poll()  # (not select(): a worker's pipe may be numbered above 1024)
        for fd in children:
            self.poll.register(fd, select.POLLIN)

    def put(self, index: int, value: object) -> None:
        self.values[index] = value
        if self.progress:
            self.progress(1)

    def drain(self) -> None:
        """Read what the workers have sent so far."""
        while self.open and self._read_ready(0):
            pass

    def all(self) -> list:
        """Read until every worker has said it is done (the watchdog's time at most between two
        messages); every result, in task order."""
        while self.open:
            if not self._read_ready(self.timeout_s * 1000.0):
                raise VeiInputError(None, "sweep", f"no result from the workers within {self.timeout_s:g} s")
        if any(v is _MISSING for v in self.values):  # (cannot happen: every worker said it is done)
            raise VeiInputError(None, "--workers", "a worker process ended without all its results")
        return self.values

    def _read_ready(self, timeout_ms: float) -> bool:
        """Read the pipes that have something within ``timeout_ms``; whether any had."""
        ready = self.poll.poll(timeout_ms)
        for fd, _ in ready:
            self._receive(fd)
        return bool(ready)

    def _receive(self, fd: int) -> None:
        data = os.read(fd, 1 << 16)
        if not data:
            self.open.discard(fd)
            self.poll.unregister(fd)
            if fd not in self.done:
                raise VeiInputError(None, "--workers", "a worker process died (out of memory, or killed)")
            return
        buf = self.buffers[fd]
        buf += data
        while len(buf) >= _HEADER.size:
            index, length = _HEADER.unpack_from(buf)
            if len(buf) < _HEADER.size + length:
                break
            payload = bytes(buf[_HEADER.size : _HEADER.size + length])
            del buf[: _HEADER.size + length]
            if index == _DONE:
                self.done.add(fd)
            elif index == _FAILED:
                raise pickle.loads(payload)
            else:
                self.put(index, pickle.loads(payload))


_MISSING = object()


def _end(fd: int, pid: int) -> None:
    """Close a worker's pipe and reap it; one still running (the evaluation stopped) is killed."""
    os.close(fd)
    try:
        finished, _ = os.waitpid(pid, os.WNOHANG)
        if finished == 0:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
    except ChildProcessError:
        pass


def _read_exactly(fd: int, n: int) -> bytes:
    """``n`` bytes, or b"" at the end of the pipe (a pipe read may return fewer than asked)."""
    data = os.read(fd, n)
    while data and len(data) < n:
        more = os.read(fd, n - len(data))
        if not more:
            raise EOFError("a ticket was cut short")
        data += more
    return data


def _write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view) :]
