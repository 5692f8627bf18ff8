"""Numbers as people state them: a number's unit, its head (what it measures) and its owner (the road
user it is said of) read from the grammar around it.

Every wording here is written for these tests (none is from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read

MPH = 0.44704
KPH = 1 / 3.6


def _speeds(text: str) -> tuple[float | None, list[float | None]]:
    r = read(text)
    return r.ego_speed_mps, [a.speed_mps for a in r.actors]


# --- the owner of a speed -------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("A van merges in front of us from the left. Van speed 60 km/h, ego speed 80 km/h.", 80, 60),
        ("A cyclist rides ahead of the ego in its lane, cyclist speed 18 km/h, ego speed 35 km/h.", 35, 18),
        ("A bus pulls out from a stop ahead. Speed of bus 15 km/h, speed of ego 45 km/h.", 45, 15),
        ("Ego speed 70 km/h. A lorry brakes hard ahead, lorry speed 65 km/h.", 70, 65),
    ],
    ids=["noun-speed", "noun-speed-after-clause", "speed-of-noun", "ego-first"],
)
def test_a_speed_headed_by_a_road_user_noun_is_that_road_users(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego * KPH) and len(others) == 1 and others[0] == pytest.approx(other * KPH)


@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("- ego: 40 km/h, straight on\n- cyclist: 12 m ahead, 15 km/h, brakes suddenly", 40, 15),
        ("* car ahead: 25 m, 50 km/h, stops hard\n* ego: 60 km/h", 60, 50),
        ("ego: 30 mph\nmotorcycle: 20 metres ahead, 25 mph, slows down", 30 * 3.6 * MPH, 25 * 3.6 * MPH),
    ],
    ids=["bullets", "ego-last", "lines-mph"],
)
def test_a_number_on_a_key_value_line_belongs_to_the_key(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego * KPH) and len(others) == 1 and others[0] == pytest.approx(other * KPH)


@pytest.mark.parametrize(
    "text, ego",
    [
        ("A cyclist overtakes me doing 18 mph, I'm at 25, and cuts in.", 25 * MPH),
        ("The lorry ahead was doing about 40 mph and I was at 45 when it braked hard.", 45 * MPH),
        ("Van in front at 30 m/s brakes suddenly, ego at 32.", 32.0),
    ],
    ids=["mph", "mph-about", "m/s"],
)
def test_a_bare_number_carries_the_unit_said_before_it(text, ego):
    assert read(text).ego_speed_mps == pytest.approx(ego)


@pytest.mark.parametrize(
    "text",
    [
        "A van ahead drifts into our lane at a lateral speed of 2 m/s; ego at 60 km/h.",
        "Ego at 60 km/h; a van ahead cuts in with a lateral velocity of 0.8 m/s.",
        "Ego at 60 km/h. A cyclist is overtaken with a lateral clearance of 1.2 m, 40 m ahead.",
    ],
    ids=["lateral-speed", "lateral-velocity", "lateral-clearance"],
)
def test_a_lateral_quantity_is_not_a_speed_or_gap_of_travel(text):
    r = read(text)
    assert r.ego_speed_mps == pytest.approx(60 * KPH)
    assert all(a.speed_mps is None or a.speed_mps > 5 for a in r.actors)
    assert all(a.distance_m in (None, 40.0) for a in r.actors)


@pytest.mark.parametrize(
    "text, gap",
    [
        ("Ego at 50 km/h behind a cyclist 25 m ahead; the cyclist brakes hard. Pass if remaining distance > 2 m.", 25),
        ("A moped riding the wrong way comes at us from 30 m ahead and passes about 1 m off our right side.", 30),
        ("A jogger 20 m ahead veers out and goes by half a metre off my wing mirror.", 20),
        ("A van 35 m ahead pulls out 10 m off my bumper.", 10),
    ],
    ids=["remaining-distance", "off-our-side", "off-my-mirror", "off-bumper-is-a-gap"],
)
def test_a_margin_off_a_vehicles_side_or_left_at_the_end_is_no_starting_gap(text, gap):
    assert [a.distance_m for a in read(text).actors] == [gap]


@pytest.mark.parametrize(
    "text, speed",
    [
        ("The ego and a lead truck both at 70 km/h, 30 m apart; the truck brakes hard.", 70),
        ("Ego and target car both at 45 km/h, gap 20 m, target stops suddenly.", 45),
        ("The ego and the van ahead are both doing 50 km/h when the van brakes.", 50),
    ],
    ids=["the-ego-and", "notes", "doing"],
)
def test_both_at_a_speed_gives_it_to_the_ego_and_the_other(text, speed):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(speed * KPH) and others == [pytest.approx(speed * KPH)]


@pytest.mark.parametrize(
    "text, ego, other",
    [
        (
            "A car (the intruder) cuts in from the right lane 20 m ahead. Ego speed 90 km/h, intruder speed 75 km/h.",
            90,
            75,
        ),
        ("A motorbike, our opponent, brakes hard 25 m ahead. Opponent speed 45 km/h. Ego speed 50 km/h.", 50, 45),
        (
            "A lorry, the interloper, swerves into our lane 30 m ahead; interloper speed 60 km/h, ego speed 80 km/h.",
            80,
            60,
        ),
    ],
    ids=["intruder", "opponent", "interloper"],
)
def test_a_speed_headed_by_a_name_the_reader_lacks_is_the_other_road_users(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego * KPH) and others == [pytest.approx(other * KPH)]


@pytest.mark.parametrize(
    "text",
    [
        "Ego 40 km/h, the ETX crosses from the right at 15 km/h, contact at 30% of the front.",
        "Ego speed 40 km/h, the QRB walks across from the left at 5 km/h, contact at 50% of the front.",
        "Subject car 40 km/h, the XPT darts across from the right at 12 km/h, impact at 25% of the front.",
    ],
    ids=["ego-n", "ego-speed", "subject-car"],
)
def test_the_egos_speed_said_by_grammar_stands_against_later_speeds_of_unknown_road_users(text):
    assert read(text).ego_speed_mps == pytest.approx(40 * KPH)


@pytest.mark.parametrize(
    "text, ego",
    [
        ("Doing 20-30 mph through the estate, a child chased a ball out from the right.", 25 * MPH),
        ("Ego somewhere between 40 and 60 km/h; a deer leaps out from the left.", 50 * KPH),
        ("The ego cruises at 70–90 km/h when a lorry ahead sheds its load and stops.", 80 * KPH),
    ],
    ids=["hyphen", "between", "en-dash"],
)
def test_a_range_is_read_as_its_middle(text, ego):
    assert read(text).ego_speed_mps == pytest.approx(ego)


@pytest.mark.parametrize(
    "text, gap",
    [
        ("A lorry stops suddenly 20-30 m ahead of the ego at 60 km/h.", 25.0),
        ("A van brakes hard between 8 and 12 metres in front of the ego, ego at 40 km/h.", 10.0),
        ("A tractor pulls out 2 car lengths ahead of the ego at 50 km/h.", 9.0),
    ],
    ids=["range", "between", "car-lengths"],
)
def test_a_gap_said_as_a_range_or_in_car_lengths_is_metres(text, gap):
    r = read(text)
    assert len(r.actors) == 1 and r.actors[0].distance_m == pytest.approx(gap)


@pytest.mark.parametrize(
    "text, ego",
    [
        ("We were at a gentle 30 when a fox ran out from the left.", 30 * KPH),
        ("Ego at a constant 40, a jogger steps out from the right.", 40 * KPH),
        ("I was going at around forty when a dog shot out from the left.", 40 * KPH),
        ("We were following the bus at a careful thirty when it stopped dead.", 30 * KPH),
        ("Doing a steady sixty in the outside lane, a van drifted across.", 60 * KPH),
        ("I was at an easy fifty when a moped pulled out of the side road.", 50 * KPH),
        ("Rolling along at a sensible twenty, a boy on a bike shot out.", 20 * KPH),
    ],
    ids=["gentle", "constant", "around-words", "careful-words", "steady-words", "easy-words", "sensible-words"],
)
def test_a_speed_after_at_and_a_modifier_is_read(text, ego):
    assert read(text).ego_speed_mps == pytest.approx(ego)


@pytest.mark.parametrize(
    "text",
    [
        "I was doing a good twenty minutes of driving before a cyclist swerved in front of me.",
        "At a guess three cars were queued when a scooter cut in front of me.",
    ],
    ids=["minutes", "small-count"],
)
def test_a_number_in_words_after_an_article_and_a_modifier_that_is_no_speed_is_not_read(text):
    assert read(text).ego_speed_mps is None


@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("CCRm 60/20, dry track, daylight", 60, 20),
        ("CMRb 70/70; headway 20 m, target decelerates at 4 m/s²", 70, 70),
        ("CCRb 80/80, 12 m headway, wet", 80, 80),
    ],
    ids=["ccrm", "cmrb", "ccrb"],
)
def test_a_speed_pair_after_a_test_code_is_the_egos_and_the_targets_in_km_h(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego * KPH) and others == [pytest.approx(other * KPH)]


@pytest.mark.parametrize(
    "text, gap",
    [
        ("Ego at 72 km/h; a van follows at a 2 s gap and then overtakes.", 40.0),
        ("The ego drives at 90 km/h and a lorry tailgates it with a 1-second headway.", 25.0),
        ("Ego 36 km/h, a cyclist 3 seconds ahead brakes suddenly.", 30.0),
    ],
    ids=["gap", "headway", "ahead"],
)
def test_a_time_gap_is_the_distance_covered_in_it_at_the_speed_said(text, gap):
    r = read(text)
    assert len(r.actors) == 1 and r.actors[0].distance_m == pytest.approx(gap)


@pytest.mark.parametrize(
    "text, to",
    [
        ("Ego at 70 km/h; the lorry ahead slows to 30 km/h.", 30 * KPH),
        ("Ego at 50 km/h. The car in front speeds up to 80 as the road clears.", 80 * KPH),
        ("We're doing 40 mph when the bus ahead brakes to 20.", 20 * MPH),
    ],
    ids=["slows-to", "speeds-up-to-bare", "brakes-to-bare"],
)
def test_a_speed_after_to_a_change_of_speed_is_read_in_the_unit_said(text, to):
    (a,) = read(text).actors
    assert a.speed_mps == pytest.approx(to)
    assert any(b[0] in ("change_speed", "sudden_stop") for b in a.behaviours)


@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("I was doing 40 mph behind a tractor doing 15 mph when it turned right.", 40 * MPH, 15 * MPH),
        ("The bus's speed is 30 km/h; it pulls out ahead of the ego at 50 km/h.", 50 * KPH, 30 * KPH),
        ("I was at 30 and a moped going 20 mph ahead of me braked hard.", 30 * MPH, 20 * MPH),
    ],
    ids=["participle", "possessive", "unit-after"],
)
def test_a_speed_is_said_of_the_noun_its_participle_or_possessive_names(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego) and others == [pytest.approx(other)]


@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("I reckon the lorry was going 50 mph when it cut in front of me; I was doing 60 mph.", 60 * MPH, 50 * MPH),
        ("The moped is also doing 20 mph and swerves ahead of me while I am doing 30 mph.", 30 * MPH, 20 * MPH),
        ("The coach was still travelling at 40 km/h when it pulled in ahead; we were at 70 km/h.", 70 * KPH, 40 * KPH),
    ],
    ids=["was-going", "is-also-doing", "was-still-travelling"],
)
def test_a_speed_after_a_subject_and_its_verb_of_going_is_the_subjects(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego) and others == [pytest.approx(other)]


@pytest.mark.parametrize(
    "text, other",
    [
        ("A cyclist crosses from the left. Target speed: 15 km/h. Ego speed: 40 km/h.", 15),
        ("A child steps out ahead of the ego at 40 km/h; target speed 8 km/h.", 8),
        ("A pedestrian walks out from the right, 20 m ahead. Target: 6 km/h. Ego: 30 km/h.", 6),
    ],
    ids=["target-speed-key", "target-speed", "target-key"],
)
def test_the_target_heading_a_number_is_the_road_user_already_named(text, other):
    r = read(text)
    assert len(r.actors) == 1 and r.actors[0].speed_mps == pytest.approx(other * KPH)


@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("The van at 60 km/h overtakes the ego at 50 km/h and cuts in.", 50, 60),
        ("A lorry at 70 km/h passes the ego at 90 km/h in the other lane, then cuts in.", 90, 70),
        ("The motorbike at 80 km/h comes up behind the ego at 60 km/h and overtakes.", 60, 80),
    ],
    ids=["van", "lorry", "motorbike"],
)
def test_a_speed_after_a_subject_opening_its_clause_is_the_subjects(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego * KPH) and others == [pytest.approx(other * KPH)]


# --- the unit of a bare speed from the road it is said on -----------------------------------------------
@pytest.mark.parametrize(
    "text, mph",
    [
        ("Cruising along the M4 at about 60 when a coach pulls across into my lane.", 60),
        ("We were doing 55 on the interstate and a pickup cut in ahead of us.", 55),
        ("On a narrow B-road at 30, a tractor pulls out of a field on the left.", 30),
        ("Dual carriageway, I'm at 50 in the left lane, and a van merges in front of me.", 50),
        ("Heading north on I-5 doing 60, a motorbike weaves in front of me.", 60),
        ("Doing about 25 in a 25 limit when a dog runs out in front of me.", 25),
        ("Southbound on the A34 at 50, a car ahead brakes hard.", 50),
        ("A van sat on my tail for two miles while I was doing 50, then overtook and cut in.", 50),
    ],
    ids=[
        "motorway-number",
        "interstate",
        "b-road",
        "carriageway",
        "interstate-number",
        "us-limit",
        "a-road-number",
        "miles",
    ],  # fmt: skip
)
def test_a_bare_speed_on_a_road_of_a_miles_country_is_in_mph(text, mph):
    assert read(text).ego_speed_mps == pytest.approx(mph * MPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("On the M4 at 90 km/h, a coach pulls across into my lane.", 90),
        ("On the freeway at 100, a car cuts in front. The car is going 110 km/h.", 100),
        ("On a motorway at 100, a lorry changes lane in front of the ego.", 100),
        ("At 50 on a road through town, a cyclist swerves in front of me.", 50),
        ("Doing 30 in a 30 zone, a child runs out between parked cars.", 30),
        ("Car B 20 m ahead brakes hard, ego at 40.", 40),
    ],
    ids=["unit-said", "unit-said-later", "motorway-unnumbered", "a-road-article", "limit-of-both", "label-b"],
)
def test_a_bare_speed_elsewhere_stays_in_the_unit_said_or_km_h(text, kph):
    assert read(text).ego_speed_mps == pytest.approx(kph * KPH)


# --- the ego standing still -------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "I was sat at a red light when a van went into the back of me.",
        "We were waiting at the lights and a bus clipped our rear.",
        "Ego is stationary at a stop line; a lorry approaches from behind and fails to stop.",
        "The claimant had stopped in a queue when the defendant's van struck the rear of her car.",
        "A taxi hit me from behind while I was queuing at the junction.",
    ],
    ids=["sat", "waiting", "stationary", "had-stopped", "while-queuing"],
)
def test_the_ego_said_to_stand_still_starts_at_rest(text):
    assert read(text).ego_speed_mps == 0.0


@pytest.mark.parametrize(
    "text, kph",
    [
        ("A child ran out from between parked cars and I was stopped just in time.", None),
        ("I was doing 30 km/h when a van pulled out; I was stopped within a few metres.", 30),
        ("A car in front of me is waiting at the lights, I approach at 40 km/h.", 40),
    ],
    ids=["stop-as-reaction", "speed-said", "someone-else-waits"],
)
def test_a_stop_the_ego_makes_or_anothers_wait_is_no_start_at_rest(text, kph):
    speed = read(text).ego_speed_mps
    assert (speed is None) if kph is None else speed == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text, relation",
    [
        ("I was waiting at the lights when a van in the same lane ran into my rear.", "behind"),
        ("I was sat at a red light when a van went into the back of me.", "behind"),
        ("We were queuing at the roundabout and a minibus drove straight into us.", "behind"),
        ("I was waiting at the lights in my lane when the van in front pulled away.", "ahead"),
    ],
    ids=["ran-into-rear", "back-of-me", "drove-into-us", "pulls-away-ahead"],
)
def test_who_meets_the_ego_at_rest_along_its_lane_comes_from_behind(text, relation):
    r = read(text)
    assert r.ego_speed_mps == 0.0 and [a.relation for a in r.actors] == [relation]


# --- a hedged speed, a bare speed after the ego's name ----------------------------------------------------
@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("A van behind me overtook on the bend doing at least 70 mph and cut back in. I was at 50 mph.", 50, 70),
        ("A motorbike going well over 60 passes me on the right, I'm doing 40 mph.", 40, 60),
        ("A taxi cuts in at just under 50 km/h, ego at nearly 70 km/h.", 70, 50),
    ],
    ids=["at-least", "well-over", "just-under-nearly"],
)
def test_a_hedged_speed_is_read_as_the_speed(text, ego, other):
    ego_mps, others = _speeds(text)
    unit = MPH if "mph" in text else KPH
    assert ego_mps == pytest.approx(ego * unit) and others == [pytest.approx(other * unit)]


@pytest.mark.parametrize(
    "text, ego",
    [
        ("Van pulls out from the left 20 m ahead, ego 60, wet road", 60),
        ("Lane 3, ego 80 and a lorry moves over in front", 80),
        ("Cyclist 20 km/h ahead on the right, ego 45.", 45),
        ("SUT at 40 km/h, a pedestrian crosses from the left 15 m ahead.", 40),
    ],
    ids=["ego-n-comma", "ego-n-and", "ego-n-end", "sut"],
)
def test_a_bare_number_after_the_egos_name_is_its_speed(text, ego):
    assert read(text).ego_speed_mps == pytest.approx(ego * KPH)


# --- a stated speed reaches the layers ------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Ego at 40 km/h. Crossing car from the right runs the red at 60 km/h.", 60),
        ("Ego 30 km/h on green. Speeding van from the left jumps the lights at 70 km/h.", 70),
        ("Ego doing 50 km/h. Reversing lorry backs out of a yard on the left at 8 km/h.", 8),
    ],
    ids=["crossing-car", "speeding-van", "reversing-lorry"],
)
def test_a_terse_lines_participle_before_a_road_user_is_that_road_users(text, kph):
    r = read(text)
    assert len(r.actors) == 1 and r.actors[0].speed_mps == pytest.approx(kph * KPH)
    assert r.ego_speed_mps != pytest.approx(kph * KPH)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_stated_speed_is_kept_in_every_generated_scenario(seed):
    from vei_scenario.language.rules_backend import sample_layers

    text = "Junction with lights, ego straight on at 40 km/h. A car from the right runs the red at 60 km/h."
    layers = sample_layers(read(text), text, seed)
    assert float(layers["adversaries"][0]["speed_mps"]) == pytest.approx(60 * KPH, abs=0.01)
    assert float(layers["ego"]["speed_mps"]) == pytest.approx(40 * KPH, abs=0.01)


def test_a_participle_of_going_towards_another_keeps_its_object():
    """ "Following lorry at 30 m": the ego follows it (the lorry is ahead), not a following lorry."""
    r = read("Following lorry at 30 m, ego brakes hard at 60 km/h.")
    assert [a.relation for a in r.actors] == ["ahead"]


@pytest.mark.parametrize(
    "text, mph",
    [
        ("I was doing 40ish mph when a van pulled out of a side road on my left.", 40),
        ("A motorbike came past at 70-odd mph and cut in; I was doing 50 mph.", 50),
        ("The ego was at 30 mph-ish when a cyclist swerved in front.", 30),
        ("I was in the high 60s mph on the motorway when a lorry moved into my lane.", 68),
        ("Doing the mid-40s mph, I saw a deer run out from the left.", 45),
    ],
    ids=["ish", "odd", "unit-ish", "high-60s", "mid-40s"],
)
def test_a_number_hedged_after_it_keeps_its_unit(text, mph):
    assert read(text).ego_speed_mps == pytest.approx(mph * MPH)


def test_an_age_in_decades_is_no_speed():
    r = read("A man in his mid-40s steps out from behind a bus; I'm doing 30 km/h.")
    assert r.ego_speed_mps == pytest.approx(30 * KPH) and all(a.speed_mps is None for a in r.actors)


@pytest.mark.parametrize(
    "text, gap",
    [
        ("Ego: 90 km/h. Lead van at 60 km/h far ahead. Car behind the ego, following at a 2 s gap.", 50.0),
        ("I was doing 72 km/h. A bus at 50 km/h was in the left lane. A taxi sat 1 second behind me.", 20.0),
        ("- Ego 108 kph\n- Actor 1: lorry ahead, 70 kph\n- Actor 2: car behind, 2 s headway", 60.0),
    ],
)
def test_a_time_gap_to_the_ego_is_at_the_egos_speed(text, gap):
    """The time gap between the ego and a road user behind or ahead of it is covered at the ego's speed
    (the follower's, who keeps pace), not at the speed of another road user said in between."""
    r = read(text)
    assert [a.distance_m for a in r.actors if a.distance_m is not None] == [pytest.approx(gap)]


# "@" before a number is the shorthand for "at": the number keeps the grammar of "at 3 m/s" and is
# said of the road user that acts in its clause, not of the noun right before the sign.
@pytest.mark.parametrize(
    "text, kind, speed_mps",
    [
        ("A toddler toddles out from behind parked vans @ 1.5 m/s, ego 30 km/h.", "pedestrian", 1.5),
        ("Ego 50 km/h; cyclist crosses between stationary buses @ 4 m/s from the left.", "bicycle", 4.0),
        ("Ego 40 km/h; a fox darts across between parked cars @2 m/s.", "pedestrian", 2.0),
    ],
)
def test_an_at_sign_before_a_number_reads_as_at(text, kind, speed_mps):
    specs = read(text).actors
    mover = next(s for s in specs if s.kind == kind)
    assert mover.speed_mps == pytest.approx(speed_mps)
    assert all(s.speed_mps in (None, 0.0) for s in specs if s is not mover)  # (the parked ones stand)


def test_an_at_sign_without_a_number_is_no_speed():
    from vei_scenario.language.reader import _tokens

    assert "at" not in _tokens("ping @ops when the van @ the depot leaves")  # (a handle, a place: no number)
    assert _tokens("a car @30kph")[-3:] == ["at", "30", "km/h"]


# A number right after a noun that is the object of a place preposition ("between parked cars 3 m/s")
# is not said of that noun: the scenery says where; the one that comes out from there has the number.
@pytest.mark.parametrize(
    "text, kind, speed_mps",
    [
        ("A jogger steps out between parked cars 3 m/s.", "pedestrian", 3.0),
        ("A child runs out from behind two stationary vans 2 m/s, ego 30 km/h.", "pedestrian", 2.0),
        ("Ego 40 km/h, a boy darts out between a few parked lorries 5 m/s.", "pedestrian", 5.0),
        ("A scooter rider shoots out from behind a parked bus 4 m/s.", "e-scooter", 4.0),
    ],
)
def test_a_number_after_scenery_in_a_place_phrase_is_the_movers(text, kind, speed_mps):
    specs = read(text).actors
    mover = next(s for s in specs if s.kind == kind)
    assert mover.speed_mps == pytest.approx(speed_mps)
    assert all(s.speed_mps in (None, 0.0) for s in specs if s is not mover)


@pytest.mark.parametrize(
    "text, kind, speed_mps",
    [
        # near misses: a number right after a road user that is no place's object is its own
        ("Ego 50 km/h; cyclist 15 km/h ahead.", "bicycle", 15 / 3.6),
        ("Ego 50 km/h, a car behind us 60 km/h.", "car", 60 / 3.6),
    ],
)
def test_a_number_after_a_road_user_outside_a_place_phrase_stays_its_own(text, kind, speed_mps):
    spec = next(s for s in read(text).actors if s.kind == kind)
    assert spec.speed_mps == pytest.approx(speed_mps)


@pytest.mark.parametrize(
    "text, speed",
    [
        ("The ego and the lead van will both drive at 60 km/h along the motorway.", 60),
        ("Ego and target should both travel at 40 km/h in the same lane; the target brakes.", 40),
        ("The test car and the lorry both cruise at 80 km/h, then the lorry slows.", 80),
    ],
    ids=["will-drive", "should-travel", "cruise"],
)
def test_both_with_a_modal_or_a_base_verb_of_going_gives_the_speed_to_both(text, speed):
    """ "X and Y shall both travel at N": a modal and the verb's base form stand where "are doing" does."""
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(speed * KPH) and others == [pytest.approx(speed * KPH)]


@pytest.mark.parametrize(
    "text, start, to",
    [
        ("The ego and the lead car both cruise at 80 km/h; the lead car then brakes at 3 m/s² to 40 km/h.", 80, 40),
        ("Ego and van both drive at 70 km/h, then the van decelerates at 2 m/s² down to 30 km/h.", 70, 30),
        ("A lorry ahead at 60 km/h slows at 1.5 m/s² to 20 km/h.", 60, 20),
    ],
    ids=["brakes-at-rate-to", "decelerates-down-to", "slows-at-rate"],
)
def test_a_speed_after_a_rate_and_to_is_the_speed_changed_to(text, start, to):
    """ "decelerates at 2 m/s² to 20 km/h": the rate between the verb and "to" leaves the speed the one
    it slows to, not the speed it goes at."""
    r = read(text)
    (a,) = r.actors
    assert a.speed_mps == pytest.approx(start * KPH)
    (delta,) = [b[1]["speed_delta_mps"] for b in a.behaviours if b[0] == "change_speed"]
    assert delta == pytest.approx((to - start) * KPH)


@pytest.mark.parametrize(
    "text, other, ego",
    [
        ("A maniac behind me overtook on the bend doing at least 70 mph, and I was doing 50 mph.", 70, 50),
        ("Some idiot overtook us on the bypass doing 90 mph while we were doing 60 mph.", 90, 60),
        ("An idiot cut in front of me doing about 80 mph; I was at 55 mph.", 80, 55),
    ],
    ids=["overtook-doing", "while-we", "cut-in"],
)
def test_a_person_who_drives_keeps_a_drivers_speed(text, other, ego):
    """A person noun that overtakes or cuts in is a driver: a speed no walker reaches is still its own,
    not the ego's."""
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego * MPH) and others == [pytest.approx(other * MPH)]


@pytest.mark.parametrize(
    "text, ego",
    [
        ("A man ran out in front of the car at 50 km/h.", 50),
        ("A jogger crossed in front of us at 40 km/h.", 40),
    ],
)
def test_a_speed_no_walker_reaches_is_still_the_egos(text, ego):
    assert _speeds(text)[0] == pytest.approx(ego * KPH)


@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("The ego drives at 50 km/h. A lorry went past us doing 70 km/h and cut in.", 50, 70),
        ("I was at 40 km/h when a motorbike overtook me going 90 km/h.", 40, 90),
        ("We drove at 30 km/h; a taxi passed us doing 50 km/h, then pulled in ahead.", 30, 50),
    ],
    ids=["went-past-us-doing", "overtook-me-going", "passed-us-doing"],
)
def test_a_speed_after_the_object_of_a_pass_is_the_passers(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego * KPH) and len(others) == 1 and others[0] == pytest.approx(other * KPH)


@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("The ego drives at 50 km/h. Ahead is a cyclist, 15 km/h.", 50, 15),
        ("Ego at 60 km/h. In front of the ego there is a tractor without lights, same lane, 25 km/h.", 60, 25),
        ("The ego travels at 40 km/h; there is a jogger on the verge, same direction, 9 km/h.", 40, 9),
    ],
    ids=["ahead-is-a-cyclist", "there-is-a-tractor", "a-jogger-same-direction"],
)
def test_a_speed_noted_after_a_road_user_it_introduces_is_its(text, ego, other):
    ego_mps, others = _speeds(text)
    assert ego_mps == pytest.approx(ego * KPH) and len(others) == 1 and others[0] == pytest.approx(other * KPH)


def test_a_speed_noted_after_a_road_user_the_ego_acts_on_is_not_its():
    ego_mps, others = _speeds("I overtook a cyclist, 60 km/h at the time.")
    assert others == [None] or others[0] != pytest.approx(60 * KPH)


def _gaps(text: str) -> list[float | None]:
    return [a.distance_m for a in read(text).actors]


@pytest.mark.parametrize(
    "text, gap",
    [
        ("A moped moved into our lane 8 m ahead. The smallest lateral gap recorded was about 0.4 m.", 8),
        ("A cyclist swerved in front of the ego 12 m ahead; the lateral distance between them was 0.7 m.", 12),
        ("A van cut in 10 m ahead of the ego. Its sideways offset at the nearest point is 0.3 m.", 10),
    ],
    ids=["lateral-gap-recorded-was", "lateral-distance-between-was", "sideways-offset-is"],
)
def test_a_distance_said_of_a_lateral_measure_through_a_copula_is_no_gap(text, gap):
    assert _gaps(text) == [pytest.approx(gap)]


@pytest.mark.parametrize(
    "text, gap",
    [
        ("A van ahead of the ego braked hard. The gap to it was 10 m when it braked.", 10),
        ("A cyclist rides ahead of the ego; the distance between them is 15 m.", 15),
    ],
    ids=["gap-was", "distance-is"],
)
def test_a_distance_said_of_a_gap_through_a_copula_is_the_gap(text, gap):
    assert _gaps(text) == [pytest.approx(gap)]


def test_a_minimum_gap_through_a_copula_stays_the_gap():
    assert _gaps("A van cut in ahead of the ego and braked. The minimum gap to it was 3 m.") == [pytest.approx(3)]
