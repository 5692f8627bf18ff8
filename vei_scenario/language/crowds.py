"""People named as a crowd are the setting, not a road user.

A description sets its scene with the people about ("there were kids everywhere", "people were
walking home from the match", "the pavements were full of shoppers") before the road user who acts
comes in. The format lists the road users that act; a crowd that only is there, or only walks
along, acts on no one. Read as a road user, it gives the scenario a walker too many, who may take
the ego's speed or a crossing from the sentence around it.

A crowd is told by noun-phrase grammar, not by words: a plural person noun with no number or
determiner that picks it out ("two kids", "the other joggers", "the first one" are counted or told
apart, and stay road users). It leaves the road users only when it does nothing towards the ego (it
goes along, goes on or stands: nothing of its own crosses, cuts in or comes out) and another road
user, not a crowd, acts beside it; a crowd alone ("kids walking along the road in the dark") is what
the description is about, and stays.

Road users counted by a number no scenario holds ("212 vehicles turned in and no conflicts were
recorded", "of 63 cyclists observed") are a count of traffic, a survey's figure: they leave the road
users whatever they are read doing, once another road user acts beside them.
"""

from __future__ import annotations

from typing import Protocol

from vei_scenario.language.ego_double import without_road_user
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.reading import ActorSpec, Reading, stands_there
from vei_scenario.language.said_again import plural

#: Plurals the dictionary gives as their own lemma ("people" is the plural of "person").
_PLURAL_AS_LEMMA = frozenset(("people", "folk", "folks", "children", "persons"))
#: Determiners that count or pick out: the people named with one are told apart, not a crowd.
_COUNTING = frozenset(
    ("a", "an", "the", "one", "two", "three", "four", "five", "both", "these", "those", "this", "that")
)
#: What a road user does when it acts on no one: is there, goes on, goes along, stands.
_ONLY_THERE = frozenset(("along_road", "keep_going", "keep_lane", "stop"))


class _Named(Protocol):
    word: str
    det: str
    group: list | None
    member_named: bool


def many(word: str) -> bool:
    """Whether ``word`` is a plural noun ("kids", "riders", "people"), not a word no dictionary has."""
    return word in _PLURAL_AS_LEMMA or (plural(word) and bool(lemmas(word).get("NOUN")))


def _crowd(a: _Named, spec: ActorSpec) -> bool:
    """Whether road user ``spec`` (gathered as ``a``) is a crowd that only is there: walkers named by a
    plural noun that nothing counts or picks out, doing nothing towards the ego."""
    last = a.word.split()[-1] if a.word else ""
    return (
        spec.kind == "pedestrian"
        and many(last)
        and a.det not in _COUNTING
        and not a.group
        and not a.member_named
        and {b[0] for b in spec.behaviours} <= _ONLY_THERE
    )


#: More road users than a scenario holds: a number counting them is a statistic ("212 vehicles").
_MOST = 8


class _Placed(Protocol):
    word: str
    named_end: int


def _statistic(a: _Placed, scanned: list[str]) -> bool:
    """Whether road user ``a`` is first named by a plural noun right after a number greater than a
    scenario holds ("212 vehicles", "63 cyclists")."""
    words = a.word.split()
    start = a.named_end - len(words)
    if not words or a.named_end < 0 or start < 1 or not many(words[-1]):
        return False
    number = scanned[start - 1].replace(",", "")
    return number.isdigit() and int(number) > _MOST


def drop_counts(actors: list, reading: Reading, scanned: list[str]) -> list:
    """``actors`` and ``reading``'s road users without those named only as a count of traffic (see the
    module), when another road user acts beside them; ``scanned``: the words the reader scanned."""
    counts = [k for k, a in enumerate(actors) if _statistic(a, scanned)]
    acting = [s for k, s in enumerate(reading.actors) if k not in counts and not stands_there(s)]
    if not counts or not acting or any(s.obstacle in counts for s in reading.actors):
        return actors
    for k in reversed(counts):
        actors = without_road_user(actors, reading, k)
    return actors


def drop_crowds(actors: list, reading: Reading) -> list:
    """``actors`` and ``reading``'s road users without the crowds that only are there, when a road user
    that is no such crowd and does not only stand there acts beside them (see the module); ``actors``
    are what the reader gathered of them, in the same order. Obstacles keep pointing at the same road
    users."""
    crowds = [k for k, (a, s) in enumerate(zip(actors, reading.actors)) if _crowd(a, s)]
    acting = [s for k, s in enumerate(reading.actors) if k not in crowds and not stands_there(s)]
    if not crowds or not acting or any(s.obstacle in crowds for s in reading.actors):
        return actors
    for k in reversed(crowds):  # (from the last, so that the others' places hold)
        actors = without_road_user(actors, reading, k)
    return actors
