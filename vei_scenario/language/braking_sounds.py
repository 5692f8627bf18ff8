"""The sound of a hard brake told as what happened ("tyres screeched", "with a screech of brakes",
"the van screeched to a halt", "Screeeech."): the noise locked or skidding tyres make is heard only
when someone brakes as hard as they can, so a text that tells it tells an emergency stop, whoever made it.

The sound is a brake's only when it is said of one: a screech or squeal whose subject or "of"-object is
a tyre, brake or wheel ("brakes squealing", "a squeal of tyres"), a screech of a vehicle ("the taxi
screeched"), one that ends in a stop ("screeched to a halt", "stopped with a screech"), or the sound
told alone as a sentence ("Screech!"). Owls, parrots, children and fan belts screech and squeal too; a
vehicle screeching round a bend is cornering, not braking; and brakes that "squeal a bit in the wet" are
a habit of the car, not this event. Sound words are often spelt drawn out ("SKREEEECH"), which no
dictionary knows, so the drawn-out spellings are matched by their shape.
"""

from __future__ import annotations

import re
from functools import lru_cache

from vei_scenario.language import lexicon as L
from vei_scenario.language.lemmas import lemmas

#: What squeals when a vehicle brakes hard.
_BRAKING_PARTS = frozenset(("tyres", "tyre", "tires", "tire", "brakes", "brake", "wheels", "wheel", "rubber"))
#: A screech spelt as it sounds, its vowel drawn out ("screeeech", "skreeeeech", "scrEEEch" lowercased).
_DRAWN_OUT_SCREECH = re.compile(r"s[ck]r+e{2,}ch(ed|es|ing)?")
_DRAWN_OUT_SQUEAL = re.compile(r"squea+l(ed|s|ing)?")
#: Verbs (lemmas) of coming to a stop, and the nouns of the stop a screech ends in ("screeched to a halt").
_STOPPING = frozenset(("stop", "halt", "brake", "pull"))
_STOP_NOUNS = frozenset(("halt", "stop", "standstill"))
#: What a screech round a bend is said with: a path of motion, cornering rather than braking.
_ROUND = frozenset(("round", "around"))
_BENDS = frozenset(("bend", "bends", "corner", "corners", "curve", "curves"))
#: Words that tell a habit of a present-tense sound ("squeal a bit in the wet", "whenever it rains").
#: (Said here, not taken from the reader's lists, which import the outcome reader that imports this.)
_HABITUAL = frozenset(("always", "usually", "normally", "often", "sometimes", "whenever", "every", "bit"))


def _a_stop_verb(word: str) -> bool:
    """Whether ``word`` is a verb of coming to a stop ("stopped", "halted", "braking", "pulled")."""
    return bool(_STOPPING & set(lemmas(word).get("VERB", ())))


def _lemma_of(word: str, lemma: str, drawn_out: re.Pattern[str]) -> bool:
    """Whether ``word`` is a form of ``lemma`` or its drawn-out spelling."""
    return any(lemma in forms for forms in lemmas(word).values()) or drawn_out.fullmatch(word) is not None


@lru_cache(maxsize=1)
def _vehicle_heads() -> frozenset[str]:
    """The last words of the lexicon's nouns of a vehicle ("taxi", "van", "lorry", "motorbike")."""
    phrases = list(L.CAR_NOUNS) + [p for kind, ps in L.ACTOR_NOUNS.items() if kind != "pedestrian" for p in ps]
    return frozenset(p.split()[-1] for p in phrases) - {"rider", "driver", "cyclist", "motorcyclist"}


def _vehicle(word: str) -> bool:
    return word in _vehicle_heads() or bool(set(lemmas(word).get("NOUN", ())) & _vehicle_heads())


def _said_of(words: list[str], i: int, by_a_vehicle: bool) -> bool:
    """Whether the sound at ``i`` has a braking part (or, if ``by_a_vehicle``, a vehicle) for its
    subject right before it ("the tyres screeched", "brakes squealing") or its "of"-object ("a screech
    of brakes")."""

    def of_a_brake(w: str) -> bool:
        return w in _BRAKING_PARTS or (by_a_vehicle and _vehicle(w))

    k = i - 1
    while k >= 0 and words[k].endswith("ly"):
        k -= 1
    if k >= 0 and of_a_brake(words[k]):
        return True
    return words[i + 1 : i + 2] == ["of"] and any(of_a_brake(w) for w in words[i + 2 : i + 5])


def _ends_in_a_stop(words: list[str], i: int) -> bool:
    """Whether the sound at ``i`` is the manner of a stop: "screeched to a halt", "stopped with a screech"."""
    if words[i + 1 : i + 2] == ["to"] and set(words[i + 2 : i + 5]) & _STOP_NOUNS:
        return True
    before = words[max(0, i - 5) : i]
    return "with" in before and any(_a_stop_verb(w) for w in before)


def _cornering(words: list[str], i: int) -> bool:
    """Whether the sound at ``i`` is said with a path round a bend ("screeched round the curve", "as I
    took the bend"): tyres cornering, with no stop said."""
    after = words[i + 1 :]
    if after[:1] and after[0] in _ROUND:
        return True
    stopped = any(_a_stop_verb(w) for w in words)
    return bool(_BENDS & set(after)) and not stopped


def _habit(words: list[str], i: int) -> bool:
    """Whether the sound at ``i`` is a present-tense verb said with a word of habit ("my brakes squeal
    a bit in the wet", "they always screech"): how the car is, not what happened."""
    w = words[i]
    present = not w.endswith(("ed", "ing")) and "VERB" in lemmas(w)
    return present and bool(_HABITUAL & set(words[max(0, i - 2) : i + 4]))


def braking_sound(words: list[str], i: int) -> bool:
    """Whether ``words[i]`` tells the sound of a hard brake: a screech or squeal said of a tyre, brake
    or wheel, a screech said of a vehicle or ending in a stop, or the sound alone as its sentence, and
    not a cornering screech nor a habit of the car."""
    w = words[i]
    screech = _lemma_of(w, "screech", _DRAWN_OUT_SCREECH)
    if not screech and not _lemma_of(w, "squeal", _DRAWN_OUT_SQUEAL):
        return False
    if len(words) == 1:
        return True  # ("Screeeech.", "Screech!": the sound told alone)
    if _cornering(words, i) or _habit(words, i):
        return False
    return _said_of(words, i, by_a_vehicle=screech) or _ends_in_a_stop(words, i)
