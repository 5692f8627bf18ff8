"""A text run on without its stops: a road user named right after the narrator's speed, or the narrator
right after an object pronoun, opens a clause of its own. Wordings written for the construction, none
taken from a corpus, with near misses where the words after the speed belong to the narrator's clause."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _moves(text: str) -> list[list[str]]:
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "move"),
    [
        ("I was doing 20 mph a cyclist pulled out in front of me", "cut_in"),
        ("we were at 40 km/h a deer jumped out in front of us", "cross_in_front"),
        ("doing 25 mph down the high street the bus ahead stopped suddenly", "sudden_stop"),
        ("coming along at 30 mph little lad on a bike shot out into the road", "cross_in_front"),
    ],
)
def test_a_road_user_right_after_the_narrators_speed_opens_its_clause(text, move):
    assert move in _moves(text)[0]


@pytest.mark.parametrize(
    ("text", "moves"),
    [
        ("I was doing 20 mph behind a bus that stopped suddenly", ["sudden_stop"]),
        ("I was overtaken by a 60 mph car on the bypass", ["overtake"]),
        ("I was doing 20 mph in a 30 zone when a van pulled out", ["cut_in"]),
    ],
)
def test_a_road_user_tied_to_the_speed_stays_in_the_clause(text, moves):
    assert _moves(text)[0] == moves


def test_the_narrator_after_an_object_pronoun_opens_its_clause():
    text = "I was doing 20 mph, a kid on a bike shot out in front of me I hit the horn and stopped dead."
    assert _moves(text) == [["cross_in_front"]]


def test_the_narrator_after_a_noun_stays_in_its_relative_clause():
    assert _moves("The cyclist we were following at 20 km/h braked hard.")[0] == ["sudden_stop"]


@pytest.mark.parametrize(
    ("text", "move"),
    [
        # the narrator's speed as a bare number, then a road user's clause with no comma between
        ("While I was at 30 a car cut in front of me", "cut_in"),
        ("When I was doing 40 a van pulled out of a side road on my left", "turn_into"),
        ("as we were going about 25 a taxi came out of a side street on the right", "turn_into"),
        ("was only doing 20 the bus in front stopped dead", "sudden_stop"),
        ("I'm doing 50 this lorry from the left lane swerves into my lane", "cut_in"),
        ("Driving along at 35 some kid on a bike came off the pavement on my left into the road", "cross_in_front"),
    ],
)
def test_a_road_user_right_after_a_bare_speed_opens_its_clause(text, move):
    assert move in _moves(text)[0]


@pytest.mark.parametrize(
    ("text", "moves"),
    [
        # a number that is part of the road user's own phrase, or no road user after it
        ("I was doing 30 the whole way when a van pulled out of a side road on my left", ["turn_into"]),
        ("At 30 km/h a cyclist in front of us braked hard", ["sudden_stop"]),
    ],
)
def test_a_bare_number_with_no_road_user_after_it_breaks_nothing(text, moves):
    assert _moves(text)[0] == moves
