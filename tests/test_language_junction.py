"""Junction and roundabout behaviours (:mod:`vei_scenario.language.junctions`): who crosses at a
junction's mouth, who comes off a kerb, who has the way and who takes it. Each group is one
construction, in wordings written for it (none taken from a corpus), with near misses that look alike
and must not be read so."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _only(text: str):
    (actor,) = read(text).actors
    return actor, [b[0] for b in actor.behaviours]


# a walker or rider moving off a kerb, pavement or footway goes across the road from that side, at a
# junction too (where the arm said is where it crosses, not a road it comes out of)
OFF_THE_KERB = [
    ("At the crossroads a lad on a scooter rolled off the pavement on my right just as I pulled up.", "right"),
    ("Going round the gyratory at 20 km/h, a jogger came off the footway on the left into the entry.", "left"),
    ("A girl on a bike came flying off the kerb on our left at the slip road and I braked.", "left"),
    ("As we left the roundabout a kid on a scooter rode straight off the curb on the right at the exit.", "right"),
]


@pytest.mark.parametrize("text, side", OFF_THE_KERB)
def test_a_walker_or_rider_off_the_kerb_crosses_from_that_side(text, side):
    actor, names = _only(text)
    assert names[0] == "cross_in_front"
    assert actor.relation == f"roadside_{side}"


# the mouth of a junction crossed: "over the exit", "across the entry" is where it crosses
ACROSS_AN_ARM = [
    ("An e-scooter rider zipped over the exit in front of us from the pavement on the right.", "right"),
    ("A pedestrian hurried across the entry from the left just as I reached the give-way line.", "left"),
    ("A cyclist from the shared path on our left pedalled over the mouth of the side road.", "left"),
]


@pytest.mark.parametrize("text, side", ACROSS_AN_ARM)
def test_a_walker_or_rider_across_a_junction_mouth_crosses(text, side):
    actor, names = _only(text)
    assert names == ["cross_in_front"]
    assert actor.relation == f"roadside_{side}"


# "across in front of" the ego or "across its path" after any verb of motion: a crossing
ACROSS_THE_EGO = [
    "At the crossroads a kid on a scooter shot straight across in front of me.",
    "Going round the roundabout at 15 mph, a jogger nipped across my path.",
    "At the lights a man on a bike whizzed across in front of us.",
]


@pytest.mark.parametrize("text", ACROSS_THE_EGO)
def test_across_in_front_of_the_ego_is_a_crossing(text):
    _, names = _only(text)
    assert names == ["cross_in_front"]


NOT_A_CROSSING = [
    # along the pavement: beside the road, not across it
    ("Going round the roundabout, a cyclist rode along the pavement on my left.", "along_road"),
    # a vehicle pulled off the kerb (parked) moves into the lane
    ("On the high street a taxi pulled off the kerb right in front of me.", "cut_in"),
    # what already says a move of its own keeps it
    ("A van overtook me on the bypass and then cut across in front of me.", "overtake"),
]


@pytest.mark.parametrize("text, first", NOT_A_CROSSING)
def test_near_misses_are_not_read_as_a_crossing(text, first):
    _, names = _only(text)
    assert names[0] == first


# a road user that already has the way (already on the roundabout, circulating, on the main road)
# goes on through: it does not run a red light or force its way in, even "without slowing"
HAS_THE_WAY = [
    ("At the roundabout the ego waits at the line; a taxi already circulating comes past from the right.", "right"),
    ("At the mini-roundabout a moped already on the roundabout came round from the left and I braked.", "left"),
    ("At the T-junction the ego pulls out at 10 km/h; a cyclist on the main road comes along from the right.", "right"),
    ("I edged onto the roundabout and a lorry circulating from my right carried on without slowing.", "right"),
    ("At the roundabout a van already going round came from the left and drove on right in front of us.", "left"),
]


@pytest.mark.parametrize("text, side", HAS_THE_WAY)
def test_a_road_user_that_has_the_way_goes_on(text, side):
    actor, names = _only(text)
    assert names == ["keep_going"]
    assert actor.relation == f"junction_{side}"


TAKES_THE_WAY = [
    # entering without slowing: it takes the way it does not have
    ("Going round the roundabout at 20 km/h, a van entered from the left without slowing.", "left"),
    # "already" said of the ego, not of the one that comes in
    ("I was already on the roundabout when a car came in from the right without stopping.", "right"),
]


@pytest.mark.parametrize("text, side", TAKES_THE_WAY)
def test_a_road_user_entering_without_giving_way_takes_it(text, side):
    actor, names = _only(text)
    assert names[0] in ("run_red_light", "turn_into")
    assert actor.relation == f"junction_{side}"


# a road user from a side that enters the roundabout or junction comes out of that arm; "in front of
# us" after it is where it goes, and not stopping or yielding makes it take the way
ENTERS_FROM_A_SIDE = [
    ("Ego circulating at 25 km/h; a hatchback from the right barges onto the roundabout in front of us.", "right"),
    ("Going round at 20 mph, a pickup from my left drove into the roundabout in front of me without stopping.", "left"),
    ("On the roundabout at 15 km/h. From the right comes a taxi fast, not stopping, it goes in front of us.", "right"),
]


@pytest.mark.parametrize("text, side", ENTERS_FROM_A_SIDE)
def test_a_road_user_entering_from_a_side_comes_out_of_that_arm(text, side):
    actor, names = _only(text)
    assert names[0] in ("run_red_light", "turn_into")
    assert actor.relation == f"junction_{side}"


ENTERS_NOT_FROM_AN_ARM = [
    # ahead of the ego, no side: it is in front, entering as the ego does
    ("The van in front of me entered the roundabout and braked hard.", "ahead"),
]


@pytest.mark.parametrize("text, relation", ENTERS_NOT_FROM_AN_ARM)
def test_entering_ahead_of_the_ego_is_not_an_arm(text, relation):
    actor, _ = _only(text)
    assert actor.relation == relation


# a compass point a road user comes from, read against the ego's heading: the arm or the footway on
# the ego's right when the point lies 90 degrees clockwise of its heading, on its left at 270
FROM_A_COMPASS_POINT = [
    (
        "The ego is heading south at 30 km/h; a van from the west arm runs the red at the crossroads.",
        "junction_right",
    ),
    (
        "The ego travels westbound at 40 km/h and meets a cyclist coming from the south at a junction.",
        "junction_left",
    ),
    ("The ego drives north at 25 mph; a pedestrian steps out from the western pavement.", "roadside_left"),
]


@pytest.mark.parametrize("text, relation", FROM_A_COMPASS_POINT)
def test_a_compass_origin_is_read_against_the_ego_heading(text, relation):
    actor, _ = _only(text)
    assert actor.relation == relation


NOT_A_COMPASS_ORIGIN = [
    # a street's name is no compass point: the side said is where it comes from
    ("Heading north at 20 mph, a van came out of a side road from East Street on my left.", "junction_left"),
    # without the ego's heading a compass point says nothing of the side
    ("At the crossroads a taxi from the east runs the red light in front of me.", "junction_left"),
]


@pytest.mark.parametrize("text, relation", NOT_A_COMPASS_ORIGIN)
def test_near_misses_of_a_compass_origin(text, relation):
    actor, _ = _only(text)
    assert actor.relation == relation


# a walker said to go along a kerb or verge towards the ego at a junction walks along it, facing the
# ego; the junction does not make it one that comes out of an arm and crosses
@pytest.mark.parametrize(
    "text",
    [
        "At the T-junction, ego goes straight on at 40 km/h. A pedestrian walks along the right verge towards the ego.",
        "Crossroads, ego 30 km/h straight over. Man walking towards us along the pavement on the right.",
        "I was going through the junction at about 25 mph, a woman was walking along the kerb on my left towards me.",
        "Ego 40 km/h on the main road past a side road. Pedestrian walking along the right-hand verge towards ego.",
        "At the crossroads we were doing 30; a jogger was running along the footpath on the left coming towards us.",
    ],
)
def test_a_walker_along_the_kerb_towards_the_ego_at_a_junction_walks_along(text):
    (walker,) = read(text).actors
    assert [b[0] for b in walker.behaviours] == ["along_road"]


# near misses: a walker from the kerb or across at a junction still crosses
@pytest.mark.parametrize(
    "text",
    [
        "At the T-junction, ego goes straight on at 40 km/h. A pedestrian steps off the right kerb towards the ego.",
        "At the crossroads a man walked towards us across the side road on the left; we were doing 20 mph.",
    ],
)
def test_a_walker_off_the_kerb_at_a_junction_still_crosses(text):
    (walker,) = read(text).actors
    assert [b[0] for b in walker.behaviours] == ["cross_in_front"]


# "a four-way / all-way / 3-way stop" names a junction controlled by stop signs, as "a stop sign" does:
# its "stop" is no road user's stop, and what crosses there without stopping runs it
@pytest.mark.parametrize(
    "text",
    [
        "At an all-way stop a car shot across from the left without stopping while I was going through at 15 mph.",
        "I was going through the 4-way stop at 15 mph when a pickup from the right blew through without stopping.",
        "We were crossing the four way stop at about 10 mph and a car from the left rolled right through it.",
        "Three-way stop on Elm St, I'm doing 12 mph through it, SUV from the right doesn't stop.",
        "At the all way stop, ego at 20 km/h; a car from the left goes through without stopping.",
    ],
)
def test_a_four_way_stop_is_a_junction_not_a_stop(text):
    r = read(text)
    (car,) = r.actors
    assert r.map_kind == "crossroad"
    assert [b[0] for b in car.behaviours] == ["run_red_light"]
    assert car.relation in ("junction_left", "junction_right")


def test_a_stop_said_as_a_verb_at_a_four_way_junction_stays_a_stop():
    (car,) = read("At the four-way junction the car ahead of me came to a stop; I was doing 20 mph.").actors
    assert [b[0] for b in car.behaviours][-1] in ("stop", "sudden_stop")


# --- "out the side road": "out" and the road's article, "of" left out as said aloud ---------------------
def _kinds_of_act(text: str) -> list[list[str]]:
    """The behaviours of each road user read from ``text``."""
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


@pytest.mark.parametrize(
    "text",
    [
        "I was driving at 30 mph, a woman on a bike came out the side road on the left without looking.",
        "At 40 km/h a motorbike shot out a side street on the left.",
        "Scooter kid zoomed out the side street on my left at 30 km/h.",
        "Doing 25 mph when a van pulled out the junction on my right.",
        "I was doing 30 mph when a car nosed out the T-junction on my right.",
    ],
    ids=["came-out-the-side-road", "shot-out-a-side-street", "zoomed-out", "pulled-out-the-junction", "nosed-out"],
)
def test_out_the_side_road_is_coming_out_of_it(text):
    assert _kinds_of_act(text) == [["turn_into"]]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist flew out the driveway on my left at 20 mph.", [["cross_in_front"]]),  # (no junction arm)
        ("I was doing 30 and a van pulled out the way of a bus.", [["cut_in"]]),  # (a way, no road)
    ],
    ids=["out-the-driveway", "out-the-way"],
)
def test_out_the_and_no_side_road_is_no_emergence(text, expected):
    assert _kinds_of_act(text) == expected


# a road user coming from the junction's opposite arm that only goes on, or goes past the ego, goes
# straight through on its own side while the ego turns across it: it has the way (no red is run), and
# it meets the ego head on (it overtakes no one)
THROUGH_FROM_OPPOSITE = [
    "I was turning left at the intersection when an oncoming SUV kept coming without stopping and I slammed on.",
    "Making a right turn at the crossroads, we drive on the left, and an oncoming motorbike didn't slow at all.",
    "Ego turns left at the junction; an oncoming van goes straight on and does not stop. Near miss.",
    "i was turning left at the crossroads n the oncoming ute just kept going straight thru, nearly hit it",
    "The AV turns left across an oncoming cyclist at the crossroads; the cyclist went past a metre off our bumper.",
    "We turned left at the junction and the oncoming bus flew past a few metres in front of us.",
]


@pytest.mark.parametrize("text", THROUGH_FROM_OPPOSITE)
def test_an_oncoming_road_user_going_on_through_the_junction_keeps_going(text):
    r = read(text)
    opposite = [a for a in r.actors if a.relation == "junction_opposite"]
    assert opposite, [(a.kind, a.relation) for a in r.actors]
    assert [b[0] for b in opposite[0].behaviours][:1] == ["keep_going"]


# near misses: a red said is run; one that turns across the ego turns; one out of a side road is no
# oncoming road user
NOT_THROUGH_FROM_OPPOSITE = [
    ("I was turning left at the crossroads when an oncoming car ran the red light and nearly hit me.", "run_red_light"),
    ("At the junction an oncoming van jumped the lights straight through as I turned left.", "run_red_light"),
    ("Going straight through the crossroads, an oncoming car turned left across my path.", "turn_across"),
]


@pytest.mark.parametrize("text, expected", NOT_THROUGH_FROM_OPPOSITE)
def test_a_red_or_a_turn_from_the_opposite_arm_stays_so(text, expected):
    actor, names = _only(text)
    assert names[:1] == [expected], (actor.relation, names)


# where a road user struck the ego's flank ("into my rear passenger door") is a part of the ego, not
# where the road user was: it comes from the arm said, not from behind
FLANK_STRUCK = [
    "Going round the roundabout at 20 km/h a taxi came on from the next entry without stopping and went into my rear "
    "passenger door.",
    "I was circulating on the roundabout when a ute entered from the right without giving way and smashed into our "
    "back left door.",
    "At the crossroads a van shot out of the side road on my left and hit the rear nearside wheel of my car.",
    "on the roundabout, car pulled on from the entry on the right without looking and clipped my rear driver's door",
    "Ego circulates at 25 km/h; a bus enters from the next arm without yielding and strikes the ego's rear offside "
    "quarter panel.",
]


@pytest.mark.parametrize("text", FLANK_STRUCK)
def test_a_flank_part_struck_is_no_place_behind(text):
    actor, names = _only(text)
    assert actor.relation in ("junction_left", "junction_right"), (actor.relation, names)


# near misses: the end of the ego struck says the road user was at that end
REAR_STRUCK = [
    "Waiting at the lights when a van went into my rear.",
    "Queuing at 5 mph when a van came up from behind and went into my rear passenger door.",
]


@pytest.mark.parametrize("text", REAR_STRUCK)
def test_the_rear_struck_stays_behind(text):
    actor, _ = _only(text)
    assert actor.relation == "behind"


# a turn said with its subject left out, joined by "and" / "but" to a clause that opens with the first
# road user, is the narrator's: that road user is the next clause's subject, not the turn's
NARRATORS_TURN_THEN_A_ROAD_USER = [
    ("Hung a left onto Main St around 9 and a cyclist going the wrong way in my lane came straight at me.", "left"),
    ("Turned right into the estate and a kid on a scooter was riding towards me on my side of the road.", "right"),
    ("Made a left at the lights and a guy on a moped came the wrong way down the street at me.", "left"),
    ("Took the right turn off the high road but an okada was coming against traffic in my lane.", "right"),
    ("turned left at the junction and this bike came at me the wrong way in my lane", "left"),
]


@pytest.mark.parametrize("text, route", NARRATORS_TURN_THEN_A_ROAD_USER)
def test_a_turn_with_its_subject_left_out_before_and_is_the_narrators(text, route):
    r = read(text)
    (actor,) = r.actors
    assert r.ego_route == route
    assert not {"forced_turn", "turn_across"} & {b[0] for b in actor.behaviours}


# near misses: a turn said with its road user keeps it
ROAD_USERS_TURN_THEN_ANOTHER = [
    "A van turned left in front of me and a cyclist behind it swerved.",
    "The truck ahead turned right and a cyclist came up its inside.",
]


@pytest.mark.parametrize("text", ROAD_USERS_TURN_THEN_ANOTHER)
def test_a_turn_said_with_its_road_user_stays_its_own(text):
    first = read(text).actors[0]
    assert [b[0] for b in first.behaviours][:1] == ["forced_turn"]


# near misses: one said not to give way takes a way it does not have, and runs through
TAKES_THE_WAY_FROM_OPPOSITE = [
    "I was turning left at the junction when an oncoming car failed to give way and drove through.",
    "Ego turns left at the crossroads; an oncoming scooter does not yield.",
]


@pytest.mark.parametrize("text", TAKES_THE_WAY_FROM_OPPOSITE)
def test_an_oncoming_road_user_said_not_to_give_way_runs_through(text):
    actor, names = _only(text)
    assert names[:1] == ["run_red_light"], (actor.relation, names)


# a road user said to pull out of a side road on the ego's left or right, where no light or signal is
# said, joins the ego's road: not stopping or not giving way is how it pulls out, not a red light run.
# The same thing as a British report, an American text, an Australian post, an Indian or Nigerian
# voice note, a test spec.
PULLS_OUT_WITHOUT_STOPPING = [
    ("Doing 40 mph on the main road when a van came out of a side road on my left without stopping.", "left"),
    ("Vehicle 2 emerged from the minor road on Vehicle 1's right and failed to give way; the two collided.", "right"),
    ("ute pulled out of a side street on the right without giving way, I was on 60 k", "right"),
    ("One motorbike came out from the side road on my left, not stopping at all, I was doing 40 kmph.", "left"),
    ("Ego 50 km/h on the priority road; a car emerges from the side road on the left without yielding.", "left"),
    ("Omo, this bus just pulled out of the side road on my right without stopping o, I was doing 30.", "right"),
    ("The SUV emerged from a side road on our left, intending to turn right, and did not give way.", "left"),
    ("I was cycling along at 15 mph and a taxi nosed out of the side street on my right without looking.", "right"),
    # "red" as a colour is no light said
    ("A red van came out of a side road on my left without stopping and I went into it at 30 mph.", "left"),
]


@pytest.mark.parametrize("text, side", PULLS_OUT_WITHOUT_STOPPING)
def test_pulling_out_of_a_side_road_without_stopping_turns_into_the_ego_road(text, side):
    actor, names = _only(text)
    assert set(names) == {"turn_into"}, (actor.relation, names)
    assert actor.relation == f"junction_{side}"


# near misses: a light said, or a move straight over said after the pull-out, or a road user only said
# to come from an arm (no pull-out), keeps the run through the junction
PULLS_OUT_AND_RUNS = [
    "A car came out of the side road on my right against the red light and I hit it.",
    "At the traffic lights a van pulled out of the side road on my left without stopping.",
    "At the crossroads a van came out of the side road on the left without stopping and carried on across.",
    "A car emerged from the side road on the right without stopping and went straight over the junction.",
    "At the crossroads a car from the right arm did not give way while I was doing 30 mph.",
]


@pytest.mark.parametrize("text", PULLS_OUT_AND_RUNS)
def test_a_pull_out_with_a_light_or_a_crossing_said_still_runs_through(text):
    actor, names = _only(text)
    assert names[:1] == ["run_red_light"], (actor.relation, names)


def _start(text: str) -> list[tuple[str, str]]:
    from vei_scenario.language.rules_backend import layers_from_text

    return [(a["type"], a["spawn"]["relation"]) for a in layers_from_text(text, 0)["adversaries"]]


# a rider who crosses at a junction from a side read as an arm (its road and heading said, as a report
# puts it), with no kerb, footway or crossing said, comes along the crossing road, out of that arm
THROUGH_FROM_AN_ARM = [
    (
        "Car eastbound at 40 km/h on a green; the bicycle was southbound on the side street, approaching "
        "from the car's left, and crossed in front of it.",
        "left",
    ),
    (
        "Vehicle 1 was northbound at 30 mph through the intersection. The cyclist was westbound on the cross "
        "street, approaching from V1's right, and rode across in front of it.",
        "right",
    ),
    (
        "The van was travelling west at 25 mph over the crossroads; the e-scooter rider was northbound on "
        "Mill Street, approaching from the van's left, and crossed in front of the van.",
        "left",
    ),
    (
        "SV eastbound at 50 km/h straight through the junction. E-scooter southbound on the minor road, "
        "i.e. from the SV's left, crossed the SV's path.",
        "left",
    ),
    ("I had the green at the lights, about 30 km/h, and a guy on an e-scooter jumped the red from the left.", "left"),
]


@pytest.mark.parametrize("text, side", THROUGH_FROM_AN_ARM)
def test_a_rider_crossing_from_an_arm_starts_on_that_arm(text, side):
    assert [rel for _, rel in _start(text)] == [f"junction_{side}"]


# near misses: a rider said on a kerb or footway starts there, and one that crosses the mouth of a
# side road crosses it from the kerb beside it
THROUGH_NEAR_MISSES = [
    (
        "The car was eastbound at 30 mph through the crossroads when a cyclist on the footway approaching "
        "from its left crossed in front of it.",
        "roadside_left",
    ),
    (
        "At the crossroads, going straight at 30 km/h, a cyclist rode across the mouth of the side road on "
        "my right in front of me.",
        "roadside_right",
    ),
    (
        "At the crossroads on a green at 25 mph a cyclist came off the pavement on my right against the red.",
        "roadside_right",
    ),
]


@pytest.mark.parametrize("text, relation", THROUGH_NEAR_MISSES)
def test_a_rider_placed_off_the_road_keeps_its_kerb(text, relation):
    assert [rel for _, rel in _start(text)] == [relation]


# a participle of turning that opens the sentence, then a comma and a walker: the writer's turn, which
# notes let dangle; a walker turns into no road and stays a walker
DANGLING_TURNS = [
    ("Turning right into Mill Lane, an old man was halfway across the side road.", "right"),
    ("Turning left onto Park Street, a woman with a pram stepped off the kerb in front of us.", "left"),
    ("While turning right at the crossroads, a pedestrian started to cross the road we were turning into.", "right"),
    ("Turning left into the car park, a kid ran across the entrance.", "left"),
]
#: a rider or a vehicle after the comma may be the one turning: no route is given to the ego
DANGLING_TURNS_KEPT = [
    "Turning left into Mill Lane, the cyclist wobbled and fell off.",
    "Turning right into the side road, the lorry mounted the pavement.",
]


@pytest.mark.parametrize("text, route", DANGLING_TURNS)
def test_a_turn_dangling_before_a_walker_is_the_writers(text, route):
    r = read(text)
    assert r.ego_route == route
    assert [a.kind for a in r.actors] == ["pedestrian"]
    assert not any(b[0] in ("turn_into", "forced_turn", "turn_across") for a in r.actors for b in a.behaviours)


@pytest.mark.parametrize("text", DANGLING_TURNS_KEPT)
def test_a_turn_dangling_before_a_rider_or_vehicle_stays_theirs(text):
    assert read(text).ego_route is None
