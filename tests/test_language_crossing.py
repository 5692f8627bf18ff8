"""A walker or rider whose way goes "over the road" or "to the other side" crosses the ego's road.

Wordings made up for the class in several registers (a chat message, a statement, a radio call, a
driving log); near misses that must keep their readings: a vehicle, "over" with another object,
the other side as where one is or swerves onto, and the ego's own move.
"""

from __future__ import annotations

import pytest

from tests.reading_of import acts


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("I was driving at 30 mph when an old man went over the road in front of me.", "pedestrian"),
        ("Doing about 25 and this lad on a bike rode straight over the road right in front of us.", "bicycle"),
        ("At about 40 km/h a woman walked over the street just ahead of my car and I braked.", "pedestrian"),
    ],
)
def test_a_plain_going_over_the_road_crosses(text: str, kind: str) -> None:
    """A verb of going with "over the road" as its way: the road is crossed."""
    assert acts(text)[0] == (kind, ["cross_in_front"])


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        (
            "A kid on a bike turned left across the road in front of me to get to his friends on the other side.",
            "bicycle",
        ),
        (
            "There was a lad on a scooter on the hard shoulder and then he just swings right out across the "
            "lanes to get to the garage on the other side. I had to stand on the brakes.",
            "e-scooter",
        ),
        ("Driving at 20 mph, a teenager on a scooter veered across to the other side in front of me.", "e-scooter"),
    ],
)
def test_a_move_to_the_other_side_crosses(text: str, kind: str) -> None:
    """A move made to reach the other side of the road, whatever its verb: a crossing, and the
    purpose's "get to" is no move of its own."""
    assert acts(text)[0] == (kind, ["cross_in_front"])


def test_the_turn_to_the_other_side_says_where_it_starts() -> None:
    """Turning right to go over to the other side, the rider starts on the left."""
    from vei_scenario.language.reader import read

    text = "A lad on a scooter on the verge swings right out across the road to get to the shop on the other side."
    (rider,) = read(text).actors
    assert rider.relation == "roadside_left"


@pytest.mark.parametrize(
    ("text", "first"),
    [
        ("A lorry went over the road in front of me.", ("truck", ["keep_going"])),  # (a vehicle drives on it)
        ("A cyclist went over the hill ahead of me.", ("bicycle", ["along_road"])),  # (over another thing)
        ("A man on a bike rode over the bridge ahead of me.", ("bicycle", ["along_road"])),
        (
            # (onto: the wrong side of the road)
            "A van came round the bend and swerved out onto the other side to miss a cyclist.",
            ("van", None),
        ),
    ],
)
def test_other_ways_keep_their_readings(text: str, first: tuple) -> None:
    """Not a crossing: a vehicle, "over" with another object, the other side swerved onto."""
    kind, names = first
    got = acts(text)[0]
    assert got[0] == kind
    assert "cross_in_front" not in got[1]
    if names is not None:
        assert got[1] == names


def test_a_walker_on_the_other_side_is_where_it_is() -> None:
    """ "On the other side" with no "to" before it says where someone is, not where a move goes."""
    text = "A woman was walking along the pavement on the other side of the road as I drove past."
    assert all("cross_in_front" not in names for _, names in acts(text))


def test_the_egos_move_to_the_other_side_is_no_crossing() -> None:
    """A move whose subject is the narrator is the ego's own."""
    text = "A cyclist was ahead of me, so I pulled out to the other side to give him room."
    assert all("cross_in_front" not in names for _, names in acts(text))
