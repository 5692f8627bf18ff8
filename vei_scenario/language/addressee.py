"""The road user a text is addressed to: "To the jogger on Orchard Rd - you ran across the road".

Open letters, thank-you notes and community posts open by naming whom they speak to ("To the cyclist
in the black jacket this morning, you ...", "To the lady with the pram: thank you for ...", "To the
driver of the white van - you ...") and then tell that road user what they did as "you". Read as
written, "to the jogger" is where something goes and the jogger no subject, so their deeds said with
"you" belong to no one. Without the "to" the address reads as people say it with "Dear": the road user
named first, then what they did ("Dear jogger, you ran across ...").

Only an address opens a text or a sentence, names a road user (not the ego) right after "the", "that"
or "this", and is followed by "you" or "your" in the same sentence or the next: "to the station",
"to the left", "to the lady's surprise" or a "to" anywhere else are left as they are.
"""

from __future__ import annotations

from collections.abc import Callable

#: Marks that end a sentence: an address opens a text or comes right after one.
_SENTENCE_ENDS = frozenset((".", "!", "?", ";"))
#: Determiners that open the road user an address names ("to the jogger", "to that cyclist").
_ADDRESSED = frozenset(("the", "that", "this"))
#: Words that speak to the one addressed.
_YOU = frozenset(("you", "your", "you're", "yourself"))
#: How many words after the address its "you" may come (the address, its description, a sentence).
_REACH = 40


def spoken_to(tokens: list[str], kind_at: Callable[[list[str], int], tuple[str, int] | None]) -> list[str]:
    """``tokens`` without the "to" of each address to a road user that opens a sentence and is then
    spoken to as "you"."""
    out: list[str] = []
    for i, tok in enumerate(tokens):
        if tok == "to" and _opens_an_address(tokens, i, kind_at):
            continue
        out.append(tok)
    return out


def _opens_an_address(tokens: list[str], i: int, kind_at: Callable[[list[str], int], tuple[str, int] | None]) -> bool:
    """Whether "to" at ``i`` opens a sentence, names a road user after a determiner, and the words after
    it (up to the end of the next sentence) speak to someone as "you"."""
    if i and tokens[i - 1] not in _SENTENCE_ENDS:
        return False
    if tokens[i + 1 : i + 2] == [] or tokens[i + 1] not in _ADDRESSED:
        return False
    found = next((kind_at(tokens, j) for j in range(i + 2, min(i + 5, len(tokens))) if kind_at(tokens, j)), None)
    if found is None or found[0] == "ego":
        return False
    ends = 0
    for word in tokens[i + 2 : i + 2 + _REACH]:
        if word in _YOU:
            return True
        ends += word in _SENTENCE_ENDS
        if ends == 2:
            return False
    return False
