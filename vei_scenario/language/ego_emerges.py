"""The ego pulling out of a side road or a drive: a road user then coming along from a side has the way.

Why: at a junction the reader takes a road user that comes "from the right" with a plain verb of motion
as one entering from that arm without stopping, which it plays as a run through a red light. When the
writer says the ego is the one pulling out ("I was pulling out of my drive when a car came over the
brow from my right", "we edged out of the junction and a cyclist came along from the left"), the road
user is on the road the ego joins: it goes on along it, with the way, and runs nothing. What says so is
the structure: a verb of coming out (pull, edge, nose, creep or come + "out", or "emerge") whose subject
is the ego (a first- or second-person pronoun, or nothing but the sentence's opening words), said to
leave a place or to turn ("out of the drive", "out from the side road", "out to turn left"), not to pass
("pulled out to overtake" is a lane change on the ego's own road).
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.clauses import sentence_start
from vei_scenario.language.lemmas import lemmas

#: Verbs (lemmas) that with "out" say a vehicle leaving a side road, a drive or a car park.
_OUT_VERBS = frozenset(("pull", "edge", "nose", "creep", "come", "inch", "roll"))
#: Verbs (lemmas) that alone say so.
_EMERGE = frozenset(("emerge",))
#: Pronouns that name the ego as a subject.
_EGO_SUBJECTS = frozenset(("i", "we", "you"))
#: Words that may stand between the ego's pronoun and its verb ("I was just pulling out", "we'd started
#: to edge out").
_BETWEEN = frozenset(
    ("was", "were", "am", "are", "'m", "'re", "had", "'d", "have", "'ve", "just", "slowly", "carefully",
     "started", "start", "starting", "began", "begin", "to", "then", "already", "gently")
)  # fmt: skip
#: Words of when that may open a sentence whose subject, the writer, is left out ("This morning pulled
#: out to turn left", "Yesterday, pulling out of the car park, ...").
_WHEN = frozenset(
    ("this", "that", "morning", "afternoon", "evening", "night", "today", "yesterday", "tonight", "earlier",
     "later", "then", "so", "and", "anyway", "just", ",", "last", "week", "on", "the", "way", "home", "while")
)  # fmt: skip
#: Words after "out" that say where from or where to: leaving a place, or joining a road to turn.
_LEAVING = frozenset(("of", "from", "onto", "into"))
#: How far a road user's verb may be from the side it comes from ("came along from the right").
_SIDE_REACH = 6


def _emerging_verb(tokens: list[str], i: int) -> int | None:
    """The index past the verb phrase of coming out at ``i`` ("pulling out of", "emerged from"), when it
    says leaving a place or coming out to turn; None when ``i`` starts no such phrase."""
    verbs = set(lemmas(tokens[i]).get("VERB", ()))
    if verbs & _EMERGE:
        return i + 1
    if not verbs & _OUT_VERBS or tokens[i + 1 : i + 2] != ["out"]:
        return None
    after = tokens[i + 2 : i + 4]
    if after[:1] and after[0] in _LEAVING or after == ["to", "turn"]:
        return i + 2
    return None


def _said_of_the_ego(tokens: list[str], i: int, ego_ends: set[int]) -> bool:
    """Whether the verb at ``i`` has the ego as its subject: the ego named before it ("I", "we", "you",
    "the ego", the ego's vehicle) with only auxiliaries and adverbs between, or no subject at all in its
    sentence, nothing before it but words of when ("This morning pulled out to turn left": the
    writer's own act)."""
    k = i - 1
    while k >= 0 and tokens[k] in _BETWEEN:
        k -= 1
    if k >= 0 and (tokens[k] in _EGO_SUBJECTS or k + 1 in ego_ends):
        return True
    return all(t in _WHEN for t in tokens[sentence_start(tokens, i) : k + 1])


def ego_pulls_out(tokens: list[str], ego_ends: set[int]) -> int | None:
    """The token index at which the ego is said to pull out of a side road, a drive or a car park (see
    the module's docstring), or None. ``ego_ends``: where the text's names of the ego end."""
    for i in range(len(tokens) - 1):
        if _emerging_verb(tokens, i) is not None and _said_of_the_ego(tokens, i, ego_ends):
            return i
    return None


def _plain_going(m) -> bool:
    return m.slot == "behaviour" and m.value[0] in ("keep_going", "along_road")


def _its_phrase(rest: list) -> list:
    """The mentions that belong to a road user's clause, from those after it: up to the next clause or
    road user, past the ego named in a relative clause before its verb ("a cyclist I couldn't see came
    along")."""
    verb_seen = False
    for n, x in enumerate(rest):
        if x.slot in ("conj", "link") or (x.slot == "actor" and (x.value != "ego" or verb_seen)):
            return rest[:n]
        verb_seen = verb_seen or x.slot in ("behaviour", "turn")
    return rest


def main_road_has_the_way(clauses: list, tokens: list[str]) -> list:
    """``clauses`` (link, mentions) with a road user said after the ego pulls out to come along from a
    side with a plain verb of motion ("a car came over the brow from my right") marked as having the
    way ("_has_way", "_priority", as :func:`junctions.priority` marks one on the main road): it goes on
    along the road the ego joins, through the ego's path as it may, and runs no light."""
    at = ego_pulls_out(tokens, {m.end for _, ms in clauses for m in ms if m.slot == "actor" and m.value == "ego"})
    if at is None:
        return clauses
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if m.slot != "actor" or m.value == "ego" or m.start < at:
                continue
            own = _its_phrase(mentions[k + 1 :])
            verb = next((x for x in own if x.slot in ("behaviour", "turn")), None)
            side = any(x.slot == "side" and x.start - (verb.end if verb else 0) <= _SIDE_REACH for x in own)
            if verb is None or not _plain_going(verb) or not side:
                continue
            kept[kept.index(verb)] = replace(
                verb, value=(verb.value[0], {**verb.value[1], "_has_way": 1.0, "_priority": 1.0})
            )
        out.append((link, kept))
    return out
