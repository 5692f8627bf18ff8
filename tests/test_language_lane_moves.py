"""Road users on the ego's road (:mod:`vei_scenario.language.lane_moves`): a plain braking after a
cut-in is how the cut-in settles, a hard one a sudden stop; "slow" said as a pace is no slowing.
Wordings written for each construction, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _behaviours(text: str) -> list[list[str]]:
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi cut in front of me and braked.",
        "At 70 km/h on the motorway, a hatchback from the outside lane dived into the space ahead of us and braked.",
        "A pickup cut in with barely 5 m to spare, then braked.",
        "Ego at 90 km/h in lane 1; a coupe from lane 2 cuts in aggressively and brakes.",
    ],
)
def test_a_plain_braking_after_a_cut_in_is_how_it_settles(text):
    assert _behaviours(text) == [["cut_in"]]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi cut in front of me and braked sharply.",
        "A taxi cut in front of me and then braked hard.",
        "A taxi cut in front of me and slammed on the brakes.",
        "A taxi cut in front of me and braked to a stop.",
        "A taxi cut in front of me, then braked suddenly.",
    ],
)
def test_a_hard_braking_after_a_cut_in_is_a_sudden_stop(text):
    assert _behaviours(text) == [["cut_in", "sudden_stop"]]


def test_braking_by_someone_else_after_a_cut_in_is_not_the_cut_in():
    assert _behaviours("A taxi cut in. The bus ahead of me braked.")[1] == ["sudden_stop"]
    assert _behaviours("The lorry in front of me braked.") == [["sudden_stop"]]


@pytest.mark.parametrize(
    "text",
    [
        "I came up behind a tractor ahead of me going very slow.",
        "There was a moped ahead of me in my lane, really slow.",
        "The bus in front of me was driving slow.",
    ],
)
def test_slow_said_as_a_pace_is_no_slowing(text):
    assert "change_speed" not in _behaviours(text)[0]


@pytest.mark.parametrize(
    "text",
    [
        "The van ahead of me began to slow.",
        "The van ahead of me had to slow for a dog.",
    ],
)
def test_slow_as_a_verb_is_a_slowing(text):
    assert _behaviours(text) == [["change_speed"]]
