"""What a road user on the ego's road does after a move into its lane, read as a test engineer means it.

A cut-in is a move into the ego's lane that ends close in front of it, slower than the ego: the road
user that "cut in and braked" (or "cut in, then braked") is settling in front, and the braking is how
its cut-in ends, not a second manoeuvre. Only a braking said in a hard or sudden manner ("braked
sharply", "hard brakes", "slammed on", "braked to a stop") is the sudden stop that follows a cut-in
in the brake-check scenario; the plain verb is not. A cut-in that ends an overtake of the ego ("overtook
me and cut back in front of me, then braked") is made by a road user faster than the ego, with nothing
to settle: the braking after it is a stop of its own, as after any overtake.

"Slow" said as how a road user goes ("a truck ahead going very slow", "a cyclist in my lane, really
slow", "riding slow") is its pace, as "the truck is slow" is: it keeps its lane at a low speed, no
change of speed. Only the verb ("slows", "began to slow", "slow down") is a slowing.

Passing "each other" or "one another" is two road users meeting, each going its own way: no one
overtakes anyone, so the verb of passing is no overtake of the road user it is said of.
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.motion import passes, said_hard

#: The bare verb of braking, in each form (no manner, no object: "braked", "brakes").
_PLAIN_BRAKE = frozenset(("brake", "brakes", "braked", "braking"))
#: Mentions that may stand between a cut-in and the braking said with it by the same road user
#: ("cut in front of me and then braked", "cut into the gap with 8 m to spare, then braked").
_BETWEEN = frozenset(
    ("conj", "punct", "link", "relation", "distance", "gap", "criticality", "relative", "unknown_verb")
)
#: Links that carry on the road user of the clause before ("..., then braked").
_GOING_ON = frozenset(("then", "and", "and then"))


#: Verbs (lemmas) of pressing with force whose object is the brakes ("slammed brakes", "stamped on the
#: brakes", "mashed the brakes"): a hard braking, whatever the manner said.
_FORCE = frozenset(("slam", "jam", "stamp", "stomp", "stand", "hit", "mash", "smash", "floor", "slap", "throw"))
#: Words that may stand between such a verb and the brakes ("on", "the", "his").
_TO_THE_BRAKES = frozenset(("on", "the", "a", "its", "his", "her", "their", "my", "our", "your", "both"))


def _pressed_with_force(tokens: list[str], i: int) -> bool:
    """Whether the brakes named at ``tokens[i]`` are the object of a verb of force before them, past
    "on" and a determiner ("slammed brakes", "stamped on his brakes", "mashed the brakes")."""
    j = i - 1
    while j >= 0 and i - j <= 3 and tokens[j] in _TO_THE_BRAKES:
        j -= 1
    return j >= 0 and bool(set(lemmas(tokens[j]).get("VERB", ())) & _FORCE)


def _plain_braking(m, tokens: list[str], nxt) -> bool:
    """Whether mention ``m`` is the bare verb of braking, said in no hard manner, not to a stop and
    not pressed with force (``nxt``: the mention after it)."""
    if m.slot != "behaviour" or m.value[0] != "sudden_stop" or m.words not in _PLAIN_BRAKE:
        return False
    to_a_stop = nxt is not None and nxt.slot == "to_stop"
    forced = _pressed_with_force(tokens, m.start)
    return not to_a_stop and not forced and not said_hard(tokens, m) and tokens[m.end : m.end + 1] != ["to"]


def _verb_before(mentions: list, k: int) -> int | None:
    """The verb before ``mentions[k]`` in its clause said by the same road user, or None: only places,
    gaps, links and the ego named as its object stand between (no new subject, no other verb)."""
    for j in range(k - 1, -1, -1):
        m = mentions[j]
        if m.slot == "behaviour":
            return j
        if m.slot in ("actor", "pronoun"):
            if m.value != "ego" or j == 0 or mentions[j - 1].slot not in ("relation", "behaviour"):
                return None  # (a new subject: "cut in, and I braked"; the ego as object only right after)
            continue
        if m.slot not in _BETWEEN:
            return None
    return None


def _ends_an_overtake(mentions: list, j: int) -> bool:
    """Whether the verb at ``mentions[j]`` follows an overtake by the same road user in its chain
    ("overtook me on the motorway and cut back in front of me"): no other verb, no road user but the
    ego between."""
    for m in reversed(mentions[:j]):
        if m.slot == "behaviour":
            return m.value[0] == "overtake"
        if m.slot in ("actor", "pronoun") and m.value != "ego":
            return False
    return False


def _cut_in_before(mentions: list, k: int) -> bool:
    """Whether the verb before ``mentions[k]`` (see :func:`_verb_before`) is a cut-in that settles in
    front of the ego: one that does not end an overtake."""
    j = _verb_before(mentions, k)
    return j is not None and mentions[j].value[0] == "cut_in" and not _ends_an_overtake(mentions, j)


def _carries_on(mentions: list, k: int) -> bool:
    """Whether ``mentions[k]`` opens its clause with no subject of its own, after "then" or "and"
    that carry on the road user of the clause before ("..., then braked")."""
    opening = mentions[:k]
    return (
        bool(opening)
        and all(m.slot in ("link", "conj", "punct") for m in opening)
        and any(m.words in _GOING_ON for m in opening)
    )


def braking_after_a_cut_in(clauses: list, tokens: list[str]) -> list:
    """``clauses`` without a plain braking said right after a cut-in by the same road user, in its
    clause or opening the next with "then" ("cut in and braked", "cut in front of us, then braked"):
    the braking is how the cut-in settles in front of the ego. A hard one stays a sudden stop, and so
    does one after the cut-in that ends an overtake (see the module's docstring)."""
    out: list = []
    last_cut_in = False  # (the clause before ended on a cut-in)
    for link, mentions in clauses:
        kept: list = []
        for k, m in enumerate(mentions):
            nxt = mentions[k + 1] if k + 1 < len(mentions) else None
            if _plain_braking(m, tokens, nxt):
                if _cut_in_before(mentions, k) or (last_cut_in and _carries_on(mentions, k)):
                    continue
            kept.append(m)
        verbs = [j for j, x in enumerate(kept) if x.slot == "behaviour"]
        last_cut_in = bool(verbs) and kept[verbs[-1]].value[0] == "cut_in" and not _ends_an_overtake(kept, verbs[-1])
        out.append((link, kept))
    return out


#: Verbs (lemmas) that with "in" or "over" say a move to the side of the road ("pulls in", "drew over").
_TO_THE_SIDE = frozenset(("pull", "draw"))
#: Mentions that may stand between pulling in and the stop said with it ("pulls in, and then stops").
_BEFORE_THE_STOP = frozenset(("conj", "punct", "link", "criticality", "speed_word"))


def _pulls_in(m, tokens: list[str]) -> bool:
    """Whether cut-in mention ``m`` is only "pull in" or "draw in" said with no place of the ego after
    it ("the bus pulls in and stops"; not "pulled in front of me", "pulled in ahead of us")."""
    words = m.words.split()
    if len(words) != 2 or words[1] != "in" or not _TO_THE_SIDE & set(lemmas(words[0]).get("VERB", ())):
        return False
    after = tokens[m.end : m.end + 3]
    return not (after[:1] and after[0] in ("front", "ahead", "before", "to", "into", "right", "just"))


def pulling_in_to_stop(clauses: list, tokens: list[str]) -> list:
    """``clauses`` without a "pull in" said right before the same road user stops ("the bus pulls in
    and stops at its stop", "it drew in, then halted", "the taxi ahead pulled in and stopped to drop
    someone off"): it pulls in to the side to stop there, a stop at the kerb, not a cut-in. Pulling
    in said with the ego's place ("pulled in right in front of me and stopped") stays a cut-in, and so
    does one that then brakes ("pulled in and braked")."""
    out: list = []
    gone: set[int] = set()  # (the stops said as the pull-in's end, by their start: read with it)
    for c, (link, mentions) in enumerate(clauses):
        kept: list = []
        for k, m in enumerate(mentions):
            if m.start in gone:
                continue
            if m.slot == "behaviour" and m.value[0] == "cut_in" and _pulls_in(m, tokens):
                rest = [x for x in mentions[k + 1 :] if x.slot not in _BEFORE_THE_STOP]
                if not rest and c + 1 < len(clauses):  # ("pulls in, then stops": the next clause)
                    rest = [x for x in clauses[c + 1][1] if x.slot not in _BEFORE_THE_STOP]
                if rest and _a_stop(rest[0]):
                    gone.add(rest[0].start)  # (one stop, said where the pull-in is: its subject's)
                    m = replace(m, value=("stop", {}))
            kept.append(m)
        out.append((link, kept))
    return out


def _a_stop(m) -> bool:
    """Whether mention ``m`` is a plain stop ("stops", "halted", "pulled up"), not a hard one."""
    return (m.slot == "behaviour" and m.value[0] == "stop") or m.slot == "stationary"


#: What a verb of passing is said of when two pass in opposite ways ("passed each other").
_RECIPROCAL = (["each", "other"], ["one", "another"])


def passing_each_other(clauses: list, tokens: list[str]) -> list:
    """``clauses`` without a verb of passing whose object is "each other" or "one another" ("they
    passed each other safely", "went past one another"): two meeting from opposite ways, an overtake
    by neither. ("passed each car" or "one car after another" still overtake.)"""
    return [
        (link, [m for m in mentions if not (passes(m) and tokens[m.end : m.end + 2] in _RECIPROCAL)])
        for link, mentions in clauses
    ]


#: Words that only make the adjective after them stronger ("very slow", "dead slow").
_INTENSIFIERS = frozenset(("very", "quite", "rather", "really", "extremely", "so", "too", "pretty", "super", "dead"))
#: Verbs (lemmas) of going along, after which "slow" says how ("going slow", "drove slow").
_GOING = frozenset(("go", "drive", "ride", "move", "travel", "cycle", "run", "come", "crawl", "trundle", "roll"))


def slow_as_a_pace(tokens: list[str], i: int) -> bool:
    """Whether the speed word at ``tokens[i]`` ("slow") is said as a pace, an adjective or adverb:
    after an intensifier ("very slow", "really slow"), or after a verb of going, past intensifiers
    ("going slow", "riding really slow"); not the verb ("began to slow", "they slow")."""
    j = i - 1
    intensified = False
    while j >= 0 and tokens[j] in _INTENSIFIERS:
        intensified = True
        j -= 1
    if intensified:
        return True
    return j >= 0 and tokens[j] != "to" and bool(set(lemmas(tokens[j]).get("VERB", ())) & _GOING)


#: Mentions that may stand between a verb and the place said after it ("came fully on our side, head-on").
_AFTER_A_VERB = frozenset(("relation", "punct", "criticality", "toward", "map", "speed"))
#: Mentions that may stand between a verb's object and the "and" that joins a second verb to it.
_JOINING = frozenset(("and", "then", "and then"))
_VERB_SLOTS = frozenset(("behaviour", "unknown_verb", "ego_verb", "turn"))
#: Words said of a verb's object before its noun ("a parked lorry", "two slow tractors").
_BEFORE_ITS_NOUN = frozenset(("stationary", "count", "member", "speed_adjective", "speed_word"))


def _a_verb_of_its_own(m) -> bool:
    """Whether place mention ``m`` opens with its verb ("came straight at me", "heading for us")."""
    first = m.words.split()[0]
    return m.slot == "relation" and "VERB" in lemmas(first) and first.endswith(("ed", "ing", "s", "came", "ran"))


def after_a_second_verb(mentions: list, k: int) -> bool:
    """Whether the place ``mentions[k]`` is said after a second verb joined by "and" or "then" to a
    first verb with an object ("was overtaking a truck and came onto our side, head-on towards us"):
    the second verb has the first one's subject, so the place is the subject's, not the object's."""
    j = k if _a_verb_of_its_own(mentions[k]) else k - 1
    while j >= 0 and mentions[j].slot in _AFTER_A_VERB and j < k:
        j -= 1
    if j < 1 or not (mentions[j].slot in _VERB_SLOTS or _a_verb_of_its_own(mentions[j])):
        return False
    j -= 1
    joined = False
    while j >= 0 and mentions[j].slot in ("conj", "link", "punct"):
        joined = joined or mentions[j].words in _JOINING
        j -= 1
    if not joined or j < 1 or mentions[j].slot != "actor" or mentions[j].value == "ego":
        return False
    j -= 1
    while j > 0 and mentions[j].slot in _BEFORE_ITS_NOUN:
        j -= 1
    return mentions[j].slot in _VERB_SLOTS  # (that one the first verb's object)


#: Words between "before" and the ego it is said of ("before the ego", "before my car").
_BEFORE_THE_EGO = frozenset(("the", "my", "our"))


def before_as_a_place(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with "before" said right after a road user's noun and right before the ego ("the
    bus before ego car is stopping", "car before me change lane") read as the place it is, in front of
    the ego, as "the bus in front of me": a subject whose verb is still to come takes no clause of
    time there, and "before me" has an object, not a clause. "Before" after a verb or a comma stays a
    conjunction ("it braked before I could react", "the car, before we got there, stopped")."""
    out: list = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k in range(1, len(kept) - 1):
            m, last, nxt = kept[k], kept[k - 1], kept[k + 1]
            if m.slot != "conj" or m.words != "before" or last.slot != "actor" or last.value == "ego":
                continue
            between = tokens[m.end : nxt.start]
            if last.end == m.start and nxt.slot == "actor" and nxt.value == "ego" and set(between) <= _BEFORE_THE_EGO:
                if nxt.words in ("i", "we"):
                    continue  # ("the car before I ...": a clause)
                kept[k] = replace(m, slot="relation", value="ahead")
        out.append((link, kept))
    return out


#: The ego as the object of a verb ("cut me up", "cut the ego up").
_EGO_OBJECTS = frozenset(("me", "us", "ego"))


def cut_up(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a cut-in said as "cut" the ego "up" ("cut me up", "cut us up at the lights",
    "cut the ego up", "cut me right up") marked as going the ego's way: to cut someone up is to move into their lane
    close in front of them, never to cross their road, even at a junction."""
    out: list = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            if (
                m.slot != "behaviour"
                or m.value[0] != "cut_in"
                or "cut" not in lemmas(m.words.split()[-1]).get("VERB", ())
            ):
                continue
            after = tokens[m.end : m.end + 4]
            if after[:1] == ["the"]:
                after = after[1:]
            if after[:1] and after[0] in _EGO_OBJECTS and "up" in after[1:3] and after[1] in ("up", "right"):
                kept[k] = replace(m, value=(m.value[0], {**m.value[1], "_same_way": 1.0}))
        out.append((link, kept))
    return out
