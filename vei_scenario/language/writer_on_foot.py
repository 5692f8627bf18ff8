"""A writer on foot whom the story's one motor vehicle meets: that vehicle is the ego, the writer the
walker it meets.

"I stepped off the kerb with my sign and a taxi went straight past me at 30", "Walking the dog along
the lane, a van came up behind me and passed at 40", "we were crossing the road when a ute came past
us": a crossing patrol, a dog walker, a parent on the school run writes what one vehicle did to them.
The scenario is that vehicle's (its speed the ego's), and the writer is the walker in it; read as it
is, the vehicle is a road user and no one is there for it to meet.

It is told apart by what the reading holds: the one motor vehicle read, which only goes on, brakes or
goes past, and no other road user but ones that only stand there (parked cars: scenery). Guards, each with its reason:

- the writer is on foot (:func:`vei_scenario.language.narrator_outside.on_foot`), in no vehicle of
  their own: a writer at a wheel is the ego themselves;
- an act meets the writer ("past me", "at us"): a writer who only watches is no road user;
- the writer crosses or goes along the road, which the reading can place; one who only stands is
  not placed, and the reading is left as it is;
- the vehicle is the report's (:func:`vei_scenario.language.report_vehicle.reported`): parked,
  followed, watched or in a group, it is someone else.
"""

from __future__ import annotations

from vei_scenario.language.discourse import VEHICLES
from vei_scenario.language.ego import lemma_in
from vei_scenario.language.ego_double import take_as_ego, without_road_user
from vei_scenario.language.narrator_outside import ACROSS, MET, on_foot_verb
from vei_scenario.language.reading import ActorSpec, Reading, stands_there
from vei_scenario.language.report_vehicle import reported

#: Verbs (by lemma) of going across the road on foot: the writer crosses the vehicle's way.
_CROSSING = ACROSS | {"step"}
#: Verbs (by lemma) of going along on foot: the writer walks along the vehicle's road.
_ALONG = frozenset(
    {"walk", "stroll", "jog", "amble", "wander", "hike", "march", "limp", "trek", "trudge", "saunter", "hobble", "plod"}
)
#: Crossings for people on foot: a writer on one crosses the road.
_CROSSINGS = frozenset({"zebra", "crossing", "crosswalk"})


def _writers_way(tokens: list[str]) -> tuple[str, str] | None:
    """Where and how the writer on foot is in the road: across it ("I stepped off the kerb", "we were
    crossing the road", "on the zebra"), along it ("I was walking the dog along the lane"), or None."""
    verbs = [tokens[k] for k in range(1, len(tokens)) if on_foot_verb(tokens, k)]
    on_a_crossing = any(w in _CROSSINGS and tokens[k - 1] in ("the", "a") for k, w in enumerate(tokens) if k)
    if any(lemma_in(w, _CROSSING) for w in verbs) or (verbs and on_a_crossing):
        return "roadside_right", "cross_in_front"
    if any(lemma_in(w, _ALONG) for w in verbs):
        return "ahead", "along_road"
    return None


def the_writer_met(actors: list, reading: Reading, tokens: list[str], writer_on_foot: bool) -> list:
    """Take ``reading``'s one road user, a motor vehicle that meets a writer on foot (see the module), for
    the ego, and put the writer in its place as the walker it meets. ``actors`` are what the reader
    gathered of its road users, in the same order; ``tokens`` the text as scanned. Returns ``actors``
    without it (the writer has no gathered mention)."""
    specs = reading.actors
    acting = [k for k, s in enumerate(specs) if not stands_there(s)]  # (parked cars are scenery)
    if not writer_on_foot or len(acting) != 1 or specs[acting[0]].kind not in VEHICLES or not (MET & set(tokens)):
        return actors
    k = acting[0]
    way = _writers_way(tokens)
    if way is None or not reported(actors[k], specs[k], passing=True) or not take_as_ego(reading, k):
        return actors
    actors = without_road_user(actors, reading, k)
    reading.actors.append(ActorSpec("pedestrian", relation=way[0], behaviours=[(way[1], {}, None, "sequence")]))
    return actors
