"""What a road user does, settled from the behaviours its clauses gave it: one path per road user.

A clause often says a road user's path and its manner in two verbs ("proceeds against the red
signal, passing the ego"; "emerged from the left against a red signal"; "stops at the give-way line
and waits"). The reader reads each verb, so the manner arrives as a second behaviour. These rules
keep the path:

* running the red light is the whole of a road user's path across the junction: a pass of the ego
  or an emergence from an arm said with it is how it goes, not a second manoeuvre;
* passing the ego and then turning across its path (a "left hook") is the turn: the pass is how
  the road user gets ahead to make it;
* a road user on a junction arm that only stops (and waits) is giving way: that is what stopping at
  the line of a side road is;
* a rider going along the road against the traffic, said to be on the wrong side and not at the
  kerb, is coming head-on in the ego's lane: the wrong-way rider, not one riding along the edge;
* a road user heading one compass way in the lane of the other ("southbound in the northbound
  lane") is driving the wrong way in that lane;
* where the only two headings a narrative gives are opposite ("V2, eastbound, ... V1, which was
  westbound"), the road user is coming the other way: its left turn across the ego's path is the
  turn across an oncoming path (its right turn, where the text says traffic keeps left).

A verb with the particle "out" and "of" or "from" a side road ("pops out of a side street", "shot
out from the side road") is coming out of that road, whatever the verb: the reader reads it as it
reads "comes out of" (a walker then crosses; a rider or a vehicle enters from that arm).

A move whose destination is the ego's lane or path ("swung out into my lane", "moved across into
the ego's lane", "swerves out of the bike lane into my lane") is a cut-in, whatever the verb: the
destination says what the move is, the verb only how it is made.

"Give" with the ego as its first object and the way as its second ("gives me the way", "gave us
priority", "gives the ego the right of way") is giving way, the ditransitive form of "give way".

A side road or exit said after "into", "onto" or "to" is where a road user goes, not where it
comes from: "swung across my lane to turn into one of the side roads on the right" is a turn off the
ego's road (across it, from the lane it was in), not an emergence from that side road.

Some verbs a clause holds are no behaviour at all but the outcome (read by
:mod:`vei_scenario.language.outcome`): a verb of contact whose subject is both parties ("they are
crashing", "we collided") and "yield" with an object ("designed to yield a collision": to produce).
"""

from __future__ import annotations

import re
from dataclasses import replace

from vei_scenario.language.clauses import SENTENCE_END
from vei_scenario.language.cut_back_in import sudden_returns_at_the_ego
from vei_scenario.language.discourse import VEHICLES, VULNERABLE
from vei_scenario.language.function_words import EGO_LANE_OWNERS, FIRST_PERSON, SUBJECT_PRONOUNS
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.not_told import asked_of
from vei_scenario.language.own_way import REFLEXIVES, past_its_own_object
from vei_scenario.language.quantities import OBJECT_PRONOUNS, SECONDS
from vei_scenario.language.reading import ActorSpec
from vei_scenario.language.settings import FOOT_CROSSINGS, negated
from vei_scenario.language.sides import OFF_ROAD_PLACES, VEHICLE_PARTS, stated_side
from vei_scenario.language.word_mention import word_mention

#: Behaviours that, said with running the red, are the manner of that run.
_MANNER_OF_A_RUN = frozenset(("overtake", "turn_into"))
#: Words that say a light or signal is there to be run.
_RED_SAID = re.compile(r"\b(red|amber|lights?|signals?|signalised|signalized)\b")
_ARMS = frozenset(("junction_left", "junction_right", "junction_opposite"))


def head_on(spec: ActorSpec, against_traffic: bool) -> list:
    """``spec``'s behaviours, with riding along the road against the traffic (``against_traffic``:
    said as the wrong way or side) away from the kerb read as driving head-on in the ego's lane."""
    names = [b[0] for b in spec.behaviours]
    if against_traffic and names == ["along_road"] and spec.facing == "against" and spec.lateral_m is None:
        _, cfg, crit, link = spec.behaviours[0]
        return [("wrong_way", {}, crit, link)]
    return spec.behaviours


#: Words that own a lane, path or side as the ego's ("my lane", "our side of the road", "the ego's path").
_EGO_OWNER_WORDS = frozenset(("my", "our", "ego", "ego's", "av's", "sv's", "ev's"))
_WAYS = frozenset(("lane", "path", "side"))


def in_the_ego_lane(words: str) -> bool:
    """Whether a relation said as ``words`` puts its road user in the ego's own lane, path or side of
    the road ("in my lane", "on our side of the road", "down the ego's lane"), not merely in front
    ("ahead", "in front of us") nor in its own lane ("in its lane")."""
    said = [w for w in words.replace(" 's", "'s").split() if w != "own"]  # ("in my own lane")
    return any(a in _EGO_OWNER_WORDS and b in _WAYS for a, b in zip(said, said[1:]))


def its_lane_the_egos(words: str, prev: str, said: set) -> bool:
    """Whether "in its lane" (``words``) said right after the ego (``prev``) of a road user already
    said to come at it (``said``: "oncoming") is the ego's lane ("coming towards the ego in its lane",
    "rides at the test vehicle in its lane"): the possessive owns the nearest noun, the ego. Not
    after anything else ("overtook the ego and stayed in its lane": its own, after its own verb), nor
    of a road user going the ego's way ("rides ahead of the ego in its lane": one lane for both)."""
    return [w for w in words.split() if w != "own"] == ["in", "its", "lane"] and prev == "ego" and "oncoming" in said


#: What a road user coming at the ego in its lane may be said to do besides: go on, move about in
#: that lane (a swerve said with no subject is often the narrator's), or swerve out of it at the last
#: moment ("came head-on and swerved out"), as one going back to its side does.
_HEAD_ON_MOVES = frozenset(("keep_going", "along_road", "cut_in", "change_lane", "cut_out", "wrong_way", "keep_lane"))


def comes_head_on(
    names: list[str], wrong_way: bool, said: set, passes_another: bool = True, returns: bool = False
) -> bool:
    """Whether a road user with behaviours ``names``, said to go the wrong way (``wrong_way``) and
    said the relations ``said``, is driving or riding head-on in the ego's lane: against the traffic
    (the wrong way, or coming towards the ego) and in the ego's lane (``"in_ego_lane"``), or the wrong
    way and towards the ego. Its path is the wrong-way one whatever plain verb says it goes, and
    wherever the ego is (a roundabout, a junction); a turn is a path of its own, and so is an
    overtake of another road user (``passes_another``). Going past the ego, or "passing each other",
    is how a road user coming head-on meets it ("squeezed past me", "passed 1 m off our left side"):
    no overtake, as it never drove the ego's way; so one said to come the wrong way that only goes
    past the ego ("came the wrong way down the lane and squeezed past me") is coming head-on too. One
    coming towards the ego that goes back to its own side or lane (``returns``: "swerved back over at
    the last second") was out of it, on the ego's side: head-on too, however its coming was said. One
    coming towards the ego in the middle of the road (``"mid_road"``) is half on the ego's side."""
    against = wrong_way or "oncoming" in said
    meets = wrong_way and not passes_another and "overtake" in names  # (the wrong way, then past the ego)
    middle = "mid_road" in said and "oncoming" in said  # ("down the middle of the road towards me")
    placed = "in_ego_lane" in said or (wrong_way and "oncoming" in said) or meets or returns or middle
    moves = _HEAD_ON_MOVES if passes_another else _HEAD_ON_MOVES | {"overtake"}
    return against and placed and bool(names) and set(names) <= moves


def manner_compound(tokens: list[str], i: int, behaviour_at) -> list[str] | None:
    """The words a hyphenated manner + verb at ``tokens[i]`` says ("hard-brakes": "brakes hard",
    "emergency-brakes": "emergency brakes", "panic-brakes": "panic brakes"), or None: the verb is the
    compound's head (its last part), the first part how it is done. The order that makes a longer
    phrase of the lexicon wins; the verb alone is read where neither does. ``behaviour_at(tokens,
    i)`` gives how many words from ``i`` read as a specific behaviour (0: none, nor a plain motion)."""
    tok = tokens[i]
    if tok.count("-") != 1 or behaviour_at(tokens, i) or not all(tok.split("-")):
        return None
    manner, verb = tok.split("-")
    if "VERB" not in lemmas(verb) or not behaviour_at([verb], 0):
        return None
    best = max(([verb, manner], [manner, verb]), key=lambda pair: behaviour_at(tokens[:i] + pair + tokens[i + 1 :], i))
    return best


#: Subjects that are both parties of a contact: the verb is what happened between them.
_BOTH = frozenset(("they", "we", "both", "us"))
#: Verbs of contact a behaviour may be read from ("the rider crashes": it falls).
_CONTACT = frozenset(("crash", "crashes", "crashed", "crashing", "collide", "collides", "collided", "colliding", "hit",
                      "hits", "hitting", "smash", "smashed", "smashes", "smashing"))  # fmt: skip


#: Verbs (lemmas) of touching another road user: a fall said after one is what the contact did.
_TOUCH = frozenset(("hit", "strike", "clip", "collide", "crash", "smash", "touch", "bump", "knock", "tap", "graze"))


def _touched_before(tokens: list[str], i: int) -> bool:
    """Whether a verb of contact stands before token ``i`` in its sentence ("struck", "clipped")."""
    for tok in reversed(tokens[:i]):
        if tok in (".", "!", "?", ";"):
            return False
        if set(lemmas(tok).get("VERB", ())) & _TOUCH:
            return True
    return False


#: Words between a verb of contact and the preposition of what it meets ("crashed head-on into").
_HOW_IT_MEETS = frozenset(("head-on", "headlong", "straight", "right", "full", "square", "squarely", "directly"))


#: Parts of a road user said as what was met ("into the side of my car").
_MET_PARTS = frozenset(("side", "back", "rear", "front", "nose", "tail", "flank", "door", "wing", "bumper"))


def _into_someone(tokens: list[str], j: int) -> bool:
    """Whether "into" or "with" and a road user (or a part of one) follow a verb of contact ending at
    token ``j`` ("crashed into a cyclist", "collided head-on with the bus", "smashed into the side of
    my car"): it states whom it met, the contact itself, not a fall or a stop of its own ("crashed
    into the barrier" is still how it stopped)."""
    from vei_scenario.language.outcome import names_road_user

    while j < len(tokens) and tokens[j] in _HOW_IT_MEETS:
        j += 1
    if j >= len(tokens) or tokens[j] not in ("into", "with"):
        return False
    obj = tokens[j + 1 : j + 8]
    k = next((k for k, w in enumerate(obj[:4]) if w in _MET_PARTS and obj[k + 1 : k + 2] == ["of"]), None)
    obj = obj[k + 2 :] if k is not None else obj  # ("the side of my car": my car)
    return names_road_user(obj) or obj[:1] in (["me"], ["us"], ["ego"]) or obj[:2] == ["the", "ego"]


#: Modals of what would have happened ("could have crashed"): the contact did not happen.
_COUNTERFACTUAL = frozenset(("would", "could", "might", "nearly", "almost"))


def _nearly(tokens: list[str], i: int) -> bool:
    """Whether the verb of contact at token ``i`` is hedged ("nearly crash", "very nearly collided",
    "almost crashing") or counterfactual ("could have crashed"): the contact was only nearly had, so
    the verb states a near miss (the outcome), not a fall or a stop the road user makes."""
    from vei_scenario.language.outcome import HEDGES

    if i >= 1 and tokens[i - 1] in HEDGES:
        return True
    return i >= 2 and tokens[i - 1] == "have" and tokens[i - 2] in _COUNTERFACTUAL


#: Subordinators that make a clause after a contact its circumstance or its cause ("hit the taxi when it
#: stopped", "because it braked", "after it had stopped"): what they open came first.
_CIRCUMSTANCE = frozenset(("when", "as", "while", "whilst", "because", "since", "after", "cos", "coz"))


def _struck_earlier(tokens: list[str], m) -> bool:
    """Whether the stop of mention ``m`` is the aftermath of a contact with a road user stated before
    it ("hit me. It then carried on before stopping", "clipped my mirror and stopped further on"):
    how the incident ended, whatever sentence it is in. The outcome reader decides what a contact
    is (:func:`outcome.contacts_made`): one that was missed ("nearly hit", "without hitting") or met
    no road user ("hit the brakes", "tapped the horn") ended nothing. A stop said as what came first
    is the contact's cause, not its aftermath: in a clause of time or cause after the contact ("hit
    the taxi when it stopped"), in the past perfect ("it had stopped"), or in a hard manner ("he
    stopped sharp in front of me"), or a state said to hold the whole time ("I was stopped at the time")."""
    from vei_scenario.language.outcome import contacts_made
    from vei_scenario.language.quantities import held_throughout

    i = m.start
    before = [j for j in contacts_made(tokens) if j < i]
    if not before or said_hard(tokens, m) or tokens[i - 1 : i] == ["had"]:
        return False
    if held_throughout(tokens, m.end):
        return False  # ("clipped my mirror. I was stopped at the time": the state it stood in, not what followed)
    between = tokens[before[-1] + 1 : i]
    ends = [k for k, t in enumerate(between) if t in (".", "!", "?", ";")]
    return not _CIRCUMSTANCE & set(between[ends[-1] + 1 if ends else 0 :])


#: Words that open a clause of the ego's act a road user's same act answers ("every time I slowed").
_EACH_TIME = frozenset(("when", "whenever", "time", "as", "if"))


def _mirrors_the_ego(tokens: list[str], i: int) -> bool:
    """Whether the verb at token ``i`` repeats a verb said of the ego in a clause of "when I ...",
    "every time we ..." of its sentence ("every time I slowed he slowed", "braking when I braked"):
    the road user copies the ego, which is following it, not a speed change of its own. The ego
    answering a road user ("I braked when the van braked") is not this: there the ego's clause is
    the main one. The verb of the ego's clause itself is the ego's, not the road user's."""
    if i >= 2 and tokens[i - 1] in ("i", "we") and tokens[i - 2] in _EACH_TIME:
        return True  # (the ego's own act in that clause, never the road user's)
    own = set(lemmas(tokens[i]).get("VERB", ()))
    start = max((j + 1 for j in range(i) if tokens[j] in (".", "!", "?", ";")), default=0)
    end = next((j for j in range(i, len(tokens)) if tokens[j] in (".", "!", "?", ";")), len(tokens))
    return any(
        tokens[j] in _EACH_TIME and tokens[j + 1] in ("i", "we") and own & set(lemmas(tokens[j + 2]).get("VERB", ()))
        for j in range(start, min(end, len(tokens)) - 2)
        if j + 2 != i
    )


def outcome_not_behaviour(clauses: list, tokens: list[str] | None = None) -> list:
    """``clauses`` (the reader's mentions, by clause) without the verbs that state the outcome rather
    than what a road user does: a contact verb whose subject is both parties or that says what it met
    ("crashed into a van", "collided with the bus"), "yield a/an ...", a fall said after a contact
    in its sentence or before it ("clipped my mirror and fell off", "I could not avoid hitting him.
    The rider fell": what the contact did, not a stop the road user makes), and a stop said after a
    contact with a road user ("clipped my mirror and stopped further on": the aftermath; ``tokens``:
    those the mentions index). And a verb of contact "into" the ego's path or lane is a move there
    (:func:`_into_the_ego_way`)."""
    out = []
    moved_at: int | None = None  # (where the last road user named made its last move in front, if it did)
    for link, mentions in clauses:
        kept = []
        for k, m in enumerate(mentions):
            if m.slot == "actor" and m.value != "ego" and tokens is not None and _opens_a_clause(tokens, m.start):
                moved_at = None  # (another road user as a subject: a fall after this is its own)
            if m.slot == "behaviour":
                first = m.words.split()[0]
                fall = tokens is not None and "fall" in lemmas(first).get("VERB", ())
                if fall and (_touched_before(tokens, m.start) or _struck_earlier(tokens, m)):
                    continue  # ("..., struck the ego's mirror, falling into the road"; "I hit him. He fell.")
                if tokens is not None and _fall_ends_the_move(tokens, m, moved_at):
                    continue  # ("moved back in front of the bus, then lost control and fell")
                if m.value[0] in _MOVES_IN_FRONT:
                    moved_at = m.end
                if m.value[0] == "stop" and tokens is not None and _struck_earlier(tokens, m):
                    continue  # ("struck my bumper and carried on before stopping": the aftermath)
                slows = m.value[0] in ("change_speed", "sudden_stop", "stop")
                if slows and tokens is not None and _mirrors_the_ego(tokens, m.start):
                    continue  # ("every time I slowed he slowed": following, not its own slowing)
                before = next((x for x in reversed(mentions[:k]) if x.slot not in ("modal", "ego_verb")), None)
                plural = m.prev in _BOTH or (before is not None and before.slot == "pronoun" and before.words in _BOTH)
                if first in _CONTACT and plural:
                    continue  # ("they are crashing": the collision, said of both)
                if first in _CONTACT and tokens is not None and _into_someone(tokens, m.end):
                    continue  # ("crashed head-on into a motorcyclist": the contact, the outcome)
                if first in _CONTACT and tokens is not None and _nearly(tokens, m.start):
                    continue  # ("nearly crash", "we almost collided": a near miss, the outcome)
                if first in ("yield", "yields", "yielded", "yielding") and m.next_ in ("a", "an"):
                    continue  # ("designed to yield a collision")
            elif m.slot == "stationary" and tokens is not None and _stop_said_as_a_verb(mentions, k):
                if _struck_earlier(tokens, m):
                    continue  # ("clipped my mirror and stopped further on"; not "he stopped sharp": the cause)
            elif m.slot == "intent" and tokens is not None and _into_the_ego_way(m, tokens):
                m = replace(m, slot="behaviour", value=("keep_going", {}))  # ("ran into my path": it went there)
            kept.append(m)
        out.append((link, kept))
    return out


#: A road user's moves across or in front of someone: a fall right after one is how it ended.
_MOVES_IN_FRONT = frozenset(("cut_in", "overtake", "cross_in_front", "change_lane", "cut_out"))


#: Words after which a road user named is a clause's subject ("... . A cyclist", "and the van").
_SUBJECT_COMES = frozenset((".", "!", "?", ";", ",", "and", "but", "then", "when", "while", "as", "so"))
#: Words that open a noun phrase before its road user's word.
_DETERMINERS = frozenset(("a", "an", "the", "this", "that", "another", "one", "some", "our", "my"))


def _opens_a_clause(tokens: list[str], i: int) -> bool:
    """Whether the road user named at token ``i`` stands where a clause's subject does (first, after a
    mark or a conjunction), not as an object or a place ("in front of the tram")."""
    while i > 0 and tokens[i - 1] in _DETERMINERS:
        i -= 1
    return i == 0 or tokens[i - 1] in _SUBJECT_COMES


def _fall_ends_the_move(tokens: list[str], m, moved_at: int | None) -> bool:
    """Whether behaviour mention ``m`` is a fall or a loss of control ("fell", "fell off", "lost
    control") said of a road user after its own move in front (ending at token ``moved_at``), in
    that sentence or the next ("overtook and cut back in, then lost control and fell", "swerved into
    my lane; he fell"): the move was the hazard and the fall how it ended, not a second act. A fall
    with no move of its own before it ("a cyclist ahead wobbled and fell") stays a stop."""
    if moved_at is None or m.value[0] != "sudden_stop":
        return False
    words = m.words.split()
    if "fall" not in lemmas(words[0]).get("VERB", ()) and "control" not in words:
        return False
    return sum(t in (".", "!", "?") for t in tokens[moved_at : m.start]) <= 1


def _into_the_ego_way(m, tokens: list[str]) -> bool:
    """Whether intent mention ``m`` is a verb of contact with "into" ("ran into", "crashed into") whose
    object is the ego's path, lane or side ("ran into my path", "runs into the ego's lane"): that is
    where its road user goes, a place, not what it met; into the ego itself ("ran into me") it is
    the contact."""
    return m.words.split()[-1] == "into" and _the_ego_way_at(tokens, m.end)


#: Mentions after which a word is the verb of its clause, not a participle of a noun ("a car stopped in
#: the lane"): a conjunction, a link, a pronoun as its subject.
_BEFORE_A_VERB = frozenset(("conj", "link", "pronoun"))


def _stop_said_as_a_verb(mentions: list, k: int) -> bool:
    """Whether the stationary mention ``mentions[k]`` is a verb of stopping said of a subject known
    before ("... and stopped", "then stopped", "It stopped"), not a standing road user's state."""
    m = mentions[k]
    if not _STOP_VERBS & set(lemmas(m.words.split()[0]).get("VERB", ())):
        return False
    return k == 0 or mentions[k - 1].slot in _BEFORE_A_VERB


_TOWARDS = frozenset(("into", "onto"))
#: Prepositions of where a road user makes for ("heading for the exit", "towards the exit").
_MAKING_FOR = frozenset(("for", "towards", "toward"))
_POSSESSIVE = frozenset(("its", "his", "her", "their"))


def destinations_not_origins(clauses: list, tokens: list[str] | None = None) -> list:
    """``clauses`` without the side roads and exits said as where a road user goes ("into a side
    street", "into one of the side roads on the right", "to get to its exit"), and the side said of
    them, and an exit wanted ("wanted my exit", "needed the same exit": ``tokens``, those the mentions
    index, say so); where a road user comes from or is stays ("out of the side road", "up to the entry"). A
    road user of that clause moving across the ego's way towards a side ("cuts left across me to
    turn into a side street") is turning off across it: a turn that way, read as the reader reads
    "swings left across"."""
    out = []
    for link, mentions in clauses:
        kept: list = []
        drop_side = False
        gone: str | None = None  # the side of where it goes, if said
        dropped = False
        for k, m in enumerate(mentions):
            before = mentions[k - 1] if k > 0 else None
            wanted = tokens is not None and (_wanted(tokens, m.start) or _gone_to(tokens, m.start))
            if m.slot == "arm" and (wanted or _led_towards(m, before, mentions[k - 2] if k > 1 else None)):
                drop_side = dropped = True
                if kept and kept[-1] is before and before.slot in ("pronoun", "member"):
                    kept.pop()
                continue
            if drop_side and m.slot == "side" and before is not None and before.slot in ("arm", "side"):
                gone = gone or str(m.value)
                continue  # ("... side roads on the right": the side of where it goes)
            drop_side = False
            kept.append(m)
        out.append((link, _across_as_a_turn(kept, gone) if dropped else kept))
    return out


#: Verbs (lemmas) of leaving a place: with a side road as their object, a road user comes out of it.
_LEAVE = frozenset(("exit", "leave", "quit"))
_OUT_OF = (["out", "of"], ["out", "from"], ["outta"])


def _leaves_the_arm(tokens: list[str], arm) -> int | None:
    """Where the verb stands that says a road user comes out of side road mention ``arm``: a verb +
    "out of" / "out from" before it ("came out from a side road", "rode out of the side street", or
    "out" and an article, "came out the side road", as said aloud), or
    a verb of leaving with it as its object ("exits a side road", "is leaving the side street"); None
    if neither. The verb is whatever it is: the particle or the verb's class says it leaves."""
    j = arm.start - 1
    while j >= 0 and tokens[j] in _DETERMINERS:
        j -= 1
    for particle in _OUT_OF:
        n = len(particle)
        if j - n + 1 >= 1 and tokens[j - n + 1 : j + 1] == particle:
            return j - n  # (the verb before the particle)
    if j >= 1 and tokens[j] == "out" and j < arm.start - 1:
        return j - 1  # ("came out the side road": "out" and the road's article, "of" left out as said aloud)
    verb = tokens[j] if j >= 0 else ""
    inflected = verb.endswith(("s", "ed", "ing")) and j > 0 and tokens[j - 1] not in _DETERMINERS
    if inflected and set(lemmas(verb).get("VERB", ())) & _LEAVE:
        return j
    return None


def out_of_a_side_road(clauses: list, tokens: list[str] | None = None) -> list:
    """``clauses`` with a verb + "out" + "of"/"from" + a side road, or a verb of leaving with a side
    road as its object, read as coming out of that road (``tokens``: the reader's tokens, which the
    mentions index)."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        if tokens is not None:
            kept = _leaving_a_side_road(kept, tokens)
        for k, m in enumerate(kept[:-1]):
            nxt = kept[k + 1]
            particle = m.words.endswith((" out", " out of", " out from")) and (
                m.next_ in ("of", "from") or m.words.endswith(("of", "from"))
            )
            after = tokens[m.end : m.end + 2] if tokens is not None else []
            out_after = (
                m.slot == "behaviour" and m.value[0] in _PLAIN_MOVES and after in (["out", "of"], ["out", "from"])
            )
            if out_after and _the_junction_left(nxt, kept):  # ("rode out from the crossroads")
                particle = True
            between = tokens[m.end : nxt.start] if tokens is not None else ["?"] * (nxt.start - m.end)
            right_after = all(t in ("out", "of", "from", "the", "a") for t in between)
            if m.slot == "behaviour" and particle and right_after and _the_junction_left(nxt, kept):
                # "shot out of the junction": the junction one comes out of is one of its arms
                kept.insert(kept.index(nxt) + 1, replace(nxt, slot="arm", value=None, prev="from"))
                nxt = kept[kept.index(nxt) + 1]
            if m.slot == "behaviour" and particle and nxt.slot == "arm" and nxt.prev in ("of", "from"):
                if not m.value[1].get("from_side_road"):
                    kept[k] = replace(m, value=("cut_in", {**m.value[1], "from_side_road": 1.0}))
            elif m.slot == "behaviour" and m.value[1].get("from_side_road") and _out_of_a_place(nxt):
                # "pulled out of the stop", "out of a driveway": onto the road from beside it, no arm
                cfg = {x: v for x, v in m.value[1].items() if x != "from_side_road"}
                kept[k] = replace(m, value=(m.value[0], cfg))
        if tokens is not None:
            kept = _out_of_the_side_is_from(kept, tokens)
        out.append((link, _into_the_ego_road(kept, tokens) if tokens is not None else kept))
    return out


def _out_of_the_side_is_from(mentions: list, tokens: list[str]) -> list:
    """``mentions`` with a place beside the road said right after "out of" ("came out of the hard
    shoulder", "rolled out of the verge") marked as where its road user comes from, as "from the
    verge" and "off the kerb" are: the place it leaves for the road is its start, whichever lane it
    then goes into."""
    out = list(mentions)
    for k, m in enumerate(out):
        if m.slot not in ("kerb", "kerb_side") or m.prev in ("from", "off"):
            continue
        i = m.start - 1
        while i >= 0 and m.start - i <= 3 and tokens[i] != "of" and tokens[i] not in _STOPS:
            i -= 1  # (past its article and adjectives: "out of the gravel shoulder")
        if i >= 1 and tokens[i - 1 : i + 1] == ["out", "of"]:
            out[k] = replace(m, prev="from")
    return out


#: Words of a junction as a whole (the map mention's words) that one can come out of.
_JUNCTION_WORDS = frozenset(("junction", "intersection", "crossroads", "crossroad", "t-junction", "crossing"))


def _the_junction_left(m, mentions: list) -> bool:
    """Whether map mention ``m`` is a junction as a whole said right after "out of"/"out from" ("out of
    the junction", "out from the intersection"), with no arm of it said next: the road user comes
    out of one of its arms. Only a road user's move out counts (the caller's verb): the ego coming
    out of a junction is its route, read elsewhere."""
    if m.slot != "map" or m.value != "crossroad" or m.prev not in ("of", "from", "the", "a"):
        return False
    if not set(m.words.split()) & _JUNCTION_WORDS:
        return False
    after = mentions[mentions.index(m) + 1 :]
    return not (after and after[0].slot == "arm" and after[0].start <= m.end + 1)


def _down_a_side_road(mentions: list, k: int) -> bool:
    """Whether the plain move ``mentions[k]`` is said with a side road right after it ("came down a side
    road on our left", "rode along the side street"): the way it comes, so where it ends says more."""
    m = mentions[k]
    nxt = mentions[k + 1] if k + 1 < len(mentions) else None
    return m.slot == "behaviour" and m.value[0] in _PLAIN_MOVES and nxt is not None and nxt.slot == "arm"


#: The road a side road meets, named as such ("out onto the main road"): the ego's, where it drives.
_THE_MAIN_ROAD = (("the", "main", "road"), ("the", "main", "street"), ("the", "major", "road"))


def _the_main_road_at(tokens: list[str], j: int) -> bool:
    """Whether the road a side road meets is named from ``tokens[j]`` ("the main road")."""
    return any(tuple(tokens[j : j + len(road)]) == road for road in _THE_MAIN_ROAD)


def _into_the_ego_road(mentions: list, tokens: list[str]) -> list:
    """``mentions`` with a pull-out from a side road said to end in the ego's lane or path ("came out
    of the side road without stopping and into my lane", "shot out of a side street, straight into
    our lane in front of us") read as turning into the ego's road: where it ends says it turns into
    that road, not across it, even when it did not stop first. A plain move down a side road said to
    end on the main road ("came down a side road on our left and out onto the main road") is that
    pull-out too: the side road is the way it came, the main road where it ends."""
    out = list(mentions)
    for k, m in enumerate(out):
        if m.slot != "behaviour" or not (m.value[1].get("from_side_road") or _down_a_side_road(out, k)):
            continue
        stop = next((x.start for x in out[k + 1 :] if x.slot in ("actor", "pronoun") and x.value != "ego"), None)
        end = max(x.end for x in out) if stop is None else stop
        for i in range(m.end, min(end, len(tokens))):
            ends_in = _the_ego_way_at(tokens, i + 1) or _the_main_road_at(tokens, i + 1)
            into = tokens[i] in ("into", "onto") and ends_in
            if into or _before_the_ego(tokens, i):
                out[k] = replace(m, value=("turn_into", m.value[1]))
                break
        break
    return out


def _leaving_a_side_road(mentions: list, tokens: list[str]) -> list:
    """``mentions`` with the verb that says its road user leaves a side road (:func:`_leaves_the_arm`)
    read as coming out of it: its behaviour mention made the pull-out from a side road, or one put in
    where the reader held the verb as no behaviour ("exits" read as an exit, "leaving" read past)."""
    out = list(mentions)
    for k in range(len(out) - 1, -1, -1):
        arm = out[k]
        if arm.slot != "arm" or arm.words.split()[0] in ("exit", "exits", "exited", "exiting"):
            continue
        at = _leaves_the_arm(tokens, arm)
        if at is None or at < 0:
            continue
        verb = next((x for x in out[:k] if x.start <= at < max(x.end, x.start + 1)), None)
        pull_out = ("cut_in", {"from_side_road": 1.0})
        if verb is not None and verb.slot in ("behaviour", "unknown_verb", "ego_verb", "arm"):
            if verb.slot == "behaviour" and verb.value[1].get("from_side_road"):
                continue
            if verb.slot == "behaviour" and verb.value[0] not in _PLAIN_MOVES | {"cut_in", "cross_in_front"}:
                continue  # (a move of its own: "turns out of ...", read as it is)
            out[out.index(verb)] = replace(verb, slot="behaviour", value=pull_out)
        elif verb is None:
            said = replace(arm, slot="behaviour", value=pull_out, words=tokens[at], start=at, end=at + 1, det="")
            out.insert(k, said)
    return out


def _out_of_a_place(m) -> bool:
    """Whether mention ``m`` is a place off the carriageway said as where a road user comes out of
    ("out of a driveway on the right", "from the bus stop"): sides.py reads it as a kerb with a side."""
    return m.slot == "kerb" and m.prev in ("of", "from", "out") and bool(set(m.words.split()) & _PLACE_WORDS)


_PLACE_WORDS = OFF_ROAD_PLACES | {"space", "spot", "park"}


#: Moves that, into the ego's lane, are a cut-in.
_INTO_EGO_LANE_FROM = frozenset(("keep_going", "change_lane", "cut_out", "cross_in_front"))
_EGO_OWNERS = EGO_LANE_OWNERS
_STOPS = frozenset((".", ",", ";", ":", "!", "?", "and", "but", "then", "while", "when", "as"))


#: Mentions that may stand between a move and where it ends ("swerves suddenly, 5 m ahead, in front of us").
_BETWEEN_MOVE_AND_WHERE = frozenset(("punct", "criticality", "distance", "speed"))


def _place_follows(mentions: list, j: int) -> bool:
    """Whether the place a degree phrase at ``mentions[j]`` starts is read as a relation of its own
    right after it ("right in front of us": how exactly, then where)."""
    nxt = mentions[j + 1] if j + 1 < len(mentions) else None
    return nxt is not None and nxt.slot == "relation" and nxt.start == mentions[j].start + 1


def _ends_in_front_of_the_ego(mentions: list, k: int) -> bool:
    """Whether the lane change at ``mentions[k]`` is said to end right in front of the ego ("changed
    lanes directly in front of my client", "slices over in front of me"): the ego named in a relation
    of being ahead of it, or right after one, before anything else is said. Ending in front of the
    ego, in its lane, is what a cut-in is."""
    j = k + 1
    in_front = ("relation", "criticality")  # ("right in front" is read as how close, and says where too)
    while (
        j < len(mentions)
        and mentions[j].slot in _BETWEEN_MOVE_AND_WHERE
        and ("in front" not in mentions[j].words or _place_follows(mentions, j))
    ):
        j += 1
    if j >= len(mentions) or mentions[j].slot not in in_front:
        return False
    where = mentions[j]
    if not where.words.startswith(("in front", "just in front", "right in front", "directly in front")):
        return False
    nxt = mentions[j + 1] if j + 1 < len(mentions) else None
    named = any(w in _EGO_WORDS for w in where.words.split()) or where.words.endswith("the ego")
    return named or (nxt is not None and nxt.slot == "actor" and nxt.value == "ego" and nxt.start <= where.end + 2)


def into_the_ego_lane(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a move into the ego's lane or path read as a cut-in (``tokens``: the reader's
    tokens, which the mentions index): "into" + the ego's lane after the verb's phrase ("moves across
    into my lane"), a lane change that ends right in front of the ego
    (:func:`_ends_in_front_of_the_ego`), or a swerve out from the side of the road (:func:`_from_the_side`)
    into the road or right in front of the ego."""
    out = []
    earlier: list = []  # (the mentions of the clauses before, for a subject said there)
    for link, mentions in entering_the_ego_lane(clauses, tokens):
        kept = list(mentions)
        for k, m in enumerate(kept):
            if m.slot != "behaviour" or m.value[0] not in _INTO_EGO_LANE_FROM:
                continue
            lane_change = m.value[0] == "change_lane" and _ends_in_front_of_the_ego(kept, k)
            from_the_side = m.value[0] in _OUT_OF_A_LANE and _from_the_side(kept, k, earlier)
            out_in_front = from_the_side and (_ends_in_front_of_the_ego(kept, k) or _into_the_road(tokens, m.end))
            phrase_end = m.end
            if m.words.split()[-1] in ("into", "onto") and not _from_the_side(kept, k, earlier):
                phrase_end -= 1  # ("swerves into my lane": a cut-in; from the kerb, the lane change from there)
            if _into_ego_lane(tokens, phrase_end) or lane_change or out_in_front:
                kept[k] = replace(m, value=("cut_in", {x: v for x, v in m.value[1].items() if x != "direction"}))
        earlier.extend(mentions)
        out.append((link, kept))
    return out


#: Verbs (lemmas) of going on foot, which no vehicle does ("stepped", "wandered", "staggered").
_FOOT_VERBS = frozenset(
    ("step", "walk", "wander", "stroll", "stagger", "stumble", "amble", "hobble", "limp", "toddle", "jog", "sprint",
     "saunter", "trot", "shuffle", "tiptoe", "march", "totter")
)  # fmt: skip


def _on_foot(m) -> bool:
    """Whether mention ``m`` is said with a verb of going on foot ("stepped off the kerb", "walked out",
    "wandered"): its road user walks."""
    return bool(set(lemmas(m.words.split()[0]).get("VERB", ())) & _FOOT_VERBS)


#: Moves out of a lane: from the side of the road, out into the ego's path.
_OUT_OF_A_LANE = frozenset(("change_lane", "cut_out"))
#: Where a move out from the side of the road ends: on the road, in the traffic.
_THE_ROAD = frozenset(("road", "carriageway", "roadway", "street", "traffic"))


def _from_the_side(mentions: list, k: int, earlier: list = ()) -> bool:
    """Whether the road user whose move is ``mentions[k]`` was said to be at the side of the road (at
    the kerb, in a bike lane, on the pavement, at a stop) since it was named: a swerve out of there is
    out into the road, not out of the ego's lane as a lead car's is. "One (of them)" is one of the
    group named before, so where the group was said to be is where it was; a clause with no subject
    of its own ("..., then swerved out") goes on about the road user of the clauses before
    (``earlier``: their mentions, in order)."""
    for x in reversed([*earlier, *mentions[:k]]):
        if x.slot == "kerb":
            return True
        if x.slot in ("actor", "pronoun") and x.value != "ego":
            return False
    return False


def _into_the_road(tokens: list[str], j: int) -> bool:
    """Whether "into" or "onto" + the road or the traffic follows right after token ``j`` ("swerved out
    into the road", "wobbles out into the traffic")."""
    rest = [t for t in tokens[j : j + 4] if t not in ("the", "a", "busy", "main")]
    return len(rest) >= 2 and rest[0] in ("into", "onto") and rest[1] in _THE_ROAD


def _into_ego_lane(tokens: list[str], j: int) -> bool:
    """Whether "into" + the ego's lane or path follows within the clause from token ``j``."""
    for i in range(j, min(j + 10, len(tokens))):
        if tokens[i] in _STOPS:
            return False
        if tokens[i] != "into":
            continue
        rest = tokens[i + 1 : i + 5]
        for owner in _EGO_OWNERS:
            n = len(owner)
            if tuple(rest[:n]) == owner and len(rest) > n and rest[n] in ("lane", "path"):
                return True
        return False
    return False


_GIVE = frozenset(("give", "gives", "gave", "giving", "given"))
_WAY = frozenset(("way", "priority", "precedence"))


def _rewrite(clauses: list, rule) -> list:
    """``clauses`` with each mention for which ``rule(k, m, mentions)`` gives a new mention replaced by
    it; the mentions that new one spans (up to its ``end``) are read into it and dropped."""
    out = []
    for link, mentions in clauses:
        kept: list = []
        skip_to = -1
        for k, m in enumerate(mentions):
            if m.start < skip_to:
                continue
            new = rule(k, m, mentions)
            if new is not None:
                kept.append(new)
                skip_to = new.end
                continue
            kept.append(m)
        out.append((link, kept))
    return out


def give_the_ego_the_way(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with "give" + the ego + the way (priority, the right of way) read as giving way."""

    def rule(k: int, m, mentions: list):
        nxt = mentions[k + 1] if k + 1 < len(mentions) else None
        if (
            m.words in _GIVE
            and m.slot in ("unknown_verb", "behaviour")
            and nxt is not None
            and nxt.slot == "actor"
            and nxt.value == "ego"
            and all(t in ("the", "a") for t in tokens[m.end : nxt.start])  # ("gave the ego priority")
            and set(tokens[nxt.end : nxt.end + 4]) & _WAY
        ):
            way = next(i for i in range(nxt.end, nxt.end + 4) if tokens[i] in _WAY)
            return replace(m, slot="behaviour", value=("give_way", {}), end=way + 1)  # (with "the way")
        return None

    return _rewrite(clauses, rule)


#: Verbs (lemmas) of letting someone go: with the ego as their object, the road user gives way.
_LET = frozenset(("let", "allow", "wave", "beckon"))
#: Words after "lets/waves the ego": where or how it goes ("waves me out", "lets us through").
#: (a verb after the ego, "lets the ego complete the turn", says it as well)
_GO_WORDS = frozenset(("out", "through", "on", "in", "past", "across", "by", "first", "ahead", "over", "to"))


def _let_before(tokens: list[str], i: int, before) -> int:
    """Where a verb of letting stands right before the ego at ``tokens[i]`` ("letting the ego", "lets
    me"), when no mention holds it (``before``: the mention before the ego), else 0."""
    j = i - 1
    while j > 0 and tokens[j] in ("the", "a"):
        j -= 1
    if j <= 0 or (before is not None and before.end > j):
        return 0
    return j if set(lemmas(tokens[j]).get("VERB", ())) & _LET else 0


def _past_its_speed(mentions: list, tokens: list[str], i: int) -> int:
    """Where the words after the ego at ``tokens[i]`` go on once a speed said as an aside of it is read
    past ("letting the ego (50 km/h) pass", "lets me, doing 30 mph on the main road, through"): the aside says how fast
    the ego goes, not what it is let do."""
    j = i
    while j < len(tokens) and tokens[j] in ("at", "doing", "going", ","):
        j += 1
    said = next((s for s in mentions if s.slot == "speed" and s.start == j), None)
    if said is None:
        return i
    j = said.end
    if j < len(tokens) and tokens[j] in ("on", "in", "along"):  # ("(50 km/h on the main road)": where it goes)
        where = next((s for s in mentions if s.slot == "map" and j < s.start <= j + 4), None)
        j = where.end if where is not None else j
    while j < len(tokens) and tokens[j] == ",":
        j += 1
    return j


def lets_the_ego_go(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user letting the ego go ("waves me out", "beckons us across", "lets the
    ego complete the turn", "allows the ego to finish its turn") read as giving way: the ego as the
    object of a verb of letting, then where it goes or what it does. Letting the ego do something is
    what giving way to it is, however the verb is said."""

    def rule(k: int, m, mentions: list):
        nxt = mentions[k + 1] if k + 1 < len(mentions) else None
        verb = m.words.split()[0]
        letting = m.slot in ("unknown_verb", "behaviour", "ego_verb") and bool(set(lemmas(verb).get("VERB", ())) & _LET)
        after = nxt.end if nxt is not None else len(tokens)
        said = m
        if m.slot == "actor" and m.value == "ego" and _let_before(tokens, m.start, mentions[k - 1] if k else None):
            nxt, after = m, m.end  # ("..., letting the ego go by": a participle the reader reads past)
            said = replace(m, words=" ".join(tokens[_let_before(tokens, m.start, None) : m.end]))
            letting = True
        if nxt is not None and nxt.slot == "actor" and nxt.value == "ego":
            after = _past_its_speed(mentions, tokens, after)
        if (
            letting
            and nxt is not None
            and nxt.slot == "actor"
            and nxt.value == "ego"
            and all(t in ("the", "a") for t in tokens[m.end : nxt.start])
            and after < len(tokens)
            and tokens[after] not in ("'s", "s")  # (the ego's own: "let the ego's braking decide" lets no one go)
            and (tokens[after] in _GO_WORDS or "VERB" in lemmas(tokens[after]))
        ):
            end = after + 1 + (tokens[after] == "to")  # ("allows the ego to pass": through its verb)
            return replace(said, slot="behaviour", value=("give_way", {}), end=end)
        return None

    return _rewrite(clauses, rule)


#: Verbs (lemmas) of wanting or choosing a way: a side road or exit as their object is where one goes.
_WANTING = frozenset(("want", "need", "choose", "pick", "fancy"))


def _wanted(tokens: list[str], start: int) -> bool:
    """Whether the arm mention starting at ``start`` is the object of a verb of wanting ("wanted my
    exit", "needed the same exit as me"), past its determiner and an adjective or two."""
    i = start - 1
    while i >= 0 and start - i <= 3 and not lemmas(tokens[i]).get("VERB"):
        i -= 1
    return i >= 0 and start - i <= 3 and bool(set(lemmas(tokens[i]).get("VERB", ())) & _WANTING)


#: Words that may stand between a word of going and the exit gone to: determiners, possessives,
#: ordinals and the adjectives that pick one exit of several ("the next", "its 3rd", "the same").
_EXIT_MODIFIERS = frozenset(
    ("the", "a", "an", "its", "his", "her", "their", "my", "our", "your", "this", "that")
    + ("first", "second", "third", "fourth", "fifth", "sixth", "last", "next", "same", "other", "nearest")
    + ("following", "correct", "wrong", "right", "left", "own", "upcoming")
)
#: Words that say an arm is where one does not go ("not exiting", "without taking the exit").
_NOT = frozenset(("not", "never", "without", "n't"))


def _ordinal(tokens: list[str], i: int) -> bool:
    """Whether token ``i`` is part of an ordinal written in figures ("2nd", or "2" "nd" as split)."""
    word = tokens[i]
    return bool(re.fullmatch(r"\d+(st|nd|rd|th)?", word)) or (
        word in ("st", "nd", "rd", "th") and i > 0 and tokens[i - 1].isdigit()
    )


def _gone_to(tokens: list[str], start: int) -> bool:
    """Whether the arm mention starting at ``start`` is where a road user goes, past the words that pick
    one exit of several ("to take the next exit", "heading for the 2nd exit", "to get to the same exit"),
    or where it is said not to go ("continuing round, not exiting", "without taking the exit"): the word
    that governs it is then "for"/"towards"/"into"/"onto", "to" after a verb ("get to"), a verb after
    "to" (a purpose: "to take"), or a negation. "Out of the next exit", "from the 2nd entry" are where
    it comes from and stay."""
    i = start - 1
    while i >= 0 and start - i <= 4 and (tokens[i] in _EXIT_MODIFIERS or _ordinal(tokens, i)):
        i -= 1
    if i < 0:
        return False
    word, before = tokens[i], tokens[i - 1] if i > 0 else ""
    if word in _NOT or (before in _NOT and "VERB" in lemmas(word)):  # ("not exiting", "not taking the exit")
        return True
    if i == start - 1:
        return False  # (nothing picked between: the plain cases are read by _led_towards)
    if word in _TOWARDS or word in _MAKING_FOR:
        return True
    if word == "to":
        return before not in ("up", "down", "next", "close") and "VERB" in lemmas(before)
    return before == "to" and "VERB" in lemmas(word)


def _led_towards(m, before, earlier=None) -> bool:
    """Whether a side road or exit mention ``m`` is led by "into"/"onto" or "for"/"towards" (a
    destination: "heading for the exit"), or is the object of an infinitive of purpose ("to take the
    exit", "to make its exit", "to catch the exit"): what a road user moves to reach is where it goes,
    whatever the verb."""
    if m.prev in _TOWARDS or m.prev in _MAKING_FOR:
        return True
    if before is None:
        return False
    verb = before
    if before.slot == "pronoun" and before.words in _POSSESSIVE and before.end == m.start and earlier is not None:
        verb = earlier  # ("to make its exit": past whose it is)
    purpose = verb.slot in ("unknown_verb", "behaviour", "ego_verb") and verb.prev == "to"
    direct = "VERB" in lemmas(verb.words.split()[-1])  # (its object: not "to pull out of the side road")
    if purpose and direct and verb.end <= m.start <= verb.end + 1:
        return True  # ("... to take the exit": past its determiner)
    if before.slot == "pronoun" and before.words in _POSSESSIVE and before.prev in _TOWARDS | {"to"}:
        return before.end == m.start  # ("to get to its exit")
    return before.slot == "member" and before.prev in _TOWARDS and m.prev == "of"  # ("into one of the side roads")


def _across_as_a_turn(mentions: list, gone: str | None) -> list:
    """``mentions`` with a lateral move across ("cuts left across", "swerves across") read as a turn
    that way, the clause having said where it turns off to."""
    out = list(mentions)
    for k, m in enumerate(out):
        if m.slot != "behaviour" or m.value[0] not in ("cut_in", "cross_in_front", "change_lane"):
            continue
        nxt = out[k + 1] if k + 1 < len(out) else None
        if nxt is not None and nxt.slot == "side" and nxt.next_ == "across":
            out[k : k + 2] = [replace(m, slot="turn", value=str(nxt.value), words=f"{m.words} {nxt.words}")]
            return out
        if m.next_ == "across" and gone is not None:
            out[k] = replace(m, slot="turn", value=gone)
            return out
    return out


_OPPOSITE = {"north": "south", "south": "north", "east": "west", "west": "east"}
#: (a bare compass point only right before the lane: "riding north in the southbound carriageway", not
#: "north of the bridge in the southbound lane"; a lane's kind may come between: "southbound bike lane")
_COMPASS_LANE = re.compile(
    r"\b(north|south|east|west)(?:bound\b(?:\s+\S+){0,3}?)?\s+(?:in|on|along|down|up|into)\s+(?:the|a)\s+"
    r"(north|south|east|west)bound\s+(?:painted\s+|marked\s+|segregated\s+|protected\s+)?"
    r"(?:bike\s+|cycle\s+|bus\s+)?(?:lane|lanes|carriageway|side)\b"
)


#: The same, after the normaliser has said compass headings relative to the ego's ("southbound",
#: the ego northbound: "in the opposite direction"; "the northbound lane": "the in the same direction lane").
_RELATIVE_LANE = re.compile(
    r"\bopposite direction\b(?:\s+\S+){0,3}?\s+(?:in|on|along|down|up|into)\s+(?:the\s+)?(?:in\s+the\s+)?"
    r"(?:ego 's |my |our )?same direction\s+(?:lane|lanes|carriageway|side)\b"
)


def compass_against(said: str) -> bool:
    """Whether ``said`` (normalised, lowercased) puts someone heading one way in the lane of the other."""
    if _RELATIVE_LANE.search(said):
        return True
    return any(_OPPOSITE[m.group(1)] == m.group(2) for m in _COMPASS_LANE.finditer(said))


_HEADING = re.compile(r"\b(north|south|east|west)bound\b")


def compass_opposed(said: str) -> bool:
    """Whether the headings ``said`` gives are exactly two, and opposite (the two parties meet)."""
    found = {m.group(1) for m in _HEADING.finditer(said)}
    return len(found) == 2 and _OPPOSITE[min(found)] == max(found)


#: Moves across the road: after a walker's crossing, its getting over, across or to the other side.
_ACROSS_THE_ROAD = frozenset(("cross_in_front", "cut_in", "change_lane"))


def _one_crossing(behaviours: list, again: frozenset[str] = _ACROSS_THE_ROAD) -> list:
    """A walker's behaviours with the end of its crossing said again ("stepped off the kerb ... and
    he got across", "made it over", "got to the other side") read as the one crossing: a walker has
    no lane to change, so a move across after its crossing is that crossing. Of anyone else only the
    crossing itself said again is the same one (``again``: "came out of the car park ... passed inches
    from my bumper"); a rider's move into a lane after it is a move of its own."""
    out: list = []
    for b in behaviours:
        if out and out[-1][0] == "cross_in_front" and b[0] in again:
            continue
        out.append(b)
    return out


def turn_across_side(text: str) -> str:
    """The turn that takes a road user coming the other way across the ego's path: to the far side of
    the road, left where traffic keeps right, right where the text says it keeps left ("we drive on
    the left", "UK layout"). Only a stated side counts: units and road words are too weak a guess to
    read an oncoming left turn as one away from the ego."""
    return "right" if stated_side(text) == "left" else "left"


def one_path(spec: ActorSpec, said: str = "", across: str = "left") -> list:
    """``spec``'s behaviours with the manner of its path dropped (see the module's rules); ``said`` is
    the description's normalised text, for what a road user's own clause cannot place; ``across`` the
    turn that crosses an oncoming path (:func:`turn_across_side`)."""
    if spec.kind == "pedestrian":
        spec.behaviours = _one_crossing(spec.behaviours)
    else:
        spec.behaviours = _one_crossing(spec.behaviours, frozenset(("cross_in_front",)))
    if spec.obstacle is not None and spec.behaviours[:1] and spec.behaviours[0][0] == "cut_out":
        # ("pulled out to pass a lorry parked in the lane": passing what it reveals is the cut-out)
        spec.behaviours = spec.behaviours[:1] + [b for b in spec.behaviours[1:] if b[0] != "overtake"]
    names = [b[0] for b in spec.behaviours]
    if names in (["along_road"], ["keep_going"]) and spec.lateral_m is None and compass_against(said):
        _, cfg, crit, link = spec.behaviours[0]
        spec.relation, spec.facing = "ahead", "against"
        return [("wrong_way", {}, crit, link)]
    if names[:1] == ["turn_into"] and "run_red_light" in names and not _RED_SAID.search(said):
        # ("came out of a side road to turn right and pulled across my path": with no red light said,
        # the move across the ego's path is how it turns out of the side road, not a second one)
        return [b for b in spec.behaviours if b[0] != "run_red_light"]
    if "run_red_light" in names:
        return [b for b in spec.behaviours if b[0] not in _MANNER_OF_A_RUN]
    if names[:2] == ["overtake", "forced_turn"]:
        # (passing the ego to turn across its path, a "left hook": the pass is how it gets there)
        spec.behaviours = spec.behaviours[1:]
        names = names[1:]
    turning_left = names[:1] == ["forced_turn"] and spec.behaviours[0][1].get("turn") == across
    if turning_left and spec.relation is None and compass_opposed(said):
        _, cfg, crit, link = spec.behaviours[0]
        spec.relation = "junction_opposite"
        return [("turn_across", {}, crit, link)] + spec.behaviours[1:]
    if names[:1] == ["forced_turn"] and spec.distance_m is not None and "gap_m" not in spec.behaviours[0][1]:
        name, cfg, crit, link = spec.behaviours[0]  # ("10 m ahead ... swings across": the gap it cuts across at)
        return [(name, {**cfg, "gap_m": spec.distance_m}, crit, link)] + spec.behaviours[1:]
    if names == ["stop"] and spec.relation in _ARMS:
        _, cfg, crit, link = spec.behaviours[0]
        return [("give_way", {}, crit, link)]
    return spec.behaviours


#: Mentions that name the main verb's move.
_MAIN_MOVE = frozenset(("behaviour", "turn"))
#: Going along the road (alone, on past, behind): what a participle of state says a road user is doing.
_ALONG = frozenset(("overtake", "along_road", "keep_going", "follow_vehicle"))
#: Moves out of that course, across a lane: the main verb's move that replaces it.
_ACROSS = frozenset(("cut_in", "change_lane", "cross_in_front", "forced_turn", "turn_into"))


def participle_of_state(clauses: list) -> list:
    """``clauses`` without a participle that says how a road user is going along when the clause's
    main verb says it leaves that course across a lane: "a rider filtering up the inside ... swung out
    into my lane" is a cut-in, the filtering only where it was. The participle (an "-ing" verb
    straight after the road user) is a reduced relative clause; the finite verb after it in the same
    clause, with no other road user as its subject, is the behaviour. A conjunction other than an
    "and" joining nouns ("between me and the kerb") ends the clause, and with it the rule. A crossing
    said as the participle is a path of its own ("a walker crossing from the right stops")."""
    out = []
    for link, mentions in clauses:
        drop: set[int] = set()
        for k, m in enumerate(mentions):
            before = mentions[k - 1] if k > 0 else None
            if not (
                m.slot == "behaviour"
                and m.words.split()[0].endswith("ing")
                and m.value[0] in _ALONG
                and before is not None
                and before.slot == "actor"
                and before.value != "ego"
                and before.end == m.start
            ):
                continue
            for j in range(k + 1, len(mentions)):
                x = mentions[j]
                if x.slot == "actor" and x.value != "ego":
                    break  # (another road user: its own verb)
                if x.slot == "conj":
                    nxt = mentions[j + 1] if j + 1 < len(mentions) else None
                    if x.words != "and" or nxt is None or nxt.slot in _MAIN_MOVE or nxt.slot == "actor":
                        break
                if x.slot in _MAIN_MOVE:
                    across = x.slot == "turn" or x.value[0] in _ACROSS
                    if across and not x.words.split()[0].endswith("ing") and x.prev != "to":
                        drop.add(k)  # (a finite verb: the move; the participle its setting)
                    break
        out.append((link, [m for k, m in enumerate(mentions) if k not in drop]))
    return out


#: Moves a verb + "out" is read as; before an overtake, they are its pulling out.
_OUT_MOVES = frozenset(("cut_in", "cross_in_front", "change_lane"))
#: Mentions that may stand between pulling out and the overtake it starts.
_BETWEEN_OUT_AND_PASS = frozenset(("punct", "criticality", "conj"))


def out_to_overtake(clauses: list) -> list:
    """``clauses`` without a move out ("swings out", "pulled out", "moves out") said just before an
    overtake by the same road user ("swings out, overtakes me and cuts back in"): pulling out of the
    lane is how an overtake starts, not a move of its own across the ego's path. An overtake said as
    its purpose ("pulls out to overtake") is not yet made: the move out stays."""
    out = []
    for link, mentions in clauses:
        drop: set[int] = set()
        for k, m in enumerate(mentions):
            if not (m.slot == "behaviour" and m.value[0] in _OUT_MOVES and m.words.split()[-1] == "out"):
                continue
            j = k + 1
            while j < len(mentions) and mentions[j].slot in _BETWEEN_OUT_AND_PASS:
                if mentions[j].slot == "conj" and mentions[j].words not in ("and", "then"):
                    break
                j += 1
            passing = mentions[j] if j < len(mentions) else None
            if passing is not None and passing.slot == "behaviour" and passing.value[0] == "overtake":
                if passing.prev != "to":  # ("pulls out to overtake ... into our path": the pull-out is the move)
                    drop.add(k)
        out.append((link, [m for k, m in enumerate(mentions) if k not in drop]))
    return out


#: Words of a footway: said of a road user, it is off the road.
_FOOTWAY = ("pavement", "sidewalk", "footpath", "footway")
#: Words of the kerb, the road's edge: a road user is on the footway only when on, off or from it.
_KERB = ("kerb", "curb")
#: Prepositions that put a road user on (or take it off) what they lead.
_ON_OR_OFF = frozenset(("on", "off", "from", "onto", "up", "over"))


def on_the_footway(m) -> bool:
    """Whether kerb mention ``m`` puts its road user off the road, on the footway: a pavement or
    sidewalk always does; a kerb only as what it is on, off or from ("rides on the kerb", "came off
    the curb"). Going along or close to the kerb ("hugging the kerb", "between me and the kerb") is
    riding in the road at its edge, and "the kerb side" names a side, not a place."""
    words = m.words.split()
    if any(w in _FOOTWAY for w in words):
        return True
    kerb = next((k for k, w in enumerate(words) if w in _KERB), None)
    if kerb is None:
        return False
    if kerb == len(words) - 1 and m.next_ in ("side", "lane", "edge"):
        return False  # ("on the kerb side": which side)
    return m.prev in _ON_OR_OFF


#: What a plain verb of motion ("goes", "moved", "heads") is read as before a destination is said.
_PLAIN_MOVES = frozenset(("keep_going",))
#: Verbs (lemmas) the reader may not know as a behaviour that, with a lane as where to, move into it.
_MOVE_VERBS = frozenset(("change", "switch", "move", "go", "get", "swap", "shift"))
#: Words that lead where a move goes.
_TO_A_LANE = frozenset(("to", "into", "onto"))
#: Words that may stand between the verb and where it goes ("goes over to", "moved across from lane 1 into").
_ON_THE_WAY = frozenset(("over", "across", "back", "out", "suddenly", "quickly", "slowly", "then", "straight"))
#: Lanes that are no lane of the ego's direction: a move into them is no lane change.
_NOT_OUR_WAY = frozenset(("opposite", "oncoming", "opposing", "wrong"))
_DETERMINERS = frozenset(("the", "a", "an", "another", "its", "his", "her", "their"))
_BEFORE_EGO = (("in", "front", "of"), ("ahead", "of"), ("just", "ahead", "of"), ("before",))
_EGO_WORDS = frozenset(("me", "us", "ego"))


def _lane_after(tokens: list[str], i: int) -> tuple[int, bool, str] | None:
    """The lane said from ``tokens[i]`` ("the next lane", "another lane", "lane 2", "my lane"): where
    it ends, whether it is the ego's own, and its number ("" if none), or None."""
    j = i
    own = False
    if j < len(tokens) and tokens[j] in _DETERMINERS:
        j += 1
    for owner in _EGO_OWNERS:
        if tuple(tokens[j : j + len(owner)]) == owner:
            own, j = True, j + len(owner)
            break
    start = j
    while j < len(tokens) and j - start < 3 and tokens[j] not in ("lane", "lanes") and tokens[j] not in _STOPS:
        j += 1
    if j >= len(tokens) or tokens[j] not in ("lane", "lanes") or set(tokens[start:j]) & _NOT_OUR_WAY:
        return None
    j += 1
    number = _lane_number(tokens[j]) if j < len(tokens) else ""
    return j + bool(number), own, number


_NUMBER_WORDS = {"one": "1", "two": "2", "three": "3", "four": "4", "five": "5"}


def _lane_number(token: str) -> str:
    """The lane number ``token`` says ("2", "two"), or ""."""
    return token if token.isdigit() else _NUMBER_WORDS.get(token, "")


def _ego_lanes(clauses: list, tokens: list[str]) -> set[str]:
    """The numbers of the lanes the ego is said to be in ("I was in lane 2", "Vehicle 1 ... in lane
    two"): "in lane N" said in a clause whose first road user is the ego, before any other."""
    out = set()
    for _, mentions in clauses:
        first = next((m for m in mentions if m.slot in ("actor", "pronoun")), None)
        if first is None or first.value != "ego":
            continue
        other = next((m.start for m in mentions if m.slot in ("actor", "pronoun") and m.value != "ego"), len(tokens))
        for i in range(first.end, min(other, len(tokens)) - 1):
            if tokens[i] == "in" and tokens[i + 1] == "lane" and i + 2 < len(tokens) and _lane_number(tokens[i + 2]):
                out.add(_lane_number(tokens[i + 2]))
    return out


def _before_the_ego(tokens: list[str], j: int) -> bool:
    """Whether "in front of" / "ahead of" the ego follows ``tokens[j]`` (an adverb or two between;
    not "well ahead of me", which is where, not the ego's lane)."""
    while j < len(tokens) and tokens[j] in ("directly", "right", "just", "immediately", "straight"):
        j += 1
    for lead in _BEFORE_EGO:
        n = len(lead)
        if tuple(tokens[j : j + n]) == lead:
            rest = tokens[j + n : j + n + 3]
            return bool(rest) and (rest[0] in _EGO_WORDS or rest[:2] == ["the", "ego"])
    return False


#: Forms of "be" that make an "-ing" verb after them the finite verb ("is moving", "was drifting").
_BE = frozenset(("is", "was", "are", "were", "'s", "be", "been"))


#: Moves that bring a road user into the ego's way from the side: a verbless "straight into ... lane"
#: after one says where it ends.
_COMING_IN = frozenset(("cut_in", "turn_into", "cross_in_front", "run_red_light"))


def _coming_in(m) -> bool:
    """Whether mention ``m`` is a move into the ego's way from the side (:data:`_COMING_IN`)."""
    return m.slot == "behaviour" and m.value[0] in _COMING_IN


def into_a_lane(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a plain verb of motion whose destination is a lane ("goes over to the next
    lane", "moved from lane 1 into lane 2", "heads into another lane") read as the move it is: into
    the ego's lane (its own words, the number of the lane the ego is said to be in, or "in front of"
    the ego said right after) a cut-in, into any other lane of its way a lane change. The verb says
    only that it moves; where to says which move, and so a behaviour said after it in the same chain
    ("... and then brakes") is the second of two, not the only one. The lane's mention, used up, is
    dropped ("the other lane" is no member of a group)."""
    ego_lanes = _ego_lanes(clauses, tokens)
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        used: set[int] = set()
        for k, m in enumerate(kept):
            plain = m.slot == "ego_verb" or (m.slot == "behaviour" and m.value[0] in _PLAIN_MOVES)
            plain = plain or (m.slot == "unknown_verb" and bool(set(lemmas(m.words).get("VERB", ())) & _MOVE_VERBS))
            across = m.slot == "behaviour" and m.value[0] in ("cross_in_front", "change_lane")  # (into ours: a cut-in)
            progressive = m.start > 0 and tokens[m.start - 1] in _BE  # ("is moving to my lane": a move under way)
            if not (plain or across) or (m.words.split()[0].endswith("ing") and not progressive):
                continue  # ("travelling in lane 2": where it goes along, not a move)
            if m.slot == "ego_verb" and any(_coming_in(x) for x in kept[:k]):
                continue  # ("pulled out of a lay-by, straight into his lane": where that move ends)
            j = m.end
            while j < len(tokens) and tokens[j] in _ON_THE_WAY:
                j += 1
            if j < len(tokens) and tokens[j] == "from":  # ("from lane 1 into lane 2": where it leaves)
                left = _lane_after(tokens, j + 1)
                if left is None:
                    continue
                j = left[0]
            if m.words.split()[-1] in _TO_A_LANE:  # ("moved over into": the verb's phrase holds it)
                j -= 1
            elif j >= len(tokens) or tokens[j] not in _TO_A_LANE:
                continue
            lane = _lane_after(tokens, j + 1)
            if lane is None:
                continue
            end, own, number = lane
            ours = own or (number and number in ego_lanes) or _before_the_ego(tokens, end)
            into = across and m.value[0] == "change_lane" and own and m.words.split()[-1] == "into"
            if across and (not ours or into):
                continue  # (not the ego's lane: it stays; "swerves into my lane": :func:`into_the_ego_lane`'s)
            name = "cut_in" if ours else "change_lane"
            kept[k] = replace(m, slot="behaviour", value=(name, {}))
            used |= {x for x in range(k + 1, len(kept)) if kept[x].slot == "member" and kept[x].start < end}
        out.append((link, [m for x, m in enumerate(kept) if x not in used]))
    return out


def out_of_the_ego_lane(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user said to be in front of the ego ("the car ahead of me", "the van in
    front of us") that moves into another lane ("dives into the next lane", "moves into the outside
    lane") read as changing lanes out of the ego's lane: it is in the ego's lane, so the lane it goes
    into is another, and only a move into the ego's lane (or ending in front of it) is a cut-in. A
    road user said in a lane of its own ("a van in the left lane moves into the next lane") keeps its
    reading: from beside the ego the next lane may be the ego's."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            if m.slot != "behaviour" or m.value[0] not in ("cut_in", "cross_in_front"):
                continue
            j = m.end - (m.words.split()[-1] in ("into", "onto"))
            while j < len(tokens) and tokens[j] in _ON_THE_WAY:
                j += 1  # ("scoots across into the next lane")
            if tokens[j : j + 1] not in (["into"], ["onto"]) or _ends_in_front_of_the_ego(kept, k):
                continue
            lane = _lane_after(tokens, j + 1)
            if lane is None or lane[1] or _before_the_ego(tokens, lane[0]):
                continue  # (no lane, or the ego's: "into my lane", "into the next lane in front of me")
            subject = subject_before(kept[:k])
            if subject is None or subject.value == "pedestrian":
                continue  # (a walker has no lane to change: its move across is a crossing)
            at = kept.index(subject)
            placed = [x for x in kept[at + 1 : k] if x.slot in ("relation", "lane_side", "side", "kerb")]
            if placed and all(x.slot == "relation" and x.value == "ahead" for x in placed):
                kept[k] = replace(m, value=("change_lane", {}))
        out.append((link, kept))
    return out


def _verb_into_a_lane(tokens: list[str], j: int, ego_lanes: set[str]) -> tuple[int, bool] | None:
    """Where the words end that say the verb at ``tokens[j]`` moves into a lane ("jinks out into lane
    2", "nips over into the next lane"), and whether that lane is the ego's; None if they do not. The
    verb is any inflected verb: the lane it goes into says the move."""
    said = lemmas(tokens[j])
    verbs = set(said.get("VERB", ()))
    unknown = not said and tokens[j].isalpha() and tokens[j].endswith(("s", "ed"))  # ("jinks": a verb by its place)
    if not (verbs or unknown) or verbs & {"be", "have", "do"} or tokens[j] in verbs or tokens[j].endswith("ing"):
        return None  # (no verb; a bare form or a participle: "lane" after them is where, not where to)
    k = past_its_own_object(tokens, j + 1)  # ("nosed its way into lane 2")
    while k < len(tokens) and tokens[k] in _ON_THE_WAY:
        k += 1
    if k >= len(tokens) or tokens[k] not in ("into", "onto"):
        return None
    lane = _lane_after(tokens, k + 1)
    if lane is None:
        return None
    end, own, number = lane
    return end, bool(own or (number and number in ego_lanes) or _before_the_ego(tokens, end))


def into_another_lane(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a verb the reader holds as no behaviour whose destination is a lane ("he jinks
    out into lane 2", "the lorry nips over into the next lane") read as the move into that lane: a
    cut-in into the ego's lane, else a lane change. Only the road user the clause is about, named
    before the verb and not the ego, is read so."""
    ego_lanes = _ego_lanes(clauses, tokens)
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        if not kept:
            out.append((link, kept))
            continue
        for j in range(kept[0].start, min(max(x.end for x in kept), len(tokens))):
            at = next((x for x in kept if x.start <= j < max(x.end, x.start + 1)), None)
            if at is not None:
                continue
            before = [x for x in kept if x.start < j]
            subject = subject_before(before)
            if subject is None or any(x.slot == "behaviour" and x.start > subject.start for x in before):
                continue  # (no road user, or one whose verb is read already)
            said = _verb_into_a_lane(tokens, j, ego_lanes)
            if said is None or negated(tokens, j):
                continue  # (no move into a lane, or one denied: "never forced its way into my lane")
            end, ours = said
            move = ("cut_in" if ours else "change_lane", {})
            new = word_mention(subject, tokens, j, "behaviour", move)
            kept.insert(kept.index(before[-1]) + 1, new)
            break
        out.append((link, kept))
    return out


#: Mentions that may stand between a slowing and the stop it ends in ("slows, and stops", "eases off
#: gently and pulls up").
_BETWEEN_SLOWING_AND_STOP = frozenset(("conj", "punct", "criticality", "speed_word"))
_STOPPING = frozenset(("stop", "sudden_stop"))


def slowing_into_a_stop(clauses: list) -> list:
    """``clauses`` without a slowing said just before the stop it ends in ("slows down and stops",
    "decelerates and comes to a halt", "eases off and pulls up"): slowing is how a stop is made, not a
    speed change of its own. A slowing to a stated speed ("slows to 30 km/h and then stops") is a
    step of its own and stays."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        drop: set[int] = set()
        for k, m in enumerate(kept):
            slowing = m.slot == "behaviour" and m.value[0] == "change_speed"
            if not (slowing and m.value[1].get("speed_delta_mps", 0) < 0):
                continue
            j = k + 1
            while j < len(kept) and kept[j].slot in _BETWEEN_SLOWING_AND_STOP:
                if kept[j].slot == "conj" and kept[j].words not in ("and", "then", "and then"):
                    break
                j += 1
            nxt = kept[j] if j < len(kept) else None
            if nxt is not None and (nxt.slot == "to_stop" or (nxt.slot == "behaviour" and nxt.value[0] in _STOPPING)):
                drop.add(k)  # (how it slows is how it stops: "brakes gently and comes to a halt" is a gentle stop)
                kept[j] = replace(nxt, words=f"{m.words} {nxt.words}")
        out.append((link, [m for k, m in enumerate(kept) if k not in drop]))
    return out


#: Words a verb of motion takes right after it ("came round", "pulled out", "drove along").
_PARTICLES = frozenset(("round", "around", "out", "off", "up", "down", "into", "onto", "along", "through", "over",
                        "past", "across", "back", "away", "in", "on", "at", "to", "from", "towards"))  # fmt: skip


def diary(tokens: list[str]) -> bool:
    """Whether the text opens as a driver's diary, its "I" left out: an auxiliary and a participle
    ("Was doing 50 kph ...", "Were sitting at the lights ..."), or a verb in the past and the particle
    or preposition it takes ("Came round a blind bend ...", "Pulled out of the junction ..."). A past
    participle before a noun ("Parked cars on both sides") is no such verb. The story is then the
    narrator's, as one told with "I" is."""
    if len(tokens) < 2:
        return False
    first, second = tokens[0], tokens[1]
    if first in ("was", "were"):
        return second.endswith("ing")
    verbs = lemmas(first).get("VERB", ())
    past = bool(verbs) and first not in verbs and not first.endswith(("s", "ing"))
    return past and second in _PARTICLES


def weather_not_behaviour(clauses: list) -> list:
    """``clauses`` without a verb whose subject is the weather ("snow was falling", "rain had started
    falling", "hail kept coming down"): what the weather does is the setting, no road user's behaviour.
    The subject is the weather mention right before the verb, with only auxiliaries or verbs of aspect
    ("was", "kept", "had started") between."""
    out = []
    for link, mentions in clauses:
        kept = [
            m
            for k, m in enumerate(mentions)
            if not (
                m.slot == "behaviour"
                and k > 0
                and mentions[k - 1].slot in ("weather", "unknown_verb")
                and _weather_word(mentions[k - 1])
                and 0 <= m.start - mentions[k - 1].end <= 3
            )
        ]
        out.append((link, kept))
    return out


#: Words of weather that fall or come down ("hail", which the reader may not know as a setting).
_PRECIPITATION = frozenset(("rain", "snow", "sleet", "hail", "drizzle", "snowflakes", "raindrops"))


def _weather_word(m) -> bool:
    """Whether mention ``m`` names the weather (a setting the reader read, or a word of precipitation)."""
    return m.slot == "weather" or m.words in _PRECIPITATION


#: Verbs (lemmas) that with "a left" / "a right" say a turn ("make a right", "hang a left", "take a right").
_TURN_VERBS = frozenset(("make", "take", "hang", "do", "pull", "swing", "chuck"))
#: Words after "the left/right" that make it a place, not a turn ("takes the right lane").
_NOT_A_TURN = frozenset(("lane", "lanes", "side", "kerb", "curb", "edge", "hand", "shoulder", "verge", "of"))


def a_left_or_a_right(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with "make / take / hang a left (a right, a left turn)" read as turning that way,
    as "turns left" is, whoever does it: the verb is light, the turn is its object."""
    out = []
    for link, mentions in clauses:
        kept: list = []
        skip = -1
        for k, m in enumerate(mentions):
            if k == skip:
                continue
            nxt = mentions[k + 1] if k + 1 < len(mentions) else None
            verb = m.words.split()[0]
            if (
                m.slot in ("unknown_verb", "ego_verb", "behaviour")
                and len(m.words.split()) == 1
                and set(lemmas(verb).get("VERB", ())) & _TURN_VERBS
                and nxt is not None
                and nxt.slot == "side"
                and nxt.value in ("left", "right")
                and tokens[m.end : nxt.start] in (["a"], ["the"])
                and (nxt.end >= len(tokens) or tokens[nxt.end] not in _NOT_A_TURN)
            ):
                words = f"{m.words} {' '.join(tokens[m.end : nxt.end])}"
                kept.append(replace(m, slot="behaviour", value=("forced_turn", {"turn": nxt.value}), words=words,
                                    end=nxt.end))  # fmt: skip
                skip = k + 1
                continue
            kept.append(m)
        out.append((link, kept))
    return out


#: Moves across lanes that a turn said as their purpose makes part of that turn.
_LATERAL = frozenset(("cut_in", "change_lane", "cross_in_front"))


def across_to_turn(clauses: list) -> list:
    """``clauses`` without a move across lanes made to turn ("swings across my lane to make a right",
    "cuts over in front of me to turn left"): the turn said as its purpose (after "to") is the
    behaviour, the move across how it begins. A pull-out of a side road made to turn ("emerged from a
    side road on my left, intending to turn right") is turning into the ego's road: the turn is where
    it goes once out, and the pull-out stays, read as that turn."""
    out = []
    for link, mentions in clauses:
        mentions = list(mentions)
        drop: set[int] = set()
        for k, m in enumerate(mentions):
            if not (m.slot == "behaviour" and m.value[0] in _LATERAL):
                continue
            for q, x in enumerate(mentions[k + 1 :], k + 1):
                if x.slot in ("actor", "pronoun") and x.value != "ego" or x.slot == "link":
                    break
                turning = x.slot == "turn" or (x.slot == "behaviour" and x.value[0] == "forced_turn")
                if turning and x.prev == "to" and m.value[1].get("from_side_road"):
                    mentions[k] = replace(m, value=("turn_into", m.value[1]))
                    drop.add(q)
                    break
                if turning and x.prev == "to":
                    drop.add(k)
                    break
        out.append((link, [m for k, m in enumerate(mentions) if k not in drop]))
    return out


#: Where a vehicle parked stands in the way, not at the side ("parked in the lane", "on the road").
_IN_THE_WAY = frozenset(("lane", "road", "carriageway", "roadway", "street"))


def parked_in_the_lane(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a vehicle said parked in the lane or on the road ("a lorry parked in the lane",
    "a van parked in our lane") read as standing there, in the way, not parked at the kerb: where it
    is parked says which."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            if m.slot != "stationary" or "park" not in m.words:
                continue
            after = tokens[m.end : m.end + 4]
            if after[:1] in (["in"], ["on"]) and len(after) > 2 and after[1] in _DETERMINERS | {"my", "our"}:
                if after[2] in _IN_THE_WAY and after[2:4] != ["road", "side"]:
                    kept[k] = replace(m, words="standing")
        out.append((link, kept))
    return out


#: Adjectives of a vehicle's state that say it stands only said of it, right before its noun ("a
#: broken car"; not "the broken line", "a broken light").
_STATE_BEFORE_NOUN = frozenset(("broken",))


def state_before_its_noun(clauses: list, tokens: list[str]) -> list:
    """``clauses`` without a state adjective ("broken") not right before a road user's noun: said of
    anything else it is no road user's state."""
    out = []
    for link, mentions in clauses:
        kept = []
        for k, m in enumerate(mentions):
            nxt = mentions[k + 1] if k + 1 < len(mentions) else None
            noun = nxt is not None and nxt.slot == "actor" and set(tokens[m.end : nxt.start]) <= _DETERMINERS
            if m.slot == "stationary" and m.words in _STATE_BEFORE_NOUN and not noun:
                continue
            kept.append(m)
        out.append((link, kept))
    return out


#: "There is / are / was / were": what follows is said to be there, for the first time.
_EXISTENTIAL = frozenset(("is", "are", "was", "were", "'s"))


def there_is_a_new_one(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with the road user after "there is / was" ("because there is broken car stop on
    road") read as a new one, with or without its article: an existential sentence introduces what it
    names. (A bare noun otherwise names one already met, as terse writing drops articles.) A
    stationary adjective before it ("broken", "stopped") stays its own."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        drop: set[int] = set()
        for k, m in enumerate(kept):
            if m.slot != "actor" or m.value == "ego" or m.det not in ("", "the"):
                continue
            i = m.start - 1
            while i >= 0 and (
                tokens[i] in _DETERMINERS or any(x.slot == "stationary" and x.start <= i < x.end for x in kept[:k])
            ):
                i -= 1  # (past "broken", "stopped": the vehicle's state; "there is the ..." is no known one)
            if not (i >= 1 and tokens[i] in _EXISTENTIAL and tokens[i - 1] == "there"):
                continue
            kept[k] = replace(m, det="a")
            for j in range(k - 1, -1, -1):
                x = kept[j]
                if x.start < i:
                    break
                if x.slot == "stationary":  # (its state, said of it: up to its noun)
                    kept[j] = replace(x, end=m.start, next_=tokens[m.start])
                elif x.start == i and x.slot in ("ego_verb", "unknown_verb"):
                    drop.add(j)  # ("there is": no verb of anyone's; what is there is the subject of what follows)
        out.append((link, [m for j, m in enumerate(kept) if j not in drop]))
    return out


#: Words of quantity before a noun whose "to" + verb says what there is room for ("no room to stop").
_QUANTITY = frozenset(("no", "enough", "insufficient", "sufficient", "little", "any", "more", "less", "much",
                       "some", "the", "a", "plenty", "not"))  # fmt: skip


#: Words before "a" + a noun that say what someone has with them ("with a pram"), not how much room.
_HAS_WITH = frozenset(("with", "pushing", "carrying", "holding"))


def room_to_act_not_behaviour(clauses: list, tokens: list[str]) -> list:
    """``clauses`` without a verb said as what a quantity of something allows ("leaving no room to
    stop", "with too little space to brake", "not enough time to swerve"): the infinitive completes
    the noun; nobody does it."""
    out = []
    for link, mentions in clauses:
        kept = []
        for m in mentions:
            i = m.start
            if m.slot == "behaviour" and i >= 3 and tokens[i - 1] == "to" and tokens[i - 3] in _QUANTITY:
                if tokens[i - 3] in ("a", "an") and i >= 4 and tokens[i - 4] in _HAS_WITH:
                    kept.append(m)  # ("a woman with a pram to cross": what she has, not a quantity)
                    continue
                named = any(x.start <= i - 2 < max(x.end, x.start + 1) and x.slot != "unknown_verb" for x in mentions)
                if "NOUN" in lemmas(tokens[i - 2]) and not named:  # (not "tells the van to stop": a road user)
                    continue
            kept.append(m)
        out.append((link, kept))
    return out


def chains(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with what a chain of verbs says one road user does read move by move: a plain move
    into a lane as the lane change or cut-in it is (:func:`into_a_lane`), letting the ego go as giving
    way (:func:`lets_the_ego_go`), a slowing into a stop as the stop (:func:`slowing_into_a_stop`), and
    what the weather does as no one's behaviour (:func:`weather_not_behaviour`), "makes a left" as
    turning left (:func:`a_left_or_a_right`), a move across made to turn as the turn
    (:func:`across_to_turn`); and who stands in the way, for a cut-out (:func:`parked_in_the_lane`,
    :func:`there_is_a_new_one`), a lead's move into another lane as a lane change
    (:func:`out_of_the_ego_lane`), a verb + "in" ending in front of the ego as a cut-in
    (:func:`in_in_front_of_the_ego`), passing on the wrong side as an overtake
    (:func:`overtakes_on_the_wrong_side`), a move into the lane the ego is said to be in as a cut-in
    (:func:`into_the_lane_the_ego_is_in`), any verb into a lane as that move (:func:`into_another_lane`);
    "no room to stop" as nobody's stop (:func:`room_to_act_not_behaviour`); a stop
    made abruptly as a sudden stop (:func:`hard_stops`); one coming along in the ego's lane as coming
    at it (:func:`coming_in_the_ego_lane`); a swerve round the ego as going on past it
    (:func:`round_the_ego`)."""
    clauses = right_at_the_ego(overtakes_on_the_wrong_side(the_wrong_side_of(clauses)), tokens)
    clauses = sudden_returns_at_the_ego(in_in_front_of_the_ego(clauses, tokens), tokens)
    clauses = hard_stops(weather_not_behaviour(room_to_act_not_behaviour(clauses, tokens)), tokens)
    clauses = coming_from_in_front(moving_out_to_pass(a_left_or_a_right(clauses, tokens), tokens), tokens)
    clauses = across_to_turn(turning_to_a_side(clauses, tokens))
    clauses = there_is_a_new_one(parked_in_the_lane(state_before_its_noun(clauses, tokens), tokens), tokens)
    clauses = coming_in_the_ego_lane(
        passes_while_the_ego_yields(
            follows_with_nothing_named(
                follows_the_ego(at_a_time_gap_behind(on_the_ego_tail(clauses, tokens)), tokens), tokens
            )
        )
    )
    clauses = round_the_ego(passing_in_front(out_into_the_road(clauses, tokens), tokens), tokens)
    clauses = straight_across(clauses, tokens)
    clauses = with_a_thing_out_into_the_road(out_across_the_road(clauses, tokens), tokens)
    clauses = on_a_foot_crossing(out_of_a_place_then_across(clauses), tokens)
    clauses = out_of_the_ego_lane(into_a_lane(into_another_lane(clauses, tokens), tokens), tokens)
    clauses = over_to_the_ego_half(into_the_lane_the_ego_is_in(clauses, tokens), tokens)
    return walkers_cross(slowing_into_a_stop(lets_the_ego_go(clauses, tokens)))


def walkers_cross(clauses: list) -> list:
    """``clauses`` with a cut-in said with a verb of going on foot ("stepped off the kerb into my path",
    "walked out into my lane") read as the crossing it is: into the ego's lane or path a vehicle cuts
    in, but one who steps or walks there crosses in front of the ego, whoever the noun names ("a
    guy", "a woman", whom a cut-in would make a driver)."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            if m.slot == "behaviour" and m.value[0] == "cut_in" and _on_foot(m):
                kept[k] = replace(m, value=("cross_in_front", {}))
        out.append((link, kept))
    return out


#: Verbs (lemmas) of a sudden move aside.
_SWERVES = frozenset(("swerve", "veer", "steer", "dodge", "jink", "weave", "jerk"))
#: The front of something, said as what one swerves round ("round the front of my car").
_FRONTS = frozenset(("front", "nose", "bonnet", "hood"))


def round_the_ego(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user's swerve round the ego ("had to swerve round my bonnet", "veered
    around the front of my car", "swerved round us") read as going on: it avoids the ego and keeps
    its way; a move out of its lane is a swerve round something standing in it ("swerved round a
    broken-down van": a cut-out stays one)."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        behind = False  # (the road user named last is said behind the ego: "came up behind me")
        for k, m in enumerate(kept):
            behind = _behind_after_the_last_named(kept, k, behind)
            swerve = bool(set(lemmas(m.words.split()[0]).get("VERB", ())) & _SWERVES)
            if m.slot != "behaviour" or not (swerve or (behind and m.words.split()[-1] in _OUT_ROUND)):
                continue
            j = m.end if m.words.split()[-1] in ("round", "around", "past") else m.end + 1
            if tokens[j - 1 : j] not in (["round"], ["around"], ["past"]):
                continue
            later = [x for x in kept[k + 1 :] if x.slot == "actor" and x.start < j + 6]
            if _names_the_ego(tokens[j : j + 6], later):
                kept[k] = replace(m, value=("overtake", {}) if behind else ("keep_going", {}))
        out.append((link, kept))
    return out


def _behind_after_the_last_named(mentions: list, k: int, so_far: bool) -> bool:
    """Whether the road user that does ``mentions[k]`` is said behind the ego before it, given
    ``so_far`` for ``mentions[:k - 1]``: "behind" said after the last road user named (not the ego's
    own "I was behind a van"), looking at one mention more each call."""
    if k == 0:
        return False
    m = mentions[k - 1]
    if m.slot == "actor" and m.value != "ego":
        return False  # (a road user named anew: what was said before is another's)
    return so_far or (_from_behind_the_ego(m, mentions[k]) and _named_before(mentions, k - 1))


def _named_before(mentions: list, k: int) -> bool:
    """Whether a road user other than the ego is named before ``mentions[k]``."""
    return any(x.slot == "actor" and x.value != "ego" for x in mentions[:k])


#: The last word of a move out of a lane or round something ("swung out", "pulled round").
_OUT_ROUND = frozenset(("out", "round", "around", "past", "wide"))


def _from_behind_the_ego(m, after) -> bool:
    """Whether ``m`` (``after``: the mention after it) says its road user is behind the ego before it
    moves ("came up behind me", "from behind", "a cyclist behind us", "tailing me"): not behind
    another road user ("behind the van", "behind it"). A move out and round the ego after it is an overtake of the ego,
    not a swerve of one coming at it."""
    words = m.words.split()
    if m.slot == "behaviour" and m.value[0] == "follow_vehicle":  # ("a cyclist following me")
        return after is not None and _the_ego(after) and after.start <= m.end + 1
    if not (m.slot == "relation" and m.value == "behind"):
        return False
    if words[-1] in _EGO_WORDS or (after is not None and _the_ego(after) and after.start == m.end):
        return True  # ("behind me", "following us", "tailing the ego")
    other = after is not None and after.start == m.end and after.slot == "actor"
    return words[-1] == "behind" and not other and m.next_ not in _BEHIND_WHAT


#: Words after "behind" that name what else it is behind ("behind the bus", "behind it").
_BEHIND_WHAT = frozenset(("the", "a", "an", "that", "this", "his", "her", "their", "its", "it", "him", "them"))


def _names_the_ego(obj: list[str], named: list) -> bool:
    """Whether the object ``obj`` of "round" is the ego or its front: "me", "us", "my bonnet", "the
    front of my car", "the front of" something that is no other road user named (``named``: the
    road users named in it)."""
    if named:
        return named[0].value == "ego"
    if obj[:1] and (obj[0] in _EGO_WORDS or obj[0] in ("my", "our")):
        return True
    return obj[:1] == ["the"] and obj[1:2] != [] and obj[1] in _FRONTS


def _a_following(m) -> bool:
    """Whether ``m`` says following: the behaviour, or "following" read as where one is (behind)."""
    if m.slot == "behaviour":
        return m.value[0] == "follow_vehicle" and m.prev not in _DENYING
    return m.slot == "relation" and m.value == "behind" and "follow" in lemmas(m.words.split()[0]).get("VERB", ())


def _the_ego(m) -> bool:
    return m.slot == "actor" and m.value == "ego"


def _behind_the_ego(m, after) -> bool:
    """Whether ``m`` (``after``: the mention after it) says "behind" the ego ("behind us", "behind"
    + the ego named on its own): following behind it is following it."""
    words = m.words.split()
    if not (m.slot == "relation" and m.value == "behind" and words[0] == "behind"):
        return False
    return words[-1] in _EGO_WORDS or (
        words == ["behind"] and after is not None and _the_ego(after) and after.start == m.end
    )


def follows_the_ego(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user following the ego ("a bus is following us", "tailgating me",
    "follows the ego", "following behind us") read as following it from behind: the ego as the object
    of a verb of following said of a road user is what it follows, so it starts behind the ego and
    keeps to its speed."""
    out = []
    for link, mentions in clauses:
        kept: list = []
        for k, m in enumerate(mentions):
            nxt = mentions[k + 1] if k + 1 < len(mentions) else None
            subject = next((x for x in reversed(mentions[:k]) if x.slot == "actor"), None)
            if (
                _a_following(m)
                and nxt is not None
                and (_the_ego(nxt) or _behind_the_ego(nxt, mentions[k + 2] if k + 2 < len(mentions) else None))
                and all(t in ("the", "a") or "ADV" in lemmas(t) for t in tokens[m.end : nxt.start])
                and subject is not None
                and subject.value != "ego"
            ):
                kept.append(replace(m, slot="behaviour", value=("follow_vehicle", {})))
                kept.append(replace(m, slot="relation", value="behind"))
                continue
            kept.append(m)
        out.append((link, kept))
    return out


#: Words before "following" that make it a word of order or a noun's modifier ("the following car").
_BEFORE_AN_ADJECTIVE = frozenset(("the", "a", "an", "this", "that", "our", "my"))


#: Slots of a road user's own act in a clause: what it does besides following ("stopped", "turned right").
_ACTS = frozenset(("behaviour", "stationary", "turn"))


def _has_object(tokens: list[str], end: int) -> bool:
    """Whether "following" ending before ``end`` has an object of its own: a determiner or a noun right
    after it ("following the satnav", "following directions"). Then it follows that, not the ego; a
    pronoun ("following me") is the one the telling is about."""
    nxt = tokens[end] if end < len(tokens) else ""
    return nxt in _OBJECT_OPENERS or (set(lemmas(nxt)) == {"NOUN"} and nxt not in OBJECT_PRONOUNS)


#: Words that open an object noun phrase.
_OBJECT_OPENERS = frozenset(("the", "a", "an", "its", "his", "her", "their", "my", "our", "your", "this", "that"))


def follows_with_nothing_named(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user said to be following, with nothing named that it follows ("a
    hatchback following at 2 s", "a lorry is following about 20 m back", "trailing car following at
    1.2 s"), read as following the ego: "follow" is transitive, and where its object is left out it is
    the one the telling is about, ahead of the follower. The road user is the clause's subject, not
    the ego; anything else named after it (another road user, "a bus") is what it follows, read
    elsewhere, and an act of its own in the clause ("following at 2 s, braked hard", a stop or a turn) is
    what it does, not the following; nor does one following something named ("following the satnav")."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if m.slot != "relation" or not _a_following(m) or (m.start and tokens[m.start - 1] in _BEFORE_AN_ADJECTIVE):
                continue
            subject = subject_before(mentions[:k])
            if subject is None or _has_object(tokens, m.end):
                continue
            after_subject = mentions[mentions.index(subject) + 1 :]
            if any(x.slot in _ACTS for x in after_subject) or any(
                x.slot in ("actor", "pronoun") and x.value != "ego" for x in mentions[k + 1 :]
            ):
                continue
            kept.insert(kept.index(m) + 1, replace(m, slot="behaviour", value=("follow_vehicle", {})))
            break
        out.append((link, kept))
    return out


#: What a road user the ego passes may already be said to do: going on, along the road or its lane.
_BEING_PASSED = frozenset(("keep_going", "along_road", "keep_lane"))


def passes(m) -> bool:
    """Whether mention ``m`` is a verb of passing ("passes", "overtook", "went past")."""
    return m is not None and m.slot == "behaviour" and m.value[0] == "overtake" and m.prev not in _DENYING


#: Words that, right before a verb or noun of passing, say it is not done ("no overtake", "never passed").
_DENYING = frozenset(("no", "not", "never", "without", "n't", "nor"))


def passed_goes_along(behaviours: list, passed: bool) -> list:
    """``behaviours`` of a road user the ego passes ("the ego overtakes her", "ego passes him"): being
    passed, it goes along the road ahead of the ego, not across it, whatever its place would otherwise
    make of a road user said only to go on. A move said of it (it turns, it cuts in) stays."""
    if not passed or not all(b[0] in _BEING_PASSED for b in behaviours):
        return behaviours
    return [("along_road", {}, *behaviours[0][2:])]


def passes_someone(m, nxt) -> bool:
    """Whether ``m`` is a verb of passing with a road user as its object ("overtook a cyclist", not
    "passes me" nor "passes without any conflict")."""
    return (
        passes(m)
        and nxt is not None
        and nxt.slot in ("actor", "pronoun")
        and nxt.value != "ego"
        and nxt.start <= m.end + 2
    )


#: What the ego does when it lets another go first: gives way, waits, stops.
_EGO_HOLDS = frozenset(("give_way", "stop"))


def passes_while_the_ego_yields(clauses: list) -> list:
    """``clauses`` with a road user passing, with no one as the object, after the ego gives way ("ego
    yields and the scooter passes", "we wait; the bus goes past") read as going on: it passes through
    the place the ego holds back from, it does not overtake the ego. Going on, it has the way
    ("_has_way"): it does not run across the ego's path against a signal, the ego let it by."""
    out = []
    held = False
    for link, mentions in clauses:
        kept: list = []
        for k, m in enumerate(mentions):
            before = mentions[k - 1] if k else None
            if before is not None and before.slot == "modal":
                before = mentions[k - 2] if k > 1 else None
            holds = m.slot == "stationary" or (m.slot == "behaviour" and m.value[0] in _EGO_HOLDS)
            if holds and before is not None:
                held = held or (before.slot == "actor" and before.value == "ego")
            nxt = mentions[k + 1] if k + 1 < len(mentions) else None
            acted_on = nxt is not None and nxt.slot in ("actor", "pronoun") and nxt.start <= m.end + 2
            by_another = not (before is not None and before.value == "ego")
            if held and passes(m) and not acted_on and by_another:
                kept.append(replace(m, value=("keep_going", {"_has_way": 1.0})))
                continue
            if held and m.slot == "behaviour" and m.value[0] == "keep_going" and by_another:
                kept.append(replace(m, value=("keep_going", {**m.value[1], "_has_way": 1.0})))
                continue
            kept.append(m)
        out.append((link, kept))
    return out


#: Adverbs of a hard or sudden manner ("abruptly", "sharply"); their adjective said as an adverb
#: ("stopped very sudden", "braked strong"), as second-language writers often do, says the same.
_HARD_MANNER = frozenset(
    ("abruptly", "suddenly", "sharply", "harshly", "violently", "strongly", "hard", "dead", "heavily")
)
#: Words that only make the adverb after them stronger ("very abruptly").
_INTENSIFIERS = frozenset(("very", "really", "so", "quite", "extremely", "too", "rather"))
#: Verbs of stopping (lemmas) a stationary mention may be said with ("stopped", not "parked").
_STOP_VERBS = frozenset(("stop", "halt"))


def _hard_manner(word: str) -> bool:
    """Whether ``word`` says a hard or sudden manner, as its adverb or its adjective ("abrupt")."""
    return word in _HARD_MANNER or f"{word}ly" in _HARD_MANNER


def _stopping(m) -> bool:
    """Whether mention ``m`` is a road user's plain stop: the behaviour, or "stopped" read as a state."""
    if m.slot == "behaviour":
        return m.value[0] == "stop" and m.prev not in _DENYING
    verb = m.words.split()[-1]
    stops = bool(set(lemmas(verb).get("VERB", ())) & _STOP_VERBS)
    return m.slot == "stationary" and verb.endswith(("ed", "s")) and stops


def said_hard(tokens: list[str], m) -> bool:
    """Whether the verb of mention ``m`` is said in a hard manner: an adverb of one right before it or
    right after it, past an intensifier ("abruptly stopped", "stopped very sharply")."""
    j = m.end
    while j < len(tokens) and tokens[j] in _INTENSIFIERS:
        j += 1
    after = j < len(tokens) and _hard_manner(tokens[j])
    return after or (m.start > 0 and _hard_manner(tokens[m.start - 1]) and tokens[m.start - 1] != "dead")


def hard_stops(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a stop said in a hard or sudden manner ("stopped abruptly", "abruptly stopped",
    "stopped very sudden") read as the sudden stop it is: the adverb right before the verb, or right
    after it (past an intensifier), is how that stop is made. An adverb further on belongs to the next
    verb ("stopped, then pulled away abruptly")."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            if not _stopping(m):
                continue
            if said_hard(tokens, m):
                kept[k] = replace(m, slot="behaviour", value=("sudden_stop", {}))
        out.append((link, kept))
    return out


#: Prepositions that put a road user in a lane or on a side of the road, not into it.
_IN_OR_ON = frozenset(("in", "on", "down", "along", "up"))


def coming_in_the_ego_lane(clauses: list) -> list:
    """``clauses`` with a road user that "comes" along in the ego's own lane or on its side of the road
    ("a tractor came round the corner on my side of the road", "a van was coming down the hill in my
    lane") read as coming towards the ego: "come" is motion towards the one telling, and in the ego's
    lane that is head-on. Coming up behind, or into the lane, is not: any other place said in the
    clause ("behind us", "from the right") or "into" keeps the verb a plain going on; so does a pass
    said before it ("overtook me, then came in my lane": going the ego's way, it cuts back in)."""
    out = []
    passed = False
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            passed = passed or passes(m) or (m.slot == "relation" and m.value == "behind")
            if passed or not (m.slot == "behaviour" and m.value[0] == "keep_going"):
                continue
            if "come" not in lemmas(m.words.split()[0]).get("VERB", ()):
                continue
            subject = next((x for x in reversed(mentions[:k]) if x.slot in ("actor", "pronoun")), None)
            if subject is None or subject.value == "ego":
                continue
            places = [x for x in mentions[k + 1 :] if x.slot in ("relation", "side", "lane_side", "kerb", "arm")]
            lane = next((x for x in places if x.slot == "relation" and in_the_ego_lane(x.words)), None)
            if lane is None or lane.words.split()[0] not in _IN_OR_ON:
                continue
            if any(x.slot != "relation" or x.value not in ("ahead", "oncoming") for x in places):
                continue  # ("came up behind us in our lane", "came from the left into my lane")
            towards = replace(lane, value="oncoming", words="towards")
            kept.insert(kept.index(lane), towards)
            break
        out.append((link, kept))
    return out


#: The lines that divide the two ways of a road ("the centre line"): first words, and the phrases.
_DIVIDING = frozenset(("centre", "center", "centreline", "centerline", "white", "dividing", "double"))
#: Where a move into a lane says it came from beside the ego, not from the other way's half.
_FROM_BESIDE = frozenset(("side", "lane_side", "kerb", "kerb_side"))


def _over_the_dividing_line(tokens: list[str], m) -> bool:
    """Whether move ``m`` goes over the line between the two ways ("drifted over the centre line",
    "veered across the white line"): its last word or the next one is "over" / "across", then "the"
    and a dividing line (not "the lane line": a line between lanes of one way)."""
    j = m.end
    if m.words.split()[-1] not in ("over", "across"):
        if tokens[j : j + 1] not in (["over"], ["across"]):
            return False
        j += 1
    line = tokens[j + 1 : j + 3]
    return tokens[j : j + 1] == ["the"] and bool(line) and line[0] in _DIVIDING and "lane" not in line


def _onto_the_ego_half(tokens: list[str], j: int) -> bool:
    """Whether the ego's half of the road is entered from ``tokens[j]`` ("onto our side of the road",
    "onto my side", "on to our half"): "onto" / "on to" and a side or half owned by the ego."""
    if tokens[j : j + 2] == ["on", "to"]:
        j += 1
    if tokens[j : j + 1] != ["onto"] and tokens[j : j + 1] != ["to"]:
        return False
    said = tokens[j + 1 : j + 3]
    return len(said) == 2 and said[0] in _EGO_OWNER_WORDS and said[1] in ("side", "half")


def over_to_the_ego_half(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user's move into a lane over the line dividing the two ways ("drifted
    over the centre line into my lane") or onto the ego's half of the road ("swung onto our side of
    the road") read as coming at the ego in its lane: the two ways are split by that line, so who
    crosses it into the ego's half comes from the other way's half, head-on, whatever verb of
    moving across says it. One said to be beside the ego (a side, a lane, a kerb: "a car on my
    right drifted into my lane") moves in from there: a cut-in."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if not (m.slot == "behaviour" and m.value[0] in ("cut_in", "change_lane")):
                continue
            subject = next((x for x in reversed(mentions[:k]) if x.slot in ("actor", "pronoun")), None)
            if subject is None or subject.value == "ego":
                continue
            between = mentions[mentions.index(subject) + 1 : k]
            if any(x.slot in _FROM_BESIDE or x.slot == "relation" for x in between):
                continue  # ("a car on my right drifted into my lane": from beside the ego)
            nxt = mentions[k + 1] if k + 1 < len(mentions) else None
            over = _over_the_dividing_line(tokens, m) or (nxt is not None and nxt.slot == "over_line")
            cut = nxt is not None and nxt.slot == "map" and nxt.start <= m.end + 1  # ("cut the corner onto ...")
            onto = _onto_the_ego_half(tokens, nxt.end if cut else m.end)
            if not (over or onto):
                continue
            towards = replace(m, slot="relation", value="oncoming", words="towards")
            placed = replace(m, slot="over_line", value=None, words="over the line")
            at = kept.index(nxt) + 1 if cut else kept.index(m) + 1  # (past the corner it cuts)
            kept[at:at] = [towards, placed]
            break
        out.append((link, kept))
    return out


#: What of the ego a turn crosses, after "across" and its owner ("across my path", "across our bonnet"):
#: its way, or the front of the vehicle that meets what turns over it.
_ACROSS_WAYS = frozenset(("path", "way", "lane", "lanes", "side", "front", "nose", "bonnet", "hood"))


def moving_out_to_pass(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a move out said to be made to pass ("swung out to overtake a tractor", "pulled
    out to pass the bus") read as the pass alone: "to" + the pass says what the move out is for, so
    it is the start of the overtake, not a pull-out across the ego's way from a side road."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions[:-1]):
            nxt = mentions[k + 1]
            if m.slot != "behaviour" or m.value[0] != "cross_in_front" or m.words.split()[-1] != "out":
                continue  # (a move out read as a cut-in, "out to overtake, right into our path", stays)
            if tokens[m.end : m.end + 1] != ["to"]:
                continue
            if nxt.slot == "behaviour" and nxt.value[0] == "overtake" and nxt.start == m.end + 1:
                kept.remove(m)
        out.append((link, kept))
    return out


def coming_from_in_front(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user described by "coming" + in front of / ahead of the ego ("a van
    coming in front of me", "a lorry coming ahead of us") read as coming towards the ego: "come" is
    motion towards the one telling, and from in front of the ego that is from the other way. Only
    the participle right after its noun counts: "a car came in front of me" (a finite verb) is one
    getting in front, a cut-in, and a place said before "coming" is not where the motion comes from."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if m.slot != "actor" or m.value == "ego" or tokens[m.end : m.end + 1] != ["coming"]:
                continue
            place = next((x for x in mentions[k + 1 :] if x.start > m.end), None)
            if place is None or place.slot != "relation" or place.value != "ahead" or place.start != m.end + 1:
                continue
            j = tokens.index("of", place.start) + 1 if "of" in tokens[place.start : place.start + 3] else -1
            if j < 0 or j >= len(tokens) or tokens[j] not in _EGO_WORDS:
                continue  # ("coming in front of the bus": ahead of another road user, not of the ego)
            kept[kept.index(place)] = replace(place, value="oncoming")
            break
        out.append((link, kept))
    return out


def _across_the_ego(tokens: list[str], j: int) -> bool:
    """Whether "across" + the ego's path, way or lane is said from ``tokens[j]`` ("across my path",
    "straight across our way", "across the ego's lane"), or the ego itself ("across us", "across the
    ego"), or what is crossed right in front of it ("across the tracks in front of me")."""
    while j < len(tokens) and tokens[j] in ("straight", "right", "directly", "just"):
        j += 1
    if j >= len(tokens) or tokens[j] != "across":
        return False
    if tokens[j + 1 : j + 2] in (["me"], ["us"], ["ego"], *_TOLD_OF) or tokens[j + 1 : j + 3] == ["the", "ego"]:
        return True
    if tokens[j + 1 : j + 2] == ["the"] and _in_front_of_the_ego(tokens, j + 3):
        return True  # ("across the tracks in front of me": the one thing crossed, where the ego is)
    if tokens[j + 1 : j + 4] == ["the", "front", "of"]:
        return _ego_named(tokens, j + 4)  # ("across the front of my car", "... of her")
    said = " ".join(tokens[j + 1 : j + 5]).replace(" 's", "'s").split()
    for n, owner in enumerate(said[:3]):
        if owner in _EGO_OWNER_WORDS | _TOLD_OF_OWNER and n + 1 < len(said) and said[n + 1] in _ACROSS_WAYS:
            return n == 0 or said[:n] == ["the"]
    return False


#: The ego told of in the third person as what a turn crosses ("turned right across her", "across
#: his path"): an oncoming road user's turn across a person is across that person's way.
_TOLD_OF = (["him"], ["her"], ["them"])
_TOLD_OF_OWNER = frozenset(("his", "her", "their"))


#: Words that end the name of where a turn goes ("into Church St, ...", "into the car park and").
_PAST_PLACE_STOPS = frozenset((".", ",", ";", ":", "!", "?", "and", "then", "but"))


def _past_destination(tokens: list[str], j: int) -> int:
    """Where "across" may stand after the place a turn goes into, said from ``tokens[j]`` ("turned right
    into Church St right across my path": at "right"): past "into"/"onto" and up to four words of
    the place's name; ``j`` itself where no such place is said or nothing of "across" follows it."""
    if tokens[j : j + 1] not in (["into"], ["onto"]):
        return j
    for k in range(j + 2, min(j + 7, len(tokens))):
        if tokens[k] in _PAST_PLACE_STOPS:
            return j
        if tokens[k] in ("across", "straight", "right", "directly", "just"):
            return k
    return j


def _ego_named(tokens: list[str], j: int) -> bool:
    """Whether the ego or its vehicle is named at ``tokens[j]`` ("me", "us", "her", "my car", "his
    bike", "the ego"): what "the front of" is of, in "across the front of my car"."""
    said = tokens[j : j + 2]
    return (
        said[:1] in (["me"], ["us"], ["ego"], *_TOLD_OF)
        or said == ["the", "ego"]
        or (len(said) == 2 and said[0] in _EGO_OWNER_WORDS | _TOLD_OF_OWNER)
    )


def _in_front_of_the_ego(tokens: list[str], j: int) -> bool:
    """Whether "in front of" the ego is said at ``tokens[j]`` ("in front of me", "in front of the ego")."""
    if tokens[j : j + 3] != ["in", "front", "of"]:
        return False
    rest = tokens[j + 3 : j + 5]
    return rest[:1] in (["me"], ["us"], ["ego"]) or rest == ["the", "ego"]


def turning_to_a_side(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with "turn to its left / to the right" read as turning that way, as "turns left" is
    (the side after "to" and a possessive or article is where the turn goes; "to the left lane" is a
    lane, no turn); and a turn said across the ego's path ("turned right across our path", "swung
    left across my way") by a road user said to come the other way read as the turn across the
    ego's path: "across" the ego's path says the turn crosses it, whichever side the writer's traffic
    keeps to (a turn to the far side the reader already reads so, with where it comes from)."""

    def rule(k: int, m, mentions: list):
        verb = m.words.split()[0]
        if m.slot in ("behaviour", "unknown_verb", "ego_verb", "turn") and "turn" in lemmas(verb).get("VERB", ()):
            j = m.start + 1
            side = tokens[j + 2] if j + 2 < len(tokens) else ""
            after = tokens[j + 3] if j + 3 < len(tokens) else ""
            if tokens[j : j + 1] == ["to"] and tokens[j + 1] in _POSSESSIVE | {"the"} and side in ("left", "right"):
                if after not in _NOT_A_TURN:
                    return replace(m, slot="turn", value=side, words=" ".join(tokens[m.start : j + 3]), end=j + 3)
        return None

    clauses = _rewrite(clauses, rule)
    across = turn_across_side(" ".join(tokens))
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            turning = m.slot == "turn" or (m.slot == "behaviour" and m.value[0] == "forced_turn")
            if not turning or (m.value if m.slot == "turn" else m.value[1].get("turn")) == across:
                continue
            if not (_across_the_ego(tokens, m.end) or _across_the_ego(tokens, _past_destination(tokens, m.end))):
                continue  # (the turn to the far side: the reader makes it the turn across, with its arm)
            subject = next((x for x in reversed(kept[:k]) if x.slot in ("actor", "pronoun") and x.value != "ego"), None)
            towards = any(x.slot == "relation" and x.value == "oncoming" for x in kept[:k])
            if subject is not None and towards:
                kept[k] = replace(m, slot="behaviour", value=("turn_across", {}))
        out.append((link, kept))
    return out


#: Words of the carriageway a road user comes out into ("out into the road").
CARRIAGEWAY = frozenset(("road", "street", "carriageway", "roadway", "traffic"))
#: Where a road user comes out from that hides it at the side ("out from between", "out from behind").
_FROM_HIDING = frozenset(("between", "behind"))
#: Adverbs that may stand between the verb and "out" ("came straight out", "rode suddenly out").
_BEFORE_OUT = frozenset(("straight", "suddenly", "right", "just", "quickly", "then"))
#: Road users that cross a road they come out into (a vehicle pulls out into it).
_CROSSERS = frozenset(("pedestrian", "bicycle", "e-scooter"))


def _out_into_the_road(tokens: list[str], j: int) -> int | None:
    """Where "out into the road" / "out across the road" / "out from between ..." / "out from behind ..." /
    "out in front of" the ego said from ``tokens[j]`` ends (past "out" and its preposition), or None."""
    while j < len(tokens) and tokens[j] in _BEFORE_OUT:
        j += 1
    if tokens[j : j + 1] != ["out"]:
        return None
    nxt = tokens[j + 1 : j + 4]
    if (
        nxt[:1] in (["into"], ["onto"], ["across"])
        and len(nxt) > 2
        and nxt[1] in _DETERMINERS
        and nxt[2] in CARRIAGEWAY
    ):
        return j + 2
    if nxt[:1] == ["from"] and len(nxt) > 1 and nxt[1] in _FROM_HIDING:
        return j + 2
    if _before_the_ego(tokens, j + 1):  # ("strolls out in front of me", "stepped out right in front of us")
        return j + 1
    return None


#: Mentions that give the verb after them a subject other than the road user named before.
_NEW_SUBJECT = frozenset(("count", "pronoun", "member", "conj", "link"))


def out_into_the_road(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a plain verb of motion + "out into the road", "out from between / behind"
    (parked vehicles) or "out in front of" the ego read as coming out onto the road in front of the
    ego, whatever the verb ("rode out from between two vans", "came straight out into the street",
    "strolled out in front of me"): a walker or rider crosses it, a vehicle pulls out into it. "Out
    in the road" is where one rides, not a move out, and so is "was riding out in front of me"."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            plain = m.slot == "ego_verb" or (m.slot == "behaviour" and m.value[0] in _PLAIN_MOVES | {"along_road"})
            end = _out_into_the_road(tokens, m.end) if plain else None
            if end is None or (tokens[end : end + 1] == ["in"] and m.words.split()[0].endswith("ing")):
                continue  # ("was riding out in front of me": where it rides, ahead)
            subject = next((x for x in reversed(kept[:k]) if x.slot == "actor"), None)
            if subject is None or subject.value == "ego":
                continue
            own = all(x.slot not in _NEW_SUBJECT for x in kept[kept.index(subject) + 1 : k])
            if tokens[end : end + 1] == ["in"] and not own:
                continue  # ("..., so both come out in front of me": a subject of its own, not the one named)
            name = "cross_in_front" if _crosses_out(subject.value, tokens, end) else "cut_in"
            kept[k] = replace(m, slot="behaviour", value=(name, {}))
        out.append((link, kept))
    return out


def _crosses_out(kind: str, tokens: list[str], end: int) -> bool:
    """Whether a road user of ``kind`` that comes out where ``tokens[end]`` goes on (past "out" and its
    preposition) crosses the road rather than pulling out into it: a walker or rider does, and so does
    one the reader has no kind for yet ("a rider", "someone") that comes out from between or behind
    cover, as :mod:`from_cover` reads it: only someone on foot or on two small wheels is hidden at the
    kerb by what stands there, and a vehicle is named as one."""
    return kind in _CROSSERS or (kind == "unknown" and end < len(tokens) and tokens[end] in _FROM_HIDING)


#: Junctions: going straight across one is going through it, no crossing of the ego's road.
_THROUGH_A_JUNCTION = frozenset(("crossroad", "roundabout"))


def straight_across(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a walker's or rider's plain going said with "straight" and then "across" ("went
    straight across the road in front of me", "came straight across the front of my car") read as the
    crossing that "went across" is: the lexicon's "go straight" (how the ego says its route) takes the
    adverb before the particle can, and "straight" only says how directly it crosses. Not read so: a
    vehicle (one that goes straight across keeps its road, or runs through a junction: other rules),
    the ego, and going straight across a junction or roundabout (through it)."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            if m.slot != "behaviour" or m.value[0] not in _PLAIN_MOVES or m.words.split()[-1] != "straight":
                continue
            if tokens[m.end : m.end + 1] != ["across"]:
                continue
            subject = next((x for x in reversed(kept[:k]) if x.slot == "actor"), None)
            if subject is None or subject.value not in _CROSSERS | {"unknown"}:
                continue
            crossed = next((x for x in kept[k + 1 :] if x.start > m.end), None)
            if crossed is not None and crossed.slot == "map" and crossed.value in _THROUGH_A_JUNCTION:
                if crossed.start <= m.end + 3:
                    continue  # ("went straight across the junction": through it)
            kept[k] = replace(m, value=("cross_in_front", {}))
        out.append((link, kept))
    return out


#: Words that join a verbless second half to the first ("ran along the pavement and out into the road").
_JOINS = frozenset(("and", "then", ","))


def _verbless_out(tokens: list[str], j: int) -> bool:
    """Whether "out" at token ``j`` opens a second half with no verb of its own: only a join ("and",
    "then", a comma) and adverbs ("straight", "suddenly") stand before it."""
    i = j - 1
    while i >= 0 and tokens[i] in _BEFORE_OUT and tokens[i] not in _JOINS:
        i -= 1
    return i >= 0 and tokens[i] in _JOINS


def out_across_the_road(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a verbless "and (straight) out into / across the road" after a road user's move
    ("came racing along the pavement and straight out across the road", "hurried down the footpath,
    then out into the street") read as that road user coming out onto the road: the second half
    shares the first half's subject and verb, and where it goes is out of its place beside the road
    into the carriageway. A walker or rider crosses it, a vehicle pulls out into it. The adverb read
    as the ego's route ("straight") is the manner of this move, not the ego's."""
    out: list = []
    subject = None  # the last road user named, through the clauses ("..., then straight out ...")
    for link, mentions in clauses:
        kept = list(mentions)
        for j in range(min((x.start for x in mentions), default=0), max((x.end for x in mentions), default=0)):
            if tokens[j] != "out" or not _verbless_out(tokens, j) or _out_into_the_road(tokens, j) is None:
                continue
            if any(x.slot == "behaviour" and x.start <= j < x.end for x in kept):
                continue  # (read as a move already)
            before = [x for x in mentions if x.start < j and x.slot in ("actor", "pronoun")]
            who = before[-1] if before else subject
            if who is None or who.slot != "actor" or who.value == "ego":
                continue
            name = "cross_in_front" if who.value in _CROSSERS else "cut_in"
            kept = [x for x in kept if not (x.slot == "ego_verb" and j - 3 <= x.start < j)]
            move = word_mention(who, tokens, j, "behaviour", (name, {}), "out")
            kept.insert(next((n for n, x in enumerate(kept) if x.start > j), len(kept)), move)
        named = [x for x in mentions if x.slot == "actor" and x.value != "ego"]
        subject = named[-1] if named else subject
        out.append((link, kept))
    return out


#: Verbs (lemmas) that send a thing off while the one who does it stays ("kicked a ball out into the road").
_SENDS_OFF = frozenset(("kick", "throw", "toss", "fling", "chuck", "hit", "knock", "drop", "roll", "blow", "lose"))
#: Moves a verb with a thing after it may have been read as before it is seen going out with it.
_WITH_A_THING = frozenset(("keep_going", "along_road", "follow_vehicle"))


def _a_thing_before(tokens: list[str], j: int) -> int | None:
    """Where the verb stands whose object, a thing said with at most an article or possessive and an
    adjective, ends just before ``tokens[j]`` ("chased [a ball]", "ran after [his ball]"), or None."""
    i = j - 1
    if i < 1 or "NOUN" not in lemmas(tokens[i]):
        return None
    i -= 1
    if i > 0 and "ADJ" in lemmas(tokens[i]) and tokens[i] not in _DETERMINERS:
        i -= 1  # ("chased a red ball out")
    if tokens[i] not in _DETERMINERS:
        return None
    i -= 1
    if i > 0 and tokens[i] == "after":
        i -= 1  # ("ran after her ball into the road")
    return i if i >= 0 and "VERB" in lemmas(tokens[i]) else None


def _into_the_road_from(tokens: list[str], j: int) -> int | None:
    """Where "(out) into / onto / across the road" or one of :func:`_out_into_the_road`'s ways out
    said from ``tokens[j]`` ends, or None: after a thing gone after, "out" may be left unsaid."""
    if tokens[j : j + 1] in (["into"], ["onto"], ["across"]) and j + 2 < len(tokens):
        if tokens[j + 1] in _DETERMINERS and tokens[j + 2] in CARRIAGEWAY:
            return j + 1
    return _out_into_the_road(tokens, j)


def with_a_thing_out_into_the_road(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user going out into the road with or after a thing ("a child chased a
    ball out from between two parked vans", "a woman pushed a pram out in front of me", "a boy ran
    after his ball into the road") read as that road user coming out onto the road: the verb with
    its object says what it goes with, "out into the road" where it goes. A walker or rider crosses
    it, a vehicle pulls out into it. A verb that sends the thing off ("kicked a ball out into the
    road") moves the thing, not the one who does it; a road user as the object ("followed a van
    out") is no thing, and a verb after "I" is the ego's."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for j in range(min((x.start for x in mentions), default=0), max((x.end for x in mentions), default=0)):
            i = j
            while i < len(tokens) and tokens[i] in _BEFORE_OUT:
                i += 1
            verb = _a_thing_before(tokens, i) if _into_the_road_from(tokens, i) is not None else None
            if verb is None or set(lemmas(tokens[verb]).get("VERB", ())) & _SENDS_OFF:
                continue
            if any(x.start < i and x.end > verb + 1 and x.slot not in ("pronoun", "conj") for x in kept):
                continue  # (a mention in the object: a road user, a place, not a thing)
            at = next((n for n, x in enumerate(kept) if x.start <= verb < x.end), None)
            if at is not None and not (kept[at].slot == "behaviour" and kept[at].value[0] in _WITH_A_THING):
                continue
            before = [x for x in kept if x.end <= verb]
            who = before[-1] if before else None
            if who is None or who.slot != "actor" or who.value == "ego":
                continue  # (the word before the verb is its subject: none said, or the ego's verb)
            name = "cross_in_front" if who.value in _CROSSERS else "cut_in"
            move = word_mention(who, tokens, verb, "behaviour", (name, {}), tokens[verb])
            if at is not None:
                kept[at] = move
            else:
                kept.insert(kept.index(who) + 1, move)
        out.append((link, kept))
    return out


#: Prepositions that put a road user in the crossing itself, out on the road ("halfway over the zebra"; not
#: "at" or "by" it).
_IN_IT = frozenset(("in", "on", "onto", "into", "across", "over"))
#: Prepositions of going that end on or past the crossing ("walked onto the zebra", "ran over the
#: crosswalk"): with a plain move before them, the move is the going across ("on" says only where it is).
_ONTO_IT = frozenset(("onto", "into", "across", "over"))
#: Plain moves that a going onto a foot crossing makes a crossing: going on, with nothing said of how.
_GOING_ONTO = frozenset(("keep_going", "along_road"))


def _preposition_before(tokens: list[str], start: int) -> str:
    """The word before the noun phrase starting at ``start``, past its article ("on [the] zebra")."""
    i = start - 1
    while i >= 0 and tokens[i] in _DETERMINERS:
        i -= 1
    return tokens[i] if i >= 0 else ""


def on_a_foot_crossing(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a walker or rider said to be in or on a foot crossing ("hit a pedestrian in the
    crosswalk", "a man on the zebra crossing", "a kid on a bike on the pelican") and no move of its own
    read as crossing the road on it: out on a crossing made for going across, that is what it does.
    A plain move whose way ends on or over the crossing ("walked onto the crosswalk", "ran over the
    zebra") is that crossing: the place it goes to is made for going across. Waiting at the crossing,
    or a move said of it ("walked along the crossing"), keeps what is said."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if m.slot != "kerb" or not set(m.words.split()) & FOOT_CROSSINGS:
                continue
            before = _preposition_before(tokens, m.start)
            entering = bool(set(lemmas(before).get("VERB", ())) & _ENTER)
            if before not in _IN_IT and not entering:
                continue  # (in it, or "entered the crosswalk": going into a crossing is going across on it)
            at = next((n for n in range(k - 1, -1, -1) if mentions[n].slot in ("actor", "pronoun")), None)
            if at is None or mentions[at].slot != "actor" or mentions[at].value not in _CROSSERS:
                continue
            end = next((n for n in range(k + 1, len(mentions)) if mentions[n].slot in ("actor", "pronoun")), None)
            own = [x for x in mentions[at + 1 : end] if not (entering and x.words == before)]  # (not "enters")
            said = [x for x in own if x.slot in ("behaviour", "stationary", "unknown_verb", "ego_verb", "turn")]
            manner = [x for x in said if x.slot == "ego_verb" and x.value == "straight"]  # ("walked straight onto")
            going = _going_onto([x for x in said if x not in manner], m, before)
            if said and going is None:
                continue  # (it does something said: that stands)
            # said as its participle right after it ("a man crossing on the zebra"), so the crossing is
            # the walker's even where the walker is the object of the narrator's verb ("I hit a man ...")
            crossing = replace(m, slot="behaviour", value=("cross_in_front", {}), words="crossing", det="", owners=())
            if going is not None:
                kept[kept.index(going)] = replace(going, value=("cross_in_front", {}))
                kept = [x for x in kept if x not in manner]
            else:
                kept.insert(kept.index(mentions[at]) + 1, crossing)
        out.append((link, kept))
    return out


def _going_onto(said: list, place, before: str):
    """The one plain move among the road user's ``said`` acts that goes onto or over the foot crossing
    ``place`` (``before``: the preposition before it), or None: "walked onto the zebra" goes across by
    going there, but "waited on the crosswalk" or "stopped and then walked onto it" say more than that."""
    if before not in _ONTO_IT or len(said) != 1:
        return None
    move = said[0]
    plain = move.slot == "behaviour" and move.value[0] in _GOING_ONTO and move.end <= place.start
    return move if plain else None


#: Moves out of a place beside the road that a crossing said next goes on with: the way out of it.
_WAYS_OUT = frozenset(("cut_in", "keep_going", "along_road"))


def out_of_a_place_then_across(clauses: list) -> list:
    """``clauses`` with a walker's or rider's move out of a place beside the road (a driveway, a gate,
    a bus stop, the pavement: :func:`_out_of_a_place`) followed in the same clause by its crossing
    ("came out of a driveway on the right and crossed", "stepped out from the bus stop and walked
    across") read as the crossing alone, from that side: coming out of there is how the crossing
    starts, not a cut-in into the ego's lane first. A vehicle coming out of a driveway joins the
    traffic, so its move is kept; so is a move out with no crossing after it."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions[:-1]):
            if m.slot != "behaviour" or m.value[0] not in _WAYS_OUT or not _out_of_a_place(mentions[k + 1]):
                continue
            subject = next((x for x in reversed(mentions[:k]) if x.slot in ("actor", "pronoun")), None)
            if subject is None or subject.slot != "actor" or subject.value not in _CROSSERS:
                continue
            for x in mentions[k + 1 :]:
                if x.slot in ("actor", "pronoun") and x.value != "ego":
                    break  # (someone else's move follows)
                if x.slot == "behaviour":
                    if x.value[0] == "cross_in_front":
                        kept.remove(m)
                    break
        out.append((link, kept))
    return out


#: Words of the one telling the story.
_FIRST_PERSON = frozenset(("i", "we", "me", "my", "us", "our", "i'm", "i've", "i'd", "we're"))


def told_in_the_first_person(text: str, tokens: list[str]) -> bool:
    """Whether ``text`` is the narrator's own story: it says "I", "we", "my" ... as written (the
    reader's ``tokens`` have "my car" already read as the ego), or opens as a diary without its "I"
    (:func:`diary`). A verb with no subject in such a story is the narrator's ("Braked hard.")."""
    said = set(re.findall(r"[a-z']+", text.lower()))
    return bool(_FIRST_PERSON & (said | set(tokens))) or diary(tokens)


#: Adverbs that may stand between a verb and "in front of" ("passed right in front of us").
_CLOSE = frozenset(("right", "just", "directly", "straight", "immediately"))
#: Words of how near a road user passes, between the verb and where it passes ("passed approx 2 m in
#: front of us", "passes inches from her bumper", "passed a couple of feet in front of my bonnet"):
#: hedges, counts and units of length. How near it came is no object of the verb.
_HOW_NEAR = frozenset(
    ("approx", "approx.", "approximately", "about", "around", "roughly", "maybe", "only", "barely", "less", "than",
     "a", "an", "couple", "few", "of", "one", "two", "three", "inch", "inches", "cm", "foot", "feet", "ft", "m",
     "metre", "metres", "meter", "meters", "yard", "yards", "~")
)  # fmt: skip
#: Sides said after a close pass ("on the outside"): it went along the ego's side, an overtake.
_ALONG_A_SIDE = frozenset(("outside", "inside", "offside", "nearside"))
#: The front parts of a vehicle: passing close by one ("inches from her bumper") is passing across its front.
_FRONT_PARTS = frozenset(("front", "bumper", "bonnet", "hood", "nose", "grille"))


def passing_in_front(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a verb of passing that has no object and goes on "in front of" the ego ("a
    cyclist passed in front of us", "passes right in front of my bonnet"), across its front ("passed
    across the front of my car") or close by its front ("passes inches from her bumper") read as
    crossing the ego's path: an overtake takes the one it passes as its object ("passed us"); passing
    in front of it, a road user goes across where the ego is heading. How near it came may stand
    between ("passed approx 2 m in front of us"). A verb + "past" has the ego's front as the
    particle's object ("went right past our bonnet"): it went by across the front, not along a side
    (a vehicle with no junction said: a cut across, see :func:`_past_the_front`). The ego may go
    unsaid where the story is its own: "passed across in front of" it, a walker's or rider's "passed
    in front" with no "of" ("... with a metre to spare") and "past the front" with no owner are
    across its front too (not one said to come from behind, which overtakes)."""
    out = []
    said = [x for _, xs in clauses for x in xs]
    from_behind = _said_from_behind(clauses, tokens)
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            who = _who_passes(kept[:k], said)
            front = _close_by_the_egos_front(tokens, m.end - 1) or _past_the_front_unsaid(who, tokens, m.end - 1)
            if passes(m) and m.words.split()[-1] == "past" and front:
                kept[k] = replace(m, value=(_past_the_front(kept[:k], clauses), {}))  # ("went right past our bonnet")
                continue
            if not passes(m) or len(m.words.split()) != 1:
                continue
            j = m.end
            while j < len(tokens) and (tokens[j] in _CLOSE | _HOW_NEAR or tokens[j].replace(".", "").isdigit()):
                j += 1
            overtakes_too = any(
                passes(x) and x is not m and abs(x.start - m.start) < 12 and not _someone_between(said, x, m)
                for x in said
            )
            if _across_the_ego(tokens, j) or (not overtakes_too and _close_by_the_egos_front(tokens, j)):
                kept[k] = replace(m, value=("cross_in_front", {}))
                continue
            if tokens[j : j + 1] == ["across"] and _in_front_of_the_ego(tokens, j + 1):
                kept[k] = replace(m, value=("cross_in_front", {}))  # ("passed across in front of the car")
                continue
            unsaid = _front_unsaid(who, tokens, j + 2) and not _the_one_from_behind(who, from_behind)
            if tokens[j : j + 2] == ["in", "front"] and not overtakes_too and unsaid:
                kept[k] = replace(m, value=("cross_in_front", {}))  # ("passed in front with a metre to spare")
                continue
            if tokens[j : j + 3] != ["in", "front", "of"]:
                continue
            rest = tokens[j + 3 : j + 7]
            named = bool(rest[:1]) and rest[0] in _EGO_WORDS | {"my", "our"} or rest[:2] == ["the", "ego"]
            ego = next((x for x in kept[k + 1 :] if x.slot in ("actor", "pronoun")), None)
            if named or (ego is not None and ego.value == "ego" and ego.start <= j + 5):
                kept[k] = replace(m, value=("cross_in_front", {}))
        out.append((link, kept))
    return out


#: Words after "in front" that end where the pass goes: the front is then the ego's, left unsaid
#: ("passed in front with a metre to spare", "passed right in front, missing my bumper").
_FRONT_ENDS = frozenset((",", ".", ";", "!", "?", "with", "and", "by", "then", "at", "missing", "-"))
#: Pronouns a walker or rider is told on with in the next sentence ("He passed in front ...").
_HE_OR_SHE = SUBJECT_PRONOUNS - FIRST_PERSON - {"you"}  # (he, she, they: the third persons)
#: Words before a road user's noun that make it a new one, not the one named before ("another cyclist",
#: "a different cyclist").
_ANOTHER = frozenset(("a", "an", "another", "different", "other", "second", "some"))
#: Words that open someone's or something's own back after "behind" ("from behind a parked lorry").
_OWNER_OPENS = frozenset(("a", "an", "the", "this", "that", "his", "her", "their", "its", "some", "another"))


def _who_passes(before: list, said: list):
    """The road user a verb after ``before`` (its clause's mentions before it) is said of, as
    :func:`subject_before`, with a walker's or rider's pronoun ("he", "she", "they") read as the last
    road user named before it in the text (``said``: all its mentions): a narrator's next sentence
    goes on with "he passed in front ...". A road user right after a relation is its object, not the
    subject ("a cyclist came out from behind a parked lorry and passed ...": the cyclist passed)."""
    subject = subject_before(before)
    if subject is not None and subject.slot == "actor":
        k = before.index(subject) - 1
        while k >= 0 and before[k].slot == "stationary":
            k -= 1
        if k >= 0 and before[k].slot == "relation" and subject.start - before[k].end <= 3:
            return _who_passes(before[:k], said)
    if subject is None or subject.slot != "pronoun":
        return subject
    if subject.words not in _HE_OR_SHE:
        return None
    earlier = (x for x in reversed(said) if x.start < subject.start and x.slot == "actor" and x.value != "ego")
    return next(earlier, None)


def _walker_or_rider(who) -> bool:
    """Whether the road user ``who`` (a mention, or None for the ego itself) is a walker or rider, one
    that crosses the ego's path where it passes across its front (both pass rules ask this)."""
    return who is not None and who.slot == "actor" and who.value in _CROSSERS


def _someone_between(said: list, x, m) -> bool:
    """Whether another road user (not the ego) is named between the passes ``x`` and ``m``: then the
    two are not said of the same one ("a jogger passed in front of us, then a cyclist passed ...")."""
    low, high = sorted((x.start, m.start))
    return any(low < y.start < high and y.slot == "actor" and y.value != "ego" for y in said)


def _ends_ahead_in_the_egos_lane(tokens: list[str], j: int) -> bool:
    """Whether the sentence going on at ``tokens[j]`` (after "in front") ends the road user ahead of the
    ego or in its lane ("... and rode off ahead of me in my lane", "then stayed in my lane"): a pass
    and pull-in, not a crossing."""
    rest = []
    for t in tokens[j:]:
        if t in SENTENCE_END:
            break
        rest.append(t)
    ahead = any(
        rest[i : i + 2] == ["ahead", "of"] and rest[i + 2 : i + 3] in [[w] for w in _EGO_WORDS]
        for i in range(len(rest))
    )
    lane = any(rest[i] in ("my", "our") and rest[i + 1 : i + 2] == ["lane"] for i in range(len(rest)))
    return ahead or lane


def _front_unsaid(who, tokens: list[str], j: int) -> bool:
    """Whether "in front" ends at ``tokens[j]`` with no "of" (the ego's front, told by the one whose
    story it is), said of a walker or rider ``who`` (:func:`_walker_or_rider`). A vehicle that passes
    in front with no one named may be pulling in ahead of the ego; a walker or rider is going across
    its front, unless what follows ends it ahead in the ego's lane (:func:`_ends_ahead_in_the_egos_lane`)."""
    ends = j >= len(tokens) or tokens[j] in _FRONT_ENDS
    return _walker_or_rider(who) and ends and not _ends_ahead_in_the_egos_lane(tokens, j)


def _past_the_front_unsaid(who, tokens: list[str], j: int) -> bool:
    """Whether "past the front" is said at ``tokens[j]`` with no owner ("went past the front a metre
    off the bumper") of a walker or rider ``who`` (:func:`_walker_or_rider`): the front of the one
    whose story it is, the ego's. An owner may follow a coordination ("past the front and then the
    back of the parked bus"): that front is the owner's."""
    if not _walker_or_rider(who) or tokens[j : j + 3] != ["past", "the", "front"]:
        return False
    rest = []
    for t in tokens[j + 3 : j + 10]:
        if t in SENTENCE_END or t == ",":
            break
        rest.append(t)
    owned_after = rest[:1] in (["and"], ["or"]) and "of" in rest
    return rest[:1] != ["of"] and not owned_after


def _said_from_behind(clauses: list, tokens: list[str]) -> list:
    """The road users (their mentions) said to come "from behind" the ego: a ``behind`` relation said of
    it (the last road user named before it), with no one else's back after it ("came out from behind a
    parked lorry" is behind the lorry). One that then passes in front, the ego unsaid, overtakes it."""
    found = []
    for _, mentions in clauses:
        for k, m in enumerate(mentions):
            if m.slot != "relation" or m.value != "behind":
                continue
            subject = subject_before(mentions[:k])
            if subject is None or subject.slot != "actor":
                continue
            said = tokens[m.end : m.end + 2]
            egos = [x for x in mentions[k + 1 :] if x.slot == "actor" and x.value == "ego" and x.start <= m.end + 1]
            if said[:1] and said[0] in _OWNER_OPENS and said != ["the", "ego"] and not egos:
                continue
            found.append(subject)
    return found


def _the_one_from_behind(who, from_behind: list) -> bool:
    """Whether ``who`` is a road user said to come from behind the ego (``from_behind``): the same
    mention, or a later one of its kind that is not said to be a new one ("the cyclist", not "another
    cyclist")."""
    if who is None:
        return False
    return any(
        s is who
        or (s.value == who.value and s.start < who.start and who.prev not in _ANOTHER and who.det not in _ANOTHER)
        for s in from_behind
    )


def _past_the_front(before: list, clauses: list) -> str:
    """What a road user that went past the ego's front (its clause's mentions ``before`` the verb) did:
    crossed the ego's path; a vehicle, where no junction is said in ``clauses``, has no arm to cross
    from and cut across in front of the ego, as one that "cut across our bonnet" does."""
    subject = subject_before(before)
    junction = any(x.slot == "map" and x.value in _THROUGH_A_JUNCTION for _, xs in clauses for x in xs)
    return "cut_in" if subject is not None and subject.value in VEHICLES and not junction else "cross_in_front"


def _close_by_the_egos_front(tokens: list[str], j: int) -> bool:
    """Whether "from" or "past" the front of the ego's vehicle is said at ``tokens[j]`` ("from my
    bumper", "past her bonnet", "from our front"): where a road user passing close by goes. Not a part
    of the front's ("my front wheel", by the side), nor one said along a side ("from my bumper on the
    outside"), nor beside an overtake said with it (the caller): those pass along the ego's side."""
    said = tokens[j : j + 3]
    if len(said) < 3 or said[0] not in ("from", "past") or not _ego_named(tokens, j + 1) or said[2] not in _FRONT_PARTS:
        return False
    return (
        tokens[j + 3 : j + 4] == []
        or tokens[j + 3] not in VEHICLE_PARTS
        and not set(tokens[j + 3 : j + 7]) & _ALONG_A_SIDE
    )


#: What each kind of road user most often does where it meets the ego (the commonest behaviour of the
#: kind in descriptions people write): a walker or an e-scooter crosses the ego's road, a cyclist rides
#: along it; any other road user carries on at its speed.
_COMMONEST = {"pedestrian": "cross_in_front", "e-scooter": "cross_in_front", "bicycle": "along_road"}


def default_behaviour(kind: str) -> str:
    """The behaviour a road user gets when the text says it moved or touched the ego in words no
    behaviour is read from ("a van nicked my mirror", "a cyclist was clipped by the test car"): a
    plausible scenario of that road user, with the words listed as not used, is more use than a
    refusal; the commonest behaviour of its kind is the least surprising guess."""
    return _COMMONEST.get(kind, "keep_going")


#: Verbs (lemmas) of entering: with a place as their object they go into it ("invaded my lane",
#: "entered the ego's lane", "encroached on our side").
_ENTER = frozenset(("enter", "invade", "encroach", "intrude", "penetrate"))
#: The ego's ways a road user may be said to enter: its lane, its path, its side or half of the road.
_EGO_WAYS_ENTERED = frozenset(("lane", "path", "side", "half"))
#: Possessive pronouns that stand for the ego's lane once a lane was said ("from the right lane into mine").
_EGO_LANE_PRONOUNS = frozenset(("mine", "ours"))
#: Adverbs and particles between a verb and where it goes ("came suddenly across into", "swung back over onto").
_ON_THE_WAY_IN = frozenset(("suddenly", "quickly", "slowly", "straight", "right", "just", "directly", "fully",
                            "partly", "partially", "across", "over", "back", "out", "then", "abruptly",
                            "sharply"))  # fmt: skip
#: Particles of a move sideways, across what lies between ("came over into us", "swung across into me"):
#: "into" the ego after one is a move into the ego's place on the road, not a run into its back.
_SIDEWAYS = frozenset(("over", "across"))
#: Moves a verb may already be read as that say only that it goes, or goes sideways: where to says which.
_SAYS_ONLY_THAT_IT_GOES = frozenset(("keep_going", "change_lane", "along_road", "cut_out"))


def _the_ego_way_at(tokens: list[str], j: int) -> bool:
    """Whether the ego's lane, path or side is named from ``tokens[j]`` ("my lane", "the ego's lane",
    "our side of the road", "the ego lane")."""
    for owner in _EGO_OWNERS + (("ego",),):
        n = len(owner)
        if tuple(tokens[j : j + n]) == owner and j + n < len(tokens) and tokens[j + n] in _EGO_WAYS_ENTERED:
            return True
    return False


def _lane_said_before(tokens: list[str], start: int, j: int) -> bool:
    """Whether a lane is named between ``tokens[start]`` and ``tokens[j]`` (what "mine" can stand for)."""
    return any(t in ("lane", "lanes") for t in tokens[start:j])


def _enters_the_ego_way(tokens: list[str], j: int, subject_start: int) -> int | None:
    """Where the words end that say the verb at ``tokens[j]`` goes into the ego's lane, path or side,
    or None: any verb + "into"/"onto" + the ego's way (or "mine"/"ours" for a lane said since the road
    user was named, or the ego itself after a particle of moving sideways from a lane said since:
    "a tanker in the nearside lane came over into us"); a verb
    of entering with the ego's way as its object, after "on", or "in front of" the ego."""
    said = lemmas(tokens[j])
    verbs = set(said.get("VERB", ()))
    if not verbs or verbs & {"be", "have", "do"} or tokens[j] in _ON_THE_WAY_IN:
        return None
    if tokens[j] in verbs and set(said) - {"VERB"}:
        return None  # (a bare form that is another word too: "right into my path" is where, no verb)
    k = past_its_own_object(tokens, j + 1)  # ("wedged itself into my lane", "forced its way into ours")
    while k < len(tokens) and tokens[k] in _ON_THE_WAY_IN:
        k += 1
    if tokens[k : k + 1] == ["from"]:  # ("swung from the right lane into mine": where it leaves)
        to = next((i for i in range(k + 1, min(k + 6, len(tokens))) if tokens[i] in ("into", "onto")), None)
        if to is None or set(tokens[k + 1 : to]) & _STOPS:
            return None
        k = to
    if k >= len(tokens):
        return None
    entering = bool(verbs & _ENTER)
    lead = tokens[k]
    if lead in ("into", "onto") or (entering and lead in ("on", "upon")):
        if _the_ego_way_at(tokens, k + 1):
            return k + 3
        sideways = tokens[k - 1] in _SIDEWAYS and tokens[k + 1 : k + 2] and tokens[k + 1] in _EGO_WORDS
        if sideways and _lane_said_before(tokens, subject_start, j):
            return k + 2  # ("a tanker from the nearside lane came over into us": from beside, where the ego is)
        mine = tokens[k + 1 : k + 2] and tokens[k + 1] in _EGO_LANE_PRONOUNS
        if mine and _lane_said_before(tokens, subject_start, j):
            return k + 2
        return None
    if entering and _the_ego_way_at(tokens, k):
        return k + 2
    if entering and tokens[k : k + 3] == ["in", "front", "of"]:
        rest = tokens[k + 3 : k + 5]
        if rest[:1] and (rest[0] in _EGO_WORDS or rest == ["the", "ego"]):
            return k + 3 + (2 if rest == ["the", "ego"] else 1)
    return None


#: Prepositions after which the ego is an object of place ("a car behind me", "the van in front of us").
_OBJECT_OF = frozenset(("of", "behind", "to", "past", "at", "with", "from", "than", "beside", "near", "ahead", "by"))


def subject_before(before: list):
    """The road user a verb after ``before`` (the clause's mentions before it) is said of: the last
    one named, past the ego named as the object of a preposition ("a car in front of me"); None
    where that is the ego itself."""
    for x in reversed(before):
        if x.slot not in ("actor", "pronoun"):
            continue
        if x.value == "ego" and x.prev in _OBJECT_OF:
            continue
        return None if x.value == "ego" else x
    return None


#: Slots of a mention that may be a road user's verb.
_VERB_SLOTS = ("behaviour", "unknown_verb")


def entering_the_ego_lane(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user's verb whose destination is the ego's lane, path or side read as
    a cut-in, whatever the verb ("invaded my lane", "swung from its lane into mine", "entered suddenly
    in front of the ego", "strayed onto our side of the road"), where the reader read it as no more
    than going on (or not at all). The destination says the class of the move; where the road user
    comes from then says which: from beside or behind it cuts in, from the other way it comes head-on
    (the reader's :func:`comes_head_on`). Only the road user the clause is about, named before the
    verb and not the ego, is read so; a verb said of the ego ("I moved into my lane") is its own. A
    verb of going on foot into the ego's path ("stepped out into my lane") is a crossing of it."""
    out = []
    for link, mentions in clauses:
        if not mentions:
            out.append((link, mentions))
            continue
        kept = list(mentions)
        first, last = mentions[0].start, max(x.end for x in mentions)
        for j in range(first, min(last, len(tokens))):
            at = next((x for x in kept if x.start <= j < max(x.end, x.start + 1)), None)
            if at is not None and at.slot not in ("unknown_verb", "ego_verb", "behaviour"):
                continue
            if at is not None and at.slot == "behaviour" and at.value[0] not in _SAYS_ONLY_THAT_IT_GOES:
                continue  # (a move of its own: "cut into my lane" is read already)
            if at is not None and at.slot == "behaviour" and at.words.split()[-1] in ("into", "onto"):
                continue  # ("swerves into my lane": a lane change the reader places with where it starts)
            if negated(tokens, j if at is None else at.start):
                continue  # ("the rider does not enter the vehicle's lane": it stays where it is)
            before = [x for x in kept if x.start < j]
            subject = subject_before(before)
            if subject is None:
                continue
            end = _enters_the_ego_way(tokens, j, subject.start)
            if end is None:
                continue
            cut = ("cut_in", {})
            verb = at or next((x for x in reversed(before) if x.start > subject.start and x.slot in _VERB_SLOTS), None)
            if verb is not None and _on_foot(verb):  # ("stepped out into my lane": on foot, it crosses)
                if verb.slot == "behaviour" and verb.value[0] == "cross_in_front":
                    break
                cut = ("cross_in_front", {})
            used = [  # ("mine"; "itself", "its way": the subject, not another road user)
                x for x in kept if j < x.start < end and (x.slot == "unknown_verb" or x.words in REFLEXIVES)
            ]
            if at is not None:
                kept[kept.index(at)] = replace(at, slot="behaviour", value=cut)
            else:
                said = word_mention(subject, tokens, j, "behaviour", cut)
                kept.insert(kept.index(before[-1]) + 1, said)
            kept = [x for x in kept if all(x is not u for u in used)]
            break
        out.append((link, kept))
    return out


def _on_it(m) -> bool:
    """Whether side mention ``m`` is said with "on" ("riding down the lane on the wrong side"): where a
    road user travels, not a kerb it comes from ("from the wrong side")."""
    return m.prev == "on" or m.words.startswith("on ")


def the_wrong_side_of(clauses: list) -> list:
    """``clauses`` with "the wrong side of" + any road ("the wrong side of the street", "of Abbey St",
    "of the dual carriageway") read as going the wrong way, as "the wrong side of the road" is: the
    wrong side of a road is the side of its traffic the other way, whatever the road is called. The
    reader otherwise takes "wrong side" alone as the far kerb; "of" is what makes it a side of a
    road one travels on, and so is "on" ("riding down Mill Lane on the wrong side")."""
    out = []
    for link, mentions in clauses:
        kept = [
            replace(m, slot="wrong_way", value=None)
            if m.slot == "kerb_side" and m.words == "wrong side" and (m.next_ == "of" or _on_it(m))
            else m
            for m in mentions
        ]
        out.append((link, kept))
    return out


def right_at_the_ego(clauses: list, tokens: list[str]) -> list:
    """``clauses`` without "right" read as a side where it only says how exactly a road user heads at
    the ego ("pelted right at me", "came right at us"): "right" + "at" + the ego is a degree adverb,
    as "straight at me" is; "turned right at the junction" (not the ego after "at") keeps its side."""
    out = []
    for link, mentions in clauses:
        kept = []
        for m in mentions:
            j = m.end
            at_ego = (
                tokens[j : j + 1] == ["at"]
                and j + 1 < len(tokens)
                and (tokens[j + 1] in _EGO_WORDS or tokens[j + 1 : j + 3] == ["the", "ego"])
            )
            if m.slot == "side" and m.words == "right" and at_ego:
                continue
            kept.append(m)
        out.append((link, kept))
    return out


#: The rear of the ego a road user behind it is said to sit on ("my back bumper", "our tail").
_REAR = frozenset(
    ("bumper", "tail", "backside", "rear", "boot", "trunk", "tailgate", "tailboard", "exhaust", "arse", "ass", "butt")
)
#: Words that say a part is the rear one ("back bumper", "rear bumper").
_BACK = frozenset(("back", "rear"))
#: Parts that are the rear only when said so (a bumper is also at the front).
_EITHER_END = frozenset(("bumper",))
#: The rear parts that are a space a road user can be said to be in ("practically in my boot"): so
#: close behind that, in the figure, it is inside the ego's car.
_HOLLOW_REAR = frozenset(("boot", "trunk"))
#: Prepositions of place a road user keeps itself at the ego's rear by ("on my tail", "off my bumper",
#: "up my backside"); "up" may lead another ("up on my bumper", "up against our tailgate"), and says
#: the rear by itself: what comes up on a bumper comes up from behind.
_AT_THE_REAR = ("off", "on", "up")
_AFTER_UP = frozenset(("on", "against", "behind"))
#: Verbs whose "up" is their own particle, of where a thing ends ("ended up on my bumper", "wound up
#: on our boot"): where it came to rest, not a place it keeps behind the ego.
_UP_OF_RESULT = frozenset(("end", "wind", "finish", "land"))


def _the_ego_rear_at(tokens: list[str], j: int) -> int | None:
    """Where "off / on / up (on)" + the ego's rear, or "in" + its boot after a word of degree
    ("practically in my boot"), ends when said from ``tokens[j]`` ("off my back bumper", "on our
    tail", "right up on my bumper"), or None. Being in the boot is a figure of closeness only with
    its degree said: a thing only carried there ("my bike in my boot", "my son's scooter was in my
    boot") is no road user. An "up" that is the particle of a verb of where a thing ends ("ended up
    on my bumper") is no place kept."""
    if tokens[j] not in (*_AT_THE_REAR, "in"):
        return None
    if tokens[j] == "in" and not (j and _a_degree(tokens, j - 1)):
        return None
    if tokens[j] == "up" and j and set(lemmas(tokens[j - 1]).get("VERB", ())) & _UP_OF_RESULT:
        return None
    k = j + 1
    if tokens[j] == "up" and k < len(tokens) and tokens[k] in _AFTER_UP:
        k += 1  # ("right up on my bumper")
    for owner in _EGO_OWNERS:
        if tuple(tokens[k : k + len(owner)]) == owner:
            k += len(owner)
            break
    else:
        return None
    back = k < len(tokens) and tokens[k] in _BACK
    k += back
    if k >= len(tokens) or tokens[k] not in _REAR:
        return None
    if tokens[k] in _EITHER_END and not back and tokens[j] != "up":
        return None  # ("came through from the right, inches off my bumper": at its front as well)
    if tokens[j] == "in" and tokens[k] not in _HOLLOW_REAR:
        return None  # ("a dent in my rear bumper": the place of a mark, no one keeping there)
    return k + 1


#: Words that measure a stretch of road or time kept ("for two miles", "for some distance", "for a while").
_STRETCH = frozenset(("mile", "miles", "km", "kilometre", "kilometres", "kilometer", "kilometers", "minute",
                      "minutes", "while", "ages", "distance", "way", "stretch", "journey", "trip", "time"))  # fmt: skip
#: How many words may stand between "for" and the word of its stretch ("for the best part of two miles").
_STRETCH_WORDS = 6
#: How a stretch said without "for" opens: a noun phrase of the whole of it ("the whole way", "all the
#: way", "the entire journey"), which English uses bare as an adverb of extent.
_WHOLE_OF = (("the", "whole"), ("the", "entire"), ("all", "the"), ("the", "full"))


def _a_degree(tokens: list[str], i: int) -> bool:
    """Whether ``tokens[i]`` is a word of degree of a figure ("practically", "virtually", "all but")."""
    from vei_scenario.language.outcome import HEDGES

    return tokens[i] in HEDGES or tokens[i - 1 : i + 1] == ["all", "but"]


def _behind_the_ego_for_a_stretch(tokens: list[str], j: int) -> int | None:
    """Where "behind" + the ego + "for" + a stretch ends when said from ``tokens[j]`` ("behind us for
    some distance", "behind me for two miles"), or + a stretch said whole with no "for" ("behind me the
    whole way", "behind us all the way"), or None. Why: a road user kept behind the ego over a
    stretch of road is one that follows it, as much as one sat on its tail."""
    if tokens[j] != "behind":
        return None
    k = j + 1 + (tokens[j + 1 : j + 2] == ["the"])
    if tokens[k : k + 1] == [] or tokens[k] not in _EGO_WORDS:
        return None
    if tuple(tokens[k + 1 : k + 3]) in _WHOLE_OF and tokens[k + 3 : k + 4] and tokens[k + 3] in _STRETCH:
        return k + 4  # ("behind me the whole way", "behind us all the way"): the stretch said bare
    if tokens[k + 1 : k + 2] != ["for"]:
        return None
    for m in range(k + 2, min(k + 2 + _STRETCH_WORDS, len(tokens))):
        if tokens[m] in _STRETCH:
            return m + 1
    return None


def on_the_ego_tail(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user said to be at the ego's rear ("sitting 5 metres off my back bumper",
    "hung on my tail", "right up my backside") or behind it for a stretch ("sitting close behind us for
    some distance") read as following the ego from behind: where it keeps itself, close behind the
    ego, is what following is, whatever verb of staying says it. A verb of contact before it ("hit me
    on my rear bumper"), or after "up against" it ("came up against our tailgate and hit it"), says
    where it touched, not where it follows. Following is a going road user's: not one on foot (nor
    people sat behind the writer in the car), nor a rider kept behind for a stretch (it rides at its
    own pace), nor one said to stand ("parked behind me for a while"), nor one asked about ("Was that
    van behind us the whole way?": :func:`not_told.asked_of`). A side said in the clause ("up on my
    bumper on the inside") keeps the side."""
    out = []
    for link, mentions in clauses:
        if not mentions:
            out.append((link, mentions))
            continue
        kept = list(mentions)
        first, last = mentions[0].start, max(x.end for x in mentions)
        for j in range(first, min(last + 6, len(tokens))):
            if j >= last and tokens[j] in SENTENCE_END:
                break  # (the next clause's words are its own)
            stretch = _behind_the_ego_for_a_stretch(tokens, j)
            end = _the_ego_rear_at(tokens, j) or stretch
            if end is None:
                continue
            before = [x for x in kept if x.start < j]
            subject = subject_before(before)
            if subject is None or any(set(lemmas(t).get("VERB", ())) & _TOUCH for t in tokens[subject.end : j]):
                continue
            if asked_of(tokens, subject.start):
                continue  # ("Was that van behind us the whole way?": a question asserts nothing)
            if subject.value == "pedestrian" or (stretch and subject.value in VULNERABLE):
                continue
            if any(x.slot == "stationary" for x in before):
                continue
            if tokens[j + 1 : j + 2] == ["against"] and any(
                set(lemmas(t).get("VERB", ())) & _TOUCH for t in tokens[end : last + 1]
            ):
                continue
            if any(
                x.slot == "behaviour" and x.value[0] not in _SAYS_ONLY_THAT_IT_GOES
                for x in before
                if x.start > subject.start
            ):
                continue  # (a move of its own first: "overtook me and sat on my tail" keeps its overtake)
            said = {"words": " ".join(tokens[j:end]), "start": j, "end": end, "prev": tokens[j - 1] if j else "",
                    "next_": tokens[end] if end < len(tokens) else "", "det": "", "owners": ()}  # fmt: skip
            follow = replace(subject, slot="behaviour", value=("follow_vehicle", {}), **said)
            behind = replace(subject, slot="relation", value="behind", **said)
            side = any(x.slot == "lane_side" for x in kept if x.start >= end)
            at = kept.index(before[-1]) + 1
            kept = (
                [x for x in kept[:at] if not (x.slot == "behaviour" and x.start > subject.start)]
                + ([follow] if side else [follow, behind])
                + [x for x in kept[at:] if x.start >= end]
            )
            break
        out.append((link, kept))
    return out


def _a_time_gap(m) -> bool:
    """Whether mention ``m`` is a gap said in seconds (the reader makes it metres at the speed said)."""
    return m.slot == "distance" and m.words.split()[-1] in SECONDS


def at_a_time_gap_behind(clauses: list) -> list:
    """``clauses`` with a road user said behind the ego at a gap in seconds ("Ego at 60 km/h. HGV behind
    ego at < 1 s headway", "a van 1 s behind the ego"; a gap the reader has made metres at the ego's
    speed said, so with no speed said it stays a place) read as following it: a headway is the time a follower
    takes to reach where the one ahead is, so a gap said so is kept by one going after the ego,
    whatever verb (or none) says it. A move of its own said in the clause (an overtake, a cut-in)
    keeps its reading."""
    out = []
    for link, mentions in clauses:
        gap = next((x for x in mentions if _a_time_gap(x)), None)
        behind = next((x for x in mentions if x.slot == "relation" and x.value == "behind"), None)
        subject = subject_before([x for x in mentions if gap is not None and x.start < gap.start])
        acts = [x for x in mentions if x.slot == "behaviour"]
        if gap is None or behind is None or subject is None or subject.start > behind.start:
            out.append((link, mentions))
            continue
        if any(x.value[0] not in _SAYS_ONLY_THAT_IT_GOES for x in acts):
            out.append((link, mentions))
            continue
        follow = replace(gap, slot="behaviour", value=("follow_vehicle", {}))
        kept = [x for x in mentions if x not in acts]
        kept.insert(kept.index(gap) + 1, follow)
        out.append((link, kept))
    return out


#: What a road user that stops in the lane does: its first behaviour, before anything else.
_STOPS_THERE = frozenset(("stop", "sudden_stop"))
#: Where a road user in the ego's lane (or not placed beside it) is said to be.
_IN_THE_LANE = (None, "ahead", "behind")


def stops_in_the_lane(spec: ActorSpec, specs: list[ActorSpec]) -> bool:
    """Whether ``spec`` stands in the lane a lead may swerve out of, revealing it (one of ``specs``,
    the reading's road users): it stands there (no speed), or its first act is to stop there ("a
    lorry that has braked to a halt", "a coach ahead of it has stopped dead"). What comes to a stop
    in the lane is as much in the way of the ego, once the lead swerves round it, as what was parked
    there; only one other road user of the reading can swerve round it."""
    if spec.relation not in _IN_THE_LANE:
        return False
    if spec.speed_mps == 0.0:
        return True
    first = spec.behaviours[0][0] if spec.behaviours else None
    return first in _STOPS_THERE and spec.speed_mps is None and len(specs) > 1


def standing_still(spec: ActorSpec) -> list:
    """The behaviours of the road user a lead swerves round: it stands where it stopped, so a plain
    going on (no verb of its own said) is a stop there (the generator puts it at rest); a stop said
    as sudden stays so."""
    if spec.behaviours and all(b[0] == "keep_going" for b in spec.behaviours):
        crit = next((b[2] for b in spec.behaviours if b[2]), None)
        link = spec.behaviours[0][3] if spec.behaviours else "sequence"
        return [("stop", {}, crit, link)]
    return spec.behaviours


#: Words that end a noun phrase's left edge: what stands before them is no modifier of the noun.
_PHRASE_EDGE = frozenset((".", ",", ";", ":", "!", "?", "and", "or", "but", "then"))


def after_by(tokens: list[str], i: int) -> bool:
    """Whether the noun at ``tokens[i]`` heads a noun phrase led by "by" ("by a van", "by a white
    van", "by some big old lorry"): the doer of a passive verb said before it ("I was overtaken by a
    white van" is the van's overtake). The words between are its determiner and modifiers: words the
    lemma table holds as adjectives, or holds not at all (a make, a colour it lacks)."""
    j = i - 1
    while j >= 0 and i - j <= 4 and tokens[j] not in _PHRASE_EDGE and tokens[j] != "by":
        said = lemmas(tokens[j])
        if tokens[j] not in _DETERMINERS | {"some", "this", "that"} and said and "ADJ" not in said:
            return False
        j -= 1
    return j >= 0 and tokens[j] == "by"


#: Words that may stand between "in" and "in front of" the ego: how far, how exactly ("swings in
#: about 5 metres in front of me", "tucks in right in front of us").
_HOW_FAR_IN = frozenset(("about", "around", "roughly", "some", "only", "barely", "maybe", "approx", "approximately",
                         "m", "metres", "meters", "metre", "meter", "feet", "foot", "ft", "yards", "a", "few",
                         "couple", "of", "car", "lengths", "length"))  # fmt: skip


def _in_before_the_ego(tokens: list[str], j: int) -> bool:
    """Whether "in" (or "back in") at ``tokens[j]`` is followed, past how far, by "in front of" /
    "ahead of" the ego: the particle says into the lane, the rest where in it."""
    if tokens[j : j + 2] == ["back", "in"]:
        j += 1
    if tokens[j : j + 1] != ["in"]:
        return False
    k = j + 1
    while k < len(tokens) and k - j <= 6 and (tokens[k] in _HOW_FAR_IN or tokens[k].replace(".", "").isdigit()):
        k += 1
    return _before_the_ego(tokens, k)


def in_in_front_of_the_ego(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a verb + "in" said to end in front of the ego ("swings in about 5 metres in
    front of me", "tucks in right in front of us", "nips back in just ahead of me") read as a cut-in,
    whatever the verb: "in" is into the lane, and in front of the ego it is the ego's lane. Only a
    verb of the road user the clause is about, not the ego's, is read so."""

    def rule(k: int, m, mentions: list):
        plain = m.slot == "unknown_verb" or (m.slot == "behaviour" and m.value[0] in _PLAIN_MOVES)
        if not plain or not _in_before_the_ego(tokens, m.end):
            return None
        if subject_before(mentions[:k]) is None:
            return None
        return replace(m, slot="behaviour", value=("cut_in", {}))

    return _rewrite(clauses, rule)


def overtakes_on_the_wrong_side(clauses: list) -> list:
    """``clauses`` without "on the wrong side of the road" said right after an overtake of the ego or
    of no one said ("came past on the wrong side of the road", "overtook us on the wrong side of the
    road"): going past the ego on the other side of the road is how an overtake is made, not a road
    user driving the wrong way. Overtaking others there ("overtook the queue on the wrong side")
    puts it head-on to the ego, and stays so."""
    out = []
    for link, mentions in clauses:
        kept = []
        for m in mentions:
            before = next((x for x in reversed(kept) if not (x.slot == "actor" and x.value == "ego")), None)
            if m.slot == "wrong_way" and (m.prev == "on" or m.words.startswith("on ")) and passes(before):
                ego = [x for x in kept if x.slot == "actor" and x.value == "ego" and x.start >= before.end]
                said_on = 0 if m.words.startswith("on ") else 1 + bool(m.det)  # ("past on the wrong side")
                if m.start - before.end <= sum(x.end - x.start for x in ego) + said_on:
                    continue  # (it passes the ego or no one said: "overtook a queue on the wrong side" stays)
            kept.append(m)
        out.append((link, kept))
    return out


#: Moves that, into the lane the ego is said to be in, are a cut-in.
_INTO_THE_EGO_NAMED_LANE = frozenset(("change_lane", "keep_going", "cut_in"))


def _the_ego_named_lanes(clauses: list) -> set:
    """The sides of the lanes the ego is said to be in ("I was in the left lane", "the claimant, in the
    nearside lane, ..."): a lane said right after the ego is named, before any other road user."""
    out: set = set()
    for _, mentions in clauses:
        owner = None
        for m in mentions:
            if m.slot in ("actor", "pronoun"):
                owner = m.value
            elif m.slot == "lane_side" and owner == "ego" and m.value in ("left", "right", "middle"):
                out.add(m.value)
    return out


#: Words that put a road user far in front of the ego ("further ahead", "well ahead", "far ahead").
_FAR = frozenset(("further", "farther", "well", "far", "way"))


def _well_clear(mentions: list) -> bool:
    """Whether the clause says its move is made far from the ego: its road user well ahead ("further
    ahead", "far ahead") or the move well clear (a safe manner said of it). A cut-in is a move in
    close in front of the ego; into its lane far off it is only a lane change."""
    far = any(m.slot == "relation" and m.value == "ahead" and set(m.words.split()) & _FAR for m in mentions)
    return far or any(m.slot == "criticality" and m.value == "safe" for m in mentions)


def into_the_lane_the_ego_is_in(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user's move into the lane the ego was said to be in, by that lane's
    name ("I was in the left lane ... a lorry in the right lane moved into the left lane"), read as a
    cut-in; into any other lane it named, as a lane change ("... a lorry moved into the right lane").
    The ego's lane said by name is the ego's lane as much as "my lane" is."""
    ego_lanes = _the_ego_named_lanes(clauses)
    if len(ego_lanes) != 1:
        return clauses  # (no lane said of the ego, or two: nothing to compare with)
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept[:-1]):
            nxt = kept[k + 1]
            if m.slot != "behaviour" or m.value[0] not in _INTO_THE_EGO_NAMED_LANE or nxt.slot != "toward":
                continue
            lane = "lane" in tokens[nxt.start : nxt.end] or "lanes" in tokens[nxt.start : nxt.end]
            into = m.words.split()[-1] in ("into", "onto", "the") or tokens[m.end : m.end + 1] in (["into"], ["onto"])
            if not (lane and into) or subject_before(kept[:k]) is None:
                continue
            ours = nxt.value in ego_lanes
            if ours and _well_clear(kept):
                continue  # ("further ahead a lorry moves over to my lane, well clear": a lane change far off)
            if ours and m.value[0] != "cut_in":
                kept[k] = replace(m, value=("cut_in", {}))
            elif not ours and m.value[0] == "cut_in":
                kept[k] = replace(m, value=("change_lane", {}))
        out.append((link, kept))
    return out
