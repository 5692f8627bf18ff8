"""What is scenery, not a road user: a vehicle said to stand, and vehicles named only as the place
someone comes out from.

The format lists the road users that act on the road; a vehicle that stands and does nothing is
scenery (the scenario may hold it, parked, as an occluder). Two pieces of noun-phrase grammar say so,
and the reader asks them here:

- **A state word is said of its noun, past the modifiers between them.** "a stationary foam target
  car", "a parked white van", "a stopped grey lorry": the state word heads a noun phrase whose noun
  may come a few plain modifiers later (colours, makes, materials the reader has no word for). Only
  words that are neither function words nor verbs may stand between, so "stopped, and a car ..."
  or "parked to let a car by" keep the state away from the noun.
- **The object of "between" / "among" is a place, however it is counted.** "out from between two
  vans", "between three lorries", "between two of the cars": a count or a partitive does not make
  the vehicles road users; the one who comes out is the road user, the vehicles are where it was.
"""

from __future__ import annotations

from collections.abc import Callable

from vei_scenario.language.lemmas import lemmas

#: At most this many modifiers between a state word and its noun ("a stationary foam target car").
_MODIFIERS = 3
#: Prepositions whose object is where someone was, among several of them.
_AMID = frozenset(("between", "among", "amongst"))
#: Words of a counted noun phrase between such a preposition and its noun ("between two of the parked").
_COUNTED_PHRASE = frozenset(
    "two three four five six several a couple pair few some of the these those our parked stationary stopped".split()
)


def plain_modifiers(tokens: list[str], start: int, end: int, function_word: Callable[[str], bool]) -> bool:
    """Whether ``tokens[start:end]`` may stand between a state word and the noun it is said of: at
    most a few words, each a plain word (no number, no punctuation), none a function word, none a
    word that can only be a verb ("a parked white van", not "parked to let"; "stationary, and")."""
    words = tokens[start:end]
    if len(words) > _MODIFIERS:
        return False
    for w in words:
        if not w.replace("-", "").isalpha() or function_word(w):
            return False
        pos = set(lemmas(w))
        if pos and not pos & {"NOUN", "ADJ", "PROPN"}:
            return False
    return True


def among_them(tokens: list[str], start: int) -> bool:
    """Whether the vehicle noun at ``start`` is the object of "between" or "among", past a count or a
    partitive and its state ("between two vans", "between two of the parked cars"): where someone
    comes out from, not a road user of the scene."""
    j = start - 1
    while j >= 0 and start - j <= 5 and tokens[j] in _COUNTED_PHRASE:
        j -= 1
    return j >= 0 and tokens[j] in _AMID
