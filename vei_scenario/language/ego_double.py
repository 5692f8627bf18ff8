"""The ego's own vehicle, named in the story as if it were one more road user.

"Bus was doing around 45", "the above pool car ... was moving at about 50km/hr", "Husband was only
doing about 20, slammed on the brakes", "the Corolla clipped him at around 50 km/h. The Corolla was
me": where the words that name the ego are ones the reader does not take for it, the ego's vehicle
is read as a road user of its own. Such a double is told apart by what is said of it, not by its
name: nothing places it (no start, no side, no lane, no kerb), and all it does is what the ego does
in the story it is told from: it goes on, slows, or brakes, to a stop if need be. Everyone else in
the story acts on the ego's road, and the scenario is theirs with the ego.

Where exactly one road user is read like that, beside road users that do something of their own or
start somewhere said, it is the ego: it leaves the road users, its speed is the ego's where the ego
has none, and a gap said of it is the gap to the one road user it meets. Two such cannot be told
apart by this, and both stay. So does one that the words set apart from the ego: one brought into the
story as new ("a car was going at 40": the ego, whose story it is, is never new to it), one someone is
said to see ("my dad saw the car hit a cyclist"), one said only to stop while no one gets into its path
("the bus was stopped at the stop": it may stand there; "a cyclist cut across and the vehicle came to
a halt" is the ego stopping for the cyclist, and so is "the van came to a stop when a boy stepped out",
whose "when" clause tells what happened first though it is said after, where no narrator tells
the story and nothing sets the van apart, as "I overtook it", "the target vehicle", "the car in the
other lane" and "the cyclist behind it" do), one slower or faster than the
traffic ("overtook a slow-moving bus"), one that does something to another road user, one the ego
follows or passes, one named in a group or picked out of one, parked, standing or hiding someone. A
text that calls the ego "the ego" has said which one it is, and no vehicle is taken for it. A
third-person report that names no ego at all (no narrator in the scene, no "you", no ego phrase) brings
the vehicle it is about in as new like any other, with the speed it was doing ("a resident driving home
at 30 mph was hit when ..."): there, "a" does not set apart one with a speed of its own.
"Both" after someone acted ("a van cut the corner onto my side. Both drivers braked hard") names the
ego and that one together: two such road users that only go on or brake, nowhere said, are no one new.

A passenger's story names the ego by its driver: "Driver braked hard and our cases slid everywhere",
"then driver overtake very close", "When driver turning right at the junction, one e-scooter come from
opposite direction". A road user named only by a noun for whoever is at a wheel ("driver", "the
driver", "our driver"), with no vehicle of its own, that nothing places (no start, side, lane or
kerb), that no one sees from outside and that is not brought in as new ("a driver ran the red") or
as someone else ("the other driver"), is the driver of the vehicle the story is told from: the ego.
What it does is the ego's (its speed the ego's where none was read, its turn the ego's route).
"""

from __future__ import annotations

import re
from typing import Protocol

from vei_scenario.language.clauses import sentence_stop
from vei_scenario.language.discourse import FIRST_PERSON, PERCEIVE
from vei_scenario.language.lane_to_front import lane_beside_after
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.manner import BREAKS
from vei_scenario.language.narrator_vehicle import TEST_OBJECTS
from vei_scenario.language.reading import ActorSpec, Reading, stands_there
from vei_scenario.language.vocabulary import IN_LINE

#: What the ego itself does in a story told from it: goes on, slows, brakes (to a stop).
EGO_LIKE = frozenset(("keep_going", "sudden_stop", "stop", "change_speed"))
#: What a road user does that puts it in the ego's path, for the ego to stop for: crossing, cutting in,
#: turning or pulling out across it, coming the wrong way, braking hard ahead of it.
IN_THE_PATH = frozenset(
    (
        "cross_in_front",
        "cut_in",
        "turn_into",
        "turn_across",
        "forced_turn",
        "run_red_light",
        "junction_entry",
        "wrong_way",
        "sudden_stop",
        "cut_out",
    )
)
#: Determiners that bring a road user new into the story: the ego, whose story it is, is never new.
NEW = frozenset(("a", "an", "another", "some", "one"))
#: Words that name the ego in the reader's tokens: the narrator, the reader addressed, the ego framed.
_NAMING_THE_EGO = frozenset(("i", "we", "me", "us", "my", "our", "you", "your", "yourself", "ego"))
#: The kinds the ego may be (it drives or rides: never on foot).
_EGO_KINDS = frozenset(("car", "van", "truck", "bicycle", "e-scooter"))
#: The nouns for whoever is at a wheel, said of a person and no vehicle (a closed class).
_AT_A_WHEEL = frozenset(("driver", "chauffeur", "cabbie", "cabby", "motorist"))
#: Words before a person that say it is someone else than one already there ("the other driver").
_SOMEONE_ELSE = frozenset(("other", "another", "second", "third", "oncoming", "opposing"))


class _Said(Protocol):
    """What the reader gathered of a road user, as far as this module reads it."""

    passed: bool
    followed: bool
    hides: bool
    parked: bool
    stationary: bool
    group: list | None
    member_named: bool
    det: str
    seen: bool
    object_of: object
    word: str
    named_after: str
    relation: str | None
    side: str | None
    lane_side: str | None
    kerb: bool
    kerb_side: str | None
    from_arm: bool
    beside: bool
    said: set
    named_end: int


def ego_unnamed(tokens: list[str], clauses: list, writer_outside: bool = False) -> bool:
    """Whether the reader's ``tokens`` and ``clauses`` name no ego at all: no narrator in the scene, no
    "you", no ego phrase ("the host vehicle", "the VUT") and none framed as "the ego". A third-person
    report then brings its own vehicle in as new ("a resident driving home at 30 mph was hit when
    ..."), and "new" no longer sets a vehicle apart from the ego. ``writer_outside``: the text's
    first-person writer is in no vehicle of their own (:mod:`vei_scenario.language.narrator_outside`:
    "we the undersigned", "my grandson was hit by"): their "I" and "we" name no one in the scene, and
    the story is told as a report with no narrator is ("you" and an ego phrase still name the ego)."""
    writer = FIRST_PERSON if writer_outside else frozenset()  # (the writer's own words: only theirs)
    return not ego_phrase(clauses, writer) and not ((_NAMING_THE_EGO - writer) & set(tokens))


#: "you" in the text as written (the reader's own tokens may read it as the narrator's "I").
_YOU = re.compile(r"\byou(?:r|rs|rself|rselves)?\b", re.IGNORECASE)


def addressed(text: str) -> bool:
    """Whether ``text`` as written says "you" to its reader ("Explain your answer", "you are doing 30"):
    the reader addressed is the ego, whom a writer outside the scene does not leave unnamed."""
    return _YOU.search(text) is not None


def ego_phrase(clauses: list, but: frozenset[str] = frozenset()) -> bool:
    """Whether the reader's ``clauses`` name the ego by a phrase ("the host vehicle", "the VUT"): a
    vehicle brought in as new beside it is someone else. A mention said only in words of ``but`` (a
    writer outside the scene: "we") does not count."""
    return any(
        m.slot == "actor" and m.value == "ego" and not (but and set(m.words.split()) <= but)
        for _, mentions in clauses
        for m in mentions
    )


def perceived(verb: str) -> bool:
    """Whether ``verb``, said right before a road user is first named, is one of seeing ("saw the car
    hit a cyclist", "watched the van"): that road user is watched, from outside."""
    return verb in PERCEIVE or any(x in PERCEIVE for forms in lemmas(verb).values() for x in forms)


#: What the ego has, said with "ego" as its modifier ("an ego speed of 30 km/h", "ego lane"): a closed
#: class of the quantities and places a test spec gives the ego.
_OF_THE_EGO = "speed|velocity|lane|route|path|heading|acceleration|deceleration|position|trajectory"
#: "ego" naming the ego as one of the scene, not as the modifier of something it has.
_EGO_NAMED = re.compile(rf"\bego\b(?![\s-]+(?:{_OF_THE_EGO})s?\b)", re.IGNORECASE)


def names_the_ego(text: str) -> bool:
    """Whether ``text`` calls the ego by that name ("... 20 m ahead of the ego", "the ego vehicle"): it
    has said which one the ego is, and no other vehicle is taken for it. "ego" as the modifier of what
    the ego has ("at an ego speed of 30 km/h", "ego lane") names no road user apart from the others."""
    return _EGO_NAMED.search(text) is not None


def _marked_out(a: _Said) -> bool:
    """Whether what is said about ``a`` marks it out as someone the ego meets: followed or passed by
    the ego, named in a group or picked out of one, parked, or what someone comes out from behind."""
    return bool(a.passed or a.followed or a.hides or a.parked or a.group or a.member_named)


def _placed(a: _Said) -> bool:
    """Whether the words set ``a`` somewhere by what is said about it: marked out (:func:`_marked_out`),
    or standing."""
    return _marked_out(a) or bool(a.stationary)


def stops_for_someone(spec: ActorSpec, specs: list) -> bool:
    """Whether road user ``spec``, said only to stop, stops for another of ``specs`` named before it
    that gets into its path ("a cyclist cut across in front of it and the vehicle came to a halt"):
    that is what the ego does in the story told from it, in the order it happens. One that only stops
    while the others go along or past it ("the bus was stopped when a cyclist rode into the back of
    it", "the lorry stopped and a cyclist went up its inside"), or that stops before anyone gets in
    its way ("the bus stops at a bus stop and a pedestrian walks out in front of it": it stopped for
    its own reason, and stands there) may be standing there, a road user of its own."""
    earlier = specs[: next(k for k, s in enumerate(specs) if s is spec)]
    return any(b[0] in IN_THE_PATH for s in earlier for b in s.behaviours)


#: Subordinators that open a clause telling when the act of the clause before happened ("stopped when a
#: boy ran out", "braked as a cyclist cut across"): what that clause tells happened first, or at once.
WHEN = frozenset(("when", "as"))
#: At most this many words from the subordinator to the end of its subject's name ("when a young boy").
_SUBJECT_WORDS = 4


def stops_when_someone_comes(a: _Said, others: list, specs: list, tokens: list[str]) -> bool:
    """Whether road user ``a``, said only to stop, has the time of its stop told by a clause that
    "when" or "as" opens right after it in its sentence, whose subject is the next road user named
    and gets into its path ("the van stopped when a boy stepped out on the left", "the vehicle shall
    stop when a pedestrian steps out"): the stop is for that one, though named after it, as the ego
    stops in the story told from it. ``others`` are the road users gathered (``a`` among them), in
    the order of ``specs``; ``tokens`` the scanned words their names end in. Only where no one tells
    the story in the first person (no "I" or "we", not even of a writer read as outside the scene: a
    narrator is the ego, and the one they stop behind, overtake or meet is someone else), and not one
    the words set apart (:func:`_set_apart`)."""
    if FIRST_PERSON & set(tokens) or _set_apart(a, others, tokens):
        return False
    after = [(x.named_end, s) for x, s in zip(others, specs) if x.named_end > a.named_end >= 0]
    if not after:
        return False
    end, nxt = min(after, key=lambda p: p[0])
    between = tokens[a.named_end : end]
    at = max((k for k, w in enumerate(between) if w in WHEN), default=None)
    if at is None or sentence_stop(between, 0) < len(between) or len(between) - at > _SUBJECT_WORDS:
        return False  # (its subject comes right after the subordinator: "when a boy", "as the cyclist")
    if at and between[at - 1] in BREAKS:
        return False  # ("came to a stop, and when a kid ran out I braked": it times another clause)
    return any(b[0] in IN_THE_PATH for b in nxt.behaviours)


def _set_apart(a: _Said, others: list, tokens: list[str]) -> bool:
    """Whether the words set road user ``a`` apart from the ego: named as a test's object or by its
    place in a line ("the target vehicle", "the lead car", "the other car"), set in a lane beside
    another right after its name ("the car in the other lane"), or with a road user named after it said
    to be behind or ahead of "it" ("the cyclist behind it swerved": one behind another, not the ego)."""
    words = {a.named_after, *a.word.split()[:-1]}
    if words & (_SOMEONE_ELSE | TEST_OBJECTS | IN_LINE):
        return True
    if a.named_end >= 0 and lane_beside_after(tokens, a.named_end) is not None:
        return True
    return any("near_other" in x.said for x in others if x.named_end > a.named_end)


def _double(a: _Said, spec: ActorSpec, others: list, specs: list, tokens: list[str], new_too: bool = False) -> bool:
    """Whether road user ``spec`` (gathered as ``a``) is read as the ego would be: a kind the ego may
    be, nowhere said, moving at a speed of its own or none said (not standing, not "slow-moving"),
    doing only what the ego does (only stopping where another of ``specs`` gets into its path), and
    nothing to another road user (none is its verb's object). ``tokens`` as :func:`merge_into_ego`
    takes them; ``new_too``: one brought in as new with a speed may be it (a text naming no ego)."""
    names = {b[0] for b in spec.behaviours}
    return (
        spec.kind in _EGO_KINDS
        and spec.relation is None
        and spec.lateral_m is None
        and (spec.speed_mps is None or spec.speed_mps > 0.0)
        and names <= EGO_LIKE
        and (
            names != {"stop"}
            or spec.speed_mps is None
            and not a.stationary
            and (stops_for_someone(spec, specs) or stops_when_someone_comes(a, others, specs, tokens))
        )
        and not _placed(a)
        and (a.det not in NEW or (new_too and spec.speed_mps is not None))
        and not a.seen
        and not any(x.object_of is a for x in others)
    )


def merge_into_ego(actors: list, reading: Reading, unnamed: bool, tokens: list[str]) -> list:
    """Take the one road user of ``reading`` that is the ego said again (see the module) out of its
    road users; ``actors`` are what the reader gathered of them, in the same order. Its speed becomes
    the ego's where the ego has none, and a gap said of it is the gap to the one road user it meets
    (where there is one, with no gap of its own). ``unnamed``: nothing in the text names the ego (no
    narrator, no "you", no vehicle framed as the ego), so one brought in as new may be it too.
    ``tokens``: the scanned words the road users' names end in (for a stop told with "when").
    Returns ``actors`` without it."""
    specs = reading.actors
    tokens = list(tokens)
    doubles = [k for k, (a, s) in enumerate(zip(actors, specs)) if _double(a, s, actors, specs, tokens)]
    if not doubles and unnamed:  # (one not new is the ego before any brought in as new)
        doubles = [k for k, (a, s) in enumerate(zip(actors, specs)) if _double(a, s, actors, specs, tokens, True)]
    deeds = [  # (a parked lorry does nothing the ego meets: "a van hit my dad" beside it is no report of the van)
        s
        for a, s in zip(actors, specs)
        if (not {b[0] for b in s.behaviours} <= EGO_LIKE or s.relation is not None)
        and not (a.parked and stands_there(s))
    ]
    if len(doubles) != 1 or not deeds or len(specs) < 2:
        return actors
    k = doubles[0]
    if not take_as_ego(reading, k):
        return actors
    double = specs[k]
    rest = [s for j, s in enumerate(specs) if j != k]
    if double.distance_m is not None and len(rest) == 1 and rest[0].distance_m is None:
        rest[0].distance_m = double.distance_m  # ("Bus was doing 40 only 3 m from a cyclist")
    return without_road_user(actors, reading, k)


def take_as_ego(reading: Reading, k: int) -> bool:
    """Whether ``reading``'s ``k``-th road user can be taken for the ego (no other swerves round it:
    what one swerves round is in the road, not the ego); if so, its speed becomes the ego's where the
    ego has none."""
    if any(s.obstacle == k for s in reading.actors):
        return False
    taken = reading.actors[k]
    if reading.ego_speed_mps is None and taken.speed_mps is not None and taken.speed_mps > 0:
        reading.ego_speed_mps = taken.speed_mps
    return True


def without_road_user(actors: list, reading: Reading, k: int) -> list:
    """``actors`` and ``reading``'s road users without the ``k``-th (the ego said again, a crowd): the
    others' obstacles (what they swerve round) keep pointing at the same road users."""
    for s in reading.actors:
        if s.obstacle is not None and s.obstacle > k:
            s.obstacle -= 1
    reading.actors = [s for j, s in enumerate(reading.actors) if j != k]
    return [a for j, a in enumerate(actors) if j != k]


def _ego_driver(a: _Said, spec: ActorSpec) -> bool:
    """Whether road user ``spec`` (gathered as ``a``) is the ego's driver in a passenger's story: a
    person at a wheel named with no vehicle, nowhere said (no start, side, lane, kerb, side road), not
    new to the story, not someone else, not watched from outside, and not marked out by what is said of
    it (:func:`_marked_out`; that it waits does not: "Driver held back and waited for a gap" is what the
    ego's driver does, and a driver with no vehicle parks none)."""
    return (
        spec.kind == "car"
        and a.word in _AT_A_WHEEL
        and a.det not in NEW
        and a.named_after not in _SOMEONE_ELSE
        and a.relation is None
        and not (a.side or a.lane_side or a.kerb or a.kerb_side or a.from_arm or a.beside)
        and not ({"ahead", "behind", "oncoming"} & a.said)
        and not _marked_out(a)
        and not a.seen
    )


def merge_ego_driver(actors: list, reading: Reading) -> list:
    """Take the one road user of ``reading`` that is the ego's driver in a passenger's story (see the
    module) out of its road users; ``actors`` are what the reader gathered of them, in the same order.
    Its speed becomes the ego's where the ego has none, and its turn the ego's route where none was
    read. Returns ``actors`` without it."""
    specs = reading.actors
    drivers = [k for k, (a, s) in enumerate(zip(actors, specs)) if _ego_driver(a, s)]
    if len(drivers) != 1 or len(specs) < 2:
        return actors
    k = drivers[0]
    if not take_as_ego(reading, k):
        return actors
    driver = specs[k]
    turns = [b[1].get("turn") for b in driver.behaviours if b[0] == "forced_turn"]
    if reading.ego_route is None and turns[:1] in (["left"], ["right"]):
        reading.ego_route = turns[0]  # ("When driver turning right at the junction, ...")
    return without_road_user(actors, reading, k)


def _said_again_as_both(group: list, spec_of: dict, others: list) -> bool:
    """Whether road users ``group`` (two, first named after "both") are the ego and the one already
    in the story said together: "both" names two the story has (it brings no one new in), of kinds
    the ego may be, nowhere said, doing only what the ego does and nothing to anyone else."""
    return (
        len(group) == 2
        and all(id(a) in spec_of and a.named_after == "both" for a in group)
        and all(
            spec_of[id(a)].kind in _EGO_KINDS
            and {b[0] for b in spec_of[id(a)].behaviours} <= EGO_LIKE
            and a.relation is None
            and not (a.side or a.lane_side or a.kerb or a.kerb_side or a.from_arm or a.beside or a.seen)
            and not any(x.object_of is a for x in others)
            for a in group
        )
    )


def drop_both_said_again(actors: list, reading: Reading) -> list:
    """Take out of ``reading`` the two road users named with "both" after someone acted ("a van cut
    the corner onto my side. Both drivers braked hard", "both cars stopped inches apart"): they are the
    ego and the one already there, said together, not two more. ``actors`` are what the reader gathered
    of its road users, in the same order. Returns ``actors`` without them."""
    specs = reading.actors
    spec_of = {id(a): s for a, s in zip(actors, specs)}
    for a in actors:
        group = a.group or []
        rest = [x for x in actors if all(x is not g for g in group)]
        if group and group[0] is a and rest and _said_again_as_both(group, spec_of, actors):
            if any(s.obstacle is not None for s in specs):
                return actors  # (what another swerves round is in the road)
            kept = [k for k, x in enumerate(actors) if all(x is not g for g in group)]
            reading.actors = [specs[k] for k in kept]
            return [actors[k] for k in kept]
    return actors
