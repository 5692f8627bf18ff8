"""What an annotated road user of a clip becomes in a scenario: its OpenSCENARIO class and category,
and a bounding box typical of it.

Why: every annotated road user belongs in the scenario, replayed as recorded, whether or not vei has a
behaviour model for it; players (esmini, the OSI writer) type it by its OpenSCENARIO element and
category, so a pedestrian must be a ``Pedestrian``, not a box of unknown kind. Categories name what an
annotation tool calls a road user (``pedestrian``, ``person``, ``cyclist``, ``truck`` ...); one that
OpenSCENARIO has no class for becomes a ``MiscObject`` (category ``none``) whose ``objectType``
property keeps the annotated name.
"""

from __future__ import annotations

from dataclasses import dataclass

from vei_scenario.clip.model import SCOOTER_CATEGORIES


@dataclass(frozen=True)
class RoadUserClass:
    """``kind``: the ScenarioObject element (``vehicle``, ``pedestrian``, ``misc``); ``category``: its
    OpenSCENARIO category (vehicleCategory, pedestrianCategory or miscObjectCategory); the box (m)."""

    kind: str
    category: str
    length_m: float
    width_m: float
    height_m: float
    mass_kg: float


#: E-scooter with a standing rider (m): deck and bars ~1.1–1.2 m long, shoulders ~0.6 m, ~1.9 m tall.
E_SCOOTER = RoadUserClass("vehicle", "bicycle", 1.2, 0.6, 1.9, 90.0)
#: Typical boxes (m, kg). Pedestrian: shoulder width and stride, as esmini's pedestrian catalog has it.
_PEDESTRIAN = RoadUserClass("pedestrian", "pedestrian", 0.6, 0.5, 1.8, 80.0)
_CLASSES = {
    "pedestrian": _PEDESTRIAN,
    "person": _PEDESTRIAN,
    "walker": _PEDESTRIAN,
    "adult": _PEDESTRIAN,
    "child": RoadUserClass("pedestrian", "pedestrian", 0.4, 0.4, 1.2, 30.0),
    "wheelchair": RoadUserClass("pedestrian", "wheelchair", 1.1, 0.7, 1.3, 110.0),
    "animal": RoadUserClass("pedestrian", "animal", 1.0, 0.4, 0.8, 30.0),
    "dog": RoadUserClass("pedestrian", "animal", 0.9, 0.3, 0.6, 25.0),
    "bicycle": RoadUserClass("vehicle", "bicycle", 1.8, 0.6, 1.8, 90.0),
    "bike": RoadUserClass("vehicle", "bicycle", 1.8, 0.6, 1.8, 90.0),
    "cyclist": RoadUserClass("vehicle", "bicycle", 1.8, 0.6, 1.8, 90.0),
    "motorbike": RoadUserClass("vehicle", "motorbike", 2.2, 0.8, 1.5, 250.0),
    "motorcycle": RoadUserClass("vehicle", "motorbike", 2.2, 0.8, 1.5, 250.0),
    "moped": RoadUserClass("vehicle", "motorbike", 1.8, 0.7, 1.4, 150.0),
    "car": RoadUserClass("vehicle", "car", 4.5, 1.8, 1.5, 1500.0),
    "van": RoadUserClass("vehicle", "van", 5.2, 2.0, 2.2, 2500.0),
    "truck": RoadUserClass("vehicle", "truck", 9.0, 2.5, 3.5, 12000.0),
    "lorry": RoadUserClass("vehicle", "truck", 9.0, 2.5, 3.5, 12000.0),
    "bus": RoadUserClass("vehicle", "bus", 12.0, 2.55, 3.2, 12000.0),
    "trailer": RoadUserClass("vehicle", "trailer", 6.0, 2.5, 3.0, 3000.0),
    "tram": RoadUserClass("vehicle", "tram", 30.0, 2.65, 3.4, 40000.0),
    "train": RoadUserClass("vehicle", "train", 50.0, 3.0, 4.0, 100000.0),
}
#: A road user OpenSCENARIO has no class for: a misc object of a generic size.
_OTHER = RoadUserClass("misc", "none", 1.0, 1.0, 1.5, 100.0)


def _key(category: str) -> str:
    return category.strip().lower().replace("_", "-")


def is_e_scooter(category: str) -> bool:
    """Whether an annotated category is an e-scooter (the road users vei has a rider model for)."""
    return category.strip().lower() in SCOOTER_CATEGORIES


def road_user_class(category: str) -> RoadUserClass:
    """The OpenSCENARIO class of an annotated category (a misc object when it names none)."""
    if is_e_scooter(category):
        return E_SCOOTER
    key = _key(category)
    return _CLASSES.get(key) or _CLASSES.get(key.rsplit(".", 1)[-1]) or _OTHER


def has_class(category: str) -> bool:
    """Whether OpenSCENARIO has a class for the category (otherwise it is written as a misc object)."""
    return road_user_class(category) is not _OTHER


def replay_note(category: str) -> str:
    """The compile note on a road user vei has no behaviour model for: how it is written and played."""
    cls = road_user_class(category)
    element = {"vehicle": "Vehicle", "pedestrian": "Pedestrian", "misc": "MiscObject"}[cls.kind]
    return f"category {category!r} replayed as recorded (a {element} of category {cls.category!r}; no behaviour model)"
