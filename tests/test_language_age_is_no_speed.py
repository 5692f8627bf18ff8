"""A person's age said after them ("a boy aged about 8", "a lad of 15") says who they are: it is no
speed of theirs or the ego's, as "about 8" alone would be read."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    "text",
    [
        "A boy aged about 8 ran out from between the parked cars in front of me.",
        "A girl, age 12, stepped off the kerb without looking.",
        "A boy of about 8 chased a ball into the road ahead of us.",
        "Two lads aged 14-15 on one e-scooter came off the pavement in front of the van.",
        "A kid of maybe twelve on an e-scooter pulled out of the cycle lane in front of me.",
        "An elderly man of 80 or so walked out onto the zebra.",
    ],
)
def test_an_age_after_a_person_is_no_speed(text):
    reading = read(text)
    assert reading.ego_speed_mps is None
    assert all(a.speed_mps in (None, 0.0) for a in reading.actors)  # (parked cars stand)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("I was doing about 30 when a man of 70 stepped out in front of me.", 30),
        ("A cyclist of about 20 km/h passed me.", None),  # (no person noun: a speed, the cyclist's)
    ],
)
def test_speeds_said_beside_an_age_stay(text, kph):
    reading = read(text)
    if kph is not None:
        assert reading.ego_speed_mps == pytest.approx(kph / 3.6, abs=0.5)
    else:
        assert reading.actors[0].speed_mps == pytest.approx(20 / 3.6, abs=0.1)


def test_a_height_is_no_age():
    reading = read("A man of 1.8 m height stepped out from the left in front of me.")
    assert reading.actors[0].distance_m in (None, 1.8)
    assert reading.actors[0].relation == "roadside_left"
