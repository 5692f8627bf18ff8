"""A speaker's comment clause before the clause it judges: "I reckon he was doing 90", "which I'd guess was 40".

Why: English lets a speaker put their own stance in front of a clause ("I think", "I reckon", "I'd
say", "we believe"), or inside a relative clause between its pronoun and its verb ("the van, which I
would estimate was travelling at 40 mph"). The first person there is the one who judges, not the one
who goes: the speed belongs to the subject of the clause judged. Read with it, the narrator, who is
the ego, is the nearest subject before the speed and takes it. Left out, the clause judged reads as
if said plainly ("he was doing 90", "which was travelling at 40 mph"); where its subject is the
narrator ("I think I was doing 40"), nothing changes. A comment said between a verb and its number
("doing, I reckon, 40") is :func:`vei_scenario.language.quantities.without_guesses`' to leave out.

A comment said right next to a quantity, with no clause of its own ("came from the right, very fast,
I would say 25 km/h"; "passed at 70 km/h I'd say."), judges the quantity of the clause it stands in,
whose subject said it first: left in, its "I" is the nearest subject and the ego takes the number.
"""

from __future__ import annotations

from vei_scenario.language.discourse import DETERMINERS, PRONOUNS
from vei_scenario.language.quantities import APPROXIMATORS, BOUNDS, OPINION_AUXILIARIES, OPINION_VERBS, is_number
from vei_scenario.language.vocabulary import SPEED_UNITS

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


#: Words between a comment and the number it judges ("I'd say about 25", "I reckon at least 70").
_HEDGES = APPROXIMATORS | BOUNDS | {"about", "around", "roughly", "approximately", "approx", "ca", "at", "a"}
#: Units whose number a comment beside it may judge: speeds (a bare number after it is a speed too).
_UNITS = frozenset(SPEED_UNITS)
#: Words that end the phrase a quantity or a comment stands in.
_PHRASE_ENDS = _CLAUSE_ENDS | {",", "and", "but", "then", "or", ")", "-"}


def _quantity_at(tokens: list[str], j: int) -> int:
    """The index after a quantity said from ``j`` on past its hedges ("about 25 km/h", "at least 70 mph",
    "30,"), or ``j`` where none is: a number then a unit or the end of its phrase."""
    n = j
    while n < len(tokens) and tokens[n] in _HEDGES:
        n += 1
    if n >= len(tokens) or not is_number(tokens[n]):
        return j
    n += 1
    if n < len(tokens) and tokens[n] in _UNITS:
        return n + 1
    return n if n >= len(tokens) or tokens[n] in _PHRASE_ENDS else j


def _beside_a_quantity(tokens: list[str], out: list[str], end: int) -> bool:
    """Whether the comment ending before ``end`` stands mid-sentence right before a quantity ("fast, I'd
    say 25 km/h") or right after one and ends its phrase ("at 70 km/h I'd say."); ``out`` holds the
    words kept before it."""
    before = [w for w in out[-3:] if w != ","]
    if not out or out[-1] in _CLAUSE_ENDS:
        return False
    if _quantity_at(tokens, end) > end:
        return True
    after_end = end >= len(tokens) or tokens[end] in _PHRASE_ENDS
    return after_end and bool(before) and before[-1] in _UNITS


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


def without_comments_beside_speeds(tokens: list[str]) -> list[str]:
    """``tokens`` with each first-person comment left out that stands mid-sentence right before a speed
    ("very fast, I would say 25 km/h": "very fast, 25 km/h") or right after one, ending its phrase ("at
    70 km/h I'd say."). Run after :func:`vei_scenario.language.quantities.without_guesses`, which keeps a
    comment between a verb and its number for the verb ("going at, I'd guess, 45"). See the module's
    docstring."""
    out: list[str] = []
    k = 0
    while k < len(tokens):
        end = _comment_end(tokens, k)
        if end > k and _beside_a_quantity(tokens, out, end):
            k = end
            continue
        out.append(tokens[k])
        k += 1
    return out
