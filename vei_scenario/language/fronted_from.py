"""A phrase of where a road user comes from, put before it, opens its clause, after a comma too.

"I turned left at the lights, from the opposite direction a scooter went straight on": a phrase of
where someone comes from ("from the opposite direction", "from the other way") that stands right
before a road user's noun phrase is said of that road user, fronted before its subject, as at the
start of a sentence ("From the opposite direction a scooter went straight on"). A writer who runs
two sentences together with a comma leaves the narrator as the subject before it, and read as the
narrator's the phrase is lost: the scooter starts ahead of the ego, going its way, instead of coming
towards it. So does the bare noun phrase a hurried writer fronts without its preposition ("I turned
left, the opposite direction a scooter went straight"): two noun phrases in a row after a comma are
never one, so the first says where the second comes from.

Only a phrase that is complete before the road user is named is fronted so: one that ends in its own
noun ("direction", "way"), whether or not the reader counts that noun among the words that
carry nothing alone. One that ends in a word still waiting for its object, a preposition or a
determiner, is not: "From behind the bus a scooter ..." has "the bus" as the object of "behind", and
the phrase is read where it is, as before.
"""

from __future__ import annotations

from collections.abc import Callable

from vei_scenario.language.function_words import DETERMINERS, PHRASE_ENDS

#: Words that open a phrase of where someone comes from: "from the other way", or the bare noun phrase
#: a hurried writer fronts without its preposition ("the opposite direction a scooter went straight").
_OPENS_A_PLACE = frozenset(("from", "the"))
#: Words that open a road user's noun phrase right after the fronted phrase ("a scooter", "the van").
_OPENS_A_NAME = DETERMINERS
#: Words that leave a phrase waiting for its object ("from behind" the bus, "from the" ...).
_WAITS_FOR_OBJECT = DETERMINERS | PHRASE_ENDS


def fronted_before(
    words: str,
    end: int,
    next_start: int,
    tokens: list[str],
    after_comma: bool,
    preposition: Callable[[str], bool],
) -> bool:
    """Whether a relation said in ``words`` (ending at token ``end``), right after a comma
    (``after_comma``), is a "from" phrase (or a bare "the ..." one) fronted before the road user named
    at ``next_start``: complete in itself (its last word no determiner nor preposition, the reader's
    prepositions of place by ``preposition``), with at most an opening word ("a", "the") between it and
    the road user's name."""
    said = words.split()
    last = said[-1]
    if not after_comma or said[0] not in _OPENS_A_PLACE or len(said) < 2:
        return False
    if last in _WAITS_FOR_OBJECT or preposition(last):
        return False
    return next_start == end or (next_start == end + 1 and tokens[end] in _OPENS_A_NAME)
