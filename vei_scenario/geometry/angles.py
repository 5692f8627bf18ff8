"""Heading helpers: wrapping and SLERP resampling of planar headings via scipy rotations."""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation, Slerp


def wrap_pi(a):
    """Wrap angles to (-π, π]."""
    return -((-np.asarray(a, float) + np.pi) % (2 * np.pi) - np.pi)


def slerp_yaw(t_key: np.ndarray, yaw_key: np.ndarray, t_query: np.ndarray) -> np.ndarray:
    """Spherical linear interpolation of headings (rotations about z) at ``t_query``.

    SLERP takes the short way round between keyframes, which linear interpolation of raw angles does
    not do across ±π. Queries outside the keyframe span are clamped to the end headings.
    """
    t_key = np.asarray(t_key, float)
    t_query = np.clip(np.asarray(t_query, float), t_key[0], t_key[-1])
    if t_key.size == 1:
        return np.full(t_query.shape, float(yaw_key[0]))
    rot = Rotation.from_euler("z", np.asarray(yaw_key, float)[:, None])
    out = Slerp(t_key, rot)(t_query).as_euler("zyx")[:, 0]
    return wrap_pi(out)


def unwrap_continuous(yaw: np.ndarray) -> np.ndarray:
    """Continuous heading sequence (no 2π jumps), starting within (-π, π]."""
    return np.unwrap(wrap_pi(yaw))
