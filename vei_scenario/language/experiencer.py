"""A road user the narrator *had* (or *got*, *let*, *saw*, *waited for*) doing something does it ("we
had a van pull out", "I stopped to let a girl cross").

English tells what happened to the one telling with "have"/"get" + a noun phrase + a bare verb ("I
had a kid run out in front of me", "we got a taxi swing across us"), and what the one telling let
happen or saw happen the same way: "let"/"see"/"watch"/"notice"/"spot"/"help" + a noun phrase + a
bare verb ("let a girl cross", "watched a lad dart out"; not a participle: "spotted a rider coming
off the kerb" keeps the one who spotted as the subject of what follows), "allow"/"wait for"/"stop
for" + a noun phrase + "to" + a verb ("allowed a cyclist to cross", "waited for a woman with a pram
to cross"). The noun phrase is the object of the first
verb but the subject of the second; read left to right it looks like the ego's object, and the verb
after it would be taken as the ego's. Starting a clause at the road user makes it the subject of its
verb, as it is in "a kid ran out in front of me".
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.function_words import WHERE_PREPOSITIONS
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.not_told import asked_of, undone
from vei_scenario.language.word_mention import word_mention

#: Verbs (lemmas) of the narrator's experience that take a road user and a bare verb.
_EXPERIENCE = frozenset(("have", "get"))
#: Verbs (lemmas) of letting and of seeing that take a road user and a bare verb ("let a girl cross",
#: "saw a van pull out").
_LETTING = frozenset(("let", "help"))
_SEEING = frozenset(("see", "watch", "notice", "spot"))
#: Verbs (lemmas) that take a road user and "to" + a verb ("allowed a cyclist to cross").
_ALLOWING = frozenset(("allow", "permit", "enable"))
#: Verbs (lemmas) that take "for" + a road user + "to" + a verb ("waited for a woman to cross", "stopped
#: for a kid to get across").
_WAITING = frozenset(("wait", "stop", "slow", "brake", "pause", "hold", "pull"))
#: Words of a phrase that says what a person has with them, between the road user and its verb ("a
#: woman with a pram", "an old man with a stick"): skipped when no mention stands in it.
_WITH_PHRASE = frozenset(("with", "pushing", "carrying", "holding", "walking"))
#: Mentions of where a road user is, said right after it ("a man on the pavement").
_WHERE_SLOTS = frozenset(("kerb", "kerb_side", "side"))
#: Mentions that may be the bare verb after the road user.
_VERB_SLOTS = frozenset(("behaviour", "unknown_verb", "ego_verb"))
#: Words that put a vehicle with the person named before it ("a lad on a bike", "a bloke in a van").
_WITH = frozenset(("on", "in", "with", "riding", "driving"))
#: Words that may stand between "had" and the road user's noun besides adjectives ("had this idiot in
#: a van ...", "had one of those scooters").
_BEFORE_NOUN = frozenset(("a", "an", "the", "this", "that", "some", "one", "of", "those", "these", "two"))


def _bare_verb(word: str) -> bool:
    """Whether ``word`` is a verb in its bare form ("pull", "come", "dash"), not a past, a participle or
    a third person ("pulled", "coming", "pulls"): only a bare verb makes "had X VERB" this construction.
    A verb whose bare form ends so ("swing", "bring", "speed") is its own only lemma."""
    verbs = lemmas(word).get("VERB", ())
    return word in verbs and (not word.endswith(("ed", "ing")) or verbs == (word,))


def _experienced_at(tokens: list[str], start: int, crossing: bool = False) -> str | None:
    """How the road user whose mention starts at ``start`` is said to act, by the verb before its noun
    phrase (only articles, quantifiers and adjectives, no verb, between): "bare" after "have", "get",
    "let" ("had a van pull out"), "seen" after a verb of seeing, "to"
    after "allow" or after "for" said after a verb of waiting ("waited for a kid to cross"), else None.
    ``crossing``: the road user's own verb is a crossing (see :func:`_stood_before`)."""
    i = start - 1
    while i >= 0 and start - i <= 5:
        word = tokens[i]
        said = set(lemmas(word).get("VERB", ()))
        if said & _LETTING and not crossing and _stood_before(tokens, i):
            return None  # ("I had stopped to let a bus pull out when ...": the scene opens on the ego standing)
        if said & (_EXPERIENCE | _LETTING):
            return "bare"  # ("had", "has", "got", "have", "let")
        if said & _SEEING:
            return "seen"
        if said & _ALLOWING:
            return "to"
        if word == "for" and i and set(lemmas(tokens[i - 1]).get("VERB", ())) & _WAITING:
            return "to"
        if word in _BEFORE_NOUN or (lemmas(word) and not said):
            i -= 1
            continue
        return None
    return None


def had_doing(tokens: list[str], j: int, verb: int) -> bool:
    """Whether the noun phrase that the article at ``tokens[j]`` opens follows a verb of having, letting
    or seeing and is followed by a bare verb at ``tokens[verb]`` ("had a Voi rider swing off", "saw a
    figure dart out"): a noun the reader has no word for there is the subject of that verb, as a road
    user's noun is. Without the bare verb it is what was had or seen ("had a fright today", "got a
    passenger")."""
    bare = verb < len(tokens) and _bare_verb(tokens[verb])
    return bare and _experienced_at(tokens, j + 1) in ("bare", "seen")


def _stood_before(tokens: list[str], i: int) -> bool:
    """Whether "to let" at ``tokens[i]`` follows a stop in the past perfect ("had stopped to let", "had
    pulled up to let"): the ego already stands as the scene opens (the reader starts it at 0 km/h), and
    a vehicle it had stopped for ("to let a bus pull out") did its move before the scene, not a road
    user that meets it. A walker or rider it had stopped to let cross is another matter (the caller
    does not ask then): the crossing goes on in front of the standing ego, and is the scene ("I had
    stopped to let a girl cross when the car behind overtook me": she crosses as the car goes by)."""
    if tokens[i - 1 : i] != ["to"]:
        return False
    before = tokens[max(0, i - 5) : i - 1]
    return "had" in before and any(set(lemmas(w).get("VERB", ())) & _WAITING for w in before)


def _verb_fits(how: str, word: str, between: list[str]) -> bool:
    """Whether ``word`` (the first word of the verb after the road user, ``between`` the words between)
    is the road user's verb as ``how`` (:func:`_experienced_at`) wants it: a bare verb, with "to"
    before it after "allow" or "wait for"."""
    if how == "to":
        return between[-1:] == ["to"] and _bare_verb(word)
    if between[-1:] == ["to"]:
        return False
    return _bare_verb(word)


def _between_ok(between: list[str], crossing: bool = False) -> bool:
    """Whether the words between the road user and its verb leave them one clause: nothing, one adverb
    ("had a lad just step out"), "to", or a phrase of what the person has with them ("a woman with a
    pram"); before a crossing also a short phrase of where the person waits ("stopped for a man on the
    pavement to cross", "let a woman at the kerb cross"): it says where the crossing starts."""
    rest = between[:-1] if between[-1:] == ["to"] else between
    if rest and (rest[0] in _WITH_PHRASE or (crossing and rest[0] in WHERE_PREPOSITIONS)):
        return len(rest) <= 4 and all(w.isalpha() for w in rest)
    return len(rest) <= 1


#: Modals of having to: "and had to stop" after the road user's act is the experiencer's reaction.
_HAVING_TO = frozenset(("had", "have", "needed", "need"))


def _own_reaction_after(mentions: list, first: int, j: int, tokens: list[str]) -> set[int]:
    """Make "and had to ..." after what the road user at ``mentions[first]`` was had doing (its verb at
    ``j``) the experiencer's ("Darren had a rider come off the kerb and had to stop dead": Darren
    stopped): the "and" becomes the experiencer named again, in place, so the reaction starts a clause
    of its own (its index is returned). Only the ego as the experiencer is named so; anyone named
    between ends the search."""
    had = next((x for x in reversed(mentions[:first]) if x.slot in ("actor", "pronoun")), None)
    if had is None or had.slot != "actor" or had.value != "ego":
        return set()
    for q in range(j + 1, len(mentions) - 1):
        x, nxt = mentions[q], mentions[q + 1]
        if x.slot in ("actor", "pronoun", "member") and x.value != "ego":
            return set()
        if x.slot == "conj" and x.words == "and" and nxt.slot == "modal" and nxt.words.split()[0] in _HAVING_TO:
            mentions[q] = word_mention(had, tokens, x.start, "actor", "ego", words=had.words)
            return {q}
    return set()


def _not_told(before: list, tokens: list[str], i: int) -> bool:
    """Whether the road user at ``tokens[i]`` is had, let or waited for only in a clause that tells
    nothing done (:mod:`not_told`): a counterfactual ("I would have stopped for a man to cross but he
    waved me on", "if I had let her cross, ..."), or a yes/no question about the one who let it
    ("Should I have stopped for him to cross?"; the last named in ``before``). Its verb is then no act
    of its own: nobody crossed."""
    who = next((x for x in reversed(before) if x.slot in ("actor", "pronoun")), None)
    return undone(tokens, i) or (who is not None and asked_of(tokens, who.start))


def road_user_had_acting(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with each road user said after "had"/"got" and before a bare verb of its own
    (:func:`_bare_verb`) starting a clause of its own, so the verb is its act ("we had a van pull out
    of a side road": the van pulls out). "I had a cyclist ahead of me" (no verb after it) stays as
    it is."""
    out = []
    for link, mentions in clauses:
        mentions = list(mentions)
        start = 0
        again: set[int] = set()  # (where the experiencer is named again)
        for k, m in enumerate(mentions):
            if k in again:
                out.append((link, mentions[start:k]))  # (the experiencer's own reaction: see below)
                link, start = "sequence", k
                continue
            if k == 0 or m.slot != "actor" or m.value == "ego":
                continue
            j = k + 1
            while j < len(mentions) and mentions[j].slot == "actor" and mentions[j].prev in _WITH:
                j += 1  # ("had a lad on a bike roll off the kerb": the rider and what he rides)
            said_end = mentions[j - 1].end  # (where the road user's noun phrase ends)
            if j < len(mentions) and mentions[j].slot in _WHERE_SLOTS and tokens[said_end] in WHERE_PREPOSITIONS:
                while j < len(mentions) and mentions[j].slot in _WHERE_SLOTS:
                    j += 1  # ("stopped for a man on the pavement to cross": where he waits, said with him)
            nxt = mentions[j] if j < len(mentions) else None
            if nxt is None or nxt.slot not in _VERB_SLOTS:
                continue
            crossing = nxt.slot == "behaviour" and nxt.value[0] == "cross_in_front"
            between = tokens[said_end : nxt.start]
            how = _experienced_at(tokens, m.start, crossing) if _between_ok(between, crossing) else None
            if how is None or not _verb_fits(how, nxt.words.split()[0], between):
                continue
            if _not_told(mentions[start:k], tokens, m.start):
                continue  # ("I would have stopped for a man on the pavement to cross but he waved me on")
            first = k
            while first - 1 > start and mentions[first - 1].slot == "count":
                first -= 1  # ("let two of our pupils cross": the count is the road user's)
            if m.prev == "for":  # ("waited for a woman to cross": the subject of "cross", no object of "for")
                mentions[k] = replace(m, prev="")
            out.append((link, mentions[start:first]))
            link, start = "sequence", first
            if how == "bare":
                again |= _own_reaction_after(mentions, start, j, tokens)
        out.append((link, mentions[start:]))
    return [(link, ms) for link, ms in out if ms]
