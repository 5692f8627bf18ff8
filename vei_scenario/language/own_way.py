"""A verb whose object is its own subject: the road user moves itself.

"A lorry wedged itself into my lane", "a taxi forced its way into our lane", "the van poked its nose
into lane 2": English lets almost any verb say a move when its object is the subject itself, a
reflexive pronoun or the subject's own way (the way-construction: "elbowed his way through") or, for a
vehicle, its nose (its front, so the vehicle). The verb then says only how it moved; where it goes
("into my lane") says which move, as it does after a verb with no object. Reading past that object
lets the reader's readings of where a verb goes see such a verb as the move it is. A reflexive of the
first person ("I squeezed myself in") is the ego's, and no road user's: it is not read past.
"""

from __future__ import annotations

#: Reflexive pronouns of a third person: the object that is the subject itself.
REFLEXIVES = frozenset(("itself", "himself", "herself", "themselves", "themself"))
#: Possessives of a third person, before what of the subject's own a verb moves.
_POSSESSIVES = frozenset(("its", "his", "her", "their"))
#: What of its own a road user moves when it moves itself: its way (the way-construction), its nose.
_ITS_OWN = frozenset(("way", "nose"))


def past_its_own_object(tokens: list[str], k: int) -> int:
    """Where the object that is the subject itself ends, said from ``tokens[k]`` ("itself", "its way",
    "his nose"); ``k`` where none is said there."""
    if k < len(tokens) and tokens[k] in REFLEXIVES:
        return k + 1
    if tokens[k : k + 1] and tokens[k] in _POSSESSIVES and tokens[k + 1 : k + 2] and tokens[k + 1] in _ITS_OWN:
        return k + 2
    return k


def is_its_own_object(m, tokens: list[str]) -> bool:
    """Whether mention ``m`` (a pronoun the reader read) opens an object that is the subject itself
    ("itself", "its way"): no other road user, only the one that moves."""
    return m.slot == "pronoun" and past_its_own_object(tokens, m.start) > m.start
