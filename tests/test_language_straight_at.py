"""A road user said to come straight, right or directly at the ego, or head-on at it ("came straight
at me", "rode right at us", "heading directly for my car", "coming at us head-on"), comes on the ego's
own line: in the ego's lane, head-on, the wrong way. One that only comes towards the ego ("came
towards me") is oncoming in its own lane, and one that comes out of a side road or from a side at
the ego, or turns, crosses or walks at it, is no wrong-way road user."""

from __future__ import annotations

import pytest

from tests.reading_of import first_moves_not_on_foot, moves


@pytest.mark.parametrize(
    "text",
    [
        # a British driver's post
        "Came round the bend at 40 and a lad on a motorbike was coming straight at me. Had to brake hard.",
        # an American text message
        "omg I was doing 25 and some guy on a bike rode right at us, I had to stop",
        # a police witness statement, the driver in the third person
        "The witness states that a motorcycle was travelling directly towards her and she steered left.",
        # Indian English
        "Today one scooter fellow came straight towards my car, I applied brakes fully.",
        # Nigerian English
        "As I was driving along the road, one okada man came straight for my car and I swerved.",
        # a voice note
        "and this lorry's coming at us head-on, honestly, so I'm braking and braking",
        # a test specification
        "The target vehicle drives head-on towards the ego at 50 km/h; the ego brakes.",
        # a story
        "There was a boy on one of those scooters, no lights, coming straight at her, and she wrenched the wheel.",
        # an Australian post
        "Cruising at 80 when a ute comes flying round the corner dead at me, I'm in the ditch.",
    ],
)
def test_coming_straight_at_the_ego_is_head_on_the_wrong_way(text: str) -> None:
    assert first_moves_not_on_foot(text)[0] == "wrong_way"


@pytest.mark.parametrize(
    "text",
    [
        # oncoming in its own lane: only towards the ego
        "A cyclist came towards me and passed safely.",
        "A lorry came round the bend towards us and went by.",
        # out of a side road, from a side: it crosses or turns into the ego's road
        "A van came out of the side road straight at me.",
        "I was at the lights when a car came from the right straight at me and ran the red.",
        # a walker
        "A man walked straight at my car from the pavement and I stopped.",
        # the ego the one going straight at something
        "The car ahead braked and I went straight at it.",
        # a side, not a manner
        "A cyclist was coming up on the right towards me in the cycle lane.",
        # "at" a speed, not at the ego
        "Ego turns right at 20 km/h; an oncoming motorbike is coming straight at high speed and ego gives way.",
    ],
)
def test_towards_from_a_side_or_on_foot_is_not_the_wrong_way(text: str) -> None:
    assert "wrong_way" not in [b for m in moves(text) for b in m]


@pytest.mark.parametrize(
    "text",
    [
        "An e-scooter rides towards the ego in its lane at 20 km/h.",
        "Oncoming cyclist approaches the ego vehicle in its lane, no lights, at night.",
        "A motorcycle is heading toward the test vehicle in its lane at 60 km/h.",
        "The target car comes at the ego in its lane; the ego brakes.",
        "Scenario 4: a bicycle coming towards the subject vehicle in its lane at dusk.",
    ],
)
def test_towards_the_ego_in_its_lane_is_the_egos_lane(text: str) -> None:
    """The ego owns "its" right after it, said of one coming at it: the nearest noun owns the possessive."""
    assert first_moves_not_on_foot(text)[0] == "wrong_way"


@pytest.mark.parametrize(
    "text",
    [
        "A car overtook the ego and stayed in its lane ahead.",
        "A cyclist rides ahead of the ego in its lane at 15 km/h.",
        "The ego drives in its lane at 50 km/h; an oncoming van goes by.",
    ],
)
def test_its_lane_of_one_going_the_egos_way_or_of_the_ego_itself_is_no_head_on(text: str) -> None:
    assert "wrong_way" not in [b for m in moves(text) for b in m]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came round the corner, straight at me, and I braked.",
        "A van was coming down the hill, right at us, so we stopped.",
        "A motorbike was hurtling along the lane, straight for me, no lights.",
        "An e-scooter came the wrong way up the one-way street, towards me, and I stopped.",
        "A kid on a bike came flying down the hill, head-on at us, and mum swerved.",
    ],
)
def test_at_the_ego_set_off_by_a_comma_is_still_said_of_the_travel(text: str) -> None:
    """A comma before "straight at me" sets off how the road user comes, not a new clause."""
    assert first_moves_not_on_foot(text)[0] == "wrong_way"


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came out of the side road, straight at me.",
        "A lorry came round the bend, towards me, and went by.",
    ],
)
def test_a_comma_does_not_join_a_place_one_comes_out_of_nor_make_towards_head_on(text: str) -> None:
    assert "wrong_way" not in [b for m in moves(text) for b in m]
