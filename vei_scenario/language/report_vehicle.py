"""The one motor vehicle of a third-person report about a walker or rider: the ego.

"A Ford Fiesta driven by Ms Kaur was leaving the car park at about 30 mph; the scooter came from her
right. She braked but could not avoid a collision", "Mr Shah was crossing the junction in his Prius at
20 mph. The cyclist entered from his left", "silver Golf ~30mph hit e-scooter rider who came off
pavement", "A bus is moving at 10 m/s when the driver spots a cyclist 20 m ahead ... Give your
answer": an inquest, a judgment, a news item, a log or an exam question with no narrator is told
about the vehicle whose driver it is about, and the walker or rider that vehicle meets (where it says
"you" to its reader, or names the ego by a phrase the reader did not tie to this vehicle, still).
The scenario is that vehicle's: it is the ego, not one more road user.

It is told apart by what the reading holds, not by its words: the one motor vehicle read that moves,
beside road users that are all walkers or riders, doing only what the ego does in the story told from
it (it goes on, slows, brakes, or goes past one of the walkers or riders: "a van overtook the
cyclist far too close"). Guards, each with its reason:

- no narrator speaks ("I", "we", "my"): a narrator may be the walker or rider, or in a vehicle of
  their own; "you" and an ego phrase ("the test car") name the ego, which the one vehicle then is;
- where a phrase names the ego ("the VUT"), one brought in as new ("a car") is someone else;
- it is the only motor vehicle that moves: with two, either may be the one the report is about;
- one read ahead that brakes is the vehicle in front braking ("V1 was behind V2 when V2 braked");
- it is not parked, standing or said only to stop, and hides no one: one at the kerb is scenery;
- no one watches it ("saw a car hit a cyclist"): a vehicle watched is seen from outside;
- it is not followed, passed, grouped or picked out of a group: those are placed by someone else;
- no road user swerves round it: what one swerves round stands in the road;
- the walkers or riders do not all only go on as it does: road users listed going on together
  ("three road users came through: a van, a woman and a cyclist") are told as alike, none the one
  met (one that brakes for another braking ahead of it does meet it).
"""

from __future__ import annotations

import re

from vei_scenario.language.discourse import VEHICLES, VULNERABLE
from vei_scenario.language.ego_double import EGO_LIKE, IN_THE_PATH, NEW, take_as_ego, without_road_user
from vei_scenario.language.reading import ActorSpec, Reading, stands_there

#: Braking: one ahead that brakes is the lead vehicle braking in front of the ego, a scenario of its own.
_BRAKING = frozenset(("sudden_stop", "stop", "change_speed"))
#: Moving out to pass and back in: part of a pass ("moved fully into the right lane and passed the rider").
_MOVING_OUT = frozenset(("change_lane",))
#: Only going on: what road users listed together do where none of them meets another.
_GOING_ON = frozenset(("keep_going", "change_speed"))
#: Going past: what the ego does going on past a walker who writes.
_PASSING = frozenset(("overtake",))
#: A narrator's words: one who may be in the scene, on foot or riding, with a vehicle of their own.
_NARRATOR = frozenset(("i", "me", "my", "mine", "we", "us", "our", "ours"))
#: Where a report's vehicle may be read to start while it is the ego: nowhere, or on the ego's own
#: road ("travelling straight ahead", "hit from behind"); an arm, a side or the other way is another's.
_ON_ITS_ROAD = (None, "ahead", "behind")


def reported(a, spec: ActorSpec, passing: bool = False) -> bool:
    """Whether motor vehicle ``spec`` (gathered as ``a``) reads as the vehicle a report is about: it
    moves, does only what the ego does, starts nowhere off its own road, and nothing sets it apart
    (parked, standing, hiding someone, watched, followed, passed, in a group). With ``passing``, one
    that goes past no one named or a walker or rider ("went past me", "overtook the cyclist") is the
    ego going on past them: among walkers and riders, the one vehicle that passes passes one of them."""
    names = {b[0] for b in spec.behaviours}
    if passing and names & _PASSING and (a.object_of is None or a.object_of.kind in VULNERABLE):
        names -= _PASSING | _MOVING_OUT  # ("a van overtook the cyclist": the ego going on past them, out and back)
    return (
        spec.kind in VEHICLES
        and names <= EGO_LIKE
        and names != {"stop"}
        and spec.relation in _ON_ITS_ROAD
        and not (spec.relation == "ahead" and names & _BRAKING)
        and spec.lateral_m is None
        and (spec.speed_mps is None or spec.speed_mps > 0.0)
        and not (a.parked or a.stationary or a.hides or a.seen or a.followed or a.passed)
        and not (a.group or a.member_named or a.side or a.lane_side or a.kerb_side or a.from_arm or a.beside)
    )


def _names(spec: ActorSpec) -> frozenset[str]:
    """The behaviours ``spec`` is read doing, by name."""
    return frozenset(b[0] for b in spec.behaviours)


def merge_report_vehicle(
    actors: list,
    reading: Reading,
    text: str,
    ego_phrase: bool = False,
    writer_outside: bool = False,
) -> list:
    """Take out of ``reading`` the one motor vehicle of a report with no narrator (``text`` has no word
    of the first person: the reader's own words read "you" as one) whose other road users are all
    walkers or riders (see the module): it is the ego, its speed the ego's where none was read.
    ``actors`` are what the reader gathered of its road users, in the same order; ``ego_phrase``: a
    phrase names the ego ("the VUT"), and one brought in as new ("a car") is someone else. Returns
    ``actors`` without it. ``writer_outside``: the text's writer is in no motor vehicle of their own
    (:mod:`vei_scenario.language.narrator_outside`), and the text is told as if it had no narrator. A
    vehicle that goes past a walker or rider (or no one named) is going on past them."""
    specs = reading.actors
    narrated = not writer_outside and _NARRATOR & set(re.findall(r"[a-z]+", text.lower()))
    if narrated or len(specs) < 2:
        return actors
    movers = [k for k, s in enumerate(specs) if s.kind in VEHICLES and not stands_there(s)]
    if len(movers) != 1:
        return actors
    k = movers[0]
    rest = [s for j, s in enumerate(specs) if j != k and not stands_there(s)]
    if not rest or any(s.kind not in VULNERABLE for s in rest):
        return actors
    if _names(specs[k]) <= _GOING_ON and all(_names(s) == _names(specs[k]) for s in rest):
        return actors  # (listed going on together: none of them is the one the others meet)
    if ego_phrase and actors[k].det in NEW:
        return actors  # ("The VUT drives at 50 km/h. A car travelling at 60 km/h ...": someone else)
    if not reported(actors[k], specs[k], passing=True) or not take_as_ego(reading, k):
        return actors
    _own_speed(reading, specs[k])
    return without_road_user(actors, reading, k)


def _own_speed(reading: Reading, taken: ActorSpec) -> None:
    """The speed said of the vehicle the report is about is the ego's, over one the reading took from
    the road's limit or the scene ("two lanes each way, 60 km/h zone ... passed the rider at about 50
    km/h": 50)."""
    if taken.speed_mps is not None and taken.speed_mps > 0.0:
        reading.ego_speed_mps = taken.speed_mps


#: The reader addressed: the ego ("you spotted it and eased off").
_ADDRESSED = frozenset(("you", "your", "yourself"))
#: What one motor vehicle does to another it threatens, besides putting itself in its path.
_THREATENS = IN_THE_PATH | {"overtake", "follow_vehicle"}


def merge_threatened_vehicle(actors: list, reading: Reading, text: str, ego_phrase: bool = False) -> list:
    """Take out of ``reading`` the motor vehicle that a report with no narrator tells another motor
    vehicle threatening ("a white van was observed following a car ..., passed the car and cut back in
    in front of it, forcing the car driver to brake", "a sedan ran the red into the path of a pickup;
    the pickup braked"): two vehicles move, one does only what the ego does and reacts (slows, brakes,
    stops) and is the object of the other's verb, which puts itself in its way, passes or follows it
    ("an oncoming van overtook a slow lorry" tells of neither: no one reacts).
    The report is told about the one threatened, the ego; the other is the road user. ``actors`` are
    what the reader gathered of its road users, in the same order; ``ego_phrase``: a phrase names the
    ego, and neither is it. Returns ``actors`` without the one taken."""
    specs = reading.actors
    if ego_phrase or (_NARRATOR | _ADDRESSED) & set(re.findall(r"[a-z]+", text.lower())):
        return actors  # (a narrator, or "you", names the ego: "you sat in lane 2 after overtaking the lorry")
    movers = [k for k, s in enumerate(specs) if s.kind in VEHICLES and not stands_there(s)]
    if len(movers) != 2 or any(s.kind not in VULNERABLE for j, s in enumerate(specs) if j not in movers):
        return actors
    for k, other in (movers, movers[::-1]):
        a, threat = actors[k], actors[other]
        if (
            a.object_of is threat
            and _names(specs[k]) <= EGO_LIKE
            and _names(specs[k]) & _BRAKING  # (it reacts: "forcing the car driver to brake")
            and _names(specs[other]) & _THREATENS
            and not (a.parked or a.stationary or a.hides or a.seen or a.group)
            and take_as_ego(reading, k)
        ):
            _own_speed(reading, specs[k])
            return without_road_user(actors, reading, k)
    return actors
