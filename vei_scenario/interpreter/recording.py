"""The trace of a run as it is taken, and its arrays at the end.

Steps come from two places: the engine's own steps (one row of every road user each) and the core's
quiet stretches (a block of poses for many steps at once, as ``_core.cruise`` returns them). Both are
appended as they come to one flat buffer of C doubles and turned into one numpy array per quantity and
road user only when the run ends: no tuple per road user and step, no transposition in Python.
"""

from __future__ import annotations

import array
from itertools import repeat

import numpy as np

#: A row as the core gives it for each road user and step: x, y, yaw, metres moved, speed, acceleration;
#: the engine's own steps are kept in the same shape (metres moved: 0, not read), so that the whole
#: trace is one buffer.
_WIDTH = 6
#: The columns a trace keeps: x, y, yaw, speed, acceleration (and a status string kept beside them).
_KEPT = (0, 1, 2, 4, 5)


class Recording:
    """Per step the time and each road user's (x, y, yaw, speed, acceleration, status)."""

    def __init__(self, entities: list) -> None:
        self.entities = entities
        self.times: list[float] = []
        self.status: list[list[str]] = [[] for _ in entities]
        self._rows = array.array("d")  # every step so far, _WIDTH doubles per road user

    def record(self, t: float) -> None:
        """The road users as they are now, at time ``t`` (one of the engine's steps)."""
        self.times.append(t)
        extend = self._rows.extend
        for e, status in zip(self.entities, self.status):
            extend((e.x, e.y, e.yaw, 0.0, e.speed, e.accel))
            status.append(e.status)

    def record_core(self, times: list[float], poses: bytes, statuses: list[str]) -> None:
        """Steps the core took: ``poses`` as ``_core.cruise`` returns them for ``len(times)`` steps,
        every road user's status the same through them."""
        self._rows.frombytes(poses)
        self.times += times
        for status, s in zip(self.status, statuses):
            status.extend(repeat(s, len(times)))

    def arrays(self) -> tuple[np.ndarray, list[np.ndarray]]:
        """The times, and per road user its (steps, 5) array of x, y, yaw, speed, acceleration."""
        k = len(self.entities)
        data = np.frombuffer(self._rows, dtype=np.float64).reshape(len(self.times), k, _WIDTH)
        return np.array(self.times), [np.ascontiguousarray(data[:, i, _KEPT].T) for i in range(k)]
