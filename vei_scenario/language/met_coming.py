"""A road user met coming, or one coming the other way that waits for the ego: it comes towards the ego.

"Round the bend we met a tractor coming up the lane", "he pulls out and meets a lorry coming": on the
road, to meet someone who is coming is to come face to face with them, each going their own way
towards the other; a road user going the ego's way is caught up with, come up behind or followed,
never met coming. So a road user that is the object of "meet" with a participle of going right after
its name ("coming", "heading", "climbing") starts ahead of the ego facing it: oncoming. Not one said
to come up behind ("met a van coming up behind us" is no meeting face to face), nor one the reader
has placed already.

"A pickup coming the other way stopped and flashed us through", "the oncoming bus waited and waved
me on": a road user said to come the other way that gives way to the ego does so where it is, in its
own lane facing the ego: on a crossroad it waits on the arm opposite the ego's (the way it comes
from), not on a side road it was never said to be in; where the map has no junction, it stops in its
lane, oncoming. Only a side said of it (from the side road on the left) puts it on a side arm instead.
Which map that is the reader has settled before: a vehicle that gives way makes it a crossroad even
where no junction is said ("the oncoming bus waited and waved me on": the opposite arm), so it is on a
bend ("on the bend the oncoming bus waited ...") or for a rider ("an oncoming cyclist waited ...")
that it waits oncoming. ("A van coming the other way stopped and flashed me through" is read as a
stop, no giving way, and stays oncoming on a straight road.)
"""

from __future__ import annotations

from vei_scenario.language.lemmas import lemmas

#: Verbs (lemmas) of going whose -ing form after a road user's name says how it comes ("coming up").
_GOING = frozenset(("come", "head", "travel", "drive", "ride", "approach", "climb", "descend", "go", "trundle"))
#: How many words (determiner and modifiers) may stand between "met" and the road user's name's end.
_REACH = 6
#: Words that, between "met" and the name, end the object: punctuation and conjunctions.
_BREAKS = frozenset((",", ".", ";", ":", "!", "?", "and", "but", "when", "while", "as", "then"))
#: How far after the participle "behind" still belongs to it ("coming up fast behind us").
_BEHIND_REACH = 4


def _verbs(word: str) -> set:
    return set(lemmas(word).get("VERB", ()))


def met_coming(tokens: list[str], named_end: int) -> bool:
    """Whether the road user whose name ends at ``named_end`` (exclusive) in ``tokens`` is the object
    of "meet" and comes on: a participle of going right after its name, and "meet" before it with only
    its noun phrase between ("met an articulated lorry coming up the lane")."""
    if not 0 < named_end < len(tokens):
        return False
    after = tokens[named_end]
    if not (after.endswith("ing") and _verbs(after) & _GOING):
        return False
    if "behind" in tokens[named_end + 1 : named_end + 1 + _BEHIND_REACH]:
        return False
    for k in range(named_end - 1, max(named_end - 1 - _REACH, -1), -1):
        word = tokens[k]
        if word in _BREAKS:
            return False
        if "meet" in _verbs(word):
            return True
    return False


def waits_facing(said_towards: bool, first: str | None, rides: bool, side: str | None, junction: bool) -> str | None:
    """Where a road user said to come towards the ego (``said_towards``) that gives way first waits:
    the opposite arm on a crossroad or roundabout (``junction``), its own lane where the map has no
    junction (oncoming); None where that is not so (on foot, not giving way, or with a side of its own
    said). The map is the reader's: a vehicle giving way has made it a crossroad already, so it is a
    rider, or a road user on a bend, that waits oncoming."""
    if not (said_towards and rides and first == "give_way") or side in ("left", "right"):
        return None
    return "junction_opposite" if junction else "oncoming"
