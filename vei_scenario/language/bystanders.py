"""Road users only mentioned, beside one that acts, are no road users of the scenario.

A description names more than the road users of its situation: the car the writer once loved, the two
vehicles a reflection is about, the trams of a heading before the tram that passes. The format lists
the road users that act; one of which the words say nothing but that it is there or goes on (no act
of its own towards anyone), nowhere it is (no start, side or lane), no speed and no gap, and which is
the object of no one's verb, is only named. Beside a road user that does something of its own it is
no part of the situation and leaves the road users; alone, it is what the description is about, and
stays.

Only vehicles are read so: a walker or rider said to go along is out on the road. A road user told
anything of its own stays: where it is ("on my left", "ahead"), how fast, how far,
that it stands, that someone does something to it ("overtook a van", "hit a car"), that it is watched
doing something ("saw the car hit a cyclist": its deed is what was seen, though no verb of going names
it), or that it is one more of its kind ("another car ran it too": told apart from the one before).
"""

from __future__ import annotations

from typing import Protocol

from vei_scenario.language.ego import VEHICLES
from vei_scenario.language.ego_double import without_road_user
from vei_scenario.language.reading import ActorSpec, Reading

#: What a road user does that is no act towards anyone: it goes on (said, or read where nothing is).
_GOING_ON = "keep_going"


class _Gathered(Protocol):
    """What the reader gathered of a road user, as far as this module reads it."""

    stationary: bool
    acted_on: bool
    object_of: object
    said: set
    seen: bool
    det: str


def _only_named(a: _Gathered, spec: ActorSpec) -> bool:
    """Whether road user ``spec`` (gathered as ``a``) is only named: it goes on, nowhere said, with no
    speed or gap, standing nowhere, no one's object, not watched, not one more of its kind."""
    return (
        spec.kind in VEHICLES  # (a walker or rider said to go along is out on the road doing so)
        and [b[0] for b in spec.behaviours] == [_GOING_ON]
        and spec.relation is None
        and spec.speed_mps is None
        and spec.distance_m is None
        and not a.stationary
        and not a.acted_on
        and a.object_of is None
        and not a.said
        and not a.seen
        and a.det != "another"
    )


def _acts(spec: ActorSpec) -> bool:
    """Whether road user ``spec`` does something of its own (more than going on)."""
    return any(b[0] != _GOING_ON for b in spec.behaviours)


def drop_bystanders(actors: list, reading: Reading) -> list:
    """``actors`` and ``reading``'s road users without those only named (see the module), when a road
    user that acts is beside them; ``actors`` are what the reader gathered of them, in the same order.
    Obstacles keep pointing at the same road users."""
    specs = reading.actors
    named = [k for k, (a, s) in enumerate(zip(actors, specs)) if _only_named(a, s)]
    if not named or not any(_acts(s) for s in specs) or any(s.obstacle in named for s in specs):
        return actors
    for k in reversed(named):  # (from the last, so that the others' places hold)
        actors = without_road_user(actors, reading, k)
    return actors
