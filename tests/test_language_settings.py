"""The settings as people state them: the time of day, traffic, weather, lanes and road read from the
words that state them, weak words giving way to precise ones and a clock read with the part of the day
said beside it.

Every wording here is written for these tests (none is from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


# --- settings ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("Mid-morning, a cyclist crosses ahead of the ego.", 6, 11),
        ("Late-evening drive; a pedestrian crosses ahead of the ego.", 18, 22),
        ("A van cuts in front of the ego, early-afternoon.", 12, 17),
    ],
    ids=["mid-morning", "late-evening", "early-afternoon"],
)
def test_a_part_of_the_day_with_a_modifier_is_that_part(text, lo, hi):
    assert lo <= int(read(text).time.split(":")[0]) <= hi


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("On my commute, a dark wet morning, a cyclist swerved in front of me.", 6, 11),
        ("Rush hour on a foggy evening; a car ahead brakes hard in front of the ego.", 18, 22),
        ("In daylight, late afternoon, a child runs out in front of the ego.", 12, 17),
    ],
    ids=["commute-morning", "rush-hour-evening", "daylight-afternoon"],
)
def test_a_part_of_the_day_outweighs_a_word_that_only_hints_at_it(text, lo, hi):
    assert lo <= int(read(text).time.split(":")[0]) <= hi


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("17:40, evening, rain: a cyclist crosses ahead of the ego.", 18, 22),
        ("At 05:45 in the morning a van pulls out in front of the ego.", 6, 11),
        ("11:50, afternoon, clear; a pedestrian steps out ahead of the ego.", 12, 17),
    ],
    ids=["evening", "morning", "afternoon"],
)
def test_a_clock_next_to_a_part_of_the_day_is_read_within_that_part(text, lo, hi):
    assert lo <= int(read(text).time.split(":")[0]) <= hi


@pytest.mark.parametrize(
    "text",
    [
        "Dusk, rush-hour traffic, a van ahead brakes suddenly in front of the ego.",
        "A bus pulls out ahead of the ego in the stop-start rush-hour crawl.",
        "Queueing in rush-hour jams, a motorbike filters past the ego and cuts in.",
    ],
    ids=["traffic", "crawl", "jams"],
)
def test_a_hyphenated_setting_phrase_is_read_as_the_phrase(text):
    assert read(text).density == "heavy"


@pytest.mark.parametrize(
    "text",
    [
        "Quiet lane at night, no other vehicle in sight; a fox runs out in front of the ego.",
        "Empty streets, not a single other car around, a cyclist swerves in front of me.",
        "A quiet road with nobody else around; a van pulls out in front of the ego.",
    ],
    ids=["no-other-vehicle", "not-a-single-car", "nobody-else"],
)
def test_saying_there_is_no_other_traffic_is_no_traffic(text):
    assert read(text).density == "none"


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("On a three-lane roundabout a van in the inner lane cuts across in front of the ego.", 3),
        ("A two-lane highway through the hills; an oncoming car drifts into the ego's lane.", 1),
        ("On a two-lane highway an oncoming truck overtakes and comes head-on at the ego.", 1),
    ],
    ids=["roundabout", "highway-oncoming", "highway-head-on"],
)
def test_lanes_of_a_named_road_count_per_direction_as_its_traffic_runs(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text, weather",
    [
        ("Wet tarmac under an overcast sky; a cyclist crosses ahead of the ego.", "cloudy"),
        ("A cloudy day on a wet road, a pedestrian steps out ahead of the ego.", "cloudy"),
        ("Damp surface, sunny, a van cuts in ahead of the ego.", "clear"),
    ],
    ids=["wet-tarmac", "wet-road", "damp-surface"],
)
def test_a_wet_surface_gives_way_to_the_sky_said(text, weather):
    assert read(text).weather == weather


@pytest.mark.parametrize(
    "text",
    [
        "I turned left into a side street and a cyclist came round the corner at me.",
        "The ego turns right into a side road; a pedestrian is crossing it.",
        "Turning into Park Road off the high street, a scooter rider comes out from behind a van.",
    ],
    ids=["side-street", "side-road", "named-road"],
)
def test_turning_into_a_road_makes_a_junction(text):
    assert read(text).map_kind == "crossroad"


def test_nothing_else_happening_says_nothing_of_the_traffic():
    assert read("Light traffic; a van cuts in ahead of the ego, and nothing else happens.").density == "light"


@pytest.mark.parametrize(
    "text",
    [
        "Barely any traffic about; a van pulls out in front of the ego.",
        "Not much traffic on the ring road, and a cyclist swerves in front of the ego.",
        "Only a handful of cars around when a bus pulls out in front of the ego.",
    ],
    ids=["barely-any", "not-much", "handful"],
)
def test_a_small_quantity_of_traffic_is_light_traffic(text):
    assert read(text).density == "light"


@pytest.mark.parametrize(
    "text",
    [
        "Blue skies over the bypass; a van cuts in front of the ego.",
        "The sun was out and a cyclist swerved in front of me.",
        "Warm sunshine, a pedestrian steps out in front of the ego from the left.",
    ],
    ids=["blue-skies", "sun-out", "sunshine"],
)
def test_the_sun_or_a_blue_sky_is_clear_weather(text):
    assert read(text).weather == "clear"


@pytest.mark.parametrize(
    "text, clock",
    [
        ("At 8.15am a van pulls out in front of the ego.", "08:15"),
        ("Around 6.45 pm a cyclist crosses in front of the ego from the left.", "18:45"),
        ("At 11.05 p.m. a pedestrian steps out in front of the ego.", "23:05"),
    ],
    ids=["am", "pm-spaced", "p.m."],
)
def test_a_clock_with_a_dot_and_its_half_of_the_day_is_a_clock(text, clock):
    assert read(text).time == clock


@pytest.mark.parametrize(
    "text, clock",
    [
        ("At 23.10 on the ring road I was doing 50 mph when a van cut in.", "23:10"),
        ("Around 7.30 this morning a cyclist pulled out of a side road in front of me.", "07:30"),
        ("School run yesterday afternoon, approx 3.15, a van drove over the zebra while a girl was crossing.", "15:15"),
        ("Incident at about 17.45 - a scooter rider came off the pavement on my left.", "17:45"),
        ("Dashcam at approximately 21.40, a cyclist with no lights pulled out of a side road on my left.", "21:40"),
    ],
    ids=["night", "morning", "afternoon", "evening", "approximately"],
)
def test_a_clock_with_a_dot_after_a_word_of_time_is_a_clock_and_no_speed(text, clock):
    r = read(text)
    assert r.time == clock
    assert all(a.speed_mps is None for a in r.actors)
    assert r.ego_speed_mps in (None, 50 * 0.44704)


@pytest.mark.parametrize(
    "text",
    [
        "The e-scooter was going at about 4.5 m/s across the road in front of me.",
        "A van cut in about 2.50 m in front of me at 40 km/h.",
    ],
)
def test_a_number_with_a_dot_and_a_unit_is_no_clock(text):
    assert read(text).time is None


@pytest.mark.parametrize(
    "text",
    [
        "In the small hours a fox runs out in front of the ego.",
        "In the early hours of Sunday a van pulls out in front of the ego.",
        "In the wee hours a cyclist swerves in front of the ego.",
    ],
    ids=["small", "early", "wee"],
)
def test_the_small_hours_are_night(text):
    hour = int(read(text).time.split(":")[0])
    assert hour >= 21 or hour <= 5


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("In lane 2 of 3, a van cuts in front of the ego.", 3),
        ("The ego is in lane one of two when a lorry drifts into it.", 2),
        ("Lane 3 of 4: a car from the left lane cuts in front of the ego.", 4),
    ],
    ids=["2-of-3", "one-of-two", "3-of-4"],
)
def test_lane_n_of_m_is_m_lanes(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text, kind",
    [
        ("At a mini-roundabout a van pulls out in front of the ego from the right.", "roundabout"),
        ("At a Y-junction a van pulls out in front of the ego from the left.", "crossroad"),
        ("On a hairpin-bend a van comes towards the ego on the wrong side.", "curve"),
    ],
    ids=["mini-roundabout", "y-junction", "hairpin-bend"],
)
def test_a_hyphenated_road_word_is_read_by_its_head(text, kind):
    assert read(text).map_kind == kind


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("It had been raining since midnight; at dawn a cyclist swerved in front of me.", 5, 7),
        ("I'd been driving since 5 am and in the afternoon a van pulled out in front of me.", 12, 17),
        ("The lights stay off until 6 pm; at night a pedestrian steps out in front of the ego.", 21, 5),
    ],
    ids=["since-midnight", "since-clock", "until-clock"],
)
def test_a_time_after_since_or_until_is_not_the_scenarios(text, lo, hi):
    hour = int(read(text).time.split(":")[0])
    assert (lo <= hour <= hi) if lo <= hi else (hour >= lo or hour <= hi)


@pytest.mark.parametrize(
    "text, weather",
    [
        ("No rain today, clear skies; a van pulls out in front of the ego.", "clear"),
        ("It wasn't foggy, just overcast, when a cyclist swerved in front of me.", "cloudy"),
        ("There was not any snow, it was sunny; a pedestrian steps out in front of the ego.", "clear"),
    ],
    ids=["no-rain", "was-not-foggy", "not-any-snow"],
)
def test_a_negated_weather_word_is_not_the_weather(text, weather):
    assert read(text).weather == weather


@pytest.mark.parametrize(
    "text",
    [
        "It was not dark yet; a cyclist swerved in front of me.",
        "Not night-time, a van pulls out in front of the ego.",
        "It wasn't dusk yet when a pedestrian stepped out in front of me.",
    ],
    ids=["not-dark", "not-night", "was-not-dusk"],
)
def test_a_negated_time_word_is_not_the_time(text):
    assert read(text).time is None


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("Lanes: 3. A van cuts in front of the ego.", 3),
        ("road: urban | lanes: 2/dir | a cyclist swerves in front of the ego", 2),
        ("Setting - lanes = two; a lorry drifts into the ego's lane.", 2),
    ],
    ids=["colon", "per-dir", "equals-word"],
)
def test_a_lanes_field_is_lanes_per_direction(text, lanes):
    assert read(text).lanes == lanes


# --- settings said in passing ------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, weather",
    [
        ("Evening, thick fog - cyclist ahead brakes hard.", "fog"),
        ("Half eight, sleet \u2013 taxi pulls out from the kerb on the left.", "snow"),
        ("Drizzle \u2014 moped ahead of me slows down.", "rain"),
    ],
    ids=["hyphen", "en-dash", "em-dash"],
)
def test_a_setting_before_a_spaced_dash_is_not_a_road_users_kind(text, weather):
    assert read(text).weather == weather


def test_a_time_before_a_spaced_dash_is_the_time():
    assert read("Snowy night \u2014 minibus ahead brakes hard.").time == "23:00"


@pytest.mark.parametrize(
    "text, weather",
    [
        ("grey van ahead brakes hard | clear, morning", "clear"),
        ("Ego 50 km/h, grey saloon cuts in from the left, clear skies", "clear"),
        ("gray pickup turns across the ego at the junction, dry and sunny", "clear"),
        ("Grey, drizzly morning. A van brakes hard ahead.", "rain"),
        ("Grey sky, a van brakes hard ahead.", "cloudy"),
    ],
    ids=["bar-line", "after-comma", "gray", "grey-day", "grey-sky"],
)
def test_a_colour_right_before_a_road_user_is_its_colour_not_the_sky(text, weather):
    assert read(text).weather == weather


@pytest.mark.parametrize(
    "text",
    [
        "Taking a tight left-hander at 40 km/h when a motorbike comes the other way on my side.",
        "A van stopped just past a right-hander, I brake hard.",
        "Halfway round a sharp right hander a cyclist is in the middle of my lane.",
    ],
    ids=["left-hander", "right-hander", "spaced"],
)
def test_a_left_or_right_hander_is_a_bend(text):
    assert read(text).map_kind == "curve"


@pytest.mark.parametrize(
    "text, kind",
    [
        ("A taxi ahead suddenly makes a left onto Elm Avenue and I have to brake.", "crossroad"),
        ("The bus in front takes a right into 3rd Street.", "crossroad"),
        ("A cyclist in front of me hangs a left onto the main road.", "crossroad"),
        ("A car in front of me moves onto the hard shoulder and stops.", None),
    ],
    ids=["make-a-left-onto", "take-a-right-into", "onto-the-main-road", "hard-shoulder"],
)
def test_a_turn_onto_a_road_is_at_a_junction(text, kind):
    assert read(text).map_kind == kind


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("I'm in lane 3 when a car ahead brakes hard.", 3),
        ("A van in lane two drifts into my lane.", 2),
        ("Ego in the middle lane, a car on the left cuts in.", 3),
        ("Lane 2 of 4, a lorry changes lane in front of me.", 4),
    ],
    ids=["lane-3", "lane-two", "middle-lane", "lane-of"],
)
def test_a_numbered_or_middle_lane_needs_that_many_lanes(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text, weather",
    [
        ("Light rain ended about 10 minutes before the run, sky overcast. A van brakes ahead of me.", "cloudy"),
        ("It had stopped raining by then; a cyclist swerves in front of me.", None),
        ("The fog had lifted, bright sunshine now; a bus pulls out on the left.", "clear"),
        ("Rain. A van brakes ahead of me and stopped.", "rain"),
    ],
    ids=["rain-ended", "stopped-raining", "fog-lifted", "the-van-stopped"],
)
def test_a_weather_said_to_have_ended_is_not_the_weather(text, weather):
    assert read(text).weather == weather


@pytest.mark.parametrize(
    "text, density",
    [
        ("Sunny afternoon, traffic moderate. A car cuts in front of me.", "moderate"),
        ("Traffic heavy, dusk. A car cuts in front of me.", "heavy"),
        ("Weather: dry. Traffic: light. A van pulls out ahead.", "light"),
        ("A car runs the traffic light in front of me.", None),
    ],
    ids=["traffic-moderate", "traffic-heavy", "traffic-colon", "traffic-light-signal"],
)
def test_traffic_noted_with_its_value_after_it(text, density):
    assert read(text).density == density


@pytest.mark.parametrize(
    "text, clock",
    [
        ("Outside the school at 3:15, a child runs out in front of me.", "15:15"),
        ("At 5:40 a van pulled out of a side road on my left.", "17:40"),
        ("At 5:30 in the morning a van pulled out on me.", "06:00"),
        ("At 03:15 a van pulled out on me.", "03:15"),
        ("At 2:30 at night a van pulled out on me.", "02:30"),
        ("At 9:40 a van pulled out on me.", "09:40"),
    ],
    ids=["school-3-15", "5-40", "morning-said", "two-digit-hour", "night-said", "morning-hour"],
)
def test_a_twelve_hour_clock_of_the_first_hours_is_the_afternoons(text, clock):
    assert read(text).time == clock


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("On the two-lane approach to the roundabout, a van in the left lane cuts across me.", 2),
        ("Coming down a two-lane slip road, a lorry on my right moves over.", 2),
        ("A two-lane road through a village, a tractor comes the other way.", 1),
    ],
    ids=["approach", "slip-road", "village-road"],
)
def test_a_two_lane_approach_or_slip_road_counts_one_direction(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text, weather",
    [
        ("It was teeming down when a taxi pulled out of a side road on my left.", "heavy_rain"),
        ("The heavens opened just as a cyclist swerved in front of me.", "heavy_rain"),
        ("Rain coming down in sheets, a bus brakes hard ahead of me.", "heavy_rain"),
        ("It was only spitting when a van cut in front of me.", "rain"),
        ("A proper pea-souper, a lorry ahead brakes suddenly.", "fog"),
        ("Frosty morning; a moped skids out of a junction on the right.", "snow"),
    ],
    ids=["teeming-down", "heavens-opened", "in-sheets", "spitting", "pea-souper", "frosty"],
)
def test_weather_said_in_idioms(text, weather):
    assert read(text).weather == weather


# --- density said in its own sentence, as a quantity, or negated with a modifier ------------------------------
@pytest.mark.parametrize(
    "text, density",
    [
        ("A lorry pulls out ahead of me. Traffic volumes were moderate.", "moderate"),
        ("The traffic levels are heavy around here. A van cuts in front of me.", "heavy"),
        ("Tons of traffic on the ring road when a taxi swerved in front of me.", "heavy"),
        ("Heaps of cars about, and a cyclist darts out ahead of me.", "heavy"),
        ("A van cuts in front of the ego, no background traffic at all.", "none"),
        ("No through traffic that morning; a jogger steps off the kerb ahead of me.", "none"),
        ("Traffic was sparse. A van braked ahead of me and a car behind hit it. No other vehicles were involved.",
         "light"),
        ("There was no traffic light at the corner where a cyclist swerved ahead of me.", None),
    ],
    ids=["volumes-were", "levels-are", "tons-of", "heaps-of-cars", "no-background", "no-through",
         "others-involved", "no-traffic-light"],
)  # fmt: skip
def test_traffic_said_as_a_quantity_or_of_its_volume(text, density):
    assert read(text).density == density


def test_other_road_users_not_involved_says_nothing_of_the_traffic():
    text = "A van braked ahead of me and I ran into it. No other road users were involved."
    assert read(text).density is None


# --- a weather said of before, and since cleared -------------------------------------------------------------
@pytest.mark.parametrize(
    "text, weather",
    [
        ("It had been misty first thing but it has lifted now; a van pulls out ahead of me.", None),
        ("Drizzly earlier, though that had stopped by the time a cyclist swerved in front of me.", None),
        ("There was snow earlier but it has all cleared, bright sunshine; a van cuts in front of me.", "clear"),
        ("It was foggy and it was getting worse when a van cut in front of me.", "fog"),
        ("Rain earlier and it was still raining when a van cut in front of me.", "rain"),
    ],
    ids=["misty-lifted", "drizzly-stopped", "snow-cleared-sun", "fog-worse", "still-raining"],
)
def test_a_weather_of_earlier_since_cleared_is_not_the_weather(text, weather):
    assert read(text).weather == weather


# --- a clock said in words -------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, clock",
    [
        ("At quarter to nine a van cut in front of me.", "08:45"),
        ("About twenty past seven in the evening a van cut in front of me.", "19:20"),
        ("Around half past ten at night a cyclist swerved ahead of me.", "22:30"),
        ("At half nine a cyclist swerved ahead of me on the way to work, morning rush.", "09:30"),
        ("A quarter past eleven a van cut in front of me.", "11:15"),
    ],
    ids=["quarter-to-nine", "twenty-past-seven-evening", "half-past-ten-night", "half-nine", "quarter-past-eleven"],
)
def test_a_clock_in_words_is_that_clock(text, clock):
    assert read(text).time == clock


def test_half_a_quantity_is_no_clock():
    text = "Half a second later a van cut in front of me at half past the junction."
    assert read(text).time is None


# --- a pedestrian crossing is not a junction --------------------------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("On a straight avenue with a zebra crossing, a jogger steps out ahead of the ego.", "straight"),
        ("A woman waits at the pelican crossing as the ego drives up the high street.", "straight"),
        ("Mid-block crosswalk on a long road; a child runs across in front of me.", "straight"),
        ("At the crossroads a pedestrian on the zebra crossing steps out in front of me.", "crossroad"),
        ("Turning right at the lights, a man on the crosswalk steps out in front of me.", "crossroad"),
    ],
    ids=["zebra", "pelican", "crosswalk", "crossroads-zebra", "turning-at-lights"],
)
def test_a_pedestrian_crossing_alone_is_no_junction(text, kind):
    assert read(text).map_kind == kind


@pytest.mark.parametrize(
    "text, kind",
    [
        ("A jogger ran out at the crossing on the hairpin and I braked.", "curve"),
        ("On the bend by the school a child dashed over the crossing; I stopped short.", "curve"),
        ("Round the bend near the crossing a van overtook me and cut in.", "curve"),
        ("A kid ran across at the crossing by the school and I braked hard.", "crossroad"),
        ("At the crossing on the corner a jogger stepped out in front of me.", "crossroad"),
    ],
    ids=["hairpin", "bend-child", "bend-van", "no-bend", "corner-not-a-bend"],
)
def test_a_crossing_on_a_bend_is_that_bend(text, kind):
    assert read(text).map_kind == kind


@pytest.mark.parametrize(
    "text, kind",
    [
        ("Coming round the bend at dusk I met a cyclist with no lights riding along the edge.", "curve"),
        ("On a twisty lane a jogger without lights stepped out; get some lights, people.", "curve"),
        ("The moped on the bend had its lights off and wobbled out in front of me.", "curve"),
        ("Past the bend, at the lights, a van pulled out in front of me.", "crossroad"),
    ],
    ids=["no-lights", "without-some", "its-lights", "ran-the-lights"],
)
def test_a_road_users_lights_are_no_signals(text, kind):
    assert read(text).map_kind == kind


# --- a turn said without "turn into" ---------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "The ego makes an unprotected right on a green arrow while a cyclist comes the other way.",
        "A bus takes the left onto 5th as I come up beside it.",
        "A jogger crosses the road we are turning into.",
        "A child runs across the side street the ego is turning into.",
    ],
    ids=["unprotected-right", "left-onto-5th", "road-we-turn-into", "side-street-turning-into"],
)
def test_a_turn_said_in_other_words_is_at_a_junction(text):
    assert read(text).map_kind == "crossroad"


@pytest.mark.parametrize(
    "text",
    [
        "The ego keeps left onto the hard shoulder as a van cuts in.",
        "A van turning into a shop car park ahead slows, on a straight road.",
    ],
    ids=["keeps-left-onto-shoulder", "into-car-park"],
)
def test_a_move_onto_a_shoulder_or_a_car_park_is_no_junction(text):
    assert read(text).map_kind != "crossroad"


# --- lanes a direction, said in other words --------------------------------------------------------------
@pytest.mark.parametrize(
    "text, lanes",
    [
        ("On a one-lane-each-way country road, a tractor comes the other way.", 1),
        ("A dual carriageway, two lanes each way; a van in the left lane brakes.", 2),
        ("A one-way street with three lanes; a cab in the right lane cuts in front of me.", 3),
        ("4 lanes per direction on the ring road, a coach moves into my lane.", 4),
        ("A two-lanes-per-direction highway; a car on my left cuts in.", 2),
    ],
    ids=["one-lane-each-way", "two-lanes-each-way", "one-way-three-lanes", "4-per-direction", "hyphen-per-direction"],
)
def test_lanes_said_per_direction(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text, weather",
    [
        ("Heavy fog, but the van stopped ahead of me in time.", "fog"),
        ("It was raining, but it stopped in time: a cyclist swerved in front of me.", "rain"),
    ],
    ids=["van-stopped", "it-stopped-in-time"],
)
def test_a_road_user_stopping_after_a_contrast_leaves_the_weather(text, weather):
    assert read(text).weather == weather


# "the crossing" after a pedestrian crossing is named is that crossing (a known mention), not a junction
@pytest.mark.parametrize(
    "text, kind",
    [
        ("A long straight road with a pelican crossing. A man waits at the crossing and lets the ego go by.", None),
        ("There is a puffin crossing outside the shop; a woman stands at the crossing and lets me pass.", None),
        ("On the high street's zebra, a boy waits at the crossing and lets the ego go past.", None),
        ("A van waits at the crossing and lets the ego go past.", "crossroad"),
    ],
    ids=["pelican", "puffin", "zebra-alone", "no-crossing-named"],
)
def test_the_crossing_after_a_pedestrian_crossing_is_that_crossing(text, kind):
    assert read(text).map_kind in ((kind, "straight") if kind is None else (kind,))


@pytest.mark.parametrize(
    "text, density",
    [
        ("In heavy commuter traffic a moped cuts in front of the ego.", "heavy"),
        ("Light weekend traffic; a cyclist crosses ahead of the ego.", "light"),
        ("Moderate bg traffic, the van ahead brakes hard.", "moderate"),
        ("Zero background traffic. A jogger crosses in front of the ego.", "none"),
        ("The ego crawls along in slow holiday traffic when a scooter cuts in.", "heavy"),
        ("In light rain traffic lights ahead turn red and a cyclist crosses.", None),  # (rain; a signal)
    ],
)
def test_a_degree_of_traffic_with_words_of_which_traffic_between(text, density):
    assert read(text).density == density


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("Around seven o'clock tonight a moped cut in front of the ego.", 18, 20),
        ("At 8 o'clock in the morning a cyclist crosses ahead of the ego.", 8, 8),
        ("Sunday arvo, a jogger steps out in front of the ego.", 12, 17),
        ("At nine o'clock a bus pulls out in front of the ego, late evening.", 21, 21),
    ],
)
def test_a_whole_hour_and_the_colloquial_parts_of_the_day(text, lo, hi):
    hour = int(read(text).time.split(":")[0])
    assert lo <= hour <= hi


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("At daybreak a cyclist was riding ahead of me on the lane.", 5, 7),
        ("Just after sun-up a van cut in front of us.", 5, 7),
        ("In the forenoon a bus pulled out ahead of the ego.", 6, 11),
        ("A van cut in at lunch time on the ring road.", 11, 13),
        ("Outside the primary at home time, a kid ran out between the cars.", 12, 17),
        ("Straight after school a lad on a bike came off the pavement in front of me.", 12, 17),
        ("In the half-light a jogger stepped out in front of the ego.", 18, 21),
    ],
)
def test_the_everyday_names_of_the_parts_of_the_day(text, lo, hi):
    hour = int(read(text).time.split(":")[0])
    assert lo <= hour <= hi


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("Eastbound on the bypass, 3 lanes, at 80 km/h. A coach shifted one lane to the left, next to us.", 3),
        ("We were on a road with 4 lanes our way. A taxi on our right drifted over two lanes and stopped.", 4),
        ("Northbound, 3 lanes in our direction. A lorry moved across one lane into the lane beside ours.", 3),
        ("Two lanes each way. A van on my right changed one lane over, right in front of me.", 2),
    ],
    ids=["shifted-one-lane", "drifted-over-two", "moved-across-one", "changed-one-lane-over"],
)
def test_the_lanes_a_road_user_moves_across_are_not_the_roads_lanes(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("The street narrows to one lane and a van comes towards the ego.", 1),  # (the road's own lanes)
        ("On a road with 3 lanes a van cuts in front of the ego.", 3),
    ],
    ids=["narrows-to-one", "road-with-three"],
)
def test_lanes_that_no_one_moves_across_are_the_roads_lanes(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("On a rural road with one traffic lane each way, a cyclist rides ahead of the ego.", 1),
        ("The ego drives on an arterial, two running lanes per direction, when a van cuts in.", 2),
        ("Three narrow lanes in each direction; a car from the left lane cuts in front of the ego.", 3),
    ],
    ids=["traffic-lane", "running-lanes", "narrow-lanes"],
)
def test_a_word_between_the_count_and_lane_keeps_the_count_per_direction(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text",
    [
        "The road has one cycle lane each side and a van cuts in front of the ego.",
        "Two bus lanes each way, and a cyclist rides ahead of the ego.",
    ],
    ids=["cycle-lane", "bus-lanes"],
)
def test_lanes_beside_the_carriageway_are_not_its_traffic_lanes(text):
    assert read(text).lanes is None


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came the wrong way down the one-way street towards me.",
        "On a one way road in town an e-scooter rides towards the ego against the flow.",
        "Going along a one-way section of the high street, a jogger steps out ahead of the ego.",
    ],
    ids=["one-way-street", "one-way-road", "one-way-section"],
)
def test_a_one_way_street_with_no_lanes_counted_has_one_lane(text):
    assert read(text).lanes == 1


@pytest.mark.parametrize(
    "text, lanes",
    [
        ("A one-way street with three lanes; a taxi cuts in front of the ego.", 3),
        ("A cyclist rides one way and the ego drives the other on a road with two lanes.", 2),
    ],
    ids=["counted", "one-way-as-direction"],
)
def test_a_one_way_street_with_its_lanes_counted_or_one_way_as_a_direction(text, lanes):
    assert read(text).lanes == lanes


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("Report filed 17:45. At about 9 in the morning a cyclist pulled out in front of the ego.", 6, 11),
        ("Logged at 23:10 by the desk: this afternoon a van cut in front of the ego.", 12, 17),
        ("Ticket opened 08:02. The caller says a jogger stepped out in front of her car late at night.", 21, 29),
        ("Statement written at 16:30. It was dawn when a deer ran out in front of the ego.", 5, 7),
    ],
    ids=["filed", "logged-at", "ticket-opened", "written-at"],
)
def test_the_time_a_record_was_made_is_not_the_events(text, lo, hi):
    hour = int(read(text).time.split(":")[0])
    assert lo <= hour <= hi or lo <= hour + 24 <= hi


@pytest.mark.parametrize(
    "text, clock",
    [
        ("Time: 08:05. A cyclist swerved in front of the ego.", "08:05"),
        ("At 22:40 a van cut in front of the ego; the report was written the next day.", "22:40"),
    ],
    ids=["time-field", "event-clock"],
)
def test_the_events_own_clock_stays(text, clock):
    assert read(text).time == clock


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("Weds AM, light rain. A cyclist crosses in front of the ego.", 6, 11),
        ("Friday pm: a van pulls out of a side road in front of the ego.", 12, 17),
        ("Sat am, dry. The ego passes a jogger on the verge.", 6, 11),
        ("Coming home this aft a moped cut in front of me.", 12, 17),
    ],
    ids=["weds-am", "friday-pm", "sat-am", "this-aft"],
)
def test_a_day_with_its_half_said_is_that_half_of_the_day(text, lo, hi):
    hour = int(read(text).time.split(":")[0])
    assert lo <= hour <= hi


@pytest.mark.parametrize(
    "text",
    [
        "On Monday I am driving at 30 mph when a cyclist crosses in front of me.",
        "Today I am at the wheel and a van pulls out in front of me.",
    ],
    ids=["monday-i-am", "today-i-am"],
)
def test_am_as_a_verb_after_a_day_is_no_time(text):
    assert read(text).time is None


@pytest.mark.parametrize(
    "text",
    [
        "A van turning left from Mill Road into Church Street cut across a cyclist going straight on.",
        "I was turning right out of the supermarket car park onto the main road when a moped came from the left.",
        "The ego is turning left off Harbour Way into Quay Street as a jogger starts across.",
    ],
    ids=["from-road-into-road", "out-of-car-park-onto-main-road", "off-way-into-street"],
)
def test_a_turn_from_one_road_into_another_is_at_a_junction(text):
    assert read(text).map_kind == "crossroad"


@pytest.mark.parametrize(
    "text",
    [
        "I waited on the corner, then pulled away turning left, and a cyclist came up on my inside.",
        "At the corner we turned right and a pedestrian was crossing the road we turned into.",
    ],
    ids=["pulled-away-turning-left", "at-the-corner-turned-right"],
)
def test_the_ego_turning_at_a_corner_turns_at_a_junction(text):
    assert read(text).map_kind == "crossroad"


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came round the corner towards me on my side of the road.",
        "On the bend by the corner shop a van came towards the ego on the wrong side.",
    ],
    ids=["round-the-corner", "bend-by-the-corner-shop"],
)
def test_a_corner_no_one_turns_at_stays_a_bend(text):
    assert read(text).map_kind == "curve"


@pytest.mark.parametrize(
    "text",
    [
        "On a country road with lots of turns a tractor crawls ahead of the ego.",
        "The lane is full of twists and a van comes towards the ego on its side.",
        "Driving a road with many turns at night, the ego meets a cyclist without lights.",
    ],
    ids=["lots-of-turns", "full-of-twists", "many-turns"],
)
def test_a_road_of_many_turns_is_a_bend(text):
    assert read(text).map_kind == "curve"


@pytest.mark.parametrize(
    "text",
    [
        "Many turns later, on a straight road, a van cuts in front of the ego.",
        "The cyclist takes turns with his friend riding ahead of the ego on a straight road.",
    ],
    ids=["many-turns-later", "takes-turns"],
)
def test_turns_that_are_not_the_roads_keep_it_straight(text):
    assert read(text).map_kind == "straight"


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("saw it on my dashcam last night moped rider ran the red in front of me", 21, 23),
        ("this morning van pulled out of a side road in front of me", 6, 11),
        ("Friday evening lorry cut across my lane at the lights.", 18, 22),
    ],
)
def test_a_part_of_the_day_after_last_or_this_is_when(text, lo, hi):
    hour = int(read(text).time.split(":")[0])
    assert lo <= hour <= hi


def test_a_part_of_the_day_before_a_noun_still_modifies_it():
    assert read("I took the night bus home and a cyclist cut in front of it.").time is None


@pytest.mark.parametrize("text", ["Tonight a cyclist with no lamps swerved out in front of me.",
                                  "Out delivering tonight, a moped cut across my lane."])  # fmt: skip
def test_tonight_is_an_hour_of_both_evening_and_night(text):
    hour = int(read(text).time.split(":")[0])
    assert 21 <= hour <= 22


@pytest.mark.parametrize(
    "text, weather",
    [
        ("On misty winter evenings joggers step out from behind parked vans; I braked for one.", "fog"),
        ("A winter morning, and a cyclist wobbled out in front of me.", "snow"),
        ("Road still wet after rain, grey sky; a moped cut in front of the ego.", "cloudy"),
        ("Greasy surface since the snow, sky bright; a van pulled out on me.", "clear"),
        ("In the wet a van pulled out in front of me; not my finest hour.", "rain"),
        ("It was the clearest of mornings and a van pulled out in front of me.", None),
    ],
    ids=["season-fog", "season-alone", "after-rain", "since-snow", "finest", "clearest"],
)
def test_a_season_a_past_weather_and_a_superlative_give_way(text, weather):
    assert read(text).weather == weather


@pytest.mark.parametrize(
    "text, density",
    [
        ("Traffic was too much today, and a moped cut in front of me.", "heavy"),
        ("The traffic was horrendous; a van pulled out of a side road on me.", "heavy"),
        ("In the sim the traffic's set to heavy and a cyclist swerves out ahead of the ego.", "heavy"),
        ("The road was bad with potholes and a van pulled out in front of me.", None),
        ("The traffic was light and a moped cut in front of me.", "light"),
    ],
    ids=["too-much", "horrendous", "set-to-heavy", "bad-road", "light"],
)
def test_traffic_said_to_be_bad_is_heavy(text, density):
    assert read(text).density == density


@pytest.mark.parametrize(
    "text, kind",
    [
        ("RBT, ego enters and takes the 2nd exit; a scooter is circulating ahead.", "roundabout"),
        ("At the mini-rbt a van cut across me.", "roundabout"),
        ("Coming round the gyratory a taxi cut across my bonnet.", "roundabout"),
        ("At the roundy by the shops a van cut across me.", "roundabout"),
        ("On the dogleg past the farm a van came at me on my side.", "curve"),
        ("Through the chicane a car cut in front of me.", "curve"),
        ("At the all-way stop a pickup pulled out on me.", "crossroad"),
        ("At the chowk a motorbike came across in front of us.", "crossroad"),
        ("At the robots a taxi pulled out in front of me.", "crossroad"),
        ("A delivery robot crossed in front of me on the high street.", "straight"),
        ("Ego is a BRT bus in the BRT lane at 50 km/h; a car comes at it head-on.", "straight"),
        ("An RBT unit was parked on the verge and a ute cut in front of me.", "straight"),
    ],
)
def test_the_worlds_words_for_a_roundabout_a_junction_and_a_bend(text, kind):
    assert (read(text).map_kind or "straight") == kind


@pytest.mark.parametrize(
    "text, weather",
    [
        ("In the smog a van cut in front of me.", "fog"),
        ("Thick murk on the moor, a tractor pulled out ahead.", "fog"),
        ("It was raining cats and dogs and a bus pulled out.", "heavy_rain"),
        ("In a thunderstorm a van cut in ahead of the ego.", "heavy_rain"),
        ("Monsoon evening, a bike cut across in front of our car.", "heavy_rain"),
        ("Blue skies, a van cut in front of us.", "clear"),
        ("It was a scorcher and a cyclist rode out ahead of me.", "clear"),
    ],
)
def test_the_worlds_words_for_the_weather(text, weather):
    assert read(text).weather == weather


@pytest.mark.parametrize(
    "text, density",
    [
        ("Nose to tail on the ring road, a van cut in front of me.", "heavy"),
        ("The high street was chock-a-block and a moped cut in.", "heavy"),
        ("Gridlock on the bypass, a motorbike filtered past me.", "heavy"),
        ("Sat in a tailback when a bike came up my inside.", "heavy"),
        ("The traffic was stop-start and a scooter filtered past me.", "heavy"),
        ("Steady traffic on the bypass, a van cut in ahead of me.", "moderate"),
        ("Not a soul about, and a van pulled out of a farm gate.", "none"),
        ("The van ahead came to a standstill and I stopped behind it.", None),
    ],
)
def test_the_worlds_words_for_the_traffic(text, density):
    assert read(text).density == density


# "I am" is a verb, not the morning: a clock in words keeps the half of the day the part of the day says
@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("Last night 11 o'clock, I am on my way home and a biker comes at me on my side.", 21, 23),
        ("Friday night around ten o'clock I am driving home when a cyclist swerves out.", 21, 23),
        ("Yesterday evening at eight o'clock I am waiting at the lights and a taxi cuts in.", 18, 21),
        ("At 7 o'clock in the morning I am on the bypass and a van cuts in.", 6, 8),
        ("At nine o'clock am I was on the ring road and a van cut in front of me.", 8, 10),
    ],
    ids=["night-eleven", "night-ten", "evening-eight", "morning-said", "am-said"],
)
def test_i_am_is_not_the_morning(text, lo, hi):
    assert lo <= int(read(text).time.split(":")[0]) <= hi


# a statement asked back for confirmation ("It was dark, correct?", "You were doing 30, right?") states
# the scene as any statement does; a real question to the reader does not
@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("It was raining that evening, correct? A van pulled out on me.", 18, 21),
        ("It was dark by then, right? A van pulled out on me.", 21, 23),
        ("This was in the morning, yeah? A van pulled out on me.", 6, 11),
        ("You were driving home that night, weren't you? A van pulled out on you.", 21, 23),
        ("That was late in the afternoon, is that right? A van pulled out on me.", 12, 17),
    ],
    ids=["correct", "right", "yeah", "werent-you", "is-that-right"],
)
def test_a_tag_question_states_the_scene(text, lo, hi):
    assert lo <= int(read(text).time.split(":")[0]) <= hi


@pytest.mark.parametrize(
    "text",
    [
        "A van pulled out on me. Was it dark at the time, though?",
        "A van pulled out on me. Does this happen at night a lot, anyone?",
        "A van pulled out on me. Would it be worse at night, do you think?",
    ],
    ids=["was-it", "does-this", "would-it"],
)
def test_a_question_to_the_reader_still_states_no_setting(text):
    assert read(text).time is None


# a part of the day written as a name, before a street's word or joined to another street ("Sunset
# Boulevard", "at Sunset & 3rd", "Midnight Lane"), is where, not when
@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("A van cut across me on Sunset Boulevard this afternoon.", 12, 17),
        ("Heading along Sunset Blvd at noon, a cyclist swerved into my lane.", 11, 13),
        ("At Sunset & 3rd this morning a taxi ran the red in front of me.", 6, 11),
        ("Coming down Evening Road at lunchtime, a kid ran out in front of me.", 11, 14),
        ("Turning from Dawn Avenue onto Morning Street at 3 pm, a bus pulled out on me.", 14, 16),
    ],
    ids=["sunset-boulevard", "sunset-blvd", "sunset-and", "evening-road", "dawn-avenue"],
)
def test_a_part_of_the_day_in_a_streets_name_is_no_time(text, lo, hi):
    assert lo <= int(read(text).time.split(":")[0]) <= hi


@pytest.mark.parametrize(
    "text, lo, hi",
    [
        ("Cycling home at sunset, a van cut in front of me.", 18, 21),
        ("On a wet Friday Evening a van cut in front of me.", 18, 22),
        ("Late at night on the High Street, a van cut in front of me.", 21, 23),
    ],
    ids=["at-sunset", "friday-evening", "night-high-street"],
)
def test_a_part_of_the_day_not_in_a_name_is_still_the_time(text, lo, hi):
    assert lo <= int(read(text).time.split(":")[0]) <= hi


# where two named streets meet ("the corner of Main and Elm", "cnr King St & Queen Rd"), or someone comes
# out of a side road, the road has a junction there, whatever "corner" alone would say
@pytest.mark.parametrize(
    "text",
    [
        "A taxi smashed into my car at the corner of Main and 11th.",
        "On the corner of King Street and Albert Road a van cut across me.",
        "Crash cnr Beach Rd & Marine Pde, a ute hit a cyclist.",
        "At the corner of Elm/Oak a cab pulled out in front of me.",
        "Near the Jalan Ampang corner with Jalan Tun Razak, a car pulled out in front of me.",
        "I was pulling out of a side road at walking pace when a scooter came round the corner into my bumper.",
        "Coming out of a side street, I met a cyclist who came round the corner fast.",
    ],
    ids=["corner-of-and-ordinal", "corner-of-streets", "cnr-amp", "corner-slash", "corner-with", "out-of-side-road",
         "out-of-side-street"],
)  # fmt: skip
def test_where_streets_meet_is_a_junction(text):
    assert read(text).map_kind == "crossroad"


@pytest.mark.parametrize(
    "text, kind",
    [
        ("I came round the corner of the building and a cyclist was right there.", "curve"),
        ("Round the corner and up the hill, a cyclist swerved out in front of me.", "curve"),
    ],
    ids=["corner-of-building", "round-the-corner"],
)
def test_a_corner_of_no_streets_stays_a_bend(text, kind):
    assert read(text).map_kind == kind


# a traffic signal said by its colour ("the light was green for me", "signal became green", "the robot
# turned red") stands at a junction
@pytest.mark.parametrize(
    "text",
    [
        "The light was green for me and a kid on a scooter went across in front of me.",
        "Signal became green, I started, and a man crossed from the right in front of me.",
        "The robot turned red just as a minibus came through in front of me.",
        "Lights went green, I pulled off, and a cyclist cut across my front.",
        "At the Silk Board signal a biker crossed in front of me.",
    ],
    ids=["light-was-green", "signal-became", "robot-turned", "lights-went", "at-named-signal"],
)
def test_a_signal_by_its_colour_stands_at_a_junction(text):
    assert read(text).map_kind == "crossroad"


@pytest.mark.parametrize(
    "text",
    [
        "The pedestrian light was green and a man crossed at the zebra crossing in front of me.",
        "Traffic was light and a man crossed in front of me.",
        "A cyclist in a green jacket crossed in front of me; the light was fading.",
    ],
    ids=["pedestrian-light", "traffic-light", "light-fading"],
)
def test_other_lights_are_no_junction(text):
    assert read(text).map_kind != "crossroad"


# --- a clock as much of Europe writes it ("8h", "18h30", "17u05", "Time: 13.15"): a time, never a speed -----
@pytest.mark.parametrize(
    "text, hour, kph",
    [
        ("I drove at about 25 km/h, my light was green, a scooter turned across me. It was raining, around 8h.", 8, 25),
        ("At 18h30 a cyclist came out of a side road on my right, I was doing 30 km/h.", 18, 30),
        ("Towards 7h15 a pedestrian stepped off the kerb in front of me; I was going at 40 km/h.", 7, 40),
        ("A van cut in front of me at 22h, I was at 50 km/h on the ring road.", 22, 50),
        ("Sunday, at about 9h, a cyclist swerved in front of me.", 9, None),
        ("constat 12/12/2023 14h, place Meiser. A cyclist swerved in front of me at the roundabout.", 14, None),
        ("Date: 23/01/2024, 17u05. An e-step crossed in front of me, I was at 30 km/h.", 17, 30),
        ("Date: 10/10/2023 Time: 13.15\nA van braked hard in front of me.", 13, None),
        ("Datum 21.09.2023 time 14.10, a pedestrian stepped out in front of me.", 14, None),
        ("A car ran the red and hit me. Time: 10.01.2024, 7:20, it was still dark.", 7, None),
    ],
    ids=[
        "around-8h",
        "18h30",
        "towards-7h15",
        "at-22h",
        "about-9h",
        "after-a-date",
        "17u05",
        "time-13.15",
        "time-14.10",
        "a-date-after-time",
    ],
)
def test_a_clock_written_with_h_is_the_time_not_a_speed(text, hour, kph):
    r = read(text)
    assert int(r.time.split(":")[0]) == hour
    if kph is not None:
        assert r.ego_speed_mps * 3.6 == pytest.approx(kph, abs=0.05)


@pytest.mark.parametrize(
    "text",
    [
        "After a 3h drive I was doing 50 km/h when a cyclist swerved in front of me.",
        "On a 2h trip to the coast a van cut in front of me at 60 km/h.",
        "Travel time: 2h. A van cut in front of me.",
        "On 12/12/2023, 3h after I left home, a van cut in front of me.",
        "Lap time 1.45, then a car spun in front of me.",
        "My reaction time: 1.50, a van cut in front of me.",
        "Total time: 12.30 minutes; a van cut in front of me.",
    ],
    ids=["3h-drive", "2h-trip", "travel-time", "3h-after", "lap-time", "reaction-time", "minutes"],
)
def test_a_duration_in_hours_is_no_clock(text):
    time = read(text).time
    assert time is None or not time.startswith(("01:", "02:", "03:", "12:", "13:", "14:", "15:"))
