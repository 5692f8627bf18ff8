"""The trace of a run as it is taken, and its arrays at the end.

Steps come from two places: the engine's own steps (one row of every road user each) and the core's
quiet stretches (a block of poses for many steps at once, as ``_core.cruise`` returns them). Both are
kept as they come, in flat buffers, and turned into one numpy array per quantity and road user only
when the run ends: no tuple per road user and step, no transposition in Python.
"""

from __future__ import annotations

import array
from itertools import repeat

import numpy as np

#: What a row holds: x, y, yaw, speed, acceleration (and a status string kept beside it).
_QUANTITIES = 5
#: Where those are in a block of the core's poses (x, y, yaw, metres moved, speed, acceleration).
_CORE_COLUMNS = (0, 1, 2, 4, 5)
_CORE_WIDTH = 6


class Recording:
    """Per step the time and each road user's (x, y, yaw, speed, acceleration, status)."""

    def __init__(self, entities: list) -> None:
        self.entities = entities
        self.times: list[float] = []
        self.status: list[list[str]] = [[] for _ in entities]
        self._blocks: list[np.ndarray] = []  # (steps, road users, 5) each, in order
        self._rows = array.array("d")  # the engine's steps since the last block

    def record(self, t: float) -> None:
        """The road users as they are now, at time ``t`` (one of the engine's steps)."""
        self.times.append(t)
        extend = self._rows.extend
        for e, status in zip(self.entities, self.status):
            extend((e.x, e.y, e.yaw, e.speed, e.accel))
            status.append(e.status)

    def record_core(self, times: list[float], poses: bytes, statuses: list[str]) -> None:
        """Steps the core took: ``poses`` as ``_core.cruise`` returns them for ``len(times)`` steps,
        every road user's status the same through them."""
        self._flush()
        k = len(self.entities)
        block = np.frombuffer(poses, dtype=np.float64).reshape(len(times), k, _CORE_WIDTH)
        self._blocks.append(block[:, :, _CORE_COLUMNS])
        self.times += times
        for status, s in zip(self.status, statuses):
            status.extend(repeat(s, len(times)))

    def _flush(self) -> None:
        if self._rows:
            k = len(self.entities)
            self._blocks.append(np.frombuffer(self._rows, dtype=np.float64).reshape(-1, k, _QUANTITIES))
            self._rows = array.array("d")

    def arrays(self) -> tuple[np.ndarray, list[np.ndarray]]:
        """The times, and per road user its (steps, 5) array of x, y, yaw, speed, acceleration."""
        self._flush()
        k = len(self.entities)
        data = np.concatenate(self._blocks, axis=0) if self._blocks else np.empty((0, k, _QUANTITIES))
        return np.array(self.times), [np.ascontiguousarray(data[:, i, :].T) for i in range(k)]
