"""The ego holding back behind a walker or rider and then passing it, told without naming the ego: the
walker or rider only goes along. Wordings written for the class in several registers (a lesson
diary, a text message, a test spec, a voice note, Nigerian and Singaporean English), none taken from
a corpus; near misses where the walker or rider passes someone itself keep their overtake."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph
from vei_scenario.language import held_pass
from vei_scenario.language.reader import read


def _moves(text: str) -> list[list[str]]:
    """The behaviours of each road user read from ``text``, by name."""
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


@pytest.mark.parametrize(
    "text",
    [
        "He was riding his bike along the edge of the road, so she held back and then overtook safely.",
        "Jogger running along the left edge of the road. Slowed, waited for a gap, then passed with plenty of room.",
        "On the hill a lad on a scooter was riding along the gutter; she slowed right down and only went past"
        " when the bend opened up.",
        "Woman jogging along the verge ahead. Eased off, followed for a bit, then overtook once clear.",
        "a guy on a bicycle was riding near the edge, he held back small then overtook when the road was free",
        "Got one cyclist riding along the side of road, we slow down first then overtake when can, no problem lah.",
        "Cyclist along the nearside kerb ahead. Held back, then passed when clear, good clearance.",
        "A kid on a bike was wobbling along by the kerb, so he held back and then passed once it was clear.",
        "Rider on an e-scooter along the gutter ahead. Held back behind, then overtook with a wide berth.",
    ],
)
def test_the_egos_hold_and_pass_leave_the_walker_or_rider_going_along(text: str) -> None:
    assert _moves(text) == [["along_road"]]


@pytest.mark.parametrize(
    ("text", "moves"),
    [
        # it passes someone: the writer said whom
        ("A cyclist riding along the kerb slowed and then overtook a parked van.", ["change_speed", "overtake"]),
        ("A cyclist riding along the kerb slowed and then overtook me.", ["change_speed", "overtake"]),
        # its own noun is the subject: the writer said whose the verbs are
        ("A cyclist was riding along the kerb. The cyclist slowed down, then the cyclist overtook.", None),
        ("A cyclist riding along the kerb slowed and then overtook.", None),
        ("Two cyclists were riding along the kerb; they slowed and then overtook.", None),
        # coming up from behind, it can slow and then pass the ego
        ("An e-scooter came up behind us, slowed, then overtook.", ["change_speed", "overtake"]),
    ],
)
def test_a_walker_or_rider_that_passes_someone_keeps_its_overtake(text: str, moves: list[str] | None) -> None:
    read_moves = _moves(text)[0]
    assert "overtake" in read_moves
    if moves is not None:
        assert read_moves == moves


def test_a_motor_vehicle_that_holds_back_then_passes_keeps_its_overtake() -> None:
    """A car that waits for a gap and then goes is an ordinary overtaker, not the ego."""
    assert "overtake" in _moves("A car behind a tractor; it held back, then overtook when the road was clear.")[0]


@pytest.mark.parametrize(
    ("after", "has"),
    [
        (["a", "van"], True),
        (["me", "."], True),
        (["past", "her"], True),
        (["the", "cyclist"], True),
        (["once", "clear"], False),
        ([",", "leaving"], False),
        (["when", "clear"], False),
        ([], False),
    ],
)
def test_whether_a_verb_of_passing_has_an_object(after: list[str], has: bool) -> None:
    assert held_pass._has_object(after, lambda w: "car" if w == "van" else None) is has


@pytest.mark.parametrize(
    ("text", "ego"),
    [
        ("Jogger along the left edge. Held back at 15 mph, then went past once clear.", 24.1),
        ("Cyclist on the nearside kerb ahead. Slowed, then overtook when clear at roughly 30 km/h.", 30.0),
    ],
)
def test_a_speed_said_with_the_egos_hold_and_pass_is_the_egos(text: str, ego: float) -> None:
    """A speed said from the holding back to the end of the pass's sentence is the ego's."""
    assert ego_kph(text) == ego
    assert read(text).actors[0].speed_mps is None


def test_the_riders_own_speed_said_before_stays_its_own() -> None:
    text = "A cyclist riding along the kerb at 15 km/h. She held back, then overtook."
    assert ego_kph(text) is None
    assert round(read(text).actors[0].speed_mps * 3.6) == 15
