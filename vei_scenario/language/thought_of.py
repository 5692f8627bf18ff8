"""A contact only thought of: "a crash at that speed does not bear thinking about", "a collision
there is unthinkable". The noun of contact is the subject of a thought that is denied or said to be
impossible, so the contact is imagined, not told: what was dreaded did not happen, and the scene was
a close call, not a collision.

Only the noun's own predicate says so: "bear" with a gerund of thinking and the noun its subject, or
an adjective of the unthinkable after a copula. A thought someone else has of a contact ("my collision
... is something I cannot bear to think about", "the crash was so sudden I had no time to think") and
an adjective said of another noun ("left him with an inconceivable injury") leave it told.
"""

from __future__ import annotations

from vei_scenario.language.function_words import SUBJECT_PRONOUNS
from vei_scenario.language.lemmas import lemmas

#: Verbs (lemmas) of thinking of something.
_THINKING = frozenset(("think", "imagine", "contemplate", "consider"))
#: Adjectives that say a thing cannot be thought of.
_UNTHINKABLE = frozenset(("unthinkable", "unimaginable", "inconceivable"))
#: Words that deny the thought ("does not bear thinking about").
_DENIALS = frozenset(("not", "never", "cannot", "no"))
#: The verb a denied thought of its subject stands after, as a gerund: "does not bear thinking about".
_BEAR = frozenset(("bear", "bears"))
#: The copulas an adjective of the unthinkable is said after ("is unthinkable", "would have been").
_COPULAS = frozenset(("is", "was", "are", "were", "be", "been", "seems", "seemed"))


def _thinking(word: str) -> bool:
    return any(_THINKING & set(forms) for forms in lemmas(word).values())


def only_thought_of(words: list[str], i: int) -> bool:
    """Whether the noun of contact at ``i`` is the subject of a thought its clause denies or calls
    impossible: "bear" and a gerund of thinking after it with a denial between ("does not bear
    thinking about"), or a copula and an adjective of the unthinkable ("is unthinkable"), with no
    other subject between (a pronoun: someone else's thought of it)."""
    after = words[i + 1 :]
    for k, w in enumerate(after):
        if w in SUBJECT_PRONOUNS:
            return False  # ("... is something I cannot bear to think about": another thinks of it)
        if w in _UNTHINKABLE:
            j = k - 1
            while j >= 0 and (after[j].endswith("ly") or after[j] in ("so", "quite")):
                j -= 1
            return j >= 0 and after[j] in _COPULAS  # ("is unthinkable", "would have been simply unimaginable")
        if k > 0 and after[k - 1] in _BEAR and w.endswith("ing") and _thinking(w) and _DENIALS & set(after[:k]):
            return True
    return False
