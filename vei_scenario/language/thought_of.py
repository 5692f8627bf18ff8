"""A contact only thought of: "a crash at that speed does not bear thinking about", "a collision
there is unthinkable". The noun of contact is the subject of a thought that is denied or said to be
impossible, so the contact is imagined, not told: what was dreaded did not happen, and the scene was
a close call, not a collision.
"""

from __future__ import annotations

from vei_scenario.language.lemmas import lemmas

#: Verbs (lemmas) of thinking of something.
_THINKING = frozenset(("think", "imagine", "contemplate", "consider"))
#: Adjectives that say a thing cannot be thought of.
_UNTHINKABLE = frozenset(("unthinkable", "unimaginable", "inconceivable"))
#: Words that deny the thought ("does not bear thinking about", "I dare not think of it").
_DENIALS = frozenset(("not", "never", "cannot", "no"))
#: What a thought stands after when it is the thought of something, not an opinion: "bear thinking
#: about", "dare to imagine", "want to think about" ("I don't think he saw me" is an opinion).
_THOUGHT_AFTER = frozenset(("bear", "bears", "to", "dare"))


def _thinking(word: str) -> bool:
    return any(_THINKING & set(forms) for forms in lemmas(word).values())


def only_thought_of(words: list[str], i: int) -> bool:
    """Whether the noun of contact at ``i`` is the subject of a thought its clause denies or calls
    impossible: a verb of thinking after it, itself after "bear", "dare" or "to", with a denial
    between, or an adjective of the unthinkable."""
    after = words[i + 1 :]
    for k, w in enumerate(after):
        if w in _UNTHINKABLE:
            return True
        if k > 0 and after[k - 1] in _THOUGHT_AFTER and _thinking(w) and _DENIALS & set(after[:k]):
            return True
    return False
