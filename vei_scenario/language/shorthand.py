"""Shortened words read as the word of the reader's that they shorten.

People who note a scenario in a hurry shorten the long words ("e-scoot", "oncmg", "rdbt", "intersec").
Two ways of shortening are common and can be told apart from a slip of the keys
(:mod:`vei_scenario.language.spelling`) and from an acronym:

- cutting the word off after its first letters ("e-scoot", "intersec");
- keeping its first letter and then only consonants, in order, up to its last letter ("oncmg",
  "rdbt").

Only nouns of road users and places, and words of where one is, are read so: a shortened verb is
most often its noun ("insufficient decel"), which read as the verb would be a road user's act. A word
is read so only where it is a lower-case word of at least four letters (three letters, and words in
capitals, are too often acronyms or other words: "min", "est", "ACC", "THW"), neither an English word
nor one of the reader's, and where every word it could shorten means the same ("e-scoot" may be
"e-scooter" or "e-scooters", one road user); a shortening of two different things is left as written.
The word it shortens must be at least three letters longer (two, after a compound's first part:
"e-scoot"), so a word one or two letters off is left to the speller. The words read so are reported,
as a slip's correction is.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import lru_cache

from vei_scenario.language.lemmas import english

_VOWELS = frozenset("aeiou")
#: The shortest shortened word read (shorter ones are too often acronyms or other words).
_SHORTEST = 4
#: How many letters a cut word must lose at least (fewer is a slip, for the speller).
_CUT = 3


def _in_order(letters: str, word: str) -> bool:
    """Whether ``letters`` stand in ``word`` in this order (not necessarily together)."""
    rest = iter(word)
    return all(c in rest for c in letters)


def _shortens(short: str, word: str, cut: int = _CUT) -> bool:
    """Whether ``short`` is ``word`` cut off or kept to its first letter and consonants, losing at
    least ``cut`` letters."""
    if len(word) < len(short) + cut:
        return False
    if word.startswith(short):
        return True
    head = short[1:]
    return short[0] == word[0] and short[-1] == word[-1] and not set(head) & _VOWELS and _in_order(head, word[1:])


def _plural(noun: str) -> str:
    """``noun`` in the plural (lemminflect's, or with an "s")."""
    from lemminflect import getInflection

    forms = getInflection(noun.rsplit("-", 1)[-1], tag="NNS")
    return noun.rsplit("-", 1)[0] + "-" + forms[0] if forms and "-" in noun else forms[0] if forms else noun + "s"


class Shorthand:
    """Reads shortened words against ``meanings``: each single word of the reader's phrases that may be
    shortened (its road users, places, sides and behaviours), with what it means."""

    def __init__(self, meanings: Mapping[str, object]):
        self.meanings = {w: repr(m) for w, m in meanings.items() if w.replace("-", "").isalpha()}

    @lru_cache(maxsize=8192)  # noqa: B019 (one reader per process, its words fixed)
    def expand(self, word: str) -> str:
        """``word``, or the one word of the reader's it shortens (the shortest, if several mean the
        same); a plural's "s" kept after it ("e-scoots": "e-scooters")."""
        if english(word) or word in self.meanings:
            return word  # ("passes" is no plural of a shortened "passe")
        found = self._expand(word)
        if found == word and word.endswith("s"):
            one = self._expand(word[:-1])
            return word if one == word[:-1] else _plural(one)
        return found

    def _expand(self, word: str) -> str:
        head, dash, tail = word.rpartition("-")
        if not tail.isalpha() or len(tail) < _SHORTEST or (head and not head.isalpha()) or english(word):
            return word
        if word in self.meanings:
            return word
        cut = _CUT - 1 if head else _CUT  # (a compound's first part already narrows it: "e-scoot")
        found = sorted(
            (w for w in self.meanings if w.startswith(head + dash) and _shortens(tail, w[len(head + dash) :], cut)),
            key=lambda w: (len(w), w),
        )
        if not found or len({self.meanings[w] for w in found}) > 1:
            return word
        return found[0]
