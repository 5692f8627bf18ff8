"""Two edges of what a verb or a noun of contact says.

* **A light knock felt or heard.** "I felt the tap", "heard a soft clunk from the bumper", "felt a
  small knock on the front": a knock too light to be called a crash is still told as contact when
  it is what the narrator felt or heard, the object of a verb of perception. Elsewhere these nouns
  are something else ("gave the brakes a tap", "a knock-on effect"), so the perception is what makes
  them a contact, as "a thud" or "a crunch" needs none.
* **A marking painted on the road.** "its wheel touched the white line", "clipped the centre line
  with its trailer": the head of the object of a verb of contact is a marking, paint on the road, and
  nothing is met. (A kerb or a bollard is met, and stays a contact for the outcome reader.)
"""

from __future__ import annotations

from vei_scenario.language.lemmas import lemmas

#: Nouns of a knock too light for a crash: contact only when felt or heard.
_LIGHT_KNOCKS = frozenset(("tap", "knock", "clunk", "clonk", "nudge"))
#: The articles and the determiners that open a noun phrase. (Said here: the reader's lists live in
#: modules that import the outcome reader, which imports this.)
_ARTICLES = frozenset(("a", "an", "the"))
_DETERMINERS = _ARTICLES | frozenset(
    ("some", "another", "one", "this", "that", "these", "those", "my", "our", "his", "her", "their", "its", "your")
)
#: Verbs (lemmas) of perceiving a knock by touch or ear.
_PERCEIVING = frozenset(("feel", "hear"))
#: The heads of noun phrases that name a marking painted on the road.
MARKINGS = frozenset(
    ("line", "lines", "marking", "markings", "centre-line", "centreline", "center-line", "centerline", "stripe",
     "stripes", "hatching", "chevrons")
)  # fmt: skip
#: Words that end a noun phrase: prepositions, conjunctions and relative words after its head.
_PHRASE_ENDS = frozenset(
    ("with", "and", "as", "then", "but", "of", "on", "in", "at", "into", "to", "from", "while", "which", "that",
     "before", "after", "so", "for", "by", "again", "briefly", "slightly")
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
    while k >= 0 and words[k] not in _ARTICLES:
        if "ADJ" not in lemmas(words[k]) or "VERB" in lemmas(words[k]):
            return False  # (only adjectives between: "a small knock", "the tap")
        k -= 1
    if k < 1 or i - k > 3:
        return False
    if words[i + 1 : i + 2] == ["of"]:
        return False  # ("felt the tap of the brakes", "heard the bang of a door": whose it was)
    return _is_verb_of(words[k - 1], _PERCEIVING)


def _object_head(words: list[str], i: int) -> str | None:
    """The head of the object of the verb at ``i``: past its determiner, the last word of the noun
    phrase before a preposition, a conjunction or the clause's end ("the white line", "the centre line
    with its trailer")."""
    after = words[i + 1 : i + 7]
    if not after or after[0] not in _DETERMINERS:
        return None
    head = None
    for w in after[1:]:
        if w in _PHRASE_ENDS:
            break
        head = w
    return head


def marking_met(words: list[str], i: int) -> bool:
    """Whether the verb of contact at ``i`` has a marking painted on the road as its object ("touched
    the white line", "clipped the lane markings"): paint, not a road user or a thing met."""
    return _object_head(words, i) in MARKINGS
