"""A negation whose verb is left out: "the truck behind does not → we get rear-ended", "I stopped,
he did not". An auxiliary "do" with "not" and no verb after it stands for the verb said before
("does not [stop in time]"); what follows belongs to another clause even where the writer put no
punctuation between them, so the negation denies nothing that follows it.

A time adverbial may stand between "not" and its verb ("does not this time hit", "did not that
morning stop"): a determiner there opens a time, not a new subject, and the verb after it is denied.
"""

from __future__ import annotations

from vei_scenario.language import lexicon as L
from vei_scenario.language.function_words import ARTICLES, DEFINITE, POSSESSIVE, SUBJECT_PRONOUNS

#: The forms of "do" that carry a negation.
_DO = frozenset(("do", "does", "did"))
#: Words that open a noun phrase or are a subject: no verb follows "not" when one of these does.
_PHRASE_OPENERS = ARTICLES | DEFINITE | POSSESSIVE | SUBJECT_PRONOUNS | {"this", "ego"}
#: The nouns of a time a determiner opens between "not" and its verb ("this time", "that morning",
#: "the first time"): the lexicon's one-word times of day, and the plain units of an occasion.
_TIME_HEADS = frozenset(
    {name for names in L.TIMES.values() for name in names if name.isalpha()} | {"time", "day", "week", "once"}
)
#: Ordinals between such a determiner and its time ("the first time", "that last morning").
_ORDINALS = frozenset(("first", "second", "third", "last", "next", "one"))


def _a_time(words: list[str], k: int) -> bool:
    """Whether a time adverbial opens at ``k`` ("this time", "that morning", "the first time")."""
    if words[k] not in ("this", "that", "the"):
        return False
    j = k + 1
    while j < len(words) and words[j] in _ORDINALS:
        j += 1
    return j < len(words) and words[j] in _TIME_HEADS


def elliptical_negation(words: list[str], k: int) -> bool:
    """Whether the negator at ``k`` is "do not" with its verb left out: a form of "do" before it and
    the start of a noun phrase or a subject right after it, not of a time adverbial."""
    return (
        words[k] == "not"
        and k > 0
        and words[k - 1] in _DO
        and k + 1 < len(words)
        and words[k + 1] in _PHRASE_OPENERS
        and not _a_time(words, k + 1)
    )
