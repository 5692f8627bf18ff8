"""A bare speed ("doing about 30", "at a steady forty") takes its unit from what the text shows: a speed
said with its unit anywhere in it first, then the English it is written in. Words only British
English uses ("two hundred quid", "a pelican crossing", "the bridleway") are said where speeds are
signed in miles per hour; a text
with none of them, or one set where km/h is signed, keeps km/h. Also: "I dunno" is a guess like "I
don't know" between a verb of going and its number, and heavy rain is no slow traffic on a motorway.

Every wording here is written for these tests (none is from a corpus); each reading has near misses
that look alike but must keep reading as before."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph
from vei_scenario.language.miles_english import said_in_miles_english
from vei_scenario.language.rules_backend import layers_from_text

MPH_KPH = 1.609344


def _ego_kph_layers(text: str) -> float:
    return float(layers_from_text(text, 0)["ego"]["speed_mps"]) * 3.6


@pytest.mark.parametrize(
    ("text", "mph"),
    [
        ("Cost me two hundred quid, that mirror. I was doing about 20 and the cyclist swerved into me.", 20),
        ("My light was green, I was doing maybe 15, and a man walked out onto the pelican crossing.", 15),
        ("Two riders came off the bridleway in front of me while I was doing 40, no lights at all.", 40),
    ],
)
def test_a_bare_speed_in_miles_english_is_in_mph(text, mph):
    assert _ego_kph_layers(text) == pytest.approx(mph * MPH_KPH, abs=0.3)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        # (a unit said in the text comes first, whatever English it is written in)
        ("I was doing 30 near the pavement cafe when a van overtook me at 50 km/h.", 30),
        ("A lorry doing 40 km/h pulled out of the yard; I was at about 60 and braked hard.", 60),
        # (no word of British or American English: km/h, as before)
        ("I was doing about 40 when a scooter came off the footpath on my left and crossed in front of me.", 40),
        ("Was doing maybe 50 on the main road when a truck pulled out of a side street on the left.", 50),
        # (set where km/h is signed: the ute says so before any lorry does)
        ("In the ute doing about 80 when a lorry pulled out of a side road on my left.", 80),
    ],
)
def test_a_stated_unit_or_no_miles_english_keeps_km_h(text, kph):
    assert _ego_kph_layers(text) == pytest.approx(kph, abs=0.3)


@pytest.mark.parametrize(
    "text",
    [
        "It cost fifty quid.",
        "They crossed at the pelican crossing.",
    ],
)
def test_the_words_of_miles_english(text):
    assert said_in_miles_english(text.lower().replace(".", " .").split())


@pytest.mark.parametrize(
    "text",
    [
        "A scooter rode along the footpath.",  # (Australian, New Zealand, Irish, Indian English)
        "The truck driver waved.",
        "A pelican flew over the road.",  # (a bird, no crossing)
        "The gardai closed the road and a lorry was towed.",  # (Irish: km/h is signed)
    ],
)
def test_not_the_words_of_miles_english(text):
    assert not said_in_miles_english(text.lower().replace(".", " .").split())


@pytest.mark.parametrize(
    "text",
    [
        "A bus pulled out in front of me, I was going, I dunno, 40, and I braked.",
        "We were doing, I dunno, forty, when a bus pulled out in front of us.",
    ],
)
def test_i_dunno_is_a_guess_before_the_speed(text):
    assert ego_kph(text) == pytest.approx(40, abs=0.2)


def test_i_dunno_before_a_count_is_no_speed():
    text = "I dunno, 3 cyclists were riding along ahead of me and I passed them at 30 km/h."
    assert ego_kph(text) == pytest.approx(30, abs=0.2)


def test_heavy_rain_is_no_slow_traffic_on_a_motorway():
    text = "On the motorway doing 70 in heavy rain when a car cut in right in front of me."
    assert _ego_kph_layers(text) == pytest.approx(70 * MPH_KPH, abs=0.3)


def test_heavy_traffic_on_a_motorway_leaves_the_unit_open():
    text = "On the motorway doing 70 in heavy traffic when a car cut in right in front of me."
    assert _ego_kph_layers(text) == pytest.approx(70, abs=0.3)


@pytest.mark.parametrize(
    "text",
    [
        "Lesson 4 of 6. A cyclist pulled out of a side road in front of us at 15 km/h.",
        "Session 2 of about 8 - a cyclist pulled out of a side road in front of us at 15 km/h.",
    ],
)
def test_the_total_a_series_is_counted_out_of_is_no_speed(text):
    assert _ego_kph_layers(text) > 20  # (not 6 or 8 km/h: the text gives the ego no speed)


def test_a_speed_of_a_number_is_still_a_speed():
    text = "We were going at a speed of about 40 when a cyclist pulled out of a side road in front of us."
    assert ego_kph(text) == pytest.approx(40, abs=0.2)


def test_a_limit_noted_without_its_article_is_the_roads_not_the_egos_speed():
    text = (
        "Driving log. Student: Sam K. Vehicle: #4 (Civic). Route: Elm St, 35 mph zone, traveling ~30. Notes: a "
        "scooter rider in the bike lane to our right veered into our lane. Student was slow to react."
    )
    assert _ego_kph_layers(text) == pytest.approx(30 * MPH_KPH, abs=0.3)
