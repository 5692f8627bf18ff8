"""A walker or rider said to go "across" with no way named after it: a crossing of the ego's road.

Writers in a hurry (a dashcam voiceover, a note, a comic's panel) tell a crossing by its adverb alone:
"a lad on a scooter fires straight out, straight across", "an e-scooter out from between two parked
vans, straight across in front", "came off the pavement and across the front of the bus", "Left
pavement. Straight across." "Across" with no object of its own (or with only the front of someone as
its object) says that the one it is told of goes from one side of the road to the other, in front of
the ego: the road it crosses is the one the scene is on, the ego's. Its verb may be missing, a plain
going ("came ... and across") or one the reader has no word for ("fires"); the adverb carries the
move. The road user is the subject of its clause, or, in a clause with none ("Straight across."), the
road user named last before it.

What must not be read so: "across" that has a way of its own as its object ("across the junction",
"across the car park", "across two lanes": what it crosses is said, and read elsewhere), one said of
where someone is ("parked across the drive"), one told with a direction that puts it elsewhere than in
front of the ego ("across behind me", "across the back of the bus"), an "across" already inside a
phrase the reader knows ("walked across", "waved across"), one said of the ego or of a vehicle (a
vehicle across the ego's path goes through a junction, read elsewhere), a road user whose clause
already says it crosses, stops or gives way, one that turns ("swings right across the front of my car":
the way of the turn, read with it), one told with a verb of looking, calling or gesturing ("looked
across", "shouted across": where one looks or calls, no going), one denied ("Not across, just
waiting"), one in front of another road user than the ego ("then across, in front of the van": not
the ego's road crossed before it, and the van stays a road user of its own), and one said to go on
with a going already under way ("keeps going across in front of us", "carries on across": it is on
the road, and its way crosses the ego's there, not from a kerb).
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.discourse import PUNCT, VULNERABLE
from vei_scenario.language.function_words import CLAUSE_BREAKS, FIRST_PERSON
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.lexicon import LOOKING_OR_SIGNALLING, OBJECT_PREPOSITIONS
from vei_scenario.language.settings import NEGATORS

#: The adverb of going from one side to the other.
_ACROSS = "across"
#: Words after "across" that say it has no way of its own as object: the end of what is said.
_ENDS = PUNCT | CLAUSE_BREAKS | {"-", "–", "—"}
#: Negators that deny a going or an adverb ("not across", "never went across"); "no" and "without"
#: deny a noun ("with no warning straight across").
_DENYING = NEGATORS - {"no", "without"}
#: Words after "across" that put the crossing in front of someone ("across in front", "across the front of").
_IN_FRONT = (("in", "front"), ("infront",), ("the", "front", "of"), ("ahead",))
#: How far after "across" the road user of such a front may stand (", in front of the white van").
_FRONT_WORDS = 7
#: Road users who cross on foot or on small wheels, or whose kind the reader settles from what they do.
_CROSSERS = VULNERABLE | {"unknown"}
#: Mentions that stand for a road user named before (whose kind the reader settles later).
_STAND_INS = frozenset(("pronoun", "member"))
#: Plain goings: a verb of going with nothing said of which way ("came", "went", "rode").
_PLAIN_GOINGS = frozenset(("keep_going", "along_road"))
#: What a road user's clause may already say of it that a bare "across" adds nothing to.
_SAID_ALREADY = frozenset(("cross_in_front", "stop", "sudden_stop", "give_way", "wrong_way", "run_red_light"))


def _no_way_after(tokens: list[str], j: int) -> bool:
    """Whether "across" at ``tokens[j]`` has no way of its own as its object: the text or clause ends
    after it, or only the front of someone follows ("across in front", "across the front of the bus")."""
    rest = tokens[j + 1 : j + 4]
    if not rest or rest[0] in _ENDS:
        return True
    return any(tuple(rest[: len(words)]) == words for words in _IN_FRONT)


def _verb_before(tokens: list[str], j: int) -> int | None:
    """Where the verb nearest before "across" at ``tokens[j]`` stands in its phrase (back to the end of
    the phrase before it), or None: a word read only as a verb or noun, not an adverb ("straight") or
    adjective ("left")."""
    for k in range(j - 1, -1, -1):
        if tokens[k] in _ENDS:
            return None
        pos = lemmas(tokens[k])
        if "VERB" in pos and not pos.keys() & {"ADJ", "ADV"}:
            return k
    return None


def _no_going(tokens: list[str], j: int) -> bool:
    """Whether "across" at ``tokens[j]`` tells no going: its verb one of looking, calling or gesturing
    ("looked across", "shouted across": where one looks or calls), or the adverb or its verb denied
    ("Not across, just waiting", "did not go across")."""
    v = _verb_before(tokens, j)
    if v is not None and set(lemmas(tokens[v])["VERB"]) & LOOKING_OR_SIGNALLING:
        return True
    return any(k >= 0 and tokens[k] in _DENYING for k in (j - 1, -1 if v is None else v - 1))


def _in_front_of_another(mentions: list, k: int, tokens: list[str], j: int) -> bool:
    """Whether "across" at ``tokens[j]`` is told in front of a road user other than the ego ("then
    across, in front of the van"): the road user named first after it (from mention ``k`` of its
    clause), within the phrase of its front ("in front of the van", "the front of a lorry"). That
    crossing is not the ego's road crossed before the ego, and the van stays a road user of its own.
    Only where the ego is told by a first person before it: in a report with none ("across the front
    of the bus" told of a bus driver's account) the vehicle may be the ego's own."""
    if not FIRST_PERSON & set(tokens[:j]):
        return False
    after = next((m for m in mentions[k:] if m.slot == "actor" or (m.slot == "punct" and m.start > j + 1)), None)
    return after is not None and after.slot == "actor" and after.start <= j + _FRONT_WORDS and after.value != "ego"


def _covered(clauses: list, j: int) -> bool:
    """Whether ``tokens[j]`` lies within a phrase some mention already reads ("walked across")."""
    return any(m.start <= j < m.end for _, mentions in clauses for m in mentions)


def _clause_at(clauses: list, j: int) -> int | None:
    """The index of the clause ``tokens[j]`` belongs to: the last one whose first mention starts at or
    before it (None before any)."""
    at = None
    for c, (_, mentions) in enumerate(clauses):
        if mentions and mentions[0].start <= j:
            at = c
    return at


def _a_mover(mentions: list, k: int, tokens: list[str]) -> bool:
    """Whether the road user named at mention ``k`` may be the one that moves: not one named as the
    object of a preposition ("from between two parked vans", "in front of the bus") or said to stand."""
    m = mentions[k]
    if k and mentions[k - 1].slot == "stationary" and mentions[k - 1].end >= m.start - 1:
        return False  # ("two parked vans")
    for w in tokens[max(0, m.start - 3) : m.start]:
        if w in OBJECT_PREPOSITIONS:
            return False
    return True


def _subject(mentions: list, k: int, tokens: list[str]):
    """The road user a move at mention position ``k`` of its clause is told of: the last road user
    named before it that may move, or None where none is named in the clause."""
    for i in range(k - 1, -1, -1):
        x = mentions[i]
        if x.slot in ("actor", "pronoun", "member") and _a_mover(mentions, i, tokens):
            return x
    return None


def _last_named(clauses: list, mentions: list):
    """The road user other than the ego named last in ``clauses`` and then ``mentions``, or None."""
    found = None
    for ms in [m for _, m in clauses] + [mentions]:
        found = next((x for x in reversed(ms) if x.slot == "actor" and x.value != "ego"), found)
    return found


def across_alone(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a walker's or rider's bare "across" read as the crossing it tells: a plain going
    told of it before the adverb in its clause becomes the crossing; with no verb read, the crossing
    is added where the adverb stands."""
    out = [(link, list(mentions)) for link, mentions in clauses]
    for j, word in enumerate(tokens):
        if word != _ACROSS or _covered(out, j) or not _no_way_after(tokens, j) or _no_going(tokens, j):
            continue
        c = _clause_at(out, j)
        if c is None:
            continue
        mentions = out[c][1]
        k = next((i for i, m in enumerate(mentions) if m.start > j), len(mentions))
        if _in_front_of_another(mentions, k, tokens, j):
            continue  # ("across, in front of the van": not the ego's road crossed before it)
        subject = _subject(mentions, k, tokens)
        if subject is None and any(m.slot in ("behaviour", "actor") for m in mentions[:k]):
            continue  # (someone else's move, or the ego's)
        if subject is None or subject.slot in _STAND_INS:  # (none said: the road user named last)
            subject = _last_named(out[:c], mentions[: mentions.index(subject)] if subject else [])
        if subject is None or subject.value not in _CROSSERS:
            continue
        since = [m for m in mentions[:k] if m.start > subject.start]
        if any((m.slot == "behaviour" and m.value[0] in _SAID_ALREADY) or m.slot == "turn" for m in since):
            continue  # (a turn's "across" is the way it turns: "swings right across the front of my car")
        if any(m.slot == "actor" and m.value == "ego" and m.prev not in OBJECT_PREPOSITIONS for m in since):
            continue  # (the ego is the one said to move here)
        moves = [i for i in range(k) if mentions[i] in since and mentions[i].slot == "behaviour"]
        if moves and mentions[moves[-1]].value[0] in _PLAIN_GOINGS and len(mentions[moves[-1]].words.split()) == 1:
            mentions[moves[-1]] = replace(mentions[moves[-1]], value=("cross_in_front", {}))
        elif not moves:
            crossing = replace(
                subject, slot="behaviour", value=("cross_in_front", {}), words=_ACROSS, start=j, end=j + 1,
                prev=tokens[j - 1] if j else "", next_=tokens[j + 1] if j + 1 < len(tokens) else "", det="",
                owners=(),
            )  # fmt: skip
            mentions.insert(k, crossing)
    return out
