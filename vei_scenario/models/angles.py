"""Angle wrapping as vei run logs headings: into [−π, π), the remainder taking the divisor's sign (the
core's ``vei_wrap_angle`` is the same in C). For floats and numpy arrays alike."""

from __future__ import annotations

import math


def wrap_angle(a):
    """``a`` (rad, a float or an array) wrapped into [−π, π)."""
    return (a + math.pi) % (2 * math.pi) - math.pi
