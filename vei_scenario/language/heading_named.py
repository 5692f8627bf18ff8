"""A road user named bare in a heading, then brought in by the text that follows it.

"Scenario: E-scooter crosses from the right kerb ... When an e-scooter rider enters the road at 15
km/h", "Lorry cuts in on A14, nearly took my bonnet off. Doing 60 when a lorry from lane two swung
in", "[BUG] Lead car braking not handled. Steps: a lead car 25 m ahead brakes hard": a heading, a
title, a ticket's summary or a label names the road user with a singular noun alone (headings drop
their articles), and the text then brings it in as new with "a" or "an", as it brings every road user
in once. Read as two, it is one road user, told first in short and then in full: the one brought in
by the text stays, with the speed and gap the heading gives it where the text gives none.

A bare noun is one with no article, possessive or count before it (over its modifiers: "oncoming
e-scooter", "lead car"). The two are told apart, and both stay, where the words or the reading set
them apart: the later one is said to be someone else ("another", "a second", "the other"), named in a
group or by a plural; each is said to start somewhere the other is not ("Cyclist ahead of me ... a
cyclist behind me"), or the bare one is said to start on a side the later one is not read on ("Car
pulled out of side road on left ... A car behind me"); each does a different thing of its own ("Taxi
cut me up, then a taxi behind him ran the red"; going along is nothing of its own, and a turn across
is one act whoever's path it crosses); one is parked and the other not; one acts on the other ("Bus
pulls out. A car overtakes it"), or is the obstacle another reveals; or another road user of that
kind is named between them. Notes name road users bare too, and these guards are what keep a note's
two road users of one kind apart.
"""

from __future__ import annotations

from typing import Protocol

from vei_scenario.language.discourse import DETERMINERS
from vei_scenario.language.reading import ActorSpec, Reading
from vei_scenario.language.said_again import fold_into, plural, without

#: Determiners that bring a road user in as new.
_NEW = frozenset(("a", "an"))
#: Words before a noun that say it is someone else than one named before ("a second cyclist").
_SOMEONE_ELSE = frozenset(("other", "another", "second", "third", "further", "different"))
#: What a road user does when it only goes along as it was: no act of its own.
_GOING_ALONG = frozenset(("keep_going", "along_road", "keep_lane"))
#: Turns across the ego's way, told apart by whose path they cross: one act, a turn, for telling two
#: tellings of one road user apart ("turns right across ego path" read once as each).
_TURNING = {"turn_across": "turn", "forced_turn": "turn", "turn_into": "turn"}
#: How many modifiers may stand between a noun and its article ("a big white van").
_MODIFIERS = 2


class _Said(Protocol):
    """What the reader gathered of a road user, as far as this module reads it."""

    word: str
    det: str
    named_after: str
    named_end: int
    group: list | None
    counted: bool
    member_named: bool
    parked: bool
    said: set
    side: str | None
    kerb_side: str | None
    lane_side: str | None
    edge: str | None
    from_arm: bool
    object_of: object


def _bare(tokens: list[str], a: _Said) -> bool:
    """Whether ``a`` was first named by a singular noun with no article, possessive or count before it
    (read back over up to two modifiers): how headings, titles and labels name a road user."""
    if a.named_end < 0 or not a.word or plural(a.word.split()[-1]):
        return False
    k = a.named_end - len(a.word.split()) - 1
    for _ in range(_MODIFIERS + 1):
        if k < 0:
            return True
        w = tokens[k]
        if w in DETERMINERS or w == "'s" or w.isdigit() or w in _SOMEONE_ELSE:
            return False
        if not w.isalpha():
            return True  # (a colon, a dash, a line's end: nothing before it in its phrase)
        k -= 1
    return True


def _brought_in_new(a: _Said) -> bool:
    """Whether ``a`` is brought in as new and as one: "a" or "an", no word saying it is someone else,
    not in a group or picked out of one."""
    return (
        a.det in _NEW
        and a.named_after not in _SOMEONE_ELSE
        and not a.group
        and not a.counted
        and not a.member_named
        and bool(a.word)
        and not plural(a.word.split()[-1])
    )


def _placed(a: _Said) -> bool:
    """Whether the side ``a`` starts on was said in its own words (a side, a kerb's or a lane's side,
    an arm), not only taken from what it does."""
    return bool(a.side or a.kerb_side or a.lane_side or a.edge or a.from_arm)


def _own_act(spec: ActorSpec) -> str | None:
    """The first thing ``spec`` is read to do of its own, None where it only goes along as it was."""
    first = spec.behaviours[0][0] if spec.behaviours else None
    return None if first in _GOING_ALONG else _TURNING.get(first, first)


def _where(a: _Said) -> set[str]:
    """Where ``a`` was said to be in its own words: where it starts ("ahead of me"), and the side of the
    road, kerb, lane or edge it is on ("on the left", "from the left lane")."""
    return set(a.said) | {s for s in (a.side, a.kerb_side, a.lane_side, a.edge) if s}


def _acts(spec: ActorSpec) -> set[str]:
    """Every thing ``spec`` is read to do of its own (a turn across read as one act)."""
    return {_TURNING.get(b[0], b[0]) for b in spec.behaviours if b[0] not in _GOING_ALONG}


def told_apart(first: _Said, again: _Said, first_spec: ActorSpec, again_spec: ActorSpec, summary: bool = False) -> bool:
    """Whether the words or the reading set two road users of one kind apart: each said to start
    somewhere the other is not, or the first said to start elsewhere than the later one is read to;
    each doing a different thing of its own ("Taxi cut me up, then a taxi behind him ran the red"); one
    parked and the other not; or one acting on the other.

    With ``summary`` the first is told in a heading line over the later one's telling, which says more:
    they start apart only where each is said in words to be somewhere the other is not ("on the right"
    and "from the left", "ahead of me" and "from the left lane") and is read to start elsewhere, not
    where only the reading of a heading that says no place differs; the heading's act sets it apart
    only where the later one does no such thing (a heading names one of the acts its body tells)."""
    if summary:
        here, there = _where(first), _where(again)
        starts_apart = bool(here and there) and not here & there and first_spec.relation != again_spec.relation
        placed_apart = False
        act, later_acts = _own_act(first_spec), _acts(again_spec)
        acts_apart = act is not None and bool(later_acts) and act not in later_acts
    else:
        starts_apart = bool(first.said) and bool(again.said) and not (first.said & again.said)
        placed_apart = _placed(first) and first_spec.relation != again_spec.relation
        acts = (_own_act(first_spec), _own_act(again_spec))
        acts_apart = None not in acts and acts[0] != acts[1]
    return (
        starts_apart
        or placed_apart
        or acts_apart
        or first.parked != again.parked
        or again.object_of is first
        or first.object_of is again
    )


def _heading_said(actors: list, specs: list[ActorSpec], tokens: list[str], j: int) -> int | None:
    """The road user that road user ``j``, named bare, is brought in as later (see the module), or
    None."""
    a, kind = actors[j], specs[j].kind
    if not _bare(tokens, a) or a.group or a.counted or a.member_named:
        return None
    k = next((k for k in range(j + 1, len(specs)) if specs[k].kind == kind), None)
    if k is None or not _brought_in_new(actors[k]) or told_apart(a, actors[k], specs[j], specs[k]):
        return None
    if any(s.obstacle in (j, k) for s in specs):
        return None  # (what a cut-out reveals stands there: never the one that reveals it)
    return k


def merge_heading_named(actors: list, reading: Reading, tokens: list[str]) -> list:
    """Fold each road user of ``reading`` named bare in a heading into the one the text then brings
    in as new (see the module); ``actors`` are what the reader gathered of them, in the same order,
    ``tokens`` the words they were named in. Returns ``actors`` without the ones folded."""
    specs = reading.actors
    drop: set[int] = set()
    for j in range(len(specs)):
        if j in drop or (k := _heading_said(actors, specs, tokens, j)) is None:
            continue
        fold_into(specs[k], specs[j])
        drop.add(j)
    return without(actors, reading, drop)
