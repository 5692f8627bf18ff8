"""An act said as a noun after a light verb ("made a sudden swerve into my lane", "pulled a sharp turn
across us", "did a quick dart out"): English puts the act in the noun and leaves the verb ("make",
"do", "pull", "perform", "execute", "take") to carry tense and subject only. What the road user did is
what the noun's verb says, with the words that follow it: "made a sudden swerve into my lane" is
"swerved into my lane", suddenly.

Only a noun that is a verb too, and that with the words after it reads as an act the reader knows, is
taken so ("made a swerve into my lane"; not "made a phone call", "took a photo", "did a school run").
A light verb denied or only supposed ("didn't make a swerve", "could have made a swerve"), or in an
alternative set aside ("rather than make a swerve", "instead of making a swerve"), is left as it is:
nothing was done. Nor is a causative "make" one ("a bus made a car swerve"): a noun phrase that holds a
road user's noun is who was made to act, and the bare verb after it is that road user's.
"""

from __future__ import annotations

from collections.abc import Callable

from lemminflect import getInflection

from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.outcome import forgone

#: Verbs (lemmas) that take an act's noun as their object and say no more than that it was done.
LIGHT_VERBS = frozenset(("make", "do", "pull", "perform", "execute", "take"))
#: Words that open the noun phrase of the act ("a swerve", "his emergency stop").
_OPENERS = frozenset(("a", "an", "his", "her", "its", "their", "one"))
#: Words before the light verb that deny it or make it only supposed ("didn't make a swerve", "never did a
#: stop", "could have made a swerve").
_NOT_DONE = frozenset(
    ("not", "n't", "never", "didn't", "didnt", "don't", "doesn't", "no", "could", "would", "might", "should")
)
#: How many describing words may stand between the opener and the act's noun ("a very sudden swerve").
_DESCRIBING = 2


def _describes(word: str) -> bool:
    """Whether ``word`` may describe the act's noun: an adjective or a noun used as one ("sudden",
    "emergency", "late")."""
    pos = set(lemmas(word))
    return bool(pos & {"ADJ", "NOUN", "ADV"}) and word.isalpha()


def _in_the_form_of(noun: str, light: str) -> str:
    """The verb of act noun ``noun`` in the form light verb ``light`` has ("made" + "swerve":
    "swerved"; "makes" + "dive": "dives"), as the reader reads a verb: inflected, what a road user did.
    A compound ("turn-across") is left as it is; its own rule splits it."""
    if "-" in noun:
        return noun
    base = (lemmas(light).get("VERB") or (light,))[0]
    tag = "VB" if light == base else "VBG" if light.endswith("ing") else "VBZ" if light.endswith("s") else "VBD"
    return (getInflection(noun, tag) or (noun,))[0]


def acts_said_as_nouns(
    tokens: list[str], act_at: Callable[[list[str], int], int], road_user_at: Callable[[list[str], int], object]
) -> list[str]:
    """``tokens`` with each light verb + act noun said as the act ("made a sudden swerve into my lane":
    "sudden swerved into my lane"): the light verb and the noun phrase's opener go, the describing
    words stay before the act's verb (the reader reads "sudden" as how it was done). ``act_at(tokens,
    i)`` gives how many words from ``i`` the reader reads as a specific act (0: none);
    ``road_user_at(tokens, i)`` whether the reader reads a road user there (the noun phrase is then the
    one a causative "make" makes act, "a bus made a car swerve", no act's)."""
    out = list(tokens)
    i = 0
    while i + 2 < len(out):
        light = set(lemmas(out[i]).get("VERB", ())) & LIGHT_VERBS
        denied = any(w in _NOT_DONE for w in out[max(0, i - 2) : i]) or forgone(out, i)
        if not light or denied or out[i + 1] not in _OPENERS:
            i += 1
            continue
        for j in range(i + 2, min(i + 3 + _DESCRIBING, len(out))):
            noun = out[j]
            if road_user_at(out, j):
                break  # ("a bus made a car swerve": the car was made to swerve)
            said = set(lemmas(noun))
            as_verb = [*out[:i], _in_the_form_of(noun, out[i]), *out[j + 1 :]]
            if {"NOUN", "VERB"} <= said and act_at(as_verb, i) and not act_at(out, i):
                out[i : j + 1] = [*out[i + 2 : j], as_verb[i]]  # (the describing words stay before it)
                break
            if not _describes(noun):
                break
        i += 1
    return out


def set_aside(tokens: list[str], i: int) -> bool:
    """Whether the act at ``tokens[i]`` is in an alternative set aside, so not done: right after "rather
    than" or "instead of" ("rather than swerve, I braked") or as the noun of a light verb that is
    ("instead of making a sudden swerve")."""
    for j in range(i - 1, max(-1, i - 3 - _DESCRIBING), -1):
        if set(lemmas(tokens[j]).get("VERB", ())) & LIGHT_VERBS:
            return forgone(tokens, j)
    return forgone(tokens, i)
