"""A change of speed "from X to Y" is read by its verb.

A slowing ("slowed", "braked", "dropped", "eased off from 55 mph to 20 mph") starts at X: the speed it
had, then the one it slows to. A speeding up ("accelerated", "sped up", "picked up", "built up from 20
mph to 40 mph") reaches Y, the speed it has when what follows happens. Where the verb says neither
("went from", "drove from", "changed from"), the numbers say which: a fall is a slowing, a rise a
speeding up.
"""

from __future__ import annotations

import pytest
from reading_of import ego_kph

from vei_scenario.language.reader import read

MPH = 1.609344


@pytest.mark.parametrize(
    ("text", "mph"),
    [
        ("I accelerated from 20 mph to 40 mph and a dog ran out.", 40),
        ("I sped up from 5 mph to 50 mph, then a van pulled out.", 50),
        ("I drove from 5 mph to 50 mph in ten seconds, then a van pulled out.", 50),
        ("I picked up speed from 30 mph to 45 mph when a cyclist swerved in front of me.", 45),
        ("I was speeding up from about 30 mph (48 km/h) to 50 mph (80 km/h) when a deer jumped out.", 50),
        ("I braked at the lights, then accelerated from 10 mph to 30 mph and a van cut in.", 30),
    ],
)
def test_a_speeding_up_reaches_the_second_speed(text, mph):
    assert ego_kph(text) == pytest.approx(mph * MPH, abs=0.6)


@pytest.mark.parametrize(
    ("text", "mph"),
    [
        ("I slowed from 50 mph to 15 mph and the lorry behind me ran into my rear.", 50),
        ("The test car braked from about 60 mph (97 km/h) to around 25 mph (40 km/h); a van behind it hit it.", 60),
        ("I eased off from 50 mph to 30 mph when a pedestrian stepped out.", 50),
        ("My speed dropped from 45 mph to 20 mph as a van cut in.", 45),
        ("I went from 60 mph to 20 mph when a van cut in front of me.", 60),
        ("The speed limit changed from 60 mph to 40 mph and a van cut in.", 60),
    ],
)
def test_a_slowing_starts_at_the_first_speed(text, mph):
    assert ego_kph(text) == pytest.approx(mph * MPH, abs=0.6)


def test_an_overtaker_that_sped_up_passes_at_the_speed_it_reached():
    r = read("A car behind went from 30 mph to 70 mph and overtook me.")
    (car,) = r.actors
    assert car.speed_mps * 3.6 == pytest.approx(70 * MPH, abs=0.6)
    assert car.speed_mps > (r.ego_speed_mps or 0.0)


def test_a_road_user_ahead_that_accelerates_reaches_the_second_speed():
    r = read("The van in front accelerated from 20 mph to 40 mph and pulled away.")
    assert [a.speed_mps * 3.6 for a in r.actors] == [pytest.approx(40 * MPH, abs=0.6)]


def test_a_road_user_that_slows_starts_at_the_first_speed():
    r = read("I was doing 60 mph, the lorry ahead slowed from 60 mph to 20 mph.")
    assert [a.speed_mps * 3.6 for a in r.actors] == [pytest.approx(60 * MPH, abs=0.6)]


def test_a_speed_after_from_a_place_is_no_change_of_speed():
    assert ego_kph("I drove away from the lights at 20 mph when a cyclist came past me.") == pytest.approx(32.2)
