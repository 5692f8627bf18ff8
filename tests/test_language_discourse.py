"""Who is who in a description: the ego named in the third person, one road user named twice, people
and animals that are only scenery. Each construction is pinned by wordings of our own (none of them
from a corpus), read through the whole reader: the road users it finds and the ego's speed."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read

MPH = 0.44704


def kinds(text: str) -> list[str]:
    return [a.kind for a in read(text).actors]


# --- a person on a vehicle is one rider of that vehicle ------------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("At dusk some lad on a Voi scooter shot out from the right in front of me.", "e-scooter"),
        ("A student on one of those hire bikes cut across my lane from the left.", "bicycle"),
        ("A pizza courier on an electric scooter crossed from the right just ahead of me.", "e-scooter"),
        ("An old woman riding a bicycle wobbled across the road from the left in front of us.", "bicycle"),
    ],
    ids=["brand", "one-of-those", "two-word-person", "riding"],
)
def test_a_person_on_a_vehicle_is_one_rider_of_it(text, kind):
    assert kinds(text) == [kind]


# --- a companion of a walker is no road user of its own, unless it acts -------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A woman with a poodle stood at the kerb on my right and waited for me to pass.", ["pedestrian"]),
        ("An old man with his spaniel was walking along the left verge towards us.", ["pedestrian"]),
        (
            "A boy with his dog was walking on the pavement, and the dog suddenly ran across in front of me.",
            ["pedestrian", "pedestrian"],
        ),
    ],
    ids=["waits", "walks", "the-animal-acts"],
)
def test_a_walkers_companion_is_a_road_user_only_when_it_acts(text, expected):
    assert kinds(text) == expected


# --- the ego's own vehicle and what is in it are not road users ------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "We were in a borrowed van, a battered old Ford, doing 30 mph when a cyclist swung out from the left ahead.",
        "I was in a hire car at about 40 km/h and a jogger stepped out from the right in front of me.",
        "Van full of tools and a dog, I was doing 50 km/h on the ring road when a cyclist cut across from the left.",
    ],
    ids=["borrowed-van", "hire-car", "full-of"],
)
def test_the_narrators_vehicle_and_its_load_are_the_ego(text):
    assert kinds(text) in (["bicycle"], ["pedestrian"])


# --- a motor vehicle set against a vulnerable road user, with no ego named, is the ego ------------------
@pytest.mark.parametrize(
    "text, kind, speed_kph",
    [
        (
            "Base, collision van versus cyclist at the lights. Cyclist went across the van's front, van at 30 km/h.",
            "bicycle",
            30,
        ),
        (
            "Update: pedestrian vs car on the high street. Pedestrian stepped out from the left, car doing 25 mph.",
            "pedestrian",
            25 * MPH * 3.6,
        ),
        (
            "Caller reports jogger hit. Vehicle was going straight at about 40 km/h, jogger crossing from the right.",
            "pedestrian",
            40,
        ),
    ],
    ids=["versus", "vs", "bare-vehicle"],
)
def test_the_motor_vehicle_against_a_vulnerable_road_user_is_the_ego(text, kind, speed_kph):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps * 3.6 - speed_kph) < 0.5


# --- a radio call sign is the speaker's vehicle --------------------------------------------------------
@pytest.mark.parametrize(
    "text, speed_kph",
    [
        ("Unit 4 to base, a cyclist just swerved out from the left in front of me, I'm at 40, all fine.", 40),
        ("Car 12 to control, a pedestrian ran across from the right, I was doing 30 km/h, no injuries.", 30),
        ("Van 2 calling control: I'm at 60 km/h and a lorry in the left lane has just cut into my lane.", 60),
    ],
    ids=["unit", "car", "van"],
)
def test_a_call_sign_is_the_ego(text, speed_kph):
    r = read(text)
    assert len(r.actors) == 1
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps * 3.6 - speed_kph) < 0.5


# --- a road user named again is the same one -----------------------------------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist rides towards the ego in its lane, speed of cyclist 15 km/h, ego 40 km/h.", ["bicycle"]),
        ("A bus pulls out of a stop ahead of the ego; velocity of bus 10 km/h; ego 50 km/h.", ["truck"]),
        ("The front vehicle, a coach, drives 20 m ahead of the ego. The front vehicle then brakes hard.", ["truck"]),
        ("The vehicle ahead, a tanker, cruises at 80 km/h. Later the vehicle slows to 40 km/h.", ["truck"]),
    ],
    ids=["speed-of-bare", "velocity-of-bare", "definite-generic", "definite-generic-2"],
)
def test_a_road_user_named_again_is_the_same_one(text, expected):
    assert kinds(text) == expected


def test_a_new_label_or_an_indefinite_article_is_a_new_road_user():
    text = "A cyclist crosses from the left in front of the ego, then another cyclist crosses from the right."
    assert kinds(text) == ["bicycle", "bicycle"]


# --- a road user said in apposition in brackets ----------------------------------------------------
@pytest.mark.parametrize(
    "text, kind, speed_kph",
    [
        (
            "A sports car (the intruder) in the right lane, 10 m ahead of the ego, cuts into the ego lane. "
            "Ego speed 90 km/h, intruder speed 110 km/h.",
            "car",
            110,
        ),
        (
            "A delivery van (the obstacle) stands 40 m ahead of the ego in its lane. Ego speed 50 km/h, "
            "obstacle speed 0 km/h.",
            "van",
            0,
        ),
    ],
    ids=["intruder", "obstacle"],
)
def test_a_name_given_in_brackets_names_that_road_user(text, kind, speed_kph):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.actors[0].speed_mps is not None and abs(r.actors[0].speed_mps * 3.6 - speed_kph) < 0.5


# --- a misspelt road-user word still names its road user --------------------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("e-scoter comes at me the wrong way in my lane, im doing 30 mph", "e-scooter"),
        ("pedestrain crosses from the rigth in front of ego", "pedestrian"),
        ("a motorbik pulls out from a side road on the left in front of me", "car"),
    ],
    ids=["hyphenated", "plain", "vehicle"],
)
def test_a_misspelt_road_user_is_found(text, kind):
    assert kinds(text) == [kind]


# --- the narrator's own people are no road users --------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Drove my child to nursery this morning, about 30 mph. A cyclist swung out from the left in front of me.",
        "Our dog was barking in the back, 40 km/h, and a cyclist crossed from the right just ahead of us.",
        "Taking my toddler to the park, doing 20 mph, a cyclist came out from the kerb on my left.",
    ],
    ids=["child", "our-dog", "toddler"],
)
def test_the_narrators_own_people_are_no_road_users(text):
    assert kinds(text) == ["bicycle"]


# --- a second name of the ego is the ego -----------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Vehicle 1 (V1), a Skoda Octavia, was travelling at 30 mph when a cyclist crossed from the left ahead of V1.",
        "The ego, a small hatchback, drives at 40 km/h; a pedestrian steps out from the right in front of it.",
        "V1, a blue Vauxhall, was proceeding at 20 mph. A pedestrian walked out from the nearside kerb ahead of V1.",
        "The subject vehicle, an estate car, travels at 50 km/h; a cyclist crosses from the left in front of it.",
    ],
    ids=["code-and-bracket", "ego", "code", "subject-vehicle"],
)
def test_a_second_name_of_the_ego_is_the_ego(text):
    assert len(read(text).actors) == 1


# --- passengers ride inside the ego ----------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Heading home with the twins squabbling in the back seat, 30 mph, when a cyclist cut across from the left.",
        "I had the dog in the boot, about 40 km/h, and a cyclist came out from the right just ahead of me.",
        "Grandma chatting on the passenger seat, 30 mph, when a cyclist rode out from the kerb on my left.",
        "Two kids arguing in the back seat, 20 mph, and a cyclist came out from the right in front of me.",
        "Kids singing in the back, 25 mph, a cyclist swung out from the kerb on my left in front of me.",
    ],
    ids=["back-seat", "boot", "passenger-seat", "two-kids", "back"],
)
def test_people_inside_the_ego_are_no_road_users(text):
    assert kinds(text) == ["bicycle"]


# --- a bare noun after a preposition names again the one of its type ----------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("Cyclist rides along the kerb ahead, 15 km/h. Ego stays behind cyclist, no overtake.", ["bicycle"]),
        ("Actor: a van ahead at 40 km/h. Ego: 50 km/h, closes up to van and brakes.", ["van"]),
        ("Walker on the left verge ahead. Ego passes walker wide at 30 km/h.", ["pedestrian"]),
    ],
    ids=["behind", "to", "passes"],
)
def test_a_bare_noun_after_a_preposition_is_the_one_named_before(text, expected):
    assert kinds(text) == expected


# --- the other party of a statement, named by its code twice, then in apposition --------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        (
            "Vehicle 1 (V1) was travelling at 30 mph. Vehicle 2 (V2), a Mercedes Sprinter van, pulled out from "
            "a side road on the left into the path of V1.",
            "van",
        ),
        (
            "Unit 1 was doing 40 km/h. Unit 2 (U2), a Scania lorry, emerged from the junction on the right ahead "
            "of Unit 1.",
            "truck",
        ),
        (
            "V1 was proceeding at 20 mph. Vehicle 3 (V3), a Honda motorcycle, came out of a side road on the "
            "right in front of V1.",
            "car",
        ),
    ],
    ids=["van", "lorry", "motorcycle"],
)
def test_the_other_party_named_by_code_and_apposition_is_one_road_user(text, kind):
    assert kinds(text) == [kind]


# --- who arrives after the collision is no road user of the scenario ---------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist shot out from the left and I hit him at 20 mph. He was fine by the time the ambulance came.",
        "We were doing 30 mph when a pedestrian stepped out from the right and we struck her; the bus driver "
        "stopped to help.",
        "A cyclist came across from the right at the lights and we collided at 25 km/h. The police car pulled up "
        "behind us ten minutes later.",
    ],
    ids=["van-came", "bus-driver", "police-car"],
)
def test_who_arrives_after_the_collision_is_no_road_user(text):
    assert len(read(text).actors) == 1


# --- a log line's clock does not hide the road user after it ----------------------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("09:10 ego drives off at 40 km/h\n09:11 van ahead at 30 m brakes hard", ["van"]),
        ("16:05 ego on the ring road, 60 km/h\n16:06 cyclist crosses from the left", ["bicycle"]),
        ("07:45 ego at 30 mph\n07:46 pedestrian steps out from the right\n07:46 ego brakes", ["pedestrian"]),
    ],
    ids=["van", "cyclist", "pedestrian"],
)
def test_a_clock_at_the_start_of_a_line_hides_no_road_user(text, expected):
    assert kinds(text) == expected


# --- lettered and numbered labels name referents --------------------------------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "ego: 50 km/h\nactor A: van cuts in ahead of ego because of actor B\nactor B: truck in the left lane, "
            "steady speed",
            ["van", "truck"],
        ),
        (
            "ego at 40 km/h\nparticipant 1: cyclist crosses from the right\nparticipant 2: oncoming car keeps going",
            ["bicycle", "car"],
        ),
        (
            "ego: 30 mph\nobject C: pedestrian steps out from the left\nobject D: parked van, does nothing",
            ["pedestrian", "van"],
        ),
        (
            "ego: 40 mph\nactor A: motorcycle overtakes ego on the bend, cuts back in because of actor B\n"
            "actor B: oncoming car, keeps going",
            ["car", "car"],
        ),
    ],
    ids=["actor-letters", "participant-numbers", "object-letters", "two-of-one-type"],
)
def test_labels_name_referents(text, expected):
    assert sorted(kinds(text)) == sorted(expected)


# --- a road user named as a field of a list is the subject of what follows ----------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("cyclist: comes out from the kerb on the left, then rides ahead at 15 km/h. ego: 30 km/h.", "bicycle"),
        ("pedestrian: steps out from the right 20 m ahead. ego: 40 km/h. time: night.", "pedestrian"),
        ("van: pulls out of a side road on the left. ego: 50 km/h. weather: rain.", "van"),
    ],
    ids=["cyclist", "pedestrian", "van"],
)
def test_a_road_user_as_a_field_name_is_the_subject(text, kind):
    assert kinds(text) == [kind]


# --- a name no dictionary knows, as what the ego follows, is a vehicle -----------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "I was following a red Corsa at 30 mph through the village when it braked hard for no reason.",
        "We were tailing a Qashqai at about 40 km/h and it suddenly stopped dead in front of us.",
        "Following a grey Octavia on the ring road at 50 km/h, it slammed on its brakes.",
    ],
    ids=["corsa", "qashqai", "octavia"],
)
def test_a_name_the_ego_follows_is_a_vehicle(text):
    assert kinds(text) == ["car"]


# --- the ego named as a car, then the car said bare, is the ego ------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "ego car drive 50 km/h, one cyclist come from right and cross, car is brake hard",
        "my car go 40 km/h on small road, pedestrian walk out from left side, car not stop in time",
        "ego vehicle at 30 km/h, e-scooter cross from the right, vehicle is hit him",
    ],
    ids=["brake", "not-stop", "hit"],
)
def test_the_ego_named_as_a_car_and_then_bare_is_the_ego(text):
    assert len(read(text).actors) == 1


# --- a speed said of the ego and another road user together is each one's --------------------------------
@pytest.mark.parametrize(
    "text, ego_kph, other_kph",
    [
        ("The ego and the lead car both travel at 60 km/h; the lead car brakes hard.", 60, 60),
        ("A van and the ego are both doing 70 km/h, 20 m apart; the van brakes.", 70, 70),
        ("The truck ahead and I were both going 50 mph when it braked suddenly.", 50 * MPH * 3.6, 50 * MPH * 3.6),
    ],
    ids=["ego-first", "ego-second", "narrator"],
)
def test_a_speed_said_of_the_ego_and_another_is_each_ones(text, ego_kph, other_kph):
    r = read(text)
    assert len(r.actors) == 1
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps * 3.6 - ego_kph) < 0.5
    assert r.actors[0].speed_mps is not None and abs(r.actors[0].speed_mps * 3.6 - other_kph) < 0.5


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A van nearly hit me at 30 mph. Then the cyclist behind it swerved across from the left.", ["van", "bicycle"]),
        ("We collided at 20 mph. The van had pulled out from the left without looking.", ["van"]),
        ("I hit the brakes when the cyclist ahead swerved across from the left.", ["bicycle"]),
    ],
    ids=["near-miss", "told-after", "hit-the-brakes"],
)
def test_no_aftermath_without_a_collision_with_someone_named_before(text, expected):
    assert kinds(text) == expected


# --- vehicle labels: the first (or number one, or A) is the ego unless another is marked so ----------------
@pytest.mark.parametrize(
    "text, kind, ego_kph",
    [
        (
            "Vehicle A was travelling at 40 mph when Vehicle B pulled out of a side road on the left in front of "
            "Vehicle A.",
            "car",
            40 * MPH * 3.6,
        ),
        ("Car B (ego) drives at 50 km/h; Car A cuts in from the right lane 10 m ahead of car B.", "car", 50),
        ("Truck B pulled out in front of Car A. Car A was doing 40 km/h.", "truck", 40),
        (
            "Car 1 was doing 30 mph. Van 2 pulled out from a side road on the right ahead of Car 1.",
            "van",
            30 * MPH * 3.6,
        ),
    ],
    ids=["a-first", "b-marked", "a-second", "numbers"],
)
def test_the_first_vehicle_label_is_the_ego_unless_another_is_marked(text, kind, ego_kph):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps * 3.6 - ego_kph) < 0.5


# --- someone pushing or carrying a bike is a walker, one road user ----------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A man pushing a bike crossed from the left in front of the ego at 30 km/h.",
        "A girl wheeling her e-scooter stepped out from the right ahead of me; I was at 20 mph.",
        "A commuter carrying a folding bicycle walked out from the left in front of us at 40 km/h.",
    ],
    ids=["pushing", "wheeling", "carrying"],
)
def test_someone_pushing_a_bike_is_one_walker(text):
    assert kinds(text) == ["pedestrian"]


# --- the driver or rider of a vehicle is that vehicle -----------------------------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("The driver of the lorry ahead braked hard; we were at 50 km/h.", ["truck"]),
        ("The rider of a moped came out of a side road on the left ahead of me.", ["car"]),
        ("The van's driver pulled out from the kerb on the left just in front of the ego.", ["van"]),
    ],
    ids=["driver-of", "rider-of", "possessive"],
)
def test_the_driver_of_a_vehicle_is_that_vehicle(text, expected):
    assert kinds(text) == expected


def test_who_is_no_road_user_is_listed_as_not_used():
    r = read("Drove my child to nursery this morning, about 30 mph. A cyclist swung out from the left in front of me.")
    assert "child" in r.ignored and "my" not in r.ignored
    r = read("A man with his dog stood at the kerb on my right and waited for me to pass.")
    assert "dog" in r.ignored


# --- a relative clause after the ego is said of the ego ----------------------------------------------------
@pytest.mark.parametrize(
    "text, ego_kph",
    [
        ("A truck pulled out in front of the ego, which was doing 40 km/h.", 40),
        ("A cyclist swerved into the path of the test vehicle, which was travelling at 30 km/h.", 30),
        ("The van cut in ahead of V1, which was proceeding at 50 mph.", 50 * MPH * 3.6),
    ],
    ids=["doing", "travelling", "proceeding"],
)
def test_a_relative_clause_after_the_ego_is_the_egos(text, ego_kph):
    r = read(text)
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps * 3.6 - ego_kph) < 0.5
    assert all(a.speed_mps is None for a in r.actors)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist swung out from the left and I clipped his back wheel at 20 mph. The man from the kiosk came out.",
        "A scooter rider came off the kerb on the right and we hit her front wheel at 15 mph. The lady from the "
        "cafe ran over.",
        "A cyclist cut across from the left and I struck his rear wheel at 25 km/h; the guy from the garage walked "
        "over to help.",
    ],
    ids=["clipped-his", "hit-her", "struck-his"],
)
def test_who_comes_after_hitting_someones_wheel_is_no_road_user(text):
    assert len(read(text).actors) == 1


def test_someone_placed_by_the_ego_after_the_collision_is_still_a_road_user():
    text = "A van pulled out from the left, I hit my brakes and we collided at 20 mph. The cyclist behind me swerved."
    assert kinds(text) == ["van", "bicycle"]


# --- a log line's road user said again after its clock is the one named before -----------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("10:02 ego at 50 km/h\n10:03 bus ahead at 30 m slows down\n10:04 bus stops at the kerb", ["truck"]),
        (
            "18:20 ego sets off at 40 km/h, van following\n18:21 cyclist ahead at 20 m\n18:22 cyclist turns left",
            ["van", "bicycle"],
        ),
        ("06:15 ego on the bypass, 80 km/h\n06:16 lorry ahead slows\n06:17 lorry brakes hard", ["truck"]),
    ],
    ids=["bus", "cyclist", "lorry"],
)
def test_a_road_user_said_again_after_a_clock_is_the_same(text, expected):
    assert sorted(kinds(text)) == sorted(expected)


# --- an abbreviation defined in brackets stands for its term all through ---------------------------------
@pytest.mark.parametrize(
    "text, ego_kph",
    [
        ("The insured vehicle (IV) was travelling at 40 mph. A cyclist swerved across the path of the IV.", 64.4),
        ("Our test car (TC) drives at 30 km/h. A pedestrian crosses from the left 10 m ahead of TC.", 30),
        ("The host vehicle (HV) approaches at 50 km/h; a van pulls out 20 m in front of the HV.", 50),
    ],
    ids=["iv", "tc", "hv"],
)
def test_an_abbreviation_defined_in_brackets_stands_for_its_term(text, ego_kph):
    r = read(text)
    assert len(r.actors) == 1 and "iv" not in r.ignored and "tc" not in r.ignored and "hv" not in r.ignored
    assert r.ego_speed_mps is not None and abs(r.ego_speed_mps * 3.6 - ego_kph) < 0.5


# --- a person placed first and then said to be on or in a vehicle is one rider of it ------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("A woman ahead of us on a bicycle brakes suddenly while we drive at 30 km/h.", "bicycle"),
        ("The bloke next to me in a white van cuts into my lane, I'm at 50 km/h.", "van"),
        ("Some lad behind us on an e-scooter overtakes on the left, ego 20 km/h.", "e-scooter"),
        ("A man alongside the ego in a lorry drifts into its lane, ego 70 km/h.", "truck"),
    ],
    ids=["ahead-of-us-on", "next-to-me-in", "behind-us-on", "alongside-the-ego-in"],
)
def test_a_person_placed_then_on_a_vehicle_is_one_rider_of_it(text, kind):
    assert [a.kind for a in read(text).actors] == [kind]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A pedestrian ahead of us in the road crosses from the left, ego 30 km/h.", ["pedestrian"]),
        ("A man ahead of us on the pavement steps out from the left, ego 30 km/h.", ["pedestrian"]),
    ],
    ids=["in-the-road", "on-the-pavement"],
)
def test_a_person_placed_then_in_no_vehicle_stays_a_person(text, expected):
    assert [a.kind for a in read(text).actors] == expected


# --- an apposition that goes on with a participle is the same road user -------------------------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("The lead vehicle, a coach heading for the airport, brakes sharply in front of us, ego 30 km/h.", "truck"),
        ("A vehicle on our right, a grey pickup doing about 40 mph, drifts into our lane.", "van"),
        ("The truck ahead, an old lorry loaded with gravel, stops suddenly, ego 50 km/h.", "truck"),
    ],
    ids=["heading-for", "doing-a-speed", "loaded-with"],
)
def test_an_apposition_with_a_participle_is_the_same_road_user(text, kind):
    assert [a.kind for a in read(text).actors] == [kind]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A car, a van turning left, and a cyclist all cross in front of us, ego 30 km/h.", 3),
        ("The car ahead brakes, a cyclist coming the other way swerves, ego 30 km/h.", 2),
        ("A car overtakes us, a van following it closely, then both cut in, ego 60 km/h.", 2),
    ],
    ids=["a-list", "another-clause", "an-absolute-clause"],
)
def test_a_list_or_a_new_clause_after_a_comma_is_another_road_user(text, expected):
    assert len(read(text).actors) == expected


# --- a capitalised name after a preposition of place, or owned by a name, is a place, no vehicle -------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("Coming down the Sea to Sky at 80 km/h, a lorry comes the other way in our lane.", ["truck"]),
        ("Driving up the Kingsway at 30 mph, a cyclist ahead of us brakes hard.", ["bicycle"]),
        ("Outside St Mary's Infants on the High Street a child runs out from the left, ego 20 mph.", ["pedestrian"]),
        ("Past Hill Farm's Lodge on the right a deer jumps out, ego 50 km/h.", ["pedestrian"]),
    ],
    ids=["down-the", "up-the", "outside-a-name's", "past-a-name's"],
)
def test_a_name_in_a_place_is_no_vehicle(text, expected):
    assert [a.kind for a in read(text).actors] == expected


@pytest.mark.parametrize(
    "text",
    [
        "My neighbour Dave's Mokka pulled out in front of me, I was at 30 mph.",
        "Going up the hill at 30 mph, a silver Mokka pulled out in front of me.",
    ],
    ids=["a-person's-car", "after-a-place"],
)
def test_a_name_in_a_vehicles_place_is_still_a_car(text):
    assert [a.kind for a in read(text).actors] == ["car"]


# --- a bare plural that a singular instance follows is what happens in general, not another road user --
@pytest.mark.parametrize(
    "text, kind",
    [
        (
            "Joggers often cross here without looking; simulate a jogger crossing from the right, ego 30 km/h.",
            "pedestrian",
        ),
        (
            "We see cyclists running the red light every morning. Build one where a cyclist runs the red from the "
            "left, ego 40 km/h.",
            "bicycle",
        ),
        (
            "Teenagers on e-bikes keep jumping the kerb on Park Lane. Simulate a teenager on an e-bike riding off "
            "the kerb from the left, ego 25 mph.",
            "bicycle",
        ),
    ],
    ids=["joggers-a-jogger", "cyclists-a-cyclist", "riders-a-rider"],
)
def test_a_generic_plural_then_one_of_them_is_one_road_user(text, kind):
    assert [a.kind for a in read(text).actors] == [kind]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Two joggers cross from the left, then a jogger crosses from the right, ego 30 km/h.", 3),
        ("Cyclists ahead of us ride two abreast, ego 30 km/h.", 1),
        ("Vans often stop dead here. The van ahead of us stops, then a van behind us honks, ego 30 km/h.", 2),
    ],
    ids=["counted", "no-instance", "named-again-first"],
)
def test_a_counted_or_only_plural_stays_a_road_user(text, expected):
    assert len(read(text).actors) >= expected


def test_plural_parked_vehicles_a_walker_comes_out_from_stay_in_the_scene():
    kinds = [
        a.kind
        for a in read(
            "A child runs out from between parked cars on the left, and a car coming the "
            "other way swerves, ego 30 km/h."
        ).actors
    ]
    assert "pedestrian" in kinds and kinds.count("car") == 2


# --- "X, followed by Y, does ...": two road users who both do it, Y after X ----------------------------
@pytest.mark.parametrize(
    "text, kinds, behaviour",
    [
        (
            "A jogger, followed by a cyclist, crosses from the left, ego 30 km/h.",
            ["pedestrian", "bicycle"],
            "cross_in_front",
        ),
        (
            "A woman, closely followed by a child, steps out from the right, ego 25 mph.",
            ["pedestrian", "pedestrian"],
            "cross_in_front",
        ),
        ("A van chased by a motorbike runs the red light from the left, ego 40 km/h.", ["van", "car"], "run_red_light"),
    ],
    ids=["followed-by", "closely-followed-by", "chased-by-no-commas"],
)
def test_a_road_user_followed_by_another_is_two_who_do_the_same(text, kinds, behaviour):
    actors = read(text).actors
    assert [a.kind for a in actors] == kinds
    assert all(behaviour in [b[0] for b in a.behaviours] for a in actors)


def test_a_passive_clause_of_following_stays_its_own():
    actors = read("The cyclist was followed by a van for a while; the van overtakes us, ego 50 km/h.").actors
    assert [a.kind for a in actors] == ["bicycle", "van"]
    assert "overtake" not in [b[0] for b in actors[0].behaviours]


# --- a vehicle's type said in brackets after it is that road user's type, no second one ---------------
@pytest.mark.parametrize(
    "text, kind",
    [
        ("Vehicle B (white van) brakes hard 30 m ahead of the ego, ego 50 km/h.", "van"),
        ("The target (a small hatchback) stops suddenly ahead, ego 40 km/h.", "car"),
        ("The other vehicle (a lorry) pulls out from the left, ego 40 km/h.", "truck"),
    ],
    ids=["label-gloss", "same-type-gloss", "general-noun-gloss"],
)
def test_a_type_in_brackets_glosses_the_road_user_before_it(text, kind):
    assert [a.kind for a in read(text).actors] == [kind]


def test_a_second_road_user_in_brackets_stays_a_second_one():
    kinds = [a.kind for a in read("A car (and a cyclist behind it) turns left across us, ego 40 km/h.").actors]
    assert kinds == ["car", "bicycle"]
