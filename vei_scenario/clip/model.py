"""Plain, immutable objects for a loaded clip, in the clip's own units (GPS clock, degrees, metres)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

#: Annotation categories reconstructed as e-scooter entities; other categories are reported and skipped.
SCOOTER_CATEGORIES = frozenset({"e-scooter", "escooter", "e_scooter", "scooter"})

#: Ego box when the clip gives none: a mid-size passenger car (m).
DEFAULT_EGO_LENGTH_M = 4.8
DEFAULT_EGO_WIDTH_M = 1.9


@dataclass(frozen=True)
class EgoTrack:
    """GPS fixes of the ego; arrays share one index. ``heading_deg`` is course over ground, clockwise
    from true north."""

    t: np.ndarray
    lat: np.ndarray
    lon: np.ndarray
    heading_deg: np.ndarray
    speed_mps: np.ndarray
    length_m: float = DEFAULT_EGO_LENGTH_M
    width_m: float = DEFAULT_EGO_WIDTH_M


@dataclass(frozen=True)
class Observation:
    """One annotated object in one frame: ego-frame offsets as annotated (before any axis flip)."""

    t_annotation: float
    track_id: str
    category: str
    x_m: float
    y_m: float
    frame_index: int


@dataclass(frozen=True)
class Annotations:
    time_offset_s: float
    y_axis: str  # "right" (image convention, negated into the right-handed frame) or "left"
    frame_times: np.ndarray
    observations: tuple[Observation, ...]

    def tracks(self, categories: frozenset[str] | None = None) -> dict[str, list[Observation]]:
        """Observations grouped by track id, in time order, optionally filtered by category."""
        out: dict[str, list[Observation]] = {}
        for obs in self.observations:
            if categories is None or obs.category.lower() in categories:
                out.setdefault(obs.track_id, []).append(obs)
        return out


@dataclass(frozen=True)
class Clip:
    path: Path
    id: str
    recorded_at: str | None
    ego: EgoTrack
    annotations: Annotations
    osm_path: Path | None
    extensions: dict = field(default_factory=dict)


def local_tmerc(lat0_deg: float, lon0_deg: float) -> str:
    """The PROJ string of a clip's local frame: transverse Mercator on WGS84 centred on its first ego
    sample (metres east and north). An OpenLABEL clip carries it; the reconstruction projects with it."""
    return (
        f"+proj=tmerc +lat_0={lat0_deg:.10f} +lon_0={lon0_deg:.10f} +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m +no_defs"
    )
