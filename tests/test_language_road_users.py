"""Who is there: which road users a description names, which one is the ego, and their types. Each
construction is pinned by wordings of our own (none from a corpus), read through the whole reader."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read

MPH = 0.44704


def kinds(text: str) -> list[str]:
    return [a.kind for a in read(text).actors]


def ego_kph(text: str) -> float | None:
    r = read(text)
    return None if r.ego_speed_mps is None else r.ego_speed_mps * 3.6


# --- makes and models name vehicles of their type ---------------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("A grey Skoda pulled out of a side road on the right in front of me while I was doing 30 mph.", "car"),
        ("Some lad in a Sprinter was tailgating me on the motorway at 70 mph.", "van"),
        ("Ego at 50 km/h, a Vauxhall Astra ahead brakes hard.", "car"),
        ("A Mercedes Sprinter van overtook me on the dual carriageway at 60 mph.", "van"),
        ("I'm doing 50 mph on the bypass, Volvo sits right on my tail for miles then overtakes.", "car"),
        ("Ego at 40 km/h; a Scania ahead in our lane brakes hard.", "truck"),
    ],
    ids=["make", "van-model", "make-and-model", "make-model-noun", "bare-make", "truck-make"],
)
def test_a_make_or_model_names_a_vehicle_of_its_type(text, kind):
    assert kinds(text) == [kind]


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 25 mph on the high street when a silver Mokka pulled out from a side road on the left.",
        "A woman in a red Zafira cut across in front of me from the right as I drove at 30 km/h.",
        "On the motorway at 60 mph, a black Touareg sat on my bumper for miles and then overtook me.",
        "I was doing 40 mph when a black Focus in the next lane cut in front of me.",
        "Some kid in a red Mini came the wrong way down the street at me, I was at 20 mph.",
        "I was at 30 km/h and an Uber pulled out of a side road on the right in front of me.",
    ],
    ids=["subject", "person-in", "on-my-bumper", "english-word-model", "person-in-english-word", "an-uber"],
)
def test_a_capitalised_name_in_a_vehicles_place_is_a_car(text):
    assert kinds(text) == ["car"]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was doing 30 mph past the Odeon when a cyclist pulled out from the right in front of me.", ["bicycle"]),
        ("Near the Crown a jogger crossed from the left in front of me at 20 mph.", ["pedestrian"]),
        ("Outside the Red Lion a cyclist swung out from the left in front of me at 25 mph.", ["bicycle"]),
        ("I was at 30 mph along the Strand when a Golf pulled out from the left in front of me.", ["car"]),
        ("It was a Tuesday, I was at 30 mph and a jogger crossed from the left in front of me.", ["pedestrian"]),
        ("A woman with a Spaniel on a lead crossed from the right ahead of me, I was at 20 mph.", ["pedestrian"]),
    ],
    ids=["past-the-place", "near-the-place", "two-word-name", "along-the-place", "a-day", "a-dog"],
)
def test_a_capitalised_place_is_no_vehicle(text, expected):
    assert kinds(text) == expected


# --- a person on or in a vehicle is one road user of that vehicle --------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("Kid on a motorbike came the wrong way down the slip road towards me, I was doing 40 mph.", "car"),
        ("Woman on a moped pulled out of a side road on the left right in front of me, I was at 30 km/h.", "car"),
        ("Some guy in a van reversed out of a driveway on the right into my path while I did 20 mph.", "van"),
        ("A bloke in a lorry drifted into my lane from the left on the motorway, me at 60 mph.", "truck"),
    ],
    ids=["bare-on-motorbike", "bare-on-moped", "guy-in-van", "bloke-in-lorry"],
)
def test_a_person_on_or_in_a_vehicle_is_that_vehicle(text, kind):
    assert kinds(text) == [kind]


# --- a second road user after a collision, named as new, is a road user ------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A taxi pulled out of a side road on the left and hit my front wing at 20 mph; then a cyclist "
            "that was behind me ran into my back bumper.",
            ["car", "bicycle"],
        ),
        (
            "I hit a deer that jumped out from the right at 60 km/h, and a moment later a lorry following "
            "me struck my rear.",
            ["pedestrian", "truck"],
        ),
        (
            "A van clipped my mirror as it overtook me at 40 mph. Then a motorbike behind me went straight "
            "into my boot.",
            ["van", "car"],
        ),
    ],
    ids=["cyclist-behind", "lorry-following", "motorbike-behind"],
)
def test_a_new_road_user_after_a_collision_is_a_road_user(text, expected):
    assert kinds(text) == expected


# --- a vehicle in apposition after a placed road user is that road user ----------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("The van behind me, a white Sprinter, flashed its lights and overtook me at 50 mph.", "van"),
        ("The lorry in the next lane, a big Scania, drifted into my lane as I drove at 60 mph.", "truck"),
        ("The car ahead of us, a silver Octavia, braked sharply; we were at 40 km/h.", "car"),
    ],
    ids=["behind-me", "in-the-next-lane", "ahead-of-us"],
)
def test_a_vehicle_in_apposition_after_a_placed_road_user_is_that_one(text, kind):
    assert kinds(text) == [kind]


# --- the ego's own vehicle, named by its make or kind, is the ego ---------------------------------------
@pytest.mark.parametrize(
    "text, kind, speed_kph",
    [
        (
            "My client was driving her Volvo at 30 mph when a cyclist swung out from the left in front of her.",
            "bicycle",
            30 * MPH * 3.6,
        ),
        (
            "The insured's Corsa was travelling at 25 mph when a pedestrian stepped out from the right ahead of it.",
            "pedestrian",
            25 * MPH * 3.6,
        ),
        (
            "A cyclist cut across from the left in front of the insured's Passat. The Passat was doing about 30 mph.",
            "bicycle",
            30 * MPH * 3.6,
        ),
    ],
    ids=["driving-her", "possessive", "named-again"],
)
def test_the_egos_own_vehicle_is_the_ego(text, kind, speed_kph):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps * 3.6 - speed_kph) < 0.5


@pytest.mark.parametrize(
    "text",
    [
        "V1, a 2017 Skoda Octavia, was travelling at 30 mph when a cyclist crossed from the left ahead of V1.",
        "The ego, a 2021 Ford Transit van, drives at 40 km/h; a jogger steps out from the right in front of it.",
        "Unit 1, a 2015 Toyota, was proceeding at 20 mph. A pedestrian walked out from the nearside kerb ahead.",
    ],
    ids=["year-make-model", "year-make-model-noun", "year-make"],
)
def test_a_vehicle_with_its_year_in_apposition_to_the_ego_is_the_ego(text):
    assert len(read(text).actors) == 1


# --- someone who only sees, watches or films is a witness, no road user --------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "I was doing 30 mph when a van pulled out of a side road on the left in front of me. "
            "A man at the bus stop watched it all.",
            ["van"],
        ),
        (
            "A cyclist swerved into my lane from the right as I passed at 40 km/h; "
            "a woman on the pavement filmed it on her phone.",
            ["bicycle"],
        ),
        (
            "There was an old chap on the corner who saw everything. I was at 25 mph and a lorry "
            "cut across from the right in front of me.",
            ["truck"],
        ),
        (
            "A taxi ahead of me braked hard while I was doing 50 km/h, and two kids waiting "
            "for the bus noticed the whole thing.",
            ["car"],
        ),
    ],
    ids=["watched", "filmed", "saw-relative", "noticed"],
)
def test_a_witness_is_no_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "A man who saw me coming stepped out anyway from the left in front of me, I was doing 20 mph.",
        "A boy staring at his phone walked out into the road from the right ahead of me at 30 km/h.",
        "A woman watched the traffic and then ran across the road from the left in front of me, 25 mph.",
    ],
    ids=["saw-then-stepped", "staring-walked", "watched-then-ran"],
)
def test_someone_who_looks_and_moves_is_a_road_user(text):
    assert kinds(text) == ["pedestrian"]


# --- a narrator on foot: the vehicle the other road user comes in front of is the ego -------------------
@pytest.mark.parametrize(
    "text, kind, speed_kph",
    [
        (
            "I was waiting at the lights on foot when I saw a cyclist shoot across from the right in front "
            "of a blue estate doing about 30 km/h. The estate braked hard and stopped.",
            "bicycle",
            30,
        ),
        (
            "Walking my dog along the pavement, I watched a kid on a bike ride out of a driveway on the "
            "left right into the path of a red hatchback. The hatchback was doing maybe 25 mph and swerved.",
            "bicycle",
            25 * MPH * 3.6,
        ),
        (
            "I was sitting outside the cafe and saw a jogger step off the kerb on the right in front of a "
            "white van going at 40 km/h. The driver stopped just in time.",
            "pedestrian",
            40,
        ),
    ],
    ids=["waiting-estate", "walking-hatchback", "sitting-van"],
)
def test_a_narrator_on_foot_is_no_road_user_and_the_vehicle_in_the_conflict_is_the_ego(text, kind, speed_kph):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps * 3.6 - speed_kph) < 0.5


def test_a_narrator_who_drives_stays_the_ego():
    text = "I was driving at 40 km/h when I saw a jogger step out from the right in front of a parked van."
    r = read(text)
    assert abs(r.ego_speed_mps * 3.6 - 40) < 0.5
    assert "pedestrian" in [a.kind for a in r.actors]


# --- an animal and its rider are one road user ------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A woman on a horse was trotting along the verge on my left as I came round the bend at 30 mph.",
        "A girl riding a pony came out of a gate on the right in front of me while I was doing 20 km/h.",
        "A rider and her horse were walking along the left side of the road ahead of me at 40 km/h.",
        "A man leading a horse crossed the road from the left ahead of me, I was doing 25 mph.",
        "An old man and his horse were walking along the left verge ahead of me, I was at 30 km/h.",
    ],
    ids=["on-a-horse", "riding-a-pony", "rider-and-horse", "leading", "man-and-his-horse"],
)
def test_an_animal_and_its_rider_are_one_road_user(text):
    assert kinds(text) == ["pedestrian"]


# --- the ego said to be a vehicle is that vehicle, no second road user ------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("The ego is a 7.5 t lorry turning left at 15 km/h; a cyclist comes up on its left from behind.", "bicycle"),
        ("Host vehicle is a minibus doing 30 km/h when a jogger steps out from the right ahead of it.", "pedestrian"),
        ("The subject vehicle was a white van at 40 km/h; a motorbike overtook it on the right.", "car"),
    ],
    ids=["lorry", "minibus", "van"],
)
def test_the_ego_said_to_be_a_vehicle_is_no_second_road_user(text, kind):
    assert kinds(text) == [kind]


# --- a narrator on foot told over two sentences -----------------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        (
            "I was waiting outside the library at lunchtime. I saw a red Kia coming down the hill at about "
            "30 km/h. A girl ran out into the road from the left and the driver of the Kia stopped.",
            "pedestrian",
        ),
        (
            "We were walking back from the match. We watched a grey hatchback come along the high street, "
            "and a cyclist swung out from the right in front of it; the hatchback braked hard.",
            "bicycle",
        ),
        (
            "I was sat on the bench by the crossing. I noticed a taxi approaching at 25 mph when a jogger "
            "stepped off the kerb on the right, and the taxi swerved.",
            "pedestrian",
        ),
    ],
    ids=["waiting-kia", "walking-hatchback", "sat-taxi"],
)
def test_a_narrator_on_foot_over_two_sentences_is_no_road_user(text, kind):
    assert kinds(text) == [kind]


# --- a report that names no ego: the one motor vehicle that strikes a walker or rider is the ego ------
@pytest.mark.parametrize(
    "text, kind",
    [
        (
            "A teenager on a bike was hurt on Tuesday when he was hit by a car on Mill Road. Police said the car "
            "was travelling at about 30 mph when the boy rode out from a side street on the left.",
            "bicycle",
        ),
        (
            "An elderly man was struck by a van on the high street. The van, going at around 20 mph, hit him "
            "as he crossed from the right.",
            "pedestrian",
        ),
        (
            "A woman on an e-scooter was knocked down by a car at the junction. The car was doing about "
            "25 mph when she came across from the left.",
            "e-scooter",
        ),
    ],
    ids=["bike-car", "man-van", "scooter-car"],
)
def test_the_one_motor_vehicle_in_a_report_with_no_ego_is_the_ego(text, kind):
    assert kinds(text) == [kind]


# --- a driver said in brackets after a vehicle is that vehicle's ------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A car coming the other way drifts into our lane (driver on the phone), we are at 70 km/h.",
        "A lorry ahead of us brakes hard (the driver fell asleep) while we drive at 80 km/h.",
        "A van pulls out from the left (driver not looking) right in front of us at 30 km/h.",
    ],
    ids=["on-the-phone", "fell-asleep", "not-looking"],
)
def test_a_driver_in_brackets_is_the_vehicles(text):
    assert len(read(text).actors) == 1


@pytest.mark.parametrize(
    "text, kind, ego_mph",
    [
        (
            "Reporting vehicle: school minibus, travelling at 20 mph. A lad on a bike swerved out from the left "
            "into the path of the minibus.",
            "bicycle",
            20,
        ),
        (
            "Reporting vehicle: council refuse truck, going at 10 mph. A cyclist came up the inside of the truck.",
            "bicycle",
            10,
        ),
        (
            "Reporting vehicle: airport shuttle coach, proceeding at 25 mph. A jogger stepped out from the right "
            "in front of the coach.",
            "pedestrian",
            25,
        ),
    ],
    ids=["minibus", "refuse-truck", "shuttle-coach"],
)
def test_the_vehicle_a_report_names_as_its_own_is_the_ego(text, kind, ego_mph):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps - ego_mph * MPH) < 0.1


# --- a test engineer's names for the vehicle under test name the ego -------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("The SUT drives at 50 km/h; a pedestrian crosses from the left 20 m ahead of it.", "pedestrian"),
        ("System under test at 70 km/h in the right lane, a truck ahead brakes hard.", "truck"),
        ("Host car cruises in lane 2 with 90 km/h, a lorry in lane 1 moves over in front of it.", "truck"),
    ],
    ids=["sut", "system-under-test", "host-car"],
)
def test_names_for_the_vehicle_under_test_are_the_ego(text, kind):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.ego_speed_mps is not None
