"""Where a walker's or rider's way goes says a crossing: "over the road", "to the other side".

English says a crossing by where the way leads as often as by the verb. "Over" with the carriageway
as its object is "across" it (British "popped over the road", "walked over the street"), so a plain
going ("went", "walked", "rode") with that way is a crossing of the road, as "went across the road"
is. And a move made "to get to the other side" (or "to the shop on the other side") ends beyond the
far kerb: whatever verb tells it ("hooks a right across the front of me", "swings out across the
lanes"), a walker or rider who goes to the other side goes across the ego's road. The other side is
where it goes, so its words say nothing of the kerb it starts at, and the "get to" of the purpose is
no move of its own.

What must not be read so: a vehicle named as one or by a pronoun that stands for one (going over a
road is driving on it or through a junction; one that makes for the other side turns, read
elsewhere), "over" with anything else as its object ("over the bridge", "over the hill", and "over the
road bridge", where "road" only says which bridge), the other side of anything but the road ("of the
bus", "of the lane", "of the field") or reached along or under another way ("along the pavement",
"through the underpass"), the other side said as where someone is ("on the other side"), onto which
one swerves ("out onto the other side": the wrong side of the road) or to which one moves to
overtake or to let the ego by (a move onto the other side of the road, not across it), or from
which one comes, and a move already read as a crossing.
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.discourse import DETERMINERS, VULNERABLE
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.motion import CARRIAGEWAY
from vei_scenario.language.quantities import OBJECT_PRONOUNS

#: Plain goings: a verb of going with nothing said of which way (``keep_going``, ``along_road``).
_PLAIN_GOINGS = frozenset(("keep_going", "along_road"))
#: Adverbs that may stand between a verb of going and its way ("went straight over the road").
_ON_THE_WAY = frozenset(("straight", "right", "just", "quickly", "suddenly", "back"))
#: Road users whose kind the reader settles later (a pronoun) or cannot tell (``unknown``).
_NOT_YET_KNOWN = frozenset(("pronoun",))
#: Mentions that tell a move of the road user named before them: what "to the other side" makes a crossing.
_MOVES = frozenset(("behaviour", "turn", "unknown_verb", "ego_verb"))
#: Moves that already cross or stop: "to the other side" adds nothing to them.
_SAID_ALREADY = frozenset(("cross_in_front", "stop", "sudden_stop", "give_way", "wrong_way"))
#: The words of the far side of the road as a destination ("the other side", "the far side").
_FAR = frozenset(("other", "far", "opposite"))
#: Verbs (as written) of reaching a place in a purpose said with "to" ("to get to", "to reach").
_REACHING = frozenset(("get", "reach", "make"))
#: The sides a turn goes to.
_SIDES = frozenset(("left", "right"))
#: Mentions that the far side, said as a place, leaves in the reading: where it is, not where one goes.
_PLACE_SLOTS = frozenset(("kerb", "kerb_side", "far_side", "side"))
#: Ways gone along or under on the way to the far side: the far side of them, not across the road.
_ALONG_A_WAY = frozenset(("along", "under", "underneath", "through"))
#: Purposes of a move to the other side of the road that keep it on the road: overtaking, letting by.
_LANE_PURPOSES = frozenset(("overtake", "give_way"))


def _subject(mentions: list, k: int):
    """The road user a move at mention ``k`` is told of: the last actor or pronoun named before it in
    its clause, or None (the ego, or none named)."""
    for x in reversed(mentions[:k]):
        if x.slot in ("actor", "pronoun"):
            return None if x.slot == "actor" and x.value == "ego" else x
    return None


def _may_cross(subject, before=None) -> bool:
    """Whether the road user ``subject`` names may cross the road on foot or on small wheels: a walker
    or rider, or one of no kind yet; a pronoun stands for ``before``, the road user named last before
    it, and is left alone where none was."""
    if subject is not None and subject.slot in _NOT_YET_KNOWN:
        subject = before
    return subject is not None and subject.value in VULNERABLE | {"unknown"}


def _last_named(mentions: list, before=None):
    """The road user other than the ego named last in ``mentions``, else ``before``: whom a pronoun
    after them stands for."""
    return next((x for x in reversed(mentions) if x.slot == "actor" and x.value != "ego"), before)


def _carriageway_head(tokens: list[str], j: int) -> bool:
    """Whether ``tokens[j]`` is a carriageway word heading its noun phrase: not "road" before the noun
    it only modifies ("the road bridge", "the road hump", "the road markings")."""
    if j >= len(tokens) or tokens[j] not in CARRIAGEWAY:
        return False
    after = lemmas(tokens[j + 1]) if j + 1 < len(tokens) else {}
    return not ("NOUN" in after and not set(after) & {"ADJ", "ADV"})


def _of_the_road(tokens: list[str], j: int) -> int | None:
    """Where the noun phrase after an "of" at ``tokens[j]`` ends when its head is a carriageway word
    ("of the road", "of the dual carriageway"), else None ("of the bus", "of the lane")."""
    k = j + 1
    while k < len(tokens) and tokens[k] in DETERMINERS:
        k += 1
    for n in range(k, min(k + 3, len(tokens))):
        if _carriageway_head(tokens, n):
            return n + 1
        if tokens[n] in CARRIAGEWAY or not tokens[n].isalpha():
            return None
    return None


def _over_the_road(tokens: list[str], j: int) -> bool:
    """Whether the way said from ``tokens[j]`` is "over the road" (past adverbs: "straight over the
    street"): "over" with the carriageway as its object, its head ("over the road bridge" is not)."""
    while j < len(tokens) and tokens[j] in _ON_THE_WAY:
        j += 1
    return (
        tokens[j : j + 1] == ["over"]
        and j + 2 < len(tokens)
        and tokens[j + 1] in DETERMINERS
        and _carriageway_head(tokens, j + 2)
    )


def over_the_road(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a walker's or rider's plain going on "over the road" ("went over the road in
    front of me", "rode straight over the street") read as the crossing it is."""
    out = []
    named = None  # the road user named last in the clauses before: whom a pronoun stands for
    for link, mentions in clauses:
        kept = list(mentions)
        for k, m in enumerate(kept):
            if m.slot != "behaviour" or m.value[0] not in _PLAIN_GOINGS or len(m.words.split()) != 1:
                continue
            if _over_the_road(tokens, m.end) and _may_cross(_subject(kept, k), _last_named(kept[:k], named)):
                kept[k] = replace(m, value=("cross_in_front", {}))
        named = _last_named(mentions, named)
        out.append((link, kept))
    return out


def _goal_at(tokens: list[str], j: int) -> tuple[int, int] | None:
    """Where the purpose or goal "to" opens that leads to "the other side" at ``tokens[j]`` ("to the
    other side", "to get to the other side", "to the servo on the other side"), and where its words
    end, or None: the far side as a destination, not as a place ("stayed on the other side") or an
    origin ("from the other side"), and of the road if of anything ("the other side of the bus")."""
    if tokens[j : j + 1] != ["the"] or tokens[j + 1 : j + 3] not in ([w, "side"] for w in _FAR):
        return None
    end = j + 3
    if tokens[end : end + 1] == ["of"]:
        end = _of_the_road(tokens, end)
        if end is None:
            return None  # ("the other side of the van", "the far side of the lane": not of the road)
    i = j - 1
    if i >= 0 and tokens[i] == "to":
        return _purpose_start(tokens, i), end
    if i < 0 or tokens[i] != "on":
        return None
    for back in range(i - 1, max(i - 6, -1), -1):  # ("to [get to] the servo on the other side")
        if tokens[back] in (".", ",", ";", "!", "?"):
            return None
        if tokens[back] == "to":
            return _purpose_start(tokens, back), end
    return None


def _purpose_start(tokens: list[str], i: int) -> int:
    """The first word of the purpose whose "to" stands at ``tokens[i]``: "to get to" opens two words
    before its last "to"."""
    if i >= 2 and tokens[i - 2] == "to" and tokens[i - 1] in _REACHING:
        return i - 2
    return i


def to_the_other_side(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a walker's or rider's move made to reach the other side of the road read as a
    crossing of it: the move before the goal (a plain going, a turn, a verb the reader has no word
    for) becomes the crossing, and the goal's words (its "get to", the far side as a kerb) go."""
    out = []
    goals = [g for j in range(len(tokens)) if (g := _goal_at(tokens, j)) is not None]  # (found once per text)
    named = None  # the road user named last in the clauses before: a clause may leave its subject unsaid
    last = None  # the road user named last before, not the ego: whom a pronoun stands for
    for link, mentions in clauses:
        kept = list(mentions)
        goal, end = next(((g, e) for g, e in goals if _in(kept, g)), (None, None))
        move = None if goal is None else _move_before(kept, goal, named, last, tokens)
        if move is not None and any(
            x.slot == "behaviour" and x.value[0] in _LANE_PURPOSES and x.start >= end and x.prev == "to" for x in kept
        ):
            move = None  # ("moved over to the other side of the road to let me pass": a move on the road)
        named = next((x for x in reversed(mentions) if _a_subject(x)), named)
        last = _last_named(mentions, last)
        if move is not None:
            k = kept.index(move)
            turned = _turned_to(kept, k)
            crossing = [replace(move, slot="behaviour", value=("cross_in_front", {}))]
            if turned is not None:  # (the side it turns to is the side it goes to: it starts on the other)
                start = "left" if turned.value == "right" else "right"
                crossing.append(replace(turned, slot="kerb_side", value=start, words=f"from the {start}", prev="from"))
            kept = [
                y
                for x in kept
                if not (goal <= x.start < end and x.slot in _PLACE_SLOTS | {"behaviour"})
                and (x is move or x is not turned)
                for y in (crossing if x is move else [x])
            ]
        out.append((link, kept))
    return out


def _turned_to(mentions: list, k: int):
    """The side the move at ``k`` turns to, as a mention whose value is that side, or None: the turn
    itself ("swings right") or the side said right after a verb the reader has no word for ("hooks a
    right")."""
    m = mentions[k]
    if m.slot in ("turn", "ego_verb", "side") and m.value in _SIDES:
        return m
    nxt = mentions[k + 1] if k + 1 < len(mentions) else None
    if m.slot == "unknown_verb" and nxt is not None and nxt.slot == "side" and nxt.value in _SIDES:
        return nxt
    return None


def _a_subject(m) -> bool:
    """Whether mention ``m`` names a road user that may be the subject of what follows: not one said
    in the object's form ("same way as me", "passed him"), who is not the one who goes on."""
    return m.slot in ("actor", "pronoun") and m.words not in OBJECT_PRONOUNS


def _in(mentions: list, j: int) -> bool:
    """Whether ``tokens[j]`` lies within the clause whose ``mentions`` are given."""
    return bool(mentions) and mentions[0].start <= j <= max(x.end for x in mentions)


def _move_before(mentions: list, goal: int, named=None, last=None, tokens: list[str] = ()):
    """The walker's or rider's move told just before the goal opening at ``goal``, with nothing but
    places, manners and the ego between: None where there is none, it is the ego's or a vehicle's, it
    already crosses or stops, or a way along or under is said on the way ("along the pavement to the
    other side"). With no subject said in its clause, the move is that of ``named``, the road user
    named last before ("he's cruising in the gutter, then hooks a right ..."); a pronoun stands for
    ``last``, the road user other than the ego named last before the clause. A side said right after a
    verb the reader has no mention for ("hooked a right") is the move."""
    for k in range(len(mentions) - 1, -1, -1):
        m = mentions[k]
        if m.start >= goal:
            continue
        if m.slot in ("actor", "pronoun") and m.value != "ego":
            return None  # (someone else's clause)
        if m.slot == "side" and m.value in _SIDES and "VERB" in lemmas(m.prev):
            pass  # ("hooked a right": the turn, its verb unread)
        elif m.slot not in _MOVES:
            continue
        if m.slot == "behaviour" and m.value[0] in _SAID_ALREADY:
            return None
        if m.slot == "ego_verb" and m.value not in _SIDES:
            continue  # (a route word: "straight"; "turned left" is a turn)
        if _along_a_way(tokens[m.end : goal]):
            return None
        said = any(x.slot in ("actor", "pronoun") for x in mentions[:k])
        subject = _subject(mentions, k) if said else _subject([named], 1) if named is not None else None
        return m if _may_cross(subject, _last_named(mentions[:k], last)) else None
    return None


def _along_a_way(words: list[str]) -> bool:
    """Whether ``words`` say a way gone along or under ("along the pavement", "through the underpass"),
    not through the traffic of the road ("through the traffic", "through the cars"): its far side is no
    far side of the road."""
    return any(
        w in _ALONG_A_WAY and not (w == "through" and any(x in CARRIAGEWAY for x in words[i + 1 : i + 4]))
        for i, w in enumerate(words)
    )
