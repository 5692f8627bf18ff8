"""A walker or rider coming out from behind or between something (a parked vehicle, a hedge, a van),
or said to be part of the way across, crosses the ego's road. Wordings written for the class in
several registers (a police note, a parent's post, a text, a test log, a court report, a voice note),
none taken from a corpus; near misses that look alike keep their readings."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph
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


def _cover(text: str) -> list[tuple[str, list[str], str | None, float | None]]:
    """The vehicles read from ``text`` that stand at the kerb or are read as parked cover: kind,
    behaviours' names, start and speed."""
    return [
        (a.kind, [b[0] for b in a.behaviours], a.relation, a.speed_mps)
        for a in read(text).actors
        if a.kind in ("car", "van", "truck")
    ]


@pytest.mark.parametrize(
    "text",
    [
        # (the ego named by the cover's kind, its braking and speed read as the cover's)
        "A toddler ran from between two parked cars into the road ahead of us, we were going 30 km/h and "
        "the taxi stopped just in time.",
        "A woman walked out from behind a parked car in front of the Uber, the car was doing 25 mph and "
        "it stopped in time.",
        "Pedestrian emerged from between stationary lorries ahead of the HGV; the lorry, at 40 km/h, braked hard.",
        "Kid darted out from behind a parked van right in front of our van, we were doing 30 and the van "
        "stopped just in time.",
        "Small boy run out from behind parked bus, our bus going 30 km/h, bus brake hard and stop.",
        "A schoolboy stepped out from behind a parked lorry in front of the coach; the coach was doing 30 mph "
        "and it braked hard.",
        "A child ran out between parked cars in front of the minicab, the cab was going 20 mph and it "
        "stopped just short.",
    ],
)
def test_cover_stands(text: str) -> None:
    """A parked or standing vehicle someone comes out from behind or between stands at the kerb,
    whatever else was said near it: scenery, not a road user that brakes or moves."""
    cover = _cover(text)
    assert cover
    assert all(
        names == ["stop"] and speed == 0.0 and (rel or "").startswith("roadside") for _, names, rel, speed in cover
    )


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("A woman walked out from behind a parked car in front of the Uber, the car was doing 25 mph and "
         "it stopped in time.", 40.2),
        ("Pedestrian emerged from between stationary lorries ahead of the HGV; the lorry, at 40 km/h, "
         "braked hard.", 40.0),
        ("A schoolboy stepped out from behind a parked lorry in front of the coach; the coach was doing "
         "30 mph and it braked hard.", 48.3),
    ],
)  # fmt: skip
def test_speed_hung_on_the_cover_with_a_braking_is_the_egos(text: str, kph: float) -> None:
    """The speed said with the braking that the reader hung on the cover is the ego's."""
    assert ego_kph(text) == kph


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("A parked car pulled out in front of me without indicating.", ["cut_in"]),  # (no one's cover)
        ("A kid ran out from behind a bus that was pulling away from the stop.", ["cut_in"]),  # (not said to stand)
        (
            "A car pulled out from behind a parked van and cut in front of me.",
            ["cut_in", "stop"],
        ),  # (a vehicle's cover)
        ("A cyclist came from behind a parked bus and overtook me.", ["stop"]),
    ],
)
def test_what_is_no_standing_cover_keeps_its_moves(text: str, want: list[str]) -> None:
    """A parked vehicle that is no one's cover, and cover not said to stand, keep what they do."""
    assert [names[0] for _, names, _, _ in _cover(text)] == want


def test_cover_alone_is_left_alone() -> None:
    """Where the reader found no one but the cover ("Lad" is no word it knows), what it hung on the
    cover is all it read of the story, and it is kept."""
    assert [names for _, names, _, _ in _cover("Lad ran out from between two parked vans into my path.")] == [
        ["cut_in"],
        ["cut_in"],
    ]
