"""A number as a quantity: its unit, its head (what it measures) and its owner (whom it is said of),
read from the grammar around it rather than from where it stands.

Why: a speed or a gap lost or given to the wrong road user is the commonest way a description is read
unfaithfully, and position alone ("the road user named last") cannot tell "van speed 60 km/h, ego speed
80 km/h" apart from "a van overtakes the ego at 60 km/h". The constructions that name a number's owner
are few and closed, and the same in every writer's style:

- a noun heading the quantity: "<road user> speed N", "speed of <road user> N", "<road user> N km/h";
- a key and its values: "<road user>: 6 m ahead, 20 mph, ..." (a bullet or a line of notes);
- a coordinated subject with "both": "<road user> and <road user> both at N".

What a number measures is said by the unit after it and, where a unit is shared, by its head noun: a
lateral speed, a sideways clearance, a visibility distance are numbers of the scene, not the speed a road
user travels at or its gap to the ego. A bare number ("I'm at 50") carries the speed unit the text used
before it. Everything here works on the reader's tokens; what a road-user mention is comes from the
reader (a callback), so the owner is the mention the reader already found.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from vei_scenario.language import vocabulary as V

#: Heads that make a number no speed of travel nor a starting gap: a measure across the road ("a lateral
#: velocity of 1 m/s", "1.5 m clearance"), how far one sees ("visibility reduced to 150 m"), or the
#: closest approach, an outcome ("a minimum separation of 0.5 m"); a plain "separation of 120 m" is a gap.
LATERAL_HEADS = frozenset(
    {"lateral", "laterally", "sideways", "clearance", "visibility", "offset", "minimum", "closest"}
)
#: Nouns a test engineer calls the other road user by, whatever it is ("target speed: 15 km/h"): heading a
#: number after a road user is named, they name that one.
ROLE_NOUNS = frozenset({"target", "other vehicle"})
#: Nouns that head a speed ("van speed 60 km/h", "speed of the bus 15 km/h").
SPEED_HEADS = frozenset({"speed", "velocity"})
#: Words between a head and its number that carry nothing ("speed is about 20", "speed of ~20").
_LINKS = frozenset({"about", "is", "was", "of", "at", "=", "approximately", "around", "roughly", "ca", "circa"})
_STOPS = frozenset({".", ";", "!", "?"})
#: Verbs of going whose subject a speed after "at" is said of ("the ego drives at 40 km/h").
_MOTION = frozenset(
    "doing going driving travelling traveling moving riding drives travels moves rides goes drove travelled "
    "traveled moved rode went".split()
)
_AUXILIARIES = frozenset({"is", "was", "are", "were", "am", "be", "been", "'s", "still", "also", "then", "just"})
#: Words after which a noun opens a clause, as its subject ("; the bus at 15 km/h", "and the van at 60").
_CLAUSE_OPENERS = frozenset({",", ";", ":", ".", "and", "but", "while", "whereas", "when", "then", "as"})
_OBJECT_PRONOUNS = frozenset({"me", "us", "him", "her", "them", "it", "you"})
_DETERMINERS = frozenset({"the", "a", "an", "this", "that", "our", "my", "its", "their", "his", "her"})

#: A car's length (m), the unit of "two car lengths behind".
CAR_LENGTH_M = 4.5
#: Words that may stand between "at" and a bare speed: an article and one modifier ("at a steady 50").
_ARTICLES = frozenset({"a", "an"})

#: "20-30 mph", "70–90 km/h", "between 8 and 12 metres": a range with its unit.
_RANGE = re.compile(
    r"\b(?:between\s+)?(\d+(?:\.\d+)?)\s*(?:-|\u2013|\u2014|(?<=\d) and)\s*(\d+(?:\.\d+)?)\s*"
    r"(?=(?:km/h|mph|m/s|m|metres|meters|metre|meter|car lengths?)\b)"
)


def ranges(text: str) -> str:
    """Each range of a quantity in the normalised ``text`` as its middle, approximately ("20-30 mph":
    "about 25 mph"): a writer giving a range means a value within it, and the middle is the one that
    errs least. "From 50 to 20 km/h" is a change of speed, not a range, and stays."""

    def middle(m: re.Match) -> str:
        if not m.group(0).startswith("between") and " and" in m.group(0):
            return m.group(0)  # ("slows to 30 and 20 m later": a list, not a range)
        value = (float(m.group(1)) + float(m.group(2))) / 2
        return f"about {value:g} "

    return _RANGE.sub(middle, text)


#: Words that make a number of seconds a time gap between two road users ("a 2 s gap", "1.5 s headway",
#: "3 seconds ahead"), not a time of the story ("at t = 3 s", "TTC 1.5 s", "for 2 seconds").
HEADWAY_WORDS = frozenset({"gap", "headway", "ahead", "behind", "apart", "back", "following", "interval"})
_SECONDS = frozenset({"s", "sec", "secs", "second", "seconds"})


def headway_m(tokens: list[str], i: int) -> float | None:
    """The distance (m) of a time gap at ``i`` ("a 2 s gap" at 72 km/h: 40 m): the seconds times the
    ego's speed where it is said as the ego's, else the speed said last before it with its unit (a time
    gap is the time one takes to reach where the other is); None where it is no time gap or no speed
    is said before it."""
    if tokens[i + 1 : i + 2] == [] or tokens[i + 1] not in _SECONDS:
        return None
    nxt = tokens[i + 2 : i + 3] if tokens[i + 2 : i + 3] != ["time"] else tokens[i + 3 : i + 4]  # ("1.5 s time gap")
    before = tokens[max(i - 6, 0) : i]
    follows = any(w.startswith(("follow", "tailgat")) for w in before) and tokens[i - 1] in ("at", "about", "a")
    if not (nxt and nxt[0] in HEADWAY_WORDS) and not follows:
        return None
    ego = ego_speed_mps(tokens)
    if ego is not None:
        return float(tokens[i]) * ego
    for k in range(i - 1, 0, -1):
        if tokens[k] in V.SPEED_UNITS and tokens[k - 1].replace(".", "", 1).isdigit():
            return float(tokens[i]) * float(tokens[k - 1]) * V.SPEED_UNITS[tokens[k]]
    return None


#: Words that name the ego as the subject of its own speed ("ego 90 km/h", "I was doing 72 km/h").
_EGO_SUBJECTS = frozenset({"ego", "i", "we", "vut", "sv"})


def ego_speed_mps(tokens: list[str]) -> float | None:
    """The ego's speed (m/s) where the text gives it with its unit right after naming the ego (within
    four words of its clause: "Ego: 90 km/h", "I was doing 72 km/h"), else None. A time gap to the ego
    is covered at this speed: the ego's, or its follower's, who keeps pace with it."""
    for k, word in enumerate(tokens):
        if word not in V.SPEED_UNITS or not k or not tokens[k - 1].replace(".", "", 1).isdigit():
            continue
        for j in range(k - 2, max(k - 7, -1), -1):
            if tokens[j] in _STOPS or tokens[j] == ",":
                break
            if tokens[j] in _EGO_SUBJECTS:
                return float(tokens[k - 1]) * V.SPEED_UNITS[word]
    return None


def after_at(tokens: list[str], i: int) -> bool:
    """Whether a bare number at ``i`` follows "at" (or "doing") past an article and one modifier
    ("at a steady 50", "doing a brisk 30"): a speed, as "at 50" is."""
    return i >= 3 and tokens[i - 2] in _ARTICLES and tokens[i - 3] in ("at", "doing") and tokens[i - 1].isalpha()


#: ``mention_ending_at(k)``: the start of the road-user (or ego) mention whose last word is token ``k``.
Mentions = Callable[[int], "int | None"]


def carried_unit(tokens: list[str], i: int) -> float:
    """The factor to m/s of a bare speed at ``i`` ("I'm at 50"): the unit of the last speed said with
    one before it, else of the first said after it in its sentence, else km/h (the unit of a test
    engineer who gives none)."""
    for k in range(i - 1, 0, -1):
        if tokens[k] in V.SPEED_UNITS and tokens[k - 1].replace(".", "", 1).isdigit():
            return V.SPEED_UNITS[tokens[k]]
    for k in range(i + 1, len(tokens)):  # none before: the one said after it in its sentence ("at 30 and ... 20 mph")
        if tokens[k] in _STOPS:
            break
        if tokens[k] in V.SPEED_UNITS and tokens[k - 1].replace(".", "", 1).isdigit():
            return V.SPEED_UNITS[tokens[k]]
    return 1 / 3.6


def lateral(tokens: list[str], i: int, used: int) -> bool:
    """Whether the number at ``i`` (``used`` tokens with its unit) measures across the road: a lateral
    head in the three words before it or the two after it, within its clause."""
    for k in range(i - 1, max(i - 4, -1), -1):
        if tokens[k] in _STOPS or tokens[k] == ",":
            break
        if tokens[k] in LATERAL_HEADS:
            return True
    after = tokens[i + used : i + used + 2]
    return bool(after) and after[0] in LATERAL_HEADS


def _skip_back(tokens: list[str], j: int) -> int:
    while j >= 0 and tokens[j] in _LINKS:
        j -= 1
    return j


#: An owner the reader has no word for ("challenger speed 90 km/h"): a road user other than the ego.
UNNAMED = -1


def owners(
    tokens: list[str], i: int, unit: bool, mention_ending_at: Mentions, noun: Callable[[str], bool] = lambda w: False
) -> tuple[int, ...]:
    """The starts of the mentions the number at ``i`` is said of by grammar (empty where the grammar
    names none and the reader's reading of the clause decides). ``unit``: a speed unit follows it;
    ``noun(word)``: whether a word is only a noun (a name of someone, not "top" or "constant")."""
    j = _skip_back(tokens, i - 1)
    if j < 0:
        return ()
    if tokens[j] in SPEED_HEADS:  # "van speed 60 km/h"; "challenger speed 90 km/h": someone not the ego
        owner = mention_ending_at(j - 1)
        if owner is None and j >= 2 and tokens[j - 1] == "'s":  # "the bus's speed is 30 km/h"
            owner = mention_ending_at(j - 2)
        if owner is None and j and noun(tokens[j - 1]) and tokens[j - 2 : j - 1] not in (["the"], ["a"], ["its"]):
            return (UNNAMED,)
        return (owner,) if owner is not None else ()
    owner = mention_ending_at(j)
    if owner is not None:
        k = owner - 1
        while k >= 0 and tokens[k] in _DETERMINERS:
            k -= 1
        if k >= 1 and tokens[k] == "of" and tokens[k - 1] in SPEED_HEADS:  # "speed of the bus 15 km/h"
            return (owner,)
        if j == i - 1 and unit:  # "cyclist 15 km/h": said of the noun it stands after
            return (owner,)
        if unit and tokens[j + 1] == "at" and (k < 0 or tokens[k] in _CLAUSE_OPENERS):
            return (owner,)  # "the van at 60 km/h overtakes ...": said of the subject opening its clause
    if tokens[j] in _MOTION and j and tokens[j - 1] == "both":  # "... are both doing 50 km/h"
        j -= 1
    elif tokens[j] in _MOTION and unit and tokens[j - 1] not in _OBJECT_PRONOUNS:
        # "the ego drives at 40 km/h", "a tractor doing 15 mph": its subject's ("overtakes me doing 18 mph": not mine)
        k = j - 1
        while k > 0 and tokens[k] in _AUXILIARIES:  # ("the van was going 40 mph", "I was doing 50")
            k -= 1
        owner = mention_ending_at(k)
        return (owner,) if owner is not None else ()
    if tokens[j] == "both":  # "the ego and a lead truck both at 70 km/h"
        k = j - 1
        while k >= 0 and tokens[k] in ("are", "were", "is", "was"):
            k -= 1
        second = _mention_near(k, mention_ending_at)  # (past a word after it: "the van ahead")
        joint = next((a for a in range(second - 1, second - 4, -1) if a >= 1 and tokens[a] in ("and", "&")), None)
        first = None if joint is None else _mention_near(joint - 1, mention_ending_at)
        return (first, second) if first is not None and first >= 0 else ()
    return _key_of_line(tokens, i, mention_ending_at)


def _mention_near(k: int, mention_ending_at: Mentions) -> int:
    """The start of a mention ending at ``k`` or one word before it, else -1."""
    for end in (k, k - 1):
        start = mention_ending_at(end) if end >= 0 else None
        if start is not None:
            return start
    return -1


def _key_of_line(tokens: list[str], i: int, mention_ending_at: Mentions) -> tuple[int, ...]:
    """ "<road user> ...: 6 m ahead, 20 mph": the road user that keys the line the number is on, when
    no other road user is named between the key and the number."""
    start = i
    while start > 0 and tokens[start - 1] not in _STOPS:
        start -= 1
    colon = next((k for k in range(start, i) if tokens[k] == ":"), None)
    if colon is None or colon - start > 4:
        return ()
    key = next((s for k in range(start, colon) if (s := mention_ending_at(k)) is not None and s >= start), None)
    if key is None or any(mention_ending_at(k) is not None for k in range(colon + 1, i)):
        return ()
    return (key,)
