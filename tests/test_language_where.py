"""Where a road user starts: classes of wording that place it, each in wordings of our own, with
near misses that look alike and must not be read so."""

import pytest

from vei_scenario.language.reader import read


def relation(text: str) -> str | None:
    return read(text).actors[0].relation


@pytest.mark.parametrize(
    "text, expected",
    [
        # a side word, then an end of a vehicle and its part: where it was hit, not where it came from
        ("Doing 30 mph, a jogger stepped off the kerb on my left and bounced off the offside front corner.",
         "roadside_left"),
        ("At 20 mph a cyclist pulled out from the pavement on the right and hit the nearside rear door.",
         "roadside_right"),
        # an end closing the phrase ("the offside front"), and the part after a second word
        ("At 25 mph a child ran out from the pavement on my left and went under the offside front.", "roadside_left"),
        ("At 30 mph a scooter came out of a side road on my right and scraped the nearside rear passenger door.",
         "junction_right"),
    ],
)  # fmt: skip
def test_a_side_word_before_an_end_and_a_part_is_a_part_of_a_vehicle(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: the side word names a kerb or a lane, and "front" is no part here
        ("Doing 20 mph, a boy ran out from the nearside in front of me.", "roadside_left"),
        ("At 40 mph a van in the offside lane moved over in front of me.", "right"),
    ],
)
def test_a_side_word_of_a_kerb_or_lane_stays_a_place(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a side word before "side road" / "side street" / "minor road": the arm on that side
        ("Ego at 40 km/h through the crossroads; a cyclist from the right side road crosses without stopping.",
         "junction_right"),
        ("At the junction, ego 30 km/h, a van pulls out of the left minor road in front of us.", "junction_left"),
        ("Ego 35 km/h at the intersection; an e-scooter from the left side street rides across our path.",
         "junction_left"),
    ],
)  # fmt: skip
def test_a_side_word_before_a_side_road_is_that_arm(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: "the left side of the road" is a kerb side, and "the right side" alone no road
        ("At 30 km/h a pedestrian crosses from the left side of the road.", "roadside_left"),
        ("At 30 km/h a pedestrian crosses from the right side.", "roadside_right"),
    ],
)
def test_a_side_of_the_road_is_no_side_road(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a road named by its name, out of which a road user comes: a junction arm
        ("Doing 25 mph down the high street when a cyclist shot out of Albert Street on my left.", "junction_left"),
        ("A van pulled out of Elm Close on our right while we were doing 30 mph.", "junction_right"),
        ("I was doing 20 mph when a scooter emerged from Mill Lane (the turning on my left) without stopping.",
         "junction_left"),
    ],
)  # fmt: skip
def test_a_named_road_a_road_user_comes_out_of_is_a_junction_arm(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: a place named with a capital is not a road ("out of Tesco"), and a lane is a lane
        ("At 20 mph a van pulled out of the Tesco car park on my left.", "roadside_left"),
        ("At 60 mph a lorry in the left lane drifted into mine.", "left"),
    ],
)
def test_a_named_place_is_no_road(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # "approaching from X": where it approaches from, not that it comes towards the ego
        ("At 40 km/h a motorbike approaching from behind swerves past and cuts in front of us.", "behind"),
        ("I was doing 30 mph when a cyclist approaching from behind overtook me.", "behind"),
        ("Ego at 50 km/h; a van approaches from behind and overtakes.", "behind"),
    ],
)
def test_approaching_from_a_place_is_not_oncoming(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # near misses: approaching with no origin, or from the front, is still oncoming
        "On a narrow road at 40 km/h, an approaching van swings into our lane.",
        "Ego at 50 km/h; a lorry approaching from the front drifts over the centre line.",
    ],
)
def test_approaching_alone_is_still_oncoming(text):
    assert relation(text) == "oncoming"


@pytest.mark.parametrize(
    "text",
    [
        # the other way said with another adjective or noun: it comes towards the ego
        "Ego at 60 km/h on a bend; a truck coming in the contrary direction drifts into our lane.",
        "At 50 mph, a van travelling in the reverse direction crossed the centre line.",
        "Ego 70 km/h, one lane each way; a car driving the other direction swerves into the ego lane.",
    ],
)
def test_the_other_direction_in_other_words_is_oncoming(text):
    assert relation(text) in ("oncoming",)


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: turning or looking "the other way" says where it turns or looks
        ("At 30 km/h a cyclist ahead of us turns the other direction and stops.", "ahead"),
    ],
)
def test_turning_the_other_direction_is_no_start(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a walker crossing the mouth of the road the ego turns into is on the side it turns to
        # (miles per hour: the near kerb is the left, so a right turn tells the kerb apart from it)
        ("I turned right into Elm Street at 10 mph and a man was crossing the side road, so I waited.",
         "roadside_right"),
        ("The ego turns left into a side street; a woman with a pram is crossing the side street.", "roadside_left"),
        ("Turning right at 10 mph, I had to stop for a jogger crossing the minor road I was turning into.",
         "roadside_right"),
    ],
)  # fmt: skip
def test_a_walker_crossing_the_arm_the_ego_turns_into_is_on_that_side(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: a side said of the walker wins, and without a turn the near kerb stays
        ("The ego turns left into a side street; a man crosses the side street from the right.", "roadside_right"),
        ("At 30 km/h on a straight road, a child crosses from the left.", "roadside_left"),
    ],
)
def test_a_side_said_of_the_walker_wins_over_the_turn(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # a side word, a word that says which part, then a kerb noun: that kerb
        ("Ego turning right at 15 km/h; a pedestrian steps off the right corner kerb and crosses.", "roadside_right"),
        ("At 30 km/h a jogger runs out from the left grass verge in front of us.", "roadside_left"),
        ("At 25 km/h a child steps off the left side pavement into the road.", "roadside_left"),
    ],
)
def test_a_side_word_and_a_modifier_before_a_kerb_noun_is_that_kerb(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # from a kerb with no side said into a lane of a side: the kerb beside that lane
        ("Ego at 80 km/h; a cyclist comes off the hard shoulder into the left lane just ahead.", "roadside_left"),
        ("At 60 km/h on a dual carriageway a pedestrian stepped off the verge into the right lane.", "roadside_right"),
        ("Ego 70 km/h, two lanes each way; an e-scooter rider swerves off the shoulder into the right lane.",
         "roadside_right"),
    ],
)  # fmt: skip
def test_from_an_unsided_kerb_into_a_lane_of_a_side_is_that_kerb(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # one that passes the ego to turn across its path starts behind it, though the pass is read into the turn
        "Doing 20 mph, a van overtook me and immediately turned left across my path into a side road.",
        "At 30 km/h at the junction a taxi overtakes the ego and turns left across its bonnet.",
        "I was cycling at 15 mph at the crossroads when a car overtook me and then turned left across my path.",
    ],
)
def test_one_that_overtakes_the_ego_to_turn_across_it_starts_behind(text):
    assert relation(text) == "behind"


def test_an_overtaker_said_in_a_lane_starts_in_that_lane():
    text = "At 30 km/h at the junction a taxi in the right lane overtakes the ego and turns left across its bonnet."
    assert relation(text) == "right"


@pytest.mark.parametrize(
    "text",
    [
        # the ego named as a label, then a colon or a comma, then its verb of following: the one followed leads
        "Ego: following a lorry at 70 km/h on a motorway. The lorry brakes hard.",
        "Host vehicle: tailing a minibus at 40 km/h. The minibus stops suddenly.",
        "The ego, following a tanker at 60 km/h, has to brake when the tanker stops.",
    ],
)
def test_the_ego_following_after_a_colon_or_comma_has_it_ahead(text):
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text",
    [
        # what the ego follows or sits behind, said in a lane, is in the ego's own lane: ahead
        "I was following a minibus in the right lane at 40 mph when it braked sharply.",
        "We were stuck behind a tractor in the left-hand lane, doing 15 mph, when it stopped dead.",
        "Doing 45 mph I came up behind a horse rider in the nearside lane.",
        "The ego follows a pickup in the left lane at 70 km/h; the pickup brakes to a stop.",
    ],
)
def test_what_the_ego_follows_in_a_lane_is_ahead(text):
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: the ego's own lane said apart, or someone merely ahead in a lane, keep the side
        ("I was in the right lane following traffic at 50 mph when a minibus in the left lane braked.", "left"),
        ("A car ahead in the left lane brakes hard; the ego drives at 60 km/h in the right lane.", "left"),
        ("I was doing 40 mph when a minibus in the right lane braked hard.", "right"),
    ],
)  # fmt: skip
def test_a_lane_of_someone_not_followed_keeps_its_side(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # a road user said in a lane and in front of the ego, whose own lane is not said: the ego is in
        # that lane too, behind it (a text, a forum post, a voice note, a police line, a test line)
        "A cyclist was pedalling along in the right lane in front of me at 12 mph, two lanes each way.",
        "there was this bus in the left lane right in front of us doing like 20 km/h, so slow",
        "Two lanes per direction. A horse and rider in the nearside lane ahead of me at 10 mph.",
        "Vehicle 2 was travelling in lane 2 directly in front of my vehicle at 30 mph.",
        "Ego at 50 km/h. A tractor in the right lane in front of the ego travels at 25 km/h.",
        "On the dual carriageway at 40 mph, a learner car in the inside lane in front of me was crawling along.",
        "Doing 60 mph, there was a tractor ahead of me in the left lane doing maybe 15 mph.",
    ],
)
def test_a_lane_said_of_what_is_in_front_of_the_ego_is_the_egos_own(text):
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: the ego's own lane said apart, or in front of someone else, keep the side
        ("I was in the left lane at 40 mph; a van in the right lane in front of me braked.", "right"),
        ("A van in the right lane in front of a lorry braked hard. I was doing 40 mph.", "right"),
        ("At 50 km/h, a van in the left lane cut in front of me.", "left"),
        ("At 40 mph a pickup in the lane to my left suddenly swings across in front of me to turn right.", "left"),
    ],
)  # fmt: skip
def test_a_lane_in_front_of_someone_else_keeps_its_side(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # a verb of coming, where it comes along, then "towards", "at" or "for" the ego: it comes at the ego
        "Doing 40 mph on a country lane, a tractor came round the corner towards me.",
        "At 50 km/h a motorbike came flying down the hill straight at me.",
        "At 30 mph a delivery van came barrelling round the bend right at us.",
        "At 60 km/h on the A-road a tractor was heading right for us.",
        "Doing 25 mph, a scooter rider rode down the middle of the lane towards my car.",
    ],
)
def test_coming_at_the_ego_past_where_it_comes_is_oncoming(text):
    actor = read(text).actors[0]  # (a rider going on comes along the ego's lane, ahead and facing it)
    assert actor.relation == "oncoming" or (actor.relation, actor.facing) == ("ahead", "against")


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: a move sideways towards the ego, or coming out of or off a place towards it
        ("At 20 mph a cyclist swerved towards me.", None),
        ("At 20 mph a van came out of the side road on my left towards me.", "junction_left"),
        ("At 20 mph a cyclist came off the pavement on my left towards me.", "roadside_left"),
        ("At 30 mph a cyclist came up behind me and rode past towards the lights.", "behind"),
    ],
)  # fmt: skip
def test_moving_sideways_or_out_towards_the_ego_is_not_oncoming(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # one overtaking another, then coming at the ego: the overtaker comes, past what it overtakes
        "Doing 50 mph on the A-road, a lorry was overtaking a tractor and came towards us on our side.",
        "At 80 km/h a bus overtook a lorry and came head-on at us.",
        "At 70 km/h a car was passing a van, right on our side of the road, head-on towards us.",
    ],
)
def test_an_overtaker_coming_at_the_ego_is_oncoming(text):
    assert relation(text) == "oncoming"


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: a new subject after "and", or the ego overtaken
        ("At 50 mph a van overtook a cyclist and a car came towards us.", None),
        ("At 50 mph a van overtook me and cut in; a car was coming the other way.", None),
    ],
)  # fmt: skip
def test_another_coming_at_the_ego_leaves_the_overtaker(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # a rider at the kerb or in a cycle lane, no side said, overtaking the ego: from behind it
        "A kid on an e-scooter in the cycle lane overtook me at 40 km/h; I was doing 30 km/h.",
        "Doing 15 mph, a courier on a bicycle came along the kerb and overtook me.",
        "At 20 km/h in traffic, a cyclist riding in the bike lane shot past me.",
    ],
)
def test_a_rider_at_the_kerb_overtaking_the_ego_starts_behind(text):
    assert relation(text) == "behind"


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: a side said keeps it, and one swerving out of the cycle lane starts there
        ("Doing 15 mph, a cyclist in the cycle lane on my left overtook me.", "left"),
        ("Doing 30 km/h, a cyclist in the bike lane swerved into my lane.", "roadside_right"),
    ],
)  # fmt: skip
def test_a_rider_at_the_kerb_not_overtaking_keeps_the_kerb(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # travelling "on the wrong side" is going the wrong way, and "in my own lane" is the ego's lane
        "At 20 mph I saw a cyclist on the wrong side, riding towards me.",
        "At 20 mph a moped was on the wrong side, heading for me.",
        "At 30 mph a lad on a scooter was on the wrong side, in my own lane, and I had to mount the kerb.",
    ],
)
def test_on_the_wrong_side_or_in_my_own_lane_comes_at_the_ego(text):
    actor = read(text).actors[0]
    assert actor.relation == "oncoming" or (actor.relation, actor.facing) == ("ahead", "against")


def test_from_the_far_side_is_still_a_kerb():
    # near miss: coming from the far side of the road is a kerb, not the wrong way
    assert relation("At 30 mph a pedestrian stepped out from the far side.") == "roadside_right"


@pytest.mark.parametrize(
    "text, expected",
    [
        # the passenger side is the nearside and the driver's side the offside, by the writer's convention
        ("At 20 mph a car pulled out of a side road on the driver's side.", "junction_right"),
        ("At 20 mph a man stepped out from the passenger side.", "roadside_left"),
        ("At 30 km/h a child ran out from the driver's side.", "roadside_left"),
        ("At 30 km/h a dog ran out from the passenger's side.", "roadside_right"),
        # and the ego's own nearside or offside, said as where someone is, is that side of the ego
        ("At 20 mph a car came out of a side road on my offside.", "junction_right"),
        ("Doing 30 mph, a cyclist was riding along on my nearside and swerved into me.", "roadside_left"),
    ],
)  # fmt: skip
def test_passenger_and_driver_sides_follow_the_convention(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: a part of a vehicle named by the side, where it was hit, is no place
        ("At 20 mph a child ran out from the pavement on my right and hit the passenger side door.", "roadside_right"),
        ("At 20 mph a cyclist came off the kerb on my right and scraped the driver's side mirror.", "roadside_right"),
        ("At 30 mph a van pulled out of a side road on the left and hit our offside.", "junction_left"),
    ],
)  # fmt: skip
def test_a_vehicle_side_hit_says_no_start(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # a question of how far behind someone the one asked was: the ego was behind, so it is ahead
        "How far behind the bus were you? About 10 m. It stopped dead and I hit it at 20 mph.",
        "Q: How close behind the lorry were you at the time? A: Maybe 15 metres, doing 50 mph. It braked.",
    ],
)
def test_how_far_behind_someone_the_ego_was_has_it_ahead(text):
    assert relation(text) == "ahead"


def test_a_question_of_how_far_behind_the_ego_someone_was_keeps_it_behind():
    # near miss: the road user is the one asked about, behind the ego
    assert relation("How far behind you was the van? About 5 m, at 40 mph. It hit us.") == "behind"


@pytest.mark.parametrize(
    "text, expected",
    [
        # on a roundabout, one said to be on the ego's side ("on my left") goes round beside it, not from an arm
        ("Going round the roundabout at 15 mph, a cyclist on my left carried straight on past my exit.", "left"),
        ("Circulating on the roundabout at 20 km/h, a scooter on our right kept going round.", "right"),
    ],
)  # fmt: skip
def test_on_a_roundabout_one_on_the_ego_side_goes_round_beside_it(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: coming from a side, or beside the ego at a crossroads, is an arm
        ("At the roundabout a car from my left came on without stopping; I was doing 20 mph.", "junction_left"),
        ("At the crossroads a cyclist on my left carried straight on; I was doing 20 mph.", "junction_left"),
    ],
)  # fmt: skip
def test_coming_from_a_side_at_a_roundabout_is_an_arm(text, expected):
    assert relation(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # a sentence, or a statement after a label's colon, opening on "following": the narrator follows
        "It was raining. Following a bus on the ring road at 30 mph, it stopped dead.",
        "Incident report. Statement: following a tipper lorry at about 40 mph, the lorry braked sharply.",
    ],
)
def test_an_opening_following_later_in_the_text_has_it_ahead(text):
    assert relation(text) == "ahead"


def test_following_said_of_a_road_user_keeps_it_behind():
    # near miss: "following" after the road user it is said of
    assert relation("It was raining. A car following us flashed its lights; I was doing 30 mph.") == "behind"


def test_a_rider_coming_at_the_ego_along_the_kerb_rides_along_facing_it():
    # near miss of coming head-on: a rider kept to the kerb against the traffic rides along its edge
    actor = read("At 20 mph a cyclist rode along the kerb toward me against the traffic, staying tight in.").actors[0]
    assert ([b[0] for b in actor.behaviours], actor.relation, actor.facing) == (["along_road"], "ahead", "against")


@pytest.mark.parametrize(
    "text",
    [
        # an exit said with its order ("at the first exit") where a road user ahead leaves is where it
        # acts, not an arm it comes out of (a diary, a forum post, a report, a text, a test line)
        "On the roundabout at 15 mph, a cyclist ahead of me was very slow, and she came off at the first exit.",
        "Going round at 20 mph, the bus in front of us slowed right down at the second exit.",
        "Roundabout, ego 25 km/h; the lead car ahead stops at the next exit.",
        "I was at 10 mph on the roundabout behind a hatchback that braked at the third exit.",
        "On the roundabout doing 15 mph, the van ahead of me slowed at the last exit.",
    ],
)
def test_an_exit_with_its_order_where_one_ahead_leaves_is_no_arm(text):
    assert relation(text) == "ahead"


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: out of an arm with its order, it comes from that arm
        ("At 30 mph a car came out of the first turning on the left.", "junction_left"),
        ("Doing 25 mph, a van shot out of the next side road on my right.", "junction_right"),
    ],
)
def test_an_arm_with_its_order_come_out_of_is_where_it_starts(text, expected):
    assert relation(text) == expected
