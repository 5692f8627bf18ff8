"""Where a road user starts along the road, for three ways of saying it comes towards the ego:

* met coming: "we met a tractor coming up the lane": to meet a road user that is coming is to come
  face to face with it, so it is oncoming (not one met "coming up behind");
* a road user coming the other way that gives way to the ego waits where it comes from: the opposite
  arm of a crossroad (on a road with no side road it stops in its own lane, as it did before);
* a direction of travel followed by the road it is on ("travelling in the opposite direction on Elm
  Street"): the road is where it travels, not a place it approaches, so it stays oncoming.

The guards keep what is read right now: a road user placed behind, one followed or caught up with,
one giving way from a side road said, and the ego's own approach to a place."""

from __future__ import annotations

import pytest
from play_layers import play_layers

from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.met_coming import met_coming
from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text

TOWARDS = ("oncoming", "junction_opposite")


def _first(text: str):
    return read(text).actors[0]


MET_COMING = [
    ("Rounding the corner on the narrow lane we met a milk tanker coming up the hill.", "truck"),
    ("I was doing 30 through the woods when I met a motorbike coming down the track.", "car"),
    ("A car pulled out to overtake the cyclist and met a removal lorry coming, so it braked.", "truck"),
    ("Halfway along the causeway we met a camper van heading our way.", "van"),
]


@pytest.mark.parametrize(("text", "kind"), MET_COMING)
def test_a_road_user_met_coming_is_oncoming(text, kind):
    actor = next(a for a in read(text).actors if a.kind == kind)
    assert actor.relation in TOWARDS


NOT_MET_COMING = [
    ("On the slip road we met a courier van coming up behind us.", "behind"),
    ("I caught up with a horsebox and followed it for a mile.", None),
    ("A tractor came up behind me and flashed its lights.", "behind"),
]


@pytest.mark.parametrize(("text", "relation"), NOT_MET_COMING)
def test_a_road_user_not_met_face_to_face_keeps_its_place(text, relation):
    assert _first(text).relation == relation


def test_met_coming_needs_the_road_user_as_the_object_of_meet():
    tokens = "we met at the cafe and a lorry coming the other way".split()
    assert not met_coming(tokens, tokens.index("lorry") + 1)
    tokens = "we met a lorry coming up".split()
    assert met_coming(tokens, tokens.index("lorry") + 1)


_FLASHED_THROUGH = "At the lights a taxi coming the other way stopped and let me turn first."


def test_an_oncoming_road_user_giving_way_on_a_crossroad_waits_on_the_opposite_arm():
    text = _FLASHED_THROUGH
    actor = _first(text)
    assert actor.relation == "junction_opposite"
    assert [b[0] for b in actor.behaviours] == ["give_way"]


def test_one_coming_the_other_way_that_waves_the_ego_on_waits_facing_it():
    actor = _first("A horsebox coming the other way stopped and waved me on.")
    assert actor.relation == "junction_opposite"


def test_an_oncoming_give_way_plays(tmp_path):
    text = _FLASHED_THROUGH
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert adv["spawn"]["relation"] == "junction_opposite"
    assert played_problems(play_layers(layers, tmp_path), layers) == []


def test_giving_way_from_a_side_road_said_keeps_that_arm():
    text = "A car pulled out of the side road on the left and stopped to let me through."
    assert _first(text).relation == "junction_left"


def test_a_walker_coming_towards_the_ego_who_lets_it_through_stays_at_the_kerb():
    text = "A man walking towards me stopped at the kerb and let me through."
    assert _first(text).relation not in TOWARDS


ON_A_NAMED_ROAD = [
    "A taxi travelling in the opposite direction on Mill Street went straight through the junction.",
    "A pickup driving in the opposite direction on Station Road drifted over the centre line.",
]


@pytest.mark.parametrize("text", ON_A_NAMED_ROAD)
def test_a_direction_of_travel_on_a_named_road_stays_oncoming(text):
    assert _first(text).relation in TOWARDS


def test_the_egos_approach_to_a_place_places_no_one():
    text = "We were approaching the lights at 30 when a delivery van pulled out in front of us."
    assert _first(text).relation not in TOWARDS


def test_compass_headings_opposite_on_one_road_are_oncoming():
    text = "I was heading north on the avenue. A removal van heading south on the avenue hit the back of my car."
    assert _first(text).relation in TOWARDS


def test_an_oncoming_road_user_letting_the_ego_by_on_a_straight_road_stops_in_its_lane(tmp_path):
    text = "On a straight country road a horsebox coming the other way stopped and waved me on."
    actor = _first(text)
    assert actor.relation == "oncoming"
    assert [b[0] for b in actor.behaviours] == ["stop"]
    layers = layers_from_text(text, 0)
    assert played_problems(play_layers(layers, tmp_path), layers) == []
