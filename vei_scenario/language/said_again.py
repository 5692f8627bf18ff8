"""One road user said again with words the reader does not tie back to it.

"A car ran the red light. This guy in a red SUV blew through the red and I T-boned him": the second
sentence tells again what the first told, of the same road user, in other words ("this guy in a red
SUV" is a person the reader turns into the SUV he drives, so no car named before is looked for). Read
as one more road user, it is that road user read twice: the same kind, starting where the first
starts and doing what the first does.

A road user is said again so when it is brought in with a determiner that points back ("the", "this",
"that") or, as notes write, with none at all (a singular noun alone), and its reading is the one of an
earlier road user of its kind: the same start and the same acts, and no speed or gap of its own that
differs. Two road users are told apart in the words, and then both stay: one brought in as new ("a",
"another", "one", "some"), named in a group or picked out of one ("two riders", "the other"), or named
by a plural. Its speed and gap go to the road user it is, where that one has none.
"""

from __future__ import annotations

from typing import Protocol

from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.reading import ActorSpec, Reading

#: Determiners that point back to one named before (none: a noun alone, as notes write "the").
_POINTING_BACK = frozenset(("", "the", "this", "that"))


class _Said(Protocol):
    """What the reader gathered of a road user, as far as this module reads it."""

    word: str
    det: str
    group: list | None
    member_named: bool


def plural(word: str) -> bool:
    """Whether ``word`` (the last word a road user is named by) is a plural noun: a noun that is not
    its own lemma ("riders", "scooters"), or, a word no dictionary has, one ending in a single "s"."""
    nouns = lemmas(word).get("NOUN")
    if nouns:
        return word not in nouns
    return word.endswith("s") and not word.endswith("ss")


def _points_back(a: _Said) -> bool:
    """Whether ``a`` is brought in as one named before: a singular noun with a determiner that points
    back or none, not in a group and not picked out of one."""
    return (
        a.det in _POINTING_BACK
        and bool(a.word)
        and not plural(a.word.split()[-1])
        and not a.group
        and not a.member_named
    )


def _same_reading(first: ActorSpec, again: ActorSpec) -> bool:
    """Whether road user ``again`` is read as ``first`` is: its kind, its start, its acts, and no speed
    or gap of its own that differs."""
    return (
        first.kind == again.kind
        and first.relation == again.relation
        and first.lateral_m == again.lateral_m
        and [b[0] for b in first.behaviours] == [b[0] for b in again.behaviours]
        and (again.speed_mps is None or first.speed_mps in (None, again.speed_mps))
        and (again.distance_m is None or first.distance_m in (None, again.distance_m))
    )


def merge_said_again(actors: list, reading: Reading) -> list:
    """Fold each road user of ``reading`` that is an earlier one said again (see the module) into that
    one; ``actors`` are what the reader gathered of them, in the same order. Returns ``actors``
    without the ones folded."""
    specs = reading.actors
    drop: set[int] = set()
    for k, (a, spec) in enumerate(zip(actors, specs)):
        if k == 0 or not _points_back(a) or any(s.obstacle == k for s in specs):
            continue
        first = next(
            (j for j in range(k) if j not in drop and not actors[j].group and _same_reading(specs[j], spec)), None
        )
        if first is None:
            continue
        fold_into(specs[first], spec)
        drop.add(k)
    return without(actors, reading, drop)


def fold_into(kept: ActorSpec, told: ActorSpec) -> None:
    """Give ``kept`` the speed and the distance ``told`` states where ``kept`` states none: one road
    user said twice keeps what either telling says of it."""
    kept.speed_mps = told.speed_mps if kept.speed_mps is None else kept.speed_mps
    kept.distance_m = told.distance_m if kept.distance_m is None else kept.distance_m


def without(actors: list, reading: Reading, drop: set[int]) -> list:
    """``actors`` and ``reading.actors`` without the tellings at the indices ``drop``, and each
    obstacle index (a road user another reveals) moved down past those dropped before it."""
    if not drop:
        return actors
    for s in reading.actors:
        if s.obstacle is not None:
            s.obstacle -= sum(1 for k in drop if k < s.obstacle)
    reading.actors = [s for k, s in enumerate(reading.actors) if k not in drop]
    return [a for k, a in enumerate(actors) if k not in drop]
