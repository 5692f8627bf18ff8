"""A vehicle said in a lane beside the ego's that comes to be in front of the ego has cut in, whatever
its verb. Wordings written for the class in several registers (a British driver, an American text, a
test spec, a fleet log, a police line, an Indian and a Nigerian English report), none taken from a
corpus; near misses (a position said, no move) keep their reading."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _moves(text: str) -> list[list[str]]:
    """The behaviours of each road user read from ``text``."""
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("I was doing 60 km/h in the middle lane and a taxi in the left lane came in front of me.", "left"),
        ("Doing 40 on the M6 when a Range Rover from the right-hand lane shoved in front of me.", "right"),
        ("The ego drives at 90 km/h; a car from the right lane comes in front of the ego.", "right"),
        ("I'm doing 70 km/h; the bus from the left-hand lane muscled in ahead of us.", "left"),
        ("Ego at 100 kph in lane 2, a car from the left lane nipped in ahead of the ego.", "left"),
        ("I was in the right lane at 50 mph and a lorry in the left lane barged in front of me.", "left"),
        ("Was going 60 kmph only, one car in the right lane simply got in front of me, no indicator.", "right"),
        ("I dey drive for 50 km/h when one danfo from the left lane enter in front of me sharp sharp.", "left"),
    ],
)
def test_from_a_lane_beside_to_in_front_is_a_cut_in(text: str, side: str) -> None:
    r = read(text)
    assert [[b[0] for b in a.behaviours] for a in r.actors] == [["cut_in"]]
    assert r.actors[0].relation == side


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 60 km/h and a van in the right lane was ahead of me.",  # where it is, no move
        "I was doing 60 km/h and a van in the right lane stayed ahead of me.",
        "I was doing 60 km/h and a van in the right lane drove ahead of me.",  # going along there
        "I was doing 60 km/h and the van in the right lane, ahead of me, kept going.",
        "I was doing 60 km/h and the car in the right lane pulled ahead of me.",  # further along its lane
        "I was doing 60 km/h and the car in the right lane sped ahead of me.",
        "I was doing 60 km/h and the car in the right lane got ahead of me.",
        "Doing 60 km/h with a lorry in the left lane right in front of us, crawling.",  # how close, no move
        "We had a van in the next lane just in front of us the whole way at 50 km/h.",
    ],
)
def test_a_position_in_front_is_no_cut_in(text: str) -> None:
    assert "cut_in" not in {b for moves in _moves(text) for b in moves}


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 60 km/h and the car in the next lane came in front of me.",
        "Ego at 80 kph; a van from the adjacent lane gets in front of the ego.",
        "Cruising at 50 mph, a pickup out of the other lane barged in front of us.",
    ],
)
def test_from_the_lane_beside_side_unsaid_is_a_cut_in(text: str) -> None:
    assert _moves(text) == [["cut_in"]]


@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("We were doing 20 mph when a taxi on our right came in front of us.", "right"),
        ("I was doing 30 mph and a van on my left suddenly lurched right in front of me.", "left"),
        ("lol doing like 40 and this SUV on my right just squeezed in front of me no signal", "right"),
    ],
)
def test_from_beside_the_ego_to_in_front_is_a_cut_in(text: str, side: str) -> None:
    r = read(text)
    assert [[b[0] for b in a.behaviours] for a in r.actors] == [["cut_in"]]
    assert r.actors[0].relation == side


@pytest.mark.parametrize(
    "text",
    [
        "Driving at 50 km/h, a car from the right came in front of me at the junction.",  # comes from there
        "I was doing 30 mph and a car on my right was in front of me.",
    ],
)
def test_from_a_side_or_a_position_is_no_cut_in(text: str) -> None:
    assert "cut_in" not in {b for moves in _moves(text) for b in moves}


def test_a_position_in_the_next_lane_is_no_cut_in() -> None:
    assert _moves("I was doing 60 km/h and a car in the next lane was in front of me.") == [["keep_going"]]


def test_a_walker_has_no_lane_to_cut_in_from() -> None:
    moves = _moves("I was doing 30 mph and a man in the left lane walked in front of me.")
    assert "cut_in" not in {b for m in moves for b in m}
