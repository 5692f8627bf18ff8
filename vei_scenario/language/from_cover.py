"""A walker or rider coming out from behind or between something that hides them: a crossing.

"A man stepped from behind a bus", "a child appeared from behind an ice-cream van", "the pedestrian
stepped from between two parked vans", "a girl chased her ball out between two parked cars", "it comes
out from behind the parked car on the right": people say where someone came out from cover and leave
the move itself to a verb the reader reads as no more than going ("stepped", "appeared", "came"), or
has no word for. Someone on foot or on two small wheels who comes out from behind a vehicle at the side
of the road comes onto the road across the ego's path; that is what the cover is told for.

What must not be read so: cover that is the ego ("came up from behind me": the ego's own rear, where
an overtaker starts), being behind or between something with no coming out ("a cyclist rode between
two lorries", "a man stood behind a van": "from" or "out" must govern the preposition), a vehicle
("a car pulled out from behind the bus" joins the traffic, which other passes read), and anyone whose
move the text does say (overtakes, stops, goes along the kerb, waits): only a bare going on is mended.

The cover itself stands. A vehicle said to be parked or standing that someone comes out from behind or
between ("from between two parked cars", "out from behind a stationary lorry") is told for who comes out
of it: it is scenery at the kerb, and whatever else the reader hung on it was said of someone else (the
ego named by the cover's kind: "the taxi stopped just in time"; a remark about the road). It stands
there, at speed 0; a speed hung on it ("the coach was doing 30 mph and it braked hard") was the ego's,
and is the ego's where the ego has none. A parked vehicle that is no one's cover keeps its own moves ("a
parked car pulled out"), and so does cover the text does not call parked or standing ("from behind a bus
that was pulling away"); where the reader found no one but the cover, what it hung on the cover is all
it read of the story, and it is left alone.
"""

from __future__ import annotations

from typing import Protocol

from vei_scenario.language.discourse import VEHICLES
from vei_scenario.language.reading import ActorSpec, Reading, stands_there

#: Prepositions of cover: what someone is behind, between or among hides them from the ego.
_COVER = frozenset(("behind", "between", "among", "amongst"))
#: Words that make the preposition of cover one of leaving it ("from behind", "out between").
_LEAVING = frozenset(("from", "out", "fae"))
#: Words that may stand between the preposition and the noun of the cover ("from behind the two parked
#: vans", "between a couple of parked cars"): determiners, counts, partitives and the state of the cover.
_COVER_PHRASE = frozenset(
    ("a", "an", "the", "this", "that", "these", "those", "some", "two", "three", "couple", "pair", "row", "line",
     "few", "several", "of", "parked", "stationary", "stopped", "waiting", "double-parked", "big", "large",
     "high", "tall", "white", "my", "our", "his", "her", "their")
)  # fmt: skip
#: Words that open the noun phrase of a cover ("from behind a hedge", "from behind the bins").
_DETERMINERS = frozenset(("a", "an", "the", "this", "that", "these", "those", "some", "two", "three", "one"))
#: Road users who come out from cover across the road on foot or on two small wheels (or whose kind the
#: reader will take from what they do).
_WALKERS_AND_RIDERS = frozenset(("pedestrian", "bicycle", "e-scooter", "unknown"))
#: Behaviours that say no more than that someone goes: what the cover says is the move.
_BARE_GOING = frozenset(("keep_going",))


def out_of_cover(tokens: list[str], start: int, function_words: set[str] | frozenset[str]) -> bool:
    """Whether the noun phrase whose head starts at ``start`` is the cover someone leaves: governed by
    "behind", "between" or "among" (past determiners, counts, the cover's state and words that say what
    kind it is: "from behind an ice cream van"), with "from" or "out" right before that ("from behind a
    bus", "out between two parked cars", "out from between"). "From in front of the bus" is no cover
    left towards the ego's road, and is not read here."""
    j = start - 1
    while j >= 0 and start - j <= 6 and _in_cover_phrase(tokens[j], function_words):
        j -= 1
    return j >= 1 and tokens[j] in _COVER and tokens[j - 1] in _LEAVING


def leaves_cover(tokens: list[str], start: int, end: int) -> bool:
    """Whether the place phrase ``tokens[start:end]`` ("from behind", "behind") says someone leaves
    cover named right after it: it ends in "behind", "from" or "out" governs that, and a determiner
    opens the cover's noun phrase ("came from behind a hedge", "out from behind the bus shelter"); the
    caller makes sure that the cover is not the ego ("from behind my car" said of the ego's)."""
    said = tokens[max(0, start - 1) : end]
    if said[-1:] != ["behind"] or len(said) < 2 or said[-2] not in _LEAVING:
        return False
    return end < len(tokens) and tokens[end] in _DETERMINERS


def _in_cover_phrase(word: str, function_words: set[str] | frozenset[str]) -> bool:
    """Whether ``word`` may stand inside the noun phrase of a cover before its head: a determiner, a
    count or a state, or a content word ("ice", "cream", "delivery"); no mark, preposition or other
    function word (those end the phrase)."""
    if word in _COVER_PHRASE:
        return True
    return word.replace("-", "").isalpha() and word not in function_words and word not in _COVER


def crosses_from_cover(kind: str, behaviours: list, quiet: bool) -> bool:
    """Whether a road user of ``kind`` said to come out from cover, with ``behaviours`` as read so far,
    crosses: a walker or rider (or one the reader names by what it does) of whom nothing more is said
    than that it goes, or nothing at all; ``quiet`` is False when anything else makes it go along, stand,
    be passed or drive against the traffic (those keep their reading)."""
    if kind not in _WALKERS_AND_RIDERS or not quiet:
        return False
    return all(b[0] in _BARE_GOING for b in behaviours)


class _Cover(Protocol):
    """What the reader gathered of a road user, as far as :func:`cover_stands` reads it."""

    kind: str
    hides: bool
    parked: bool
    stationary: bool


def _standing_cover(a: _Cover) -> bool:
    """Whether road user ``a`` is a vehicle said to be parked or standing that someone comes out from
    behind or between: cover, which stands at the kerb the whole time."""
    return a.kind in VEHICLES and a.hides and (a.parked or a.stationary)


def cover_stands(actors: list, reading: Reading) -> None:
    """Make every road user of ``reading`` that is standing cover (gathered as ``actors``, in the same
    order; see the module) stand: it stops, at speed 0, parked at the kerb (its start is cleared for
    the parked ones' side). Only where someone else than cover is read: the one it hides. A speed hung
    on it is the ego's, where the ego has none: it is what the ego does for the one who comes out
    ("the taxi was doing 30 and stopped just in time", the taxi read as the cover)."""
    if all(_standing_cover(a) for a in actors):
        return  # (no one but the cover: what it carries is all that was read)
    for a, spec in zip(actors, reading.actors):
        if _standing_cover(a):
            stand_at_the_kerb(a, spec, reading)


def stand_at_the_kerb(a: _Cover, spec: ActorSpec, reading: Reading) -> None:
    """Make road user ``spec`` (gathered as ``a``) of ``reading`` stand parked at the kerb: it stops, at
    speed 0 (its start is cleared for the parked ones' side). What the reader hung on it was said of
    someone else; a speed is the ego's, where the ego has none (with a braking: the ego's stop for the
    one the parked vehicle hides; "past the parked lorries a cyclist swerved ... at 25 mph": the ego's
    going past them)."""
    if stands_there(spec):
        return
    if reading.ego_speed_mps is None and spec.speed_mps:
        reading.ego_speed_mps = spec.speed_mps
    spec.behaviours = [("stop", {}, None, "sequence")]
    spec.speed_mps = 0.0
    a.stationary = a.parked = True  # (at the kerb, where it hides someone)
    if not (spec.relation or "").startswith("roadside"):
        spec.relation = None  # (the parked ones' side puts it at the kerb)


class _Placed(Protocol):
    """What the reader gathered of where a road user is, as far as :func:`side_of_the_cover` reads it."""

    kind: str
    parked: bool
    stationary: bool
    relation: str | None
    side: str | None
    kerb_side: str | None
    lane_side: str | None


def side_of_the_cover(who: _Placed, cover: _Placed | None) -> str | None:
    """The kerb side a walker or rider who comes out from behind or between a road user said to stand
    (parked or stationary) at a side of the road starts at: that side ("a van is parked on the left ...
    a child runs out from behind the van"), where nothing places the walker itself. Why: the cover hides
    it from the ego because they are at the same kerb; read alone, it was put at the writer's near kerb.
    A vehicle going by ("a van on my left was turning into a driveway") stands at no kerb."""
    if cover is None or who.side or who.kerb_side or who.lane_side or cover.kind not in VEHICLES:
        return None
    if not (cover.parked or cover.stationary):
        return None  # ("a van on my left was turning into a driveway": going, it is at no kerb)
    where = cover.kerb_side or cover.side or (cover.relation or "").removeprefix("roadside_")
    return where if where in ("left", "right") else None
