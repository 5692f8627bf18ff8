"""Road users moving between lanes and coming the other way (:mod:`vei_scenario.language.motion`,
:mod:`vei_scenario.language.sides`): a cut-out round what stops in the lane, a swerve into another
lane, an overtake that cuts back in, a move into the lane the ego is said to be in, and head-on
traffic. Wordings written for each construction, none taken from a corpus; near misses beside them."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _actors(text: str) -> list[tuple[str, str | None, list[str]]]:
    return [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in read(text).actors]


# A lead that moves out of the ego's lane while the road user in front of it stops reveals that one:
# what stops in the lane is an obstacle as much as what already stands there.
@pytest.mark.parametrize(
    "text",
    [
        "The car ahead of me swerves into the next lane to avoid a lorry that has braked to a halt.",
        "The car ahead changes into the right lane; a van in front of it brakes hard to a standstill.",
        "The hatchback in front of us dives into the outside lane because a coach ahead of it has stopped dead.",
    ],
)
def test_a_lead_moving_out_round_a_road_user_that_stops_is_a_cut_out(text):
    lead, obstacle = read(text).actors
    assert [b[0] for b in lead.behaviours] == ["cut_out"] and lead.relation == "ahead"
    assert lead.obstacle == 1 and obstacle.relation == "ahead"
    assert [b[0] for b in obstacle.behaviours][-1] in ("stop", "sudden_stop")


@pytest.mark.parametrize(
    "text",
    [
        "The car in front changes into the left lane.",
        "The van ahead of me moves into the next lane and then brakes to a stop.",
        "A car in the left lane changes into the right lane while the lorry ahead of me brakes to a stop.",
    ],
)
def test_a_lane_change_with_nothing_stopping_in_the_lane_it_leaves_is_no_cut_out(text):
    assert all("cut_out" not in names for _, _, names in _actors(text))


# A road user in front of the ego is in the ego's lane: the lane it moves into is another one.
@pytest.mark.parametrize(
    "text",
    [
        "The hatchback in front of us moves into the outside lane.",
        "The car ahead of me dives into the next lane.",
        "The estate car ahead pulls into the adjacent lane at 60 km/h.",
    ],
)
def test_a_lead_moving_into_another_lane_changes_lanes(text):
    assert _actors(text) == [("car", "ahead", ["change_lane"])]


@pytest.mark.parametrize(
    "text",
    [
        "The car ahead dives into my lane.",  # (the lead said so, but the lane is the ego's)
        "A van in the left lane moves into the next lane right in front of me.",
    ],
)
def test_a_move_into_the_ego_lane_stays_a_cut_in(text):
    assert [names for _, _, names in _actors(text)] == [["cut_in"]]


# Any verb whose destination is a lane is a move into it: the lane says the move, even where the verb
# is one the lexicon does not hold.
@pytest.mark.parametrize(
    "text",
    [
        "Following a saloon at 50 mph, he suddenly jinks out into lane 2.",
        "The taxi ahead of us jinked over into the right lane.",
        "The car in front of me scoots across into the next lane.",
    ],
)
def test_any_verb_into_another_lane_is_a_lane_change(text):
    assert _actors(text) == [("car", "ahead", ["change_lane"])]


def test_a_participle_before_a_lane_is_where_it_goes_not_a_move():
    assert ["change_lane"] not in [names for _, _, names in _actors("A lorry travelling in the right lane.")]


# A move into the ego's lane is a cut-in, whatever the verb's phrase holds ("swerves into"); from the
# kerb it stays the lane change from the roadside it was.
@pytest.mark.parametrize(
    "text",
    [
        "A motorbike alongside me swerves into my lane.",
        "An e-scooter rider in the cycle lane on our right veers into our lane 10 m ahead.",
        "A coach in the left lane lurches into the ego's lane.",
    ],
)
def test_a_swerve_into_the_ego_lane_is_a_cut_in(text):
    assert [names for _, _, names in _actors(text)] == [["cut_in"]]


# The doer of a passive verb is the noun phrase after "by", whatever modifies its noun.
@pytest.mark.parametrize(
    "text",
    [
        "I was overtaken by a white van.",
        "We got overtaken by some big old lorry at 70 mph.",
        "Yesterday I was passed by a silver hatchback on the bypass.",
    ],
)
def test_the_doer_of_a_passive_overtake_is_the_noun_phrase_after_by(text):
    ((_, relation, names),) = _actors(text)
    assert names == ["overtake"] and relation in (None, "behind")


def test_a_noun_after_by_a_verb_is_no_doer_of_a_passive():
    assert all(names != ["overtake"] for _, _, names in _actors("I was overtaken by the ego near a white van."))


# A verb + "in" that ends in front of the ego is a cut-in: "in" is into the lane, in front of the ego
# its lane.
@pytest.mark.parametrize(
    "text",
    [
        "The van swings in about 5 metres in front of me.",
        "A car tucks in right in front of us.",
        "The estate car nips back in just ahead of me.",
    ],
)
def test_a_verb_in_ending_in_front_of_the_ego_is_a_cut_in(text):
    ((_, _, names),) = _actors(text)
    assert names == ["cut_in"]


@pytest.mark.parametrize(
    "text",
    [
        "The van swings in behind me.",
        "The van pulled in at the bus stop in front of me.",
    ],
)
def test_a_verb_in_ending_elsewhere_is_no_cut_in(text):
    assert all("cut_in" not in names for _, _, names in _actors(text))


# Going past on the wrong side of the road is how an overtake is made, not driving the wrong way.
@pytest.mark.parametrize(
    "text",
    [
        "A car overtook us on the wrong side of the road.",
        "A van comes past on the wrong side of the road and swings in about 5 metres in front of me.",
        "On the hill a lorry passed me on the wrong side of the road.",
    ],
)
def test_passing_on_the_wrong_side_of_the_road_is_an_overtake(text):
    ((_, relation, names),) = _actors(text)
    assert names[0] == "overtake" and "wrong_way" not in names and relation in (None, "behind")


@pytest.mark.parametrize(
    "text",
    [
        "A car came round the bend on the wrong side of the road.",
        "A scooter rider on the wrong side of the road rides straight at me.",
    ],
)
def test_going_along_on_the_wrong_side_of_the_road_stays_the_wrong_way(text):
    ((_, _, names),) = _actors(text)
    assert names == ["wrong_way"]


# The lane the ego is said to be in, by its name, is the ego's lane: a move into it is a cut-in.
@pytest.mark.parametrize(
    "text",
    [
        "I was in the left lane at 30 mph when a lorry in the right lane moved into the left lane.",
        "We were in the right lane when a coach in the left lane swerved into the right lane.",
        "I'm in the nearside lane doing 40; a tipper in the offside lane shifts into the nearside lane.",
    ],
)
def test_a_move_into_the_lane_the_ego_is_said_to_be_in_is_a_cut_in(text):
    ((_, relation, names),) = _actors(text)
    assert names == ["cut_in"] and relation in ("left", "right")


@pytest.mark.parametrize(
    "text",
    [
        "I was in the left lane at 30 mph when a lorry moved into the right lane.",
        "I'm in the left lane at 70 km/h. Further ahead a lorry in the right lane moves over to the left lane.",
    ],
)
def test_a_move_into_another_lane_or_far_ahead_is_a_lane_change(text):
    ((_, _, names),) = _actors(text)
    assert names == ["change_lane"]


# A road user coming head-on in the ego's lane that then goes past the ego meets it: no overtake.
@pytest.mark.parametrize(
    "text",
    [
        "A scooter rider came towards me in my lane and squeezed past me.",
        "A cyclist riding the wrong way in my lane passed me with a foot to spare.",
        "A moped came at us head-on in our lane and shot past us.",
    ],
)
def test_going_past_the_ego_after_coming_head_on_is_still_the_wrong_way(text):
    ((_, _, names),) = _actors(text)
    assert names == ["wrong_way"]


def test_an_overtake_behind_the_ego_in_its_lane_stays_an_overtake():
    assert _actors("A car behind me in my lane overtook me.") == [("car", "behind", ["overtake"])]


def test_overtaking_others_on_the_wrong_side_of_the_road_stays_the_wrong_way():
    text = "A moped rider overtook the queue on the wrong side of the road and crashed head-on into a van."
    assert "wrong_way" in _actors(text)[0][2]
