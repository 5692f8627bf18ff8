"""Form fields of witnesses and injuries, survey question numbers, a rule said to "you", a wrong-way
rider placed in a lane, and an oncoming turn across the ego's path said after where it goes."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def _read(text: str) -> list[tuple[str, str | None, list[str]]]:
    return [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in read(text).actors]


_STATEMENT = (
    "Date: 25/11/23 16:50\nVehicle A: me, Mini Cooper\nVehicle B: pedestrian\n"
    "Sketch: a pedestrian stepped off the kerb on my right without looking, I was doing 15 mph and hit him.\n"
)


@pytest.mark.parametrize(
    "field",
    [
        "Witness: driver of the tanker behind me, J. Barker 07700 900 233",
        "Witnesses: 2 people at the bus stop, details taken.",
        "Witness details: a cyclist behind me, gave email.",
        "Getuigen: tram driver stopped, name not known.",
    ],
)
def test_who_a_witness_field_names_is_no_road_user(field):
    read_as = _read(_STATEMENT + field)
    assert read_as == [("pedestrian", "roadside_right", ["cross_in_front"])]
    assert read(_STATEMENT + field).ignored  # (and the run says what it left)


def test_a_witness_field_that_tells_an_account_is_read():
    text = "Witness: a man at the stop said the van went through the red light."
    assert _read(text) == [("van", "junction_left", ["run_red_light"])]  # (the account names the road user)
    text = "Witness statement: I was driving at 30 km/h when a scooter rode onto the zebra from the right."
    assert _read(text) == [("e-scooter", "roadside_right", ["cross_in_front"])]
    text = "Witness: the hatchback was on the roundabout when a moped came in from the left and did not stop."
    assert _read(text)  # (two road users: an account, not who saw it)
    text = "LAWYER: What time was it?\nWITNESS: Evening.\nLAWYER: And then?\nWITNESS: A taxi ran the red light."
    assert _read(text) == [("car", "junction_left", ["run_red_light"])]  # (a speaker's turns)
    assert layers_from_text(text, 0)["environment"]["time_of_day"] is not None


@pytest.mark.parametrize(
    "text",
    [
        "Datum: 11-04-2024, tijd 07:55\nGewonden: ja, the cyclist has light wound on the hand\n"
        "Voertuig A: Toyota Corolla, driver me\nVoertuig B: fietser (cyclist), no registration\n"
        "B: 17 - did not respect red light\nSchets: I drive north, cyclist comes from Mauritskade from my left "
        "side crossing on red. I brake but touch him with the left front corner. Speed around 35 km/h.",
        "Date: 12 July 2024, 7.20 am\nInjuries: Yes - cyclist (B) grazed arm and shoulder\n"
        "Vehicle A: Volvo XC60, me\nVehicle B: bicycle (road bike), rider Mr Hall\nWhat happened: I came up "
        "behind the cyclist going uphill, waited, then started to overtake at about 20 mph. Cyclist says I came "
        "too close and he swerved into the verge and fell off.",
    ],
    ids=["gewonden", "injuries"],
)
def test_the_injured_named_again_in_a_field_is_the_party_named_elsewhere(text):
    assert [kind for kind, _, _ in _read(text)] == ["bicycle"]


def test_an_injuries_field_that_alone_names_a_party_keeps_it():
    text = (
        "Injuries: scooter rider cut on chin.\nI was coming out of the side street at walking pace, "
        "he was riding the wrong way and went into my front bumper."
    )
    assert "e-scooter" in [kind for kind, _, _ in _read(text)]


@pytest.mark.parametrize(
    ("text", "clock"),
    [
        ("Q7: a cyclist pulled out of a side road on my left at night. I was doing 30 mph.\nQ9: 10", "23:00"),
        ("Q7: a cyclist pulled out of a side road on my left. I was doing 30 mph.\nQ10: 17:30", "17:30"),
        ("Time of day: Night (after 9pm)\nQ7: a cyclist pulled out on my left.\nQ9: 10", "21:00"),
    ],
)
def test_a_question_number_and_its_answer_are_no_clock(text, clock):
    assert layers_from_text(text, 0)["environment"]["time_of_day"] == clock


@pytest.mark.parametrize(
    ("rule", "verb"),
    [
        ("Riding on the footpath is legal here now but you still have to give way.", None),
        ("You must stop at the kerb and look.", "look"),
        ("You should always wait for the lights.", "wait"),
    ],
)
def test_what_you_have_to_do_is_no_deed(rule, verb):
    text = "I was doing 30 km/h. An e-scooter came off the footpath on my left and across the road. " + rule
    assert _read(text) == [("e-scooter", "roadside_left", ["cross_in_front"])]
    assert verb is None or verb in read(text).ignored  # (the run says it did not use the rule's words)


def test_a_question_of_what_you_have_to_do_is_left_to_the_other_rules():
    from vei_scenario.language.norms import without_norms

    tokens = "do you have to stop for a scooter ? a van pulled out".split()
    assert without_norms(tokens, []) == tokens
    tokens = "you should have looked , the van pulled out".split()
    assert without_norms(tokens, []) == tokens


@pytest.mark.parametrize(
    "text",
    [
        "An e-scooter was going the wrong way in the fast lane of the dual carriageway. I missed it by a foot.",
        "A cyclist was riding the wrong way in the left lane. I braked.",
    ],
)
def test_a_rider_going_the_wrong_way_in_a_lane_rides_against_the_traffic(text):
    assert [b for _, _, b in _read(text)] == [["wrong_way"]]


def test_a_rider_in_a_lane_of_its_own_going_the_wrong_way_rides_along_it():
    assert _read("A cyclist was riding the wrong way in the cycle lane on my left. I braked.")[0][2] != ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming car turned right into Church Street across my path.",
        "E-scooter rider coming the other way turned right into Church St right across my path, no signal.",
        "An oncoming van turned right into the retail park entrance across me.",
    ],
)
def test_an_oncoming_turn_said_across_the_egos_path_after_where_it_goes_is_a_turn_across(text):
    assert [b for _, _, b in _read(text)] == [["turn_across"]]


def test_an_oncoming_turn_to_the_near_side_not_said_across_stays_a_turn_away():
    assert _read("An oncoming car turned right into Church Street.")[0][2] == ["forced_turn"]
    assert _read("An oncoming car turned right into the car park right in front of the bus stop.")[0][2] == [
        "forced_turn"
    ]


def test_a_motorway_junction_by_its_number_is_no_crossroads():
    text = "I was doing 60 mph on the M6 southbound just after junction 16 when a van cut in from the left lane."
    assert read(text).map_kind != "crossroad"
    assert read("At the junction a van pulled out on my left.").map_kind == "crossroad"


@pytest.mark.parametrize(
    ("text", "route"),
    [
        (
            "DC Smith: You were at the end of Conygre Road, waiting to pull out onto the A38.\nSuspect: Yeah.\n"
            "DC Smith: Which way were you going?\nSuspect: Left. Towards the town centre.\n"
            "DC Smith: The rider was on the A38, coming from your right, and hit your car.",
            "left",
        ),
        (
            "Q. Were you turning left or right?\nA. Um, right. Into Mill Lane.\nQ. And the scooter?\n"
            "A. It came towards me and I hit it.",
            "right",
        ),
    ],
)
def test_the_answer_to_which_way_is_the_egos_route(text, route):
    assert read(text).ego_route == route


@pytest.mark.parametrize(
    "text",
    [
        # the way is not the answer's first word, or not a way at all
        "Q. Which way were you going?\nA. I left the house at eight and a cyclist pulled out on my left.",
        "Q. Which way were you going?\nA. North, to work. A cyclist pulled out on my left.",
        # a question told in the story, not asked in a turn
        "I asked him which way he was going? He said left, and a cyclist pulled out on my left.",
    ],
)
def test_no_answer_of_way_is_read_where_none_is_given(text):
    from vei_scenario.language.normalise import route_answered

    assert route_answered(text) == text


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist pulled out in front of me. I swerved to avoid him and hit the metal post.",
        "A cyclist pulled out in front of me. I braked, but my van hit the kerb.",
        "A young man on an e-scooter came out from the pavement on my left. I turn the wheel right and brake, "
        "I not touch him, but my van hit the kerb of the traffic island.",
    ],
)
def test_hitting_street_furniture_to_escape_is_no_contact_with_the_road_user(text):
    assert read(text).intent == "near_miss"


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist pulled out in front of me. I braked but hit the cyclist.",
        # a passenger's fall on the bus is not the ego escaping into the pole
        "An Audi cut straight in front of the bus. Driver slammed on and an old lady banged her head on the pole.",
    ],
)
def test_contact_that_is_not_with_furniture_stays(text):
    assert read(text).intent == "collision"


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("At that junction you have to stop and a van came flying round the corner and hit my front.", "van"),
        ("You have to understand the lorry pulled out right in front of me from a side road on the left.", "truck"),
        (
            "Then you have to swerve because this idiot on a bike comes straight out of a side road on the left.",
            "bicycle",
        ),
    ],
)
def test_what_happens_after_a_rule_or_around_it_is_still_read(text, kind):
    assert [k for k, _, _ in _read(text)][:1] == [kind]


def test_a_text_told_to_you_keeps_what_you_have_to_do():
    text = "You are the ego vehicle. You have to turn left at the crossroads while an oncoming car goes straight."
    assert read(text).ego_route == "left"


@pytest.mark.parametrize(
    "text",
    [
        "Q: Which way were you looking when you pulled out?\nA: Right. I didn't see the van coming from the left.",
        "Q: Which way were you going?\nA: Not left, I was going straight on. A cyclist came out on my left.",
        "Q: Which way were you going?\nA: Right, so I was heading up the main road and a van pulled out on my left.",
    ],
)
def test_no_way_is_read_from_an_answer_that_gives_none(text):
    assert read(text).ego_route is None


@pytest.mark.parametrize(
    "text",
    [
        "Approaching the junction 30 mph, a car pulled out from the left.",
        "While waiting at the junction 3 cyclists rode through the red light from the right.",
    ],
)
def test_a_number_after_junction_that_counts_something_else_leaves_the_junction(text):
    assert read(text).map_kind == "crossroad"


@pytest.mark.parametrize(
    ("text", "read_as"),
    [
        ("Witness: the lorry ran the red light at speed.", [("truck", "junction_left", ["run_red_light"])]),
        (
            "Other party: pedestrian\nInjuries: pedestrian stepped off the kerb on my right and I hit her at about "
            "15 mph, she hurt her hip.",
            [("pedestrian", "roadside_right", ["cross_in_front"])],
        ),
    ],
)
def test_a_field_that_tells_a_deed_is_an_account(text, read_as):
    assert _read(text) == read_as


def test_a_witness_named_by_what_they_drive_is_one_witness():
    text = "I was doing 30 km/h when a scooter rode onto the zebra from the right.\nWitness: bus driver behind me."
    assert _read(text) == [("e-scooter", "roadside_right", ["cross_in_front"])]
