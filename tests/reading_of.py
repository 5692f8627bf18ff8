"""What the rules reader makes of a description, in the two facts most reader tests check: the kinds
of the road users it names and the ego's speed, for the tests of who is who and of the ego."""

from __future__ import annotations

from vei_scenario.language.reader import read


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
