"""Where a road user starts beside the ego, read from the side phrase attached to it: lane, kerb and
junction-arm nouns with their side word before or after them, in the writer's driving convention."""

import pytest
from play_layers import play_layers

from vei_scenario.language.reader import read
from vei_scenario.language.sides import beside, drives_on_left, phrase_at


def relation(text: str) -> str | None:
    return read(text).actors[0].relation


@pytest.mark.parametrize(
    "text, expected",
    [
        # a UK writer (miles per hour): the nearside / inside lane is the left one, offside / outside the right
        (
            "I was cruising at 60 mph in the offside lane when a coach in the nearside lane moves over into my lane.",
            "left",
        ),
        ("I was doing 50 mph in the inside lane when a taxi in the outside lane swerved into mine.", "right"),
        (
            "I was at 40 mph in the nearside lane and a hatchback in the offside lane came across into my lane.",
            "right",
        ),
        # the same words without miles per hour keep the right-hand convention
        ("Ego at 90 km/h; a minibus in the nearside lane moves into the ego lane 20 m ahead.", "right"),
    ],
)
def test_lane_words_follow_the_writers_driving_side(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was in the left lane at 30 mph and a pickup in the right lane swung across into my lane.", "right"),
        ("We sat in the middle lane at 65 mph; a coach in lane 1 drifted into our lane.", "left"),
        ("Going 45 mph in lane 1, a saloon in lane 2 squeezed into my lane.", "right"),
    ],
)
def test_a_lane_is_compared_with_the_egos_own(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("At 20 mph a boy stepped out from the nearside (right) footpath into my path.", "roadside_right"),
        ("At 25 mph a girl ran out from the offside (left) verge in front of me.", "roadside_left"),
        ("At 15 mph a man stepped from the nearside footpath into the road ahead of me.", "roadside_left"),
    ],
)
def test_a_kerb_side_restated_plainly_wins(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("At 30 km/h a van came out of a minor road on our right and pulled into our road ahead.", "junction_right"),
        ("Driving at 40 km/h, a hatchback emerged from a side street on my left into my road.", "junction_left"),
        (
            "At 30 km/h a motorbike came out of the side road on the ego's right and turned into our road.",
            "junction_right",
        ),
    ],
)
def test_an_arm_with_its_side_after_it(text, expected):
    assert relation(text) == expected


def test_phrases_in_both_orders():
    said = phrase_at("a jogger came off the footpath on my right".split(), 3, False, False)
    assert said is not None and ("kerb_side", "right") in said.mentions
    said = phrase_at("from the right-hand verge".split(), 0, False, False)
    assert said is not None and ("kerb_side", "right") in said.mentions
    assert phrase_at("in the same lane 30 m ahead".split(), 0, False, False) is None  # (a distance, no lane 30)
    assert phrase_at("from the right".split(), 0, False, False) is None  # (no noun: the lexicon's)
    # a roundabout's inner lane is by the island, on the offside
    assert phrase_at("on the inner lane".split(), 0, False, True).mentions == (("lane_side", "left"),)
    assert phrase_at("on the inner lane".split(), 0, True, True).mentions == (("lane_side", "right"),)


def test_beside_and_convention():
    assert beside("left", "right") == "left" and beside("right", "middle") == "right"
    assert beside("left", None) == "left" and beside("middle", None) is None and beside("left", "left") is None
    assert drives_on_left("at 30 mph".split()) and not drives_on_left("at 30 km/h".split())


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "On the roundabout at 15 mph, a taxi entering from my left did not stop and hit my nearside.",
            "junction_left",
        ),
        (
            "Round the roundabout at 20 mph, a pickup came out of the entry on our left and hit our offside.",
            "junction_left",
        ),
        (
            "I was in lane 2 at 60 mph when a coach in lane 1 moved over; its offside touched the nearside of my car.",
            "left",
        ),
    ],
)
def test_a_side_of_a_vehicle_is_no_place(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Doing 20 mph, a toddler ran out from the nearside into my path.", "roadside_left"),
        ("At 25 mph a jogger stepped off the offside straight in front of me.", "roadside_right"),
        ("At 30 km/h a toddler runs out from the nearside into the ego's path.", "roadside_right"),
    ],
)
def test_a_bare_kerb_side_follows_the_writers_driving_side(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "Doing 40 mph on a country lane when a pickup came straight towards us in our lane.",
        "At 60 km/h a taxi came towards us on our side of the road.",
        "On the bend at 50 km/h a lorry crossed the white line and came head-on at me in my lane.",
    ],
)
def test_a_road_user_coming_at_the_ego_in_its_lane_starts_oncoming(text):
    assert relation(text) == "oncoming"


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "Unit 1 was heading north at 30 mph when Unit 2, travelling southbound, turned left across its path.",
            ("oncoming", "junction_opposite"),
        ),
        (
            "V1 was westbound at 40 km/h. V2, northbound, went through the red light into the path of V1.",
            ("junction_left",),
        ),
        (
            "The ego was heading south at 50 km/h when a lorry going east ran the red at the crossroads.",
            ("junction_right",),
        ),
        (
            "V1 was eastbound at 40 km/h when V2, heading north, drove across the junction in front of V1.",
            ("junction_right",),
        ),
        (
            "V1 was northbound at 30 mph; V2 was travelling southbound in the northbound lane and hit V1 head-on.",
            ("oncoming",),
        ),
    ],
)
def test_compass_headings_are_related_to_the_egos(text, expected):
    assert relation(text) in expected


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "At 30 km/h a cyclist came out of a side road on my right and turned into my road ahead of me.",
            "junction_right",
        ),
        (
            "At 25 mph an e-scooter rider emerged from a minor road on our left and pulled into our road.",
            "junction_left",
        ),
        (
            "The ego drives at 40 km/h; a cyclist comes out of the side street on its left into its road.",
            "junction_left",
        ),
    ],
)
def test_a_rider_out_of_a_side_road_turns_in_from_that_arm(text, expected):
    reading = read(text)
    assert (reading.actors[0].relation, reading.actors[0].behaviours[0][0]) == (expected, "turn_into")


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A car in the right lane 15 m ahead cuts across to turn into a side street; ego at 50 km/h.", "right"),
        ("A taxi in front of us swings left into a minor road on the left; we are doing 30 km/h.", "ahead"),
        ("At 40 km/h a van ahead of me turned right into the side road on the right.", "ahead"),
        ("At 30 km/h a cyclist ahead of me turned left into a side street on the left.", "ahead"),
    ],
)
def test_a_side_road_turned_into_is_where_it_goes_not_where_it_starts(text, expected):
    reading = read(text)
    assert reading.actors[0].relation == expected
    assert reading.map_kind == "crossroad"  # (the side road is a junction all the same)


def test_the_edge_of_the_road_is_a_kerb():
    said = phrase_at("keeping to the right edge".split(), 1, False, False)
    assert said is not None and ("kerb_side", "right") in said.mentions


@pytest.mark.parametrize(
    "text, expected",
    [
        ("VUT 30 km/h; child running from the near (left) side at 6 km/h.", "roadside_left"),
        ("Ego at 40 km/h, an adult walking from the far (right) side at 5 km/h.", "roadside_right"),
        ("VUT 25 km/h; elderly pedestrian moving from the opposite (left) kerb at 3 km/h.", "roadside_left"),
    ],
)
def test_a_far_or_near_side_restated_plainly(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("At 40 mph a coach in the left lane moved over into our lane; our mirror hit its rear window.", "left"),
        ("At 30 mph a taxi in the left lane moved over into my lane; my bonnet hit its rear door.", "left"),
        ("At 35 mph a pickup in the right lane moved over into my lane; my wing touched its back tyre.", "right"),
    ],
)
def test_an_end_of_a_vehicle_is_no_place(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "Three lanes each way, ego in the left lane at 90 km/h; a coach in the middle lane 25 m ahead "
            "moves over to the right lane.",
            "right",
        ),
        ("Ego: middle lane, 100 km/h. A van in the right lane, 15 m ahead, changes to the left lane.", "right"),
        (
            "I'm in the right lane at 60 mph; a minibus in the centre lane 40 m in front drifts to the left lane.",
            "left",
        ),
    ],
)
def test_a_lane_beside_the_egos_with_a_distance_ahead_is_where_it_starts(text, expected):
    """The lane says the side, "N m ahead" how far along: a lane change from it starts beside the ego."""
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "A scooter rider overtakes me, and once he is in my lane he slams on the brakes. I'm at 40 km/h.",
        "At 80 km/h a sports car passes us and then, in our lane, it brakes hard.",
        "ego 60 km/h, bike overtake ego then he go in ego lane and he stop suddenly",
    ],
)
def test_a_road_user_overtaking_the_ego_starts_behind_it(text):
    """Overtaking the ego ends in its lane ahead: "in my lane" said after it is where it ends up."""
    reading = read(text)
    assert reading.actors[0].relation in ("behind", None)
    assert reading.actors[0].behaviours[0][0] == "overtake"


@pytest.mark.parametrize(
    "text",
    [
        "On a roundabout at 25 km/h, the van ahead of me brakes at the exit.",
        "Roundabout, ego 30 km/h: the car in front slows down at the entrance.",
        "At the crossroads, ego 40 km/h, the bus in front of us stops at the approach.",
    ],
)
def test_a_lead_doing_something_at_a_junction_arm_stays_ahead(text):
    """ "at the entry" after what a lead does is where it does it, not an arm it comes out of."""
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text, expected",
    [
        ("At a crossroads I'm doing 20 mph and a van comes from the left, slows and lets me through.", "junction_left"),
        ("Approaching the junction at 40 km/h, a cyclist comes along from my left and slows down.", "junction_left"),
        ("T-junction ahead, ego 30 km/h: a moped rider approaching from the right eases off.", "junction_right"),
    ],
)
def test_a_road_user_coming_from_a_side_at_a_junction_comes_along_that_arm(text, expected):
    assert relation(text) == expected


def test_a_lane_said_at_a_junction_stays_a_lane():
    assert relation("At the junction at 40 km/h, a car in the right lane slows down.") == "right"


@pytest.mark.parametrize(
    "text, expected",
    [
        # British words, no unit at all: the writer drives on the left, so the inside lane is the left one
        ("On the motorway in the middle lane doing 60, a lorry in the inside lane wanders across into mine.", "left"),
        ("Dual carriageway, I'm in lane 2, an HGV in the outside lane starts coming over on me.", "right"),
        ("Middle lane of the M6, a coach on the inside lane swerves across into me, I'm doing about 65.", "left"),
        # American words with miles per hour: the writer drives on the right
        ("On the freeway at 60 mph in the middle lane, a semi in the inside lane drifts into mine.", "right"),
        ("At 25 mph a kid ran out from the nearside sidewalk in front of me.", "roadside_right"),
    ],
)
def test_the_writers_driving_side_from_their_words(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # American road and car words beside miles per hour: a right-hand writer, so the passenger side
        # and the nearside are the right (a claim letter, a forum post, a 911 call, a text, a witness)
        (
            "My insured was crossing the intersection on a green at 25 mph when a sedan ran the red light and "
            "struck the passenger side of his car.",
            "junction_right",
        ),
        ("At 20 mph on a downtown street a kid darted out from the nearside in front of my windshield.",
         "roadside_right"),
        ("Doing 30 mph into the intersection, a minivan blew the red and hit my passenger side.", "junction_right"),
        ("I was at 15 mph when a jogger stepped off the nearside onto the road in front of me, no blinker from me.",
         "roadside_right"),
        ("Off the on-ramp at 40 mph, a pickup ran the light at the intersection and slammed into the passenger side "
         "of my truck.", "junction_right"),
        # the driver's side is the offside, the left for a right-hand writer
        ("Going through the intersection at 20 mph, a cab ran the red and plowed into my driver's side.",
         "junction_left"),
        # near misses: the same with British words, or no American one, keep the left
        ("I was crossing the junction on a green at 25 mph when a lorry ran the red light and hit my passenger side.",
         "junction_left"),
        ("At 20 mph a kid darted out from the nearside in front of me.", "roadside_left"),
    ],
)  # fmt: skip
def test_american_road_words_with_miles_per_hour_keep_right(text, expected):
    assert relation(text) == expected


def test_driving_side_words():
    assert drives_on_left("a lorry in the inside lane drifted into me".split())
    assert not drives_on_left("a lorry in the nearside lane cuts in ahead of the av".split())  # (a test line)
    assert not drives_on_left("i was at 60 km/h and a lorry cut in".split())  # (metric: Euro NCAP's convention)
    assert drives_on_left("on the m 25 at 70".split())
    assert not drives_on_left("on the interstate at 70 mph".split())
    assert not drives_on_left("stopped 25 m ahead at 70 km/h".split())


@pytest.mark.parametrize(
    "text, expected",
    [
        ("VUT 40 km/h, cyclist crossing R->L at 15 km/h", "roadside_right"),
        ("A child runs across right to left in front of the ego at 30 km/h.", "roadside_right"),
        ("pedestrian crossing left->right, ego 30 km/h", "roadside_left"),
        ("Ego 25 km/h; a jogger crosses L > R.", "roadside_left"),
    ],
)
def test_a_crossing_direction_in_notation_starts_at_its_first_side(text, expected):
    """ "L->R", "right to left": the crossing starts on the side said first."""
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Ego 40 km/h. An old man shuffles off the far kerb in front of the ego.", "roadside_left"),
        ("At 20 mph a woman stepped out from the opposite pavement right in front of me.", "roadside_right"),
        ("Ego 30 km/h; a boy runs from the near kerb across the road ahead.", "roadside_right"),
        ("Doing 30 mph, a kid ran out from the far side of the road into my path.", "roadside_right"),
    ],
)
def test_a_far_or_near_kerb_follows_the_writers_driving_side(text, expected):
    """The far kerb is across the road: on the left where traffic keeps right, on the right where it
    keeps left (a writer in miles per hour)."""
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "At 20 mph a man walked out from the far side of the road, that is from my left, into my path.",
            "roadside_left",
        ),
        (
            "Ego 30 km/h; a girl comes off the opposite kerb (i.e. from the right) in front of the car.",
            "roadside_right",
        ),
    ],
)
def test_a_far_side_restated_later_as_a_plain_side(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Ego 30 km/h. A child runs across to the left in front of the ego.", "roadside_right"),
        ("At 20 mph a dog dashed across the road towards the right, just in front of me.", "roadside_left"),
        ("Ego 40 km/h; a jogger crosses over to the right 20 m ahead.", "roadside_left"),
        ("Ego 40 km/h; a jogger crosses from the left to the right 20 m ahead.", "roadside_left"),
    ],
)
def test_a_side_a_crossing_goes_to_puts_its_start_on_the_other(text, expected):
    assert relation(text) == expected


def test_a_side_of_another_road_user_is_a_place_not_where_a_crossing_goes():
    assert relation("Ego 30 km/h. A boy crosses to the left of the parked bus, in front of the ego.") == "roadside_left"


def _side_started(text: str) -> str | None:
    """The side of the ego a road user starts on: said by its relation, or by its offset at the edge of
    the ego's lane (a rider going along the road)."""
    a = read(text).actors[0]
    if a.relation in ("left", "right", "roadside_left", "roadside_right"):
        return a.relation.removeprefix("roadside_")
    if a.lateral_m:
        return "left" if a.lateral_m > 0 else "right"
    return None


@pytest.mark.parametrize(
    "text, expected",
    [
        # a bare "inside" is the kerb side of the writer's road: the left where speeds are in mph
        ("Rolling at 10 mph in town, a courier on a bike crept up on our inside and rode on.", "left"),
        ("Doing 15 mph past the shops, a cyclist nipped up the inside of me and kept going.", "left"),
        ("At 20 km/h in traffic a cyclist rolls along on our inside and carries on.", "right"),
        ("Doing 30 mph when a cyclist came by on the outside and kept going.", "right"),
    ],
)
def test_a_bare_inside_or_outside_is_a_side_of_the_writers_road(text, expected):
    assert _side_started(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "At 40 mph on the bypass a van tore past me on the outside and then cut in just ahead of me.",
        "Doing 50 mph in the middle lane when a hatchback shot up the inside and cut in ahead of me.",
        "At 60 km/h a motorbike came up on the outside of us and pulled in sharply in front.",
    ],
)
def test_one_that_comes_up_or_past_on_a_side_starts_behind_the_ego(text):
    assert read(text).actors[0].relation in ("behind", "left", "right")


@pytest.mark.parametrize(
    "text, expected",
    [
        ("At 30 mph a car pulled out of a lay-by on my left in front of me.", "roadside_left"),
        ("A van pulled out of a parking space on my right just ahead of me at 30 mph.", "roadside_right"),
        ("Doing 40 km/h, a taxi pulls out of a driveway on the left into our lane.", "roadside_left"),
        ("At 20 km/h, a cyclist shoots out of a driveway on the left across the road.", "roadside_left"),
    ],
)
def test_out_of_a_place_beside_the_road_is_from_the_roadside_not_a_junction_arm(text, expected):
    """A driveway, a bus stop, a lay-by or a parking space is beside the carriageway: what comes out of
    it pulls in (or crosses) from that side, not out of a side road (no junction arm); a vehicle out of
    a private way (a driveway) turns into the road from the roadside."""
    actor = read(text).actors[0]
    assert actor.relation in (expected, expected.removeprefix("roadside_"))
    assert actor.behaviours[0][0] in ("cut_in", "cross_in_front", "turn_into")


@pytest.mark.parametrize(
    "text, expected",
    [
        # a vehicle that comes out of a place beside the carriageway starts at that roadside, whatever owns
        # the place ("the builders' yard", "the hotel gates", "the school car park", "a farm track")
        ("Doing 35 mph, a delivery truck nosed out of the builders' yard on my right just in front of me.",
         "roadside_right"),
        ("At 50 km/h a minibus eased out of the hotel gates on the left into our lane.", "roadside_left"),
        ("A pickup rolled out from the school car park on our left straight into my path at 25 mph.", "roadside_left"),
        ("Cruising at 60 km/h, a tractor crept out of a farm track on the right a few metres ahead.",
         "roadside_right"),
        # no side said: the writer's near kerb (the left of one who gives miles per hour)
        ("At 30 mph the coach lurched out of the stop ahead of me without indicating.", "roadside_left"),
        ("A minibus edged out from its stop just ahead of us at 40 km/h.", "roadside_right"),
    ],
)  # fmt: skip
def test_a_vehicle_out_of_a_place_beside_the_road_starts_at_that_roadside(text, expected):
    assert read(text).actors[0].relation == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # going to, past or by such a place is no start there
        ("At 40 mph a van in the right lane pulled in to the stop on my left just ahead of me.", "right"),
        ("A lorry in the left lane overtook the bus waiting at the stop on my left at 30 mph.", "left"),
        # backing out of it: into the lane it backs across (the layers have no reversing)
        ("A van reversed out of a driveway on the right into my path at 20 mph.", "right"),
        # a farm or a field is no place of that kind: only the place noun at the head decides
        ("At 40 mph a tractor on the right came out of the farm and cut in ahead of me.", None),
    ],
)
def test_near_misses_of_a_place_beside_the_road(text, expected):
    relation = read(text).actors[0].relation
    assert not str(relation).startswith("roadside") and (expected is None or relation == expected)


def test_a_vehicle_pulling_out_of_a_place_beside_the_road_stands_there_and_plays_a_cut_in(tmp_path):
    """Its layers: standing at the roadside far enough ahead for the ego to close in (a distance said is
    its gap when it pulls out), then cutting in; the scenario plays and it ends ahead in the ego's lane."""
    from vei_scenario.language.corpus_check import played_problems
    from vei_scenario.language.rules_backend import layers_from_text

    layers = layers_from_text("At 30 mph a bus pulled out of the stop on my left 10 m ahead of me.", 0)
    adv = layers["adversaries"][0]
    assert adv["spawn"]["relation"] == "roadside_left" and adv["speed_mps"] == 0.0
    assert adv["spawn"]["longitudinal_m"] > 20.0
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []


@pytest.mark.parametrize(
    "text, expected",
    [
        # a count of lanes with a side says how far over a road user is: a lane on that side
        ("At 80 km/h on a three-lane motorway, a van two lanes to our left moved across into the lane next to ours.",
         "left"),
        ("Doing 110 km/h on the autobahn, a sports car three lanes over on my right cut across into my lane.", "right"),
        ("At 100 km/h a coach 2 lanes to the ego's right drifted across one lane.", "right"),
    ],
)  # fmt: skip
def test_a_count_of_lanes_to_a_side_is_a_lane_on_that_side(text, expected):
    assert read(text).actors[0].relation == expected


@pytest.mark.parametrize(
    "text, lanes",
    [
        # the road's lanes on a side of something else, or the ego's own side: no road user's place
        ("On a road with two lanes to the left of the median at 80 km/h, a van ahead braked.", 2),
        ("At 80 km/h on a road with 2 lanes on our side, a truck ahead braked.", 2),
    ],
)
def test_a_count_of_the_roads_lanes_is_no_place(text, lanes):
    reading = read(text)
    assert reading.actors[0].relation == "ahead" and reading.lanes == lanes


@pytest.mark.parametrize(
    "text",
    [
        # a rider from the other side of a junction who rides on comes from the opposite arm
        "At the crossroads I was turning right at 15 km/h; a cyclist came from the opposite side going straight.",
        "At the junction I turned left at 20 km/h and a scooter from the other side carried straight on into me.",
        "At the T-junction, ego turning left at 15 km/h, a cyclist from the other side goes straight ahead.",
    ],
)
def test_a_rider_from_the_other_side_of_a_junction_comes_from_the_opposite_arm(text):
    assert read(text).actors[0].relation == "junction_opposite"


@pytest.mark.parametrize(
    "text",
    [
        # a walker from there, the far side of the road, or a road away from any junction: a crossing
        "A pedestrian came from the opposite side at the crossroads and I stopped at 30 km/h.",
        "At the crossroads a cyclist came from the other side of the road across in front of me at 30 km/h.",
        "At 30 km/h on a straight road a cyclist came from the opposite side.",
    ],
)
def test_near_misses_of_the_opposite_arm(text):
    assert read(text).actors[0].relation != "junction_opposite"


# A degree word before a place phrase ("right in front of me", "just ahead", "right behind us")
# sharpens the place and never changes it: the road user starts where the bare phrase puts it.
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A taxi pulled up right in front of us and the driver got out.", "ahead"),
        ("A lorry braked just in front of me at 40 km/h.", "ahead"),
        ("A bus halted right ahead of us.", "ahead"),
        ("A pickup braked directly in front of us.", "ahead"),
        ("A hatchback sat right behind me for a mile, then overtook.", "behind"),
    ],
)
def test_a_degree_word_keeps_the_place_it_sharpens(text, expected):
    assert relation(text) == expected
    bare = text.replace("right ", "").replace("just ", "").replace("directly ", "")
    assert relation(bare) == expected  # (the same start as without the degree word)


def test_a_degree_word_before_a_place_still_says_how_close():
    # the danger the degree word says of an act at the ego stays read alongside the place
    spec = read("A lorry braked just in front of me at 40 km/h.").actors[0]
    assert spec.relation == "ahead" and abs(spec.speed_mps - 40 / 3.6) < 1e-9


@pytest.mark.parametrize(
    "text, behaviour, turn",
    [
        # near misses: "right" is the side a road user turns to, not a degree of the place after it
        ("The cyclist turns right in front of me.", "forced_turn", "right"),
        ("A van turned right into the side road just ahead of us.", "forced_turn", "right"),
    ],
)
def test_a_side_word_before_a_place_stays_a_turn(text, behaviour, turn):
    name, cfg, *_ = read(text).actors[0].behaviours[0]
    assert (name, cfg.get("turn")) == (behaviour, turn)


def test_place_after_degree_needs_a_degree_word_and_a_place():
    from vei_scenario.language.reader import _relation_length
    from vei_scenario.language.sides import place_after_degree

    words = "a van stopped right in front of us".split()
    assert place_after_degree(words, 3, ("right", "in", "front"), _relation_length) == 8
    words = "he arrived just in time".split()  # "in time": no place after the degree word
    assert place_after_degree(words, 2, ("just", "in", "time"), _relation_length) is None
    words = "a car in the right lane".split()  # no degree word where the phrase starts
    assert place_after_degree(words, 4, ("right", "lane"), _relation_length) is None


@pytest.mark.parametrize(
    "text, expected",
    [
        # something that happened, told in British road words with metric speeds: a keep-left country
        (
            "The rider said she was doing 30 km/h along Station Parade when a boy darted out from between two "
            "parked vans on the nearside.",
            "roadside_left",
        ),
        (
            "Our minibus was travelling at 40 km/h when a woman stepped off the kerb and walked into our path.",
            "roadside_left",
        ),
        (
            "The driver stated that she was travelling at 25 km/h when a girl ran out from behind a parked lorry on "
            "the nearside.",
            "roadside_left",
        ),
        # no unit at all: the same British words in a told event
        ("A jogger ran out from the nearside verge and the taxi driver braked hard.", "roadside_left"),
    ],
)
def test_british_road_words_in_a_told_event_keep_left(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: a test line in the present tense keeps Euro NCAP's convention (the nearside is the right)
        ("Ego at 40 km/h; a child runs out from behind a parked van on the nearside.", "roadside_right"),
        ("An adult walks out from the nearside kerb at 5 km/h while the VUT approaches at 40 km/h.", "roadside_right"),
        # a told event with no British road word keeps the default
        ("I was doing 40 km/h when a boy ran out from the sidewalk and crossed in front of me.", "roadside_right"),
    ],
)
def test_a_test_line_or_american_words_keep_right(text, expected):
    assert relation(text) == expected


def test_told_in_the_past_counts_finite_verbs():
    from vei_scenario.language.sides import told_in_the_past

    assert told_in_the_past("she said a boy darted out and she braked".split())
    assert not told_in_the_past("a truck parked on the nearside hides a child who steps out".split())
    assert not told_in_the_past("a child runs out from behind two parked vans".split())


@pytest.mark.parametrize(
    "text, expected",
    [
        # lanes are numbered from the kerb: keeping left a higher number is further right ...
        ("Doing 60 mph in lane one, I saw a tanker in lane two swing across into my lane.", "right"),
        ("I was in lane 2 at 55 mph when a coach in lane 1 drifted into my lane.", "left"),
        # ... keeping right, further left
        ("The AV holds lane 3 at 100 km/h; a coupe in lane 2 merges into the AV's lane 20 m ahead.", "right"),
        # the ego's lane is the one a road user moves into directly in front of it
        (
            "The insured was doing 50 mph when a motorbike moved from lane 3 into lane 2 directly in front of "
            "the insured vehicle.",
            "right",
        ),
        # a side said plainly after the lane's number wins
        ("Ego in lane 2 at 90 km/h; a van in lane 1 (on the ego's left) cuts in ahead of it.", "left"),
    ],
)
def test_numbered_lanes_are_compared_with_the_egos_number(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # near misses: a lane number that is no lane of the road user, and a distance after "lane"
        "In lane 2 at 90 km/h, the ego follows a van that brakes hard 30 m ahead.",
        "The van stopped in my lane 2 m ahead of me while I was doing 20 mph.",
    ],
)
def test_a_number_that_names_no_other_lane_gives_no_side(text):
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text",
    [
        # the ego following a road user: that one is ahead of it, wherever the sentence starts
        "Wet evening, ego following a school bus at 25 m. The bus pulls in and stops.",
        "Night drive: ego following a moped at 15 m, the moped pulls in to the side and halts.",
        "Rainy night: ego is following a minibus at 30 m when the minibus brakes hard.",
        "Test: the ego tails a delivery van through town and the van stops suddenly.",
    ],
)
def test_what_the_ego_follows_is_ahead(text):
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text",
    [
        # a kerb or crossing said "at" after what a road user ahead does is where it does it
        "The ego follows a cyclist who stops at the pelican crossing.",
        "Ahead of the ego a scooter rider slows and halts at the crosswalk.",
    ],
)
def test_a_crossing_where_one_ahead_stops_is_a_landmark(text):
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: a road user following the ego is behind it; one waiting at a crossing is at the kerb
        ("A hatchback is following the ego at 20 m and then overtakes.", "behind"),
        ("A pedestrian waits at the zebra crossing and then crosses in front of the ego.", "roadside_right"),
    ],
)
def test_following_the_ego_and_waiting_at_a_crossing_keep_their_places(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a road user at a place beside the carriageway on a side starts at that roadside, not in a lane
        ("A coach waiting in a lay-by on the right 50 m ahead pulls out into the ego's lane.", "roadside_right"),
        ("A minibus sitting at the bus stop on the left pulls out 30 m ahead of the ego.", "roadside_left"),
        ("Ego at 30 km/h; a taxi at the bus stop on the right moves off into the ego's lane.", "roadside_right"),
        # near misses: a finite verb of arriving there says where it stops, a landmark
        ("The bus in front of the ego pulls in at the stop on the left and stops.", "ahead"),
        ("Ego at 40 km/h behind a bus; the bus stops at the stop on the right.", "ahead"),
    ],
)
def test_a_place_beside_the_road_where_one_waits_is_its_roadside(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # the oncoming lane said of one already said to come from behind is where it overtakes
        ("A van from behind overtakes the ego in the oncoming lane and pulls back in.", "behind"),
        ("Ego at 80 km/h; a sports car comes up from behind and passes us in the opposite lane.", "behind"),
        ("A motorbike behind me swung out into the oncoming lane to overtake.", "behind"),
        # near misses: first said to be in that lane, it comes towards the ego
        ("A bus in the oncoming lane comes towards the ego.", "oncoming"),
        ("A lorry in the oncoming lane overtakes a tractor and comes at us in our lane.", "oncoming"),
    ],
)
def test_the_oncoming_lane_of_one_from_behind_is_where_it_overtakes(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a side said and at once taken back (a phone-in, a voice note, a 911 call, a text, a statement):
        # the side it is put right to
        ("At 20 mph a van came out of a side road on the right, no, sorry, on the left, and I braked.",
         "junction_left"),
        ("Doing 30 mph and a kid ran out from the left - wait, no, from the right - straight in front of me.",
         "roadside_right"),
        ("I was at 40 km/h when a cyclist on my right, I mean my left, swerved into my lane.", "left"),
        ("At 25 mph a jogger stepped out from the right, sorry, left, in front of me.", "roadside_left"),
        ("Ego 30 km/h. A scooter comes out of a driveway on the left... correction, on the right.", "roadside_right"),
        # near misses: no side taken back
        ("At 20 mph a van came out of a side road on the right, no indicator, and I braked.", "junction_right"),
        ("Doing 30 mph a kid ran out from the left, no warning, right in front of me.", "roadside_left"),
        ("At 20 mph a van came out of the side road on the left, no right turn there, and I braked.", "junction_left"),
    ],
)  # fmt: skip
def test_a_side_taken_back_is_the_side_put_right(text, expected):
    assert relation(text) == expected


def _names(text: str) -> list[str]:
    return [b[0] for b in read(text).actors[0].behaviours]


# a rider travelling on the ego's half of the road ("on my side of the road", "on our side") at the
# ego, or a verb of riding or driving right before "at" + the ego ("rode at me"): it comes head-on in
# the ego's lane; "side" owned by someone is a half of the road, not the edge one keeps to
HEAD_ON_ON_THE_EGO_S_SIDE = [
    "I was going about 40 and a lad on a scooter was riding on my side of the road straight at me.",
    "Doing 30 mph on the lane, a cyclist pedalling along on our side of the road straight towards us.",
    "A kid on an e-scooter rode at me in my lane while I was doing 20 mph.",
    "We were at 50 km/h when a cyclist on our side of the road rode directly at us.",
    "At 25 km/h an e-scooter rider zoomed at us on our side of the road with no lights.",
]


@pytest.mark.parametrize("text", HEAD_ON_ON_THE_EGO_S_SIDE)
def test_riding_at_the_ego_on_its_side_is_the_wrong_way(text):
    assert _names(text) == ["wrong_way"]


# near misses: along the edge of the road towards the ego (it keeps to its kerb), on its own side
# (oncoming in its own lane), and a verb that is no travel before "at" the ego
NOT_HEAD_ON_ON_THE_EGO_S_SIDE = [
    "I was doing 30 mph and a cyclist riding down the side of the road towards me kept to the kerb.",
    "I was doing 30 mph and a cyclist on his side of the road came towards me.",
    "I was doing 30 mph and a cyclist on the pavement waved at me.",
]


@pytest.mark.parametrize("text", NOT_HEAD_ON_ON_THE_EGO_S_SIDE)
def test_riding_towards_the_ego_elsewhere_is_not_the_wrong_way(text):
    assert "wrong_way" not in _names(text)


# a move into the ego's lane over the line that divides the two ways ("drifted over the centre line
# into my lane", "veered across the white line") or onto the ego's half of the road ("swung onto our
# side of the road"): it comes from the other way's half, so it is head-on, not a cut-in from beside
OVER_TO_THE_EGO_S_HALF = [
    "At 60 km/h a van veered across the centre line into my lane.",
    "Doing 45 mph, a pickup drifted over the center line into my lane.",
    "We were at 50 kph when a bus swerved onto our side of the road.",
    "On the bend at 50 km/h a lorry cut the corner onto our side of the road.",
    "At 40 mph a tractor swung onto my side of the road on the bend.",
    "At 60 km/h a van came over the white line into my lane.",
]


@pytest.mark.parametrize("text", OVER_TO_THE_EGO_S_HALF)
def test_a_move_over_to_the_ego_s_half_is_head_on(text):
    assert _names(text)[:1] == ["wrong_way"]


# near misses: from a lane beside (its side said, or over a lane line), and onto the road's edge
NOT_OVER_TO_THE_EGO_S_HALF = [
    "At 40 mph a car on my right drifted into my lane.",
    "On the motorway at 70 mph a car from the left lane moved over into my lane.",
    "At 40 mph a car in the next lane drifted across the lane line into my lane.",
    "At 40 mph a van on my left swerved onto my side of the road.",
]


@pytest.mark.parametrize("text", NOT_OVER_TO_THE_EGO_S_HALF)
def test_a_move_into_the_ego_lane_from_beside_is_no_head_on(text):
    assert "wrong_way" not in _names(text)
