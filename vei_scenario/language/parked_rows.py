"""Vehicles named in the plural as parked line the road: scenery at the kerb.

"Cars parked both sides as usual", "you can't see a thing past the parked vans", "ran out from between
two parked cars", "a street lined with parked taxis": a plural of vehicles said to be parked sets the
scene the road user of the story comes out of or is hidden by. A scenario's road users act one by one;
a plural said to be parked is the row they stand in, and whatever else the reader hung on it (the verb
of the next clause it was joined to as a subject, a side road it was read as waiting in, a speed said
next to it) was said of someone else. It stands parked at the kerb, as cover does
(:func:`from_cover.stand_at_the_kerb`).

Parked is said of the plural inside its noun phrase ("the parked vans", "two parked cars") or right
after its noun ("cars parked both sides", "vans were parked there"). A row of which a move is said, with
a verb right after its name, or past an adverb ("two parked vans pulled out", "the parked vans then
started up", "two parked cars both pulled out"), or said of one of them ("the parked cars, one of which
then pulled out"), keeps its moves; so does one parked vehicle ("a parked car pulled out": read where
the reader reads cover and the kerb). Where the reader found no one but parked rows, what it hung on
them is all it read of the story, and it is left alone.
"""

from __future__ import annotations

from typing import Protocol

from vei_scenario.language.discourse import BE, PUNCT, VEHICLES
from vei_scenario.language.from_cover import stand_at_the_kerb
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.reading import Reading
from vei_scenario.language.said_again import plural

#: The word that says a vehicle is parked (double-parked ones stand in a traffic lane: not read here).
_PARKED = "parked"
#: How many words of a noun phrase may stand between its state and its noun ("two parked tour buses").
_PHRASE_REACH = 3
#: How many adverbs may stand between a row and the verb of its move ("suddenly", "then", "slowly").
_ADVERB_REACH = 2
#: Words that say a move is the whole row's, between its name and its verb ("both pulled out").
_THE_ROW = frozenset(("all", "both", "each"))


class _Row(Protocol):
    """What the reader gathered of a road user, as far as this module reads it."""

    kind: str
    word: str
    named_end: int
    hides: bool
    parked: bool
    stationary: bool


def _name_span(a: _Row, tokens: list[str]) -> tuple[int, int] | None:
    """Where ``a`` was first named in ``tokens`` (start, end), or None where that is not known."""
    words = a.word.split()
    start = a.named_end - len(words)
    if not words or start < 0 or tokens[start : a.named_end] != words:
        return None
    return start, a.named_end


def _parked_in_phrase(tokens: list[str], start: int) -> bool:
    """Whether "parked" stands inside the noun phrase ending at the noun that starts at ``start``
    ("the parked vans", "two parked tour buses"), no mark between."""
    for j in range(start - 1, max(start - 1 - _PHRASE_REACH, -1), -1):
        if tokens[j] in PUNCT:
            return False
        if tokens[j] == _PARKED:
            return True
    return False


def _parked_after(tokens: list[str], end: int) -> bool:
    """Whether "parked" is said right after the noun ending at ``end`` ("cars parked both sides"), or
    after a form of "be" ("vans were parked there")."""
    after = tokens[end : end + 2]
    return after[:1] == [_PARKED] or (len(after) == 2 and after[0] in BE and after[1] == _PARKED)


def _verb_at(tokens: list[str], k: int) -> int | None:
    """Where the verb is that follows from ``k`` past up to two adverbs or words of the whole row
    ("suddenly pulled out", "then started up", "both pulled out"), or None where no verb follows."""
    for j in range(k, min(k + _ADVERB_REACH + 1, len(tokens))):
        forms = lemmas(tokens[j])
        if "VERB" in forms and "NOUN" not in forms:
            return j
        if tokens[j] not in _THE_ROW and "ADV" not in forms:
            return None
    return None


def _moves_next(tokens: list[str], end: int) -> bool:
    """Whether a verb follows the noun ending at ``end``: a move said of it as its subject ("two parked
    vans pulled out", "two parked cars suddenly pulled out", "the parked vans then started up"), or of
    one of them ("the parked cars, one of which then pulled out"). "Parked" itself is its state, not a
    move; nor is being or having something ("one of which was a taxi")."""
    if end >= len(tokens) or tokens[end] == _PARKED:
        return False
    k = end + (tokens[end] == ",")
    if tokens[k : k + 2] == ["one", "of"] and tokens[k + 2 : k + 3] in (["which"], ["them"]):
        j = _verb_at(tokens, k + 3)
        return j is not None and tokens[j] not in BE and "have" not in lemmas(tokens[j]).get("VERB", ())
    return _verb_at(tokens, end) is not None


def parked_row(a: _Row, tokens: list[str]) -> bool:
    """Whether road user ``a`` is a row of parked vehicles in ``tokens`` (the reader's scanned words):
    vehicles named in the plural, said to be parked, of which no move is said (see the module)."""
    span = _name_span(a, tokens)
    if a.kind not in VEHICLES or span is None or not plural(tokens[span[1] - 1]):
        return False
    start, end = span
    return (_parked_in_phrase(tokens, start) or _parked_after(tokens, end)) and not _moves_next(tokens, end)


def rows_stand(actors: list, reading: Reading, tokens: list[str]) -> None:
    """Make every road user of ``reading`` that is a row of parked vehicles (gathered as ``actors``, in
    the same order) stand parked at the kerb; only where someone else than parked rows is read."""
    rows = [parked_row(a, tokens) for a in actors]
    if all(rows):
        return  # (no one but the rows: what they carry is all that was read)
    for a, spec, row in zip(actors, reading.actors, rows):
        if row:
            stand_at_the_kerb(a, spec, reading)
