"""Crossing told by where the move ends: a walker or rider whose plain move goes onto or over a foot
crossing crosses the road on it, and a rider who comes down a side road and out onto the main road
turns into it rather than running through the junction. Wordings made up for each construction, none
taken from a corpus; each group has near misses that must keep their old reading."""

from __future__ import annotations

import pytest

from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text


def _acts(text: str) -> list[tuple[str, str, list[str]]]:
    """Each adversary's type, spawn relation and behaviour names, as the layers write them."""
    layers = layers_from_text(text, 0)
    return [
        (a["type"], a["spawn"]["relation"], [n["behaviour"] for _, n in behaviour_nodes(a["behaviour"])])
        for a in layers["adversaries"]
    ]


def _one(text: str) -> tuple[str, str, list[str]]:
    (actor,) = _acts(text)
    return actor


# A plain move onto, over, into or across a foot crossing is the crossing: the place is made for it.
@pytest.mark.parametrize(
    "text",
    [
        "An old man walked onto the crosswalk as I came up to it at 20 mph.",
        "I was doing about 25 km/h when a teenager ran over the zebra in front of me.",
        "A woman with a pushchair went over the pelican crossing while I was driving at 30 km/h.",
        "A boy on a bike rode onto the pedestrian crossing just ahead of my car.",
        "Approaching the shops at 15 mph, a jogger walked straight onto the zebra crossing.",
    ],
)
def test_a_plain_move_onto_a_foot_crossing_crosses(text):
    _, relation, names = _one(text)
    assert names == ["cross_in_front"]
    assert relation.startswith("roadside_")


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist rode along the crosswalk ahead of me while I followed at 10 mph.",
        "A van drove over the zebra crossing in front of me at 20 mph.",
        "A man walked along the pavement past the zebra while I drove by at 20 mph.",
        "A woman was standing on the zebra waiting as I drove up at 15 mph.",
    ],
)
def test_a_move_beside_or_along_a_foot_crossing_is_no_crossing(text):
    assert all("cross_in_front" not in names for _, _, names in _acts(text))


# A rider or driver coming down a side road and out onto the main road turns into it.
@pytest.mark.parametrize(
    "text",
    [
        "A lad on an e-scooter came racing down a side road on my left and straight out onto the main road at 40 km/h.",
        "Doing 30 mph, I saw a cyclist come down the side road on my right and out onto the main road in front of me.",
        "A van came down a side street on the left and onto the main road just ahead of us while we drove at 25 mph.",
    ],
)
def test_down_a_side_road_and_onto_the_main_road_turns_into_it(text):
    _, relation, names = _one(text)
    assert names[0] == "turn_into"
    assert relation in ("junction_left", "junction_right")


@pytest.mark.parametrize(
    "text",
    [
        "At 30 mph a cyclist came down a side road on my left and straight across the junction.",
        "A car came down the side road on the right without stopping as I drove through at 40 km/h.",
        "I turned into the side road at 15 mph and a van came down it towards me.",
    ],
)
def test_down_a_side_road_without_the_main_road_keeps_its_reading(text):
    assert all("turn_into" not in names for _, _, names in _acts(text))
