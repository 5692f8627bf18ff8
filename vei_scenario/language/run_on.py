"""Where a text run on without its stops opens a new clause the writer left unmarked.

Why: a spoken or hurried text ("I was doing 20 mph a van pulled out in front of me", "coming up the
road about 20 mph wee guy on a scooter shoots out") runs the narrator's speed straight into the next
road user's sentence. Read as one clause, that road user's verb goes to the narrator and the road
user is left doing nothing. A speed said with its unit ends what the narrator says of itself, so a
road user named right after it opens a clause of its own: the reader puts the comma back there. So
does a bare number ("while I was at 30 a car pulled out") with a determiner right after it: a number
and "a", "the" or "this" never make one noun phrase, so the determiner opens the next one.
"""

from __future__ import annotations

import re
from collections.abc import Callable

#: Units that end a speed said as a number ("20 mph", "40 km/h").
_SPEED_UNITS = frozenset(("mph", "km/h", "kph", "kmh", "kmph", "m/s"))
#: Words that may open a road user's noun phrase ("a van", "the cyclist", "this guy").
_OPENS_A_NAME = frozenset(("a", "an", "the", "this", "some", "one"))
#: A number said without its unit ("at 30", "doing 12.5").
_BARE_NUMBER = re.compile(r"\d+(\.\d+)?")
#: Object pronouns: what stands right after one is no part of its noun phrase.
_OBJECTS = frozenset(("me", "us", "him", "her", "them"))
#: The narrator as a subject: never an object, so after an object pronoun it opens a clause.
_NARRATOR = frozenset(("i", "we"))


def _names_a_road_user(tokens: list[str], j: int, actor_at: Callable[[list[str], int], bool], idle: set[str]) -> bool:
    """Whether a road user's noun phrase starts at ``j``: an opening word at most, then up to two words
    that are no function words ("wee", "white"), then a road user's name."""
    if j < len(tokens) and tokens[j] in _OPENS_A_NAME:
        j += 1
    for k in range(j, min(j + 3, len(tokens))):
        if actor_at(tokens, k):
            return True
        if tokens[k] in idle or not tokens[k].isalpha():
            return False
    return False


def break_after_a_speed(tokens: list[str], actor_at: Callable[[list[str], int], bool], idle: set[str]) -> list[str]:
    """``tokens`` with a comma put between a speed with its unit and a road user named right after it
    ("doing 20 mph a cyclist shot out", "at 30 km/h the bus ahead braked"): the road user opens a
    clause of its own. A word before the road user that links it to the speed or the narrator
    ("20 mph behind a bus", "20 mph towards a cyclist", "20 mph with a van") keeps it in the clause;
    so does a speed said of the road user before its name ("a 60 mph car"). And a comma put before
    "I" or "we" right after an object pronoun ("cut in front of us we braked")."""
    out: list[str] = []
    for i, tok in enumerate(tokens):
        if tok in _NARRATOR and i and tokens[i - 1] in _OBJECTS:
            out.append(",")  # ("shot out in front of me I braked": the narrator's clause)
        out.append(tok)
        if _bare_number_then_a_name(tokens, i):
            if _names_a_road_user(tokens, i + 1, actor_at, idle):
                out.append(",")  # ("while I was at 30 a car pulled out")
            continue
        if tok not in _SPEED_UNITS or not i or not tokens[i - 1][:1].isdigit():
            continue
        if i > 1 and tokens[i - 2] in _OPENS_A_NAME:
            continue  # ("a 60 mph car": the speed says what the road user is like)
        if _names_a_road_user(tokens, i + 1, actor_at, idle):
            out.append(",")
    return out


def _bare_number_then_a_name(tokens: list[str], i: int) -> bool:
    """Whether ``tokens[i]`` is a number with no unit right before a determiner ("at 30 a car", "doing
    40 the bus"): the two are never one noun phrase, so the number ends its clause. A number that is
    itself part of a name ("a 30 zone", "the 42 bus") has its own determiner before it."""
    if not _BARE_NUMBER.fullmatch(tokens[i]) or tokens[i + 1 : i + 2] == [] or tokens[i + 1] not in _OPENS_A_NAME:
        return False
    return not (i and tokens[i - 1] in _OPENS_A_NAME)
