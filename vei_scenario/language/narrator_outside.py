"""A first-person writer who is not in a motor vehicle of their own in the scene.

"We are told a taxi doing 40 mph struck a boy who ran into the road", "my son ran out and was hit
by a van doing 25", "we the undersigned note that a child crossing was hit by a car": the writer
only reports, signs, is told, or is the parent of the one hit. The one motor vehicle of such a
story is still the one the scenario is told from (the ego), as in a report with no narrator at all;
only a writer who may be at a wheel of their own keeps it a road user of its own.

It is read from the narrator's part in the scanned words, not from the story's wording: the writer
may be at a wheel, or on foot beside the one it happened to, when

- a motor vehicle is theirs ("my car", "our van"; not "my husband's car", whose owner is someone
  else, nor "my bike", a rider's);
- they are the subject of a verb of steering a vehicle ("I was driving", "we braked", "I pulled
  over"), or have a speed of their own ("I was doing 30", "we were at 40 km/h");
- an act meets them ("in front of me", "came at us", "behind me"): they are in the scene, at a wheel
  or on foot beside the one it happened to;
- they are placed on the road, behind, beside or ahead of someone, in its traffic or at its lights ("I was behind my
  neighbour's car", "we were stuck in traffic behind a bus").

A writer who is on foot is outside any vehicle even where an act meets them or they wait at the
lights ("I was walking my dog when a van came past me", "we were on the pavement at the lights",
"I stepped off the kerb and a car went past me"): they are the walker the one vehicle meets, and that
vehicle is the ego. On foot means the writer, as a subject, walks, steps, stands or crosses a road
(a verb no one at a wheel does of themselves; not "stood on the brakes"), or is on a place for people
on foot (the pavement, the kerb, the zebra); a vehicle of their own or a verb of steering still
puts them at a wheel.
"""

from __future__ import annotations

from vei_scenario.language.ego import (
    BETWEEN,
    FIRST_PERSON,
    SENTENCE_END,
    VEHICLES,
    KindAt,
    Known,
    lemma_in,
    narrator_subject,
    road_users,
)
from vei_scenario.language.narrator_vehicle import narrator_speed

#: Verbs of steering or handling a vehicle (by lemma): a writer who does one is at a wheel.
AT_THE_WHEEL = frozenset(
    {
        "drive",
        "steer",
        "brake",
        "swerve",
        "slow",
        "accelerate",
        "indicate",
        "overtake",
        "reverse",
        "park",
        "pull",
        "merge",
        "stop",
        "turn",
        "creep",
        "approach",
        "follow",
        "travel",
        "cruise",
    }
)
#: Verbs that give their subject a speed when a number follows ("I was doing 50", "we were going 40").
AT_A_SPEED = frozenset({"do", "go", "travel", "cruise"})
#: First-person words of one an act meets ("in front of me", "towards us").
MET = frozenset({"me", "us", "myself", "ourselves"})
#: Words that place their subject on the road beside a road user, in its traffic or at its signals ("I was
#: behind my neighbour's car", "we were stuck in traffic behind a bus", "we were waiting at the lights").
ON_THE_ROAD = frozenset(
    {"behind", "beside", "alongside", "ahead", "next", "traffic", "queue", "queueing", "queuing", "lights", "signals"}
)
#: What ends the clause a writer is the subject of, for the words that place them.
_CLAUSE_END = frozenset({".", ",", ";", ":", "!", "?", "when", "while", "and", "but", "as", "until"})
#: Possessives of the writer.
OWN = frozenset({"my", "our"})


def _owns_a_vehicle(tokens: list[str], kind_at: KindAt) -> bool:
    """Whether a motor vehicle is the writer's ("my car", "our minibus"; not "my dad's car")."""
    for k, w in enumerate(tokens[:-1]):
        if w in OWN:
            found = kind_at(tokens, k + 1)
            if found is not None and found[0] in VEHICLES:
                return True
    return False


def _at_a_speed(tokens: list[str], k: int) -> bool:
    """Whether the verb at ``k`` gives its subject a speed ("doing 50", "going about 40")."""
    after = [w for w in tokens[k + 1 : k + 4] if w not in ("about", "around", "roughly", "maybe", "at", "like")]
    return lemma_in(tokens[k], AT_A_SPEED) and bool(after) and after[0].isdigit()


def _steers(tokens: list[str]) -> bool:
    """Whether the writer is the subject of a verb of steering or of one with a speed ("I was driving",
    "we braked hard", "we were doing 50")."""
    return any(
        (lemma_in(w, AT_THE_WHEEL) or _at_a_speed(tokens, k)) and narrator_subject(tokens, k)
        for k, w in enumerate(tokens)
        if k
    )


def _placed_on_the_road(tokens: list[str]) -> bool:
    """Whether the writer, as the subject of a clause, is placed on the road: behind, beside or ahead
    of someone, or in its traffic or queue ("I was behind a car when ...", "we were stuck in traffic")."""
    for f, w in enumerate(tokens):
        if w not in ("i", "we"):
            continue
        for nxt in tokens[f + 1 : f + 7]:
            if nxt in _CLAUSE_END:
                break
            if nxt in ON_THE_ROAD:
                return True
    return False


#: Verbs (by lemma) of going or being on foot that no one at a wheel says of themselves ("I was walking
#: the dog", "we stepped off the kerb", "I was stood at the corner"); "wait" and "sit" are not among
#: them, a driver waits or sits at the lights too.
ON_FOOT = frozenset(
    {"walk", "stroll", "jog", "step", "stand", "amble", "wander", "hike", "march", "limp", "tiptoe", "trek", "trudge"}
    | {"saunter", "hobble", "plod"}
)
#: Verbs (by lemma) of going across, on foot only where what is crossed is a road or a crossing ("I
#: was crossing the road"; a driver crosses a junction or a bridge).
ACROSS = frozenset({"cross"})
#: Places for people on foot (a closed class): a writer on one is on foot ("we were on the pavement").
FOOT_PLACES = frozenset(
    {
        "pavement",
        "pavements",
        "footpath",
        "footway",
        "sidewalk",
        "sidewalks",
        "kerb",
        "curb",
        "kerbside",
        "curbside",
        "verge",
        "zebra",
        "crosswalk",
        "crossing",
        "towpath",
        "footbridge",
        "foot",
    }
)
#: What is crossed on foot: a road or a crossing for people on foot.
_CROSSED_ON_FOOT = frozenset({"road", "street", "zebra", "crossing", "crosswalk"}) | {"roads", "streets"}
#: Words after "stood" or "stepped" that make it a driver's foot on a pedal ("stood on the brakes").
_PEDALS = frozenset({"brake", "brakes", "pedal", "gas", "accelerator", "throttle", "clutch"})


#: What a walker carries or pushes, or sits in, that no one at a wheel has (a closed class): a writer
#: with one of their own is on foot ("in my wheelchair", "with my cane", "pushing our pram").
WALKING_AIDS = frozenset(
    {
        "wheelchair",
        "chair",
        "cane",
        "crutch",
        "crutches",
        "rollator",
        "zimmer",
        "pram",
        "buggy",
        "stroller",
        "pushchair",
        "guide",
    }
)
#: Words that open a clause with a subject of its own: a verb after one is not the writer's.
_NEW_SUBJECT = frozenset({"when", "while", "as", "because", "until", "who", "which", "that", "he", "she", "they", "it"})


def _writers_verb(tokens: list[str], k: int) -> bool:
    """Whether the verb at ``k`` has the writer as its subject: right before it ("I was walking") or as
    the subject of the sentence it is joined to with "and" ("I checked both ways and stepped off")."""
    if narrator_subject(tokens, k):
        return True
    f = k - 1
    while f >= 0 and tokens[f] in BETWEEN:
        f -= 1
    if f < 0 or tokens[f] != "and":
        return False
    for j in range(f - 1, max(f - 12, -1), -1):
        if tokens[j] in SENTENCE_END or tokens[j] in _NEW_SUBJECT or tokens[j] == "and":
            return False
        if tokens[j] in FIRST_PERSON:
            return True
    return False


def on_foot_verb(tokens: list[str], k: int) -> bool:
    """Whether the word at ``k`` is a verb of going or being on foot whose subject is the writer ("I was
    walking", "we stepped off the kerb", "I was crossing the road"), not a foot on a pedal."""
    w = tokens[k]
    if not (lemma_in(w, ON_FOOT) or lemma_in(w, ACROSS)) or not _writers_verb(tokens, k):
        return False
    after = tokens[k + 1 : k + 5]
    if lemma_in(w, ON_FOOT):  # (not "stood on the brakes", nor "stood at the lights" or "the stop", as a driver is)
        return not (_PEDALS & set(after)) and not (ON_THE_ROAD & set(after)) and "stop" not in after
    return lemma_in(w, ACROSS) and bool(_CROSSED_ON_FOOT & set(after))


#: Prepositions of being somewhere, bare ("on foot") or with "the" ("on the pavement", "at the kerb").
_AT = frozenset({"on", "at"})
_AT_THE = (["on", "the"], ["at", "the"])


def _on_a_foot_place(tokens: list[str]) -> bool:
    """Whether the writer, as the subject of a clause, is on a place for people on foot ("we were on the
    pavement", "I was at the kerb", "I was on foot")."""
    for f, w in enumerate(tokens):
        if w not in FIRST_PERSON:
            continue
        for j in range(f + 1, min(f + 7, len(tokens))):
            if tokens[j] in _CLAUSE_END:
                break
            if tokens[j] in FOOT_PLACES and (tokens[j - 1] in _AT or tokens[j - 2 : j] in _AT_THE):
                return True  # ("on the pavement", "at the kerb", "on foot"; not "swerved onto the kerb")
    return False


def _with_a_walking_aid(tokens: list[str]) -> bool:
    """Whether the writer has a walking aid of their own ("in my wheelchair", "with our pram")."""
    return any(w in OWN and tokens[k + 1] in WALKING_AIDS for k, w in enumerate(tokens[:-1]))


def on_foot(tokens: list[str]) -> bool:
    """Whether the writer of ``tokens`` (as scanned) is on foot in the scene: the subject of a verb of
    going or being on foot, on a place for people on foot, or with a walking aid of their own (see the
    module)."""
    return (
        _on_a_foot_place(tokens)
        or _with_a_walking_aid(tokens)
        or any(on_foot_verb(tokens, k) for k in range(1, len(tokens)))
    )


def outside(tokens: list[str], kind_at: KindAt, known: Known) -> bool:
    """Whether ``tokens`` (as scanned) have a first-person writer who is in no motor vehicle of their
    own: they only report, are told or know the one it happened to (see the module)."""
    words = set(tokens)
    if not (words & (FIRST_PERSON | MET | OWN)):
        return False  # (no writer: the reader's passes for reports with no narrator apply as they are)
    if _owns_a_vehicle(tokens, kind_at):
        return False
    if _steers(tokens):
        return False
    if on_foot(tokens):  # (a speed after "past us at 40" is then the vehicle's: a walker has none)
        return True  # ("I was walking the dog when a van came past me": the walker it meets)
    if narrator_speed(tokens, road_users(tokens, kind_at, known)):
        return False
    if _placed_on_the_road(tokens):
        return False  # ("we were stuck in traffic behind a bus when ...": the writer is on the road)
    return not (words & MET)
