"""The ego pulling out of a side road or a drive: a road user then coming along from a side has the way.

Why: at a junction the reader takes a road user that comes "from the right" with a plain verb of motion
as one entering from that arm without stopping, which it plays as a run through a red light. When the
writer says the ego is the one pulling out ("I was pulling out of my drive when a car came over the
brow from my right", "we edged out of the junction and a cyclist came along from the left"), the road
user is on the road the ego joins: it goes on along it, with the way, and runs nothing. What says so is
the structure: a verb of coming out (pull, edge, nose, creep or come + "out", or "emerge") whose subject
is the ego (a first- or second-person pronoun, or nothing but the sentence's opening words, unless a
comma then a road user follows: "Emerging from the junction, a car came" is the car's), said to leave
a place one joins a road from or to turn ("out of the drive", "out from the side road", "out to turn
left"), not to pass ("pulled out to overtake" is a lane change on the ego's own road) nor to come out
of a tunnel, a bend, a roundabout or "the way", nor into a junction or on a green light or arrow (the
ego goes on its own light). Only a road user of that sentence or the next is marked, and none after
another junction comes in ("At the next crossroads a car came from the left").
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.access_pull_out import ACCESS_HEADS
from vei_scenario.language.clauses import SENTENCE_END, sentence_start, sentence_stop
from vei_scenario.language.junctions import SIGNAL_WORDS
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.sides import OFF_ROAD_PLACES

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
#: Head nouns of a place one joins a road from, giving way to it: a private way or a place off the
#: carriageway (:data:`ACCESS_HEADS`, :data:`OFF_ROAD_PLACES`: a drive, a car park, a forecourt), a side
#: road, a junction said left ("out of the junction") or a petrol station. Not a tunnel, a bend, a
#: roundabout or "the way": one comes out of those along its own road.
_JOINED_FROM = ACCESS_HEADS | OFF_ROAD_PLACES | {"road", "street", "junction", "turning", "station", "estate"}
#: Junctions one pulls out into, not a road one joins: the ego crossing on its own light.
_JUNCTIONS = frozenset(("junction", "crossroads", "crossroad", "intersection", "box"))
#: Words before a place's head noun that say whose or which it is ("my", "the petrol", "a side").
_PLACE_WORDS = 3
#: How far a road user's verb may be from the side it comes from ("came along from the right").
_SIDE_REACH = 6


def _emerging_verb(tokens: list[str], i: int) -> int | None:
    """The index past the verb phrase of coming out at ``i`` ("pulling out of", "emerged from"), when it
    says leaving a place or coming out to turn; None when ``i`` starts no such phrase."""
    verbs = set(lemmas(tokens[i]).get("VERB", ()))
    if verbs & _EMERGE:
        link = tokens[i + 1] if i + 1 < len(tokens) else ""
        return i + 1 if link not in _LEAVING or _joins_from(tokens, i + 2, link) else None
    if not verbs & _OUT_VERBS or tokens[i + 1 : i + 2] != ["out"]:
        return None
    after = tokens[i + 2 : i + 4]
    if after == ["to", "turn"]:
        return i + 2
    if after[:1] and after[0] in _LEAVING and _joins_from(tokens, i + 3, after[0]):
        return i + 2
    return None


def _joins_from(tokens: list[str], k: int, link: str) -> bool:
    """Whether the place said from token ``k`` on (after ``link``: "of", "from", "onto", "into") is one
    the ego joins a road from: its head noun (within a few words) one of :data:`_JOINED_FROM` after
    "of"/"from"; after "onto"/"into" any road but a junction ("pulled out into the junction": the ego
    crossing on its own light)."""
    head = next((m for m in range(k, min(k + 1 + _PLACE_WORDS, len(tokens))) if not tokens[m].isalpha()), None)
    words = tokens[k : min(k + 1 + _PLACE_WORDS, len(tokens)) if head is None else head]
    if link in ("onto", "into"):
        return not set(words) & _JUNCTIONS
    return bool(set(words) & _JOINED_FROM)


def _on_its_own_light(tokens: list[str], i: int) -> bool:
    """Whether the sentence of token ``i`` says a green light or a filter arrow ("the lights turned green
    and I pulled out", "On green I edged out"): the ego goes on its light, giving way to no one."""
    start, stop = sentence_start(tokens, i), sentence_stop(tokens, i)
    for k in range(start, stop):
        nxt = tokens[k + 1] if k + 1 < len(tokens) else ""
        if tokens[k] == "arrow" or (tokens[k] == "green" and (nxt in SIGNAL_WORDS or set(lemmas(nxt)) != {"NOUN"})):
            return True
    return False


def _said_of_the_ego(tokens: list[str], i: int, ego_ends: set[int], users: set[int]) -> bool:
    """Whether the verb at ``i`` has the ego as its subject: the ego named before it ("I", "we", "you",
    "the ego", the ego's vehicle) with only auxiliaries and adverbs between, or no subject at all in its
    sentence, nothing before it but words of when ("This morning pulled out to turn left": the
    writer's own act), and its clause not a participle that opens a main clause on a road user
    ("Emerging from the junction, a car came from the right": the car's, the main clause's subject;
    ``users``: where the text's road users other than the ego are named)."""
    k = i - 1
    while k >= 0 and tokens[k] in _BETWEEN:
        k -= 1
    if k >= 0 and (tokens[k] in _EGO_SUBJECTS or k + 1 in ego_ends):
        return True
    if not all(t in _WHEN for t in tokens[sentence_start(tokens, i) : k + 1]):
        return False
    comma = next((c for c in range(i, sentence_stop(tokens, i)) if tokens[c] == ","), None)
    return comma is None or not any(comma < u <= comma + 3 for u in users)


def ego_pulls_out(tokens: list[str], ego_ends: set[int], users: frozenset[int] = frozenset()) -> int | None:
    """The token index at which the ego is said to pull out of a side road, a drive or a car park (see
    the module's docstring), or None. ``ego_ends``: where the text's names of the ego end; ``users``:
    where its other road users' names start. Not where its sentence says the ego's light is green."""
    for i in range(len(tokens) - 1):
        if (
            _emerging_verb(tokens, i) is not None
            and _said_of_the_ego(tokens, i, ego_ends, set(users))
            and not _on_its_own_light(tokens, i)
        ):
            return i
    return None


def _apart(tokens: list[str], at: int, x: int, links: list[int]) -> bool:
    """Whether token ``x`` is in a later clause or sentence than the verb at ``at``: a clause's link
    (``links``: where they stand) or a sentence's end stands between them."""
    return any(at < c < x for c in links) or any(t in SENTENCE_END for t in tokens[at:x])


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
    along the road the ego joins, through the ego's path as it may, and runs no light. Only one said in
    the sentence of the pull-out or the next, with no junction brought in after the pull-out's clause
    ("I pulled out of the petrol station. At the next crossroads a car came from the left": another
    junction, where the ego has no one to give way to)."""
    actors = [m for _, ms in clauses for m in ms if m.slot == "actor"]
    users = frozenset(m.start for m in actors if m.value != "ego")
    at = ego_pulls_out(tokens, {m.end for m in actors if m.value == "ego"}, users)
    if at is None:
        return clauses
    stop = sentence_stop(tokens, at)
    reach = sentence_stop(tokens, stop + 1)  # (the end of the next sentence)
    links = [x.start for _, ms in clauses for x in ms if x.slot in ("conj", "link")]
    maps = [x.start for _, ms in clauses for x in ms if x.slot == "map" and x.start > at]
    junction = next((x for x in maps if _apart(tokens, at, x, links)), None)
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(mentions):
            if m.slot != "actor" or m.value == "ego" or m.start < at or m.start > reach:
                continue
            if junction is not None and junction < m.start:
                continue  # (a junction brought in after the pull-out: the road user is met there)
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
