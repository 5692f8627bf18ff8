"""A vehicle in the lane beside the ego's that comes to be in front of the ego: a cut-in, whatever the verb.

"A taxi in the left lane came in front of me", "a van from the right lane shoved in ahead of us", "the
lorry in the offside lane got in front of the ego", "a car from lane 3 nipped in ahead of me": people
say a cut-in by where it starts and where it ends, with whatever verb comes to mind (came, got,
barged, nipped, shoved, muscled, squeezed), and the reader cannot know every such verb. The path is
enough: a road user said to be in (or from) a lane on one side of the ego or beside it ("the next
lane"), then a verb, then "in front of" the ego (or "in ahead of" it: "ahead of" alone with a verb of
going, "pulled ahead of me", says it got further along its own lane), is a road user that left its
lane for the ego's, right in front of it: what a cut-in is. So is one said on a side of the ego ("a
taxi on our right came in front of us"): beside it, going its way, in the lane on that side.

What must not be read so: a verb of being or of going along ("a van in the right lane was ahead of
me", "stayed ahead of us", "drove ahead of me"), which says where it is, not a move; no verb at all
("the car in the left lane ahead of me": a noun phrase, a position); anything that opens a new clause
between the lane and the end of the path ("a taxi in the left lane, and a bus was ahead of me"); a
verb with "out" or "across" (a pull-out or a crossing, which other readings take); a walker (who
has no lane); a verb the reader already read as a behaviour of its own (a stop, an overtake, ...).
Only a plain going on ("came", read as keep_going) or a verb the reader has no behaviour for is read
anew.
"""

from __future__ import annotations

from dataclasses import replace

from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.own_way import is_its_own_object

#: Verbs (lemmas) of being somewhere or of going along: with "ahead of me" they say a position, no move.
_BEING_OR_GOING_ALONG = frozenset(
    ("be", "stay", "remain", "sit", "keep", "stand", "wait", "drive", "travel", "ride", "cruise", "run", "go",
     "hold", "lead", "queue", "idle", "continue", "proceed", "follow", "have", "seem", "appear", "look")
)  # fmt: skip
#: Tokens that end a clause: what follows them is said of something else.
_CLAUSE_ENDS = frozenset((".", ",", ";", ":", "!", "?", "and", "but", "then", "while", "when", "as", "where", "so"))
#: Particles of a move that is no cut-in: out of a side road or a parking place, across the road.
_NOT_INTO_THE_LANE = frozenset(("out", "across", "over", "through", "past", "by", "round", "around"))
#: The sides of the ego a lane may be on.
_SIDES = frozenset(("left", "right"))
#: Words that make "lane" one beside the ego's, side unsaid ("the next lane", "the adjacent lane").
_BESIDE = frozenset(("next", "adjacent", "neighbouring", "neighboring", "other", "parallel", "nearside", "offside"))
#: Words that make a side the ego's ("on my right", "on our left", "on the ego's left").
_EGO_OWNERS = frozenset(("my", "our", "ego", "ego's"))
#: The words of the ego after "in front of" or "ahead of".
_EGO_WORDS = frozenset(("me", "us", "ego"))


def _ends_in_front_of_the_ego(mentions: list, tokens: list[str], j: int) -> bool:
    """Whether ``mentions[j]`` is a relation of being in front of the ego ("in front of me", "in ahead
    of us", "in front of the ego"): where a path ends. "Ahead of" alone with a verb of going says it
    got further along ("pulled ahead of me", "sped ahead of us": in its own lane); only with "in"
    ("nipped in ahead of me") does it say a move into the ego's lane."""
    rel = mentions[j]
    if rel.slot != "relation" or rel.value != "ahead":
        return False
    if "front" not in rel.words.split() and (rel.start == 0 or tokens[rel.start - 1] != "in"):
        return False
    if set(rel.words.split()) & _EGO_WORDS:
        return True
    nxt = mentions[j + 1] if j + 1 < len(mentions) else None
    return nxt is not None and nxt.slot == "actor" and nxt.value == "ego" and nxt.start <= rel.end + 2


def _plain_verb(m) -> bool:
    """Whether mention ``m`` is a verb that says no more than a going on ("came", read as keep_going) or
    one the reader has no behaviour for ("got", "shoved"): the path around it says what the move is."""
    return m.slot == "unknown_verb" or (m.slot == "behaviour" and m.value[0] == "keep_going")


def _a_move_between(tokens: list[str], start: int, end: int) -> bool:
    """Whether ``tokens[start:end]`` (between the lane said and the end of the path) hold a verb of
    moving: a verb that is not one of being or going along, nor a word that may be an adverb ("right
    in front of us": how close, no move), and nothing that ends the clause or makes the move a pull-out
    or a crossing."""
    words = tokens[start:end]
    if not words or any(w in _CLAUSE_ENDS or w in _NOT_INTO_THE_LANE for w in words):
        return False
    verbs = [lemmas(w).get("VERB", ()) for w in words]
    if any(set(v) & _BEING_OR_GOING_ALONG for v in verbs):
        return False
    return any(v and not lemmas(w).get("AUX") and not lemmas(w).get("ADV") for v, w in zip(verbs, words, strict=True))


def lane_beside_after(tokens: list[str], i: int) -> int | None:
    """Where a lane beside the ego's with no side said ("in the next lane", "from the adjacent lane",
    "out of the other lane") ends, when one is said from token ``i``; None where none is."""
    j = i
    while j < len(tokens) and j < i + 2 and tokens[j] in ("in", "from", "out", "of"):
        j += 1
    if j == i or j + 2 >= len(tokens) or tokens[j] not in ("the", "a"):
        return None
    if tokens[j + 1] in _BESIDE and tokens[j + 2] in ("lane", "lanes"):
        return j + 3
    return None


def _beside_the_ego(m) -> bool:
    """Whether mention ``m`` is a side said as the ego's ("on my right", "on our left"): a road user
    there is beside the ego, going its way; "from the right" (where it comes from) is not."""
    words = m.words.split()
    return m.slot == "side" and words[:1] == ["on"] and bool(set(words) & _EGO_OWNERS)


def _skip_manner(mentions: list, j: int) -> int:
    """The index of the first mention from ``j`` on that is not a manner ("suddenly", "right in front"):
    how a move is made stands anywhere along its path."""
    while j < len(mentions) and mentions[j].slot == "criticality":
        j += 1
    return j


def _lane_end(mentions: list, tokens: list[str], k: int) -> tuple[int, int] | None:
    """(The index of the mention after the lane and the token the lane ends at) where the road user
    named at ``mentions[k]`` is said right after in a lane on one side of the ego ("in the left lane")
    or beside it ("in the next lane"); None where it is not."""
    nxt = mentions[k + 1] if k + 1 < len(mentions) else None
    if nxt is not None and (nxt.slot == "lane_side" or _beside_the_ego(nxt)) and nxt.value in _SIDES:
        return k + 2, nxt.end
    end = lane_beside_after(tokens, mentions[k].end)
    if end is None:
        return None
    j = k + 1
    while j < len(mentions) and mentions[j].start < end:  # ("the other": read as a member, part of the lane)
        j += 1
    return j, end


def _cut_in_at(mentions: list, tokens: list[str], k: int) -> tuple[int, int, int] | None:
    """Where the road user named at ``mentions[k]``, in a lane beside the ego's, is said to come in
    front of the ego: (the index of the mention read as the move, or -1 where no verb was read, the
    index of the relation it ends at, and the token its lane ends at); None where it is not."""
    who = mentions[k]
    if who.slot != "actor" or who.value in ("ego", "pedestrian"):
        return None
    lane = _lane_end(mentions, tokens, k)
    if lane is None:
        return None
    j, lane_end = lane
    verb = -1
    j = _skip_manner(mentions, j)
    if j < len(mentions) and _plain_verb(mentions[j]):
        verb, j = j, _skip_manner(mentions, j + 1)
    if j < len(mentions) and is_its_own_object(mentions[j], tokens):
        j = _skip_manner(mentions, j + 1)  # ("muscled its way in front of me": the road user moves itself)
    if j >= len(mentions) or not _ends_in_front_of_the_ego(mentions, tokens, j):
        return None
    if not _a_move_between(tokens, lane_end, mentions[j].start):
        return None
    return verb, j, lane_end


def into_the_lane_in_front(clauses: list, tokens: list[str]) -> list:
    """``clauses`` with a road user said in a lane beside the ego's that then comes to be in front of
    the ego read as cutting in (``tokens``: the reader's tokens, which the mentions index): the verb's
    mention (a plain going on) becomes the cut-in, or, where the reader read no verb, the relation
    that ends the path does; either way the relation is read into the move, as "cut in front of me"
    is."""
    out = []
    for link, mentions in clauses:
        kept = list(mentions)
        for k in range(len(kept)):
            found = _cut_in_at(kept, tokens, k)
            if found is None:
                continue
            verb, j, lane_end = found
            rel = kept[j]
            start = kept[verb].start if verb >= 0 else lane_end
            words = " ".join(tokens[start : rel.end])
            move = replace(
                rel, slot="behaviour", value=("cut_in", {}), words=words, start=start, prev=tokens[start - 1]
            )
            if verb >= 0:  # (the move where its verb is, the relation read into it)
                kept[verb] = move
                del kept[j]
            else:
                kept[j] = move
            break
        out.append((link, kept))
    return out
