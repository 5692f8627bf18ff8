"""A writer on foot whom the story's one motor vehicle meets: that vehicle is the ego, the writer the
walker it meets. Wordings written for the class in several registers (a dog walker's complaint, a
crossing patrol's note, an American crosswalk post, an Indian and a Nigerian account, a Singapore
jogger, an Australian voice note), none taken from a corpus; near misses where the writer is at a
wheel, only watches, or only stands keep the vehicle as a road user."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph
from vei_scenario.language import narrator_outside
from vei_scenario.language.reader import read


def _users(text: str) -> list[tuple[str, str | None, list[str]]]:
    """The road users read from ``text``: kind, start and behaviours."""
    return [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "behaviour", "kph"),
    [
        (
            "I was walking my dog along the lane when a van came up behind me and went past at 40 mph, inches away.",
            "along_road",
            64.4,
        ),
        (
            "Crossing patrol note: I stepped out with my lollipop and a taxi went straight past me at about 25mph.",
            "cross_in_front",
            40.2,
        ),
        (
            "I had looked both ways and stepped onto the crosswalk when a white SUV drove past right in front of"
            " me at 50 km/h.",
            "cross_in_front",
            50,
        ),
        (
            "We were crossing the road near the temple when one car came very fast past us at 60 km/h, nearly hit us.",
            "cross_in_front",
            60,
        ),
        (
            "I was trekking along the road to the junction when a Camry came from behind and passed me at 80 km/h.",
            "along_road",
            80,
        ),
        ("I was jogging along Upper Thomson Road when a lorry overtook me at 50 km/h, so close.", "along_road", 50),
        (
            "So I'm walking along the road out near the servo and this ute comes flying past me at like 80.",
            "along_road",
            80,
        ),
        (
            "We were crossing at the zebra when a bus went through in front of us at 30 mph without stopping.",
            "cross_in_front",
            48.3,
        ),
    ],
)
def test_the_vehicle_that_meets_a_writer_on_foot_is_the_ego(text: str, behaviour: str, kph: float) -> None:
    users = _users(text)
    assert [(kind, behaviours) for kind, _, behaviours in users] == [("pedestrian", [behaviour])]
    assert ego_kph(text) == pytest.approx(kph, abs=0.1)


@pytest.mark.parametrize(
    "text",
    [
        "I was driving along the high street when a van came past me at 40 mph.",  # (at a wheel)
        "I stood on the brakes as a van came past me at 40 mph.",  # (a foot on a pedal)
        "I had stepped on the gas when a van came past me at 40 mph.",
        "I swerved onto the kerb as a van came past me at 40 mph.",  # (a driver onto the kerb)
        "I was stood at the lights when a van came past me at 40 mph.",  # (a driver at the lights)
        "I was crossing the junction in my car when a van came past me at 40 mph.",  # (the writer's car)
        "I was standing at the bus stop when a van went past me at 40 mph.",  # (only stands: not placed)
        "I was walking the dog and watched a car go past at 40 mph.",  # (met by nothing: only watches)
        "I was walking home when I saw a van overtake a bus at 40 mph.",  # (two vehicles: the one passed)
    ],
)
def test_a_writer_at_a_wheel_watching_or_standing_keeps_the_vehicle(text: str) -> None:
    assert any(kind in ("car", "van", "truck") for kind, _, _ in _users(text))


def test_a_vehicle_a_writer_on_foot_sees_hit_a_rider_is_the_ego() -> None:
    """Where the writer on foot only sees it meet someone else, the one vehicle is still the ego."""
    text = "I was walking my dog when a Hilux travelling at 60 km/h hit a cyclist in front of me."
    assert [kind for kind, _, _ in _users(text)] == ["bicycle"]
    assert ego_kph(text) == 60


def test_a_writer_on_foot_is_outside_any_vehicle_even_where_met() -> None:
    scanned = "i had checked both ways and stepped off the kerb when a car went past me".split()
    assert narrator_outside.on_foot(scanned)
    assert not narrator_outside.on_foot("i stood on the brakes when a car went past me".split())
    assert not narrator_outside.on_foot("i swerved onto the kerb when a car came at me".split())
    assert narrator_outside.on_foot("we were on the pavement when a lorry went past us".split())
    assert narrator_outside.on_foot("i was out in the road in my wheelchair".split())


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("We are told a delivery van passed a cyclist on the hill far too close at around 30 mph.", 48.3),
        (
            "Parents please note: a silver car overtook a boy on his bike outside the school gates at 25 mph,"
            " very close.",
            40.2,
        ),
        ("A danfo overtook a cyclist at 50 km/h near the market and nearly knocked him down.", 50),
        ("One private bus overtook a cyclist at 60 km/h on the highway, very dangerous.", 60),
    ],
)
def test_the_one_vehicle_that_passes_a_rider_in_a_report_is_the_ego(text: str, kph: float) -> None:
    """Among walkers and riders, the one vehicle that overtakes passes one of them: the ego going on."""
    assert [kind for kind, _, _ in _users(text)] == ["bicycle"]
    assert ego_kph(text) == pytest.approx(kph, abs=0.1)


@pytest.mark.parametrize(
    "text",
    [
        "A lorry overtook a bus at 50 km/h and a cyclist came out from behind it.",  # (it passes a vehicle)
        "A van overtook me at 60 mph while I was cycling to work.",  # (the writer rides: the van meets them)
        "I was driving behind a cyclist when a van overtook us both at 50 mph.",  # (the writer at a wheel)
    ],
)
def test_a_vehicle_passing_a_vehicle_or_a_writer_at_a_wheel_stays(text: str) -> None:
    assert any(kind in ("car", "van", "truck") for kind, _, _ in _users(text))
