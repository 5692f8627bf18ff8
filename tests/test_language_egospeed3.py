"""The ego's speed said in ways a talker says it: two numbers with a comma between ("doing 30, 35"), a
past "did" ("we did 40 along the main road"), a speed with two words before it ("at a nice steady 50"),
and a British A-road, whose bare speeds are in mph.

Every wording here is written for these tests (none is from a corpus). Each construction has wordings
that must read the new way, and near misses that look alike but must keep their old reading."""

from __future__ import annotations

import pytest

from vei_scenario.language import vocabulary as V
from vei_scenario.language.reader import read

KPH, MPH = V.SPEED_UNITS["km/h"], V.SPEED_UNITS["mph"]


# --- two numbers with a comma between, after a verb of going: a range, its middle --------------------------
@pytest.mark.parametrize(
    "text, mps",
    [
        ("We were doing maybe 40, 50 km/h on the bypass when a lorry pulled out in front of us.", 45 * KPH),
        ("I was going about 20, 25 mph when a kid on a bike shot out from the left.", 22.5 * MPH),
        ("I was travelling 30, 35 km/h through the village when a jogger stepped out in front of me.", 32.5 * KPH),
    ],
    ids=["doing-maybe", "going-about", "travelling"],
)
def test_two_numbers_with_a_comma_after_a_verb_of_going_are_a_range(text, mps):
    assert read(text).ego_speed_mps == pytest.approx(mps, abs=0.05)


@pytest.mark.parametrize(
    "text, mps",
    [
        ("I was doing 30, 40 m behind a bus, when a cyclist cut in front of me.", 30 * KPH),
        ("I was doing 40, 2 cars behind a truck, when a van cut in front of me.", 40 * KPH),
    ],
    ids=["then-a-distance", "then-a-count"],
)
def test_a_comma_after_a_speed_before_a_measure_or_a_count_is_no_range(text, mps):
    assert read(text).ego_speed_mps == pytest.approx(mps, abs=0.05)


def test_a_dash_range_still_reads_as_before():
    assert read("I was doing 30-35 km/h when a cyclist pulled out in front of me.").ego_speed_mps == pytest.approx(
        32.5 * KPH
    )


# --- "did <number>": the past of "doing <number>" --------------------------------------------------------
@pytest.mark.parametrize(
    "text, mps",
    [
        ("We did 40 along the main road until a cyclist swerved in front of us.", 40 * KPH),
        ("I did about 60 on the ring road, then a van cut in front of me.", 60 * KPH),
        ("Did 30 through the estate and a kid ran out in front of me.", 30 * KPH),
    ],
    ids=["along", "about-then", "subjectless"],
)
def test_did_and_a_bare_number_is_a_speed(text, mps):
    assert read(text).ego_speed_mps == pytest.approx(mps, abs=0.05)


@pytest.mark.parametrize(
    "text",
    [
        "I did 3 laps of the roundabout before a van cut in front of me.",
        "I did 20 years on the buses and a cyclist never cut in front of me like that.",
    ],
    ids=["laps", "years"],
)
def test_did_and_a_count_is_no_speed(text):
    kph = (read(text).ego_speed_mps or 0) / KPH
    assert round(kph) not in (3, 20)


# --- "at a <adjective> <adjective> <number>": a speed with two words before it ------------------------------
@pytest.mark.parametrize(
    "text, mps",
    [
        ("I was at a nice steady 50 on the bypass when a car pulled out in front of me.", 50 * KPH),
        ("We were cruising at a very sensible 80 when a van cut in front of us.", 80 * KPH),
        ("Doing a really gentle 20 past the school, I saw a boy run out in front of me.", 20 * KPH),
    ],
    ids=["nice-steady", "very-sensible", "doing-really-gentle"],
)
def test_a_speed_after_an_article_and_two_modifiers(text, mps):
    assert read(text).ego_speed_mps == pytest.approx(mps, abs=0.05)


def test_at_the_place_and_a_number_is_no_speed():
    kph = (read("I stopped at the old station 12 minutes before a van cut in front of me.").ego_speed_mps or 0) / KPH
    assert round(kph) != 12


# --- the A-road: a British road, whose bare speeds are in mph ----------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "On the A-road at about 50, a car pulled out in front of me.",
        "I was doing 50 on a quiet A-road when a tractor pulled out in front of me.",
    ],
    ids=["the-a-road", "a-quiet-a-road"],
)
def test_a_bare_speed_on_an_a_road_is_in_mph(text):
    assert read(text).ego_speed_mps == pytest.approx(50 * MPH)


def test_a_bare_speed_on_a_road_is_in_kmh():
    assert read(
        "I was on a road doing about 50 when a tractor pulled out in front of me."
    ).ego_speed_mps == pytest.approx(50 * KPH)


# --- a number in words after two modifiers, and "-ish" after a bare speed --------------------------------
@pytest.mark.parametrize(
    "text, mps",
    [
        ("We sat at a very calm eighty-five on the ring road when a van cut in front of us.", 85 * KPH),
        ("I was doing 30ish through the village when a jogger stepped out in front of me.", 30 * KPH),
        ("Did 40-ish along the main road until a cyclist swerved in front of me.", 40 * KPH),
    ],
    ids=["two-modifiers-in-words", "doing-ish", "did-ish"],
)
def test_a_hedged_or_described_bare_speed(text, mps):
    assert read(text).ego_speed_mps == pytest.approx(mps, abs=0.05)


def test_an_age_with_ish_is_no_speed():
    kph = (read("A 40ish man on a bike swerved in front of me.").ego_speed_mps or 0) / KPH
    assert round(kph) != 40
