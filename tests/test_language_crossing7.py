"""A walker or rider said to pass close by the front of the ego goes across its path, not along it.

"Passed a couple of feet in front of my bonnet", "passes inches from her bumper", "went past across the
front of my car": how near it came may stand between the verb and where it passed, and where it passed
may be the ego's front (its bumper, bonnet, nose) rather than "in front of" the ego. Either way the
verb has no object of its own: it passes across where the ego is heading. A crossing said again so is
the one crossing. Wordings made up for each construction; near misses keep their old reading: a pass
with an object, one that comes up from behind, one whose "in front" belongs to another verb, and a
pass in front of someone other than the ego.
"""

from __future__ import annotations

import pytest

from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text


def _moves(text: str) -> list[list[str]]:
    """The behaviours of each adversary in the layers of ``text`` (seed 0), by name."""
    layers = layers_from_text(text, 0)
    return [[n["behaviour"] for _, n in behaviour_nodes(a["behaviour"])] for a in layers["adversaries"]]


@pytest.mark.parametrize(
    "text",
    [
        "An e-scooter rider came out of the car park on the right. The rider passed inches from my bumper.",
        "Doing 40 km/h on the high street when a lad on a scooter passed about 2 m in front of my bonnet.",
        "I was driving at 30 km/h and a jogger passed a couple of feet in front of my car, I had to brake.",
        "Driving at 40 km/h, I saw a cyclist pass just across the front of my car from the left.",
        "At 25 mph a woman with a pushchair passed maybe 3 feet past my bonnet.",
    ],
)
def test_a_pass_close_by_the_egos_front_is_a_crossing(text):
    (moves,) = _moves(text)
    assert moves == ["cross_in_front"]


def test_a_rider_out_of_a_side_road_who_then_passes_the_egos_front_does_not_overtake():
    text = "A girl on a bike came out of a side road on my left. She passed inches from my bumper as I braked."
    (moves,) = _moves(text)
    assert "overtake" not in moves
    assert moves[0] in ("turn_into", "cross_in_front")


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30 mph when a cyclist came up behind me and passed me on the right.",  # (an object: me)
        "A cyclist overtook me at 25 km/h and pulled in in front of me.",  # ("in front" is the pull-in's)
        "A cyclist on the left passed a parked van about 2 m in front of me.",  # (an object: the van)
    ],
)
def test_a_pass_of_someone_stays_an_overtake(text):
    moves = _moves(text)
    assert "overtake" in moves[0]
    assert "cross_in_front" not in moves[0]


def test_a_pass_in_front_of_someone_else_is_no_crossing_of_the_ego():
    text = "I was waiting at the lights when a cyclist passed about 2 m in front of the bus ahead of me."
    assert all("cross_in_front" not in moves for moves in _moves(text))
