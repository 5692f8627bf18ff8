"""A mention made at one word of the text, in the likeness of another (its road user's).

Why: several passes (a crossing said by "across", a run of "the red", a cut-in said by "into my
lane") add a behaviour or verb the lexicon had no entry for at the word that says it; the mention
must carry that word's place and neighbours, and nothing of the mention it copies but its type, so
that later passes read it as if the lexicon had found it there.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TypeVar

M = TypeVar("M")


def word_mention(like: M, tokens: list[str], j: int, slot: str, value: object, words: str | None = None) -> M:
    """A mention of ``slot``/``value`` standing at ``tokens[j]`` (its words ``words``, or that token),
    made from ``like`` (a reader mention: the road user or verb it belongs to) with no determiner and
    no owners of its own."""
    return replace(
        like,  # type: ignore[type-var]
        slot=slot,
        value=value,
        words=tokens[j] if words is None else words,
        start=j,
        end=j + 1,
        prev=tokens[j - 1] if j else "",
        next_=tokens[j + 1] if j + 1 < len(tokens) else "",
        det="",
        owners=(),
    )
