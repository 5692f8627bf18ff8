"""Which lanes the ego's road has and which of them the ego drives in, so that every lane the road
users start in or change into exists.

Why: the reading says where each road user starts (in the lane on the ego's left, at the kerb ...)
and which way it changes lane, and separately how many lanes the road has and which one the ego is
in. The two often disagree (a road said to have one lane each way and a lorry "in the lane on my
left"; the ego in the left lane and a cut-in whose side the text leaves open), and a scenario whose
road user is put in a lane the map lacks cannot be written, so it plays nothing. The first choice is
what the reading says; where that leaves a road user without its lane, the nearest choice that gives
it one is taken: the ego moves over within the lanes said, then a side the text left open goes where
a lane is, and only then the road gets the lanes the story needs (at most two more each way).

Lanes count as in the layers: lane 1 is the kerb lane of the ego's direction, lane ``n`` the one next
to the centre line (:func:`~vei_scenario.language.placement.lane_id`).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

#: Behaviours that move their road user one lane sideways, each from the lane it starts in (a
#: behaviour compiles against its road user's starting lane).
LANE_CHANGES = ("change_lane", "cut_out")
#: Sides a road user starts on that are lanes of the ego's own direction (+1 left of the ego, -1 right).
SIDE_STEP = {"left": 1, "right": -1}
#: At most this many lanes are added to each direction for the story to fit.
MAX_EXTRA_LANES = 2


@dataclass(frozen=True)
class LaneUser:
    """What :func:`choose` needs of one road user: where it starts (``relation``, None where the
    text leaves it to its first behaviour's ``default``), whether it starts at the kerb and swerves
    from there (a rider who swerves starts on the kerb lane's edge), and its lane changes as
    (behaviour, stated direction or None)."""

    relation: str | None
    default: str | None
    at_kerb: bool
    changes: tuple[tuple[str, float | None], ...]


@dataclass(frozen=True)
class LaneChoice:
    lanes: int
    ego_lane: int
    #: Road users whose unstated side was put on the other side (index → relation).
    relations: dict[int, str]


def _start_lane(user: LaneUser, relation: str | None, lanes: int, ego_lane: int) -> int | None:
    """The layers lane (1 = kerb) the road user starts in, 0 where it starts in no lane of the ego's
    direction (oncoming, a junction arm, beyond the kerb), None where that lane does not exist."""
    if relation in SIDE_STEP:
        lane = ego_lane + SIDE_STEP[relation]
        return lane if 1 <= lane <= lanes else None
    if relation in ("ahead", "behind", None):
        return ego_lane
    if user.at_kerb and relation == "roadside_right":
        return 1  # (the kerb lane's edge)
    if user.at_kerb and relation == "roadside_left":
        return lanes  # (the left edge of the ego's direction: the lane next to the centre line)
    if relation.startswith("junction") and user.changes:
        return 1  # (its arm's kerb lane: the arms have as many lanes as the ego's road)
    return 0


def _fits(users: list[LaneUser], relations: list[str | None], lanes: int, ego_lane: int) -> bool:
    """Whether every road user's start lane exists and each of its lane changes has a lane to go
    to: on the side stated, or on either side where none is; a lead swerving out of a road with one
    lane each way goes into the oncoming lane, which is always there."""
    for user, relation in zip(users, relations):
        lane = _start_lane(user, relation, lanes, ego_lane)
        if lane is None:
            return False
        if lane == 0:
            continue
        for name, direction in user.changes:
            if name == "cut_out" and lanes == 1:
                continue
            sides = (1, -1) if direction is None else (1 if direction >= 0 else -1,)
            # (a rider on the kerb lane's edge told to move towards the centre moves into that lane)
            centre = 1 if relation == "roadside_right" else -1
            edge_to_centre = user.at_kerb and lane == ego_lane and name == "change_lane" and direction is not None
            edge_to_centre = edge_to_centre and (1 if direction >= 0 else -1) == centre
            if not edge_to_centre and not any(1 <= lane + s <= lanes for s in sides):
                return False
    return True


def _other_side(relation: str) -> str:
    return "right" if relation == "left" else "left"


def choose(users: list[LaneUser], lanes: int, ego_lane: int) -> LaneChoice:
    """The lanes and the ego's lane for ``users``, starting from what the reading gives (``lanes``,
    ``ego_lane``): unchanged where every road user has its lane; else, in this order, the ego in
    another of the lanes, a side the text left open on the other side, the road one lane wider each
    way (up to :data:`MAX_EXTRA_LANES`). Where nothing fits, what the reading gives (the writer
    then says which road user has no lane)."""
    stated = [u.relation or u.default for u in users]
    flipped = [
        _other_side(u.default) if u.relation is None and u.default in SIDE_STEP else r for u, r in zip(users, stated)
    ]
    for extra in range(MAX_EXTRA_LANES + 1):
        n = lanes + extra
        ego_lanes = [min(ego_lane, n)] + [k for k in range(1, n + 1) if k != min(ego_lane, n)]
        for relations, k in itertools.product((stated, flipped), ego_lanes):
            if _fits(users, relations, n, k):
                changed = {i: r for i, (r, s) in enumerate(zip(relations, stated)) if r != s}
                return LaneChoice(n, k, changed)
    return LaneChoice(lanes, ego_lane, {})
