"""A distance said of a road user going along the road that is how near the ego came, not where it starts.

A writer tells how close an encounter with a walker or rider going along the road was: the room given
passing ("went round him giving about 2 m", "the Highway Code's 1.5 m"), how far short the ego stopped
behind it ("stopped 1.5 metres before the rider"). That is the distance at the end of the encounter.
Read as where the road user starts, it puts the two bodies on top of each other when the scenario
begins (a car's front half and a cyclist's rear half take more than 1.5 m), and the road user is then
never seen going along ahead: the run starts with a collision. So a distance too short to hold the two
bodies with room between them is kept as the road user's closest approach, and it starts where a road
user going along with nothing said of its start does. Only for one in the ego's lane, ahead of or behind
it: a rider said beside the ego ("on my left") or in a lane of its own ("in the cycle lane") passes
clear of it, and a short distance is where it starts (a left hook).
"""

from __future__ import annotations

#: Free space (m) a start must leave between the ego's body and the road user's: less than this is no
#: place to start from, but how near they came.
ROOM_BETWEEN_M = 1.0


def is_closest_approach(distance_m: float, ego_length_m: float, its_length_m: float) -> bool:
    """Whether ``distance_m``, said of a road user ahead of or behind the ego in its lane (reference
    point to reference point, as a start is placed), leaves less than :data:`ROOM_BETWEEN_M` between
    the two bodies: then it cannot be where the road user starts, and is how near the ego came."""
    return abs(distance_m) < (ego_length_m + its_length_m) / 2 + ROOM_BETWEEN_M
