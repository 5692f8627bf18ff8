"""A walker or rider coming out from behind or between something (a parked vehicle, a hedge, a van),
or said to be part of the way across, crosses the ego's road. Wordings written for the class in
several registers (a police note, a parent's post, a text, a test log, a court report, a voice note),
none taken from a corpus; near misses that look alike keep their readings."""

from __future__ import annotations

import pytest

from vei_scenario.language import from_cover
from vei_scenario.language.reader import FUNCTION_WORDS, read


def _acts(text: str) -> list[tuple[str, list[str], str | None]]:
    """Each road user read from ``text``: its kind, its behaviours' names and where it starts."""
    return [(a.kind, [b[0] for b in a.behaviours], a.relation) for a in read(text).actors]


def _crosser(text: str) -> tuple[str, list[str], str | None]:
    """The first road user read from ``text`` that is no parked vehicle."""
    return next(x for x in _acts(text) if x[1] != ["stop"])


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A man stepped from behind a bus in front of me.", "pedestrian"),
        ("Kid appeared from behind an ice cream van, I was doing maybe 20 mph.", "pedestrian"),
        ("Police say the boy came from behind a parked delivery lorry and was struck by the car.", "pedestrian"),
        ("A jogger came from behind a hedge into the road just ahead of us.", "pedestrian"),
        ("The pedestrian stepped from between two parked vans.", "pedestrian"),
        ("A girl chased her ball out between two parked cars in front of me.", "pedestrian"),
        ("Test 4: the dummy child emerges from behind the parked car obstruction at 5 km/h.", "pedestrian"),
        ("Some lad on a bike came flying from between the parked cars on my right.", "bicycle"),
        ("A kid on a scooter came out from behind a parked lorry.", "e-scooter"),
    ],
)
def test_out_from_cover_crosses(text: str, kind: str) -> None:
    """Coming out from cover with no other move said: a crossing from the kerb, not a walk along."""
    got_kind, names, relation = _crosser(text)
    assert (got_kind, names[:1]) == (kind, ["cross_in_front"])
    assert relation is not None and relation.startswith("roadside")


@pytest.mark.parametrize(
    ("text", "names"),
    [
        ("A cyclist came up from behind me and overtook me.", ["overtake"]),  # (the ego's rear)
        ("A cyclist came from behind a bus and overtook me.", ["overtake"]),  # (its move is said)
        ("A cyclist rode between two lorries.", ["along_road"]),  # (no coming out)
        ("A pedestrian walked behind my car.", ["along_road"]),
        ("A pedestrian waited behind a parked van at the kerb.", ["stop"]),
    ],
)
def test_near_misses_keep_their_reading(text: str, names: list[str]) -> None:
    """Cover that is the ego, a move that is said, or being behind or between with no "from"/"out"."""
    assert _acts(text)[0][1] == names


def test_a_vehicle_out_from_behind_joins_the_traffic() -> None:
    """A car pulling out from behind a parked van is no walker: it does not cross from a kerb."""
    kinds = _acts("A car pulled out from behind a parked van.")
    assert kinds[0][0] == "car" and "cross_in_front" not in kinds[0][1]


@pytest.mark.parametrize(
    ("tokens", "start", "out"),
    [
        ("a man stepped from behind an ice cream van".split(), 8, True),
        ("she ran out between two parked cars".split(), 6, True),
        ("a cyclist rode between two lorries".split(), 5, False),
        ("he stood behind a van".split(), 4, False),
        ("came out from behind me and a van".split(), 7, False),
    ],
)
def test_out_of_cover(tokens: list[str], start: int, out: bool) -> None:
    """The cover is the noun phrase that "from"/"out" + "behind"/"between" governs, and nothing past
    a function word."""
    assert from_cover.out_of_cover(tokens, start, FUNCTION_WORDS) is out


@pytest.mark.parametrize(
    "text",
    [
        "An elderly man was halfway across when a car went straight over the crossing.",
        "The taxi never slowed although a woman was already half-way across from the right.",
        "cctv: a lad was midway across when the lorry went through",
        "A kid was part way across the zebra when a bus sped through.",
        "An old fella was partway across the road when the van came round the bend.",
    ],
)
def test_part_of_the_way_across_crosses(text: str) -> None:
    """Someone said to be halfway (midway, part way) across is crossing the road."""
    assert any(k == "pedestrian" and n[:1] == ["cross_in_front"] for k, n, _ in _acts(text))


@pytest.mark.parametrize(
    "text",
    [
        "My son stepped out between parked cars to cross the road and was hit by a car.",
        "Her grandson crossed the road in front of me, I was doing 20.",
        "Our nan stepped off the kerb in front of a bus on Tuesday.",
        "my daughter ran across the road to her friend's house and a car nearly hit her",
        "His daughter darted out into the street right in front of the van.",
    ],
)
def test_ones_own_people_crossing_are_walkers(text: str) -> None:
    """One of someone's own people ("my son", "her grandson") who crosses on foot is a walker."""
    assert any(k == "pedestrian" and n[:1] == ["cross_in_front"] for k, n, _ in _acts(text))


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("My husband was driving at 30 mph when a cyclist cut in.", ["bicycle"]),  # (he drives the ego)
        ("My daughter was in the back when a van hit us.", ["van"]),  # (a passenger)
        ("My wife braked hard when a kid ran out.", ["pedestrian"]),
    ],
)
def test_ones_own_people_who_do_not_cross_are_no_walkers(text: str, kinds: list[str]) -> None:
    assert [k for k, _, _ in _acts(text)] == kinds
