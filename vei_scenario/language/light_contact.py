"""Two edges of what a verb or a noun of contact says.

* **A light knock felt or heard.** "I felt the tap", "heard a soft clunk from the bumper", "felt a
  small knock on the front": a knock too light to be called a crash is still told as contact when
  it is what the narrator felt or heard, the object of a verb of perception. Elsewhere these nouns
  are something else ("gave the brakes a tap", "a knock-on effect"), so the perception is what makes
  them a contact, as "a thud" or "a crunch" needs none. Where it landed or came from (:data:`LOCATING`)
  the outcome reader weighs: on a body part, a window or the engine it is no contact.
* **A marking painted on the road.** "its wheel touched the white line", "clipped the centre line
  with its trailer": the head of the object of a verb of contact is a marking, paint on the road, and
  nothing is met. (A kerb or a bollard is met, and stays a contact for the outcome reader, as does
  "the line of cars": what a line is of is the object.)
"""

from __future__ import annotations

from vei_scenario.language.function_words import ARTICLES, CLAUSE_BREAKS, DETERMINERS, PHRASE_ENDS
from vei_scenario.language.lemmas import lemmas

#: Nouns of a knock too light for a crash: contact only when felt or heard.
_LIGHT_KNOCKS = frozenset(("tap", "knock", "clunk", "clonk", "nudge"))
#: Prepositions that say where a knock landed or what it came from ("on the front", "from the engine").
LOCATING = frozenset(("on", "from", "at", "against", "in"))
#: Verbs (lemmas) of perceiving a knock by touch or ear.
_PERCEIVING = frozenset(("feel", "hear"))
#: The heads of noun phrases that name a marking painted on the road.
MARKINGS = frozenset(
    ("line", "lines", "marking", "markings", "centre-line", "centreline", "center-line", "centerline", "stripe",
     "stripes", "hatching", "chevrons")
)  # fmt: skip


def _is_verb_of(word: str, verbs: frozenset[str]) -> bool:
    return bool(set(lemmas(word).get("VERB", ())) & verbs)


def knock_felt(words: list[str], i: int) -> bool:
    """Whether the noun at ``i`` is a light knock (:data:`_LIGHT_KNOCKS`) that heads the object of a
    verb of perception: "felt the tap", "heard a soft clunk", "felt a small knock on the front". Only
    adjectives stand between the determiner and the knock ("a small knock"; not "felt a tap of the
    brakes" read as anything but the knock, whose "of" the caller's clause keeps)."""
    if words[i] not in _LIGHT_KNOCKS:
        return False
    k = i - 1
    while k >= 0 and words[k] not in ARTICLES:
        if "ADJ" not in lemmas(words[k]) or "VERB" in lemmas(words[k]):
            return False  # (only adjectives between: "a small knock", "the tap")
        k -= 1
    if k < 1 or i - k > 3:
        return False
    if words[i + 1 : i + 2] == ["of"]:
        return False  # ("felt the tap of the brakes", "heard the bang of a door": whose it was)
    return _is_verb_of(words[k - 1], _PERCEIVING)


def _ends_phrase(w: str) -> bool:
    """Whether ``w`` ends a noun phrase after its head: a preposition, a conjunction, a relative word
    or an adverb of the verb ("the white line briefly", "the line again")."""
    return w in PHRASE_ENDS or w in CLAUSE_BREAKS or w == "into" or set(lemmas(w)) == {"ADV"}


def _object_head(words: list[str], i: int) -> str | None:
    """The head of the object of the verb at ``i``: past its determiner, the last word of the noun
    phrase before a preposition, a conjunction or the clause's end ("the white line", "the centre line
    with its trailer"). A head with "of" after it names a group or a part of what follows, which is
    then the thing met ("the line of cars": the cars; "the edge of the white line": the line)."""
    after = words[i + 1 : i + 9]
    if not after or after[0] not in DETERMINERS:
        return None
    head = None
    for k, w in enumerate(after[1:], 1):
        if w == "of":
            head = None  # (what it is of is the object: "the line of parked cars")
            continue
        if _ends_phrase(w):
            break
        if not (w in DETERMINERS and after[k - 1] == "of"):
            head = w
    return head


def marking_met(words: list[str], i: int) -> bool:
    """Whether the verb of contact at ``i`` has a marking painted on the road as its object ("touched
    the white line", "clipped the lane markings"): paint, not a road user or a thing met."""
    return _object_head(words, i) in MARKINGS
