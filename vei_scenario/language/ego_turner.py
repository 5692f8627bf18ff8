"""The ego's own vehicle, told as the one that turns across a walker or rider, or that one overtakes.

"A lorry turning left at a crossroads struck a cyclist who had ridden up the inside of its cab", "a
delivery van was turning right into a side road when it hit a pedestrian", "the instrumented vehicle
turns right at a T-junction. The driver stops abruptly when an e-scooter rider ... appears": a
report, a case study or a test log is about a motor vehicle that turns across a walker or a rider.
The scenario is that vehicle's turn with that walker or rider in its way: the turning vehicle is the
ego, and its turn is the ego's route.

It is told apart by what the reading holds, not by its words: the one motor vehicle read, whose
first act is a turn to a side, that nothing places (no start, side, lane, kerb or arm of its own: a
car ahead, oncoming or from a side road turns in front of the ego and is someone else), that no one
watches, beside road users that are all walkers or riders. Guards, each with its reason:

- the ego has no route of its own yet: a second turn would be a second vehicle's;
- nothing else in the reading is a motor vehicle that acts: with two, the turner may be anyone's;
- it is not said as stopped or parked: one standing at the side does not turn across anyone;
- it is no one's object ("overtook a turning van"): what the story's subject passes is in its road;
- one brought in as new ("a car turned left across a cyclist") is someone else where the text names
  an ego (a narrator, "you", an ego phrase): the ego, whose story it is, is never new to it.

The same holds for the one motor vehicle a walker or rider overtakes while it only pulls away or goes
on ("collided with a cyclist who was overtaking the bus on its offside", "Bus pulling out from stop.
E-scooter rider overtaking the bus ..."): the story is told from it. Not where anyone meets a narrator
("... and cut in front of me": the narrator is the ego), nor one parked, standing, placed ahead or
behind, or slower than the traffic.
"""

from __future__ import annotations

from vei_scenario.language.discourse import VEHICLES, VULNERABLE
from vei_scenario.language.ego_double import NEW, take_as_ego, without_road_user
from vei_scenario.language.reading import ActorSpec, Reading, stands_there

#: First-person words of a narrator someone meets ("in front of me", "our lane"): the narrator is the ego.
_MEETS_NARRATOR = frozenset(("me", "us", "my", "our"))
#: The sides a turn goes to that make a route of the ego's.
_SIDES = ("left", "right")


def _turn_of(spec: ActorSpec) -> str | None:
    """The side ``spec``'s first act turns to, where its first act is a turn ("turned left across
    her path"), else None."""
    first = spec.behaviours[0] if spec.behaviours else None
    if first is None or first[0] != "forced_turn":
        return None
    side = first[1].get("turn")
    return side if side in _SIDES else None


def _unplaced(a, spec: ActorSpec) -> bool:
    """Whether nothing places road user ``spec`` (gathered as ``a``): no start, side, lane, kerb or
    junction arm, nothing said of where it is, not watched, parked, followed or passed."""
    return (
        spec.relation is None
        and spec.lateral_m is None
        and not a.said
        and not (a.side or a.lane_side or a.kerb_side or a.from_arm or a.beside or a.arm)
        and not (a.seen or a.parked or a.followed or a.passed or a.acted_on or a.group)
    )


def merge_turner_into_ego(actors: list, reading: Reading, unnamed: bool = False) -> list:
    """Take the motor vehicle of ``reading`` that turns across its walkers or riders (see the module)
    out of its road users: its turn becomes the ego's route, its speed the ego's where none was read.
    ``actors`` are what the reader gathered of them, in the same order; ``unnamed``: nothing in the text
    names the ego, so one brought in as new may be it. Returns ``actors`` without it."""
    if reading.ego_route is not None or len(reading.actors) < 2:
        return actors
    specs = reading.actors
    movers = [k for k, s in enumerate(specs) if s.kind in VEHICLES and not stands_there(s)]
    if len(movers) != 1:
        return actors
    k = movers[0]
    turner, a = specs[k], actors[k]
    side = _turn_of(turner)
    if side is None or not _unplaced(a, turner) or a.stationary or turner.speed_mps == 0.0:
        return actors
    if a.det in NEW and not unnamed:
        return actors
    rest = [s for j, s in enumerate(specs) if j != k and not stands_there(s)]
    if not rest or any(s.kind not in VULNERABLE for s in rest):
        return actors
    if not take_as_ego(reading, k):
        return actors
    reading.ego_route = side
    return without_road_user(actors, reading, k)


#: What the ego's vehicle does while another passes it: pulls away or out, goes on, changes speed.
_PULLS_AWAY = frozenset(("cut_in", "keep_going", "change_speed"))
#: Where the ego's vehicle may be said to be while one passes it: a side it is passed on ("on its
#: offside"), the kerb it pulls away from ("out from the stop").
_PASSING_SIDES = (None, "left", "right", "roadside_left", "roadside_right")


def _overtaken(a, spec: ActorSpec, actors: list, specs: list[ActorSpec]) -> bool:
    """Whether motor vehicle ``spec`` (gathered as ``a``) is what the story's one other road user, a
    walker or rider, overtakes while it only pulls away or goes on ("a cyclist who was overtaking the bus as it pulled
    away from the stop"): nowhere said but on a side, not watched, parked, followed or standing."""
    overtakers = [k for k, x in enumerate(actors) if x is not a and a.object_of is x and specs[k].behaviours[:1]]
    return (
        spec.kind in VEHICLES
        and bool(spec.behaviours)
        and {b[0] for b in spec.behaviours} <= _PULLS_AWAY
        and spec.relation in _PASSING_SIDES
        and a.said <= set(_PASSING_SIDES)
        and (spec.speed_mps is None or spec.speed_mps > 0.0)
        and not (a.seen or a.parked or a.stationary or a.followed or a.passed or a.group)
        and len(overtakers) == 1
        and specs[overtakers[0]].behaviours[0][0] == "overtake"
        and specs[overtakers[0]].kind in VULNERABLE
    )


def merge_overtaken_into_ego(actors: list, reading: Reading, tokens: list[str]) -> list:
    """Take out of ``reading`` the motor vehicle its one other road user overtakes while it pulls away
    or goes on (see :func:`_overtaken`): the story is told from it, the ego. Only where no one in the
    text meets a narrator (``tokens`` hold no "me", "us", "my" or "our": a narrator met is the ego).
    ``actors`` are what the reader gathered of its road users, in the same order. Returns ``actors``
    without it."""
    specs = reading.actors
    acting = [s for s in specs if not stands_there(s)]
    if len(acting) != 2 or _MEETS_NARRATOR & set(tokens):
        return actors
    taken = [k for k, (a, s) in enumerate(zip(actors, specs)) if _overtaken(a, s, actors, specs)]
    if len(taken) != 1 or not take_as_ego(reading, taken[0]):
        return actors
    return without_road_user(actors, reading, taken[0])
