"""A walker or rider going along the edge of the ego's road who then moves out: two acts, in order.

"A cyclist riding along the kerb ahead swerved out into my lane", "an e-scooter rider going along
the left edge of the road cut across to the right", "a man walking along the roadside, same way as
us, suddenly turned and crossed": the road user first goes along the road at its edge (along_road)
and then moves out of that course, into the ego's lane (cut_in) or across it to the other side
(cross_in_front). The going along is said by the particle "along" on its verb or before its kerb or
edge ("rides along", "along the kerb", "hugging the curb") or by its heading ("in the same
direction"). One in a lane of its own beside the ego's (a cycle lane, a bus lane) that moves
into the ego's lane is cutting in from that lane, and one that pulls out to overtake someone is
overtaking. Without such a going-along a walker who just steps off the kerb crosses from it
(cross_in_front alone), and one said to come from the kerb or the pavement starts there.
"""

from __future__ import annotations

#: Verbs and particles that put a road user along the kerb or edge it is named with.
_ALONG_THE_EDGE = frozenset(("along", "hugging", "hugs", "hug", "hugged"))
#: What a road user going along the road may first be said to do.
_GOING = frozenset(("keep_going", "along_road", "keep_lane"))
#: Moves out of that course: into the ego's lane, or across the road.
_OUT = frozenset(("cut_in", "change_lane", "cut_out", "cross_in_front"))


def goes_along(words: str) -> bool:
    """Whether a verb phrase says going along ("rides along", "walking along the"), not across."""
    return "along" in words.split()


def along_the_edge(prev: str) -> bool:
    """Whether the word before a kerb or edge puts the road user along it ("along the kerb",
    "hugging the curb"), not coming off or from it."""
    return prev in _ALONG_THE_EDGE


def same_heading(words: str) -> bool:
    """Whether a relation's words say the ego's heading ("in the same direction", "same way as us")."""
    said = words.split()
    return "same" in said and ("direction" in said or "way" in said)


def along_then_out(behaviours: list, across: bool, side: str | None = None) -> list | None:
    """``behaviours`` (name, cfg, criticality, link) read as going along the road, then moving out,
    where they start with a going-along and the next other act is a move out of it with nothing (a
    stop, a wait) between; None where they do not. A move out said with "across" (``across``: "cut
    across to the right", "swerved across my lane") or as a crossing crosses the road; one into the
    lane ends in it (a cut-in)."""
    if not behaviours or behaviours[0][0] not in _GOING or any(b[0] == "overtake" for b in behaviours):
        return None  # (pulling out to pass another rider is that pass's start: out_to_overtake)
    k = next((k for k, b in enumerate(behaviours) if b[0] not in _GOING), None)
    if k is None or behaviours[k][0] not in _OUT:
        return None
    name, cfg, crit, link = behaviours[k]
    out = "cross_in_front" if name == "cross_in_front" or across else "cut_in"
    if out == "cross_in_front" and side != "left":
        return None  # (from the right edge of the ego's lane the layers cross to its right: from the kerb)
    _, _, first_crit, first_link = behaviours[0]
    move = (out, cfg if out == name else {}, crit, link or "sequence")
    return [("along_road", {}, first_crit, first_link), move, *behaviours[k + 1 :]]


#: How far left of the ego's lane centre a road user going along its edge is (m; negative: right).
EDGE_OFFSET_M = 1.2


def at_the_edge(spec, side: str | None) -> None:
    """Put ``spec``, going along the road before it moves out, ahead of the ego at the edge of its
    lane on the side said (the right where none is), going the ego's way: it moves out of the ego's
    own road, so it rides or walks with the traffic there (along_road's start)."""
    spec.relation = "behind" if spec.relation == "behind" else "ahead"
    spec.lateral_m = EDGE_OFFSET_M if side == "left" else -EDGE_OFFSET_M
    spec.facing = None


def said_across(name: str, words: str, after: list[str]) -> bool:
    """Whether a move into or out of a lane (``name``, said by ``words``, followed by the tokens
    ``after``) is said with "across" ("cut across to the right", "swerved right across my lane",
    "swerved out across the road"): it crosses the lane rather than ending in it."""
    return name in ("cut_in", "change_lane", "cut_out") and "across" in (*words.split(), *after)
