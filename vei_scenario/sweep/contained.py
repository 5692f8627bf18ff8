"""Rows of the sweep kernel with a native FMU on the ego, computed in forked children so that a crash or
a hang inside the FMU's binary fails the one variant it happened in and never the sweep (Linux).

Why children and not the parent: the FMU is native code in the process that steps it; a segmentation
fault there ends that process whatever Python does, and a call that never returns cannot be
interrupted. The parent never loads the FMU: it hands each child a chunk of variants, reads their rows
as each batch of them is done, and watches a page of shared memory where the kernel writes, before each
call into the FMU, which call, which variant and the step time (``vei_fmu_ego.h``: progress).

* A child that dies (a signal, or an exit) before all its rows: the variant it was in is read from its
  page and fails with one line (``planner.fmu crashed (SIGSEGV) in doStep``, at its step time); the
  chunk's other variants without a row are run again in a new child. Where the page names no call into
  the FMU (the child died elsewhere), the rest are run again one at a time, so the variant whose own
  run kills its process is the one that fails.
* A call into the FMU that does not return within ``--controller-timeout`` (without it, a minute:
  :data:`vei_scenario.batch.fmu_ego.CALL_BOUND_S`) is killed there: its variant fails with the line
  ``vei run`` gives, and the rest go on in a new child.
* An exception of vei's own code in a child (not the FMU's fault, which is a row) stops the evaluation
  and is raised in the parent, as a pool raises it.
* Children are killed and reaped when the parent stops (and die with it: PR_SET_PDEATHSIG), so no
  process is left behind.
"""

from __future__ import annotations

import mmap
import os
import pickle
import select
import signal
import struct
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from vei_scenario.child_process import die_with_parent
from vei_scenario.core.fmu_ego import PROGRESS
from vei_scenario.errors import VeiInputError

#: doubles of one child's page: the kernel's progress, then the chunk position of the batch it runs
_SLOT = PROGRESS + 1
_HEADER = struct.Struct("<iI")  # (first position in the chunk, payload length)
_FAILED = -1  # (the payload: the exception that stopped the child)
#: variants a child runs per kernel call, and sends back together
BATCH = 32


@dataclass
class _Child:
    pid: int
    fd: int
    slot: int
    chunk: list[int]
    alone: bool = False  # (a chunk run again one at a time: its death is its variant's)
    done: set[int] = field(default_factory=set)
    buffer: bytearray = field(default_factory=bytearray)
    calls: float = -1.0
    since: float = 0.0


def run_contained(
    run_rows: Callable[[list[int], np.ndarray], list[dict]],
    groups: list[list[int]],
    workers: int,
    death_row: Callable[[str, float, int, bool], dict],
    timeout_s: float | None = None,
    progress: Callable[[int], None] | None = None,
    watchdog_s: float = 6 * 3600.0,
) -> dict[int, dict]:
    """Rows by index of every index in ``groups`` (indices that may share one kernel call, in
    order). ``run_rows(indices, page)`` gives their rows in a child, the kernel writing its progress to
    ``page``; ``death_row(how, t, call, timed_out)`` the row of a variant whose child died (``how``:
    'crashed (SIGSEGV)') or overran ``timeout_s`` in an FMU call."""
    chunks: list[tuple[list[int], bool]] = []
    total = sum(len(g) for g in groups)
    size = max(1, min(256, -(-total // max(1, workers))))  # (a fork costs ms: one chunk a worker when few)
    for g in groups:
        chunks += [(g[k : k + size], False) for k in range(0, len(g), size)]
    pages = mmap.mmap(-1, max(1, workers) * _SLOT * 8)
    page = np.frombuffer(pages, dtype=float).reshape(max(1, workers), _SLOT)
    rows: dict[int, dict] = {}
    live: dict[int, _Child] = {}
    free = list(range(max(1, workers)))
    poller = select.poll()
    last_heard = time.monotonic()
    try:
        while chunks or live:
            while chunks and free:
                chunk, alone = chunks.pop(0)
                slot = free.pop()
                page[slot] = (0.0, np.nan, -1.0, -1.0, 0.0)
                child = _fork(run_rows, chunk, page[slot], slot, alone, live)
                live[child.fd] = child
                poller.register(child.fd, select.POLLIN)
            ready = poller.poll(100 if timeout_s is not None else 1000)
            now = time.monotonic()
            if ready:
                last_heard = now
            for fd, _ in ready:
                child = live[fd]
                data = os.read(fd, 1 << 16)
                if data:
                    child.buffer += data
                    _take(child, rows, progress)
                    continue
                how = _reap(child)
                _ended(child, how, page[child.slot], chunks, rows, death_row, progress, False)
                _drop(child, live, free, poller)
            if timeout_s is not None:
                for child in list(live.values()):
                    calls, call = page[child.slot][0], page[child.slot][2]
                    if calls != child.calls:
                        child.calls, child.since = calls, now
                        last_heard = now
                    elif call >= 0 and now - child.since > timeout_s:
                        _kill(child)
                        _ended(child, "", page[child.slot], chunks, rows, death_row, progress, True)
                        _drop(child, live, free, poller)
            if not ready and now - last_heard > watchdog_s:
                raise VeiInputError(None, "sweep", f"no result from the workers within {watchdog_s:g} s")
    finally:
        for child in live.values():
            _kill(child)
            os.close(child.fd)
    return rows


def _fork(run_rows, chunk: list[int], page: np.ndarray, slot: int, alone: bool, live: dict) -> _Child:
    r, w = os.pipe()
    parent = os.getpid()
    pid = os.fork()
    if pid == 0:  # the child: run the chunk, batch by batch, and never return into the parent's code
        code = 1
        try:
            os.close(r)
            for fd in live:
                os.close(fd)
            die_with_parent(parent)
            import faulthandler

            faulthandler.disable()  # (a crash is said once, by the parent, in one line)
            signal.signal(signal.SIGINT, signal.SIG_IGN)  # (Ctrl-C is the parent's to handle)
            for k in range(0, len(chunk), BATCH):
                page[PROGRESS] = k
                try:
                    payload = pickle.dumps(run_rows(chunk[k : k + BATCH], page), pickle.HIGHEST_PROTOCOL)
                except Exception as exc:  # noqa: BLE001 (vei's own failure, not the FMU's: the parent raises it)
                    payload, k = _exception(exc), _FAILED
                _write_all(w, _HEADER.pack(k, len(payload)) + payload)
            code = 0
        except BaseException:  # noqa: BLE001, S110 (the parent says what happened, from the missing rows)
            pass
        finally:
            os._exit(code)
    os.close(w)
    return _Child(pid, r, slot, chunk, alone, since=time.monotonic())


def _exception(exc: Exception) -> bytes:
    try:
        payload = pickle.dumps(exc, pickle.HIGHEST_PROTOCOL)
        pickle.loads(payload)  # (some exceptions pickle but cannot be rebuilt from their arguments)
        return payload
    except Exception:  # noqa: BLE001 (an exception that cannot travel: its text)
        return pickle.dumps(RuntimeError(f"{type(exc).__name__}: {exc}"))


def _take(child: _Child, rows: dict, progress) -> None:
    buf = child.buffer
    while len(buf) >= _HEADER.size:
        first, length = _HEADER.unpack_from(buf)
        if len(buf) < _HEADER.size + length:
            break
        batch = pickle.loads(bytes(buf[_HEADER.size : _HEADER.size + length]))
        del buf[: _HEADER.size + length]
        if first == _FAILED:  # (an exception of vei's own code in the child: it stops the evaluation)
            raise batch
        for k, row in enumerate(batch):
            index = child.chunk[first + k]
            rows[index] = row
            child.done.add(index)
        if progress:
            progress(len(batch))


def _ended(child: _Child, how: str, page: np.ndarray, chunks: list, rows: dict, death_row, progress, timed_out) -> None:
    """A child gone before all its rows: its variant fails, the others go again."""
    left = [i for i in child.chunk if i not in child.done]
    if not left:
        return
    call = int(page[2])
    in_fmu = call >= 0 and page[3] >= 0
    if in_fmu or child.alone or timed_out:
        culprit = child.chunk[int(page[PROGRESS]) + int(page[3])] if in_fmu else left[0]
        rows[culprit] = death_row(how, float(page[1]), call, timed_out)
        if progress:
            progress(1)
        left = [i for i in left if i != culprit]
        if left:
            chunks.insert(0, (left, child.alone))
    else:  # (it died outside the FMU's calls: one at a time finds the variant that kills its process)
        chunks[:0] = [([i], True) for i in left]


def _drop(child: _Child, live: dict, free: list, poller) -> None:
    poller.unregister(child.fd)
    os.close(child.fd)
    del live[child.fd]
    free.append(child.slot)


def _reap(child: _Child) -> str:
    """How the child ended: 'crashed (SIGSEGV)', 'ended with exit status 1' (reaped)."""
    _, status = os.waitpid(child.pid, 0)
    child.pid = 0
    if os.WIFSIGNALED(status):
        return f"crashed ({signal.Signals(os.WTERMSIG(status)).name})"
    return f"ended with exit status {os.WEXITSTATUS(status)}"


def _kill(child: _Child) -> None:
    if child.pid:
        try:
            os.kill(child.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        os.waitpid(child.pid, 0)
        child.pid = 0


def _write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view) :]
