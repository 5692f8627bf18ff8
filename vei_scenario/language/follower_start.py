"""A road user said to be right behind another, or to follow it, starts where that one starts.

"A car pulled out of the side street on my right and a scooter came out right behind it"; "a van
emerged from the junction on the left, a cyclist following it"; "a woman crossed from the left kerb
with her little boy behind her": the second road user is placed by the first ("behind it", "follows
it"), not by the ego, so it comes from the same side road or kerb and does what the first does there
(comes out, crosses). Read alone it has no start of its own, or the ego's "behind" / "ahead", and a
follower of the ego that never comes out.

The one it follows is the object of its verb of following ("a cyclist followed a van out of the side
road"), or, said behind a pronoun, the road user named last before it (what "it", "him", "her" point
back to). It is taken so only where:

- the follower is said to follow another road user, or to be behind one with a pronoun ("behind it",
  "follows her"): "behind us" or "following me" places it behind the ego, and that reading stays;
- nothing else places the follower (no side, lane, kerb or arm of its own): a side said of it is its
  own start;
- the one followed comes onto the ego's road from a side road or a kerb (its start is a junction arm
  or a roadside): one followed along the ego's own road is followed where the reader already puts it.
"""

from __future__ import annotations

from typing import Protocol

from vei_scenario.language.reading import ActorSpec

#: Starts off the ego's road, from which a road user comes onto it.
_FROM_A_SIDE = frozenset(("junction_left", "junction_right", "roadside_left", "roadside_right"))
#: What a follower's own reading may say of it and still be placed by the one it follows: nothing, or
#: going on behind it ("follows it", "came out too"), or the ego's "in front" where both come out.
_FOLLOWING = frozenset(("follow_vehicle", "keep_going", "keep_lane", "along_road"))
#: Acts of coming onto the ego's road from a side (what a follower does after the one it follows).
_COMING_ON = frozenset(("turn_into", "cross_in_front", "run_red_light", "cut_in"))


class _Said(Protocol):
    """What the reader gathered of a road user, as far as this module reads it."""

    said: set
    object_of: object
    side: str | None
    lane_side: str | None
    kerb: bool
    kerb_side: str | None
    arm: bool
    from_arm: bool


def _placed_by_itself(a: _Said) -> bool:
    """Whether something said of ``a`` itself places it (a side, a lane, a kerb, an arm)."""
    return bool(a.side or a.lane_side or a.kerb or a.kerb_side or a.arm or a.from_arm)


def _only_follows(spec: ActorSpec) -> bool:
    """Whether all ``spec`` is read to do is go on or follow (nothing of its own across or into a lane)."""
    return all(b[0] in _FOLLOWING for b in spec.behaviours)


def _the_followed(actors: list[_Said], k: int) -> int | None:
    """The index of the road user road user ``k`` is said to follow: the object of its verb of following
    ("a cyclist followed a van out"), else, said behind a pronoun ("right behind it", "follows her"),
    the one named last before it. None where it follows no other road user (the ego, or none)."""
    a = actors[k]
    if "follows_other" in a.said:
        return next((j for j, x in enumerate(actors) if j != k and x.object_of is a), None)
    return k - 1 if "behind_other" in a.said and k > 0 else None


def starts_with_the_followed(actors: list[_Said], specs: list[ActorSpec]) -> None:
    """Give each road user said right behind the one named before it (and placed by nothing else) that
    one's start and its act of coming on, where that one comes onto the ego's road from a side road or
    a kerb. ``actors`` are the reader's road users, ``specs`` their readings, in the same order."""
    for k in range(min(len(actors), len(specs))):
        a, spec = actors[k], specs[k]
        j = _the_followed(actors, k)
        if j is None or _placed_by_itself(a) or not _only_follows(spec):
            continue
        leader = specs[j]
        if leader.relation not in _FROM_A_SIDE or not leader.behaviours:
            continue
        act = leader.behaviours[0]
        if act[0] not in _COMING_ON:
            continue
        crit = spec.behaviours[0][2] if spec.behaviours else None
        spec.relation = leader.relation
        spec.behaviours = [(act[0], dict(act[1]), crit or act[2], act[3])]
