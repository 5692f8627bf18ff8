"""A vehicle that pulls out of a private way onto the ego's road turns into it: no cut-in from a lane.

"A jeep pulled out of a field gate on the left", "an Uber pulls out of a driveway on the right", "a
Corsa came straight out of the car park on my left", "a pickup nosed out of a gravel drive", "a van
emerged from the petrol station forecourt", "a tractor came out of the farm track": the road user was
off the road, on a way of its own that meets the road (a drive, a gate, a car park's exit, a yard, a
track), and comes onto it across the kerb line, as one from a side road does: it turns into the road.
The reader places it on that roadside (sides.py) and first reads the move as a cut-in; this reads
the cut-in as the turn into the road.

What stays a cut-in: a vehicle leaving a place at the road's own edge (a bus stop, a lay-by, a
parking space or bay): it stood on the carriageway's edge already and pulls out into the lane
beside it, as a bus away from a stop does. A walker or rider out of a driveway crosses or rides on
(other readings take it); a vehicle said in a lane or at a junction arm keeps its reading.
"""

from __future__ import annotations

#: Head nouns of a private way onto the road (the road user leaves it across the kerb line): a drive,
#: a gate, a car park ("park"), a forecourt, a yard, a track.
ACCESS_HEADS = frozenset(("driveway", "drive", "gateway", "gate", "gates", "forecourt", "yard", "track", "park"))


def turns_in_from_an_access(place: str | None, relation: str | None, behaviours: list) -> list:
    """``behaviours`` of a vehicle, with a first cut-in or plain going on read as a turn into the road (``turn_into``)
    where the vehicle comes out of a private way (``place``, the head noun of where it comes out of)
    on a roadside (``relation``): it joins the road from off it. Anything else is kept: a place at
    the road's edge (a stop, a bay), a start in a lane or at an arm, a first move of its own (a stop,
    a reverse, a crossing)."""
    if place not in ACCESS_HEADS or not (relation or "").startswith("roadside") or behaviours[:1] == []:
        return behaviours
    name, cfg, crit, link = behaviours[0]
    if name not in ("cut_in", "keep_going"):  # (a plain going, "drove out of the gate", is the same move)
        return behaviours
    return [("turn_into", {}, crit, link)] + [b for b in behaviours[1:] if b[0] not in ("cut_in", "keep_going")]
