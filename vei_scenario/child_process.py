"""Children that hold a user's native code (an FMU) die with the process that forked them.

A hung ``doStep`` never reads the end-of-file its parent's death leaves on their socket, so a child
that only exits on end-of-file outlives a ``vei`` killed by SIGTERM or SIGKILL and spins on. Linux
delivers a signal to a child when its parent dies if the child asks for it (``PR_SET_PDEATHSIG``).
"""

from __future__ import annotations

import ctypes
import os
import signal

_PR_SET_PDEATHSIG = 1


def die_with_parent(parent_pid: int) -> None:
    """Linux: this process gets SIGKILL when ``parent_pid`` (the process that forked it) dies; where
    the parent is already gone, it exits now. Elsewhere nothing (the end-of-file rule remains)."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    except (OSError, AttributeError):
        pass
    if os.getppid() != parent_pid:  # (the parent died before the call)
        os._exit(1)
