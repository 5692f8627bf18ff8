"""Clip input: the ``vei-clip/1`` contract (JSON Schema plus the checks a schema cannot express)."""

from pathlib import Path

from vei_scenario.clip.loader import clip_from_document, read_json
from vei_scenario.clip.model import SCOOTER_CATEGORIES, Annotations, Clip, EgoTrack, Observation

__all__ = ["SCOOTER_CATEGORIES", "Annotations", "Clip", "EgoTrack", "Observation", "load_clip"]


def load_clip(path: str | Path, frame_rate_hz: float | None = None, time_unit: str | None = None) -> Clip:
    """Read, validate and normalise a clip file: ``vei-clip/1`` JSON, or ASAM OpenLABEL 1.0 JSON (a
    top-level ``openlabel`` object, see :mod:`vei_scenario.clip.openlabel`); ``frame_rate_hz``: the
    frame rate of an OpenLABEL file without timestamps, ``time_unit``: the unit (s, ms, us, ns) of an
    OpenLABEL file's timestamps written as numbers. Raises :class:`VeiInputError` on any bad input."""
    path = Path(path)
    doc = read_json(path)
    if isinstance(doc, dict) and "openlabel" in doc:
        from vei_scenario.clip.openlabel import clip_from_openlabel  # (the VCD library: only for OpenLABEL)

        return clip_from_openlabel(path, doc, frame_rate_hz, time_unit)
    if frame_rate_hz is not None or time_unit is not None:
        from vei_scenario.clip.openlabel import refuse_clock_options

        refuse_clock_options(path, frame_rate_hz, time_unit)
    return clip_from_document(path, doc)
