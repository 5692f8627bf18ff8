"""The ego's speed: which stated number is the ego's, and the unit of a number said bare.

Every wording here is written for these tests (none is from a corpus). Each class of construction has
at least three wordings that must read, and near misses that look alike but must not."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read

MPH = 0.44704
KPH = 1 / 3.6


def _ego(text: str) -> float | None:
    return read(text).ego_speed_mps


# --- "<subject> <be> at <speed>": the subject's -----------------------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("a lorry ahead slams on and then the van behind me nearly hits us we were at roughly 60 km/h", 60),
        ("the bus in front stopped dead and a taxi behind almost rear-ended us I was at about 40 km/h", 40),
        ("A cyclist swerves out and a moped behind clips us, we are at maybe 30 km/h at that point", 30),
    ],
    ids=["we-were", "i-was", "we-are"],
)
def test_a_speed_after_the_ego_and_a_form_of_be_is_the_egos(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


def test_a_speed_after_another_subject_and_be_is_that_road_users():
    r = read("The ego drives at 50 km/h. A van ahead brakes, the van was at about 45 km/h.")
    assert r.ego_speed_mps == pytest.approx(50 * KPH) and r.actors[0].speed_mps == pytest.approx(45 * KPH)


# --- "the same <noun> as <road user>": a comparison, not the subject of a clause ---------------------------
@pytest.mark.parametrize(
    "text, ego, other",
    [
        ("The cyclist rides in the same lane as the ego at 18 km/h. The ego comes up from behind at 40 km/h.", 40, 18),
        ("A scooter moves the same way as the ego at 20 km/h; the ego closes in at a speed of 50 km/h.", 50, 20),
        ("The target car keeps the same lane as the SUT at 30 km/h. The SUT follows at 60 km/h.", 60, 30),
    ],
    ids=["same-lane-as", "same-way-as", "same-lane-as-sut"],
)
def test_a_speed_after_the_same_x_as_the_ego_is_the_subjects(text, ego, other):
    r = read(text)
    assert r.ego_speed_mps == pytest.approx(ego * KPH)
    assert [a.speed_mps for a in r.actors] == [pytest.approx(other * KPH)]


def test_a_clause_opened_by_as_still_has_its_subject():
    r = read("A pedestrian steps out as the ego at 40 km/h comes past.")
    assert r.ego_speed_mps == pytest.approx(40 * KPH)


# --- the unit of a bare speed: the writer's road signs ---------------------------------------------------
@pytest.mark.parametrize(
    "text, mph",
    [
        ("Doing 25 past the school, a boy ran out about ten feet ahead of my bumper.", 25),
        ("I was going 40 on the way home when a pickup pulled out maybe 60 feet in front of me.", 40),
        ("I was doing 30 when a kid on a bike shot out a few yards in front of me.", 30),
    ],
    ids=["feet", "feet-later", "yards"],
)
def test_a_bare_speed_in_a_text_that_measures_in_feet_or_yards_is_mph(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH)


@pytest.mark.parametrize(
    "text, mph",
    [
        ("Going 40 on a divided highway when a semi drifted into my lane.", 40),
        ("Doing about 30 and a jogger stepped off the curb right in front of me.", 30),
        ("I was going 25 by the gas station and a cyclist cut across from the sidewalk.", 25),
        ("Rolling along at 20 through the parking lot, a kid ran out between two cars.", 20),
    ],
    ids=["divided-highway", "curb", "gas-station-sidewalk", "parking-lot"],
)
def test_a_bare_speed_on_an_american_road_is_mph(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("On the motorway doing 120, a van cut in front of me.", 120),
        ("Heavy traffic on the motorway, I'm doing 60 and a courier van darts into my lane.", 60),
        ("On the Autobahn A8 doing 70 in the jam, a truck pulled out in front of me.", 70),
        ("Doing 40 on the B27, a cyclist swerved out 2 km before the Autobahn exit.", 40),
        ("Doing 40, a man on foot crossed in front of me.", 40),
        ("Doing 30, a cyclist put his feet down and wobbled into my lane.", 30),
        ("Out this aft doing 40 when a cyclist pulled out in front of me.", 40),
    ],
    ids=["motorway-fast", "motorway-jam", "autobahn", "bundesstrasse-km", "on-foot", "body-feet", "aft-no-foot"],
)
def test_a_bare_speed_stays_kmh_without_a_sign_of_miles(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


# --- a bare speed only a mile-per-hour limit rounds to: mph ----------------------------------------------
@pytest.mark.parametrize(
    "text, mph",
    [
        ("Was doing about 35 when a lad on a scooter pulled out of the side road.", 35),
        ("hey so i was going like 25 and this guy on a bike just swerves in front of me lol", 25),
        ("My car was travelling at approx 45 when the pedestrian stepped out from the nearside.", 45),
        ("Cruising at 65 in the fast lane when a sedan merged in front of me without signalling.", 65),
        ("My wife was only doing 25ish, thank god, when the kid darted out between the cars.", 25),
        ("Coming over the brow at a steady 55, we saw a tractor turning in ahead.", 55),
    ],
    ids=["uk-text", "us-message", "my-car", "us-fast-lane", "hedged", "steady"],
)
def test_a_bare_speed_at_a_value_only_mph_limits_have_is_mph(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("Was doing about 30 when a lad on a scooter pulled out of the side road.", 30),
        ("Was doing about 50 when a lad on a scooter pulled out of the side road.", 50),
        ("A cyclist was doing 20 km/h beside me and I was at 35.", 35),
        ("Doing 45 in the ute when a cyclist swerved out in front.", 45),
        ("I was riding my e-scooter at 25 when a car door opened right in front of me.", 25),
        ("I was going 45 speed only near the flyover when an auto cut in.", 45),
        ("The test car was doing about 35 when the pedestrian dummy stepped out.", 35),
        ("Witness says the van was going around 45 when it hit the cyclist.", 45),
    ],
    ids=["round-30", "round-50", "unit-said-before", "metric-country", "rider", "number-speed", "spec", "witness"],
)
def test_a_bare_speed_not_only_of_mph_limits_keeps_its_unit(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


# --- a change of speed in a crash (delta-v, EES) is no speed anyone travels at --------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("V1 was travelling at about 80 km/h when V2 pulled out from the left; delta-v V1 = 30 km/h.", 80),
        ("The car was doing approximately 60 km/h before impact. Delta V for the car was 25 km/h.", 60),
        ("Ego at 50 km/h, a van pulls out from the right; estimated delta-v of the ego 20 km/h.", 50),
        ("I was doing 70 km/h when a truck pulled out. Reconstruction: my car's EES was 35 km/h.", 70),
        ("Vehicle 1 at approx. 90 km/h, the other car turned across it. dV vehicle 1: 40 km/h.", 90),
    ],
    ids=["delta-v-equals", "delta-v-spaced", "delta-v-of", "ees", "dv"],
)
def test_a_crash_change_of_speed_is_not_the_egos_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


def test_a_car_named_delta_keeps_its_speed():
    reading = read("A Lancia Delta doing 40 km/h pulled out in front of me while I was at 60 km/h.")
    assert reading.ego_speed_mps == pytest.approx(60 * KPH)
    assert [a.speed_mps for a in reading.actors] == [pytest.approx(40 * KPH)]


# --- "<speed> down to <speed>": the speed it had, then the one it braked to ---------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I slammed on, 70 down to 30 km/h, as the van cut in.", 70),
        ("Speed dropped from 60 down to 20 km/h when the cyclist swerved.", 60),
        ("We went 50 down to 10 mph in about two seconds when a deer ran out.", 50 * 1.609344),
        ("Ego brakes 80 down to 40 km/h behind the truck that cut in.", 80),
        ("Had to scrub off speed fast, 100 down to 60 km/h, because a car pulled out.", 100),
    ],
    ids=["slammed", "from-down-to", "mph", "spec", "scrub"],
)
def test_a_speed_said_down_to_another_is_the_first(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, rel=1e-3)


def test_a_number_counted_down_to_another_is_no_speed():
    assert _ego("The lights counted 10 down to 1 while I was doing 40 km/h and a cyclist crossed.") == pytest.approx(
        40 * KPH
    )


# --- a sentence opening with a participle of driving: its speed is the narrator's --------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Rolling down Mill Lane at about 40 km/h, a delivery van reversed out of a drive into my path.", 40),
        ("Heading into town at 50 km/h on Sunday morning, and a cyclist swung out from the kerb ahead.", 50),
        ("Towing a caravan at 80 km/h on the coast road when a motorbike overtook and cut in.", 80),
        ("Coming over the hill at roughly 30 mph, a tractor pulled out of a field gate ahead of her.", 48.28),
    ],
    ids=["rolling", "heading-and", "towing-when", "coming-her"],
)
def test_a_speed_in_an_opening_participle_of_driving_is_the_egos(text, kph):
    r = read(text)
    assert r.ego_speed_mps == pytest.approx(kph * KPH, rel=1e-3)
    assert all(a.speed_mps is None for a in r.actors)


@pytest.mark.parametrize(
    "text",
    [
        "Crossing the road at 6 km/h, a jogger stepped in front of the ego.",
        "Riding along the kerb at 18 km/h, a cyclist swerved into the ego's lane.",
    ],
    ids=["crossing", "riding"],
)
def test_a_speed_in_an_opening_participle_of_walking_or_riding_is_not_the_egos(text):
    r = read(text)
    assert r.ego_speed_mps is None and r.actors[0].speed_mps is not None


def test_a_participle_the_lexicon_lacks_still_opens_the_narrators_drive():
    assert _ego("Creeping through the roadworks at 15 km/h when a pedestrian walked out in front of me.") == (
        pytest.approx(15 * KPH)
    )


# --- the ego standing as the scene opens ---------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "We were stopped at the junction and a scooter ran into the back of us.",
        "I am stopped at a zebra crossing; a moped clips my rear.",
        "Pulled up to the lights early, I was stopped at the red light and a cyclist rode into my rear bumper.",
    ],
    ids=["were-stopped-at", "am-stopped-at", "after-own-move"],
)
def test_the_ego_said_to_be_stopped_somewhere_starts_at_rest(text):
    assert _ego(text) == 0.0


@pytest.mark.parametrize(
    "text",
    [
        "A child ran out ahead of me and I stopped at the crossing just in time.",
        "A van cut in, so we stopped at the next lay-by to check the car.",
    ],
    ids=["stop-as-reaction", "stop-later"],
)
def test_a_stop_the_ego_makes_after_someone_acts_is_no_start_at_rest(text):
    assert _ego(text) != 0.0


# --- a speed at impact after the ego braked is no start speed -------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist swerved in front of me, I braked hard and we hit her at about 10 mph.",
        "The ego brakes hard but hits the dummy at 25 km/h.",
        "A dog ran out; I was braking already and still struck it at an estimated 12 km/h.",
    ],
    ids=["we-hit", "but-hits", "still-struck"],
)
def test_the_speed_of_an_impact_after_braking_is_not_the_egos_start_speed(text):
    assert _ego(text) is None


def test_an_impact_speed_after_braking_leaves_the_start_speed_said_before():
    assert _ego("Doing 50 km/h, I saw the boy late, braked, and clipped him at around 20 km/h.") == pytest.approx(
        50 * KPH
    )


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I hit the cyclist at 30 km/h without braking.", 30),
        ("We struck the barrier at 40 km/h and only then braked.", 40),
    ],
    ids=["no-braking", "braking-after"],
)
def test_an_impact_speed_with_no_braking_before_it_is_the_egos_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


def test_an_impact_speed_after_another_road_users_braking_is_the_egos_speed():
    assert _ego("The car in front braked sharply and I hit it at 20 mph.") == pytest.approx(20 * MPH)


# --- "both at <speed>" after a line that names the ego and one other -----------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Ego: behind a bus, 20 m back, both at 40 km/h. The bus brakes hard.", 40),
        ("The ego follows a van with a 25 m gap, both at 60 km/h; the van stops suddenly.", 60),
        ("Ego in lane 1 behind a lorry, 30 m gap, both at 70 km/h; the lorry brakes.", 70),
    ],
    ids=["key-line", "follows", "behind"],
)
def test_both_at_a_speed_after_the_ego_and_another_is_the_speed_of_each(text, kph):
    r = read(text)
    assert r.ego_speed_mps == pytest.approx(kph * KPH)
    assert r.actors[0].speed_mps == pytest.approx(kph * KPH)


def test_both_of_a_pair_said_without_the_ego_is_not_the_egos_speed():
    r = read("Two scooters ride ahead, both at 20 km/h, and one of them brakes.")
    assert r.ego_speed_mps is None


# --- a speed note with no verb, set off right after the ego is named: the ego's ------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("a scooter darts across my bonnet, 25 mph, just missed it", 25 / 0.621371),
        ("bus pulls out right in front of us, about 30 km/h, had to brake hard", 30),
        ("motorbike undertakes and cuts in ahead of me, 50 km/h, close call", 50),
        ("the courier van swung into my lane - roughly 40 km/h - and I braked", 40),
    ],
    ids=["bonnet-mph", "us-about", "me-kmh", "dashes"],
)
def test_a_verbless_speed_note_right_after_the_ego_is_the_egos(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, rel=1e-3)


@pytest.mark.parametrize(
    "text",
    [
        "a cyclist, 20 km/h, crosses in front of the ego",  # (the note follows the cyclist)
        "a van cuts in front of me, the cyclist at 20 km/h behind it",  # (a speed with its own subject)
        "a van cut in front of my car, 30 km/h limit there",  # (a limit, not a speed)
        "A jogger was running in the road in front of me, about 10 km/h, so I slowed.",  # (how the jogger goes)
        "A cyclist rode along the gutter ahead of my car, roughly 30 km/h.",
    ],
    ids=["after-other", "own-subject", "limit", "jogger-running", "cyclist-rode"],
)
def test_a_speed_note_not_right_after_the_ego_is_not_the_egos(text):
    assert all(_ego(text) != pytest.approx(v * KPH) for v in (10, 20, 30))


# --- "<verb> into/across/in front of the ego <place> at <speed>": of the ego as well ------------------------
@pytest.mark.parametrize(
    "text, mph",
    [
        ("LORRY SWERVES INTO MY LANE ON THE M1 AT 60MPH", 60),
        ("A van cut across me on the ring road at 40 mph.", 40),
        ("Truck merged into us on the interstate at 70 mph, no signal.", 70),
    ],
    ids=["headline", "across-me", "into-us"],
)
def test_a_speed_after_the_ego_and_its_place_is_the_egos_too(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist overtook me on the bridge at 25 mph.",  # (the ego is the object of overtaking: slower)
        "A van cut across the cyclist on the ring road at 25 mph.",  # (not the ego)
    ],
    ids=["overtook-me", "other-object"],
)
def test_a_speed_after_a_place_not_of_the_ego_named_after_a_preposition_is_not_the_egos(text):
    assert _ego(text) != pytest.approx(25 * MPH)


# --- the ego said to stand, in a note with no verb ("Ego stationary at the lights") -------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Ego stationary at the red light; a cyclist rides into its rear.",
        "With my car stationary in the queue, a scooter rider ran into the back of it.",
        "Ego vehicle stationary in lane 1. A truck approaches from behind and fails to stop.",
        "Us parked up at the kerb, hazards on, when a moped clipped the back of the van.",
    ],
    ids=["ego-stationary", "with-my-car", "ego-vehicle", "us-parked"],
)
def test_the_ego_with_a_state_of_standing_and_no_verb_starts_at_rest(text):
    assert _ego(text) == 0.0


@pytest.mark.parametrize(
    "text, kph",
    [
        ("Ego at 40 km/h passes a stationary bus; a child steps out from behind it.", 40),
        ("The van ahead stationary in lane 1, the ego approaches at 50 km/h.", 50),
    ],
    ids=["passes-stationary", "other-stationary"],
)
def test_a_state_of_standing_of_another_road_user_is_not_the_egos(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


# --- a road user that follows the ego keeps the ego's pace: its speed is the ego's too -----------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("A van tailgated me for miles on the bypass at 60 mph.", 60 / 0.621371),
        ("A black SUV sat right on my rear bumper at 70 km/h for ages.", 70),
        ("A lorry followed us closely at 80 km/h, about 10 m back.", 80),
    ],
    ids=["tailgated-me", "sat-on-bumper", "followed-us"],
)
def test_the_speed_of_a_road_user_following_the_ego_is_the_egos(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, rel=1e-3)


@pytest.mark.parametrize(
    "text",
    [
        "A taxi followed a cyclist at 20 km/h in the bus lane.",  # (it follows someone else)
        "A lorry overtook me on the bypass, doing 20 km/h more than me.",  # (it overtakes: faster than the ego)
        "A moped tails the ego for a while and then overtakes it on the left at 20 km/h.",  # (then overtakes)
    ],
    ids=["follows-another", "overtakes", "follows-then-overtakes"],
)
def test_the_speed_of_a_road_user_following_another_is_not_the_egos(text):
    assert _ego(text) != pytest.approx(20 * KPH)


# --- a number hedged or given as a choice before its unit: about that number, the middle of the two ----------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was driving at 30 or so mph when a cyclist pulled out in front of me.", 30 / 0.621371),
        ("We were doing 40-something mph when a van cut in ahead of us.", 45 / 0.621371),
        ("I was going 50 or 60 km/h when a child ran out from the left.", 55),
        ("The ego travels at 40 to 50 km/h when a scooter ahead brakes.", 45),
        ("I was cruising at about 70 or 80 km/h when a lorry cut in front of me.", 75),
    ],
    ids=["or-so", "something", "or", "at-to", "about-or"],
)
def test_a_speed_hedged_or_given_as_a_choice_before_its_unit(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, rel=1e-3)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("The ego slows from 50 to 20 km/h as a cyclist crosses ahead.", 50),  # (a change, not a choice)
        ("I went from 60 to 30 km/h when the van in front braked.", 60),
    ],
    ids=["slows-from-to", "went-from-to"],
)
def test_a_speed_from_one_number_to_another_is_a_change_not_a_choice(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


# --- a speed set right after the ego where it is the object of a verb ("lets the ego (50 km/h) pass") -------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("A cyclist waits at the kerb and lets the ego (40 km/h) go by, then crosses behind it.", 40),
        ("A scooter rider stops at the give-way line, letting the ego (50 km/h on the main road) pass.", 50),
        ("A pedestrian on the island waits for the ego (30 km/h) to go past, then steps out.", 30),
    ],
    ids=["lets-the-ego", "letting-the-ego", "waits-for-the-ego"],
)
def test_a_speed_right_after_the_ego_as_an_object_is_the_egos(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text",
    [
        "A van (30 km/h) pulls out of a driveway in front of the ego.",
        "A pedestrian waits for the ego to pass, then crosses at 6 km/h.",
    ],
    ids=["after-the-van", "later-in-the-clause"],
)
def test_a_speed_not_right_after_the_ego_object_is_not_the_egos(text):
    assert all(_ego(text) != pytest.approx(v * KPH) for v in (6, 30))


# --- the writer's country by the words only one side of the mph / km/h divide uses for road things ----------
@pytest.mark.parametrize(
    "text, mph",
    [
        ("Doing 60 in lane one when a van shot off the slip road right in front of me.", 60),
        ("I was doing about 50 when a lorry pulled out of a lay-by just ahead of me.", 50),
        ("Was doing 70 when a car parked on the hard shoulder pulled straight out in front of me.", 70),
        ("Coming down the sliproad doing 40, a van in the inside lane swerved across into me.", 40),
        ("going 30 through the stoplight when a kid on a bike came across from the right", 30),
        ("Doing maybe 45 and a state trooper's cruiser pulled out of the median in front of me.", 45),
    ],
    ids=["slip-road", "lay-by", "hard-shoulder", "sliproad", "stoplight", "trooper"],
)
def test_a_bare_speed_by_a_british_or_american_road_word_is_mph(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("Doing 60 on the freeway in the ute when a semi drifted into my lane.", 60),
        ("I was doing 40 near the curb when an okada cut right in front of me.", 40),
        ("Going about 30 past the crosswalk when a tuk-tuk pulled out from the left.", 30),
        ("A danfo swerved into my lane on the expressway; I was doing 70 on the wet carriageway.", 70),
        ("doing 50 on the freeway and a matatu overtook me then cut in sharp", 50),
        ("Doing 60 down the slip road when a bakkie pulled out in front of me.", 60),
    ],
    ids=["ute-freeway", "okada-curb", "tuk-tuk-crosswalk", "danfo-carriageway", "matatu-freeway", "bakkie-slip"],
)
def test_a_bare_speed_beside_a_road_user_only_km_h_countries_have_stays_kmh(text, kph):
    """A minibus taxi, a motorbike taxi, a three-wheeler or a pickup by a name only countries that sign km/h
    use sets the text there, whatever road word it shares with Britain or America."""
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("Doing about 80 klicks on the freeway when a semi came across the centre line.", 80),
        ("I was at 40 klicks near the curb when a cyclist swerved out.", 40),
        ("maybe 50 clicks, then a car pulled out of the gas station in front of me", 50),
    ],
    ids=["klicks-freeway", "klicks-curb", "clicks"],
)
def test_klicks_are_kilometres_an_hour(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text, mph",
    [
        ("Doing 40 on the slip road, a van cut in about 10 metres ahead of me.", 40),  # (metres: British too)
        ("Doing 50 past the lay-by when a pickup truck pulled out on the left.", 50),  # (a pickup: said anywhere)
        ("I was doing 30 on the high street when an auto parts van pulled out.", 30),  # (no auto-rickshaw)
    ],
    ids=["slip-metres", "lay-by-pickup", "auto-parts"],
)
def test_words_said_on_both_sides_change_no_unit(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH)


# --- a label numbered before a dash is no range -------------------------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Run 3 - 60 km/h, a car cuts in from the left lane 15 m ahead.", 60),
        ("Test 2 – 40 km/h, pedestrian crossing from the right.", 40),
        ("Case 1 - 50 km/h: cyclist ahead brakes hard.", 50),
        ("I was doing 30-40 km/h when a bus pulled out.", 35),  # (a range still)
        ("I was doing 20 - 25 mph when a dog ran out.", 22.5 / 0.621371),  # (a range still)
    ],
    ids=["run-dash", "test-en-dash", "case-dash", "range", "range-spaced"],
)
def test_a_small_number_before_a_dash_and_a_speed_is_a_label_not_a_range(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, rel=1e-3)


# --- a speed the ego owns ("my 70") or is said with ("with me doing 50") ---------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("A motorbike flew past, much faster than my 70, and cut in front of me.", 70),
        ("A car overtook me going well over my 80 km/h and cut in.", 80),
        ("Some idiot came past at double our 50 and swerved in ahead of us.", 50),
        ("The truck kept pace with my 90 km/h for a while, then drifted into my lane.", 90),
        ("A van pulled out from the left with me doing about 50 km/h.", 50),
        ("A kid ran out between parked cars, with us going maybe 30, and I braked hard.", 30),
    ],
    ids=["than-my", "over-my-unit", "double-our", "pace-with-my", "with-me-doing", "with-us-going"],
)
def test_a_speed_the_ego_owns_or_is_said_with_is_the_egos(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was pulling away when my 4 kids shouted and a cyclist hit the door.", 4),  # (a count)
        ("A van overtook me doing 50 km/h and cut in.", 50),  # (the van's: it overtakes)
        ("A cyclist rode beside me at my window at 20 km/h.", 20),  # (no number after "my": the cyclist's)
        ("My 2 year old screamed as a cyclist swerved out at 15 km/h.", 2),  # (an age)
    ],
    ids=["my-count", "overtook-me-doing", "my-window", "my-age"],
)
def test_a_number_near_my_or_me_is_not_the_egos_speed(text, kph):
    assert _ego(text) != pytest.approx(kph * KPH)


# --- a speed limit said with a unit is the road's, not the ego's speed said beside it -------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was doing 50 in a 60 km/h zone when a van pulled out.", 50),
        ("I was only doing 25 mph in a 40 mph limit when a van pulled out.", 25 / 0.621371),
        ("Doing about 40 km/h on a 60 km/h road, a cyclist swerved out in front of me.", 40),
        ("In a 30 mph zone, I was doing 20 mph when a kid ran out.", 20 / 0.621371),
        ("I was doing 30 mph, well under the 40 mph speed limit, when a dog ran out.", 30 / 0.621371),
    ],
    ids=["zone-bare", "limit", "road", "zone-first", "speed-limit"],
)
def test_a_limit_is_not_the_speed_said_beside_it(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


def test_a_limit_said_alone_still_gives_the_egos_speed():
    assert _ego("In a 30 mph zone a kid ran out between parked cars in front of me.") == pytest.approx(30 * MPH)


# --- a limit said in another sentence than the speed someone goes at: the road's, not the ego's ------------------
@pytest.mark.parametrize(
    "text, mph",
    [
        # a campaign's headline, then the story
        ("WE WANT A 20MPH ZONE OUTSIDE THE SCHOOL\nLast week I was doing about 25 mph when a boy ran out.", 25),
        # a petition: the limit asked for, then the resident's drive
        (
            "Cut the speed limit on Mill Lane to 20 mph. A neighbour driving home at 30 mph was hit by a van "
            "turning right across her.",
            30,
        ),
        # a news item: the road's limit as an aside of its own
        ("The road has a 40 mph limit. The driver was travelling at 35 mph when a cyclist swerved in front.", 35),
        # a text message: the limit first, the speed after
        ("its a 30 zone. i was only going 25 mph n this kid on a scooter shot out in front of me", 25),
        # an Indian English complaint: "limit of" then the number, the speed in the next sentence
        (
            "Speed limit of 50 km/h is there on this road. I was going at 40 km/h only when one auto cut in front "
            "of me.",
            40 / 1.609344,
        ),
        # a police report: the limit after the story
        ("Vehicle 1 was travelling at 28 mph when a pedestrian stepped out. The limit there is 20 mph.", 28),
    ],
    ids=["headline", "petition", "news-aside", "text-message", "limit-of", "limit-after"],
)
def test_a_limit_in_another_sentence_is_not_the_speed_someone_goes_at(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH, rel=1e-3)


@pytest.mark.parametrize(
    "text, mph",
    [
        (
            "The estate is a 20 mph zone. A van travelling at 30 mph struck a boy who ran out from between parked "
            "cars.",
            30,
        ),
        (
            "Our road is a 20mph zone!! a delivery van doing 35 mph nearly took out a lad on a bike who came out "
            "from behind a parked car",
            35,
        ),
        ("Speed limit: 30 mph. The bus was doing 40 mph when a child ran out from behind a parked car.", 40),
    ],
    ids=["zone-then-report", "zone-then-post", "limit-key"],
)
def test_a_limit_gives_way_to_the_one_speed_of_the_scene(text, mph):
    r = read(text)
    pace = r.ego_speed_mps if r.ego_speed_mps is not None else r.scene_pace_mps
    assert pace == pytest.approx(mph * MPH, rel=1e-3)


@pytest.mark.parametrize(
    "text, mph",
    [
        # the limit alone: still the ego's pace
        ("It's a 30 mph road. A kid ran out between parked cars in front of me.", 30),
        # the other speed is a walker's pace: nothing of the traffic's, the limit stays the ego's pace
        ("The road has a 40 mph limit. A jogger at 6 mph crossed in front of me.", 40),
        # keeping to the limit is the ego's own speed, no limit's number
        ("I was keeping to the limit of 30 mph when a van came past me at 50 mph.", 30),
    ],
    ids=["alone", "walker-pace", "keeping-to"],
)
def test_a_limit_stays_the_egos_pace_where_nothing_else_gives_one(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH, rel=1e-3)


# --- a motorway's free-flowing speed under 80 said bare: mph, where km/h signs a motorway at 100 or more ----------
@pytest.mark.parametrize(
    "text, mph",
    [
        ("On the motorway doing 70, a hatchback undertook me and cut across my front.", 70),
        ("I was doing about 60 in lane two of the motorway when a lorry drifted over into me.", 60),
        ("Motorway, clear run, sat at 70 in the middle lane when a van cut straight across.", 70),
        ("Coming off the motorway at 65 when a car on the slip lane swerved in front of me.", 65),
        ("doing 56 on the motorway in the artic and some idiot dives in front of me", 56),
    ],
    ids=["undertook", "lane-two", "clear-run", "coming-off", "artic"],
)
def test_a_bare_free_motorway_speed_under_80_is_mph(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("Heavy traffic on the motorway, I'm doing 60 and a courier van darts into my lane.", 60),
        ("Motorway was jammed, we were crawling along at 50 when a truck pushed into our lane.", 50),
        ("On the motorway doing 100, a van cut in front of me.", 100),
        ("Doing 70 on the motorway in the ute when a truck drifted into my lane.", 70),
        ("Rush hour on the motorway, doing 60 when a car cut in.", 60),
        ("Doing 70 through the roadworks on the motorway when a van merged in front of me.", 70),
    ],
    ids=["heavy", "jammed", "hundred", "ute", "rush-hour", "roadworks"],
)
def test_a_bare_motorway_speed_in_slow_traffic_or_at_100_stays_kmh(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


# --- a bare number after a speed's head, and a bound said with "than" ------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Ego initial speed: 50. A cyclist ahead brakes hard.", 50),
        ("ego spd 60, lead car brakes hard in front.", 60),
        ("Ego velocity = 40; a pedestrian steps out from the right.", 40),
        ("Our speed was 30 when a pedestrian stepped out from the right.", 30),
        ("Test vehicle speed of approx 70, a car cuts in from the left lane.", 70),
    ],
    ids=["initial-speed-colon", "spd", "velocity-equals", "our-speed-was", "speed-of-approx"],
)
def test_a_bare_number_after_a_speed_head_is_a_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was doing no more than 50 when a pedestrian stepped out from the right.", 50),
        ("I was going less than 30 when a dog ran out in front of me.", 30),
        ("I was doing a bit over 40 when a van pulled out of a side road on the left.", 40),
        ("We were going not more than 20 when a cyclist swerved out in front of us.", 20),
        ("I was doing a little under 60 when a car cut in front of me.", 60),
    ],
    ids=["no-more-than", "less-than", "a-bit-over", "not-more-than", "a-little-under"],
)
def test_a_speed_bounded_with_than_or_a_bit_is_that_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("Speed camera 3 flashed as a van pulled out in front of me at 40 km/h.", 3),  # (a camera's number)
        ("More than 20 people saw a van pull out in front of me.", 20),  # (a count)
    ],
    ids=["speed-camera", "more-than-people"],
)
def test_a_number_after_a_speed_word_or_than_that_is_no_speed(text, kph):
    assert _ego(text) != pytest.approx(kph * KPH)


# --- a note that opens with a state of standing and no subject: the narrator stands still ----------------------
@pytest.mark.parametrize(
    "text",
    [
        "Stationary at the lights when a scooter rider went into my door.",
        "Sat at the red light when a cyclist rode into the back of me.",
        "Waiting at the junction to turn right when a motorbike hit my front.",
        "Queuing at the roundabout, a van rolled into the back of me.",
        "Parked up outside the shop with the engine running when a van reversed into me.",
        "Idling at the give way line when a bus clipped my wing.",
    ],
    ids=["stationary", "sat", "waiting", "queuing", "parked-up", "idling"],
)
def test_a_note_opening_with_a_state_of_standing_starts_the_ego_at_rest(text):
    assert _ego(text) == 0.0


@pytest.mark.parametrize(
    "text",
    [
        "Stationary traffic ahead on the motorway, a lorry behind me did not stop.",  # (the traffic's)
        "Parked car on the left, a child runs out from behind it.",  # (the car's)
        "Waiting pedestrians at the kerb; one steps out in front of the ego.",  # (theirs)
        "Stopped just short of a cyclist who swerved out in front of me.",  # (a stop made)
        "Sat at the lights, green goes, I pull off and a van runs the red from my right.",  # (then sets off)
    ],
    ids=["stationary-traffic", "parked-car", "waiting-pedestrians", "stopped-short", "then-pulls-off"],
)
def test_a_state_of_something_named_or_a_stop_made_is_no_start_at_rest(text):
    assert _ego(text) != 0.0


# --- a choice of two bare speeds, in figures or in words: its middle ----------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was doing 50 or 60 when a van pulled out from the left.", 55),
        ("Going 40 or 50 past the school, a kid ran out in front of me.", 45),
        ("I was doing about fifty or sixty when a van pulled out from the left.", 55),
        ("We were going at thirty to forty when a dog ran out in front of us.", 35),
    ],
    ids=["or-figures", "going-or", "or-words", "to-words"],
)
def test_a_choice_of_two_bare_speeds_is_their_middle(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("At 2 or 3 in the afternoon I was doing 50 when a van pulled out.", 50),  # (a time)
        ("I was doing 50, and 2 or 3 cyclists rode out in front of me.", 50),  # (a count after)
    ],
    ids=["clock", "count"],
)
def test_two_numbers_joined_by_or_that_are_no_speeds_stay(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


# --- the cruise control's setting, and a number sat on said in words: the ego's speed ---------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Cruise set to 100, a truck drifted into my lane from the left.", 100),
        ("I had the cruise on 90 when a car cut in front of me.", 90),
        ("Cruise control at 80 km/h and a lorry pulled out to overtake right in front of me.", 80),
        ("Had cruise control set at 110 when a ute swerved into my lane.", 110),
        ("Sat on a hundred in the left lane when a truck drifted into my lane.", 100),
        ("We were sitting on seventy in lane two when a van cut across.", 70),
    ],
    ids=["cruise-set-to", "cruise-on", "cruise-control-at-unit", "cruise-control-set-at", "sat-on-words", "sitting-on"],
)
def test_the_cruise_setting_or_a_number_sat_on_is_the_egos_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text",
    [
        "A van on cruise control at 90 km/h came up behind me and rear-ended me.",  # (the van's)
        "We sat on the bus for 20 minutes when a car hit it.",  # (a time)
    ],
    ids=["vans-cruise", "sat-on-bus"],
)
def test_a_cruise_setting_of_another_or_a_time_is_not_the_egos_speed(text):
    assert _ego(text) not in (pytest.approx(90 / 3.6), pytest.approx(20 / 3.6))


# --- a bare speed after a verb of going and the manner of going ("going slowly 20", "going straight with 40") ----
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Late last night on a one-way street I was going slowly 20. A courier came the wrong way in my lane.", 20),
        ("We were driving carefully 30, then a boy ran out from behind the bus.", 30),
        ("I was travelling steadily 50 on the ring road and a truck pulled out of a side road.", 50),
        ("my light was green, i was going straight with 40, a scooter ran the red from the left and i hit him", 40),
        ("I was going very slowly 15, a cyclist came off the footpath right in front of me.", 15),
        ("I was driving with about 60 when a van pulled out of a side road on my left.", 60),
        ("Was driving normally 40 when a kid on a bike came out of a driveway.", 40),
    ],
    ids=["slowly", "carefully", "steadily", "straight-with", "very-slowly", "with-about", "subjectless"],
)
def test_a_bare_speed_after_a_verb_of_going_and_its_manner_is_the_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, abs=0.05)


@pytest.mark.parametrize(
    "text",
    [
        "I was going slowly 2 cars behind the bus when a boy ran out in front of me.",
        "We were driving with 3 kids in the back when a van pulled out of a side road.",
        "I was going with 2 friends to the match when a cyclist came off the pavement.",
        "I was driving carefully. 20 minutes later a van pulled out of a side road.",
    ],
    ids=["cars-behind", "kids-in-the-back", "friends", "minutes-later"],
)
def test_a_number_after_a_verb_of_going_that_counts_or_times_is_no_speed(text):
    assert _ego(text) is None


# --- how far over the limit a speed was ("8 mph over the limit", "over the limit by 15 mph"): no one's speed -----
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was doing 38 mph, 8 mph over the limit, when a cyclist pulled out in front of me.", 38 * MPH * 3.6),
        ("The camera had me 12 km/h above the limit, and I was at 62 km/h when a kid ran out in front of me.", 62),
        ("Speed at trigger 61 km/h, 11 km/h over the posted limit. A scooter came out between parked cars.", 61),
        ("A kid ran out in front of me. I was 10 mph over the speed limit, I admit.", None),
        ("I was over the limit by 15 mph when a cyclist swerved into my lane.", None),
        ("Telematics: a scooter came out between parked cars on the left, speed 8 mph over limit at trigger.", None),
    ],
    ids=["aside", "above", "over-posted", "over-speed-limit", "over-by", "note"],
)
def test_how_far_over_the_limit_a_speed_was_is_no_speed(text, kph):
    got = _ego(text)
    assert (got is None) if kph is None else got == pytest.approx(kph * KPH, abs=0.05)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was doing 38 mph over the bridge when a cyclist pulled out in front of me.", 38 * MPH * 3.6),
        ("I was at 60 km/h above the harbour when a van pulled out of a side road.", 60),
    ],
    ids=["over-the-bridge", "above-the-harbour"],
)
def test_a_speed_over_a_place_is_still_the_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, abs=0.05)


# --- every way a speed's unit is written: per-hour slashes, SI exponents, other languages' hour ---------------
@pytest.mark.parametrize(
    "unit, kph",
    [
        ("mp/h", 20 * MPH * 3.6),
        ("m/ph", 20 * MPH * 3.6),
        ("mi/hr", 20 * MPH * 3.6),
        ("mi per hr", 20 * MPH * 3.6),
        ("miles/hr", 20 * MPH * 3.6),
        ("km p/h", 20),
        ("km/ph", 20),
        ("km h-1", 20),
        ("km h^-1", 20),
        ("km·h⁻¹", 20),
        ("km.h-1", 20),
        ("km hr-1", 20),
        ("km/u", 20),
        ("km/t", 20),
        ("km/jam", 20),
        ("km per hr", 20),
        ("m s-1", 72),
        ("m s^-1", 72),
        ("ms-1", 72),
        ("m.s-1", 72),
        ("m·s⁻¹", 72),
        ("metres/sec", 72),
        ("m/sec", 72),
    ],
)
def test_every_written_form_of_a_speed_unit_is_read(unit, kph):
    text = f"I was driving at 20 {unit} when a kid ran out from behind a parked van in front of me."
    assert _ego(text) == pytest.approx(kph * KPH, abs=0.05)


def test_an_acceleration_in_exponents_is_no_speed():
    text = "I was driving at 50 km/h and braked at 6 m s^-2 when a kid ran out in front of me."
    assert _ego(text) == pytest.approx(50 * KPH, abs=0.05)


# --- a speed said of what did not happen (a condition, what would or should have been): no one's speed ------------
@pytest.mark.parametrize(
    "text, mph",
    [
        # an expert's report: the condition inverted
        ("I was doing 40 mph when a boy ran out. Had I been doing 20 mph, I would have stopped in time.", 40),
        # a witness statement: "if ... had been"
        ("The car was doing 35 mph when the girl stepped out. If it had been doing 20 mph she would be fine.", 35),
        # a judgment: what a careful driver would have done
        ("The van was travelling at 26 mph when the child ran out. A careful driver would have slowed to 15 mph.", 26),
        # a campaign post: what the driver should have been doing
        ("The bus was doing 30 mph when a girl ran out in front of it. It should have been doing 20 mph there.", 30),
        # a coroner's note: "ought to have"
        ("The lorry was going at 40 mph when the cyclist fell. It ought to have slowed to 25 mph at the bend.", 40),
        # the norm said first, then the story
        ("Near a school any driver should have slowed to 15 mph. The van was doing 26 mph when a boy ran out.", 26),
    ],
    ids=["had-inverted", "if-had", "would-have", "should-have-been", "ought-to-have", "norm-first"],
)
def test_a_speed_of_what_did_not_happen_is_no_ones(text, mph):
    r = read(text)
    pace = r.ego_speed_mps if r.ego_speed_mps is not None else r.scene_pace_mps
    assert pace == pytest.approx(mph * MPH, rel=1e-3)


@pytest.mark.parametrize(
    "text, mph",
    [
        # an estimate said with a modal: someone's real speed, guessed
        ("A van overtook me, he must have been doing 60 mph. I was doing 40 mph.", 40),
        ("I would have been doing about 30 mph when a kid ran out in front of me.", 30),
        # a plain past perfect: what was
        ("I had been doing 50 mph for a mile when a cyclist pulled out in front of me.", 50),
        # "had" as a verb at the start
        ("Had a fright coming home at about 20 mph, a scooter came out in front of me.", 20),
    ],
    ids=["must-have-been", "would-have-been-doing", "past-perfect", "had-a-fright"],
)
def test_a_guessed_or_past_speed_is_still_read(text, mph):
    assert _ego(text) == pytest.approx(mph * MPH, rel=1e-3)


# --- "km" said for km/h, a change of speed drawn as an arrow, the speed left when the subject vehicle strikes -----
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was going slow maybe 20 km. A lady crossed the road in front of me.", 20),
        ("I go behind a cyclist at 15 km because I cannot pass.", 15),
        ("I was doing 60 km on the ring road when a van cut in.", 60),
        ("A boy on an e-scooter cut in front of my car at full speed, maybe 25 km. I was at 30 km.", 30),
    ],
    ids=["going-maybe", "at", "doing-on-a-road", "the-ego-after-the-rider"],
)
def test_km_after_a_word_of_a_speed_held_is_km_h(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


@pytest.mark.parametrize(
    "text",
    [
        "I was at 15 km from the city when a van cut in front of me.",
        "We were doing 20 km a day. A van cut in front of me.",
        "I was going 5 km further when a van cut in front of me.",
    ],
    ids=["from-a-place", "a-day", "further"],
)
def test_km_of_how_far_is_no_speed(text):
    assert _ego(text) is None


@pytest.mark.parametrize(
    "text, unit, speed",
    [
        ("SV 68 mph -> 49 mph. HGV changes lane into SV lane.", MPH, 68),
        ("Ego speed 50 -> 30 km/h. A cyclist crosses from the right.", KPH, 50),
        ("Ego 50 km/h \u2192 30 km/h while a cyclist crosses from the right.", KPH, 50),
        ("SV slows 68 -> 49 mi/h as a lorry changes lane into SV lane.", MPH, 68),
        ("Ego slows 50 -> 30 km per hour while a cyclist crosses from the right.", KPH, 50),
    ],
    ids=["unit-on-both", "unit-after", "unicode-arrow", "unit-spelt-other", "unit-in-words"],
)
def test_an_arrow_between_two_speeds_starts_from_the_first(text, unit, speed):
    assert _ego(text) == pytest.approx(speed * unit)


@pytest.mark.parametrize(
    "text",
    [
        "SV on straight rural 2-lane at 41 mph (GPS). Ped walks out from the L shoulder. Subject driver reacts "
        "~0.8 s before impact and brakes; SV strikes ped at ~25 mph, right front.",
        "The subject vehicle, traveling at 41 mph, approached a ped. The subject driver braked late and the SV "
        "struck the ped at 25 mph.",
        "SV traveling at 41 mph. After moving away from the curb, SV brakes and strikes ped at 25 mph.",
    ],
    ids=["subject-driver", "the-subject-driver", "a-place-before-the-sv"],
)
def test_the_speed_the_subject_vehicle_strikes_at_after_its_driver_brakes_is_no_start_speed(text):
    assert _ego(text) == pytest.approx(41 * MPH)


@pytest.mark.parametrize(
    "text",
    [
        "Ego changes lane 1 -> 2 at 80 km/h; a truck brakes ahead.",
        "Ego at 80 km/h, lane 2 -> 3, a truck brakes ahead.",
        "The road narrows 3 -> 2 lanes and a truck brakes in front of me at 80 km/h.",
    ],
    ids=["lane-change", "lane-after-the-speed", "lanes-narrowing"],
)
def test_an_arrow_between_numbers_without_a_speed_unit_is_no_change_of_speed_nor_a_time(text):
    """("lane 1 -> 2": a lane, not "from 1 to 2", which reads as a clock time)."""
    reading = read(text)
    assert reading.ego_speed_mps == pytest.approx(80 * KPH)
    assert reading.time is None


def test_chained_arrows_start_from_the_first_value_and_a_limits_arrow_is_no_speed():
    assert _ego("Ego 50 km/h -> 30 km/h -> 0, a child runs out in front of me.") == pytest.approx(50 * KPH)
    (lead,) = read("Lead car 80 -> 60 -> 40 km/h in front of the ego.").actors
    assert lead.speed_mps == pytest.approx(80 * KPH)
    text = "Speed limit 50 -> 30 km/h zone; a child runs out in front of me at 30 km/h."
    assert _ego(text) == pytest.approx(30 * KPH)


@pytest.mark.parametrize(
    "text",
    [
        "The crash happened at 50 km on the A1; a truck braked in front of me.",
        "At 50 km the road narrows and a truck merges into my lane.",
        "The van broke down at 12 km and I braked behind it.",
        "A car braked in front of me at 25 km into the trip.",
        "Speed of 30 km is the limit here; a van cut in front of me.",
        "I was at 15 km and 20 m from the junction when a van cut in.",
    ],
    ids=["happened-at", "sentence-opening", "broke-down-at", "into-the-trip", "the-limit", "and-metres"],
)
def test_km_of_a_place_on_the_road_is_no_speed(text):
    assert _ego(text) is None


@pytest.mark.parametrize(
    "text, kph",
    [
        ("POV ahead of SV brakes hard; SV strikes POV at 25 mph.", 25 * MPH / KPH),
        ("The lead car in front of the VUT brakes; VUT hits it at 30 km/h.", 30),
    ],
    ids=["pov-ahead-of-sv", "lead-in-front-of-vut"],
)
def test_a_strike_after_anothers_braking_is_the_subject_vehicles_speed(text, kph):
    """The braking is the lead's ("the POV ahead of the SV brakes"): the SV's speed at the strike is all
    that is said of it, so it stays the ego's."""
    assert _ego(text) == pytest.approx(kph * KPH)
