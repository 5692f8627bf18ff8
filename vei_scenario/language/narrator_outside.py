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
"""

from __future__ import annotations

from vei_scenario.language.ego import FIRST_PERSON, VEHICLES, KindAt, Known, lemma_in, narrator_subject, road_users
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


def outside(tokens: list[str], kind_at: KindAt, known: Known) -> bool:
    """Whether ``tokens`` (as scanned) have a first-person writer who is in no motor vehicle of their
    own: they only report, are told or know the one it happened to (see the module)."""
    words = set(tokens)
    if not (words & (FIRST_PERSON | MET | OWN)):
        return False  # (no writer: the reader's passes for reports with no narrator apply as they are)
    if _owns_a_vehicle(tokens, kind_at):
        return False
    if _steers(tokens) or narrator_speed(tokens, road_users(tokens, kind_at, known)):
        return False
    if _placed_on_the_road(tokens):
        return False  # ("we were stuck in traffic behind a bus when ...": the writer is on the road)
    return not (words & MET)
