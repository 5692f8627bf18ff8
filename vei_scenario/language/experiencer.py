"""A road user the narrator *had* (or *got*) doing something does it ("we had a van pull out").

English tells what happened to the one telling with "have"/"get" + a noun phrase + a bare verb ("I
had a kid run out in front of me", "we got a taxi swing across us"). The noun phrase is the object of
"have" but the subject of the bare verb; read left to right it looks like the ego's object, and the
verb after it would be taken as the ego's. Starting a clause at the road user makes it the subject of
its verb, as it is in "a kid ran out in front of me".
"""

from __future__ import annotations

from vei_scenario.language.lemmas import lemmas

#: Verbs (lemmas) of the narrator's experience that take a road user and a bare verb.
_EXPERIENCE = frozenset(("have", "get"))
#: Mentions that may be the bare verb after the road user.
_VERB_SLOTS = frozenset(("behaviour", "unknown_verb", "ego_verb"))
#: Words that put a vehicle with the person named before it ("a lad on a bike", "a bloke in a van").
_WITH = frozenset(("on", "in", "with", "riding", "driving"))
#: Words that may stand between "had" and the road user's noun besides adjectives ("had this idiot in
#: a van ...", "had one of those scooters").
_BEFORE_NOUN = frozenset(("a", "an", "the", "this", "that", "some", "one", "of", "those", "these", "two"))


def _bare_verb(word: str) -> bool:
    """Whether ``word`` is a verb in its bare form ("pull", "come", "dash"), not a past, a participle or
    a third person ("pulled", "coming", "pulls"): only a bare verb makes "had X VERB" this construction."""
    return word in lemmas(word).get("VERB", ()) and not word.endswith(("ed", "ing"))


def _experienced_at(tokens: list[str], start: int) -> bool:
    """Whether "have"/"get" stands before the noun phrase starting the road user mention at ``start``,
    with only articles, quantifiers and adjectives (no verb) between."""
    i = start - 1
    while i >= 0 and start - i <= 5:
        word = tokens[i]
        said = lemmas(word).get("VERB", ())
        if any(v in _EXPERIENCE for v in said):
            return True  # ("had", "has", "got", "have")
        if word in _BEFORE_NOUN or (lemmas(word) and not said):
            i -= 1
            continue
        return False
    return False


def road_user_had_acting(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with each road user said after "had"/"got" and before a bare verb of its own
    (:func:`_bare_verb`) starting a clause of its own, so the verb is its act ("we had a van pull out
    of a side road": the van pulls out). "I had a cyclist ahead of me" (no verb after it) stays as
    it is."""
    out = []
    for link, mentions in clauses:
        start = 0
        for k, m in enumerate(mentions):
            if k == 0 or m.slot != "actor" or m.value == "ego":
                continue
            j = k + 1
            while j < len(mentions) and mentions[j].slot == "actor" and mentions[j].prev in _WITH:
                j += 1  # ("had a lad on a bike roll off the kerb": the rider and what he rides)
            nxt = mentions[j] if j < len(mentions) else None
            if nxt is None or nxt.slot not in _VERB_SLOTS or nxt.start - mentions[j - 1].end > 1:
                continue  # (one adverb may stand between: "had a lad just step out")
            if not _bare_verb(nxt.words.split()[0]) or not _experienced_at(tokens, m.start):
                continue
            out.append((link, mentions[start:k]))
            link, start = "sequence", k
        out.append((link, mentions[start:]))
    return [(link, ms) for link, ms in out if ms]
