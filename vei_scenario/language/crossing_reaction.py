"""A brake or a stop said after a road user crossed the ego's way is the ego's reaction, not its own.

When a road user comes across the ego's path (steps out, pulls out of a side road, turns across,
runs the red, comes the wrong way), what the story says next of braking or stopping is nearly always
the one it came in front of: "... shoots out in front of me, I've stopped dead", "pulled out right in
front of her. She braked and missed it", "turns across him. OP brakes", "sees the rider late and
stops", "the brakes stopped me dead". The reader gives such a verb to the road user named last, and
the crossing gains a second behaviour, a hard stop the scenario then plays.

Told of the road user, its own stop says where it stands or follows its move as the next step:

* **placed in the road**: "stops dead in our lane", "stops in the middle of the road", "stopped
  neatly at the kerb", "slammed on in front of me": it stays there, a stop the scenario must play;
* **joined by "then"**: "pulls out then stops", "ran out and then froze": its own next act;
* **said with its own noun**: "a lad on a bike crossed ... the cyclist stopped": named again, it is
  the subject.

A road user that moves along the ego's lane (cuts in, overtakes, changes lane) and then brakes is
not read here: braking in front of the ego after a cut-in is a move of its own (a brake check).
"""

from __future__ import annotations

from collections.abc import Callable

from vei_scenario.language.clauses import sentence_start
from vei_scenario.language.ego import SENTENCE_END
from vei_scenario.language.lemmas import lemmas

#: Moves that bring a road user across the ego's path rather than along its lane.
CROSSING = frozenset(("cross_in_front", "turn_into", "turn_across", "run_red_light", "wrong_way"))
#: Behaviours of slowing or stopping.
SLOWING = frozenset(("sudden_stop", "stop", "change_speed"))
#: Behaviours of going on as before: no move that brings a road user anywhere.
_GOING_ON = frozenset(("keep_going", "keep_lane", "along_road", "follow_vehicle"))
#: Words that place a stop in the road: where the road user stands once stopped.
_IN_THE_ROAD = frozenset(
    ("middle", "lane", "road", "carriageway", "street", "kerb", "curb", "front", "centre", "center", "junction",
     "intersection", "island", "median", "roadway")
)  # fmt: skip
#: Prepositions of where something stands ("in", "at", "on", "across").
_AT = frozenset(("in", "at", "on", "across", "inside"))
#: How many words after the verb may say where it stops ("stops dead in the middle of our lane").
_WINDOW = 4


def placed_in_road(after: list[str]) -> bool:
    """Whether the words right after a stop (from its verb's last word) say where the road user
    stands ("dead in our lane", "in the middle of the road", "at the kerb"): a preposition of place,
    then a noun of the road."""
    window = after[:_WINDOW]
    return any(w in _AT and any(x in _IN_THE_ROAD for x in window[k + 1 :]) for k, w in enumerate(window))


#: The mark a slowing behaviour carries from its words to the pass over the finished reading.
MARK = "_said_free"


def said_free(name: str, cfg: dict, tokens: list[str], start: int, end: int, own_noun: Callable[[str], bool]) -> bool:
    """Whether slowing behaviour ``name`` (its parameters ``cfg``), said in ``tokens[start:end]``, is
    said free of the road user it was given to: not placed in the road (the words from its verb's last
    word on), not joined to a move before by "then" in its sentence and not said with the road user's
    own noun right before it (``own_noun``: whether a word names that road user). Speeding up ("he
    accelerated") is no reaction."""
    if name not in SLOWING:
        return False
    if name == "change_speed" and float(cfg.get("speed_delta_mps", -1.0)) > 0:
        return False
    sentence = tokens[sentence_start(tokens, start, SENTENCE_END) : start]
    if placed_in_road(tokens[max(0, end - 1) :][:_WINDOW]) or "then" in sentence:
        return False
    subject = _subject(sentence)
    if subject == "it" and any(own_noun(w) for w in sentence):
        return False  # ("we had a van pull out ... and it had to stop": the van its sentence is about)
    return not any(own_noun(w) for w in tokens[max(0, start - 2) : start]) and not own_noun(subject)


#: Words between a subject and its verb ("it had to stop", "the van was forced to brake").
_BETWEEN = frozenset(("had", "has", "have", "to", "was", "were", "is", "been", "just", "also", "forced", "did"))


def _subject(before: list[str]) -> str:
    """The word right before a verb once the auxiliaries between are passed ("it" in "it had to
    stop"), or "" where none is within a few words."""
    k = len(before) - 1
    while k >= 0 and len(before) - k <= _WINDOW and before[k] in _BETWEEN:
        k -= 1
    return before[k] if k >= 0 and len(before) - k <= _WINDOW else ""


def drop_egos_reactions(behaviours: list) -> list:
    """``behaviours`` (name, cfg, criticality, link) as read, without the slowing ones said free (see
    :func:`said_free`) right after a move across the ego's path: those are the ego's reaction to it.
    The mark is taken off the ones kept."""
    out: list = []
    for name, cfg, crit, link in behaviours:
        free = cfg.pop(MARK, None)
        last_move = next((b[0] for b in reversed(out) if b[0] not in SLOWING | _GOING_ON), None)
        if free and last_move in CROSSING:
            continue  # ("pulled out right in front of her. She braked": hers)
        out.append((name, cfg, crit, link))
    return out


#: Verbs (lemmas) of stopping, waiting or slowing for someone ("stopped for him", "waited for her").
_HOLDING = frozenset(("stop", "wait", "slow", "brake", "pause", "halt", "yield", "hold"))
#: Object pronouns that name whom a stop is made for (not "it": "waited for it to change" is a light).
_FOR_WHOM = frozenset(("him", "her", "them"))
#: Subject pronouns read here, each with the object pronoun of its own sex ("" for "it": any object).
_SUBJECTS = {"it": "", "he": "him", "she": "her"}
#: Marks that end a clause: a stop said after one is another clause's.
_CLAUSE_END = frozenset((",", ";", ":"))
#: How many words after its subject a stop made for someone is looked for.
_FOR_WINDOW = 10


def stops_for_another(tokens: list[str], start: int) -> bool:
    """Whether the clause of the pronoun subject at ``tokens[start]`` says a stop, a wait or a slowing
    made for someone an object pronoun names ("it just stopped and waited for him", "she slowed right
    down for them"): a verb of holding, then "for" and "him", "her" or "them", before the clause ends.
    Why: one who stops for a road user is not that road user; where that road user is the only one named,
    the one who stops for it is the ego. A person's pronoun of the other sex ("she waited for him") may
    name the road user as well as the object does, and "they" a group: neither is read."""
    subject = tokens[start]
    if subject not in _SUBJECTS:
        return False
    held = False
    for k in range(start + 1, min(start + 1 + _FOR_WINDOW, len(tokens))):
        word = tokens[k]
        if word in SENTENCE_END or word in _CLAUSE_END:
            return False
        held = held or bool(set(lemmas(word).get("VERB", ())) & _HOLDING)
        if held and word in _FOR_WHOM and tokens[k - 1] == "for":
            return _SUBJECTS[subject] in ("", word)
    return False
