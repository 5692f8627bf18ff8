"""A walker or rider said on a side of a road with one lane each way starts at that side's edge (the
kerb), not in a lane beside the ego's, which such a road does not have. Wordings written for the class
in several registers (a British driver, an American post, an Australian voice note, a test spec, a
rural report), none taken from a corpus; near misses that look alike keep their lane. And a side said
from a named vehicle ("from the Civic's right") is where the one coming from it starts."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _starts(text: str) -> list[tuple[str, str | None]]:
    """Each road user's kind and start as read from ``text``."""
    return [(a.kind, a.relation) for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "kind", "start"),
    [
        (
            "Two-lane road, one lane in each direction, I'm doing 35 mph and a guy on a bike on my right"
            " swerves into my lane.",
            "bicycle",
            "roadside_right",
        ),
        (
            "Single lane each way, sitting on 60 k's, and a bloke on an e-scooter on my left cuts in right in"
            " front of me.",
            "e-scooter",
            "roadside_left",
        ),
        (
            "Road: 1 lane per direction. Ego 50 km/h. E-scooter rider on the ego's left cuts into the ego's lane.",
            "e-scooter",
            "roadside_left",
        ),
        (
            "B-road, one lane each way, I was doing 40 mph when a cyclist on my left wobbled out in front of me.",
            "bicycle",
            "roadside_left",
        ),
        (
            "Country road with one lane each way, 30 mph, a pedestrian on my right stepped out in front of me.",
            "pedestrian",
            "roadside_right",
        ),
    ],
)
def test_a_walker_or_rider_beside_the_ego_on_a_one_lane_road_is_at_the_edge(text, kind, start):
    assert _starts(text) == [(kind, start)]


@pytest.mark.parametrize(
    ("text", "kind", "start"),
    [
        # two lanes each way: the lane beside is there
        (
            "Two lanes per direction, ego 50 km/h, an e-scooter rider in the left lane cuts in front of the ego.",
            "e-scooter",
            "left",
        ),
        # a vehicle beside the ego on a one-lane road keeps its lane (it passes through the other one)
        ("One lane each way, 40 mph, a car on my left pulled out in front of me.", "car", "left"),
        ("One lane each way, 40 mph, a motorbike on my right overtook me and cut in.", "car", "right"),
    ],
)
def test_a_lane_beside_that_may_be_there_is_kept(text, kind, start):
    assert _starts(text) == [(kind, start)]


def test_lanes_not_said_keep_the_lane():
    assert _starts("Ego 50 km/h. An e-scooter rider in the lane on the ego's left cuts in front of the ego.") == [
        ("e-scooter", "left")
    ]


@pytest.mark.parametrize(
    ("text", "kind", "start"),
    [
        (
            "It had been green for the bus for a while when a van from the bus's left went through on red.",
            "van",
            "junction_left",
        ),
        (
            "Green light for the Prius, and a cyclist shot through the red from the Prius's right.",
            "bicycle",
            "junction_right",
        ),
        (
            "The lights were green for the grey Corolla when a lorry approaching from the Corolla's left drove"
            " through the red light.",
            "truck",
            "junction_left",
        ),
        (
            "The signal was green for the Civic when a pickup coming from the Civic's right ran the red light.",
            "van",
            "junction_right",
        ),
        (
            "V1 was proceeding through the crossroads at 30 mph on a green light when V2 came from V1's right"
            " and went through the red light.",
            "car",
            "junction_right",
        ),
    ],
)
def test_from_a_named_vehicles_side_is_where_the_subject_comes_from(text, kind, start):
    """ "From the Civic's right": the side is the one coming from it, seen from the Civic (here the
    ego said by name), not the Civic's own place."""
    assert _starts(text) == [(kind, start)]


def test_on_a_named_vehicles_side_keeps_the_owner():
    """ "On the lorry's left" is a place beside the lorry, which is a road user of its own."""
    assert [k for k, _ in _starts("A cyclist rode along on the lorry's left and I was doing 30 mph behind them.")] == [
        "bicycle",
        "truck",
    ]
