"""Errors a user can act on.

Every user-facing failure (bad clip, bad map, broken XML, a missing tool) is a :class:`VeiInputError`
that names the file, the field or line, and the reason, so the CLI can print one line and exit 2
without a traceback. Anything else escaping is a bug in vei-scenario.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path


class VeiError(Exception):
    """Base class of the errors vei-scenario raises on purpose."""


@dataclass
class VeiInputError(VeiError):
    """Bad input: ``file``: ``where``: ``reason``.

    ``where`` is a JSON field path (``ego.samples[3].t``), an XML line (``line 12``) or empty when the
    problem concerns the whole file.
    """

    file: str | Path | None
    where: str
    reason: str

    def __post_init__(self) -> None:
        super().__init__(str(self))

    def __reduce__(self):
        """Pickled by its three fields, so an error raised in a worker process reaches the parent
        intact (the default would call ``__init__`` with the message alone, and fail there)."""
        return (type(self), (self.file, self.where, self.reason))

    def __str__(self) -> str:
        parts = [str(self.file)] if self.file else []
        if self.where:
            parts.append(self.where)
        parts.append(self.reason)
        return ": ".join(parts)
