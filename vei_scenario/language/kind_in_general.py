"""A kind of walker or rider named in general is no road user beside one of that kind in the scene.

People set a story up with what they think of a kind of road user before they tell what one of them
did: "these e-scooters are a menace", "riders come off the path at full speed without looking",
"what's changed is the scooters", and then "a lad on a Lime came off the pavement". The plural says
what such road users do; the singular one (or the ones a number counts: "two lads on scooters") is
who the scenario is about. Read as a road user of its own, the plural gives the scenario a rider or
walker too many, often taking the singular one's crossing or the ego's speed.

The kind in general is told by noun-phrase grammar, as :mod:`crowds` tells a crowd: a plural noun
that nothing counts, picks out or sets apart (no number, "both", "a", "another", "the other"; not
named in a group or picked out of one), and that is not told doing something then or now ("kids were
racing down the hill", "cyclists are riding two abreast": those ones were there). It leaves the road
users only when another road user of the same kind, named in the singular or counted, is in the
reading: a plural alone ("e-scooter riders came off the path") is what the description is about and
stays; a walker named beside riders in general is a road user of another kind, and stays too (a rider
and a walker are two).
"""

from __future__ import annotations

from typing import Protocol

from vei_scenario.language.crowds import many
from vei_scenario.language.discourse import told_in_the_past
from vei_scenario.language.ego_double import without_road_user
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.normalise import NUMBER_WORDS
from vei_scenario.language.reading import Reading
from vei_scenario.language.said_again import plural

#: The kinds of road users on foot or on two wheels, the ones people name in general this way.
WALKERS_AND_RIDERS = frozenset(("pedestrian", "bicycle", "e-scooter", "motorcycle"))
#: Determiners that count or bring in one new: a plural named with one (or a number) is counted.
_COUNTING = frozenset(("a", "an", "another", "several", "both", "each", "every", "couple", "pair"))
#: The modal auxiliaries of what ought to or may be, by their lemmas ("should" is "shall"'s, "might" is
#: "may"'s): said after a plural, what such ones ought to or may do. "Could" and "would" ("can"'s and
#: "will"'s) tell what those ones could not or would not do then ("the joggers couldn't hear me and ran").
_MODAL_LEMMAS = frozenset(("shall", "may", "must", "ought"))
#: Words that set a plural apart from the one in the scene: "the other joggers" are others there.
_APART = frozenset(("other", "others", "rest"))


class _Named(Protocol):
    word: str
    det: str
    named_after: str
    group: list | None
    member_named: bool
    counted: bool
    named_end: int


def _counted(word: str) -> bool:
    """Whether ``word``, said right before a road user's name, counts it ("two", "3", "both")."""
    return word in _COUNTING or word in NUMBER_WORDS or word.isdigit()


def _many(a: _Named) -> bool:
    """Whether road user ``a`` is named by a plural noun ("riders", "people"; a word no dictionary has
    by its ending: "e-scooters")."""
    last = a.word.split()[-1] if a.word else ""
    return bool(last) and (many(last) or plural(last))


def _modal(word: str) -> bool:
    """Whether ``word`` is a modal auxiliary of what ought to or may be ("should", "must", "might"; by
    its lemma); "could" and "would" are not (see :data:`_MODAL_LEMMAS`)."""
    return bool(set(lemmas(word).get("AUX", ())) & _MODAL_LEMMAS)


def _told_then_or_now(tokens: list[str], k: int) -> bool:
    """Whether the verb at ``k``, right after a plural, tells what those ones did or are doing ("were
    running", "ran", "are riding"); a past that is also the verb's plain form ("riders come off the
    path", "cyclists cut across here") may be said of them in general, and is not taken as told, nor
    is a modal ("those scooters should not be allowed": what such ones may or ought to do)."""
    w = tokens[k] if k < len(tokens) else ""
    if _modal(w):
        return False
    plain = w in lemmas(w).get("VERB", ()) and w not in ("are", "am", "'re", "were", "was")
    return told_in_the_past(tokens, k) and not plain


def _in_general(a: _Named, tokens: list[str]) -> bool:
    """Whether road user ``a`` is named as its kind in general: a plural noun that nothing counts or
    sets apart, and not told as doing something then or now ("joggers were running across", "cyclists
    are riding two abreast": those ones, road users of the event)."""
    return (
        _many(a)
        and not _counted(a.det)
        and not _counted(a.named_after)
        and a.named_after not in _APART
        and not (0 <= a.named_end and _told_then_or_now(tokens, a.named_end))
        and not a.group
        and not a.member_named
        and not a.counted
    )


def _one_in_the_scene(a: _Named) -> bool:
    """Whether road user ``a`` is named as one in the scene: in the singular, or counted in a group."""
    return bool(a.word) and (not _many(a) or bool(a.group) or a.member_named or a.counted)


def drop_kinds_in_general(actors: list, reading: Reading, tokens: list[str]) -> list:
    """``actors`` and ``reading``'s road users without the walkers and riders named as their kind in
    general beside one of that kind in the scene (see the module); ``actors`` are what the reader
    gathered of them, in the same order, named in ``tokens``. Obstacles keep pointing at the same road users."""
    specs = reading.actors
    general = [
        k
        for k, (a, s) in enumerate(zip(actors, specs))
        if s.kind in WALKERS_AND_RIDERS
        and _in_general(a, tokens)
        and any(j != k and t.kind == s.kind and _one_in_the_scene(b) for j, (b, t) in enumerate(zip(actors, specs)))
    ]
    if any(s.obstacle in general for s in specs):
        return actors  # (something swerves round it: it is there)
    for k in reversed(general):  # (from the last, so that the others' places hold)
        actors = without_road_user(actors, reading, k)
    return actors
