"""No one passes themselves: the object of a verb of passing is the one passed.

"A cyclist ahead is riding at 12 km/h and our rider overtakes it", "e-scooters on the carriageway
... pool car passed e-scooter at the kerb": the subject of the verb of passing is someone the reader
holds as no road user (a person it has no word for, the ego named in a way of its own), so the verb
goes to the road user named before it; and its object names that same road user again. A road user
cannot pass itself: what is passed is the object, and the one that passes is the subject, the one the
story is told from. So the road user keeps no overtake of that verb: it goes on, and it is what the ego
passes (ahead of it, going along the road).

Told apart by the reading alone: the object mention right after the verb names a road user that was
given that very verb in the same clause. A road user that passes another ("a van overtook the
cyclist") or the ego ("overtook me") names someone else as the object and keeps its overtake.
"""

from __future__ import annotations

from vei_scenario.language.motion import passes


def passed_by_its_own_verb(who: object, verb: object, added: list[tuple[object, int]]) -> bool:
    """Whether road user ``who``, named as the object of ``verb``, was itself given ``verb`` as an
    overtake in this clause (``added``: the (road user, behaviour index) pairs the clause gave; the
    members of a group named together share it). Where it was, that overtake becomes its going on: the
    road user is the one passed, moving along the road as it was."""
    if not passes(verb):
        return False
    same = [who, *(getattr(who, "group", None) or ())]
    own = [(a, i) for a, i in added if any(a is x for x in same) and _is_the_verb(a.behaviours[i], verb)]
    for a, i in own:
        a.behaviours[i] = ("keep_going", *a.behaviours[i][1:])
    return bool(own)


def _is_the_verb(behaviour: tuple, verb: object) -> bool:
    """Whether ``behaviour`` is the overtake read from mention ``verb``."""
    return behaviour[0] == "overtake" and behaviour[1].get("_start") == verb.start
