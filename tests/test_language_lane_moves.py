"""Road users on the ego's road (:mod:`vei_scenario.language.lane_moves`): a plain braking after a
cut-in is how the cut-in settles, a hard one a sudden stop; "slow" said as a pace is no slowing.
Wordings written for each construction, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.sides import not_a_side


def _behaviours(text: str) -> list[list[str]]:
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi cut in front of me and braked.",
        "At 70 km/h on the motorway, a hatchback from the outside lane dived into the space ahead of us and braked.",
        "A pickup cut in with barely 5 m to spare, then braked.",
        "Ego at 90 km/h in lane 1; a coupe from lane 2 cuts in aggressively and brakes.",
    ],
)
def test_a_plain_braking_after_a_cut_in_is_how_it_settles(text):
    assert _behaviours(text) == [["cut_in"]]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi cut in front of me and braked sharply.",
        "A taxi cut in front of me and then braked hard.",
        "A taxi cut in front of me and slammed on the brakes.",
        "A taxi cut in front of me and braked to a stop.",
        "A taxi cut in front of me, then braked suddenly.",
    ],
)
def test_a_hard_braking_after_a_cut_in_is_a_sudden_stop(text):
    assert _behaviours(text) == [["cut_in", "sudden_stop"]]


def test_braking_by_someone_else_after_a_cut_in_is_not_the_cut_in():
    assert _behaviours("A taxi cut in. The bus ahead of me braked.")[1] == ["sudden_stop"]
    assert _behaviours("The lorry in front of me braked.") == [["sudden_stop"]]


@pytest.mark.parametrize(
    "text",
    [
        "I came up behind a tractor ahead of me going very slow.",
        "There was a moped ahead of me in my lane, really slow.",
        "The bus in front of me was driving slow.",
    ],
)
def test_slow_said_as_a_pace_is_no_slowing(text):
    assert "change_speed" not in _behaviours(text)[0]


@pytest.mark.parametrize(
    "text",
    [
        "The van ahead of me began to slow.",
        "The van ahead of me had to slow for a dog.",
    ],
)
def test_slow_as_a_verb_is_a_slowing(text):
    assert _behaviours(text) == [["change_speed"]]


@pytest.mark.parametrize(
    "text",
    [
        "A boy on a bike rode the wrong way up the street and squeezed past my car.",
        "Two girls on scooters came the wrong way round the roundabout and went past either side of us.",
        "A moped came the wrong way down the one-way street and passed me with inches to spare.",
    ],
)
def test_the_wrong_way_then_past_the_ego_is_coming_head_on(text):
    assert all(b == ["wrong_way"] for b in _behaviours(text))


@pytest.mark.parametrize(
    "text",
    [
        "A moped came up behind me and squeezed past on the wrong side.",
        "A moped overtook me on the wrong side of the road.",
    ],
)
def test_passing_the_ego_from_behind_stays_an_overtake(text):
    assert _behaviours(text) == [["overtake"]]


@pytest.mark.parametrize(
    "text",
    [
        "A lorry was overtaking a tractor and came onto our side, head-on towards us.",
        "A minibus overtook the cyclist and came straight at me.",
        "A bus passed a parked lorry and was coming straight at us.",
    ],
)
def test_a_place_after_a_second_verb_is_the_subjects_not_the_objects(text):
    reading = read(text)
    assert reading.actors[0].relation == "oncoming"
    assert [b[0] for b in reading.actors[0].behaviours] == ["wrong_way"]


def test_what_an_oncoming_road_user_overtakes_comes_towards_the_ego_too():
    reading = read("An oncoming van overtook a jogger.")
    assert [(a.relation, a.facing) for a in reading.actors] == [("oncoming", None), ("ahead", "against")]


def test_a_place_said_with_a_new_subject_after_and_is_that_ones():
    reading = read("I overtook a cyclist and a car came towards me.")
    assert [(a.kind, a.relation) for a in reading.actors] == [("bicycle", "ahead"), ("car", "oncoming")]


@pytest.mark.parametrize(
    "text",
    [
        "Ego 90 km/h, lead truck 30 m ahead does a lane chg to the left around a stopped car in the lane.",
        "ego 80 km/h; lead van 25 m ahead -> lane chng L round a broken-down car in lane",
    ],
)
def test_lane_chg_shorthand_is_a_lane_change(text):
    assert _behaviours(text)[0] == ["cut_out"]


@pytest.mark.parametrize(
    "text",
    [
        "A pickup behind me tried to squeeze past on the narrow bridge.",
        "The van behind me decided to nip past at the lights.",
    ],
)
def test_an_act_tried_in_the_infinitive_is_that_act(text):
    assert _behaviours(text) == [["overtake"]]


def test_an_infinitive_of_purpose_is_not_a_second_act():
    text = "A moped in the cycle lane on my right swerves left across my lane to turn into a side road on the left."
    assert _behaviours(text) == [["forced_turn"]]


@pytest.mark.parametrize(
    "text",
    [
        "Coming round a bend at 40 mph, a lorry came towards me half over the centre line.",
        "An oncoming van was well over the white line.",
        "A car coming the other way was straddling the centerline.",
        "Doing 50 on a country lane when a tractor came at us across the dividing line.",
        "A quad bike heading towards me was over the double yellow line.",
    ],
)
def test_one_coming_towards_the_ego_over_the_centre_line_comes_head_on(text):
    assert _behaviours(text) == [["wrong_way"]]


@pytest.mark.parametrize(
    "text",
    [
        "A BMW overtook me, swinging over the centre line.",
        "A cyclist ahead of me was riding over the white line at the edge.",
        "I went over the centre line to pass a slow cyclist.",
        "A van ahead of me in my lane drifted over the centre line.",
    ],
)
def test_over_the_centre_line_going_the_ego_way_is_no_head_on(text):
    assert "wrong_way" not in _behaviours(text)[0]


@pytest.mark.parametrize(
    "text",
    [
        "A moped came towards me in the rain. I kept left, and they passed each other safely.",
        "A delivery van was coming the other way on the narrow lane. They went past each other slowly.",
        "A horse rider came towards us on the bridge; they passed one another at walking pace.",
        "An e-scooter came towards me on the bend. They passed each other safely.",
    ],
)
def test_passing_each_other_is_meeting_not_overtaking(text):
    assert not {"overtake", "wrong_way"} & set(_behaviours(text)[0])


@pytest.mark.parametrize(
    "text",
    [
        "A motorbike came up behind me and passed each car in the queue.",
        "A van came up behind me and passed one car after another.",
        "A cyclist came up behind me and passed me.",
    ],
)
def test_passing_each_or_one_of_several_is_still_an_overtake(text):
    assert "overtake" in _behaviours(text)[0]


@pytest.mark.parametrize(
    "text",
    [
        "Doing 60 on the motorway, a coach in the middle lane suddenly wanted my lane.",
        "Two lanes each way at 40 mph; a van in the right lane decided it wanted our lane, no signal.",
        "At 50 mph a taxi in the outside lane just took my lane without looking.",
        "Cruising at 70, a pickup in lane 2 went for my lane with no indicator.",
    ],
)
def test_a_road_user_beside_wanting_or_taking_the_ego_lane_cuts_in(text):
    assert _behaviours(text) == [["cut_in"]]


@pytest.mark.parametrize(
    "text",
    [
        "Doing 60 on the motorway, a coach in the middle lane stayed in its lane.",
        "A van behind me in my lane kept a steady gap.",
        "A cyclist ahead of me wanted to turn left, so I waited.",
    ],
)
def test_a_road_user_keeping_to_a_lane_does_not_cut_in(text):
    assert "cut_in" not in _behaviours(text)[0]


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 40 when one of the buses pulled out into my lane.",
        "One of the lorries in the left lane moved into my lane.",
        "Doing 60 when one of your drivers changed into my lane right in front of me.",
        "one of them vans swerved into our lane just ahead of us",
        "Ego at 50 km/h; one of the parked taxis pulls into the ego's lane.",
    ],
)
def test_one_of_several_named_first_is_the_subject(text):
    assert _behaviours(text)[0] == ["cut_in"]


def test_one_of_several_after_a_verb_stays_its_object():
    assert _behaviours("A van overtook one of the buses.")[0] == ["overtake"]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi cut in front of me and slammed brakes.",
        "A taxi cut in front of me and stamped on the brakes.",
        "A taxi cut in front of me and mashed the brakes.",
        "A taxi cut in front of me and hit the anchors.",
        "A taxi cut in front of me and braked heavily.",
        "A taxi cut in front of me and brake-checked me.",
    ],
)
def test_a_braking_said_with_force_after_a_cut_in_is_a_sudden_stop(text):
    assert _behaviours(text) == [["cut_in", "sudden_stop"]]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi cut in front of me and I slammed brakes.",
        "A taxi cut in front of me and I hit the anchors.",
        "A taxi cut in front of me, so I stamped on the brakes.",
        "A taxi cut in front of me and hit the kerb.",
    ],
)
def test_the_ego_pressing_the_brakes_after_a_cut_in_is_no_stop_of_the_cut_in(text):
    assert _behaviours(text) == [["cut_in"]]


@pytest.mark.parametrize(
    "text",
    [
        "A van was double-parked on the left. The car ahead of me swerved round it.",
        "The car ahead of me swerved out because a van was double parked.",
        "A lorry was double-parked outside the shop and the taxi ahead of me pulled out round it at the last minute.",
        "Delivery van double-parked, the hatchback ahead of us swung out round it late.",
    ],
)
def test_a_lead_swerving_round_a_double_parked_vehicle_cuts_out(text):
    assert ["cut_out"] in _behaviours(text)


def test_a_double_parked_vehicle_nobody_swerves_round_stays_at_the_side():
    reading = read("A child stepped out from behind a double-parked van.")
    assert [a.relation for a in reading.actors] == ["roadside_right", "roadside_right"]


@pytest.mark.parametrize(
    "text",
    [
        "The bus before ego car is stopping at the bus stop slowly.",
        "The truck before us braked hard.",
        "The van before the ego car slows down.",
        "car before me change lane very late because a broken car is standing in the lane",
        "The lorry before my car stopped suddenly.",
    ],
)
def test_before_the_ego_after_a_road_user_is_in_front_of_it(text):
    assert read(text).actors[0].relation == "ahead"


@pytest.mark.parametrize(
    "text",
    ["The car braked before I could react.", "A lorry stopped before me.", "The car before the last one stopped."],
)
def test_before_as_a_conjunction_or_after_a_verb_puts_no_one_ahead(text):
    assert read(text).actors[0].relation is None


@pytest.mark.parametrize(
    "text",
    [
        "E-scooter cut me up at the lights",
        "A cyclist cut us up at the roundabout.",
        "Some lad on a bike cut me right up at the junction.",
        "At the lights a courier on an e-bike cut the ego up.",
        "kid on a scooter cut me up at the crossroads, nearly had him",
    ],
)
def test_a_rider_cutting_the_ego_up_at_a_junction_cuts_in(text):
    assert _behaviours(text)[0] == ["cut_in"]


@pytest.mark.parametrize(
    "text",
    ["A cyclist cut across in front of me at the junction.", "At the lights a cyclist cut across my path."],
)
def test_a_rider_cutting_across_at_a_junction_still_crosses(text):
    assert _behaviours(text)[0] == ["cross_in_front"]


@pytest.mark.parametrize(
    "text",
    ["a motorbike flew right by me and cut in", "a van went right by my mirror", "she squeezed right by us"],
)
def test_right_stressing_by_is_no_side(text):
    """("right across" stays a side: "cut right across my lane to turn into a side street" turns right.)"""
    tokens = text.split()
    assert not_a_side(tokens, tokens.index("right"))


@pytest.mark.parametrize("text", ["a taxi turned right across my path", "the van swung right across two lanes"])
def test_right_after_a_verb_of_heading_stays_a_side(text):
    tokens = text.split()
    assert not not_a_side(tokens, tokens.index("right"))
