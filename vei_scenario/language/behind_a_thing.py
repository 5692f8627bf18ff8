"""A road user said to be behind a thing, not a road user, is not behind the ego.

"I came upon a van stopped behind a fallen tree", "a car stood in lane behind an earlier crash", "a
cyclist waiting behind the stop line": "behind" with an object that is no road user places the road
user by that thing, where it stands, not by the ego. Read as the ego's "behind", the van the ego comes
upon would start behind the ego and come up on its rear. Said so, "behind" sets no start of its own:
the road user starts where the rest of the text puts it (ahead where the ego comes upon it or
follows it, behind where it overtakes the ego).

The object is the noun phrase right after "behind", opened by an article or a demonstrative ("behind
a tree", "behind the line"). "Behind" stays the ego's where that phrase names a road user (the ego,
"behind the bus": where that one is, which a witness's story may make the ego), the ego by one of its
nouns, or someone's ("behind Dad's car"); where "from" opens it ("came from behind a hedge": out of
cover, :mod:`from_cover`); and where the road user comes "up behind" it ("an e-scooter came up behind
the robot"): coming up on something from behind is what one does to a vehicle, told of here by a
noun the reader does not know as one (a delivery robot, a shuttle the report is about).
"""

from __future__ import annotations

from vei_scenario.language import lexicon as L
from vei_scenario.language.function_words import DEFINITE, INDEFINITE

#: Words that open a noun phrase naming something other than the speaker ("behind a tree", "the bus"):
#: the determiners but the possessives ("behind my car" is the ego's).
_OPENERS = INDEFINITE | DEFINITE
#: How many words of the object are read for the ego's noun or a possessive ("the white ego car").
_OBJECT_WORDS = 4


def _egos(words: list[str]) -> bool:
    """Whether ``words`` (the object's, in order) name the ego ("the ego vehicle", "the AV")."""
    for n in range(len(words), 0, -1):
        for i in range(len(words) - n + 1):
            if " ".join(words[i : i + n]) in L.EGO_NOUNS:
                return True
    return False


def behind_a_thing(tokens: list[str], words: str, start: int, end: int, road_users: set[int]) -> bool:
    """Whether the relation "behind" said in ``words`` (tokens ``start`` to ``end``) has an object of
    its own that names no road user ("behind a tree", "behind an earlier crash"): then it places its
    road user by that thing, not by the ego. ``road_users`` are the token indices where the reader
    names a road user (the ego among them)."""
    said = words.split()
    if said[-1] != "behind" or "from" in said or end >= len(tokens) or tokens[end] not in _OPENERS:
        return False
    if "up" in said or (start > 0 and tokens[start - 1] == "up"):
        return False  # ("came up behind the robot": a vehicle the reader does not know as one)
    obj = []
    for i in range(end + 1, min(end + 1 + _OBJECT_WORDS, len(tokens))):
        w = tokens[i]
        if i in road_users or w == "'s":
            return False
        if not w.isalpha():
            break
        obj.append(w)
    return bool(obj) and not _egos(obj)
