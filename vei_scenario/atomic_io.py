"""Write files so that a failure never leaves half an output behind.

Each writer renders into a temporary file in the target directory and renames it over the target
(``os.replace`` is atomic on POSIX). :class:`OutputSet` stages several files and commits them only
when all were rendered, which is what ``vei compile`` needs: either every output or none.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

_UMASK: list[int] = []


def _default_mode() -> int:
    """The mode ``open()`` gives a new file (0666 less the umask): a temporary file is created 0600,
    and renaming it must not make every output private to its owner."""
    if not _UMASK:
        mask = os.umask(0o022)  # read the umask (there is no other way) and put it back at once
        os.umask(mask)
        _UMASK.append(mask)
    return 0o666 & ~_UMASK[0]


def _temporary(path: Path) -> tuple[int, str]:
    """A temporary file beside ``path``, named ``.NAME.PID.XXXX.tmp``. Temporary files of the same
    target left by a process that no longer runs (killed with SIGKILL mid-write, which no handler can
    catch) are removed first, so a crash leaves nothing behind for long."""
    prefix = f".{path.name}."
    try:
        leftovers = [p for p in path.parent.iterdir() if p.name.startswith(prefix) and p.name.endswith(".tmp")]
    except OSError:
        leftovers = []
    for p in leftovers:
        pid = p.name[len(prefix) :].split(".", 1)[0]
        if pid.isdigit() and not _alive(int(pid)):
            p.unlink(missing_ok=True)
    return tempfile.mkstemp(prefix=f"{prefix}{os.getpid()}.", suffix=".tmp", dir=path.parent)


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # exists, owned by somebody else
        return True
    return True


def _write(fd: int, tmp: str, data: bytes) -> None:
    """``data`` into the open temporary file ``fd`` (closed either way), with the usual file mode."""
    try:
        fh = os.fdopen(fd, "wb")
    except BaseException:
        os.close(fd)
        raise
    with fh:
        fh.write(data)
    os.chmod(tmp, _default_mode())


def _named(exc: OSError, path: Path) -> OSError:
    """``exc`` naming ``path``, the file the user asked for, not the temporary file beside it (a
    read-only folder refuses the temporary file first, and the user never named that)."""
    names = [str(n) for n in (exc.filename, exc.filename2) if n is not None]
    ours = [n for n in names if Path(n).name.startswith(f".{path.name}.") and n.endswith(".tmp")]
    if exc.errno is None or (names and not ours):
        return exc  # (a folder that cannot be made, say: the user's own path already)
    return OSError(exc.errno, exc.strerror, str(path))


def write_bytes_atomic(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file and a rename."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        fd, tmp = _temporary(path)
    except OSError as exc:
        raise _named(exc, path) from None
    try:
        _write(fd, tmp, data)
        os.replace(tmp, path)
    except BaseException as exc:
        Path(tmp).unlink(missing_ok=True)
        if isinstance(exc, OSError):
            raise _named(exc, path) from None
        raise


class OutputSet:
    """Collect rendered outputs in memory and write all of them, or none, on :meth:`commit`."""

    def __init__(self) -> None:
        self._files: dict[Path, bytes] = {}

    def add(self, path: Path, data: bytes | str) -> None:
        self._files[Path(path)] = data.encode("utf-8") if isinstance(data, str) else data

    @property
    def paths(self) -> list[Path]:
        return list(self._files)

    def commit(self) -> None:
        for path in self._files:  # a folder where a file goes: refused before anything is written
            if path.is_dir():
                raise IsADirectoryError(21, "Is a directory", str(path))
        staged: list[tuple[str, Path]] = []
        path = None
        try:
            for path, data in self._files.items():
                path.parent.mkdir(parents=True, exist_ok=True)
                fd, tmp = _temporary(path)
                staged.append((tmp, path))  # (before writing: a failed write is cleaned up too)
                _write(fd, tmp, data)
        except BaseException as exc:
            for tmp, _ in staged:
                Path(tmp).unlink(missing_ok=True)
            if isinstance(exc, OSError) and path is not None:
                raise _named(exc, path) from None
            raise
        for k, (tmp, path) in enumerate(staged):
            try:
                os.replace(tmp, path)
            except BaseException as exc:
                for rest, _ in staged[k:]:
                    Path(rest).unlink(missing_ok=True)
                if isinstance(exc, OSError):
                    raise _named(exc, path) from None
                raise


def finite_json(obj):
    """``obj`` with every non-finite float (NaN, ±inf) replaced by None: JSON has no such numbers,
    and a metric that is not defined is null in vei's outputs."""
    import math

    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: finite_json(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [finite_json(v) for v in obj]
    return obj


def json_text(obj, **kwargs) -> str:
    """Strict JSON text of ``obj`` (``allow_nan=False``): fast when every number is finite, and
    non-finite numbers written as null otherwise, never as the invalid ``NaN``/``Infinity``."""
    import json

    try:
        return json.dumps(obj, allow_nan=False, **kwargs)
    except ValueError:
        return json.dumps(finite_json(obj), allow_nan=False, **kwargs)
