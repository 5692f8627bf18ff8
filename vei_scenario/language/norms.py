"""What "you" have to, must or should do: a rule of the road, not what anyone did.

Writers end a story with the rule they think was broken: "footpath riding's legal here now but mate,
you still have to give way", "you must stop at a zebra", "you should always look before pulling
out". The generic "you" with a verb of obligation in the present says what anyone ought to do; read
as a clause of the story, its verb becomes one more behaviour of the road user told of last (the
rider "gives way" after riding across the ego's path).

The clause is told by "you", a few adverbs, then "have to", "has to", "must", "should", "need to",
"ought to" or "('ve) got to" and a verb; it runs to the next mark or the word that opens the next
clause ("and", "because", "so", "when" ...). Not a past or perfect ("you should have looked", "you
had to brake": told of the past, which other rules read), not a question ("do you have to ...?"),
not a verb of taking what is told ("you have to understand the lorry pulled out") or of a driver's
reaction ("suddenly you have to slam on": the writer's, told as anyone's), and not in a text
told to "you" or in the second person ("you're driving down the high street and suddenly you have to
slam on", "You are the ego vehicle. You have to turn left"), where what "you" have to do is the ego's.
"""

from __future__ import annotations

#: Adverbs that may stand between "you" and the obligation ("you still have to", "you really must").
_BETWEEN = frozenset(("still", "just", "always", "really", "also", "then", "simply", "absolutely", "all"))
#: The obligations, as the words that follow "you" (and the adverbs).
_OBLIGED = (("have", "to"), ("has", "to"), ("must",), ("should",), ("need", "to"), ("ought", "to"), ("got", "to"),
            ("have", "got", "to"))  # fmt: skip
#: Where the rule's clause ends: a mark, or a word that opens the next clause ("you have to stop and a
#: van came round the corner", "you have to brake because a tractor is turning").
_ENDS = frozenset((".", "!", ";", ",", "?", "but", "and", "because", "so", "when", "as", "while", "then", "until"))
#: Verbs after the obligation that say how to take what is told, not a rule of the road ("you have to
#: understand the lorry pulled out").
_TOLD = frozenset(("understand", "remember", "admit", "realise", "realize", "appreciate", "know", "believe", "see",
                   "bear", "accept", "agree", "imagine", "picture", "say", "laugh", "wonder", "ask", "love",
                   # a driver's reaction told in the second person ("suddenly you have to slam on"):
                   "brake", "slam", "swerve", "steer", "stamp", "jam", "hit", "dodge", "slow"))  # fmt: skip


def _obligation_at(tokens: list[str], k: int) -> int:
    """The length of an obligation at ``tokens[k]`` followed by a plain verb, or 0 (none, or a
    perfect: "should have looked")."""
    for words in _OBLIGED:
        n = len(words)
        verb = tokens[k + n : k + n + 1]
        if tuple(tokens[k : k + n]) == words and verb not in ([], ["have"], ["be"]) and verb[0] not in _TOLD:
            return n
    return 0


#: "You" contracted with a verb, as written: the subject of something other than an obligation.
_YOU_DOING = frozenset(("you're", "you've", "you'll", "you'd", "youre", "youve"))


def _told_to_you(tokens: list[str]) -> bool:
    """Whether "you" is also the subject of something other than an obligation: a text told in the
    second person ("so you're driving down the high street and suddenly you have to slam on") or
    to the ego ("You are the ego vehicle. You have to turn left"), whose obligations are its acts."""
    for i, w in enumerate(tokens):
        if w in _YOU_DOING:
            return True
        if w != "you":
            continue
        k = i + 1
        while k < len(tokens) and tokens[k] in _BETWEEN:
            k += 1
        if k < len(tokens) and tokens[k].isalpha() and not _obligation_at(tokens, k) and tokens[k] not in _AFTER_OBJECT:
            return True
    return False


#: Words after "you" that show it is an object, not a subject ("thank you.", "I'll show you where").
_AFTER_OBJECT = frozenset(("know", "see", "guys", "all", "lot", "very", "too", "for", "to", "that", "if", "where",
                           "what", "how", "mate"))  # fmt: skip


def _question(tokens: list[str], end: int) -> bool:
    """Whether the sentence running to ``end`` is a question."""
    while end < len(tokens) and tokens[end] not in (".", "!", "?"):
        end += 1
    return tokens[end : end + 1] == ["?"]


def without_norms(tokens: list[str], dropped: list[str], said: list[str] | None = None) -> list[str]:
    """``tokens`` without the clauses of what "you" have to, must or should do (see the module's
    docstring); the words taken out are added to ``dropped``, so the run says it did not use them.
    ``said``: the text's words as written (lowercased), where "you" is looked for as a subject; the
    tokens where it is not given."""
    if _told_to_you(tokens if said is None else said):
        return tokens
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
