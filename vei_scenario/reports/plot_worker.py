"""The sweep report's plots drawn in other processes, so that they add little to a sweep's time.

Importing matplotlib (~0.3 s) and drawing three plots (~0.3 s at 10 000 variants) would follow the
evaluation on one core. Forked as the command starts (this module imports nothing heavy), the worker
imports numpy and matplotlib while the parent imports the sweep and the kernel runs, and draws while
the parent writes the catalog; the PNGs are the bytes an in-process drawing gives (same code, same
inputs). Where fork is not available, only one core is or the caller runs other threads, the plots are
drawn in-process; where the worker fails, the parent draws them itself (and meets the same error).
"""

from __future__ import annotations

import os
import sys
import threading


def end_with_parent(parent_pid: int) -> None:
    """Ask the kernel to end this process when its parent does (Linux ``PR_SET_PDEATHSIG``), so a
    killed ``vei sweep`` (SIGKILL included, which no handler sees) leaves no worker drawing behind;
    and end at once if the parent is already gone."""
    try:
        import ctypes
        import signal

        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG = 1
    except (OSError, AttributeError):
        pass
    if os.getppid() != parent_pid:
        os._exit(0)


def _serve(conn, parent_pid: int | None = None) -> None:
    """In the worker: import matplotlib, then draw what the parent sends (None: nothing). The plots
    after the first are drawn by forks of the worker (matplotlib imported already): the three share
    both cores with the parent's catalog writing."""
    if parent_pid is not None:
        end_with_parent(parent_pid)
    try:
        _warm_up()
        inputs = conn.recv()
        if inputs is not None:
            conn.send(_render_each(inputs))
    except (Exception, KeyboardInterrupt):  # noqa: BLE001 - the parent draws in-process instead
        pass
    finally:
        conn.close()


def _warm_up() -> None:
    """Import matplotlib and draw a throw-away figure with text, markers and a legend: fonts and
    caches are then loaded once, in the worker, before the variants finish (the forks inherit them)."""
    import vei_scenario.reports.sweep_plots  # noqa: F401  (numpy, matplotlib)
    from vei_scenario.reports.figures import agg_figure, png_bytes

    fig = agg_figure((2, 1))
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1], marker=".", label="x")
    ax.plot([0], [1], "x")
    ax.set_title("x", fontsize=10)
    ax.set_xlabel("x")
    ax.legend(fontsize=8)
    png_bytes(fig, 10)


def _render_each(inputs: tuple) -> list[tuple[str, int]]:
    """Every plot but the first in a fork of its own (matplotlib is imported already), the first here."""
    import pickle

    from vei_scenario.reports.sweep_plots import SERIES, render_plots

    # the parent writes the catalog meanwhile, then waits for these: drawing at a lower priority lets
    # it keep a core, and the plots take the rest of both once it is done
    try:
        os.nice(10)
    except OSError:
        pass
    helpers = []
    for i in range(1, len(SERIES)):
        read_end, write_end = os.pipe()
        worker = os.getpid()
        pid = os.fork()
        if pid == 0:  # a helper: plot i, pickled into the pipe
            end_with_parent(worker)
            try:
                os.close(read_end)
                with os.fdopen(write_end, "wb") as out:
                    pickle.dump(render_plots(inputs, range(i, i + 1)), out)
            finally:
                os._exit(0)
        os.close(write_end)
        helpers.append((i, pid, read_end))
    plots = render_plots(inputs, range(1))
    for i, pid, read_end in helpers:
        with os.fdopen(read_end, "rb") as got:
            try:
                plots += pickle.load(got)
            except (EOFError, pickle.UnpicklingError):  # the helper died: draw its plot here
                plots += render_plots(inputs, range(i, i + 1))
        os.waitpid(pid, 0)
    return plots


class PlotWorker:
    """``PlotWorker()`` forks the worker (do it before any thread starts); ``draw(inputs)`` hands it
    :func:`plot_inputs`' result and returns at once; ``plots()`` waits for :func:`render_plots`' result;
    ``close()`` ends the worker (also when nothing was drawn)."""

    def __init__(self) -> None:
        self._proc = self._conn = None
        self._inputs: tuple | None = None
        self._sent = False
        # fork only a process without other threads (a thread holding a lock at the fork would leave it
        # held in the child): the command line; a library caller with threads draws in-process
        if sys.platform != "linux" or (os.cpu_count() or 1) < 2 or threading.active_count() > 1:
            return
        import multiprocessing

        ctx = multiprocessing.get_context("fork")
        self._conn, child = ctx.Pipe()
        self._proc = ctx.Process(target=_serve, args=(child, os.getpid()), daemon=True)
        self._proc.start()
        child.close()

    def draw(self, inputs: tuple | None) -> None:
        self._inputs = inputs
        if self._conn is not None and inputs is not None:
            try:
                self._conn.send(inputs)
                self._sent = True
            except OSError:
                pass

    def plots(self) -> list[tuple[str, int]]:
        from vei_scenario.reports.sweep_plots import render_plots

        if self._sent:
            try:
                return self._conn.recv()
            except (EOFError, OSError):  # the worker died: draw here
                pass
        return render_plots(self._inputs)

    def close(self) -> None:
        if self._proc is None:
            return
        try:
            self._conn.send(None)
        except OSError:
            pass
        self._conn.close()
        self._proc.join(timeout=5)
        if self._proc.is_alive():
            self._proc.kill()
            self._proc.join()
        self._proc = self._conn = None
