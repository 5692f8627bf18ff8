"""What "you" have to, must or should do: a rule of the road, not what anyone did.

Writers end a story with the rule they think was broken: "footpath riding's legal here now but mate,
you still have to give way", "you must stop at a zebra", "you should always look before pulling
out". The generic "you" with a verb of obligation in the present says what anyone ought to do; read
as a clause of the story, its verb becomes one more behaviour of the road user told of last (the
rider "gives way" after riding across the ego's path).

The clause is told by "you", a few adverbs, then "have to", "has to", "must", "should", "need to",
"ought to" or "('ve) got to" and a verb; it runs to the end of its sentence or the next comma or
"but". Not a past or perfect ("you should have looked", "you had to brake": told of the past, which
other rules read), and not a question ("do you have to ...?": its sentence ends with "?").
"""

from __future__ import annotations

#: Adverbs that may stand between "you" and the obligation ("you still have to", "you really must").
_BETWEEN = frozenset(("still", "just", "always", "really", "also", "then", "simply", "absolutely", "all"))
#: The obligations, as the words that follow "you" (and the adverbs).
_OBLIGED = (("have", "to"), ("has", "to"), ("must",), ("should",), ("need", "to"), ("ought", "to"), ("got", "to"),
            ("have", "got", "to"))  # fmt: skip
#: Where the rule's clause ends.
_ENDS = frozenset((".", "!", ";", ",", "but", "?"))


def _obligation_at(tokens: list[str], k: int) -> int:
    """The length of an obligation at ``tokens[k]`` followed by a plain verb, or 0 (none, or a
    perfect: "should have looked")."""
    for words in _OBLIGED:
        n = len(words)
        if tuple(tokens[k : k + n]) == words and tokens[k + n : k + n + 1] not in ([], ["have"], ["be"]):
            return n
    return 0


def _question(tokens: list[str], end: int) -> bool:
    """Whether the sentence running to ``end`` is a question."""
    while end < len(tokens) and tokens[end] not in (".", "!", "?"):
        end += 1
    return tokens[end : end + 1] == ["?"]


def without_norms(tokens: list[str], dropped: list[str]) -> list[str]:
    """``tokens`` without the clauses of what "you" have to, must or should do (see the module's
    docstring); the words taken out are added to ``dropped``, so the run says it did not use them."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        if tokens[i] == "you":
            k = i + 1
            while k < len(tokens) and tokens[k] in _BETWEEN:
                k += 1
            n = _obligation_at(tokens, k)
            if n:
                end = k + n
                while end < len(tokens) and tokens[end] not in _ENDS:
                    end += 1
                if not _question(tokens, end):
                    dropped.extend(w for w in tokens[i:end] if w.isalpha())
                    i = end
                    continue
        out.append(tokens[i])
        i += 1
    return out
