"""Clip input: the ``vei-clip/1`` contract (JSON Schema plus the checks a schema cannot express)."""

from vei_scenario.clip.loader import load_clip
from vei_scenario.clip.model import SCOOTER_CATEGORIES, Annotations, Clip, EgoTrack, Observation

__all__ = ["SCOOTER_CATEGORIES", "Annotations", "Clip", "EgoTrack", "Observation", "load_clip"]
