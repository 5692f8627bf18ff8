"""What a description says once read (before anything is sampled): the actors, where they start and
what they do, the road, the weather, the ego; and the refusal that names the words nothing could place.
The reader (:mod:`vei_scenario.language.reader`) and the local language model fill it in; the
sampling (:mod:`vei_scenario.language.rules_backend`) turns it into layers."""

from __future__ import annotations

from dataclasses import dataclass, field


class NotUnderstood(ValueError):
    """The description cannot become a scenario: it names no road user, or nothing says what its road
    users do. ``missing`` says which ("road user", "behaviour"); ``words`` are the words not used."""

    def __init__(self, words: list[str], text: str, missing: str | None = None, of: str = "") -> None:
        self.words = words
        self.missing = missing
        listed = ", ".join(f"'{w}'" for w in words)
        unused = f"; words not used: {listed}" if words else ""
        if missing == "road user":
            message = (
                f"no road user found (name one: the ego, a pedestrian, cyclist, e-scooter, car, van, truck ...){unused}"
            )
        elif missing == "behaviour":
            message = f"no behaviour found: nothing says what the {of} does (`vei behaviours` lists them){unused}"
        else:
            message = f"could not place {listed}"
        super().__init__(message)


@dataclass
class ActorSpec:
    kind: str
    relation: str | None = None
    distance_m: float | None = None
    speed_mps: float | None = None
    behaviours: list[tuple[str, dict, str | None, str]] = field(default_factory=list)  # name, cfg, class, link
    #: Sideways in its lane (left positive, m) and which way it faces (``with``/``against`` the lane).
    lateral_m: float | None = None
    facing: str | None = None
    #: Said beside the ego ("2 m behind me on my left") or in a lane of its own ("in the cycle lane"), not
    #: in the ego's lane: a short distance said of it is where it starts (:mod:`closest_approach`).
    beside: bool = False
    #: For a vehicle that swerves round something standing: the index of that actor in the reading.
    obstacle: int | None = None


@dataclass
class Reading:
    """What the parser understood, before sampling."""

    map_kind: str | None = None
    lanes: int | None = None
    weather: str | None = None
    time: str | None = None
    density: str | None = None
    intent: str | None = None
    ego_route: str | None = None
    ego_speed_mps: float | None = None
    #: The one speed said of the scene, on a road user, where the ego's own is not said: the ego's
    #: default speed in the layers (scene_pace), in place of one drawn at random.
    scene_pace_mps: float | None = None
    ego_relation: str | None = None
    actors: list[ActorSpec] = field(default_factory=list)
    ignored: list[str] = field(default_factory=list)  # words read past: nothing in the layers holds them
    #: Phrases whose verb the reader has no word for, read as a plain motion verb: (said, read as).
    read_as: list[tuple[str, str]] = field(default_factory=list)


#: What a road user does while it only stands there: nothing that moves it.
_STANDING = frozenset(("keep_going", "stop", "keep_lane"))


def stands_there(spec: ActorSpec) -> bool:
    """Whether road user ``spec`` only stands there (a car parked at the kerb): scenery the scenario may
    hold, no road user that acts on anyone."""
    return spec.speed_mps == 0.0 and {b[0] for b in spec.behaviours} <= _STANDING


def _kph(mps: float | None) -> str | None:
    return None if mps is None else f"{mps * 3.6:.3g} km/h"


def reading_document(reading: Reading) -> dict:
    """What was read, as plain values (batch.json's ``reading``): one entry per road user as read
    (type, where it starts, its behaviours, speed, gap), the settings the text states, and the words
    it did not use. What the text leaves open is absent here (it is drawn per scenario)."""
    actors = []
    for a in reading.actors:
        entry: dict = {"type": a.kind, "start": a.relation}
        entry["behaviours"] = [
            {"behaviour": n, "criticality": c} if c else {"behaviour": n} for n, _, c, _ in a.behaviours
        ]
        if a.speed_mps is not None:
            entry["speed_mps" if a.speed_mps >= 0 else "speed_factor"] = round(abs(a.speed_mps), 3)
        if a.distance_m is not None:
            entry["gap_m"] = round(a.distance_m, 3)
        actors.append(entry)
    settings = {
        "map": reading.map_kind,
        "lanes_per_direction": reading.lanes,
        "weather": reading.weather,
        "time_of_day": reading.time,
        "traffic_density": reading.density,
        "ego_speed_mps": None if reading.ego_speed_mps is None else round(reading.ego_speed_mps, 3),
        "ego_route": reading.ego_route,
        "intent": reading.intent,
    }
    return {
        "actors": actors,
        "settings": {k: v for k, v in settings.items() if v is not None},
        "not_used": list(reading.ignored),
        "read_as": [{"said": said, "read_as": as_} for said, as_ in reading.read_as],
    }


def reading_lines(reading: Reading) -> list[str]:
    """What was read, as the lines ``vei describe`` prints: one per road user, the settings, and the
    words not used (so a misreading shows before the scenarios are looked at)."""
    doc = reading_document(reading)
    lines = []
    for k, (a, spec) in enumerate(zip(doc["actors"], reading.actors), 1):
        said = [a["type"], f"starts {a['start'] or 'where its behaviour starts'}"]
        said.append(
            ", then ".join(
                b["behaviour"] + (f" ({b['criticality']})" if "criticality" in b else "") for b in a["behaviours"]
            )
            or "keep_going"
        )
        if spec.speed_mps is not None:
            said.append(
                f"speed {_kph(spec.speed_mps)}" if spec.speed_mps >= 0 else f"speed {-spec.speed_mps:g} × the usual"
            )
        if spec.distance_m is not None:
            said.append(f"gap {spec.distance_m:g} m")
        lines.append(f"read: road user {k}: " + "; ".join(said))
    s = doc["settings"]
    shown = [f"{key.replace('_', ' ')} {value}" for key, value in s.items() if key != "ego_speed_mps"]
    if "ego_speed_mps" in s:
        shown.insert(0, f"ego speed {_kph(s['ego_speed_mps'])}")
    lines.append("read: settings: " + ("; ".join(shown) if shown else "none stated (drawn per scenario)"))
    if doc["read_as"]:
        lines.append("read: " + ", ".join(f"'{x['said']}' as '{x['read_as']}'" for x in doc["read_as"]))
    if doc["not_used"]:
        lines.append("read: not used: " + ", ".join(f"'{w}'" for w in doc["not_used"]))
    return lines
