"""Which behaviour a road user's verb phrase means (:mod:`vei_scenario.language.motion`): the class of
move is said by where it goes (the ego's lane, the roundabout) and where it comes from (the other way),
not by the verb. Wordings written for each construction, none taken from a corpus; each class has
near-miss wordings that must not be read so."""

from __future__ import annotations

import pytest

from tests.reading_of import moves
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def _behaviours(text: str) -> list[str]:
    (actor,) = read(text).actors
    return [b[0] for b in actor.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "A car in the left lane invaded my lane just ahead of me.",
        "A pickup from the next lane encroached into our lane without signalling.",
        "A motorbike coming up from behind entered suddenly in front of the ego, 8 m ahead.",
        "A taxi in the right lane swung from its lane into mine.",
        "A van in the outside lane moved across into ours and braked.",
    ],
)
def test_entering_the_ego_lane_from_beside_is_a_cut_in(text):
    assert _behaviours(text)[0] == "cut_in"


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming lorry invaded my lane on the bend.",
        "A bus coming the other way encroached onto our side of the road at the corner.",
        "A tractor travelling in the opposite direction entered the ego's lane at the curve.",
        "A pickup is driving in contrary direction and invade our lane on the bend.",
    ],
)
def test_entering_the_ego_lane_from_the_other_way_is_driving_the_wrong_way(text):
    assert _behaviours(text) == ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "A car in the left lane entered the motorway well ahead of me.",
        "An oncoming van stayed in its own lane as we passed.",
        "A lorry in the right lane drove into the car park on the left.",
    ],
)
def test_entering_somewhere_else_is_no_move_into_the_ego_lane(text):
    names = _behaviours(text)
    assert "cut_in" not in names and "wrong_way" not in names


@pytest.mark.parametrize(
    "text",
    [
        "Two kids on scooters raced down the wrong side of the road straight at us.",
        "A cyclist on the wrong side of the street pelted right at me.",
        "A moped was coming directly at the ego on the wrong side of the road.",
    ],
)
def test_going_straight_at_the_ego_the_wrong_way_is_head_on(text):
    for actor in read(text).actors:
        assert [b[0] for b in actor.behaviours] == ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "A pedestrian looked straight at me and then crossed the road.",
        "The van driver shouted at us and drove on in the other lane.",
    ],
)
def test_looking_or_shouting_at_the_ego_is_no_head_on_drive(text):
    assert "wrong_way" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "I was on the roundabout at 20 km/h when a cyclist rode straight onto it in front of me.",
        "Going round the roundabout at 15 mph, a moped shot onto the roundabout right in front of us.",
        "The ego is circulating in the roundabout. A van enter the roundabout from the next entry and do not give way.",
        "We were on the roundabout when a car drove onto it from the next arm without slowing.",
    ],
)
def test_coming_onto_the_roundabout_the_ego_is_on_is_entering_it(text):
    assert _behaviours(text)[0] in ("turn_into", "run_red_light")


@pytest.mark.parametrize(
    "text",
    [
        "I was on the roundabout when a cyclist already circulating rode round in front of me.",
        "At the roundabout a pedestrian walked onto the zebra crossing in front of me.",
    ],
)
def test_going_round_or_crossing_at_the_roundabout_is_no_entry(text):
    assert _behaviours(text)[0] not in ("turn_into", "run_red_light")


@pytest.mark.parametrize(
    "text",
    [
        "At the crossroads a moped came out of the side road on the left without stopping and into my lane just ahead.",
        "A van shot out of a side street on the right without looking, straight into our lane in front of us.",
        "At the junction a cyclist rolled out of the side road on my left without stopping, right into the ego's path.",
    ],
)
def test_out_of_a_side_road_into_the_ego_lane_is_turning_into_its_road(text):
    assert _behaviours(text)[0] == "turn_into"


@pytest.mark.parametrize(
    "text",
    [
        "At the crossroads a van came out of the side road on the left without stopping and carried on across.",
        "At the junction a car shot out of the side road on the right without stopping and went straight over.",
    ],
)
def test_out_of_a_side_road_and_across_without_stopping_is_no_turn_into(text):
    assert _behaviours(text)[0] != "turn_into"


@pytest.mark.parametrize(
    "text",
    [
        "A BMW was sitting two metres off my rear bumper for miles.",
        "A white van hung on my tail all the way down the bypass.",
        "Some lorry stayed right up my backside on the dual carriageway.",
    ],
)
def test_sitting_on_the_ego_tail_is_following_it_from_behind(text):
    (actor,) = read(text).actors
    assert [b[0] for b in actor.behaviours] == ["follow_vehicle"] and actor.relation == "behind"


@pytest.mark.parametrize(
    "text",
    [
        "A car hit me on my rear bumper at the lights.",
        "A cyclist clipped my back bumper as he went past.",
        "A moped came flying across from the left, inches off my bumper.",
    ],
)
def test_touching_the_ego_rear_is_no_following(text):
    assert "follow_vehicle" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "Two cyclists were riding in the bike lane; one of them swerved out into the road right in front of me.",
        "Three kids on bikes in the cycle lane; one suddenly swerves out into the street in front of us.",
        "A lad on a scooter was going along the kerb on my left, then lurched out into the road in front of me.",
    ],
)
def test_one_of_those_at_the_side_swerving_out_in_front_of_the_ego_cuts_in(text):
    moves = [b[0] for a in read(text).actors for b in a.behaviours]
    assert "change_lane" not in moves and {"cut_in", "cross_in_front"} & set(moves)


def test_one_of_two_cars_in_another_lane_moving_over_well_ahead_changes_lane():
    text = "Two cars were in the left lane; one of them swerved out into the right lane well ahead of us."
    moves = [b[0] for a in read(text).actors for b in a.behaviours]
    assert "change_lane" in moves and "cut_in" not in moves


# A road user's act said with a verb the reader has no behaviour for, read by the structure around it
# (own_way.py, motion.follows_with_nothing_named): a verb whose object is the road user itself ("wedged
# itself into my lane", "forced its way into our lane", "poked its nose into my lane") moves it where
# the verb goes; "following" said of a road user with nothing named that it follows ("a van following
# at 2 s") follows the ego. Guards: the ego's own act, another road user as the object, a denial, "the
# following" as a word of order, an act of its own besides.


def _first_acts(text: str) -> list[str]:
    return moves(text)[0]


@pytest.mark.parametrize(
    "text",
    [
        "A delivery lorry wedged itself into my lane at the last second.",
        "On the ring road a taxi from the right lane forced its way into our lane.",
        "I was doing 40 when a white pickup elbowed its way into my lane.",
        "dashcam: silver estate in lane 2 poked its nose into my lane, I braked",
        "The coach eased itself over into my lane without indicating.",
    ],
)
def test_a_road_user_moving_itself_into_the_ego_lane_cuts_in(text: str) -> None:
    assert _first_acts(text)[0] == "cut_in"


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 50 km/h on a straight road, a hatchback following at 2 s.",
        "I was at 30 mph and a Transit was following at about 1.5 seconds the whole way.",
        "The ego travels at 80 km/h; a lorry is following about 20 m back.",
        "log: host 70 km/h | trailing car following at 1.2 s | dry",
    ],
)
def test_a_road_user_following_with_nothing_named_follows_the_ego(text: str) -> None:
    layers = layers_from_text(text, 0)
    follower = next(a for a in layers["adversaries"] if a["type"] != "pedestrian")
    assert [node["behaviour"] for _, node in behaviour_nodes(follower["behaviour"])][:1] == ["follow_vehicle"]


@pytest.mark.parametrize(
    ("text", "old"),
    [
        # the ego's own act: "itself" is the ego, no road user moves
        ("I squeezed myself into the left lane and a van kept going ahead of me.", "keep_going"),
        # another road user as the object: the verb says what is done to it, not a move of the subject
        ("A tow truck dragged a wreck into my lane.", "keep_going"),
        # a denial: no move
        ("A taxi in the right lane never forced its way into my lane, it stayed put.", None),
    ],
)
def test_other_objects_and_denials_keep_their_reading(text: str, old: str | None) -> None:
    acts = moves(text)
    if old is None:
        assert all("cut_in" not in a for a in acts)
    else:
        assert acts and acts[-1][0] == old


@pytest.mark.parametrize(
    "text",
    [
        # following named: what it follows is said, and read as before
        "A cyclist was following a bus along the high street at 20 km/h.",
        # an act of its own besides: that act, not a following
        "A car following at 2 s suddenly braked hard.",
        # "the following" is a word of order
        "The following car overtook me on the left.",
    ],
)
def test_following_with_its_own_object_or_act_keeps_its_reading(text: str) -> None:
    acts = moves(text)
    assert acts and acts[0][:1] != ["follow_vehicle"]


def test_the_ego_following_is_no_road_users_act() -> None:
    acts = moves("The ego is following at 2 s behind a lorry that brakes hard.")
    assert acts == [["sudden_stop"]]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi from the left lane muscled its way in front of me.",
        "A hatchback in the right lane squeezed itself in front of us at the lights.",
    ],
)
def test_a_road_user_moving_itself_in_front_of_the_ego_from_a_lane_beside_cuts_in(text: str) -> None:
    assert _first_acts(text)[0] == "cut_in"
