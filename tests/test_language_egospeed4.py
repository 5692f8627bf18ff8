"""The unit of a bare speed a narrator gives in the words of British (or American) roads.

A driver who tells their own drive with a lorry, a pavement, a wing mirror or a limit called by a British town
limit ("a 20 limit") reads their speedometer in mph. Words every English of km/h shares ("kerb", "car park"),
a zone ("a 30 zone"), a stated unit, a text set in Ireland, and a text not told in the first person
keep km/h. Every wording here is written for these tests (none is from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.miles_english import told_in_miles_english
from vei_scenario.language.reader import read

MPH = 0.44704
KPH = 1 / 3.6


def _ego(text: str) -> float | None:
    return read(text).ego_speed_mps


@pytest.mark.parametrize(
    "text, mph",
    [
        ("I was doing about 20 when a kid stepped off the pavement right in front of me.", 20),
        ("I was doing about 30 when a lorry pulled out of a side road on my left.", 30),
        ("I was doing about 40 when a van coming the other way clipped my wing mirror.", 40),
        ("It's a 20 limit on our street and I was doing 20 when a cyclist pulled out from the left.", 20),
    ],
    ids=["pavement", "lorry", "wing-mirror", "bare-limit"],
)
def test_a_narrators_bare_speed_in_british_road_words_is_mph(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH, abs=0.05)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("The ego drives at 50 when a lorry cuts in from the left.", 50),
        ("I was doing 50 when a cyclist came off the kerb on my left.", 50),
        ("It's a 30 zone and I was doing 30 when a kid ran out from the right.", 30),
        ("I was doing 50 km/h when a lorry pulled out on my left.", 50),
        ("I was doing 50 when a lorry pulled out on my left. The gardai came and took details.", 50),
        ("We were only doing fifteen through the car park when a car reversed out of a bay on our right.", 15),
    ],
    ids=["not-first-person", "kerb-is-commonwealth", "zone", "unit-stated", "ireland", "car-park"],
)
def test_near_misses_keep_km_h(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, abs=0.05)


@pytest.mark.parametrize(
    "words, said",
    [
        ("a 20 limit here".split(), True),
        ("the national speed limit".split(), True),
        ("the thirty limit".split(), True),
        ("the forty limit".split(), True),
        ("the 50 km h limit".split(), False),
        ("a 30 zone".split(), False),
        ("the speed limit".split(), False),
        ("the lorry and the gardai".split(), False),
    ],
)
def test_told_in_miles_english(words, said):
    assert told_in_miles_english(words) is said
