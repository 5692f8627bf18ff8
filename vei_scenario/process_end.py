"""How a ``vei`` process ends once it has loaded a user's native library (an FMU).

The C runtime finalises a loaded library after Python's own exit work, in an order the library's
author may not have foreseen: a PythonFMU-built FMU runs its interpreter finaliser after its own static
objects were destroyed and reads freed memory (valgrind: invalid read in ``finalizePythonInterpreter``
under ``_dl_fini``), which now and then aborts the process with "corrupted double-linked list" after
every output was written and the command had succeeded. The exit status would then lie about the run.

So once such a library is loaded, the command ends by doing Python's exit work itself (joining
threads, running the ``atexit`` handlers that remove extracted FMUs and temporary folders, flushing the
streams) and then leaves with :func:`os._exit`, which skips the libraries' finalisers. A process that
loaded none ends as usual.
"""

from __future__ import annotations

import atexit
import os
import sys
import threading

_LOADED: set[str] = set()  # (one entry per library, however many instances a sweep makes)


def note_native_library(path: str) -> None:
    """Record that this process has loaded the native library of an FMU (``path``, for the record)."""
    _LOADED.add(str(path))


def end_process(code: int) -> None:
    """Leave the process with ``code``: as usual when no native library was loaded, else after
    Python's exit work without the libraries' finalisers (see the module docstring)."""
    if not _LOADED:
        sys.exit(code)
    shutdown = getattr(threading, "_shutdown", None)  # (what the interpreter does first at its exit)
    if shutdown is not None and threading.current_thread() is threading.main_thread():
        shutdown()
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # (a closed pipe: nothing more to say)
            pass
    os._exit(code)
