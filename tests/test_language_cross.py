"""A road user coming into the road from its side and across or into the ego's path: the class of
its move and where it starts. Wordings written for each construction, none taken from a corpus; each
group has near misses that look alike and must not be read so."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _one(text: str):
    (actor,) = read(text).actors
    return actor


def _names(text: str) -> list[str]:
    return [b[0] for b in _one(text).behaviours]


# "VERB the red (light)": any verb with the red as its object runs it (the verb says only how).
@pytest.mark.parametrize(
    "text",
    [
        "Doing 30 mph through town when a courier on a scooter shot the red at the crossroads in front of me.",
        "We were at 40 km/h and a taxi blasted the red light at the next junction, right across our bows.",
        "At the lights on Park Lane a cyclist barrelled the red as I drove through at 25 mph and I nearly hit him.",
    ],
)
def test_a_verb_with_the_red_as_its_object_runs_it(text):
    actor = _one(text)
    assert actor.behaviours[0][0] == "run_red_light"
    assert actor.relation.startswith("junction_")


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30 mph when a van overtook the red car ahead of me and cut in.",
        "A cyclist waited at the red while I drove through at 25 mph.",
    ],
)
def test_the_red_as_a_colour_or_a_place_to_wait_is_no_run(text):
    assert "run_red_light" not in [b[0] for a in read(text).actors for b in a.behaviours]


# "have/get + a road user + a bare verb": the road user does the verb, not the one who "had" it.
@pytest.mark.parametrize(
    ("text", "expected", "relation"),
    [
        (
            "We had a van pull out of a side street on the left right in front of us at the crossroads.",
            "turn_into",
            "junction_left",
        ),
        (
            "I had a lad on a bike roll off the kerb on the right into my path at 20 mph.",
            "cross_in_front",
            "roadside_right",
        ),
        (
            "At 15 mph I had a cyclist come out of a driveway on the left just in front of me.",
            "cross_in_front",  # (a rider out of a place beside the road crosses: test_language_off_a_place)
            "roadside_left",
        ),
    ],
)
def test_a_road_user_had_doing_something_does_it(text, expected, relation):
    actor = _one(text)
    assert actor.behaviours[0][0] == expected
    assert actor.relation == relation


def test_having_a_road_user_with_no_verb_after_it_is_no_act_of_its():
    reading = read("I had a cyclist ahead of me at 20 km/h and I overtook him at 40 km/h.")
    (actor,) = reading.actors
    assert actor.behaviours[0][0] in ("along_road", "keep_going", "keep_lane")


# "... and (straight) out across / into the road": a verbless conjunct goes on with its subject's move.
@pytest.mark.parametrize(
    "text",
    [
        "A boy on a scooter came racing along the pavement on the right and straight out across the road ahead of me.",
        "A woman hurried down the footpath on the left and out into the street in front of us at 20 mph.",
        "A kid on a bike pelted along the sidewalk on the left then straight out across the road ahead of my car.",
    ],
)
def test_out_across_the_road_after_going_along_the_footway_is_a_crossing(text):
    assert _names(text)[0] == "cross_in_front"


def test_going_along_the_footway_without_coming_out_is_no_crossing():
    names = _names("A boy on a scooter came racing along the pavement on the right as I drove past at 20 mph.")
    assert "cross_in_front" not in names


# "came out of a driveway / gate / bus stop and crossed": one crossing from that side, not a cut-in first.
@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("A girl on a scooter rolled out of a garden gate on the left and crossed in front of us at 20 mph.", "left"),
        ("A man walked out from the bus stop on my right and crossed just ahead of the car.", "right"),
        ("An old man on a bicycle came out of a farm track on the left and rode across the lane ahead of us.", "left"),
    ],
)
def test_out_of_a_roadside_place_then_across_is_one_crossing(text, side):
    actor = _one(text)
    assert [b[0] for b in actor.behaviours] == ["cross_in_front"]
    assert actor.relation == f"roadside_{side}"


def test_a_vehicle_out_of_a_driveway_then_across_is_not_a_walkers_crossing():
    names = _names("A van reversed out of a driveway on the left and crossed into my lane at 10 mph.")
    assert names[0] != "cross_in_front"


# "out of the junction / intersection": the junction as what one comes out of is one of its arms.
@pytest.mark.parametrize(
    "text",
    [
        "I was doing 25 mph when a lad on a scooter shot out of the junction without stopping and I hit him.",
        "A cyclist came flying out of the intersection just in front of me while I was at 30 km/h.",
        "At 20 mph a girl on an e-scooter rode out from the crossroads straight into my path.",
    ],
)
def test_a_rider_out_of_the_junction_comes_from_an_arm(text):
    actor = _one(text)
    assert actor.relation.startswith("junction_")
    assert actor.behaviours[0][0] in ("run_red_light", "turn_into", "cross_in_front")


@pytest.mark.parametrize(
    "text",
    [
        "I came out of the junction at 20 mph and a cyclist was riding along ahead of me.",
        "At the junction a woman stepped off the kerb on my left in front of me as I drove at 20 mph.",
    ],
)
def test_the_ego_out_of_the_junction_or_a_kerb_at_it_is_no_arm_of_the_road_user(text):
    assert not _one(text).relation.startswith("junction_")


# A walker or rider in or on a foot crossing (crosswalk, zebra, pelican) is crossing the road on it.
@pytest.mark.parametrize(
    "text",
    [
        "I was turning left on green at 15 mph and hit a pedestrian in the crosswalk.",
        "Turning right at the lights, I nearly hit a man on the zebra crossing.",
        "At 20 mph I clipped a kid on a bike on the pelican crossing.",
    ],
)
def test_a_walker_on_a_foot_crossing_crosses(text):
    actor = _one(text)
    assert actor.behaviours[0][0] == "cross_in_front"
    assert actor.relation.startswith("roadside_")


@pytest.mark.parametrize(
    "text",
    [
        "A pedestrian waiting at the crosswalk stepped back as I passed at 20 mph.",
        "A cyclist rode past the zebra crossing ahead of me at 15 km/h while I followed at 20 km/h.",
        "A woman by the zebra crossing waited for me to pass at 20 mph.",
    ],
)
def test_a_walker_beside_a_foot_crossing_does_not_cross(text):
    assert _one(text).behaviours[0][0] != "cross_in_front"


# "out of" a place beside the road is where the road user comes from, as "from" and "off" are: into a
# lane of a side, it came out of the kerb beside that lane.
@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("A cyclist came out of the hard shoulder into the left lane just ahead of us at 60 km/h.", "left"),
        ("A boy on a scooter rolled out of the verge into the right lane in front of my car.", "right"),
        ("A jogger ran out of the gravel shoulder into the left lane ahead of me as I drove at 40 km/h.", "left"),
    ],
)
def test_out_of_the_side_into_a_lane_starts_beside_that_lane(text, side):
    assert _one(text).relation == f"roadside_{side}"


def test_riding_along_the_shoulder_is_no_coming_out_of_it():
    actor = _one("A cyclist rode along the hard shoulder on the left as I passed at 60 km/h.")
    assert [b[0] for b in actor.behaviours] == ["along_road"]


# "It" stands for the roundabout once one is said, in the plural too ("roundabouts today ... onto it").
@pytest.mark.parametrize(
    "text",
    [
        "Roundabouts scare me. Yesterday I was going round one at 20 mph and a cyclist rode straight onto it in "
        "front of me.",
        "Practised roundabouts with my instructor. Halfway round the big one at 15 mph, a van shot onto it right "
        "in front of us.",
        "Mini-roundabouts are the worst: I was halfway round one at 10 mph when a scooter rolled onto it ahead of me.",
    ],
)
def test_onto_it_after_roundabouts_is_entering_from_an_arm(text):
    actor = _one(text)
    assert actor.relation.startswith("junction_")
    assert actor.behaviours[0][0] in ("run_red_light", "turn_into", "cross_in_front")


def test_roundabouts_said_with_no_entry_is_no_entry():
    actor = _one("Roundabouts are fine. A cyclist rode along the road ahead of me at 15 km/h while I followed at 20.")
    assert actor.behaviours[0][0] == "along_road"


# "let / see / watch + a road user + a bare verb", "allow / wait for + a road user + to + verb": the road
# user does the verb (it is the object of the first verb but the subject of the second).
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Doing 20 mph, I pulled up at the zebra to let an old man with a stick cross.", "cross_in_front"),
        ("We were at 30 km/h and braked to allow a cyclist to cross ahead of us.", "cross_in_front"),
        ("I slowed right down and waited for a woman with a buggy to cross the road.", "cross_in_front"),
        ("At 25 mph I watched a lad on a scooter dart out from behind a bus.", "cross_in_front"),
        ("I saw a lorry pull out of the side road on the left right in front of me.", "turn_into"),
    ],
)
def test_a_road_user_let_or_seen_doing_something_does_it(text, expected):
    assert _names(text)[0] == expected


@pytest.mark.parametrize(
    "text",
    [
        "I saw a cyclist ahead of me at 20 km/h and overtook him.",
        "I let a taxi out of the rank and followed it at 30 km/h.",
        "We waited for a bus behind the stop line, then went at 20 km/h.",
    ],
)
def test_a_road_user_let_or_seen_with_no_verb_of_its_own_is_no_act_of_its(text):
    assert "cross_in_front" not in [b[0] for a in read(text).actors for b in a.behaviours]


# What the narrator does after a road user comes out is not the road user's: "... in front of me had to
# brake" said on without a stop, "had a rider come out ... and had to stop" (the one who had it), and a
# fall after the contact ("I hit him. He fell.") is how it ended.
@pytest.mark.parametrize(
    "text",
    [
        "doing about 40 k's and a lad on a bike whizzed off the pavement on the left in front of me had to stop dead",
        "At 20 mph Tom, in the minibus, had a girl on a scooter roll off the kerb in front of him and had to "
        "brake hard.",
        "I was doing 25 mph when a boy on a bike came off the kerb on my left into the road. I could not avoid "
        "hitting him. He fell off.",
    ],
)
def test_the_narrators_reaction_and_a_fall_after_contact_leave_the_crossing(text):
    assert _names(text) == ["cross_in_front"]


@pytest.mark.parametrize(
    "text",
    [
        "doing 40 k's and a cyclist ahead of me had to slam the brakes",
        "doing 40 k's and a cyclist on the left in front of me had to stop dead",
        "At 30 mph we had a van pull out of a side road on the left and it had to stop sharply.",
    ],
)
def test_a_road_users_own_having_to_brake_stays_its(text):
    assert _names(text)[-1] == "sudden_stop"


# Pulling out from the side said with a date before it, or with where it ends said after a comma: one
# move into the ego's way.
@pytest.mark.parametrize(
    "text",
    [
        "I drive a taxi. On 12 March a minibus pulled out of the stop on the left into my path as I was doing 30 mph.",
        "I was doing 50 mph when a tractor pulled out of a farm gate on my left, straight into my lane.",
        "Doing 40 mph, Sam in the tipper had a quad bike pull out of a lay-by on his left, straight into his lane.",
    ],
)
def test_a_pull_out_from_the_roadside_is_one_cut_in(text):
    """One move into the ego's way: a cut-in from a stop or a lay-by, a turn into the road out of a
    private way (a farm gate)."""
    assert _names(text) == (["turn_into"] if "gate" in text else ["cut_in"])


def test_a_move_out_of_the_ego_lane_said_with_straight_is_a_lane_change():
    assert _names("At 40 mph a van in front of me moved straight into the next lane.") == ["change_lane"]


# A turn "across us" or across the way right in front of the ego, by one coming the other way, is the
# turn across the ego's path.
@pytest.mark.parametrize(
    "text",
    [
        "We were doing 40 km/h when an oncoming taxi turned right across us into a side street.",
        "I was driving the bus north at 30 km/h when a van heading south turned right across the road in front of me.",
    ],
)
def test_a_turn_across_the_ego_by_one_coming_the_other_way_turns_across(text):
    assert _names(text) == ["turn_across"]


def test_a_pull_out_of_a_side_road_made_to_turn_and_across_the_ego_is_one_turn_into_its_road():
    text = "I was doing 30 mph when a van came out of a side road on the left to turn right and pulled across my path."
    assert _names(text) == ["turn_into"]


def test_a_side_road_pull_out_then_a_red_light_run_stays_a_run():
    text = "I was doing 30 mph at the lights when a van came out of a side road on the left and ran the red."
    assert _names(text) == ["run_red_light"]


# A vehicle said ahead of the ego that swings out moves out of the ego's lane; one that swings out
# across the road in front of the ego crosses it.
@pytest.mark.parametrize(
    "text",
    [
        "We were at 20 mph. A lorry was double-parked and the taxi ahead of us veered out round it.",
        "We were at 20 mph. A lorry was double-parked and the taxi in front swung out round it.",
    ],
)
def test_a_vehicle_ahead_that_swings_out_leaves_the_lane(text):
    (_, car) = read(text).actors
    assert car.behaviours[0][0] in ("change_lane", "cut_out")


def test_a_vehicle_that_swings_out_across_the_road_in_front_crosses_it():
    assert _names("We were at 20 mph when a taxi swung out across the road in front of us.") == ["run_red_light"]


# "VERB out in front of me": a walker or rider comes out across the road, a vehicle pulls out; "was
# riding out in front of me" is where it rides.
@pytest.mark.parametrize(
    "text",
    [
        "Heading home at 30 mph and a deer just strolled out in front of me.",
        "At 30 mph an old man ambled out right in front of us.",
        "At 30 mph a woman on a bike came out in front of us.",
        "At 30 mph a dog went out in front of me.",
    ],
)
def test_out_in_front_of_the_ego_is_a_crossing(text):
    assert _names(text) == ["cross_in_front"]


def test_riding_out_in_front_of_the_ego_is_going_along():
    assert _names("At 30 mph a cyclist was riding out in front of me.") == ["along_road"]


# A vehicle's sudden move sideways that ends in front of the ego ("dives / swoops / nips in front of me")
# is a cut-in; in front of someone else it is not the ego's.
@pytest.mark.parametrize(
    "text",
    [
        "Doing 60 on the motorway when a hatchback from the slip road dived in front of me.",
        "At 50 mph a BMW from the next lane swooped in front of us.",
    ],
)
def test_a_sudden_move_in_front_of_the_ego_is_a_cut_in(text):
    assert _names(text) == ["cut_in"]


# An exit a road user wants ("wanted my exit", "needed the same exit") is where it goes, not the arm it
# comes from: beside the ego on the roundabout, cutting across is a cut-in from that side.
@pytest.mark.parametrize(
    "text",
    [
        "Going round the roundabout at 15 mph in the right lane, a taxi on my left wanted the same exit and cut "
        "across in front of me.",
        "I was in the outside lane of the roundabout at 20 mph and a lorry on my left needed my exit too and cut "
        "straight across in front of me.",
    ],
)
def test_an_exit_wanted_is_where_the_road_user_goes(text):
    actor = _one(text)
    assert actor.behaviours[0][0] == "cut_in"
    assert actor.relation == "left"


# Where someone or something is carried is no move of a road user's ("taken out of service", "towed
# away", "brought over to the kerb").
@pytest.mark.parametrize(
    "text",
    [
        "At 25 km/h a rider stopped abruptly in front of me. Scooter damaged, taken out of service.",
        "At 25 km/h a rider stopped abruptly in front of me. Scooter dragged into the road, later collected.",
    ],
)
def test_being_carried_somewhere_is_no_move(text):
    assert _names(text) == ["sudden_stop"]


# One already on the roundabout has the way also when where it comes from is said of the ego's side
# before its verb ("approaching from the ego's left"): it goes on, no red-light run.
def test_already_on_the_roundabout_from_the_ego_side_goes_on():
    text = (
        "The ego enters the roundabout at 20 km/h. A bus already on the roundabout, approaching from the ego's "
        "left, continues past the entry."
    )
    assert _names(text) == ["keep_going"]


@pytest.mark.parametrize(
    "text",
    [
        "At the lights a cyclist ran the red in front of us at 20 km/h. Cyclist fine, checked over on scene.",
        "At the lights a cyclist ran the red in front of us at 20 km/h. Rider fine, looked over by a medic.",
    ],
)
def test_looking_or_being_looked_over_is_no_move(text):
    assert _names(text) == ["run_red_light"]


def test_the_lane_count_after_the_ego_lane_is_no_speed_of_the_one_cutting_in():
    reading = read("Doing 56 in lane 1 of 3 when a hatchback from the slip road dived in front of me.")
    (actor,) = reading.actors
    assert actor.behaviours[0][0] == "cut_in"
    assert actor.speed_mps is None or actor.speed_mps > 5


# Going out into the road with or after a thing ("chased a ball out", "pushed a pram out"): the road
# user goes out with it and crosses; "out" may be left unsaid after "ran after ...".
@pytest.mark.parametrize(
    "text",
    [
        "Doing 25 mph past the school when a little girl chased her ball out from behind a parked van.",
        "At 20 mph on our street a boy ran after a football into the road ahead of me.",
        "A mum pushed a buggy straight out in front of me while I was doing 30 mph.",
        "I was at 15 mph when a man pulled his trolley out into the street.",
    ],
)
def test_going_out_with_or_after_a_thing_is_crossing(text):
    assert read(text).actors[0].behaviours[0][0] == "cross_in_front"


@pytest.mark.parametrize(
    "text",
    [
        "I was driving at 20 mph when a boy kicked a ball out into the road.",
        "I was driving at 20 mph when a car followed the bus out into the road.",
        "I was doing 20 mph when I followed a lorry out into the road.",
        "A man walked his dog along the pavement while I drove past at 30 mph.",
    ],
)
def test_a_thing_sent_out_or_the_egos_own_move_is_no_crossing(text):
    assert "cross_in_front" not in [b[0] for a in read(text).actors for b in a.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        # a crossing named by a place noun before it, as a heading, is a place, nobody crossing
        "Riverside towpath crossing. A cyclist and a dog walker come off the path on my left and cross the road.",
        "Mill Lane crossing. A jogger and a boy on a scooter step off the kerb on the left and cross in front of me.",
    ],
)
def test_a_crossing_named_as_a_heading_is_no_crossing_act(text):
    assert [a.relation for a in read(text).actors] == ["roadside_left", "roadside_left"]


@pytest.mark.parametrize(
    "text",
    [
        # near misses: a road user before the word crosses
        "Two kids crossing.",
        "Cyclist crossing from the left at 15 km/h.",
    ],
)
def test_a_road_user_crossing_as_a_heading_still_crosses(text):
    assert all(b[0] == "cross_in_front" for a in read(text).actors for b in a.behaviours[:1])


# A person who steps, walks or wanders into the ego's path is on foot and crosses it: the destination
# (the ego's path or lane) makes a vehicle's move a cut-in, never a walker's, whoever the noun names.
@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("I was driving at 30 km/h and a woman stepped off the footpath on the left into my path.", "left"),
        ("Was doing 20 mph when this man walked out into my path from the right, head down in his phone.", "right"),
        ("I was going about 25 when some guy stepped out into my lane from the pavement on my left", "left"),
        ("Ego at 40 km/h. An elderly lady wanders off the right kerb into the ego's path.", "right"),
        ("we were doing 30 and a bloke staggered out of the pub on the left straight into our path", "left"),
    ],
)
def test_a_person_on_foot_into_the_ego_path_crosses_it(text, side):
    actor = _one(text)
    assert actor.kind == "pedestrian"
    assert [b[0] for b in actor.behaviours] == ["cross_in_front"]
    assert actor.relation == f"roadside_{side}"


@pytest.mark.parametrize(
    ("text", "move"),
    [
        # a vehicle's move into the ego's lane stays a cut-in; so does a driver's, whatever the noun
        ("I was doing 30 mph and a van pulled into my lane from the left.", "cut_in"),
        ("I was doing 50 on the motorway and some guy swerved into my lane right in front of me.", "cut_in"),
    ],
)
def test_a_move_into_the_ego_lane_not_on_foot_stays_a_cut_in(text, move):
    assert _names(text)[0] == move


# "ran into" the ego's path or lane is where one goes, not what one hits ("ran into me" is contact).
@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30 and a kid ran into my path from between two parked vans.",
        "Ego at 25 km/h; a child runs into the ego's path from behind a parked car on the right.",
        "doing about 20 when a little girl ran into my lane from between the parked cars, I stopped just in time",
        "We were at 30 km/h when a boy ran straight into our path from the left.",
    ],
)
def test_running_into_the_ego_path_is_a_crossing(text):
    walkers = [a for a in read(text).actors if a.kind == "pedestrian"]
    assert [[b[0] for b in a.behaviours] for a in walkers] == [["cross_in_front"]]


def test_running_into_the_ego_is_still_contact():
    r = read("I was doing 30 when a kid on a bike ran into me from the left.")
    assert r.intent == "collision"
