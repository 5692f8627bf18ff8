"""Crossings at junctions and roundabouts: a walker or rider who goes across the mouth of an arm, or
across in front of the ego, crosses the ego's road, whatever verb of motion the writer chose.

Why: at a junction the reader takes a side said of a road user with a plain verb ("came", "rode",
"zipped over") as the arm it comes out of, which makes a rider on the footway run a red light that
is not there. What makes it a crossing is the structure, not the verb: "over / across" + the mouth of
an arm ("over the exit", "across the entry", "over the mouth of the side road"), or "across" + the ego's
path ("across in front of me", "across my path"). Both rewrite the clause's plain verb of motion (or
add the crossing where the verb is one the lexicon lacks: "shot straight across in front of me").
Only walkers and riders are read so: a vehicle across the ego's path is read by the junction rules.
"""

from __future__ import annotations

import re
from dataclasses import replace

from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.word_mention import word_mention

#: Road users that cross a road on foot or by bike or scooter.
_CROSSERS = frozenset(("pedestrian", "bicycle", "e-scooter"))
#: Verbs that say only that a road user moves (the lexicon's plain going on, or a lane change read
#: from "zip over", "swing across"): what it does is then said by the words after them.
_PLAIN = frozenset(("keep_going", "change_lane", "along_road"))
#: Words of crossing, and what may stand between them and the arm crossed.
_ACROSS = frozenset(("across", "over"))
_BEFORE_ARM = frozenset(("the", "a", "an", "its", "mouth", "of", "straight", "right", "just", "directly"))
#: Adverbs between a verb and "across" ("shot straight across").
_MANNER = frozenset(("straight", "right", "just", "directly", "quickly", "suddenly"))
#: How the ego is named after "in front of" ("in front of me", "in front of the ego", "of our car").
_EGO_OBJECTS = frozenset(("me", "us", "ego", "my", "our"))
#: The ego's ways crossed ("across my path", "across our nose").
_EGO_WAYS = frozenset(("path", "way", "lane", "nose", "bonnet", "front", "bow"))


def _plain(m) -> bool:
    return (m.slot == "behaviour" and m.value[0] in _PLAIN) or (m.slot == "ego_verb" and not m.value)


def _subject(mentions: list, k: int):
    """The road user the clause is about before mention ``k``: the last actor named before it, or None
    when that is the ego or a pronoun (whose kind the reader settles later)."""
    for x in reversed(mentions[:k]):
        if x.slot in ("actor", "pronoun"):
            return x if x.slot == "actor" and x.value != "ego" else None
    return None


def _crossed_arm(mentions: list, k: int, tokens: list[str]) -> bool:
    """Whether the plain verb at ``k`` goes "over / across" the mouth of an arm named next."""
    m = mentions[k]
    nxt = mentions[k + 1] if k + 1 < len(mentions) else None
    if nxt is None or nxt.slot != "arm":
        return False
    between = tokens[m.end : nxt.start]
    said = m.words.split()[-1:] + between
    return bool(_ACROSS & set(said)) and all(w in _BEFORE_ARM | _ACROSS for w in between)


def _across_the_ego(tokens: list[str], j: int) -> bool:
    """Whether "across" at ``j`` goes on to the ego: "across in front of me", "across my path"."""
    after = tokens[j + 1 : j + 6]
    if after[:3] == ["in", "front", "of"]:
        rest = after[3:]
        return bool(rest) and (rest[0] in _EGO_OBJECTS or rest[:2] == ["the", "ego"])
    owner = after[1:] if after[:1] == ["the"] else after
    return (
        len(owner) > 1
        and owner[0] in ("my", "our", "ego", "ego's")
        and (owner[1] in _EGO_WAYS or (owner[1] == "'s" and len(owner) > 2 and owner[2] in _EGO_WAYS))
    )


#: What says a road user is already on the junction's circulating or major road: it has the way.
_CIRCULATING = frozenset(("circulating", "circling"))
_ON_THE_RING = frozenset(("roundabout", "ring", "circle", "gyratory", "mini-roundabout", "junction"))
_MAJOR = frozenset(("main", "major", "priority"))
_ROADS = frozenset(("road", "rd", "carriageway", "route"))
#: Where the phrase that describes a road user ends: the next clause, or the next road user.
_PHRASE_ENDS = frozenset((".", ";", "!", "?", "and", "but", "when", "while", "as", "then", "so"))


def _has_the_way(words: list[str]) -> bool:
    """Whether ``words`` (what follows a road user's noun, up to its verb) put it where it has the way:
    "already on the roundabout", "already circulating", "circulating from the right", "on the main
    road", "on major rd"; or the ring said as its place right after its noun ("a car on the roundabout
    came round", as "already on" says)."""
    for k, w in enumerate(words):
        if w in _CIRCULATING:
            return True
        if k == 0 and w == "on" and (_ON_THE_RING - {"junction"}) & set(words[1:3]):
            return True
        if w == "already" and k + 1 < len(words) and words[k + 1] in ("on", "in", "round", "around", "going"):
            rest = words[k + 2 : k + 4]
            if words[k + 1] == "going" or _ON_THE_RING & set(rest):
                return True
        if w in ("on", "along") and _MAJOR & set(words[k + 1 : k + 3]) and _ROADS & set(words[k + 2 : k + 4]):
            return True
    return False


def _owns(m) -> bool:
    """Whether road-user mention ``m`` is the ego said as an owner ("the ego's left", "my left"): part
    of a place, not a road user of the clause."""
    return m.value == "ego" and (m.next_ == "'s" or m.words in ("my", "our"))


def priority(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user said to be already on the roundabout (or on it, right after its
    noun), circulating, or on the main road marked as having the way ("_has_way", "_priority") on the
    plain verb it goes on with: at a junction it goes on through the ego's path as it may ("a cyclist
    already on the roundabout came round from the right"), even "without slowing"; it does not run a
    red light or force its way in. Said of the ego ("I was already on the roundabout when a car came
    in"), it says nothing of the other."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if m.slot != "actor" or m.value == "ego":
                continue
            verb = next((n for n in range(k + 1, len(mentions)) if mentions[n].slot in ("behaviour", "ego_verb")), None)
            other = next(
                (
                    n
                    for n in range(k + 1, len(mentions))
                    if mentions[n].slot in ("actor", "pronoun") and not _owns(mentions[n])
                ),
                None,
            )  # (not the ego owning a side or a place said of the road user: "from the ego's left")
            v = mentions[verb] if verb is not None else None
            if v is None or (other is not None and other < verb) or not _plain(v):
                continue
            if v.slot == "behaviour" and v.value[0] == "change_lane":
                continue  # (a lane change on the ring is its own move)
            end = mentions[verb].start
            words = tokens[m.end : end]
            if any(w in _PHRASE_ENDS for w in words) or not _has_the_way(words + tokens[end : end + 1]):
                continue
            cfg = v.value[1] if v.slot == "behaviour" else {}
            kept[kept.index(v)] = replace(
                v, slot="behaviour", value=("keep_going", {**cfg, "_has_way": 1.0, "_priority": 1.0})
            )
            places = mentions[k + 1 : verb]
            if places and all(x.slot == "map" for x in places):
                # ("a cyclist already on the roundabout coming ..."): the place is the scene's; said before
                # the road user, its participle follows it and is its own
                at = kept.index(m)
                kept = [x for x in kept if all(x is not p for p in places)]
                kept[at:at] = places
        out.append((link, kept))
    return out


#: Words of a traffic signal that may follow "the red" ("ran the red light").
SIGNAL_WORDS = frozenset(("light", "lights", "signal", "signals", "man", "arrow"))
#: Verbs (lemmas) that take the red as their object without going through it ("saw the red", "waited
#: for ... the red", "approached the red"): perceiving it, coming up to it, keeping to it.
_NOT_THROUGH = frozenset(
    ("see", "spot", "notice", "watch", "approach", "reach", "face", "obey", "respect", "wait", "stop", "get", "have")
)
#: Articles before "red" when it names the signal ("blew the red", "jumped a red").
_RED_ARTICLES = frozenset(("the", "a"))


def _runs_the_red_at(tokens: list[str], i: int) -> bool:
    """Whether token ``i`` is a verb whose object is the red signal ("shot the red", "blasted the red
    light at Eglinton"): verb + "the"/"a" + "red" (+ a word of the signal), with no other noun after
    "red" ("overtook the red car" is a colour), and the verb not one of seeing or coming up to it."""
    said = lemmas(tokens[i]).get("VERB", ())
    if not said or any(v in _NOT_THROUGH for v in said) or tokens[i + 1 : i + 3] not in (["the", "red"], ["a", "red"]):
        return False
    after = tokens[i + 3] if i + 3 < len(tokens) else ""
    if after in SIGNAL_WORDS:
        return True
    forms = lemmas(after)
    return not (forms.get("NOUN") and not forms.get("VERB") and not forms.get("ADP"))


def verb_the_red(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user's verb that takes the red signal as its object read as running
    it, whatever the verb (:func:`_runs_the_red_at`): "blew the red", "shot the red", "barrelled the
    red light" say how it went through; that it went through against the red is the object. Only a
    verb after a road user other than the ego, with no move of its own read between, counts; a
    "red light" the reader read as the junction's signal stays that, and the run is added at the verb."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if m.slot != "actor" or m.value == "ego":
                continue
            stop = next((x.start for x in mentions[k + 1 :] if x.slot in ("actor", "pronoun", "conj", "link")), None)
            end = min(stop if stop is not None else len(tokens), len(tokens) - 2)
            moves = [x for x in mentions[k + 1 :] if x.slot in ("behaviour", "turn") and x.start < end]
            for i in range(m.end, end):
                if tokens[i] in (".", ";", "!", "?"):
                    break
                if not _runs_the_red_at(tokens, i) or any(x.start < i and not _plain(x) for x in moves):
                    continue
                verb = next((x for x in kept if x.start == i and x.slot in ("behaviour", "unknown_verb")), None)
                ran = word_mention(m, tokens, i, "behaviour", ("run_red_light", {}))
                if verb is not None:
                    kept[kept.index(verb)] = ran
                else:
                    at = next((n for n, x in enumerate(kept) if x.start > i), len(kept))
                    kept.insert(at, ran)
                break
        out.append((link, kept))
    return out


def crossings(clauses: list, tokens: list[str]) -> list:
    """``clauses`` (link, mentions) with a walker or rider's crossing read from its structure: a plain
    verb of motion going over or across the mouth of an arm, or a road user going "across" in front
    of the ego or across its path (its plain verb made the crossing, or the crossing added where the
    verb is not one the reader knows). A clause that says another move already keeps it."""
    out = []
    for link, mentions in entering_the_roundabout(verb_the_red(clauses, tokens), tokens):
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if _plain(m) and _crossed_arm(mentions, k, tokens):
                subject = _subject(mentions, k)
                if subject is not None and subject.value in _CROSSERS:
                    kept[kept.index(m)] = replace(m, slot="behaviour", value=("cross_in_front", {}))
        kept = _across_in_front(kept, tokens)
        out.append((link, kept))
    return out


def _across_in_front(mentions: list, tokens: list[str]) -> list:
    if not mentions:
        return mentions
    first, last = mentions[0].start, max(x.end for x in mentions)
    for j in range(first, min(last, len(tokens))):
        if tokens[j] != "across" or not _across_the_ego(tokens, j):
            continue
        k = next((n for n, x in enumerate(mentions) if x.start >= j), len(mentions))
        if any(x.start <= j < x.end for x in mentions):
            continue  # ("cut across in front of me": a phrase the lexicon reads already)
        subject = _subject(mentions, k)
        if subject is None or subject.value not in _CROSSERS:
            continue
        since = [x for x in mentions[mentions.index(subject) + 1 : k]]
        if any(x.slot in ("behaviour", "turn") and not _plain(x) for x in since):
            continue  # (it already does something: "overtook me and cut across in front")
        moves = [x for x in since if _plain(x)]
        manner = [x for x in since if x.slot == "ego_verb" and x.value == "straight" and x.end == j]
        crossing = word_mention(
            moves[-1] if moves else subject, tokens, j, "behaviour", ("cross_in_front", {}), "across"
        )
        gone = set(map(id, moves + manner))
        mentions = [x for x in mentions[:k] if id(x) not in gone] + [crossing] + mentions[k:]
        break
    return mentions


#: Words that say a signal the road user could run ("ran the red", "jumped the lights", "on amber").
_SIGNAL_SAID = re.compile(r"\b(red|amber|lights?|signals?)\b")


def through_from_opposite(
    relation: str | None, behaviours: list, said: str, passes_another: bool, going_on: bool = True
) -> list:
    """``behaviours`` of a road user coming from the junction's opposite arm, with its going on read as
    going straight through on its own side (``keep_going``): said to go on "without stopping" or
    "straight through" (read as running the red) where no signal is said, or to go "past" the ego
    (read as an overtake) when it passes no one else ("sailed past", "went by our bumper"). Coming the
    other way it has the way over an ego that turns across it, and meets the ego head on rather than
    overtaking it. A red, amber or lights said keeps the run ("an oncoming car jumped the lights"), and
    so does a way said to be taken (``going_on`` false: "doesn't yield", "fails to give way"); an
    overtake of another road user stays its own ("pulled out to pass a bus")."""
    if relation != "junction_opposite" or not behaviours:
        return behaviours
    name, _, crit, link = behaviours[0]
    through = (name == "run_red_light" and going_on and not _SIGNAL_SAID.search(said)) or (
        name == "overtake" and not passes_another
    )
    return [("keep_going", {}, crit, link)] + behaviours[1:] if through else behaviours


#: Words of a signal or sign that controls a junction: where one is said, not stopping runs it.
_CONTROL_SAID = re.compile(
    r"\b(?:red|amber|lights?|signals?|signalised|signalized|signalled|signal-controlled|robots?)\b|\bstop signs?\b"
)
#: Words after a plain verb of motion that take it on over or through the junction ("carried on across").
_OVER = frozenset(("across", "over", "through"))


def signal_said(said: str) -> bool:
    """Whether the description says a light, signal or stop sign (``said``: its text as the reader
    reads it) that a road user could run: "red" only as the signal, not as the colour of a noun ("a red
    van"), and lamps are not signals (the reader has made those "lamps")."""
    for m in _CONTROL_SAID.finditer(said):
        if m.group(0) != "red":
            return True
        after = said[m.end() :].split()[:1]
        nxt = after[0] if after else ""
        forms = lemmas(nxt)
        if nxt in SIGNAL_WORDS or not (forms.get("NOUN") and not forms.get("VERB") and not forms.get("ADP")):
            return True
    return False


def goes_on_over(name: str, words: str, after: list[str]) -> bool:
    """Whether a plain move (``name``, said by ``words``, followed by the tokens ``after``) goes on over
    or through the junction ("carried on across", "went straight over", "kept going through"): a road
    user that does so after pulling out crosses the ego's road rather than joining it."""
    return name in _PLAIN and bool(_OVER & {*words.split(), *after})


#: Words after "straight" that make it the way through, not the aim ("straight on", not "straight at me").
_ON_THROUGH = frozenset(("on", "ahead", "through", "over", "across"))


def says_straight_on(name: str, words: str, after: list[str]) -> bool:
    """Whether a plain move or a run of the red (``name``, said by ``words``, followed by the tokens
    ``after``) says its way through is straight on ("carried straight on", "went straight through the
    red"): the text has said the runner's way, and the builder keeps it rather than choosing one that
    meets the ego. "Straight at me", "straight for us" say where it aims, not its way through."""
    if name not in _PLAIN and name != "run_red_light":
        return False
    said = [*words.split(), *after]
    return any(w == "straight" and said[k + 1 : k + 2] and said[k + 1] in _ON_THROUGH for k, w in enumerate(said))


def pulls_out_to_join(pulled_out: bool, goes_over: bool, names: list[str], relation: str | None, signal: bool) -> bool:
    """Whether a road user said to pull out of a side road on the ego's left or right ("came out of a side
    street without stopping", "emerged from the minor road and failed to give way") joins the ego's road
    rather than running through the junction: with no light, signal or stop sign said (``signal``), not
    stopping or giving way is how it pulls out, and leaving a side road ends in the road it meets. A
    light said keeps the run ("came out of Station Road against the red"), and so does a move over or
    across said after the pull-out (``goes_over``, or a crossing among ``names``: "... and carried on
    across"); one only said to come from an arm ("a car from the right arm did not yield") pulls out of
    nothing and goes through."""
    if not pulled_out or goes_over or signal or relation not in ("junction_left", "junction_right"):
        return False
    return names[:1] == ["cut_in"] and not {"run_red_light", "cross_in_front"} & set(names[1:])


#: Road users that ride a road: out of a side road they come along its carriageway, not off a kerb.
_RIDERS = frozenset(("bicycle", "e-scooter"))


def rides_across_from_an_arm(junction: bool, kind: str, from_arm: bool, kerb: bool, side: str | None) -> bool:
    """Whether a rider said to cross the ego's road at a junction comes out of a side road said with its
    side ("a cyclist from the right side road crosses", "an e-scooter from the left side street rides
    across our path"): it rides through the junction from that arm, across the ego's path, as a red-light
    runner does (the arm, not the kerb, is where it starts). A walker crosses from the kerb of that side,
    and a rider said on a kerb or footway ("off the pavement on the left") starts there; an arm it
    crosses ("crossing the exit from the right") is where it crosses, not where it comes from."""
    return junction and kind in _RIDERS and from_arm and not kerb and side in ("left", "right")


def rides_through_from_a_side(
    relation: str | None, kind: str, first: str | None, side: str | None, off_the_road: bool, route: str | None
) -> str | None:
    """The arm a rider starts on who crosses the ego's road at a junction from a side with no kerb,
    footway or crossing said, where the side is read as an arm ("approaching from our right on the cross
    street and entered the junction") or the rider runs the red light (``side`` is then given; the red
    stands at the arm's stop line, not at a kerb): a rider with nothing to place it off the road rides the
    road, so from that side it comes along the crossing road's carriageway, not off a kerb.
    None (keep the kerb) where the reading has it elsewhere than at that side's kerb, where it is said on
    a kerb, footway or lane, leaves a place beside the road (a path, a driveway), waits, or goes to a side
    (``off_the_road``), and where the ego turns
    towards that side: the rider there may be beside the ego at the kerb, which the turn then crosses."""
    if kind not in _RIDERS or first != "cross_in_front" or off_the_road or side not in ("left", "right"):
        return None
    if relation != f"roadside_{side}" or route == side:
        return None
    return f"junction_{side}"


#: Road users who cross the mouth of a side road on foot or on wheels.
_WALKERS_AND_RIDERS = frozenset(("pedestrian", "bicycle", "e-scooter"))


def crosses_the_arm_turned_into(
    kind: str, first: str | None, arm: bool, from_arm: bool, side: str | None, route: str | None
) -> str | None:
    """The kerb a walker or rider starts at who crosses the road the ego turns into, when no side is said
    of them ("I turned left into it; a man was crossing the side road"): the side road lies on the side
    the ego turns to, so whoever crosses its mouth starts on that side of the ego, whichever side traffic
    keeps to. None where a side is said, no arm is crossed (one said to come out of it is not crossing
    it), or the ego does not turn."""
    crosses = kind in _WALKERS_AND_RIDERS and first == "cross_in_front" and arm and not from_arm
    return f"roadside_{route}" if crosses and side is None and route in ("left", "right") else None


#: Verbs (lemmas) of entering: with the roundabout as their object, a road user comes onto it.
_ENTER = frozenset(("enter", "join"))
#: What a roundabout is called (the map mention's words).
_RING_WORDS = frozenset(("roundabout", "mini-roundabout", "gyratory", "circle", "rotary", "traffic circle"))
#: Adverbs between a verb and where it goes ("rode straight onto it", "shot suddenly onto the roundabout").
_BEFORE_ONTO = frozenset(("straight", "right", "just", "directly", "suddenly", "quickly", "out"))


def _ring(m) -> bool:
    """Whether ``m`` names a roundabout, in the singular or the plural ("roundabouts today": once said,
    "it" may stand for the one the story is at)."""
    if m.slot != "map" or m.value != "roundabout":
        return False
    words = set(m.words.split())
    singular = {n for w in words for n in lemmas(w).get("NOUN", ())}
    return bool((words | singular) & _RING_WORDS)


def _onto_the_ring(tokens: list[str], j: int, mentions: list, ring_said: bool):
    """The mention of the roundabout (or "it" standing for it) the verb at ``tokens[j]`` enters, or
    None: a verb of entering with it as its object, or any verb + "onto"/"into" it."""
    said = lemmas(tokens[j])
    verbs = set(said.get("VERB", ()))
    if not verbs or verbs & {"be", "have", "do"}:
        return None
    if tokens[j] in verbs and set(said) - {"VERB"}:
        return None  # (a bare form that is another word too: no verb here)
    k = j + 1
    while k < len(tokens) and tokens[k] in _BEFORE_ONTO:
        k += 1
    if k < len(tokens) and tokens[k] in ("onto", "into"):
        k += 1
    elif not verbs & _ENTER:
        return None
    while k < len(tokens) and tokens[k] in ("the", "a", "this", "that"):
        k += 1
    place = next((x for x in mentions if x.start == k), None)
    if place is not None and _ring(place):
        return place
    if place is not None and place.slot == "pronoun" and place.words == "it" and ring_said:
        return place
    return None


def entering_the_roundabout(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user that comes onto the roundabout ("rode straight onto it in front of
    me", "shot onto the roundabout", "entered the roundabout") read as entering it from one of its
    arms, whatever the verb: what it goes onto says the move. As the reader reads "enters the
    roundabout from the next entry", it then comes in from an arm across the ego's way round (and
    without giving way, runs it). "It" stands for the roundabout once one is said; a road user
    already on it, going round, is no entry (no "onto"), nor is the ego's own entry."""
    ring_said = False
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for j in range(mentions[0].start if mentions else 0, max((x.end for x in mentions), default=0)):
            if j >= len(tokens):
                break
            at = next((x for x in kept if x.start <= j < max(x.end, x.start + 1)), None)
            if at is not None and at.slot not in ("unknown_verb", "ego_verb", "behaviour"):
                continue
            if at is not None and at.slot == "behaviour" and at.value[0] not in _PLAIN:
                continue
            place = _onto_the_ring(tokens, j, kept, ring_said or any(_ring(x) for x in kept if x.start < j))
            if place is None:
                continue
            subject = _subject(kept, next((n for n, x in enumerate(kept) if x.start >= j), len(kept)))
            if subject is None:
                continue
            arm = replace(place, slot="arm", value=None, words="entry")
            if place.slot == "pronoun":
                kept[kept.index(place)] = arm
            else:
                kept.insert(kept.index(place) + 1, arm)
            if at is not None and at.slot == "unknown_verb":  # ("a scooter enter the roundabout": a plain going on)
                kept[kept.index(at)] = replace(at, slot="ego_verb", value=None)
            elif at is None:
                verb = word_mention(subject, tokens, j, "ego_verb", None)
                kept.insert(next((n for n, x in enumerate(kept) if x.start > j), len(kept)), verb)
            break
        ring_said = ring_said or any(_ring(x) for x in kept)
        out.append((link, kept))
    return out


#: Words that count the ways of a junction with stop signs ("a four-way stop", "the all-way stop").
_WAYS = frozenset(("all", "two", "three", "four", "five", "2", "3", "4", "5", "multi", "multiway"))


def ways_stop_at(tokens: list[str], i: int) -> bool:
    """Whether "stop" at token ``i`` ends the name of a junction whose arms all have stop signs ("an
    all-way stop", "a 4-way stop", "the three way stop"; American "AWSC", said in words): a place,
    like "a stop sign", not a road user stopping."""
    if tokens[i] != "stop" or i < 1:
        return False
    if tokens[i - 1].endswith("-way"):
        return tokens[i - 1].removesuffix("-way") in _WAYS
    return tokens[i - 1] == "way" and i >= 2 and tokens[i - 2] in _WAYS


#: Units a number after "junction" may count: then the number is a speed or a distance, no junction's.
_COUNTED = frozenset(("mph", "kph", "km/h", "km", "m", "metres", "meters", "miles", "mile", "ft", "feet", "yards", "s"))
#: Words of a motorway, where "junction 27" is an interchange by its number.
_MOTORWAY = frozenset(("motorway", "motorways", "mwy", "freeway", "interstate", "autobahn", "slip", "carriageway"))


def numbered_on_a_motorway(tokens: list[str], i: int) -> bool:
    """Whether "junction" at ``tokens[i]`` is a motorway's interchange named by its number ("on the M6
    near junction 19", "between junctions 25 and 26 of the motorway"): a number after it, no unit or
    noun after the number ("the junction 30 mph", "the junction 2 pedestrians" count something else),
    and a motorway said in the text (a word of one, or its name: "M25", "I-95", "A1(M)")."""
    number = tokens[i + 1 : i + 2]
    if not number or not number[0].isdigit():
        return False
    after = tokens[i + 2] if i + 2 < len(tokens) else ""
    nouns = lemmas(after).get("NOUN", ()) if after.isalpha() else ()
    plural = bool(nouns) and after not in nouns
    if after in _COUNTED or plural:
        return False  # ("the junction 30 mph", "the junction 3 cyclists")
    named = any(
        w in ("m", "i") and k + 1 < len(tokens) and tokens[k + 1].isdigit() or w.startswith("i-")
        for k, w in enumerate(tokens)
    )
    return named or bool(_MOTORWAY & set(tokens))
