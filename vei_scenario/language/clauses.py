"""Cutting a token list into clauses. The readers of the outcome, the manner and the ego's turn each
read within a clause (a negation's scope, a degree word's, a turn's subject), and each cuts at its own
words: what ends a clause for one is part of a clause for another ("as" opens a clause of time for the
turn, and is a comparison for the outcome), so the cut words are theirs and the cutting is here."""

from __future__ import annotations

from collections.abc import Iterable

#: What ends a sentence, and so a clause for every reader.
SENTENCE_END = frozenset(".;!?:")


def sentence_start(tokens: list[str], i: int, ends: frozenset[str] = SENTENCE_END) -> int:
    """The index of the first token of the sentence that holds token ``i`` (after the last of ``ends``
    before it, or 0)."""
    while i > 0 and tokens[i - 1] not in ends:
        i -= 1
    return i


def sentence_stop(tokens: list[str], i: int, ends: frozenset[str] = SENTENCE_END) -> int:
    """The index just past the last token of the sentence that holds token ``i`` (the first of ``ends``
    from ``i`` on, or the end of ``tokens``): with :func:`sentence_start`, the sentence's span."""
    while i < len(tokens) and tokens[i] not in ends:
        i += 1
    return i


def split(tokens: Iterable[str], breaks: frozenset[str]) -> list[tuple[list[str], bool]]:
    """The non-empty clauses of ``tokens`` cut at each of ``breaks`` (punctuation or conjunctions, left
    out of the clauses), each with whether it opens its sentence (nothing but breaks before it since
    the text began or a sentence ended)."""
    out: list[tuple[list[str], bool]] = []
    current: list[str] = []
    first = True
    for tok in tokens:
        if tok in breaks and not (tok == "so" and current[-1:] == ["or"]):  # ("a metre or so": no clause)
            if current:
                out.append((current, first))
            first = tok in SENTENCE_END or (first and not current)
            current = []
            continue
        current.append(tok)
    if current:
        out.append((current, first))
    return out
