"""A pull-in close in front of the ego told in a sentence of its own after an overtake: a cut-in of its own.

"A car overtook me and cut back in" tells one manoeuvre in one chain of clauses: an overtake ends by
getting back into the lane it left, and the pull-in only says how it ends (the reader folds it into
the overtake). Told in a sentence of its own, with its own place phrase ending at the ego ("The estate
swerves in two metres in front of our bonnet", "Then it dived in front of my car") and said to be
close there, the writer reports the pull-in as an event the ego met: a road user coming into its lane
close in front of it, a cut-in after the overtake.

Close is what the pull-in's clause says: a close manner on the scales of :mod:`manner` ("just in front
of me", "I had to brake"), an exact place ("right on my nose"), a few metres ("5 m ahead of the ego"),
or a verb of a sudden move sideways ("dived in", "swerved in", "cut in"); a wide margin ("with plenty of
room", "by a good 50 metres"; for the sudden verb, one said anywhere in its sentence: "cut back in front
of me, leaving plenty of room") or none said leaves the ordinary end of an overtake ("It pulled in ahead
of me").

In the same sentence (up to ". ! ?": a ";" or ":" joins two clauses of one sentence) a pull-in said
to end close in front of the ego is a cut-in too ("came past on my right and cut in right in front of
me"): the writer names the place the overtaker took, the ego's lane close ahead, not only that it got
back. A plain return there is the overtake's end: "back" with a verb that only says it went ("came
back in just in front of me", "pulled back in") tells the overtaker regaining its lane; "back" with a
verb of a sudden move sideways ("cut back in right in front of me") is a cut-in.

Guards: a pull-in whose place phrase names someone else ("behind a lorry well ahead of me", "in front of
the car ahead of me"), the ego from behind ("just behind me"), or no ego at all ("the van pulled back
in": an oncoming overtaker back to its own side) stays folded.
"""

from __future__ import annotations

from vei_scenario.language.clauses import sentence_start, sentence_stop
from vei_scenario.language.discourse import FIRST_PERSON
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.manner import (
    BREAKS,
    DANGEROUS,
    EXACTLY,
    METRES,
    MODERATE,
    SAFE,
    SMALL_SPARE_M,
    stated_manner,
)

#: The mark an overtake or a cut-in carries to the tidying of a road user's behaviours: where its sentence starts.
SENTENCE = "_sentence_start"
#: The mark a cut-in carries when its place phrase ends close at the ego (in its clause).
AT_EGO = "_at_the_ego"
#: The mark a cut-in carries when it is said as a plain return ("came back in"): see the module's docstring.
PLAIN_RETURN = "_plain_return"
#: What ends a sentence: a ";" or ":" joins two clauses of one.
_SENTENCE_ENDS = frozenset(".!?")
#: Words that name the ego after a verb: the narrator's object and possessive forms, or the ego itself.
_EGO_AFTER = (FIRST_PERSON - {"i", "we"}) | {"ego"}
#: How many words after a pull-in's verb may say where it ends ("in about two metres in front of our").
_WHERE_IT_ENDS = 10
#: Place words whose object ("of" + it) is where a pull-in ends, in front of it.
_IN_FRONT = frozenset(("front", "ahead"))
#: Place words whose object may be where a pull-in ends ("on my nose", "into my lane"), or only where
#: it goes on ("on the motorway", "into the gap").
_ONTO = frozenset(("on", "onto", "into"))
#: Place words of an end that is not in front ("pulled in just behind me", "alongside the van").
_NOT_IN_FRONT = frozenset(("behind", "alongside", "beside", "past", "after"))
#: Verbs of a sudden move sideways (the lexicon's "dive/lunge/swoop/... in front" of a cut-in), by lemma:
#: said of a pull-in, a close one.
_SUDDEN = frozenset(
    ("cut", "dive", "lunge", "swoop", "nip", "lurch", "duck", "dart", "swerve", "veer", "barge", "swing")
)


def _the_ego_at(tokens: list[str], k: int) -> bool:
    """Whether the noun phrase at ``k`` is the ego ("me", "my car", "the ego")."""
    return tokens[k : k + 1] != [] and tokens[k] in _EGO_AFTER or tokens[k : k + 2] == ["the", "ego"]


def _place(tokens: list[str], start: int, stop: int) -> int | None:
    """Where the place phrase of a pull-in whose verb is at ``tokens[start]`` ends at the ego, in its
    clause (up to ``stop``): the index of its place word, or None where it ends elsewhere or nowhere."""
    for k in range(start + 1, stop):
        w = tokens[k]
        if w in BREAKS or w in _NOT_IN_FRONT:
            return None  # (another clause: "pulled in and then braked hard in front of me")
        if w in _IN_FRONT and tokens[k + 1 : k + 2] == ["of"]:
            return k if _the_ego_at(tokens, k + 2) else None  # (not "in front of the car ahead of me")
        if w in _ONTO and _the_ego_at(tokens, k + 1):
            return k
    return None


def _metres(word: str) -> float | None:
    try:
        return float(word)
    except ValueError:
        return None


def _close(tokens: list[str], start: int, place: int, stop: int) -> bool:
    """Whether the pull-in at ``tokens[start]`` ending at the place word ``place`` is said to be close
    in its clause (up to ``stop``; see the module's docstring)."""
    clause = tokens[sentence_start(tokens, start, _SENTENCE_ENDS) : stop]
    measured = [
        v for k in range(start + 1, stop) if tokens[k + 1 : k + 2] != [] and tokens[k + 1] in METRES
        if (v := _metres(tokens[k])) is not None
    ]  # fmt: skip
    if measured:  # (before or after the place: "cuts in 5 m ahead of the ego", "into our lane 4 m ahead")
        return min(measured) <= SMALL_SPARE_M  # (not "40 m ahead")
    manner = stated_manner(clause)
    if manner is not None:
        return manner in (DANGEROUS, MODERATE)  # ("just in front of me"; not "with plenty of room")
    said = tokens[start + 1 : place + 1]
    if any(w in _IN_FRONT | _ONTO and said[k - 1 : k] != [] and said[k - 1] in EXACTLY for k, w in enumerate(said)):
        return True  # ("right on my nose")
    measure = any(_metres(w) is not None for w in tokens[place:stop])  # ("by a good 50 metres")
    sentence = tokens[sentence_start(tokens, start, _SENTENCE_ENDS) : sentence_stop(tokens, start, _SENTENCE_ENDS)]
    wide = stated_manner(sentence) == SAFE  # (said after the clause: "cut back in front of me, leaving plenty of room")
    return not measure and not wide and sudden(tokens[start])


def ends_close_at_the_ego(tokens: list[str], start: int) -> bool:
    """Whether the pull-in whose verb is at ``tokens[start]`` ends close in front of the ego, in its clause."""
    stop = start + 1
    while stop < min(len(tokens), start + _WHERE_IT_ENDS) and tokens[stop] not in BREAKS:
        stop += 1
    place = _place(tokens, start, stop)
    if place is None:  # ("cuts back in way too early": back before there was room)
        return too_soon(tokens, start)
    return _close(tokens, start, place, stop)


def too_soon(tokens: list[str], start: int) -> bool:
    """Whether the return whose verb is at ``tokens[start]`` ("cut back in", "came back into my lane") is
    said to come "too early", "too soon" or "too tight" in its clause: back before there was room, close
    in front of the one it passed."""
    if tokens[start + 1 : start + 2] != ["back"]:
        return False  # (a return: "cut in too soon" after passing someone else is that one's)
    stop = start + 1
    while stop < min(len(tokens), start + _WHERE_IT_ENDS) and tokens[stop] not in BREAKS:
        stop += 1
    return any(tokens[k] == "too" and tokens[k + 1] in _TOO_SOON for k in range(start + 1, stop - 1))


#: Said after "too" of a pull-in, how it ends close in front of the one passed: it came in before there
#: was room.
_TOO_SOON = frozenset(("early", "soon", "quickly", "sharply", "tight", "tightly"))


def mark(name: str, cfg: dict, tokens: list[str], start: int, end: int) -> None:
    """Mark on ``cfg`` (an overtake's or a cut-in's, said at ``tokens[start:end]``) the sentence it is
    told in, and for a cut-in whether it ends close in front of the ego."""
    if name not in ("overtake", "cut_in"):
        return
    cfg[SENTENCE] = sentence_start(tokens, start, _SENTENCE_ENDS)
    if name == "cut_in":
        cfg[AT_EGO] = ends_close_at_the_ego(tokens, start)
        cfg[PLAIN_RETURN] = _plain_return(tokens, start)


def sudden(word: str) -> bool:
    """Whether ``word`` is a verb of a sudden move sideways ("cut", "dived", "swerves")."""
    return bool(_SUDDEN & set(lemmas(word).get("VERB", ())))


def _plain_return(tokens: list[str], start: int) -> bool:
    """Whether the pull-in whose verb is at ``tokens[start]`` is said as a return with a verb that only
    says it went ("came back in", "pulled back in"), not as a sudden move ("cut back in")."""
    return tokens[start + 1 : start + 2] == ["back"] and not sudden(tokens[start])


def told_apart(overtake_cfg: dict, cut_in_cfg: dict) -> bool:
    """Whether a cut-in said right after an overtake is a move of its own: ending close in front of the
    ego, told in a later sentence, or in the same one unless as a plain return (see the module's docstring)."""
    first, then = overtake_cfg.get(SENTENCE), cut_in_cfg.get(SENTENCE)
    if first is None or then is None or then < first or not cut_in_cfg.get(AT_EGO):
        return False
    return then > first or not cut_in_cfg.get(PLAIN_RETURN)


def unmarked(cfg: dict) -> dict:
    """``cfg`` without the marks of this module."""
    return {k: v for k, v in cfg.items() if k not in (SENTENCE, AT_EGO, PLAIN_RETURN)}
