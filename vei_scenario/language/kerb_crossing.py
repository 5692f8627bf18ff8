"""A walker or rider who comes off the kerb or out from cover, then only a brake: a crossing.

"A kid on a scooter came out between parked cars, I braked", "a lad darts off the left-hand pavement.
I slam the anchors on", "a woman steps off the footpath ... stood on everything": the writer says where
someone leaves the side of the road from (a kerb, a pavement, cover) and then what the ego does about
it. The reader gives a brake with no subject to the road user named last, so the reading holds no
more of that road user than a bare going (or a verb it has no word for) and brakes said free of it
(see :mod:`crossing_reaction`). Leaving the side of the road with nothing else said of the move is a
crossing of the ego's road (as :mod:`from_cover` and the reader's "walks from the far side" read it
with no brake after); the brakes are then the ego's reaction, which the pass over the finished reading
drops. The crossing may be said in words too ("stepped out", "ran across") with a brake said before
the road user is even named ("The emergency brake was shown ... a child stepped out from behind a
van"): the reader hands that brake to the first road user named, but it is the ego's all the same, and
the crossing comes first.

What must not be read so: a vehicle (one coming off the side of the road joins the traffic, read
elsewhere), a road user whose own move is said (along the kerb, standing, passed, waiting, against the
traffic, in a lane of its own, coming towards the ego: the caller tells it as not ``quiet``), one whose
stop is its own (said with its noun, placed in the road, joined by "then": no free mark), and one of
whom only a brake is said with no going at all and no verb of its own (nothing says it moved off the
side).
"""

from __future__ import annotations

from vei_scenario.language.crossing_reaction import MARK, SLOWING
from vei_scenario.language.discourse import VULNERABLE

#: Road users who leave the side of the road on foot or on two small wheels (or whose kind the reader
#: takes from what they do).
_WALKERS_AND_RIDERS = VULNERABLE | {"unknown"}
#: Behaviours that say no more than that someone goes.
_BARE_GOING = frozenset(("keep_going",))
#: The crossing said in words ("stepped out", "ran across"): what leaving the side of the road is.
_CROSSING = "cross_in_front"


def _free_brake(behaviour: tuple) -> bool:
    """Whether ``behaviour`` (name, cfg, criticality, link) is a slowing said free of its road user."""
    name, cfg = behaviour[0], behaviour[1]
    return name in SLOWING and bool(cfg.get(MARK))


def crossing_then_brakes(kind: str, behaviours: list, quiet: bool, own_verb: bool) -> list | None:
    """``behaviours`` of a road user of ``kind`` said to leave the kerb or come out from cover, read as
    a crossing followed by the free brakes (which the reader's last pass drops as the ego's), or None
    where they are no such thing: it must be a walker or rider that is ``quiet`` (nothing else makes it
    go along, stand or be passed) whose behaviours are bare goings, crossings and at least one free brake, with a
    going or a crossing among them or a verb of its own the reader has no word for (``own_verb``:
    "darts off"). A crossing said in words keeps its settings and criticality."""
    if kind not in _WALKERS_AND_RIDERS or not quiet or not behaviours:
        return None
    if not all(b[0] in _BARE_GOING or b[0] == _CROSSING or _free_brake(b) for b in behaviours):
        return None
    brakes = [b for b in behaviours if _free_brake(b)]
    going = any(b[0] in _BARE_GOING or b[0] == _CROSSING for b in behaviours)
    if not brakes or not (going or own_verb):
        return None
    said = next((b for b in behaviours if b[0] == _CROSSING), None)  # (its words' criticality and settings)
    _, cfg, crit = said[:3] if said else ("", {}, None)
    return [(_CROSSING, cfg, crit, behaviours[0][3]), *brakes]
