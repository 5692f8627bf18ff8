"""A road user coming at the ego on the ego's half of the road, said with the ego in the second or
third person ("towards her on her side of the road", "in your lane") or in the middle of the road
("right down the middle of the lane, straight at me"): it comes the wrong way, head-on. Near misses:
one on its own half ("a cyclist riding on his side of the road"), one in the middle of the road going
the ego's way, a walker standing there, a third-person pronoun in a text its narrator tells as "I"."""

from __future__ import annotations

import pytest

from tests.reading_of import first_moves_not_on_foot, moves


@pytest.mark.parametrize(
    "text",
    [
        # a police report, the driver in the third person
        "Witness states the motorcyclist was travelling towards her on her side of the road and she "
        "steered onto the grass verge to avoid him.",
        # a club newsletter
        "One of our members was heading home on Friday when a kid on an e-bike came round the corner "
        "towards him in his lane, no lights at all.",
        # a forum reply, the reader as the driver
        "So you were doing 40 and a cyclist with no lights was riding towards you in your lane? Not your fault.",
        # a news item with the driver named
        "The van came over the brow on Priya's side of the road and Priya swerved into the hedge.",
        # a claim letter
        "Our client states that the third party's vehicle was travelling towards him on his side of the "
        "road at speed, and a collision could not be avoided.",
    ],
)
def test_coming_at_the_ego_on_its_half_told_in_the_third_person_is_the_wrong_way(text: str) -> None:
    assert first_moves_not_on_foot(text)[0] == "wrong_way"


@pytest.mark.parametrize(
    "text",
    [
        "Coming round the bend I met a tractor slap bang in the middle of the lane, coming straight at me.",
        "two lads on one scooter came towards us right in the middle of the road, no lights",
        "A cyclist came down the hill towards me right down the middle and I had to stop.",
        "An e-scooter rider was heading for our bus in the middle of the road; the driver swerved.",
        "A car approached head-on down the middle of the carriageway at about 50 km/h; ego braked.",
    ],
)
def test_coming_at_the_ego_in_the_middle_of_the_road_is_the_wrong_way(text: str) -> None:
    assert first_moves_not_on_foot(text)[0] == "wrong_way"


@pytest.mark.parametrize(
    "text",
    [
        # its own half: the possessive is its own subject's
        "A cyclist was riding on his side of the road when the van came past.",
        # the ego's way, in the middle of the lane ahead
        "We were doing 20 when a cyclist riding in the middle of the road in front of us braked.",
        "A cyclist was riding in the middle of the lane ahead of us at about 15 km/h.",
        # a walker standing there
        "A pedestrian was standing in the middle of the road as we approached.",
    ],
)
def test_own_half_or_the_egos_way_is_not_the_wrong_way(text: str) -> None:
    assert "wrong_way" not in first_moves_not_on_foot(text)


def test_she_kept_to_her_side_is_her_own_half() -> None:
    """A clause whose subject is the pronoun's own person: her half is hers, whoever she is."""
    text = "The driver said she kept to her side of the road and the cyclist came past her."
    assert "wrong_way" not in [b for m in moves(text) for b in m]


@pytest.mark.parametrize(
    "text",
    [
        "At about 2am a man was riding a bicycle north in the southbound carriageway of the bypass.",
        "The e-scooter was going east in the westbound lane when the bus met it.",
        "Our van was northbound when a cyclist came riding south in the northbound carriageway.",
        "A cyclist was pedalling west along the eastbound carriageway, no lights.",
    ],
)
def test_a_compass_point_against_the_lane_it_is_in_is_the_wrong_way(text: str) -> None:
    """A bare compass point right before a lane of the other heading, whatever kind of lane."""
    assert first_moves_not_on_foot(text) == ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist was riding north in the northbound cycle lane ahead of us.",
        "We stopped just north of the bridge in the southbound lane; a cyclist rode past.",
    ],
)
def test_a_compass_point_with_its_own_lane_or_a_place_is_not_the_wrong_way(text: str) -> None:
    assert "wrong_way" not in first_moves_not_on_foot(text)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came at me against the direction of travel, no lights, and I had to swerve.",
        "Yesterday I was driving at 40 when an e-bike going retrograde appeared right in front of me.",
        "The moped rode towards us against the driving direction and we braked.",
        "Some kid on a scooter riding against the flow of traffic nearly hit my car.",
        "I was doing 30 when a delivery rider came the other way against the one-way, straight at me.",
    ],
)
def test_against_the_way_one_may_go_however_said_is_the_wrong_way(text: str) -> None:
    assert first_moves_not_on_foot(text)[0] == "wrong_way"


def test_against_the_direction_on_its_own_cycle_lane_is_not_head_on() -> None:
    """A rider against the traffic in a cycle lane of its own goes along that lane, not in the ego's."""
    text = "A cyclist was riding against the direction of traffic in the cycle lane on our left."
    assert "wrong_way" not in first_moves_not_on_foot(text)


@pytest.mark.parametrize(
    "text",
    [
        "My son had his driving lesson today. A man on an e-scooter came down the high street the wrong "
        "way, straight at the car in our lane. He was doing about 30 and had to stop dead.",
        "Coming home, a cyclist rode towards me on my side of the road with no lights. Had to brake hard.",
    ],
)
def test_a_stop_said_free_after_a_head_on_road_user_is_the_egos(text: str) -> None:
    """The ego's reaction, told after it, neither is its act nor hides its coming head-on."""
    assert first_moves_not_on_foot(text) == ["wrong_way"]


def test_its_own_stop_then_said_stays_its_own() -> None:
    """Its own stop, joined by "then" and placed in the road, is its act: it stays."""
    text = "A cyclist came straight at me in my lane and then stopped dead in the middle of the road."
    assert {"stop", "sudden_stop"} & set(first_moves_not_on_foot(text))
