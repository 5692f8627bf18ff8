"""Where the ego goes at a junction (:mod:`vei_scenario.language.route`): read from the clauses whose
subject is the ego, never from another road user's turn. Each group is one construction, in wordings
written for it (none taken from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import _tokens, read
from vei_scenario.language.route import ego_route

# a participle or a verb after "and" with no subject of its own: the subject of the clause before it
INHERITED = {
    "left": [
        "I was easing round the gyratory at 10 mph, bearing left for the retail park, when a skater rolled out.",
        "We came up to the lights and swung left onto Quay Street as a jogger stepped out.",
        "The ego slows for the junction, then turns left towards the station; a pedestrian waits on the corner.",
    ],
    "right": [
        "I slowed at the crossroads, turning right behind a bus, and a cyclist came down the outside.",
        "The test vehicle approaches the T-junction at 20 km/h and turns to the right.",
        "We were at the lights by the bakery, making a right turn, when a lad on a scooter shot across.",
    ],
}
# a narrator's sentence that opens with the turn: the narrator turns
NARRATOR = {
    "right": [
        "Turning right into the industrial estate, a forklift reversed out in front of me.",
        "Hanging a right at the chapel, I spotted a dog loose on the verge.",
        "Taking the next right off the bypass, I met a cyclist coming the wrong way.",
    ],
    "left": [
        "Turning left out of the car park, a kid on a bike came along the pavement towards me.",
        "Made a left at the church and a woman with a buggy was halfway over the road in front of me.",
        "Bearing left at the fork at about 15 mph, I saw a horse rider ahead of me.",
        "We went left at the mini-roundabout and a cyclist came round towards us.",
    ],
}
# the ego named by a noun, before the verb or as the subject of a copula whose complement turns;
# an infinitive shares the subject of the verb it completes
NAMED = {
    "left": [
        "The host vehicle is a minibus turning left at a signalised crossroads at 12 km/h.",
        "I'm sitting at the give-way line waiting to turn left, and a cyclist passes along the main road.",
        "Our car pulls up at the junction to turn left while a pedestrian crosses the side road.",
    ],
    "right": [
        "VUT turns at right at the crossing, a pedestrian is on the far kerb.",
        "The ego Volvo XC60 arrived at the junction and turned right, a cyclist was coming the other way.",
        "Ego 25 km/h, crossroads, turning R, oncoming cyclist.",
    ],
}
# "a left turn" as the object of the ego's verb; an opening participle takes the main clause's subject
TURN_NOUN_AND_OPENING = {
    "left": [
        "The ego performs a left turn at the signalised junction while a pedestrian waits.",
        "While turning left, the test vehicle meets a cyclist on the inside.",
        "Pulling away from the lights to go left, I spotted a jogger on the crossing.",
    ],
    "right": [
        "The subject vehicle executes a right turn into the side road at 12 km/h.",
        "Before turning right, the ego slows to 15 km/h for a pedestrian.",
        "We completed the right turn onto the high street as a moped came past.",
    ],
    None: [
        "The van ahead of the ego sits in the left turn lane.",
        "While turning right, a cyclist cuts across the ego's path.",
    ],
}
# another road user's turn is its own, however it is said: the ego's route is not read from it
OTHERS = {
    None: [
        "A van coming the other way made a right across my lane into the garage forecourt.",
        "I was heading into town when the cyclist ahead of me turned left without signalling.",
        "The lorry in front swung left into the yard and I slowed behind it.",
        "I waited at the lights for the bus to turn right.",
        "A moped pulled right in front of me at the junction.",
        "I braked but the van went right into the back of the taxi.",
    ],
}


def _cases(*groups: dict) -> list:
    return [(text, route) for group in groups for route, texts in group.items() for text in texts]


@pytest.mark.parametrize("text, route", _cases(INHERITED, NARRATOR, NAMED, TURN_NOUN_AND_OPENING, OTHERS))
def test_the_ego_route_is_read_from_the_ego_clauses(text, route):
    assert ego_route(_tokens(text)) == route


@pytest.mark.parametrize("text, route", _cases(INHERITED, NARRATOR, NAMED))
def test_the_reader_takes_the_ego_route(text, route):
    assert read(text).ego_route == route


# the ego turning left or right turns at a junction, whatever the road was called
TURN_AT_A_JUNCTION = [
    "Made a right onto Elm Street at 15 mph when a kid on a scooter came off the kerb on my left.",
    "I turned left into Rope Walk, a narrow street, and a dog ran out from between parked cars.",
    "On a straight road the ego turns right into a driveway while a cyclist comes the other way.",
]


@pytest.mark.parametrize("text", TURN_AT_A_JUNCTION)
def test_the_ego_turning_turns_at_a_junction(text):
    assert read(text).map_kind == "crossroad"


# the turn as the object of a verb of carrying out a manoeuvre, with adjectives before the direction;
# an exit or turning taken or a roundabout left towards a side; "go/bear right at" a place is a turn
MANOEUVRE_AND_EXIT = {
    "left": [
        "The ego shuttle is performing a protected left at the lights when a jogger steps off the kerb.",
        "Ego attempts a slow left into the car park at 10 km/h; a cyclist comes up on the inside.",
        "I took the second exit on the left at the gyratory and a moped came round behind me.",
        "We came off the roundabout to the left at 15 mph as a walker stepped onto the zebra.",
        "Ego exits the traffic circle left at 20 km/h and a scooter rider crosses the exit.",
    ],
    "right": [
        "Our car begins a wide right across the junction at 12 mph while a van comes the other way.",
        "I took the next turning on the right and a child ran out from behind a parked car.",
        "The ego leaves the roundabout towards the right at 25 km/h; a cyclist follows it.",
        "The ego slows to go right at the crossroads while a bus approaches from the other side.",
        "I was bearing right at the junction at 10 mph when a jogger crossed in front of me.",
    ],
    None: [
        "A van performing a quick left into the yard cut across in front of me.",
        "I left the roundabout behind and a lorry on my right drifted into my lane.",
        "The cyclist took the exit on the right and I carried on round.",
        "A scooter went right at me at the junction.",
        "A motorbike came right at us at the roundabout.",
    ],
}


@pytest.mark.parametrize("text, route", _cases(MANOEUVRE_AND_EXIT))
def test_a_manoeuvre_an_exit_or_a_way_off_the_roundabout_is_the_ego_turn(text, route):
    assert ego_route(_tokens(text)) == route


@pytest.mark.parametrize(
    "text, route",
    [
        ("Run 12 ego turning left at the crossroads, a cyclist comes the other way.", "left"),
        ("Event 3051 AV executing an unprotected right at a signalised junction; an oncoming moped.", "right"),
        ("Log 7 VUT turns right at the T-junction as a pedestrian crosses.", "right"),
    ],
    ids=["run-12-ego", "event-av", "log-vut"],
)
def test_a_label_number_before_the_egos_name_leaves_the_turn_the_egos(text, route):
    assert read(text).ego_route == route


@pytest.mark.parametrize(
    "text, route",
    [
        ("Shuttle bus (reporting vehicle) turning right at the lights when a cyclist crossed in front of it.", "right"),
        ("Delivery van (our driver) turning left into a side road as a jogger stepped off the kerb.", "left"),
    ],
    ids=["reporting-vehicle", "our-driver"],
)
def test_a_turn_of_the_vehicle_a_report_names_as_its_own_is_the_egos(text, route):
    assert read(text).ego_route == route


@pytest.mark.parametrize(
    "text",
    [
        "Lane 3 car turns left in front of the ego at the junction.",
        "At 4 the bus turns right across the ego's path.",
    ],
    ids=["lane-3-car", "at-4-bus"],
)
def test_a_number_before_another_road_user_keeps_its_turn_its_own(text):
    assert read(text).ego_route in (None, "straight")


@pytest.mark.parametrize(
    "text, route",
    [
        ("We went left at 20 km/h into the side road when a jogger stepped out.", "left"),
        ("I go right at about 30 km/h at the junction and a cyclist comes the other way.", "right"),
        (
            "Taxi entering the roundabout to go right at 15 mph. A moped already going round came from the left "
            "and our driver braked.",
            "right",
        ),
    ],
    ids=["went-left-at-20", "go-right-at-about-30", "taxi-our-driver"],
)
def test_going_left_or_right_at_a_speed_is_a_turn(text, route):
    assert read(text).ego_route == route


def test_going_right_at_someone_is_no_turn():
    assert read("I was cycling along when a van went right at me.").ego_route in (None, "straight")


# the ego waiting in a lane kept for a turn: that turn is its route
TURN_LANE = {
    "right": [
        "I was in the right-turn lane at the lights when a moped came through on red.",
        "We were sat in the right filter lane and a bus overshot the stop line.",
        "Ego queues in the right turning lane; an oncoming van jumps the amber.",
        "I was on the right filter when a cyclist came the wrong way.",
    ],
    "left": [
        "I was queuing in the left-turn lane when a scooter squeezed up my inside.",
        "Stopped in the left-turn-only lane, I saw a jogger step onto the crossing.",
        "The host vehicle waits in the left turn pocket while a cyclist rides past.",
    ],
}
# a lane named by its side, or someone else's turn lane: no route of the ego
TURN_LANE_NOT = [
    "I was in the right lane on the dual carriageway when a van undertook me.",
    "A van in the right-turn lane pulled out in front of me.",
    "The right-turn lane was closed, so I carried on and a cyclist came past.",
]


@pytest.mark.parametrize("route, text", [(r, t) for r, texts in TURN_LANE.items() for t in texts])
def test_the_ego_in_a_turn_lane_turns_that_way(route, text):
    assert ego_route(_tokens(text)) == route


@pytest.mark.parametrize("text", TURN_LANE_NOT)
def test_a_side_lane_or_anothers_turn_lane_is_no_route(text):
    assert ego_route(_tokens(text)) is None


# the ego signalling a turn: that turn is its route
SIGNALLING = {
    "left": [
        "I indicated left and started to turn when a cyclist appeared on my inside.",
        "I had my left indicator on at the junction and a scooter came up the pavement.",
        "Ego signals left at the T-junction as a pedestrian steps off the kerb.",
    ],
    "right": [
        "I was signalling right at the crossroads and a van overtook me.",
        "Sat at the lights with my right blinker on, a motorbike came through.",
        "We were indicating right into the garage forecourt when the bus behind us pulled out.",
    ],
}
# a signal for a lane change or for pulling over, or someone else's: no route of the ego
SIGNALLING_NOT = [
    "I indicated right to overtake the tractor and a motorbike was already alongside.",
    "I signalled left and pulled over to let the ambulance through.",
    "I indicated left to pull in at the bus stop.",
    "I signalled left and tucked in behind the lorry.",
    "The van indicated left but then went straight on in front of me.",
    "I was indicating right to change lanes when a car came up fast behind.",
]


@pytest.mark.parametrize("route, text", [(r, t) for r, texts in SIGNALLING.items() for t in texts])
def test_the_ego_signalling_a_turn_turns_that_way(route, text):
    assert ego_route(_tokens(text)) == route


@pytest.mark.parametrize("text", SIGNALLING_NOT)
def test_a_signal_to_change_lanes_or_anothers_is_no_route(text):
    assert ego_route(_tokens(text)) is None


# an instruction to the reader (a test spec, a study's briefing, a driving lesson): the ego's turn,
# whoever is named after it, with "please", after a place it is done at, or opening its sentence
INSTRUCTION = {
    "left": [
        "Please turn left when your signal shows green. A cyclist will come towards you from the far side.",
        "At the second junction, kindly turn left once the way is clear; a jogger crosses the side road.",
        "At the roundabout take the second exit on the left. A moped is already circulating.",
        "Participants: pls turn left when you feel it is safe. An e-scooter rider approaches from ahead.",
        "At the lights turn left, and watch for the cyclist coming the other way.",
    ],
    "right": [
        "At the T-junction, please turn right when the arrow lights up. A pedestrian steps off the kerb.",
        "Bear right at the fork, then a lorry comes round the bend towards you.",
        "Now make a right into the car park while a child runs out from between the cars.",
        "On reaching the crossroads, please turn right after your light goes green; an oncoming biker runs the red.",
        "Go right at the lights when your phase is green. A van coming the other way does not stop.",
    ],
}
# a turn that is someone else's, or a participle whose subject comes after it: no instruction
INSTRUCTION_NOT = [
    "Turning left at the lights, the lorry clipped a cyclist on its inside.",
    "A lorry turned left across a cyclist at the lights.",
    "The van stopped and then turned left into the yard, and a jogger stepped out.",
    "At the junction the bus turns left across a cyclist.",
    "Please note that a van turned right across the cyclist.",
]


@pytest.mark.parametrize("route, text", [(r, t) for r, texts in INSTRUCTION.items() for t in texts])
def test_an_instruction_to_turn_is_the_egos_route(route, text):
    assert read(text).ego_route == route


@pytest.mark.parametrize("route, text", [(r, t) for r, texts in INSTRUCTION.items() for t in texts[:2]])
def test_an_instructions_turn_is_no_one_elses(route, text):
    assert not any(b[0] in ("forced_turn", "turn_across") for a in read(text).actors for b in a.behaviours)


@pytest.mark.parametrize("text", INSTRUCTION_NOT)
def test_another_road_users_turn_is_no_instruction(text):
    assert ego_route(_tokens(text)) is None


# a turn said as a noun opening a sentence of a narrator's story: the narrator's turn
TURN_NOUN = {
    "left": [
        "Left turn at the lights, green arrow, all good, and then a car from the other way ran the red on me.",
        "Left turn into the shopping centre. I'd just started to go when a kid on a bike shot across.",
    ],
    "right": [
        "Right turn onto Main Street, I had the filter and a cyclist came straight through.",
        "Right turn here. We had the green and a bus came the wrong way.",
    ],
}
TURN_NOUN_NOT = [
    "Left turn lane was backed up so I stayed straight on, and a van cut across me.",
    "Right turn across a cyclist by a lorry at the junction; nobody hurt.",
]


@pytest.mark.parametrize("route, text", [(r, t) for r, texts in TURN_NOUN.items() for t in texts])
def test_a_narrators_turn_said_as_a_noun_is_the_route(route, text):
    assert ego_route(_tokens(text)) == route


@pytest.mark.parametrize("text", TURN_NOUN_NOT)
def test_a_turn_lane_or_a_reports_turn_noun_is_no_route(text):
    assert ego_route(_tokens(text)) is None


# an exit or turning taken by its number, any of the ordinals a roundabout or a road has
@pytest.mark.parametrize(
    "text, route",
    [
        ("I took the third exit on the right and a cyclist was already on the roundabout.", "right"),
        ("We take the 4th exit to the right while a moped circulates.", "right"),
        ("I took the last turning on the left and a jogger stepped out.", "left"),
        ("I took the 3rd road on the left when a van came the other way.", "left"),
    ],
)
def test_an_exit_taken_by_its_number_is_a_turn(text, route):
    assert ego_route(_tokens(text)) == route


def test_another_taking_a_numbered_exit_is_no_route():
    assert ego_route(_tokens("A van took the third exit on the left across my path.")) is None


# a test spec's or a terse note's wording of the ego's turn: the side of an exit in brackets, "me" as
# the subject of a note that leaves out "I", and any of the ego's names the reader knows (a spec's
# "vehicle under test", "automated vehicle", "robotaxi"); near misses: another road user's exit or turn
TERSE = {
    "left": [
        "Ego: takes 1st exit (left) @ 25 kph. Target: cyclist on ego's left, going round.",
        "Roundabout, one lane. Host vehicle takes exit 1 (left); a pedestrian waits at the exit.",
        "SUT: leaves at the first exit (L) at 15 km/h, e-scooter on its nearside.",
        "me going left at the mini roundabout, cyclist came round from the right, braked",
        "Me turning left into the car park, lad on a scooter on the pavement rolled out",
        "The robotaxi begins a left turn into Quay Street while a jogger steps off the kerb.",
        "Automated vehicle shall not start a left turn while a cyclist is alongside on the nearside.",
    ],
    "right": [
        "Ego vehicle takes the 3rd exit (right) at 30 km/h; a pedestrian crosses the exit.",
        "Ego: exit 3 (R) at 20 km/h, moped circulating on its left.",
        "T-junction. me going right, van coming from the left, gave way",
        "xroads by the church. me turning R, oncoming bike going str8 on, i waited for it",
        "The vehicle under test shall not commence a right turn across an oncoming motorcycle at 40 km/h.",
    ],
    None: [
        "Ego goes round at 20 km/h; a cyclist takes the 1st exit (left) in front of it.",
        "A van took exit 2 (right) and I carried on round at 15 km/h.",
        "the car behind me turning left, i went straight on, a jogger crossed",
        "He saw me and a scooter turning right cut across the junction.",
        "A van behind the test vehicle turns right at the junction as a cyclist passes.",
        "I was going round the roundabout, the exit on the right was shut, a cyclist cut across.",
        "Target: moped takes exit 2 (R) at 30 km/h. Ego: goes round at 20 km/h.",
    ],
}


@pytest.mark.parametrize("text, route", _cases(TERSE))
def test_a_spec_or_a_terse_note_says_the_ego_turn(text, route):
    assert ego_route(_tokens(text)) == route


@pytest.mark.parametrize(
    "text, route",
    [
        ("The ADS shall not initiate a right turn across an oncoming cyclist approaching at 20 km/h.", "right"),
        ("ADS-equipped vehicle turning left at a signalised crossroads; a cyclist alongside on the nearside.", "left"),
        ("The automated driving system must not begin a right turn across an oncoming moped.", "right"),
    ],
    ids=["ads", "ads-equipped", "automated-driving-system"],
)
def test_a_specs_automated_driving_system_is_the_ego_and_its_turn_the_egos(text, route):
    reading = read(text)
    assert reading.ego_route == route
    assert all(b[0] != "forced_turn" for a in reading.actors for b in a.behaviours)


def test_ads_as_a_word_of_a_vehicle_is_no_ego():
    reading = read("A bus covered in ads turned left across a cyclist.")
    assert reading.ego_route is None and len(reading.actors) == 2
