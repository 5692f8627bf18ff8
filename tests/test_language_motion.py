"""One path per road user (:mod:`vei_scenario.language.motion`): the manner said with a path is not a
second behaviour. Wordings written for each construction, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _behaviours(text: str) -> list[str]:
    (actor,) = read(text).actors
    return [b[0] for b in actor.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "At the signalised crossroads a taxi from the right arm drives through against the red light, passing the ego.",
        "A moped rider came out of the junction on my left against a red light.",
        "The ego goes straight on at 30 km/h; a van from the left arm runs the red signal and overtakes the ego.",
    ],
)
def test_running_the_red_is_the_whole_path(text):
    names = _behaviours(text)
    assert "run_red_light" in names and not {"overtake", "turn_into"} & set(names)


@pytest.mark.parametrize(
    "text",
    [
        "At the T-junction a delivery van on the side road to the right stops at the line and waits.",
        "Ego on the main road at 40 km/h; a cyclist on the side road on the left comes to a stop at the give-way line.",
        "A tractor in the side road on my right halts at the junction and sits there while I go past.",
    ],
)
def test_a_road_user_on_a_junction_arm_that_stops_gives_way(text):
    assert _behaviours(text) == ["give_way"]


def test_a_car_standing_on_a_junction_arm_stays_stopped():
    r = read("A parked car stands in the side road on the left; the ego drives past at 30 km/h.")
    assert all(b[0] != "give_way" for a in r.actors for b in a.behaviours)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist on the wrong side of the road rides straight at the ego.",
        "A girl on an e-scooter is riding the wrong way down the middle of the road towards us.",
        "Some lad on a push bike came the wrong way round the bend, on my side, heading for me.",
    ],
)
def test_a_rider_the_wrong_way_away_from_the_kerb_comes_head_on_in_the_ego_lane(text):
    assert _behaviours(text) == ["wrong_way"]


def test_a_rider_the_wrong_way_along_the_kerb_rides_along_the_road():
    assert _behaviours("A kid on a scooter rides against the traffic along the kerb on my left.") == ["along_road"]


@pytest.mark.parametrize(
    "text",
    [
        "The ego is heading southbound on Mill Road at 25 mph. A moped was riding northbound in the southbound lane.",
        "Ego eastbound at 50 km/h; a cyclist heading westbound along the eastbound carriageway.",
        "My car was westbound on the ring road when a van came eastbound down the westbound lane.",
    ],
)
def test_heading_one_compass_way_in_the_lane_of_the_other_is_the_wrong_way(text):
    (actor,) = read(text).actors
    assert [b[0] for b in actor.behaviours] == ["wrong_way"]
    # in the ego's lane facing it, or (said to come the opposite way: sides.py) oncoming drifting over
    assert (actor.relation, actor.facing) in (("ahead", "against"), ("oncoming", None))


@pytest.mark.parametrize(
    "text",
    [
        "A taxi swings out of a driveway on the left and we collide.",
        "A moped darts across from the right pavement and they crash.",
        "The jogger steps off the kerb on the left without looking and we hit.",
    ],
)
def test_a_contact_of_both_parties_is_the_outcome_not_a_behaviour(text):
    r = read(text)
    assert r.intent == "collision" and "sudden_stop" not in [b[0] for a in r.actors for b in a.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist rides straight on in the lane beside the turning ego; the set-up should yield a near miss.",
        "An e-scooter keeps going along the cycle lane on the right while the ego turns right, to yield an impact.",
        "A pedestrian walks along the left verge as the ego passes; the layout is meant to yield a safe pass.",
    ],
)
def test_yield_with_an_object_produces_it_and_is_no_giving_way(text):
    assert "give_way" not in [b[0] for a in read(text).actors for b in a.behaviours]


@pytest.mark.parametrize(
    "text, relation, turn",
    [
        ("A taxi in the left lane 15 m ahead swings right across the ego to turn into a side road.", "left", "right"),
        (
            "The van in the lane to my right cuts left across me to turn into one of the side streets on the left.",
            "right",
            "left",
        ),
        ("A cyclist in the right lane suddenly swerves left across my lane into a side road.", "right", "left"),
    ],
)
def test_a_side_road_turned_into_is_where_it_goes_not_where_it_comes_from(text, relation, turn):
    (actor,) = read(text).actors
    assert (actor.relation, actor.behaviours[0][0], actor.behaviours[0][1]["turn"]) == (relation, "forced_turn", turn)


def test_a_side_road_come_out_of_is_still_where_it_comes_from():
    (van,) = read("A van pulls out of the side road on the left into my lane.").actors
    assert (van.relation, van.behaviours[0][0]) == ("junction_left", "turn_into")


def test_the_gap_said_of_a_forced_turn_is_its_gap_when_it_cuts_across():
    (taxi,) = read("A taxi in the left lane 15 m ahead swings right across the ego to turn into a side road.").actors
    assert taxi.behaviours[0][1]["gap_m"] == 15.0


@pytest.mark.parametrize(
    "text, relation",
    [
        ("A cyclist came out of a side road on the right and turned into my road ahead of me.", "junction_right"),
        ("A moped shot out from the side road on the right straight in front of me.", "junction_right"),
        ("An e-scooter bursts out of a side street on my left into my lane.", "junction_left"),
        ("A girl on a bike nips out of the side road on the left and heads off in front of us.", "junction_left"),
    ],
)
def test_a_rider_or_vehicle_out_of_a_side_road_enters_from_that_arm(text, relation):
    (actor,) = read(text).actors
    assert (actor.relation, actor.behaviours[0][0]) == (relation, "turn_into")


def test_a_walker_out_of_a_side_road_crosses():
    (child,) = read("A child pops out of a side street on the left.").actors
    assert child.behaviours[0][0] == "cross_in_front"


@pytest.mark.parametrize(
    "text",
    [
        "A taxi in the right lane travelling alongside moves across into my lane.",
        "An e-scooter in the bike lane on the right swerves out into my lane just ahead.",
        "A coach in the left lane changes lanes into the ego's lane 20 m ahead.",
        "A van from the lane on our left keeps going straight into our lane ahead of us.",
    ],
)
def test_a_move_into_the_ego_lane_is_a_cut_in(text):
    assert _behaviours(text) == ["cut_in"]


def test_a_move_into_another_lane_is_a_lane_change():
    assert _behaviours("A lorry in the right lane moves over into the left lane.") == ["change_lane"]


@pytest.mark.parametrize(
    "text",
    [
        "At the roundabout a van waiting at the entry on the left gives us the right of way.",
        "A cyclist at the junction on the right gave the ego priority.",
        "A lorry on the side road on my left stops and gives me the way.",
    ],
)
def test_giving_the_ego_the_way_is_giving_way(text):
    assert _behaviours(text)[-1:] == ["give_way"]


@pytest.mark.parametrize(
    "text",
    [
        "At the crossroads a pickup heading southbound made a left turn across the path of the ego, which was "
        "northbound at 30 mph.",
        "V1 was northbound at 40 km/h at the lights. V2, southbound, turned left across the front of V1.",
        "The insured vehicle was eastbound through the junction at 20 mph; a taxi, westbound, turned left "
        "across its path.",
    ],
)
def test_a_left_turn_across_by_the_party_heading_the_other_way_is_a_turn_across(text):
    (actor,) = read(text).actors
    assert (actor.relation, actor.behaviours[0][0]) == ("junction_opposite", "turn_across")


def test_a_left_turn_across_by_a_party_heading_the_same_way_stays_a_forced_turn():
    text = "At the crossroads a pickup heading northbound made a left turn across the path of the ego, northbound too."
    assert _behaviours(text) == ["forced_turn"]


@pytest.mark.parametrize(
    "text",
    [
        "An e-scooter rider was ahead of me on the left. I was hanging back. Then he swung right across my lane.",
        "A taxi was in front of me. I was keeping my distance. Then she turned left into a side street.",
        "A van sat ahead of us in the right lane. We were doing 30 mph. Then he made a left turn across our lane.",
    ],
)
def test_he_or_she_in_a_first_person_story_is_the_road_user_not_the_narrator(text):
    r = read(text)
    (actor,) = r.actors
    assert r.ego_route is None and actor.behaviours[0][0] == "forced_turn"


@pytest.mark.parametrize(
    "text,expected",
    [
        ("A moped squeezing past on my left between me and the verge abruptly pulled out into our path.", ["cut_in"]),
        ("A courier on a bike overtaking on my inside suddenly cut out into my lane in front of me.", ["cut_in"]),
        ("A van overtaking me on the left suddenly swung out into my lane.", ["cut_in"]),
        ("A rider going past on the inside between me and the kerb abruptly turned across my lane.", ["forced_turn"]),
    ],
)
def test_a_participle_after_a_road_user_is_where_it_was_not_a_second_move(text, expected):
    assert _behaviours(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "Waiting to turn left at the crossroads, I saw a cyclist come round the corner on the wrong side of the road"
        " straight towards me.",
        "At the T-junction a kid on a bike swung round the corner the wrong way, riding straight at us.",
        "Turning into the side road at the junction, I met a scooter rider coming round the bend on the wrong side"
        " of the road, straight at me.",
    ],
)
def test_a_rider_the_wrong_way_at_a_junction_still_comes_head_on(text):
    assert _behaviours(text) == ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi comes up from behind, swings out, overtakes me and cuts back in.",
        "On the dual carriageway a van came up behind us, pulled out, passed us and tucked back in ahead.",
        "Behind me a hatchback swung out, overtook me and dived back in.",
    ],
)
def test_pulling_out_just_before_an_overtake_is_how_it_starts(text):
    assert _behaviours(text) == ["overtake"]


def test_a_pull_out_after_a_stretch_behind_the_ego_is_no_move_of_its_own():
    # Sitting behind the ego for a while is following it; the pull-out is how the overtake starts.
    text = "A coach sat behind us for a while, then swung out and overtook us."
    assert _behaviours(text) == ["follow_vehicle", "overtake"]


@pytest.mark.parametrize(
    "text,expected",
    [
        ("A cyclist ahead of me keeping close to the kerb swung right across my lane to turn into a side road.",
         ["forced_turn"]),
        ("A lad on a bike ahead was hugging the curb; then he cut right across my lane to turn into a side street.",
         ["forced_turn"]),
        ("An e-scooter rider filtering between me and the kerb suddenly swerved out into my lane.", ["cut_in"]),
    ],
)  # fmt: skip
def test_a_rider_along_the_kerb_is_in_the_road_not_on_the_footway(text, expected):
    assert _behaviours(text) == expected


def test_a_rider_off_the_kerb_or_pavement_crosses_into_the_road():
    assert _behaviours("A cyclist came off the kerb into my path.") == ["cross_in_front"]
    said = "A cyclist rode on the pavement, then swung out into the road in front of me."
    assert _behaviours(said) == ["cross_in_front"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego 40 km/h on the main road. A van waits at the stop line on the left, letting the ego (40 km/h) go by.",
        "On the side road to our right a cyclist pulls up at the line, allowing us (at 30 mph) to pass.",
        "A lorry at the junction on my left holds back and lets me (doing 25 mph in the main road) through.",
    ],
)
def test_an_aside_in_brackets_after_the_ego_does_not_break_letting_it_go(text):
    assert _behaviours(text)[-1:] == ["give_way"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 50 km/h. A cyclist rides along the right edge in our direction at 15 km/h, ego passes him.",
        "Ego 50 km/h. A walker on the left verge going our way at 5 km/h; the ego overtakes her.",
        "Overtook a cyclist on our way home, he was riding by the verge at about 10 mph.",
        "I went past a mobility scooter on the lane this morning, she was trundling along at 5 mph.",
    ],
)
def test_a_road_user_the_ego_passes_goes_along_ahead_of_it(text):
    (actor,) = read(text).actors
    assert actor.behaviours[0][0] in ("along_road", "keep_lane", "keep_going")
    assert actor.relation in ("ahead", "roadside_left", "roadside_right")


@pytest.mark.parametrize(
    "text",
    [
        "Ego turns right at a junction; an oncoming cyclist goes straight at 20 km/h, ego gives way and "
        "the cyclist passes.",
        "We give way at the T-junction, and a lorry on the main road goes past at 60 km/h.",
        "The ego waits at the give-way line and a motorbike on the main road passes by at 50 km/h.",
    ],
)
def test_a_road_user_passing_while_the_ego_yields_keeps_going(text):
    assert _behaviours(text)[0] in ("keep_going", "keep_lane", "along_road")


@pytest.mark.parametrize(
    "text",
    [
        "Ego 60 km/h on the ring road. A van is following us closely.",
        "Ego at 50 mph, a pickup has been tailing me for miles, braking whenever I braked. It never overtook.",
        "Ego 70 km/h; a lorry follows the ego at 10 m the whole way.",
    ],
)
def test_a_road_user_following_the_ego_follows_it_from_behind(text):
    (actor,) = read(text).actors
    assert actor.behaviours[0][0] == "follow_vehicle"
    assert actor.relation == "behind"


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 20 km/h at a roundabout, a van already going round from the left, we yield. The van carries on round.",
        "Mini-roundabout: the ego waits at the line; a cyclist coming round from the right continues at 15 km/h.",
        "At the roundabout we give way. A lorry from the left keeps going at 25 km/h.",
    ],
)
def test_a_road_user_the_ego_gives_way_to_goes_on_through_the_junction(text):
    (actor,) = read(text).actors
    assert (actor.relation, actor.behaviours[0][0]) in {
        (f"junction_{side}", name) for side in ("left", "right") for name in ("keep_going", "keep_lane")
    }


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 50 km/h; a motorbike comes past us on the right at 80 km/h.",
        "I was doing 40 mph when a van came past me on the outside.",
        "We are at 30 km/h and a cyclist is coming past us on the left.",
    ],
)
def test_coming_past_the_ego_is_overtaking_it(text):
    assert _behaviours(text)[0] == "overtake"


@pytest.mark.parametrize(
    "text",
    [
        "We drive on the left here. An oncoming van turns right across our path at the crossroads.",
        "UK layout, ego at 40 km/h: at the junction an oncoming cyclist turns right across the front of us.",
        "Left-hand traffic. At the crossroads a car coming towards us swings right across our lane.",
    ],
)
def test_in_left_hand_traffic_the_oncoming_turn_across_the_ego_is_to_the_right(text):
    (actor,) = read(text).actors
    assert (actor.relation, [b[0] for b in actor.behaviours]) == ("junction_opposite", ["turn_across"])


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming car turns left across our path at the crossroads.",  # (right-hand traffic: the far side)
        "Ego at 40 km/h. At the crossroads an oncoming van turns right.",  # (right-hand: the near side, no crossing)
    ],
)
def test_the_turn_across_is_to_the_far_side_of_the_traffic_the_text_drives_in(text):
    (actor,) = read(text).actors
    turns_across = [b[0] for b in actor.behaviours] == ["turn_across"]
    assert turns_across == ("left" in text)


def test_driving_on_the_left_lane_says_no_traffic_side():
    from vei_scenario.language.sides import drives_on_left

    for text in ("i am driving on the left lane at 50 km/h", "we were driving on the left edge of the lane at 50 km/h"):
        assert not drives_on_left(text.split(), text)
    for text in ("we are driving on the left , at 50 km/h", "I drove on the left, at 50 km/h", "we keep left here"):
        assert drives_on_left(text.split(), text)


@pytest.mark.parametrize(
    "text, relation",
    [
        ("At the junction a van came out from a side road on the right just ahead of us.", "junction_right"),
        ("At the crossroads an e-scooter exits a side road on the left onto our road 15 m ahead.", "junction_left"),
        ("A cyclist rode out from the side street on my left into the road in front of me.", "junction_left"),
        ("At the T-junction a lorry is leaving the side road on our right as we arrive.", "junction_right"),
    ],
)
def test_coming_out_from_or_leaving_a_side_road_is_turning_into_the_ego_road(text, relation):
    (actor,) = read(text).actors
    assert (actor.relation, actor.behaviours[0][0]) == (relation, "turn_into")


@pytest.mark.parametrize(
    "text, first",
    [
        ("At the crossroads a car comes from the left and drives straight across.", "run_red_light"),
        ("A man walks out from a side street on the left.", "cross_in_front"),
        ("At the roundabout a bus takes the exit on the left.", None),
    ],
)
def test_what_is_not_coming_out_of_a_side_road_stays_as_it_was(text, first):
    (actor,) = read(text).actors
    assert actor.behaviours[0][0] != "turn_into" and (first is None or actor.behaviours[0][0] == first)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist was coming the other way in my lane.",
        "A moped comes round the corner on our side of the road, head on.",
        "A quad bike is riding in the wrong direction towards us.",
        "At the roundabout a cyclist goes the wrong way round, straight towards us.",
        "A tractor was heading the other way down our lane.",
    ],
)
def test_a_road_user_coming_the_other_way_in_the_ego_lane_comes_head_on(text):
    assert _behaviours(text) == ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming car 50 m ahead keeps to its lane.",
        "A van in our lane 30 m ahead drives on at 40 km/h.",
        "A cyclist rides ahead of us in our lane, the same way as us.",
    ],
)
def test_oncoming_in_its_own_lane_or_ahead_the_same_way_is_no_wrong_way(text):
    assert "wrong_way" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "A jogger waits at the kerb on the left and does not cross.",
        "A woman stands on the pavement on our right and never crosses.",
        "An elderly man on the left footway hesitates but doesn't cross in front of us.",
    ],
)
def test_a_walker_who_waits_and_does_not_cross_gives_way(text):
    assert _behaviours(text) == ["give_way"]


@pytest.mark.parametrize(
    "text, names",
    [
        ("A pedestrian waits at the kerb on the right, then crosses in front of us.", ["cross_in_front"]),
        ("A man on the right does not stop and crosses in front of us.", ["cross_in_front"]),
    ],
)
def test_a_walker_who_crosses_after_all_crosses(text, names):
    assert _behaviours(text)[-1:] == names


@pytest.mark.parametrize(
    "text",
    [
        "A van 20 m ahead of us hard-brakes.",
        "The lead car emergency-brakes to a complete stop 20 m ahead.",
        "The bus in front of me panic-brakes for no reason.",
    ],
)
def test_a_manner_and_a_verb_of_braking_in_one_hyphenated_word_read_as_the_phrase(text):
    assert _behaviours(text) == ["sudden_stop"]


@pytest.mark.parametrize(
    "text, names",
    [
        ("A lorry ahead slows to a full stop at the lights.", ["stop"]),
        ("A well-known local cyclist rides along the kerb ahead.", ["along_road"]),
    ],
)
def test_a_hyphenated_word_that_is_no_manner_and_verb_reads_as_before(text, names):
    assert _behaviours(text) == names


@pytest.mark.parametrize(
    "text",
    [
        "On the dual carriageway a coupe in the left lane darts across in front of us to catch the exit.",
        "A hatchback in the inside lane slices over in front of me to make its exit.",
        "Two lanes each way; a pickup in the right lane cuts across ahead of us to reach the exit.",
    ],
)
def test_an_exit_said_as_the_purpose_of_a_move_is_where_it_goes(text):
    (actor,) = read(text).actors
    assert not (actor.relation or "").startswith("junction") and actor.behaviours[0][0] == "cut_in"


def test_an_exit_a_road_user_comes_out_of_is_still_where_it_comes_from():
    (actor,) = read("A car comes out of the exit on the left and pulls into my lane.").actors
    assert actor.relation == "junction_left"


@pytest.mark.parametrize(
    "text",
    [
        "A scooter rider in the cycle lane moves across into the ego's lane 10 m ahead.",
        "A van in the lane next to me drifts over into my lane.",
        "A removal lorry in the left lane changes lanes right in front of us.",
    ],
)
def test_a_move_that_ends_in_the_ego_lane_or_right_in_front_of_it_is_a_cut_in(text):
    assert _behaviours(text) == ["cut_in"]


@pytest.mark.parametrize(
    "text",
    [
        "A lorry in the left lane changes lanes 50 m behind us.",
        "A car ahead of us in the right lane moves into the left lane.",
    ],
)
def test_a_lane_change_elsewhere_stays_a_lane_change(text):
    assert _behaviours(text) == ["change_lane"]


@pytest.mark.parametrize(
    "text",
    [
        "A moped is following behind us at a two-second gap; at the lights it pulls up behind us.",
        "A taxi is following behind me at 30 km/h and then pulls up behind me.",
        "A cyclist is following behind the ego and then comes to a stop behind it.",
    ],
)
def test_following_behind_the_ego_then_stopping_is_both_in_order(text):
    r = read(text)
    follower = next(a for a in r.actors if a.relation == "behind")
    assert [b[0] for b in follower.behaviours] == ["follow_vehicle", "stop"]


def test_behind_the_ego_without_following_is_only_where_it_is():
    (van,) = read("A van waits behind us at the lights and then stops.").actors
    assert "follow_vehicle" not in [b[0] for b in van.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "A van overtakes me and then turns left across my path.",
        "A taxi passed us on the right and swung right across our lane into a side road.",
        "A cyclist undertakes us at the lights then cuts across in front of us to turn right.",
    ],
)
def test_passing_the_ego_to_turn_across_its_path_is_the_turn(text):
    assert _behaviours(text) == ["forced_turn"]


@pytest.mark.parametrize(
    "text, names",
    [
        ("A car overtakes us and cuts back in.", ["overtake"]),
        ("A van overtakes us and then stops at the bus stop ahead.", ["overtake", "stop"]),
    ],
)
def test_an_overtake_with_no_turn_after_it_stays(text, names):
    assert _behaviours(text) == names


@pytest.mark.parametrize(
    "text",
    [
        "The minibus in front of us stopped abruptly outside the school.",
        "A cyclist ahead of me pulled up sharply at the junction.",
        "The hatchback ahead abruptly stopped in the middle of the road.",
        "In front of us the delivery van halted very sudden at the corner.",
    ],
)
def test_a_stop_made_hard_or_abruptly_is_a_sudden_stop(text):
    assert _behaviours(text) == ["sudden_stop"]


@pytest.mark.parametrize(
    "text",
    [
        "The minibus in front of us stopped gently outside the school.",
        "The hatchback ahead stopped at the lights and then pulled away abruptly.",
    ],
)
def test_a_stop_with_no_hard_manner_of_its_own_is_a_stop(text):
    assert _behaviours(text)[0] == "stop"


@pytest.mark.parametrize(
    "text",
    [
        "On the motorway the white car in the lane beside us switched to our lane just ahead.",
        "On the dual carriageway the coach in the right lane is moving to my lane without signalling.",
        "Doing 70 mph, a pickup from the next lane changed to my lane a few metres ahead.",
        "On the motorway a hatchback in the next lane was drifting over to our lane.",
    ],
)
def test_a_move_to_the_ego_lane_is_a_cut_in(text):
    assert _behaviours(text) == ["cut_in"]


@pytest.mark.parametrize(
    "text",
    [
        "On the motorway the white car in the lane beside us switched to the left lane.",
        "On the dual carriageway the coach is moving to the inside lane.",
    ],
)
def test_a_move_to_a_lane_not_the_ego_s_is_a_lane_change(text):
    assert _behaviours(text) == ["change_lane"]


@pytest.mark.parametrize(
    "text",
    [
        "On a narrow lane a tractor came round the corner on my side of the road.",
        "A hatchback came over the crest on our side of the road at speed.",
        "A minibus was coming down the hill in my lane.",
    ],
)
def test_coming_along_on_the_ego_side_of_the_road_is_head_on(text):
    assert _behaviours(text) == ["wrong_way"]


@pytest.mark.parametrize(
    "text, names",
    [
        ("A hatchback came up behind us in our lane.", {"keep_going", "follow_vehicle", "along_road", "keep_lane"}),
        ("A minibus came into my lane from the slip road.", {"cut_in"}),
        ("A hatchback overtook us and then came in our lane.", {"overtake", "cut_in"}),
    ],
)
def test_coming_up_behind_or_into_the_ego_lane_is_not_head_on(text, names):
    assert set(_behaviours(text)) <= names


@pytest.mark.parametrize(
    "text, turn",
    [
        ("At the crossroads the minibus in front of me turned to its right.", "right"),
        ("At the junction a pickup ahead of us turns to the left without indicating.", "left"),
        ("At the lights the hatchback ahead was turning to his left.", "left"),
    ],
)
def test_turning_to_a_side_is_a_turn_that_way(text, turn):
    (actor,) = read(text).actors
    assert [b[0] for b in actor.behaviours] == ["forced_turn"]
    assert actor.behaviours[0][1].get("turn") == turn


@pytest.mark.parametrize(
    "text",
    [
        "At the crossroads the minibus in front of me moved to the left lane.",
        "At the junction the pickup ahead of us pulled over to the left.",
    ],
)
def test_a_lane_or_a_pull_to_a_side_is_no_turn(text):
    assert "forced_turn" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "At the crossroads a minibus coming towards me turned to its left across my path.",
        "At the lights a hatchback coming the other way turned right across our path.",
        "At the junction an oncoming pickup swung right across my way.",
    ],
)
def test_an_oncoming_turn_said_across_the_ego_path_is_the_turn_across(text):
    assert _behaviours(text) == ["turn_across"]


def test_an_oncoming_turn_away_from_the_ego_path_stays_a_turn():
    assert _behaviours("At the lights a hatchback coming the other way turned right into a side street.") != [
        "turn_across"
    ]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist suddenly rode out from between two parked vans just ahead of us.",
        "A lad on an e-scooter came straight out into the street in front of me.",
        "A jogger went out into the road from behind a parked lorry.",
    ],
)
def test_a_walker_or_rider_out_into_the_road_crosses_it(text):
    assert read(text).actors[0].behaviours[0][0] == "cross_in_front"


def test_a_vehicle_out_into_the_road_pulls_out():
    assert _behaviours("A hatchback drove out into the road just ahead of us.") == ["cut_in"]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist rode out in the middle of the road ahead of us.",
        "A cyclist rode out of the village on the road ahead of us.",
    ],
)
def test_riding_out_in_the_road_is_no_crossing(text):
    assert "cross_in_front" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "A jogger stepped off the kerb in front of my car. Braked hard, just missed her.",
        "A courier on a bike cut across in front of my taxi. Slammed on, stopped a metre short.",
        "A lad on a scooter came off the pavement in front of my van. Stopped sharply.",
    ],
)
def test_a_verb_with_no_subject_in_the_narrator_s_story_is_the_narrator_s(text):
    assert "sudden_stop" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "A jogger stepped off the kerb in front of my car and then braked hard.",
        "The bus in front of my car braked hard.",
    ],
)
def test_a_verb_said_of_the_road_user_in_the_narrator_s_story_stays_its_own(text):
    assert "sudden_stop" in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "At the crossroads a cyclist from the left passed in front of us.",
        "A pedestrian passes in front of the ego at the zebra.",
        "At the junction a boy on a scooter passed right in front of my bonnet from the right.",
    ],
)
def test_passing_in_front_of_the_ego_with_no_object_crosses_its_path(text):
    assert read(text).actors[0].behaviours[0][0] != "overtake"


@pytest.mark.parametrize(
    "text",
    [
        "A van passed us and pulled in front of us.",
        "A motorbike passes the ego and cuts in front of it.",
    ],
)
def test_passing_the_ego_then_in_front_stays_an_overtake(text):
    assert _behaviours(text)[0] == "overtake"
