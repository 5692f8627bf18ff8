"""A road user that goes onto a roundabout from one of its arms joins the ring in front of the ego.

Where no light, signal or stop sign is said, a roundabout has nothing to run: a road user told by its
going in or on ("came onto the roundabout from the left without giving way", "rolled onto it from
the road on my left", "at the roundabout a Corolla comes in from the right and doesn't stop") turns
out of its arm onto the ring, into the ego's way round, across the ego's path: a turn into the ego's
road (``turn_into``, which rides the ring from that arm), not a run of a red that is not there.
"Without giving way" or "without stopping" says how it went on, not where.

What must not be read so: a roundabout with a light or signal said (a red there is run), a road user
told refusing to give way in so many words ("fails to yield", "does not give way": the reader's
denied give-way, read as driving through the entry), one not from an arm on the ego's left or right
(the opposite arm, ahead, on the ring beside the ego or already on it: "a car on the roundabout came
round from the right"), one said to take an exit ("takes the exit on the left": it leaves by that
arm), a meeting at the next junction after the roundabout ("we came out of the roundabout and a
cyclist came from the left at the next junction"), and any junction that is no roundabout.
"""

from __future__ import annotations

import re

#: A junction said as the next one after the roundabout ("at the next junction"): where the ego meets
#: the road user once it has left the ring.
_NEXT_JUNCTION = re.compile(r"\bnext (?:junction|crossroads?|intersection|t-junction|lights)\b")
#: The arms a road user comes onto the ring from, across the ego's way round.
_SIDE_ARMS = frozenset(("junction_left", "junction_right"))
#: The settings a run through the entry shares with a turn onto the ring (the rest are the run's own).
_SHARED = frozenset(("arrival_gap_s",))


def joins_the_ring(
    map_kind: str | None,
    signal: bool,
    relation: str | None,
    refuses_way: bool,
    on_the_ring: bool,
    leaves: bool,
    behaviours: list,
    said: str = "",
) -> list:
    """``behaviours`` of a road user read as running through a roundabout's entry from the arm at
    ``relation``, with its first act (a run) made the turn onto the ring it is, where the map is a
    roundabout, no light or signal is said (``signal``), the road user is not told refusing to give way
    (``refuses_way``: the reader's denied give-way) nor already on the ring (``on_the_ring``: the
    reader's priority of one "already on the roundabout"), it is not said to take an exit (``leaves``:
    "takes the exit on the left" is leaving by that arm, not coming out of it), and the description
    (``said``) puts no next junction after the roundabout."""
    if map_kind != "roundabout" or signal or leaves or relation not in _SIDE_ARMS or not behaviours:
        return behaviours
    if _NEXT_JUNCTION.search(said) or refuses_way or on_the_ring:
        return behaviours
    if behaviours[0][0] != "run_red_light":
        return behaviours
    _, cfg, crit, link = behaviours[0]
    return [("turn_into", {k: v for k, v in cfg.items() if k in _SHARED}, crit, link), *behaviours[1:]]
