"""Who rear-ends whom says who was behind: the one that runs into another's rear came from behind it.

"A minicab rear-ended me", "I got rear-ended by a delivery van", "my car was rear-ended by a coach":
the road user is behind the ego; "I rear-ended a hatchback": the hatchback was ahead of it. Why a rule:
the reader reads "rear-ended" as the outcome (a collision) and nothing of where anyone was, so a road
user said only so started where nothing placed it (ahead of the ego, in its lane), which is the ego
rear-ending it, the other way round.

The grammar says who does it: in the active voice the subject named before the verb rear-ends its
object named right after it; in the passive ("was rear-ended by", "got rear-ended by") the one after
"by" rear-ends the subject, which a sentence of its own may leave out for the narrator ("just got
rear-ended by a van"). Only the ego and one road user are read so; between two road users the
verb says nothing of where either is from the ego.
"""

from __future__ import annotations

from dataclasses import replace

#: How far (tokens) after the verb its object or the "by" phrase's noun may start ("by a delivery van").
_OBJECT_REACH = 4
#: Slots of another verb: an object is not looked for past one.
_ACTS = frozenset(("behaviour", "stationary", "turn", "intent", "unknown_verb"))
#: Slots that name someone who can rear-end or be rear-ended.
_PARTIES = frozenset(("actor", "pronoun"))


def _rear_ends(m) -> bool:
    """Whether mention ``m`` is the verb "rear-end" (any form: "rear-ended", "rear-ends", "rear ending")."""
    return m.slot == "intent" and m.words.replace(" ", "-").startswith("rear-end")


def _party_after(mentions: list, k: int) -> int | None:
    """The index of the one named right after verb ``mentions[k]`` (its object, or after "by" its doer)."""
    end = mentions[k].end + (1 if mentions[k].next_ == "by" else 0)
    for j in range(k + 1, len(mentions)):
        x = mentions[j]
        if x.start > end + _OBJECT_REACH or x.slot in _ACTS:
            return None  # (past another verb: "the taxi I rear-ended had stopped for a cat")
        if x.slot in _PARTIES:
            return j
    return None


def _party_before(mentions: list, k: int) -> int | None:
    """The index of the subject of verb ``mentions[k]``: the nearest one named before it in its clause
    that is not the object of a place ("the van ahead of me was rear-ended": the van, not "me")."""
    placed = lambda j: j > 0 and mentions[j - 1].slot == "relation" and mentions[j].start - mentions[j - 1].end <= 1  # noqa: E731
    return next((j for j in range(k - 1, -1, -1) if mentions[j].slot in _PARTIES and not placed(j)), None)


def _opens_a_sentence(mentions: list) -> bool:
    """Whether the clause of ``mentions`` is a sentence of its own, not one joined to the one before
    ("and", "then"): its subject, left out, is then the narrator's ("Just got rear-ended by a van")."""
    return not (mentions and mentions[0].slot == "link")


def _ego(m) -> bool:
    return m.slot == "actor" and m.value == "ego"


def _road_user(m) -> bool:
    return m.slot == "actor" and m.value != "ego"


def rear_ender_behind(clauses: list) -> list:
    """Clauses (link, mentions) with a road user that rear-ends the ego said to be "behind" right after
    its name, and one the ego rear-ends said to be "ahead", so that this is the first place said of it."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if not _rear_ends(m):
                continue
            before, after = _party_before(mentions, k), _party_after(mentions, k)
            passive = m.next_ == "by"
            if after is None or (before is None and not (passive and _opens_a_sentence(mentions))):
                continue
            doer, done_to = (mentions[after], None if before is None else mentions[before])
            if not passive:
                doer, done_to = done_to, doer
            if _road_user(doer) and (done_to is None or _ego(done_to)):
                who, where = doer, "behind"
            elif _ego(doer) and done_to is not None and _road_user(done_to):
                who, where = done_to, "ahead"
            else:
                continue
            place = replace(who, slot="relation", value=where, words=where, start=who.end, prev=who.words)
            at = next(j for j, x in enumerate(kept) if x is who) + 1
            kept.insert(at, place)
        out.append((link, kept))
    return out
