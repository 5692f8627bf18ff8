"""The road the generator writes has every lane its road users start in or change into: a reading
whose lanes and sides disagree (a lorry "in the lane on my left" on a road said to have one lane each
way, a cut-in from an open side while the ego is in the left lane) is given the nearest road that
holds it, and plays what its layers say. Readings are built directly (no sentence, so no wording is
favoured), sampled, written and played with vei run's interpreter."""

from __future__ import annotations

import pytest
from play_layers import play_layers

from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.lane_room import LaneUser, choose
from vei_scenario.language.reading import ActorSpec, Reading
from vei_scenario.language.rules_backend import sample_layers


def _user(relation, default="ahead", at_kerb=False, changes=()):
    return LaneUser(relation, default, at_kerb, tuple(changes))


def test_a_reading_whose_road_users_have_their_lanes_is_left_as_it_is():
    """Near miss: nothing moves where everything fits (one lane each way and a head-on road user; two
    lanes with the ego on the right and someone on its left moving over into its lane)."""
    assert choose([_user("oncoming", "ahead")], 1, 1) == choose([_user("oncoming")], 1, 1)
    assert (choose([_user("oncoming")], 1, 1).lanes, choose([_user("oncoming")], 1, 1).ego_lane) == (1, 1)
    room = choose([_user("left", changes=[("change_lane", -1.0)])], 2, 1)
    assert (room.lanes, room.ego_lane, room.relations) == (2, 1, {})
    room = choose([_user("ahead", changes=[("cut_out", 1.0)])], 1, 1)  # (round it over the centre line)
    assert (room.lanes, room.ego_lane) == (1, 1)


def test_someone_beside_the_ego_moving_over_into_its_lane_needs_no_lane_beyond_the_ego():
    """A road user on the ego's left changing lane to the right ends in the ego's lane: the ego stays
    in the right-hand lane of two rather than being moved over, where it would leave no lane left."""
    room = choose([_user("left", changes=[("change_lane", -1.0)])], 2, 2)
    assert (room.lanes, room.ego_lane) == (2, 1)


def test_a_side_the_text_leaves_open_goes_where_a_lane_is_before_the_road_is_widened():
    """The ego in the left lane of two, one road user said to be on its right and a cut-in whose side
    is not said: the cut-in comes from the right too, on the road said, rather than the road getting
    a third lane for it. Where no side has a lane (one lane each way), the road gets one."""
    room = choose([_user(None, "left"), _user("right")], 2, 2)
    assert (room.lanes, room.ego_lane, room.relations) == (2, 2, {0: "right"})
    room = choose([_user(None, "left")], 1, 1)
    assert (room.lanes, room.ego_lane, room.relations) == (2, 1, {})


def test_the_road_gets_the_lanes_a_stated_side_needs():
    """A road said to have one lane each way and a road user said to be on the ego's left (and one on
    its right): the road gets a lane each way more (two), the ego between them."""
    assert (choose([_user("left")], 1, 1).lanes, choose([_user("left")], 1, 1).ego_lane) == (2, 1)
    room = choose([_user("left"), _user("right")], 2, 2)
    assert (room.lanes, room.ego_lane) == (3, 2)


def _reading(lanes, actors, ego_relation=None, map_kind=None, ego_speed=None):
    return Reading(map_kind=map_kind, lanes=lanes, ego_relation=ego_relation, ego_speed_mps=ego_speed, actors=actors)


def _spec(kind, relation, behaviours, distance_m=None, speed_mps=None):
    return ActorSpec(kind, relation, distance_m, speed_mps, [(name, cfg, None, "sequence") for name, cfg in behaviours])


READINGS = {
    # a lorry in the lane on the ego's left that moves over, on a road said to have one lane each way
    "left-cut-in-one-lane": lambda: _reading(1, [_spec("truck", "left", [("cut_in", {})])]),
    # the ego on the right of two lanes, a rider on its left swerving right into its lane
    "left-rider-moves-right": lambda: _reading(
        2, [_spec("e-scooter", "left", [("change_lane", {"direction": -1.0})], distance_m=8.0)], ego_relation="right"
    ),
    # the ego in the left lane of two and a cut-in whose side is not said
    "open-side-cut-in-ego-left": lambda: _reading(2, [_spec("van", None, [("cut_in", {})])], ego_relation="left"),
    # a rider at the kerb of a road with one lane each way changing lane, its side not said
    "kerb-rider-open-side": lambda: _reading(
        1, [_spec("bicycle", "roadside_right", [("change_lane", {})], distance_m=30.0, speed_mps=4.0)]
    ),
    # a car ahead moving over to the right on a road with one lane each way
    "ahead-moves-right-one-lane": lambda: _reading(1, [_spec("car", "ahead", [("change_lane", {"direction": -1.0})])]),
}


@pytest.mark.parametrize("name", sorted(READINGS))
@pytest.mark.parametrize(("seed", "ego_speed"), [(0, 8.0), (1, 14.0), (2, 22.0)])
def test_a_reading_whose_lanes_and_sides_disagree_is_written_and_plays(name, seed, ego_speed, tmp_path):
    reading = READINGS[name]()
    reading.ego_speed_mps = ego_speed
    layers = sample_layers(reading, "built by a test", seed)
    assert played_problems(play_layers(layers, tmp_path), layers) == []


def test_a_roundabout_arm_is_widened_for_a_road_user_on_the_ego_s_left(tmp_path):
    reading = _reading(None, [_spec("car", "left", [("cut_in", {})])], ego_relation="left", map_kind="roundabout")
    layers = sample_layers(reading, "built by a test", 0)
    assert layers["environment"]["map"]["lanes_per_direction"] == 2
    assert played_problems(play_layers(layers, tmp_path), layers) == []
