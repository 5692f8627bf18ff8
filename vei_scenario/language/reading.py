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
    ego_relation: str | None = None
    actors: list[ActorSpec] = field(default_factory=list)
    ignored: list[str] = field(default_factory=list)  # words read past: nothing in the layers holds them
