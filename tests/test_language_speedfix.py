"""Two readings of a bare number that the last round widened, narrowed again (review findings 24-25).

- An age is no road called by its limit: "the driver was a 30, 35 year old woman" says how old she is,
  and a bare speed in the text keeps km/h; "the road was a 30" and "it's a twenty" still call a road
  by its limit, and a bare speed there is mph.
- A number right after a verb of going is a speed, even with a part of the day said before it ("At
  lunchtime, doing about 12 through the car park"); an hour after "about"/"around" with no verb of
  going before it is still a time ("Tonight around 10", "At lunchtime, about 12,").

Every wording here is written for these tests (the first of each group is the review's)."""

from __future__ import annotations

import pytest

from vei_scenario.language import miles_english, quantities
from vei_scenario.language.rules_backend import layers_from_text

MPH_KPH = 1.609344


def _ego_kph(text: str) -> float:
    return float(layers_from_text(text, 0)["ego"]["speed_mps"]) * 3.6


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("The rider was a twenty, maybe twenty-two year old bloke; I was doing 60 when he cut in 10 m ahead.", 60),
        ("The driver was a 30, 35 year old woman in a hatchback; I was doing 50 when she pulled out 10 m ahead.", 50),
        ("The cyclist was a 20, 25 year old lad, and I was doing 40 when he swerved out 10 m ahead of me.", 40),
        ("The lad on the bike was a twenty year old student; I was doing 60 when he cut in 10 m ahead.", 60),
    ],
)
def test_an_age_is_no_road_called_by_its_limit(text, kph):
    assert _ego_kph(text) == pytest.approx(kph, abs=0.3)


@pytest.mark.parametrize(
    ("text", "mph"),
    [
        # (the guards: a road said to be a 30 or a twenty, no age after it, is still the town road)
        ("The road was a 30, and I was doing 40 when a cyclist pulled out 10 m ahead.", 40),
        ("We came round by the shops, it's a twenty, and I was doing twenty when a boy ran out in front of me.", 20),
        ("I was doing 40 in a 30, fair enough, when a cyclist came the other way.", 40),
    ],
)
def test_a_road_called_by_its_limit_as_before(text, mph):
    assert _ego_kph(text) == pytest.approx(mph * MPH_KPH, abs=0.3)


def test_road_called_by_its_limit_reads_an_age_as_none():
    assert not miles_english.road_called_by_its_limit("the driver was a 30 , 35 year old woman".split())
    assert not miles_english.road_called_by_its_limit("he was a twenty , maybe twenty-two year old bloke".split())
    assert miles_english.road_called_by_its_limit("the road was a 30 , and i was doing 40".split())


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("At lunchtime, doing about 12 through the car park, a car reversed out 5 m ahead of me.", 12),
        ("Around sundown, going just 10 in the lane, a tractor pulled out 20 m ahead of me.", 10),
        ("At nightfall, driving about 8 down the lane, a deer ran out 10 m ahead of me.", 8),
        (
            "This morning I was doing about 9 through the car park when a car reversed out 5 m ahead of me.",
            9,
        ),
    ],
)
def test_a_number_right_after_a_verb_of_going_is_a_speed_beside_a_part_of_the_day(text, kph):
    # (a "car park" is said where km/h is signed too: the bare speed stays km/h)
    assert _ego_kph(text) == pytest.approx(kph, abs=0.3)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        # (the guards: no verb of going before the hour, a time as before)
        ("Tonight around 10 I was doing 40 km/h when a kid ran out from the footpath.", 40),
        ("At lunchtime, about 12, I was doing 30 km/h when a car reversed out 5 m ahead of me.", 30),
        ("Weds arvo about 3, busy road. Our sweeper was doing 30 km/h when a kid ran out from the footpath.", 30),
    ],
)
def test_an_hour_beside_a_part_of_the_day_still_a_time(text, kph):
    assert _ego_kph(text) == pytest.approx(kph, abs=0.3)


def test_clock_hour_reads_the_verb_before_the_number():
    assert not quantities.clock_hour("at lunchtime , doing about 12 through".split(), 5)
    assert not quantities.clock_hour("around sundown , going just 10 in".split(), 5)
    assert quantities.clock_hour("tonight around 10 i was".split(), 2)
    assert quantities.clock_hour("at lunchtime , about 12 ,".split(), 4)
