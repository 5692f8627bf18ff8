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
        ("We were at a gentle 35 when a fox ran out from the left.", 35 * KPH),
        ("Ego at a constant 45, a jogger steps out from the right.", 45 * KPH),
        ("I was going at around forty when a dog shot out from the left.", 40 * KPH),
    ],
    ids=["gentle", "constant", "around-words"],
)
def test_a_speed_after_at_and_a_modifier_is_read(text, ego):
    assert read(text).ego_speed_mps == pytest.approx(ego)


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
