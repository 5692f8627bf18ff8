"""Where a text run on without its stops opens a new clause the writer left unmarked.

Why: a spoken or hurried text ("I was doing 20 mph a van pulled out in front of me", "coming up the
road about 20 mph wee guy on a scooter shoots out") runs the narrator's speed straight into the next
road user's sentence. Read as one clause, that road user's verb goes to the narrator and the road
user is left doing nothing. A speed said with its unit ends what the narrator says of itself, so a
road user named right after it opens a clause of its own: the reader puts the comma back there.
"""

from __future__ import annotations

from collections.abc import Callable

#: Units that end a speed said as a number ("20 mph", "40 km/h").
_SPEED_UNITS = frozenset(("mph", "km/h", "kph", "kmh", "kmph", "m/s"))
#: Words that may open a road user's noun phrase ("a van", "the cyclist", "this guy").
_OPENS_A_NAME = frozenset(("a", "an", "the", "this", "some", "one"))
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
        if tok not in _SPEED_UNITS or not i or not tokens[i - 1][:1].isdigit():
            continue
        if i > 1 and tokens[i - 2] in _OPENS_A_NAME:
            continue  # ("a 60 mph car": the speed says what the road user is like)
        if _names_a_road_user(tokens, i + 1, actor_at, idle):
            out.append(",")
    return out
