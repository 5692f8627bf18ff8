"""Where a road user starts when its side is said of something else: a place beside the road said on
the nearside or offside ("out of a driveway on the offside"), and cover said to stand at a side of the
road that a walker or rider comes out from behind ("a van is parked on the left ... a boy runs out from
behind the van")."""

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def relation(text: str, kind: str | None = None) -> str | None:
    actors = read(text).actors
    return next(a.relation for a in actors if kind is None or a.kind == kind)


@pytest.mark.parametrize(
    "text, expected",
    [
        # miles per hour: the writer keeps left, so the offside is the right and the nearside the left
        ("I was doing 25 mph when a car pulled out of a driveway on my offside.", "roadside_right"),
        ("Doing 20 mph along the estate road. A van came out of a gateway on the offside without looking.",
         "roadside_right"),
        ("At 30 mph a pickup nosed out of the farm track on the nearside.", "roadside_left"),
        # kilometres an hour in a present-tense test line: the right-hand convention
        ("The ego drives at 40 km/h. A car pulls out of a parking space on the nearside.", "roadside_right"),
        # a side restated in brackets right after wins over the convention
        ("The ego drives at 40 km/h. A car pulls out of a driveway on the nearside (left).", "roadside_left"),
    ],
)  # fmt: skip
def test_a_place_on_a_kerb_side_is_that_roadside(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # guards: a plain side keeps reading as before, and so does a place said with no side
        ("I was doing 25 mph when a car pulled out of a driveway on my right.", "roadside_right"),
        ("I was doing 25 mph when a car pulled out of a driveway on the left.", "roadside_left"),
        ("I was doing 25 mph when a bus pulled out from the stop.", "roadside_left"),
        # the offside of a vehicle is a part of it, not the side of the place
        ("I was doing 25 mph when a car pulled out of a driveway and hit the offside of the van.", "roadside_left"),
    ],
)
def test_a_plain_side_or_none_keeps_its_reading(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("The ego drives at 40 km/h. A lorry is parked on the left side of the road. A boy runs out from behind "
         "the lorry.", "roadside_left"),
        ("I was doing 20 mph. There was a van parked on the right. A girl stepped out from behind the van.",
         "roadside_right"),
        ("Ego at 30 km/h on a residential street. A delivery van stands on the left. A kid on a scooter shoots "
         "out from behind the van.", "roadside_left"),
    ],
)  # fmt: skip
def test_who_comes_out_from_behind_placed_cover_starts_at_its_side(text, expected):
    walker = next(a for a in read(text).actors if a.kind in ("pedestrian", "e-scooter"))
    assert walker.relation == expected


def test_the_cover_side_holds_on_every_seed():
    text = "The ego drives at 40 km/h. A lorry is parked on the left side of the road. A boy runs out from behind it."
    for seed in (0, 1, 2):
        walker = next(a for a in layers_from_text(text, seed)["adversaries"] if a["type"] == "pedestrian")
        assert walker["spawn"]["relation"] == "roadside_left"


@pytest.mark.parametrize(
    "text, expected",
    [
        # guards: a side said of the walker itself wins over its cover's
        ("I was doing 20 mph. A van was parked on the right. A girl on my left stepped out from behind the van.",
         "roadside_left"),
        # "from behind me" is the ego's rear: the overtaker stays behind
        ("I was doing 30 mph when a car came from behind me and overtook.", "behind"),
        # a rider on my left who crosses to the right starts on the left
        ("I was doing 20 mph and the scooter on my left crossed to the right.", "roadside_left"),
    ],
)  # fmt: skip
def test_near_misses_keep_their_start(text, expected):
    walker = next(a for a in read(text).actors if a.kind != "van")
    assert walker.relation == expected
