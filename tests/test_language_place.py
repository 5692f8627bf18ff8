"""Where each road user starts relative to the ego: the writer's side of the road said outright, the
kerb a road user is at when no side is said, and what a side said of a road user's goal (not its
start) leaves open."""

import re

import pytest
from play_layers import play_layers

from vei_scenario.language.reader import read
from vei_scenario.language.sides import drives_on_left


def relation(text: str) -> str | None:
    return read(text).actors[0].relation


def _side_started(text: str) -> str | None:
    a = read(text).actors[0]
    if a.relation in ("left", "right", "roadside_left", "roadside_right"):
        return a.relation.removeprefix("roadside_")
    if a.lateral_m:
        return "left" if a.lateral_m > 0 else "right"
    return None


def _tokens(text: str) -> list[str]:
    return re.findall(r"[a-z0-9/]+|[^\sa-z0-9]", text.lower())


@pytest.mark.parametrize(
    "text",
    [
        "We're in Dublin, 50 km/h, a courier on a bike rolls along on our inside.",
        "Setting: New Zealand, rural road at 80 km/h; a ute in the nearside lane drifts across.",
        "Sim for the Australian market (we drive on the left), ego 60 km/h.",
        "Left-hand traffic please. Ego at 40 km/h on a two-lane road.",
        "Based in Mumbai: ego at 30 km/h and an auto-rickshaw in the inside lane.",
        "Japan, city street, 30 km/h, cyclist on the nearside.",
        "Rural road, driving on the left, 70 km/h; a tractor on the nearside.",
    ],
)
def test_a_place_or_convention_of_left_hand_traffic_said_outright(text):
    """Metric speeds alone keep Euro NCAP's right-hand convention; a writer who says where the road
    is, or that traffic keeps left, is read as driving on the left whatever the unit."""
    assert drives_on_left(_tokens(text), text)


@pytest.mark.parametrize(
    "text",
    [
        "US city street, 25 mph, a cyclist on the inside.",
        "In Canada at 40 mph on the nearside.",
        "We drive on the right here: 30 mph, a van in the inside lane.",
        "On holiday in France, 50 mph, a cyclist on my inside.",
        # near misses: words that only look like a place or a convention
        "The van drove on the left lane at 60 km/h.",
        "A car driving on the left of us at 60 km/h cuts in.",
        "My English is not good: ego 30 km/h, a bike on the inside.",
        "A Japanese hatchback in the nearside lane, ego 50 km/h.",
    ],
)
def test_a_place_or_convention_of_right_hand_traffic_or_none(text):
    assert not drives_on_left(_tokens(text), text)


def test_the_pronoun_us_is_no_country():
    text = "Let us know: 30 mph, a cyclist in the inside lane."
    assert drives_on_left(_tokens(text), text)  # (miles per hour, and "us" a pronoun, not the US)


def test_two_places_of_different_conventions_say_nothing_of_the_side():
    text = "A rental in Spain on holiday from Ireland, at 50 mph; a cyclist on the inside."
    assert drives_on_left(_tokens(text), text)  # (both said: the unit decides, miles per hour)


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Ireland, 50 km/h: a cyclist came up on our inside and rode on.", "left"),
        ("Ego at 40 km/h in Sydney, Australia; a scooter nips up the inside and keeps going.", "left"),
        ("It's a UK road, 60 km/h, I'm in lane 1 and a van in the outside lane drifts into mine.", "right"),
    ],
)
def test_a_left_hand_place_sets_the_inside(text, expected):
    assert _side_started(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "Doing 25 mph, a courier on a moped shot past the test car on the inside and cut in front of us.",
        "At 30 km/h an e-scooter went past our van on the outside, then pulled in ahead of it.",
        "At 40 mph a motorbike flew past my car on the inside and swerved in right in front.",
    ],
)
def test_one_that_goes_past_the_ego_on_a_side_comes_from_behind(text):
    """ "past the ego on the inside": the verb's particle is said before its object, and the side after."""
    assert relation(text) == "behind"


def test_a_side_said_after_a_clause_break_is_no_overtake_from_behind():
    assert relation("At 20 mph, a cyclist up ahead, on the inside, keeps riding.") != "behind"


@pytest.mark.parametrize(
    "text, expected",
    [
        # the far kerb is across the road: the left one where traffic keeps right, the right one where it keeps left
        ("Ego 50 km/h. A tractor along the left verge is coming towards us.", "oncoming"),
        ("Doing 40 mph, a tractor along the right verge was coming towards us.", "oncoming"),
        ("In Ireland at 60 km/h, a lorry hugging the right kerb came towards us.", "oncoming"),
    ],
)
def test_a_vehicle_at_the_far_kerb_comes_the_other_way(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "Doing 40 mph, a tractor along the left verge slows down.",
        "In Ireland at 60 km/h, a van tucked in at the left kerb slows down.",
    ],
)
def test_a_vehicle_at_the_near_kerb_of_a_left_hand_writer_goes_the_egos_way(text):
    assert relation(text) != "oncoming"


@pytest.mark.parametrize(
    "text, expected",
    [
        # no side said: the kerb a rider rides along or a walker steps off is the writer's near one
        ("Doing 20 mph, a cyclist riding along the kerb ahead suddenly swerves into my path.", "left"),
        ("In Dublin at 30 km/h, a boy stepped off the kerb right in front of us.", "left"),
        ("Ego at 30 km/h; a boy steps off the kerb right in front of the car.", "right"),
        ("Doing 20 mph, a lad stepped off the kerb just in front of me.", "left"),
    ],
)
def test_a_kerb_with_no_side_said_is_the_near_one(text, expected):
    assert _side_started(text) == expected


@pytest.mark.parametrize(
    "text, side",
    [
        ("A cyclist riding along the kerb ahead swerves into my lane. I was at 30 km/h.", "right"),
        ("Ego 45 km/h; an e-scooter in the bike lane pulls out into our lane.", "right"),
        ("We do 40 km/h and a cyclist at the kerb cuts into our lane at 15 km/h.", "right"),
        # a writer who keeps left: the near kerb is the left one, and the rider rides the ego's way there
        ("Doing 20 mph, a cyclist riding along the kerb ahead suddenly swerves into my path.", "left"),
        ("In Dublin at 30 km/h an e-scooter riding by the kerb pulls out into our lane.", "left"),
    ],
)
def test_a_rider_at_the_kerb_who_swerves_in_rides_along_it_first_and_plays(text, side, tmp_path):
    """A rider at the kerb (no side said: the near one) keeps its pace before it swerves into the ego's
    lane, and the scenario plays: it starts on the kerb lane's edge and ends ahead in the ego's lane."""
    from vei_scenario.language.corpus_check import played_problems
    from vei_scenario.language.rules_backend import layers_from_text

    layers = layers_from_text(text, 0)
    adv = layers["adversaries"][0]
    assert adv["spawn"]["relation"] == f"roadside_{side}" and adv["speed_mps"] > 1.0
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []


@pytest.mark.parametrize(
    "text",
    [
        "Doing 15 mph past the shops, a cyclist nipped up the inside of me and kept going.",
        "At 10 km/h in the queue, an e-scooter came up on our inside along the kerb and rode on.",
        "Crawling at 8 mph when a cyclist rolled up behind me on the left and carried on.",
    ],
)
def test_one_going_along_the_road_from_behind_starts_behind_and_comes_up(text):
    """The layers keep a rider going along the road where the reader put it: behind the ego, and
    faster than it (it comes up), not ahead of it."""
    from vei_scenario.language.rules_backend import layers_from_text

    for seed in (0, 1):
        adv = layers_from_text(text, seed)["adversaries"][0]
        assert adv["spawn"]["relation"] == "behind" and adv["spawn"]["longitudinal_m"] < 0
        assert adv["speed_mps"] > layers_from_text(text, seed)["ego"]["speed_mps"]


@pytest.mark.parametrize(
    "text, expected",
    [
        # a bare nearside / offside said of a driver is the lane on that side; of a walker, that kerb
        ("Doing 50 mph, a car on the offside drifted into my lane.", "right"),
        ("At 60 km/h a van on the nearside came across into our lane.", "right"),
        ("Doing 40 mph when a hatchback on the nearside swerved into me.", "left"),
    ],
)
def test_a_bare_near_or_offside_of_a_driver_is_a_lane_beside_the_ego(text, expected):
    assert relation(text) == expected


def test_a_bare_offside_of_a_walker_is_still_the_far_kerb():
    assert relation("At 25 mph a jogger stepped off the offside straight in front of me.") == "roadside_right"


@pytest.mark.parametrize(
    "text",
    [
        "Doing 20 mph, a cyclist at the right kerb pulls out into my lane to pass a parked van.",
        "In London at 30 km/h, an e-scooter in the cycle lane on our right cuts into our lane.",
    ],
)
def test_a_rider_at_the_kerb_who_swerves_in_goes_the_egos_way(text):
    """A rider at a kerb swerving into the ego's lane rides beside it, not against it, for a writer who
    keeps left too: the right kerb is said of where it is, not of the traffic across the road."""
    actor = read(text).actors[0]
    assert actor.relation in ("right", "roadside_right") and actor.behaviours[0][0] != "wrong_way"


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Ego 40 km/h in the right lane; a taxi in the left lane darts across us to reach the exit.", "left"),
        ("Two lanes, 30 mph, a hatchback in the right lane dived in front of me to get the exit.", "right"),
        ("Ego 60 km/h in lane 1; a van in lane 2 cuts across us heading for the exit.", "left"),
    ],
)
def test_an_exit_a_road_user_makes_for_is_where_it_goes_not_where_it_comes_from(text, expected):
    """ "to take the exit", "heading for the exit": the exit is the object of where it goes; it starts in
    its lane beside the ego, not on a junction arm."""
    assert relation(text) == expected


def test_an_exit_it_comes_out_of_is_still_its_arm():
    assert relation("At the junction, ego 30 km/h, a van pulls out of the exit on our left in front of us.") == (
        "junction_left"
    )


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 70 km/h on a country road. On the bend a van is coming on our lane because it is overtaking a tractor.",
        "Doing 50 mph, a car was coming down my lane, passing a lorry.",
        "Ego 60 km/h; a motorbike comes along the ego's lane while it overtakes a bus.",
        "At 40 km/h a truck heading at us in our lane.",
    ],
)
def test_one_coming_in_the_egos_lane_comes_towards_it(text):
    """ "coming on our lane", "comes along the ego's lane": coming in the ego's own lane is coming at it."""
    assert relation(text) in ("oncoming", "junction_opposite")


@pytest.mark.parametrize(
    "text",
    [
        "Ego 50 km/h; a van coming at 40 km/h cuts in ahead of us.",  # (a speed, not at the ego)
        "Ego 50 km/h; a van came into our lane from the left.",  # (into: a cut-in)
        "Ego 30 km/h; a cyclist is coming up behind us in our lane.",
    ],
)
def test_coming_into_or_behind_or_at_a_speed_is_not_towards_the_ego(text):
    assert relation(text) != "oncoming"


def test_arriving_in_the_egos_lane_after_passing_it_is_no_oncoming():
    text = "Ego 60 km/h, a van overtakes me and once it came in my lane it braked hard."
    assert relation(text) != "oncoming"


@pytest.mark.parametrize(
    "text, expected",
    [
        ("ego 30 km/h, car from side road R pulls out in front", "junction_right"),
        ("host 40 km/h | van out of junction L into our path ~10 m ahead", "junction_left"),
        ("Ego at 30 km/h; a car from the junction on the right pulls out in front of us.", "junction_right"),
        ("ego 25 km/h, kid steps off kerb R in front", "roadside_right"),
    ],
)
def test_a_side_said_after_the_place_it_names(text, expected):
    """ "junction L", "side road R", "from the junction on the right": the side of the road it comes out of."""
    assert relation(text) == expected


def test_a_junction_said_only_as_where_the_ego_is_names_no_side():
    assert relation("At the junction at 40 km/h, a car in the right lane slows down.") == "right"


# an exit said as where a road user goes with an ordinal or an adjective before it ("to take the next
# exit", "heading for the 2nd exit", "to get to the same exit as me"), or said as where it does not go
# ("not exiting", "without taking the exit"), is no arm it comes out of: it starts beside the ego
EXIT_GONE_TO_PAST_ITS_MODIFIERS = [
    (
        "On the roundabout at 20 mph a cyclist in the cycle lane on my left swerved across my bonnet to get "
        "to the second exit.",
        "left",
    ),
    (
        "Going round the roundabout in the right lane, a taxi in the left lane cut in front of us to take the "
        "next exit.",
        "left",
    ),
    (
        "On the roundabout, ego circulating at 25 km/h; a van on our right cuts across us heading for the 2nd exit.",
        "right",
    ),
    ("At the roundabout a motorbike on my left swerved in front of me towards the third exit.", "left"),
    (
        "Mini-roundabout, 15 mph: a taxi beside me in the right-hand lane swung over in front of me to make the "
        "same exit as me.",
        "right",
    ),
    (
        "Roundabout, 2 lanes, ego takes the 1st exit at 20 km/h; a car in the lane on the ego's left keeps "
        "going round, not exiting.",
        "left",
    ),
    (
        "Ego on the roundabout at 30 km/h, a cyclist in the cycle lane on my right carried on round without "
        "taking the next exit.",
        "right",
    ),
]


@pytest.mark.parametrize("text, side", EXIT_GONE_TO_PAST_ITS_MODIFIERS)
def test_an_exit_gone_to_past_an_ordinal_is_no_arm_it_comes_from(text, side):
    assert _side_started(text) == side, relation(text)


# near misses: an exit or entry said as where a road user comes out of or from, ordinal or not, is its arm
EXIT_COME_FROM = [
    ("At the roundabout, ego 30 km/h, a van pulls out of the second exit on our left in front of us.", "junction_left"),
    ("On the roundabout at 20 mph a lorry came out from the next entry on my right.", "junction_right"),
]


@pytest.mark.parametrize("text, expected", EXIT_COME_FROM)
def test_an_exit_come_from_past_an_ordinal_is_still_its_arm(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "At 20 mph, a cyclist ahead of me suddenly swung right into the second side road on the right.",
        "Ego 30 km/h; the scooter in front of us turns left into the next side street without signalling.",
    ],
)
def test_a_side_road_turned_into_past_an_ordinal_is_where_the_one_ahead_goes(text):
    """ "into the second side road": where the road user ahead turns off, not an arm it comes out of."""
    actor = read(text).actors[0]
    assert actor.relation == "ahead" and actor.behaviours[0][0] == "forced_turn", actor.relation


# a test line's or a terse note's side in brackets right after the place a road user comes out of
# ("pulls out of stop (left)", "out of a parking space (R)") is that place's side, as "on the left" is
PLACE_SIDE_IN_BRACKETS = [
    ("Ego 40 km/h, bus pulls out of stop (left) 25 m ahead.", "roadside_left"),
    ("Ego 40 km/h, a car pulls out of a parking space (L) 20 m ahead.", "roadside_left"),
    ("ego 30 mph; delivery van pulls out of a loading bay (right), 15 m ahead", "roadside_right"),
    ("Ego 30 mph. Coach pulls out of the bus stop (right-hand) and merges in front of ego.", "roadside_right"),
    ("At 30 km/h a taxi pulled out of the lay-by (L) right in front of me.", "roadside_left"),
]


@pytest.mark.parametrize("text, expected", PLACE_SIDE_IN_BRACKETS)
def test_a_side_in_brackets_after_a_place_is_its_side(text, expected):
    assert relation(text) == expected


# near misses: a bracket that says something else (a name, a note) leaves the writer's near kerb, and so
# does a side in brackets that is not right after the place
PLACE_BRACKET_NEAR_MISSES = [
    ("Ego 40 km/h, bus pulls out of stop (route 12) 25 m ahead.", "roadside_right"),
    ("Ego 40 km/h, bus pulls out of stop 25 m ahead (left lane closed).", "roadside_right"),
]


@pytest.mark.parametrize("text, expected", PLACE_BRACKET_NEAR_MISSES)
def test_a_bracket_that_is_no_side_leaves_the_place_as_it_was(text, expected):
    assert relation(text) == expected
