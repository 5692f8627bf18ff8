"""What kind of road user a noun phrase names, and setting words that name no road user: a hyphenated
compound by its head noun, an abbreviation by the term whose initials it spells, street lighting as
lighting (not traffic lights)."""

from __future__ import annotations

import pytest
from reading_of import kinds as _kinds

from vei_scenario.language.reader import _tokens as _TOKENS
from vei_scenario.language.reader import read


# --- a hyphenated compound is the road user its head noun names ---------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("A tow-truck pulls out from the left in front of us while we drive at 30 km/h.", "truck"),
        ("An e-bike comes out of a driveway on the right and crosses in front of us at 25 km/h.", "bicycle"),
        ("Our car at 40 km/h; a camper-van ahead brakes hard.", "van"),
        ("A double-decker pulls away from the stop on our left at 20 km/h, ego 30 km/h.", "truck"),
    ],
    ids=["tow-truck", "e-bike", "camper-van", "double-decker"],
)
def test_a_hyphenated_compound_is_read_by_its_head_noun(text, kind):
    assert _kinds(text) == [kind]


def test_a_compound_opened_by_a_preposition_names_no_road_user():
    assert _kinds("In-car footage: a cyclist ahead of us brakes hard while we drive at 30 km/h.") == ["bicycle"]


# --- an abbreviation is the term whose initials it spells -------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("Test with a bicycle target dummy: ego 40 km/h, the BTD crosses from the right.", "bicycle"),
        ("Setup with an e-scooter dummy, ego at 30 km/h; ESD rides across from the left.", "e-scooter"),
        ("Powered two-wheeler (PTW) ahead at 40 km/h; the PTW brakes hard, ego 50 km/h.", "car"),
    ],
    ids=["btd", "esd-undefined", "ptw-bracketed"],
)
def test_an_abbreviation_is_the_term_whose_initials_it_spells(text, kind):
    assert _kinds(text) == [kind]


# --- street lighting is lighting, not a signalised junction -------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "At night under orange street lights a jogger ahead of us crosses from the left, we drive at 40 km/h.",
        "The streetlights are out; a cyclist ahead of us brakes hard while we drive at 30 km/h.",
        "Dark road with street lamps, a deer jumps out from the right, ego 60 km/h.",
    ],
    ids=["street-lights", "streetlights", "street-lamps"],
)
def test_street_lighting_does_not_make_a_junction(text):
    assert read(text).map_kind in (None, "straight")


# --- the writer's own vehicle or driver is the ego ------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist crosses from the left and our driver stamps on the brakes at 40 km/h.",
        "A jogger steps out from the right; my old van brakes hard, doing 30 mph.",
        "At 50 km/h our lorry follows a bus that suddenly stops ahead.",
    ],
    ids=["our-driver", "my-old-van", "our-lorry"],
)
def test_a_first_person_possessive_before_a_vehicle_names_the_ego(text):
    assert len(read(text).actors) == 1


def test_a_first_person_possessive_before_a_person_is_no_vehicle():
    r = read("I drove my kid to school at 20 mph when a cyclist ahead of us braked hard.")
    assert [a.kind for a in r.actors] == ["bicycle"]


# --- a closed compound is the road user its head names ------------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("A firetruck pulls out from the left in front of us at 30 km/h.", "truck"),
        ("A schoolbus ahead of us stops suddenly, we drive at 40 km/h.", "truck"),
        ("A minicab overtakes us and cuts in, ego at 50 km/h.", "car"),
    ],
    ids=["firetruck", "schoolbus", "minicab"],
)
def test_a_closed_compound_is_read_by_its_head_noun(text, kind):
    assert _kinds(text) == [kind]


@pytest.mark.parametrize("word", ["vicar", "syllabus", "caravan", "oscar"])
def test_a_word_that_only_ends_like_a_vehicle_is_left_whole(word):
    # (what is before the vehicle noun is no word of its own, or too short to be one)
    assert _TOKENS(f"the {word} waits")[1] == word


@pytest.mark.parametrize("noun", ["people carrier", "MPV"])
def test_a_people_carrier_is_a_van(noun):
    assert _kinds(f"A {noun} pulls out from the right in front of us at 30 km/h.") == ["van"]


# --- lights named by a modifier are a vehicle's or a street's, not a junction's signals -------------------
@pytest.mark.parametrize(
    "text",
    [
        "An ambulance with flashing lights overtakes us at 80 km/h while we drive at 50 km/h.",
        "A police car with its blue lights on passes us at 90 km/h, ego 60 km/h.",
        "In the dark I see only the tail lights of a truck ahead, which brakes hard; ego 70 km/h.",
    ],
    ids=["flashing", "blue", "tail"],
)
def test_lights_after_a_modifier_make_no_junction(text):
    assert read(text).map_kind in (None, "straight")


@pytest.mark.parametrize("lights", ["the lights", "the traffic lights", "red lights", "temporary lights"])
def test_signal_lights_still_make_a_junction(lights):
    assert read(f"A car ahead of us stops at {lights}, we drive at 30 km/h.").map_kind == "crossroad"


# --- a motor two-wheeler or quad named by "bike" is a car, as FORMAT has motorbikes ---------------------------
@pytest.mark.parametrize("noun", ["motor bike", "quad bike", "dirt bike", "4x4", "fire engine"])
def test_motor_vehicles_named_by_their_trade_words(noun):
    kind = "truck" if noun == "fire engine" else "car"
    assert _kinds(f"A {noun} ahead of us brakes hard, ego at 50 km/h.") == [kind]


@pytest.mark.parametrize("noun, kind", [("tow-trucks", "truck"), ("firetrucks", "truck"), ("e-bikes", "bicycle")])
def test_a_plural_compound_is_read_by_its_head_noun(noun, kind):
    assert set(_kinds(f"Two {noun} ahead of us brake hard, ego at 50 km/h.")) == {kind}


# --- Euro NCAP target abbreviations name their target's type, with or without a test code -------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("Ego at 30 km/h on a straight road; an EPTa steps out from the right 20 m ahead.", "pedestrian"),
        ("The EPTc runs across from the left kerb, VUT 20 km/h.", "pedestrian"),
        ("VUT at 40 km/h, the EBTa rides across from the left at 15 km/h.", "bicycle"),
        ("An EMT ahead of the VUT brakes hard; VUT 50 km/h.", "car"),
    ],
    ids=["epta", "eptc", "ebta", "emt"],
)
def test_a_euro_ncap_target_abbreviation_names_its_target_type(text, kind):
    assert _kinds(text) == [kind]


def test_the_target_abbreviation_said_again_is_the_same_target():
    assert _kinds("Ego 25 km/h. EPTa on the zebra from the far side at 5 km/h. Ego stops for the EPTa.") == [
        "pedestrian"
    ]


# --- trade words and models of heavy, light and three-wheeled vehicles -------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("A road train coming the other way drifts into our lane, ego 90 km/h.", "truck"),
        ("A B-double ahead of us brakes hard while we drive at 80 km/h.", "truck"),
        ("A Hilux pulls out of a farm track on the left in front of us, we drive at 60 km/h.", "van"),
        ("A tuk-tuk ahead of the ego stops suddenly, ego 30 km/h.", "car"),
        ("An auto rickshaw cuts in from the right lane, ego at 40 km/h.", "car"),
    ],
    ids=["road-train", "b-double", "pickup-model", "tuk-tuk", "auto-rickshaw"],
)
def test_heavy_light_and_three_wheeled_vehicles_by_their_trade_words(text, kind):
    assert _kinds(text) == [kind]


def test_a_pickup_model_after_a_person_in_it_is_a_van():
    assert _kinds("Some guy in a Tacoma runs the red light from the left, ego 40 km/h.") == ["van"]


@pytest.mark.parametrize(
    "text",
    [
        # "standing" naming the stand-up kind of scooter (Indian, British, American, a test spec, a text)
        "One fellow on those standing type electric scooters came from wrong side towards my car at 40 kmph.",
        "At 20 mph a lad on a standing e-scooter shot across the road in front of me from the left.",
        "A boy on a rental e-scooter, the standing kind, swerved in front of me from the left. I was at 15 kmph.",
        "Target: adult dummy on a standing electric scooter crossing from the left at 15 km/h; VUT 40 km/h.",
        "some dude on one of those standing scooters cut across in front of me from the left, i was doing 25 mph",
    ],
)
def test_standing_before_a_scooter_names_its_kind_not_a_state(text):
    actor = read(text).actors[0]
    assert actor.kind == "e-scooter" and actor.behaviours[0][0] not in ("stop", "keep_going")


@pytest.mark.parametrize(
    "text",
    [
        # near misses: someone standing, or a scooter standing, is still
        "At 30 mph there was a scooter rider standing still in my lane and I had to stop.",
        "There was an e-scooter standing in my lane, no rider, and I stopped at 20 km/h.",
    ],
)
def test_standing_said_of_a_road_user_is_its_state(text):
    assert read(text).actors[0].behaviours[0][0] == "stop"
