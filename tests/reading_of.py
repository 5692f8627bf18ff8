"""What the rules reader makes of a description, in the two facts most reader tests check: the kinds
of the road users it names and the ego's speed, for the tests of who is who and of the ego."""

from __future__ import annotations

from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def kinds(text: str) -> list[str]:
    """The kinds of the road users read from ``text``, in the order the reader lists them."""
    return [a.kind for a in read(text).actors]


def ego_kph(text: str) -> float | None:
    """The ego's speed read from ``text`` in km/h to one decimal, or None where none is said."""
    mps = read(text).ego_speed_mps
    return None if mps is None else round(mps * 3.6, 1)


def moves(text: str) -> list[list[str]]:
    """The behaviours of each road user read from ``text``, by name, in the order the reader lists them."""
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


def first_moves_not_on_foot(text: str) -> list[str]:
    """The behaviours of the first road user read from ``text`` that is not a walker, or of the first."""
    actors = read(text).actors
    actor = next((a for a in actors if a.kind != "pedestrian"), actors[0])
    return [b[0] for b in actor.behaviours]


def _behaviour_names(behaviour: dict) -> list[str]:
    """The names in a layers' behaviour tree (one behaviour, or a sequence or parallel of them), in order."""
    if "behaviour" in behaviour:
        return [behaviour["behaviour"]]
    parts = behaviour.get("sequence", behaviour.get("parallel", []))
    return [name for part in parts for name in _behaviour_names(part)]


def acts(text: str) -> list[tuple[str, list[str]]]:
    """(type, behaviour names) of each adversary in ``text``'s layers (seed 0): what the scenario plays."""
    return [(a["type"], _behaviour_names(a["behaviour"])) for a in layers_from_text(text, 0)["adversaries"]]
