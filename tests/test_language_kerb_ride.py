"""A walker or rider going along the edge of the ego's road who then moves out of it: along_road first,
then into the ego's lane (cut_in) or across it (cross_in_front). Wordings written for the class in
several registers (a text, a police note, a test spec, a learner's English), none taken from a
corpus; near misses that look alike must keep their one act."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _one(text: str):
    (actor,) = read(text).actors
    return actor


def _names(text: str) -> list[str]:
    return [b[0] for b in _one(text).behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist was riding along the kerb ahead of me at 30 km/h. Suddenly he swerved into my lane.",
        "Test spec: ego 40 km/h. Bicycle rides along the right kerb 30 m ahead, then moves over into the ego lane.",
        "lad on a bike cycling along the gutter in front of us, then he just pulled out into our lane, i was at 25mph",
        "An e-scooter rider was going along the side of the road ahead of my car and then veered into my lane. 20 mph.",
        "Ego 50 km/h. A cyclist travelling along the nearside kerb ahead, same direction, then cuts into ego's lane.",
    ],
)
def test_going_along_the_edge_then_into_the_lane_is_along_then_cut_in(text):
    actor = _one(text)
    assert [b[0] for b in actor.behaviours] == ["along_road", "cut_in"]
    assert actor.relation == "ahead" and actor.lateral_m is not None and actor.facing is None


@pytest.mark.parametrize(
    "text",
    [
        "A man was walking along the roadside on the left, same direction as us. Then he crossed the road. 30 mph.",
        "Ego 35 km/h. An e-scooter rides along the left kerb ahead, then swerves right across the ego's lane.",
        "Cyclist riding along the left edge of the road ahead of me then cut across to the other side. 40 km/h.",
        "The pedestrian was walking along the left kerb same direction as the vehicle, then he crossed. 30 mph.",
        "One boy cycling along the left edge in front of my car, then he cut across to the right to enter a shop.",
    ],
)
def test_going_along_the_edge_then_across_is_along_then_cross(text):
    actor = _one(text)
    assert [b[0] for b in actor.behaviours] == ["along_road", "cross_in_front"]
    assert actor.relation == "ahead" and actor.facing is None


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist is riding along the kerb ahead of me. I am at 40 km/h.",  # (only along)
        "A pedestrian stepped off the kerb in front of me and crossed. I was doing 30 mph.",  # (from the kerb)
        "A woman walking along the pavement stepped out into the road in front of me at 20 mph.",  # (pavement)
        "A cyclist came off the kerb on my left and across the road ahead of me. 25 mph.",  # (off it)
        "A child ran across the road from the left kerb, 15 m ahead of the ego at 30 km/h.",  # (across, no along)
    ],
)
def test_no_going_along_before_the_move_keeps_one_act(text):
    assert "along_road" not in _names(text)[1:] and len(_names(text)) == 1


def test_along_the_road_then_a_stop_is_no_move_out():
    """A stop between going along and crossing starts the crossing from where it stopped."""
    names = _names("A pedestrian walked along the kerb ahead, stopped, and then crossed the road. Ego 30 km/h.")
    assert names[-1] == "cross_in_front" and names[:1] != ["along_road"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego 40 km/h. A cyclist rides in the bike lane on our right, same direction, then swerves into our lane.",
        "Two cyclists riding along the kerb ahead; one pulls out to overtake the other, right into my path. 30 mph.",
    ],
)
def test_from_a_lane_of_its_own_or_out_to_overtake_is_not_along_first(text):
    assert read(text).actors[-1].behaviours[0][0] != "along_road"


def test_along_the_right_edge_then_across_crosses_from_that_kerb():
    """From the right edge the layers cannot yet cross the ego's lane to its left: a crossing from
    the kerb, as before."""
    names = _names("A jogger runs along the road in the ego's direction and then crosses to the left side.")
    assert names == ["cross_in_front"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego 30 km/h. An e-scooter rides along the left kerb ahead, then swerves out across the road.",
        "kid on a bike going along the left edge in front of us suddenly swung out across the road, 20mph",
        "A cyclist travelling along the nearside kerb on the left veered out across both lanes ahead of me.",
    ],
)
def test_swerving_out_across_the_road_from_the_edge_crosses(text):
    """A move out of the edge said with "across" ("swerves out across the road") crosses the road."""
    assert _names(text)[-1] == "cross_in_front"


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist on the pavement swerved round a woman and into the road in front of me.",
        "An e-scooter rider on the footpath veered round a bin and off the kerb just ahead of us. 20 mph.",
        "A rider on the sidewalk swerved around a family and into the street in front of my car.",
        "A kid riding a scooter on the pavement swerved to miss a pram and came off the kerb into my path.",
        "Cyclist on the pavement swerved out around pedestrians right in front of the ego at 30 km/h.",
    ],
)
def test_a_swerve_on_the_pavement_leaves_it_across_the_road(text):
    """A rider on the pavement has no lane of the road to leave: a swerve there ends off the pavement,
    across the ego's path."""
    rider = next(a for a in read(text).actors if a.kind in ("bicycle", "e-scooter"))
    assert [b[0] for b in rider.behaviours][:1] == ["cross_in_front"]


@pytest.mark.parametrize(
    ("text", "first"),
    [
        ("A cyclist riding in the bike lane on my left swerved out across my lane.", "change_lane"),  # (own lane)
        ("A cyclist was riding along the left kerb ahead of me. Suddenly he swerved into my lane.", "along_road"),
        ("A cyclist is riding along the kerb ahead of me. I am at 40 km/h.", "along_road"),
        ("A kid on a scooter on the pavement swerved round a bin and rode on along the pavement.", "change_lane"),
    ],
)
def test_near_misses_of_a_swerve_keep_their_reading(text, first):
    assert _names(text)[0] == first


def test_a_swerve_into_the_lane_from_the_kerb_stays_a_move_into_it():
    """A rider on the kerb who swerves into the ego's lane names the lane it ends in: no crossing."""
    text = "Then the e-scooter on the left kerb swerves into my lane to get past a bin. About 20 mph."
    assert "cross_in_front" not in _names(text)
