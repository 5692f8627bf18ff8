"""Oncoming turns and cuts across at junctions and roundabouts (:mod:`vei_scenario.language.motion`):
who comes the other way and turns across the ego's path. Each group is one construction, in
wordings written for it (none taken from a corpus), with near misses that look alike and must not
be read so."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _only(text: str):
    (actor,) = read(text).actors
    return actor, [b[0] for b in actor.behaviours]


# "coming" + in front of / ahead of the ego, right after the road user's noun: it comes towards the
# ego, so its turn across the ego's path is the turn across from the opposite approach
COMING_FROM_IN_FRONT = [
    "At a crossroads I go straight at 40 km/h. A delivery van coming in front of me turned left across my path.",
    "At the crossroads I drove straight at 50 km/h when a taxi coming in front of us turned left across our nose.",
    "At the junction I keep straight on at 30 mph. A pickup coming ahead of us turned to its left across our lane.",
    "At the lights we carried straight on at 45 km/h and a minibus coming in front of us turned left across our way.",
]


@pytest.mark.parametrize("text", COMING_FROM_IN_FRONT)
def test_coming_in_front_of_the_ego_then_turning_across_is_the_turn_across(text):
    actor, names = _only(text)
    assert names[:1] == ["turn_across"]
    assert actor.relation == "junction_opposite"


# near misses: no "coming" (a road user in front goes the ego's way), a finite "came in front of" (a
# road user getting in front), and in front of another road user (not of the ego)
NOT_COMING_FROM_IN_FRONT = [
    "At the crossroads I went straight at 40 km/h. A car in front of me turned left across my path.",
    "At the crossroads I went straight at 40 km/h. A car came in front of me and turned left across my path.",
]


@pytest.mark.parametrize("text", NOT_COMING_FROM_IN_FRONT)
def test_in_front_of_the_ego_without_coming_is_not_oncoming(text):
    actor, names = _only(text)
    assert "turn_across" not in names
    assert actor.relation != "junction_opposite"


# the front of the ego's vehicle is what a turn across crosses, as its path is ("across our bonnet"):
# a road user coming the other way that turns across it turns across the ego's path, to whichever side
ACROSS_THE_FRONT = [
    "At the lights I drove straight at 50 km/h when a Transit coming towards us turned right across our bonnet.",
    "At the crossroads I went straight on at 30 mph and a lorry heading towards me swung right across my nose.",
    "I kept straight at the junction at 40 km/h; a cab coming the other way turned right across my hood.",
]


@pytest.mark.parametrize("text", ACROSS_THE_FRONT)
def test_a_turn_across_the_ego_s_front_is_the_turn_across(text):
    actor, names = _only(text)
    assert names[:1] == ["turn_across"]


# near miss: a turn away from the ego's front ("turned right in front of our bonnet") crosses nothing
def test_a_turn_in_front_of_the_bonnet_is_not_across():
    text = "At the crossroads I went straight at 40 km/h and a car ahead of us turned right in front of our bonnet."
    actor, names = _only(text)
    assert "turn_across" not in names


# a verb the reader has no word for + "into" + the ego or a part of it ("banged into my car",
# "slammed into my door") is a hit, not a move into a lane: a rider from the opposite approach that
# goes straight on and hits the turning ego keeps going towards it
HITS_INTO_THE_EGO = [
    "At the crossroads I was turning right at 15 km/h. A scooter came from the opposite side and banged into my car.",
    "At the crossroads I was turning right at 15 km/h. A cyclist from the other side went straight on and"
    " slammed into my door.",
    "At the crossroads I was turning right at 15 km/h. A scooter from the opposite side rode straight and"
    " bumped into us.",
]


@pytest.mark.parametrize("text", HITS_INTO_THE_EGO)
def test_an_unknown_verb_into_the_ego_is_a_hit_not_a_cut_in(text):
    reading = read(text)
    (actor,) = reading.actors
    assert [b[0] for b in actor.behaviours] == ["keep_going"]
    assert actor.relation == "junction_opposite"
    assert reading.intent == "collision"


# near misses: the same kind of verb + "into" + the ego's lane or path is a move into it
INTO_THE_EGO_S_WAY = [
    "On the dual carriageway at 80 km/h a lorry to my right barged into my lane.",
    "On the dual carriageway at 80 km/h a lorry to my right nosed into my path.",
]


@pytest.mark.parametrize("text", INTO_THE_EGO_S_WAY)
def test_an_unknown_verb_into_the_ego_s_lane_is_a_cut_in(text):
    _, names = _only(text)
    assert names == ["cut_in"]


# a move out made to pass ("swung out to overtake", "moved out to pass") by a road user ahead is the
# start of its overtake, not a pull-out across the ego's way (nor running a light)
OUT_TO_PASS = [
    "On the country road at 60 km/h the van ahead of me swung out to overtake a tractor.",
    "I was doing 40 mph behind a car which suddenly swung out to overtake a cyclist.",
    "On the B-road at 70 km/h the lorry in front of us moved out to pass a horse rider.",
]


@pytest.mark.parametrize("text", OUT_TO_PASS)
def test_a_move_out_to_pass_is_the_overtake(text):
    actor = read(text).actors[0]
    names = [b[0] for b in actor.behaviours]
    assert "overtake" in names and "run_red_light" not in names and "cross_in_front" not in names


# near misses: out of a side road, then a pass, is a pull-out first; out to turn is no pass
NOT_OUT_TO_PASS = [
    "A car swung out of a side road to my left and overtook a cyclist at 30 km/h.",
    "At 40 km/h on the main road a van ahead of me swung out to turn right into a yard.",
]


@pytest.mark.parametrize("text", NOT_OUT_TO_PASS)
def test_a_move_out_not_made_to_pass_is_no_overtake_alone(text):
    names = [b[0] for b in read(text).actors[0].behaviours]
    assert names != ["overtake"]


# "hung a right in front of me": after "make / take / hang a", "right" is the turn, not the stress
# of the "in front of me" that follows it
@pytest.mark.parametrize(
    ("text", "turn"),
    [
        ("I was in the right lane doing 25 mph and a van in the left lane hung a right in front of me.", "right"),
        ("Doing 30 mph in the left lane when a cab in the right lane made a left right in front of me.", "left"),
        ("we were at 40 km/h in the left lane and the truck in the right lane took a right in front of us", "right"),
    ],
)
def test_a_right_taken_in_front_of_the_ego_is_the_turn(text, turn):
    (actor,) = read(text).actors
    first = actor.behaviours[0]
    assert first[0] == "forced_turn" and first[1].get("turn") == turn


# the ego told of in the third person ("my sister was driving ...", a claim, a news item): a road
# user coming the other way that turns across her or his path, or across the front of the ego's
# vehicle, turns across the ego's path whichever side it turns to, as "across my path" does
ACROSS_THE_EGO_TOLD_OF = [
    "My dad was doing 30 mph through the lights when an oncoming taxi turned right across him.",
    "The claimant drove straight on at 40 km/h; a lorry coming the other way turned right across her path.",
    "Our son was riding home at 20 km/h and a car coming towards him swung right across his lane.",
    "My parents were going straight through the junction at 25 mph when a van coming the other way turned"
    " right across them.",
    "He was cycling at 15 mph when an oncoming bus swung right across his way into a depot.",
    "At the crossroads I went straight on at 30 mph and an oncoming pickup turned right across the front of my car.",
    "At the lights I drove straight at 50 km/h when a cab coming towards us turned right across the front of us.",
]


@pytest.mark.parametrize("text", ACROSS_THE_EGO_TOLD_OF)
def test_a_turn_across_the_ego_told_of_is_the_turn_across(text):
    actor, names = _only(text)
    assert names[:1] == ["turn_across"]


# near misses: a turn to the near side with nothing crossed, across another road's traffic by a road
# user going the ego's way, and across a road named by its place
NOT_ACROSS_THE_EGO_TOLD_OF = [
    "My dad was doing 30 mph through the lights when an oncoming taxi turned right into a side street.",
    "My dad was doing 30 mph when the taxi ahead of him turned right across the traffic.",
    "My dad was doing 30 mph when an oncoming taxi turned right across the car park entrance.",
]


@pytest.mark.parametrize("text", NOT_ACROSS_THE_EGO_TOLD_OF)
def test_a_turn_across_no_ego_is_not_the_turn_across(text):
    actor, names = _only(text)
    assert "turn_across" not in names
