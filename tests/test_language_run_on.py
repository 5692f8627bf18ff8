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
