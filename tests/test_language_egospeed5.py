"""Whose speed a number is, and which number a run of number words says.

A speed after a road user's name, past a hedge only ("ego ~50 km/h", "cyclist approx. 15 km/h"), is
that road user's, as one right after the name is ("ego 50 km/h"). A speed said "at" after a noun of
the moment of contact ("contact at 3 km/h", "impact at 20 km/h") once the ego has braked is what was
left at impact, as one after a verb of striking is: no speed the ego drives at. "est." before a number
is "estimated" cut short, and ends no sentence.

Numbers in words said one after another that make no one number:

English builds one number from its words by a rule: a tens word, then a unit ("forty-five"); hundreds,
then tens and units ("a hundred and ten"). A word that cannot go on the number before it starts a new
one, so "fifteen sixteen" or "forty forty-five" is two numbers: a speaker's range with its "to" left
out ("doing forty forty-five": 40 to 45), read as "doing 40-45" is; a number said twice ("thirty -
thirty") is that number; two numbers that make no range ("six thirty", "five fifteen": a time) are no
speed. Before, the words were summed (85, 31, 36).

The guards keep one number in words read as it was ("twenty five", "a hundred and ten").
"""

from __future__ import annotations

import pytest
from reading_of import ego_kph

from vei_scenario.language.normalise import _number_value, _numbers_in_words, _numbers_said
from vei_scenario.language.reader import read

MPH = 1.609344


@pytest.mark.parametrize(
    ("words", "numbers"),
    [
        ("forty-five", [45]),
        ("twenty five", [25]),
        ("a hundred and ten", [110]),
        ("one hundred twenty", [120]),
        ("two hundred and fifty", [250]),
        ("fifteen hundred", [1500]),
        ("a hundred and fifteen", [115]),
        ("fifteen sixteen", [15, 16]),
        ("forty forty five", [40, 45]),
        ("twenty five thirty", [25, 30]),
        ("six thirty", [6, 30]),
        ("nine nine nine", [9, 9, 9]),
    ],
)
def test_numbers_said_by_the_rule_of_english_numbers(words, numbers):
    assert _numbers_said(words) == numbers


def test_a_run_of_numbers_has_no_one_value():
    assert _number_value("fifteen sixteen") is None
    assert _number_value("seventy five") == 75


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("doing sixteen seventeen miles an hour", "doing 16-17 miles an hour"),
        ("going like twenty twenty-five when", "going like 20-25 when"),
        ("at about fifty sixty and", "at about 50-60 and"),
        ("doing about forty - forty kilometres an hour", "doing about 40 kilometres an hour"),
        ("three four metres ahead", "3-4 metres ahead"),
    ],
)
def test_a_range_without_its_to_is_a_range(text, said):
    assert _numbers_in_words(text) == said


@pytest.mark.parametrize(
    "text",
    [
        "at about six thirty in the morning",  # (a time: no range)
        "like five fifteen pm",
        "I rang nine nine nine.",
    ],
)
def test_numbers_that_make_no_range_are_left_as_words(text):
    assert _numbers_in_words(text) == text


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        (
            "I was doing sixteen seventeen mile an hour when a van pulled out of a side road in front of me.",
            round(16.5 * MPH, 1),
        ),
        ("We were doing like fifty fifty-five km/h on the main road and a car pulled out in front of us.", 52.5),
        ("I was doing about thirty - thirty kilometres an hour when a cyclist came out of a side road.", 30.0),
    ],
)
def test_the_egos_speed_said_as_a_range_of_words(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.1)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("I was doing twenty five mph when a van pulled out in front of me.", round(25 * MPH, 1)),
        ("Ego at a hundred and ten km/h on the motorway, a truck cuts in ahead of it.", 110.0),
        ("I was doing forty-five km/h when a cyclist came out of a side road.", 45.0),
    ],
)
def test_one_number_in_words_reads_as_before(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.1)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("Ego ~60 km/h, closes on a cyclist at ~25 km/h on a rural road.", 60.0),
        ("Ego approx. 60 km/h, catches up with a tractor at 25 km/h.", 60.0),
        ("ego about 60 km/h, then overtakes a cyclist doing 25 km/h", 60.0),
    ],
)
def test_a_hedged_speed_after_the_egos_name_is_the_egos(text, kph):
    assert ego_kph(text) == pytest.approx(kph)


def test_a_hedged_speed_after_a_road_users_name_stays_its_own():
    text = "The ego drives at 40 km/h. A cyclist approx. 18 km/h rides ahead of it in the lane."
    assert ego_kph(text) == pytest.approx(40.0)
    assert [round(a.speed_mps * 3.6) for a in read(text).actors] == [18]


@pytest.mark.parametrize(
    "text",
    [
        "The ego follows a van at 70 km/h. The van swerves out, revealing a stopped car. "
        "Ego brakes hard, contact at 5 km/h.",
        "I was behind a bus at 30 mph when it moved out; a parked lorry in front. I braked hard, impact at 4 mph.",
    ],
)
def test_the_speed_of_the_contact_after_braking_is_not_the_egos(text):
    kph = ego_kph(text)
    assert kph is not None and kph >= 40


def test_a_speed_of_the_ego_said_at_the_start_still_holds_without_braking():
    assert ego_kph("Ego at 60 km/h, a van pulls out of a side road on the right ahead.") == pytest.approx(60.0)


def test_est_cut_short_ends_no_sentence():
    """ "est." is "estimated" cut short: the number after it is said in the same sentence, so a road user's
    speed after it stays the road user's, and the ego said to stand keeps standing."""
    text = "Our lorry was stopped at the kerb. A cyclist came up the inside at an est. 18 mph and hit the mirror."
    assert ego_kph(text) == 0.0
    assert ego_kph("Ego northbound on Mill Lane, est. 40 km/h. A cyclist crosses from the right.") == 40.0


def test_a_full_stop_after_other_words_still_ends_the_sentence():
    assert ego_kph("I was heading west. 20 minutes later a van pulled out in front of me at 30 mph.") != 20.0


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("I slowed from 50 mph to 15 mph and the lorry behind me ran into my rear.", round(50 * MPH, 1)),
        (
            "The test car braked from about 60 mph (97 km/h) to around 25 mph (40 km/h); a van behind it hit it.",
            round(60 * MPH, 1),
        ),
    ],
)
def test_a_change_from_one_speed_to_another_starts_at_the_first(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.6)


def test_a_speed_after_from_a_place_is_no_change_of_speed():
    assert ego_kph("I drove away from the lights at 20 mph when a cyclist came past me.") == pytest.approx(32.2)
