"""A speaker's comment clause before the clause it judges: "I reckon he was doing 90", "which I'd guess was 40".

Why: English lets a speaker put their own stance in front of a clause ("I think", "I reckon", "I'd
say", "we believe"), or inside a relative clause between its pronoun and its verb ("the van, which I
would estimate was travelling at 40 mph"). The first person there is the one who judges, not the one
who goes: the speed belongs to the subject of the clause judged. Read with it, the narrator, who is
the ego, is the nearest subject before the speed and takes it. Left out, the clause judged reads as
if said plainly ("he was doing 90", "which was travelling at 40 mph"); where its subject is the
narrator ("I think I was doing 40"), nothing changes. A comment said between a verb and its number
("doing, I reckon, 40") is :func:`vei_scenario.language.quantities.without_guesses`' to leave out.
"""

from __future__ import annotations

from vei_scenario.language.discourse import DETERMINERS, PRONOUNS
from vei_scenario.language.quantities import OPINION_AUXILIARIES, OPINION_VERBS, is_number

#: The first person who comments ("I reckon", "we believe").
_COMMENTERS = frozenset({"i", "we"})
#: Finite verbs that open the clause judged right after the comment where its subject stands before the
#: comment ("which I reckon was doing 40", "a bus I'd say was doing 50"), or that follow its subject.
_FINITE = frozenset(
    {"was", "were", "is", "are", "had", "has", "must", "would", "could", "might", "'d", "'s", "did"}
)  # fmt: skip
#: Words that open a subject of the clause judged: a pronoun or a determiner of a noun phrase.
_SUBJECT_OPENERS = DETERMINERS | PRONOUNS | {"you"}
#: How many words a subject opened so may run to before its finite verb ("the white transit van was").
_SUBJECT_REACH = 5
#: Words that end the clause judged: its speed must come before one.
_CLAUSE_ENDS = frozenset({".", ";", "!", "?", ":"})
#: How far after the comment the speed of the clause judged may stand.
_SPEED_REACH = 12


def _comment_end(tokens: list[str], k: int) -> int:
    """The index after a comment clause opening at ``k`` ("I reckon", "we would estimate", "I 'd say",
    "I think that"), or ``k`` where none opens there."""
    if tokens[k] not in _COMMENTERS:
        return k
    j = k + 1
    while j < len(tokens) and tokens[j] in OPINION_AUXILIARIES:
        j += 1
    if j >= len(tokens) or tokens[j] not in OPINION_VERBS:
        return k
    j += 1
    return j + (j < len(tokens) and tokens[j] == "that")


def _opens_a_clause(tokens: list[str], j: int) -> bool:
    """Whether a clause with a finite verb opens at ``j``: the verb itself (its subject said before the
    comment) or a subject a few words long and then the verb ("he was", "the lorry was")."""
    if j >= len(tokens):
        return False
    if tokens[j] in _FINITE:
        return True
    if tokens[j] not in _SUBJECT_OPENERS:
        return False
    for n in range(j + 1, min(j + 1 + _SUBJECT_REACH, len(tokens))):
        if tokens[n] in _FINITE:
            return True
        if tokens[n] in _CLAUSE_ENDS or tokens[n] == ",":
            return False
    return False


def _says_a_number(tokens: list[str], j: int) -> bool:
    """Whether a number stands in the clause from ``j`` on, before its sentence ends."""
    for n in range(j, min(j + _SPEED_REACH, len(tokens))):
        if tokens[n] in _CLAUSE_ENDS:
            return False
        if is_number(tokens[n]):
            return True
    return False


def without_comment_clauses(tokens: list[str]) -> list[str]:
    """``tokens`` with each first-person comment clause left out where it stands before a clause of its
    own that says a number ("I reckon he was doing 90 km/h": "he was doing 90 km/h"; "which I would guess
    was doing 40": "which was doing 40"). See the module's docstring."""
    out: list[str] = []
    k = 0
    while k < len(tokens):
        end = _comment_end(tokens, k)
        if end > k and _opens_a_clause(tokens, end) and _says_a_number(tokens, end):
            k = end
            continue
        out.append(tokens[k])
        k += 1
    return out
