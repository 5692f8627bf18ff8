"""How many road users a description names: the road users other than the ego that act on the road,
not the people a story mentions who are no road users of the scene, and each road user once however
often or however differently it is named. Each construction is pinned by wordings of our own (none of
them from a corpus), read through the whole reader, with near misses that look alike but must read
otherwise."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def kinds(text: str) -> list[str]:
    return sorted(a.kind for a in read(text).actors)


# --- a person's noun before a road user's noun modifies it: one road user, of the head noun's type ----
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A schoolboy cyclist rode across from the right just ahead of me.", ["bicycle"]),
        ("A woman cyclist swung out from the left kerb in front of me.", ["bicycle"]),
        ("An adult pedestrian dummy walks across from the right at 5 km/h in front of the ego.", ["pedestrian"]),
        ("A girl pedestrian ran out from the left in front of me at dusk.", ["pedestrian"]),
        ("A scooter kid rode straight across from the right in front of me.", ["e-scooter"]),
        ("The van target brakes hard 20 m ahead of the ego.", ["van"]),
        ("The tanker driver ahead of me braked hard at 50 mph.", ["truck"]),
    ],
    ids=["schoolboy-cyclist", "woman-cyclist", "adult-dummy", "girl-pedestrian", "scooter-kid", "van-target", "driver"],
)
def test_a_person_noun_before_a_road_user_noun_is_one_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A child and a cyclist crossed from the left in front of me.", ["bicycle", "pedestrian"]),
        ("As I passed the jogger, a cyclist came out from the left in front of me.", ["bicycle", "pedestrian"]),
    ],
    ids=["joined-by-and", "separate-clauses"],
)
def test_two_road_user_nouns_apart_stay_two(text, expected):
    assert kinds(text) == expected


# --- a person set in apposition to a vehicle is whoever drives it -------------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("The hatchback's driver, a woman in her twenties, braked hard right in front of me.", ["car"]),
        ("The motorcyclist, a man in his fifties, overtook me and cut in sharply.", ["car"]),
        ("The driver of the pickup, an elderly man, pulled out from the right in front of me.", ["van"]),
    ],
    ids=["driver-possessive", "rider-noun", "driver-of"],
)
def test_a_person_in_apposition_to_a_vehicle_is_its_driver(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("The taxi stopped, a woman got out and walked across in front of me.", ["car", "pedestrian"]),
        ("I passed the bus, a man stepped out from behind it and crossed in front of me.", ["pedestrian", "truck"]),
    ],
    ids=["got-out", "stepped-out"],
)
def test_a_person_opening_a_clause_after_a_vehicle_is_someone_else(text, expected):
    assert kinds(text) == expected


# --- the people whose own vehicle acts are that vehicle's occupants, no walkers -----------------------
@pytest.mark.parametrize(
    "text",
    [
        "Two men were injured when their van ran into the back of a queuing lorry on the A40.",
        "Four teenagers were taken to hospital after their hatchback hit the back of a bus on the B4060.",
        "A young couple escaped unhurt when their camper van swerved into the path of a lorry on the A9.",
    ],
    ids=["their-van", "their-hatchback", "couple"],
)
def test_people_whose_own_vehicle_acts_are_its_occupants(text):
    assert "pedestrian" not in kinds(text)


@pytest.mark.parametrize(
    "text",
    [
        "A woman got out of her car and walked across the road in front of me.",
        "A boy was hurt when a van hit him as he ran across from the left.",
    ],
    ids=["out-of-her-car", "no-vehicle-of-theirs"],
)
def test_a_person_who_leaves_a_vehicle_or_has_none_stays_a_walker(text):
    assert "pedestrian" in kinds(text)


# --- someone who only tells what happened is a witness, no road user ----------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A cyclist shot across from the left in front of me. A man at the bus stop said the cyclist never looked.",
            ["bicycle"],
        ),
        ("A woman claims the bus pulled out from the stop on the left right in front of me at 20 mph.", ["truck"]),
        ("The lorry came through the red light from the right, a pedestrian later confirmed.", ["truck"]),
    ],
    ids=["said", "claims", "confirmed"],
)
def test_someone_who_only_tells_is_no_road_user(text, expected):
    assert kinds(text) == expected


def test_someone_who_tells_and_then_acts_is_a_road_user():
    assert kinds("A pedestrian said something to me and then stepped out in front of the car.") == ["pedestrian"]


# --- road users in general, asked or warned to do something, are none of the scene ---------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A cyclist came through the red light from the left. Campaigners want drivers to slow down here.",
            ["bicycle"],
        ),
        ("A van pulled out of the side road on the right. The council has asked cyclists to use the path.", ["van"]),
        (
            "A jogger ran across from the left in front of me; the police warn motorists to take care there.",
            ["pedestrian"],
        ),
    ],
    ids=["want", "asked", "warn"],
)
def test_road_users_asked_to_do_something_are_no_road_users_of_the_scene(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Two cyclists tried to squeeze past me on the left and cut in ahead.", ["bicycle", "bicycle"]),
        ("A cyclist to my left swerved into my lane just ahead of me.", ["bicycle"]),
    ],
    ids=["counted", "a-place"],
)
def test_counted_plurals_and_places_before_to_stay(text, expected):
    assert kinds(text) == expected


# --- a heading's bare road user is the one the text goes on to introduce ----------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "Cyclist swerve on rural bend\nSetup: ego at 60 km/h. A cyclist ahead swerves into the ego's lane.",
            ["bicycle"],
        ),
        (
            "Regression - lorry merge at motorway junction\n* Ego 100 km/h in lane 1\n"
            "* A lorry on the slip road merges right in front of the ego",
            ["truck"],
        ),
        (
            "TICKET-88: pedestrian dash at night\nA pedestrian runs across from the right 20 m ahead of the ego.",
            ["pedestrian"],
        ),
    ],
    ids=["setup", "bullets", "ticket"],
)
def test_a_headings_road_user_is_the_one_introduced_after_it(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist swerves into my lane. A van overtakes me and cuts in.", ["bicycle", "van"]),
        ("Cyclist pulls out from the left. A cyclist comes the other way in my lane.", ["bicycle", "bicycle"]),
    ],
    ids=["first-sentence-with-article", "first-sentence-with-verb"],
)
def test_a_first_sentence_that_is_no_heading_keeps_its_road_users(text, expected):
    assert kinds(text) == expected


# --- "two of our scooters": a number of a plural is so many road users --------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("Two of our e-scooters came out of the side road on the left without stopping.", ["e-scooter"] * 2),
        ("Three of the cyclists in the group swung out into my lane ahead of me.", ["bicycle"] * 3),
        ("Both of the joggers ran across the road from the left in front of me.", ["pedestrian"] * 2),
    ],
    ids=["two-of-our", "three-of-the", "both-of-the"],
)
def test_a_number_of_a_plural_is_so_many_road_users(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("One of the cyclists in the group swung out into my lane ahead of me.", ["bicycle"]),
        ("One of our vans pulled out of the depot on the left right in front of me.", ["van"]),
        ("Two of my kids were in the back when a cyclist swung out from the left in front of me.", ["bicycle"]),
    ],
    ids=["one-of-the", "one-of-our-fleet", "the-narrators-people"],
)
def test_one_of_a_plural_is_one_road_user_and_the_narrators_people_none(text, expected):
    assert kinds(text) == expected


# --- animals on the road are walkers ---------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cow wandered across the road from the left in front of me.",
        "Cattle were crossing the lane from the left ahead of me.",
        "There was a kangaroo hopping across from the right about 20 m ahead.",
    ],
    ids=["cow", "cattle", "kangaroo"],
)
def test_an_animal_on_the_road_is_a_pedestrian(text):
    assert kinds(text) == ["pedestrian"]


def test_animals_named_as_a_place_are_no_road_users():
    assert kinds("I drove past a field of cows when a cyclist pulled out from the left in front of me.") == ["bicycle"]


# --- "a person in electric scooter": a rider, in English written as a second language -------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("One man in electric scooter come from left side and cross in front of my car.", ["e-scooter"]),
        ("A boy in bicycle suddenly go across the road from the right in front of me.", ["bicycle"]),
        ("The woman in e-scooter is coming from sidewalk of right side and cross before me.", ["e-scooter"]),
    ],
    ids=["electric-scooter", "bicycle", "e-scooter"],
)
def test_a_person_in_a_bare_rideable_noun_rides_it(text, expected):
    assert kinds(text) == expected


def test_a_person_in_a_motor_vehicle_or_a_lane_is_not_riding_a_bike():
    assert "bicycle" not in kinds("A man in the bike lane waved as a van pulled out from the left in front of me.")
    assert kinds("A man in a hire van pulled out from the left in front of me.") == ["van"]


# --- a hyphenated plural ("e-scooters", "pick-ups") is a plural, as any other noun's -------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "E-scooters often cut across here from the left; simulate an e-scooter crossing from the left in "
            "front of the ego.",
            ["e-scooter"],
        ),
        (
            "E-scooters regularly ride on the pavement on this street; please model an e-scooter rider coming off "
            "the kerb on the right in front of the ego.",
            ["e-scooter"],
        ),
        (
            "Residents keep complaining about e-scooters on our street. Yesterday an e-scooter rider shot out "
            "from the right in front of me.",
            ["e-scooter"],
        ),
        (
            "Pick-ups often pull out of the farm tracks here; simulate a pick-up turning out of a track on the "
            "right ahead of the ego.",
            ["van"],
        ),
    ],
    ids=["cut-across", "ride-on-the-pavement", "complaining-about", "pick-ups"],
)
def test_a_hyphenated_plural_in_general_is_not_the_road_user_that_acts(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Two e-scooters rode side by side along the kerb ahead of me.", ["e-scooter", "e-scooter"]),
        ("Three e-bikes came towards me in my lane.", ["bicycle", "bicycle", "bicycle"]),
    ],
    ids=["two-e-scooters", "three-e-bikes"],
)
def test_counted_hyphenated_plurals_are_so_many_road_users(text, expected):
    assert kinds(text) == expected


# --- a number written in figures counts a plural as a number in words does ---------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("2 joggers running along the left edge of the road ahead, I slow down and pass them.", ["pedestrian"] * 2),
        ("ego 40 km/h, 3 cyclists in a line on the right kerb ahead, ego passes them", ["bicycle"] * 3),
        ("At dusk 2 vans came towards me in my lane, one after the other.", ["van"] * 2),
        ("2 e-scooter riders swerve out from the left kerb in front of the ego.", ["e-scooter"] * 2),
    ],
    ids=["2-joggers", "3-cyclists", "2-vans", "2-e-scooter-riders"],
)
def test_a_number_in_figures_before_a_plural_is_so_many_road_users(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("At 2 pm a jogger ran across from the left in front of me.", ["pedestrian"]),
        ("A cyclist rode across from the right, about 3 car lengths in front of me.", ["bicycle"]),
        ("Car 2 cuts in from the right lane 15 m ahead of car 1.", ["car"]),
    ],
    ids=["time-of-day", "car-lengths", "vehicle-labels"],
)
def test_a_number_before_a_vehicle_noun_that_is_no_count_stays_no_count(text, expected):
    assert kinds(text) == expected


# --- who rides, said in brackets after a rider's noun, is that rider: the vehicle's type stays ---------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("An e-scooter rider (adult) swerves out from the left kerb in front of the ego.", ["e-scooter"]),
        ("ego 40 km/h; motorbike rider (teenager) pulls out of a side road on the right ahead", ["car"]),
        ("The e-bike rider (elderly woman) crosses from the right at 12 km/h in front of the ego.", ["bicycle"]),
    ],
    ids=["e-scooter-rider-adult", "motorbike-rider-teenager", "e-bike-rider-elderly"],
)
def test_a_person_in_brackets_after_a_riders_noun_is_that_rider(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("An e-scooter rider and a child cross from the left in front of the ego.", ["e-scooter", "pedestrian"]),
        ("The bus driver braked hard 30 m ahead of me.", ["truck"]),
    ],
    ids=["rider-and-child", "bus-driver"],
)
def test_a_riders_noun_beside_another_road_user_stays_as_it_was(text, expected):
    assert kinds(text) == expected


# --- "(one of those ...)" after a road user says what kind of road user it is: the same one ----------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A ute (one of those big pickups) pulled out of a farm track on the left in front of me.", ["van"]),
        ("A tuk-tuk (one of those little three-wheeled taxis) cut in sharply from the right ahead of me.", ["car"]),
        ("A minibus (one of those white 12-seater vans) pulled out from the right in front of me.", ["van"]),
    ],
    ids=["ute", "tuk-tuk", "minibus"],
)
def test_one_of_those_in_brackets_names_the_kind_of_the_same_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A van (and one of those big pickups behind it) pulled out of a track on the left in front of me.",
            ["van", "van"],
        ),
        ("A cyclist (one of those couriers) swerved out from the left kerb in front of me.", ["bicycle"]),
    ],
    ids=["and-another", "a-person-gloss"],
)
def test_a_bracket_naming_someone_else_stays_someone_else(text, expected):
    assert kinds(text) == expected


# --- "the bike" after a motorbike or its rider is that motorbike, when no pedal cycle was named ----------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A motorcyclist pulled out of a side road on the left in front of me; I braked and the bike stopped.",
            ["car"],
        ),
        ("Oncoming motorbike turns right across the ego's path; ego brakes and waits until bike has passed.", ["car"]),
        ("A moped came up behind me and the bike then cut in sharply in front of me.", ["car"]),
    ],
    ids=["motorcyclist-the-bike", "bare-bike", "moped"],
)
def test_the_bike_after_a_motorbike_is_that_motorbike(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A motorcyclist overtook me, and then a bike came out of a side road on the left in front of me.",
            ["bicycle", "car"],
        ),
        (
            "A motorbike passed me; further on, a cyclist swerved out from the left kerb and the bike wobbled.",
            ["bicycle", "car"],
        ),
    ],
    ids=["a-bike-is-new", "a-cyclist-was-named"],
)
def test_a_bike_new_or_after_a_cyclist_is_a_pedal_cycle(text, expected):
    assert kinds(text) == expected


def test_a_seater_is_a_vehicles_size_and_no_skater():
    assert kinds("A 7-seater pulled out of a drive on the left in front of me.") == ["car"]


# --- road users in general ("to pass cyclists") before a new one of their type ("a slow jogger") ------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "It is easy to overtake cyclists safely here. Today I passed a woman on a racing bike with plenty of "
            "room at 30 mph.",
            ["bicycle"],
        ),
        (
            "You can pass joggers safely on this lane. This morning I passed a slow jogger on the left at 20 mph.",
            ["pedestrian"],
        ),
        (
            "Learners find it hard to judge vans on this hill. Yesterday a white van pulled out of a drive on the "
            "right in front of me.",
            ["van"],
        ),
    ],
    ids=["to-overtake-cyclists", "pass-joggers-a-slow-jogger", "to-spot-pedestrians"],
)
def test_road_users_in_general_before_a_new_one_are_not_that_one(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A child ran out from between parked cars in front of me.", ["pedestrian"]),
        (
            "Joggers were running across the road from the left in front of me, and a slow jogger came across "
            "from the right.",
            ["pedestrian"] * 2,
        ),
    ],
    ids=["between-parked-cars", "told-in-the-past"],
)
def test_plurals_of_a_place_or_counted_are_no_road_users_in_general(text, expected):
    assert sorted(k for k in kinds(text) if k != "car") == expected


# --- a vehicle named again between commas or dashes, then what it does, is the same one -----------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A van, a white Transit, pulled out from the left in front of me.", ["van"]),
        ("A taxi, a black cab, pulled out from the left in front of me.", ["car"]),
        ("An Audi - an AUDI of all things - undertook me on the left and cut in front of me.", ["car"]),
    ],
    ids=["van-transit", "taxi-black-cab", "audi-dashes"],
)
def test_a_vehicle_named_again_in_apposition_before_its_verb_is_one(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A van, a car and a bus pulled out from the left in front of me.", ["car", "truck", "van"]),
        ("I saw a van, then a car pulled out from the left in front of me.", ["car", "van"]),
    ],
    ids=["a-list", "then-another"],
)
def test_vehicles_in_a_list_or_one_after_another_stay_apart(text, expected):
    assert kinds(text) == expected


# --- a rider's noun names what is ridden: "a cyclist on a racing bike" is one road user ------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist on a racing bike rode out from a side road on the right in front of me.", ["bicycle"]),
        ("An e-scooter rider on a hire scooter came the wrong way towards me in my lane.", ["e-scooter"]),
        ("A cyclist riding one of those cargo bikes crossed from the left in front of the ego.", ["bicycle"]),
    ],
    ids=["cyclist-racing-bike", "scooter-rider-hire-scooter", "cyclist-cargo-bike"],
)
def test_a_rider_on_a_vehicle_of_their_own_type_is_one_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist on the left and a bike on the right crossed in front of me.", ["bicycle", "bicycle"]),
        ("A cyclist rode out from the right in front of me, and a van on the left braked hard.", ["bicycle", "van"]),
    ],
    ids=["on-the-left", "another-vehicle"],
)
def test_a_rider_beside_another_vehicle_stays_two(text, expected):
    assert kinds(text) == expected


# --- a name after a preposition is a place, even with "the" and a colour before the preposition ----------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist ran the red at Kingsway, right across in front of me.", ["bicycle"]),
        ("A jogger crossed against the green at Eastgate, right in front of me.", ["pedestrian"]),
        ("A scooter rider shot through the amber near Morrisons, right in front of me.", ["e-scooter"]),
    ],
    ids=["red-at", "green-at", "amber-near"],
)
def test_a_name_after_a_preposition_is_a_place_not_a_car(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A silver Mokka pulled out from the left in front of me.", ["car"]),
        ("Then a red Zafira cut in sharply from the right lane ahead of me.", ["car"]),
    ],
    ids=["silver-mokka", "red-zafira"],
)
def test_a_name_after_an_article_and_a_colour_is_a_car(text, expected):
    assert kinds(text) == expected


# --- "done" is a word, no code of the ego ("D1", "V1", "vehicle one") --------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "The jogger was done crossing from the left at 8 km/h before I arrived.",
        "A child, almost done crossing from the left, ran in front of me.",
        "The pedestrian is nearly done crossing from the right in front of the ego.",
    ],
    ids=["was-done", "almost-done", "nearly-done"],
)
def test_done_is_no_name_of_the_ego(text):
    (walker,) = read(text).actors
    assert walker.kind == "pedestrian" and [b[0] for b in walker.behaviours] == ["cross_in_front"]


def test_a_code_of_the_ego_in_figures_still_names_it():
    assert kinds("D1 was travelling at 30 mph when D2 pulled out from the left in front of D1.") == ["car"]


# --- a number of people the lexicon has no word for, on vehicles, is so many riders ---------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("Two youths on bikes swung out from the left kerb in front of me.", ["bicycle", "bicycle"]),
        ("Three lads on e-scooters rode towards me on the wrong side of the road.", ["e-scooter"] * 3),
        ("2 suspects on stolen e-scooters crossed in front of the patrol car from the right.", ["e-scooter"] * 2),
        ("Two couriers riding bikes came out of the side street on my left.", ["bicycle", "bicycle"]),
    ],
    ids=["youths-bikes", "lads-scooters", "figure-suspects", "couriers-riding"],
)
def test_a_count_of_unknown_people_on_vehicles_is_so_many_riders(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("After two hours on bikes we rode home and a van pulled out in front of us from the right.", ["van"]),
        ("Two weeks on e-scooters has taught me nothing; a rider cut across in front of me.", ["e-scooter"]),
    ],
    ids=["hours-on-bikes", "weeks-on-scooters"],
)
def test_a_count_that_is_no_group_of_riders_stays_as_it_was(text, expected):
    assert kinds(text) == expected


# --- "two of them": a number picked out of a plural said before (no count of its own) ------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "The delivery cyclists were out in numbers tonight. Two of them shot across the junction in front of "
            "me on red.",
            ["bicycle", "bicycle"],
        ),
        ("Joggers use this lane at dawn. Three of them ran across in front of me from the right.", ["pedestrian"] * 3),
        (
            "Hire scooters everywhere after the match, and one of them rode straight out in front of me from the left.",
            ["e-scooter"],
        ),
    ],
    ids=["two-of-them", "three-of-them", "one-of-them"],
)
def test_a_number_of_them_after_an_uncounted_plural_is_so_many_road_users(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Two cyclists rode ahead of me; one of them braked hard.", ["bicycle", "bicycle"]),
        ("One of the three lorries pulled out in front of me from the left.", ["truck"]),
        ("Two cyclists rode side by side ahead of me in the lane.", ["bicycle", "bicycle"]),
    ],
    ids=["counted-antecedent", "one-of-the-lorries", "side-by-side"],
)
def test_a_number_of_a_counted_group_keeps_the_group(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "Pupils ride scooters along Mill Road after school, and one of them shot out in front of me on Monday.",
            ["e-scooter"],
        ),
        (
            "Couriers have started riding e-bikes through the park; two of them cut across in front of me.",
            ["bicycle", "bicycle"],
        ),
    ],
    ids=["pupils-ride-one", "couriers-riding-two"],
)
def test_a_number_of_them_after_people_said_to_ride_is_so_many_riders(text, expected):
    assert kinds(text) == expected


# --- a plural in the present says what road users are like in general; a new one after it is the one ---
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "Lorries are wide and slow on this lane. Picture a lorry pulling out from the left in front of you.",
            ["truck"],
        ),
        (
            "Cyclists are hard to see at dusk. Imagine a cyclist crossing from the right in front of the ego.",
            ["bicycle"],
        ),
        (
            "Allow riders plenty of room. Say you come up behind someone on a scooter at 30 mph and pass wide.",
            ["e-scooter"],
        ),
        ("A van was behind me and somebody on a bike rode out from the left in front of me.", ["bicycle", "van"]),
    ],
    ids=["lorries-are", "cyclists-are", "someone-on-a-scooter", "somebody-on-a-bike"],
)
def test_road_users_in_general_in_the_present_are_not_the_one_that_acts(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Cyclists were riding two abreast ahead of me when a van overtook us all.", ["bicycle", "van"]),
    ],
    ids=["were-riding"],
)
def test_a_plural_told_in_the_past_is_road_users_of_the_event(text, expected):
    assert len(kinds(text)) >= 2 and set(kinds(text)) == set(expected)


# --- "before someone is hurt": someone said of what may happen is nobody of the scene -------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "A cyclist swerved out from the left in front of me. Fix this junction before somebody is hurt.",
            ["bicycle"],
        ),
        ("A van ran the red light from the right in front of me; somebody will be hurt there one day.", ["van"]),
        ("A jogger crossed from the right in front of me. Someone could easily have been injured.", ["pedestrian"]),
        ("A lorry cut in on me at 50 mph. Something has to change before someone is seriously hurt.", ["truck"]),
    ],
    ids=["is-hurt", "will-be-hurt", "could-have-been", "seriously-hurt"],
)
def test_someone_of_what_may_happen_is_no_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A van was parked on my left and someone stepped out from behind it in front of me.", ["pedestrian", "van"]),
        ("Someone is crossing from the right in front of the ego at 5 km/h.", ["pedestrian"]),
    ],
    ids=["someone-stepped-out", "someone-is-crossing"],
)
def test_someone_who_acts_in_the_scene_is_a_road_user(text, expected):
    assert kinds(text) == expected


# --- everyday words for a person, an animal on the road and a rideable name the road users they are ----
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A lad ran out from between the bins on the right in front of me.", ["pedestrian"]),
        ("An old gent stepped off the kerb on my left without looking.", ["pedestrian"]),
        ("A youngster dashed across the road from the left in front of the ego.", ["pedestrian"]),
        ("A teen walked out from the right in front of me at 20 mph.", ["pedestrian"]),
        ("A roo bounded across from the left right in front of my ute.", ["pedestrian"]),
        ("A pigeon strutted across the road in front of me.", ["pedestrian"]),
        ("An e-step rider on the cycle path crossed the exit in front of the ego.", ["e-scooter"]),
    ],
    ids=["lad", "gent", "youngster", "teen", "roo", "pigeon", "e-step"],
)
def test_everyday_names_of_road_users_are_read(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("On a gentle bend a cyclist swerved out from the left in front of me.", ["bicycle"]),
        ("A van pulled out from the left in front of me; I had to step on the brakes.", ["van"]),
    ],
    ids=["gentle", "step-on-brakes"],
)
def test_words_that_only_look_like_those_names_are_none(text, expected):
    assert kinds(text) == expected


# --- the narrator's companion set in apposition ("my passenger, an old lady,") is nobody of the scene ---
@pytest.mark.parametrize(
    "text, expected",
    [
        ("My passenger, an elderly man, shouted as a van cut in sharply in front of me.", ["van"]),
        ("My passenger, an elderly man heading back from the match, shouted as a van cut in front of me.", ["van"]),
        ("Our lodger, a student going to her lectures, yelled when a lorry pulled out from the right.", ["truck"]),
        (
            "Our neighbour, a retired nurse sitting in the back, gasped when a cyclist swerved out in front of us.",
            ["bicycle"],
        ),
        ("My son, a boy of nine, was in the back when a lorry ran the red light from the left.", ["truck"]),
    ],
    ids=["passenger-man", "passenger-heading-back", "lodger-going", "neighbour-nurse", "son-boy"],
)
def test_a_person_in_apposition_to_the_narrators_companion_is_no_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("On my left, a man stepped out from behind a parked van in front of me.", ["pedestrian", "van"]),
        ("My passenger screamed as a woman ran out in front of us from the right.", ["pedestrian"]),
    ],
    ids=["on-my-left", "no-apposition"],
)
def test_a_person_after_the_narrators_words_but_not_their_companion_stays(text, expected):
    assert kinds(text) == expected


# --- a vehicle said to be on its way, called or attending comes after the event: no road user --------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A cyclist swerved into my lane from the left and I clipped him. The ambulance is on its way.", ["bicycle"]),
        ("A pedestrian ran out in front of me from the right; a police car was called.", ["pedestrian"]),
        (
            "A scooter rider crossed from the left and went under my wheels. Two fire engines are en route.",
            ["e-scooter"],
        ),
    ],
    ids=["on-its-way", "was-called", "en-route"],
)
def test_a_vehicle_on_its_way_after_the_event_is_no_road_user(text, expected):
    assert kinds(text) == expected


# (with no article, and where no collision is said: it is the call that says it comes after)
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A bus and a scooter rider came together at the exit ahead of me. Ambulance is on its way.", "van"),
        ("A lad on a bike shot out of a side road on my left, I was doing 20 mph; police car en route now.", "car"),
        ("A pedestrian stepped out from the left in front of me; an ambulance was called but she was fine.", "van"),
        ("Cyclist swerved out from the kerb in front of us at 15 mph. Paramedic car on the way, all ok.", "car"),
        ("A woman ran across in front of me from the right. Two police vans were summoned to the scene.", "van"),
    ],
    ids=["bare-on-its-way", "police-car-en-route", "was-called-no-contact", "on-the-way", "were-summoned"],
)
def test_a_vehicle_called_to_the_scene_is_no_road_user_whatever_the_outcome(text, expected):
    assert expected not in kinds(text)


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A van was on its way out of the junction when it pulled into my path from the left.", ["van"]),
        ("A lorry was on its way to the depot when it pulled out in front of me from the left.", ["truck"]),
    ],
    ids=["on-its-way-out", "on-its-way-to"],
)
def test_a_vehicle_on_its_way_somewhere_in_the_event_stays(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("An ambulance on a blue light came through the red from the left in front of me.", ["van"]),
        ("A van was on my left and pulled out in front of me.", ["van"]),
    ],
    ids=["ambulance-acts", "van-on-my-left"],
)
def test_a_vehicle_that_acts_in_the_event_stays(text, expected):
    assert kinds(text) == expected


# --- several people on one vehicle ride it together: one road user ("two-up") ------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("Two kids on one e-scooter shot out from the left in front of me.", ["e-scooter"]),
        ("Three lads on a single bike wobbled across from the right in front of the ego.", ["bicycle"]),
        (
            "Two girls on the same scooter, and their friend on another, came at me on the wrong side.",
            ["e-scooter", "e-scooter"],
        ),
        ("A boy on a bike, and his brother on another, rode out from the left in front of me.", ["bicycle", "bicycle"]),
    ],
    ids=["two-on-one", "three-on-a-single", "plus-another", "brother-on-another"],
)
def test_people_on_one_vehicle_are_one_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Two kids on e-scooters shot out from the left in front of me.", ["e-scooter", "e-scooter"]),
        ("Two cyclists riding side by side came towards me on the wrong side.", ["bicycle", "bicycle"]),
    ],
    ids=["two-on-scooters", "two-cyclists"],
)
def test_people_on_vehicles_of_their_own_stay_so_many(text, expected):
    assert kinds(text) == expected


# --- a road user named new in a warning of what may come ("before a kid is hurt") is nobody of the scene ---
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A taxi swung out from the right in front of me. Fix the lights before a kid is killed.", ["car"]),
        ("A bus pulled out from the stop on my left at 30 mph. Act now or a cyclist will be knocked down.", ["truck"]),
        ("A van cut in on me at 40 mph. The council will wait until a walker gets seriously injured.", ["van"]),
    ],
    ids=["before-a-kid", "or-will-be-knocked", "until-gets-injured"],
)
def test_a_road_user_of_a_warning_is_no_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was at 30 mph. A van pulled out from the left, and a cyclist could be seen crossing.", ["bicycle", "van"]),
        ("A pedestrian will cross from the right at 5 km/h in front of the ego.", ["pedestrian"]),
        ("The ego brakes before a jogger crosses from the left in front of it.", ["pedestrian"]),
    ],
    ids=["could-be-seen", "will-cross", "before-crosses"],
)
def test_a_road_user_of_an_event_stays(text, expected):
    assert set(kinds(text)) == set(expected)


# --- "such people", "such riders": one of a kind, people in general, no road user of the scene -----------
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A boy on an e-scooter came at me on the wrong side. Police must deal with such people.", ["e-scooter"]),
        ("A taxi cut in front of me at 30 mph. We need more cameras to catch such cyclists.", ["car"]),
    ],
    ids=["such-people", "such-cyclists"],
)
def test_such_plurals_are_people_in_general(text, expected):
    assert kinds(text) == expected


def test_such_plural_that_is_the_only_road_user_stays():
    assert kinds("Such cyclists crossed in front of me at 30 km/h.") == ["bicycle"]


# --- an age that stands for a person ("a six-year-old") is that person; before a noun it describes it ---
@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was doing 20 mph when a seven-year-old darted into the road from the right.", ["pedestrian"]),
        ("At 25 km/h, a 9 year old on a bike came out of a driveway on my left and I braked.", ["bicycle"]),
        ("I braked hard at 30 mph as a 70-year-old, who never looked, stepped off the kerb.", ["pedestrian"]),
    ],
    ids=["seven-year-old", "nine-on-a-bike", "seventy-who"],
)
def test_an_age_as_a_noun_is_the_person(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A 17-year-old e-scooter rider swerved in front of me from the left.", ["e-scooter"]),
        ("A 40-year-old van driver pulled out from the right in front of me.", ["van"]),
    ],
    ids=["age-of-rider", "age-of-driver"],
)
def test_an_age_before_a_noun_only_describes_it(text, expected):
    assert kinds(text) == expected


# --- someone new no word names, after a clause's time adverbial ("Yesterday a heron ..."), is a road user ---
@pytest.mark.parametrize(
    "text, expected",
    [
        ("Yesterday a pheasant walked across the road in front of me and I stopped.", ["pedestrian"]),
        ("Last night a big wombat waddled out from the left in front of me at 40 mph.", ["pedestrian"]),
    ],
    ids=["yesterday-a", "last-night-a"],
)
def test_someone_new_after_a_time_adverbial_is_a_road_user(text, expected):
    assert kinds(text) == expected


# --- "a pedestrian crossing the road": a walker crossing, not a zebra crossing ---------------------------
def test_a_pedestrian_crossing_with_an_object_is_a_walker():
    text = "Ego at 30 km/h behind a cyclist on the left. Also a pedestrian crossing the road far ahead."
    assert kinds(text) == ["bicycle", "pedestrian"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego 25 kph on a narrow street behind a cyclist. Also one pedestrian crossing far ahead.",
        "Ego 40 km/h, a van pulls out from the left; and one pedestrian crossing from the right behind it.",
        "Ego 30 km/h behind a bus; also a pedestrian crossing ahead, from the left.",
        "Ego at 50 km/h behind a lorry, plus one pedestrian crossing slowly in the distance.",
        "Scene: ego 20 mph, a cyclist ahead in the lane, then a pedestrian crossing well ahead of both.",
    ],
    ids=["also-one", "and-one", "also-a", "plus-one", "then-a"],
)
def test_one_pedestrian_crossing_at_a_clauses_start_is_a_walker(text):
    assert "pedestrian" in kinds(text)


@pytest.mark.parametrize(
    "text",
    [
        "Ego 30 km/h behind a cyclist; there is one pedestrian crossing on this road.",
        "Ego 30 km/h; the cyclist ahead of us slows for a pedestrian crossing.",
        "Ego at 40 km/h behind a van that stops at one pedestrian crossing after another.",
    ],
    ids=["there-is-one", "slows-for-a", "at-one"],
)
def test_a_pedestrian_crossing_counted_after_a_verb_stays_a_place(text):
    assert "pedestrian" not in kinds(text)


def test_a_pedestrian_crossing_as_a_place_is_no_walker():
    assert kinds("Ego at 30 km/h; a cyclist ahead of us stops at a pedestrian crossing.") == ["bicycle"]


# --- of the nouns no word names, the road user is the one that does what road users do in its clause ----
@pytest.mark.parametrize(
    "text, expected",
    [
        ("The council told me the junction is safe. Three lads ran out from the left in front of my car.", 3),
        ("My satnav took me down a back street. Two youths strolled out in front of my car.", 2),
    ],
    ids=["council-told", "satnav-took"],
)
def test_the_unnamed_subject_that_acts_is_the_road_user(text, expected):
    assert kinds(text) == ["pedestrian"] * expected


def test_the_first_unnamed_subject_still_counts_when_none_acts_plainly():
    assert kinds("The rider shot off the kerb in front of me.") == ["e-scooter"]


# --- "one <noun>" the reader has no word for opens someone new, as "a <noun>" does ("one aunty was ...") ---
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A taxi cut across me at the signal, and one granny was crossing the road in front.", ["car", "pedestrian"]),
        ("A van overtook me at 30 mph, and one uncle was walking across the road ahead.", ["pedestrian", "van"]),
        ("A van overtook me at 40 km/h, same time one auntie stepped off the kerb on the left.", ["pedestrian", "van"]),
    ],
    ids=["one-granny", "one-uncle", "same-time-one"],
)
def test_one_unknown_person_is_someone_new(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A taxi cut across me at the signal, and one lane was closed for works.", ["car"]),
        ("A taxi cut across me at the signal; one wing mirror was folded in.", ["car"]),
        ("A taxi cut across me at the signal, one of those days.", ["car"]),
        ("One morning a stoat ran out in front of me at 30 mph.", ["pedestrian"]),
    ],
    ids=["one-lane", "one-mirror", "one-of-those", "one-morning-a"],
)
def test_one_thing_is_no_road_user(text, expected):
    assert kinds(text) == expected


# --- "the deceased", "the injured": an adjective standing for a person, subject of a verb, is that person ---
@pytest.mark.parametrize(
    "text, expected",
    [
        ("The accused drove his tractor at 30 mph in the dark. The deceased was walking on the verge.", ["pedestrian"]),
        ("My lorry was doing 40 mph. The injured stepped out from behind a hedge.", ["pedestrian"]),
    ],
    ids=["deceased-walking", "injured-stepped"],
)
def test_an_adjective_standing_for_a_person_is_a_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text",
    ["I drove home at 30 mph. The same happened again at the junction.", "I drove at 30 mph. The tired often nap."],
    ids=["the-same", "the-tired-in-general"],
)
def test_an_adjective_that_names_no_one_is_no_road_user(text):
    assert kinds(text) == []


def test_one_picked_out_of_many_who_reports_is_no_new_road_user():
    text = (
        "Reports of a cyclist riding the wrong way on the bypass at dawn. "
        "One motorist heading east says she only just missed him."
    )
    assert kinds(text) == ["bicycle"]


# --- a vehicle's noun before a word for a thing with no name ("these scooter contraptions") is that vehicle ---
@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was doing 20 mph when one of these electric scooter contraptions shot past and cut in.", ["e-scooter"]),
        ("Doing 30, and one of those scooter gadgets comes flying off the kerb on my left.", ["e-scooter"]),
        ("Ego 40 km/h; two bike thingies swerve out from the left kerb in front of it.", ["bicycle", "bicycle"]),
        ("One of these e-scooter deathtraps came at me the wrong way down the high street at 15 mph.", ["e-scooter"]),
        ("I was on 25 mph and one of those hoverboard toys rolled out from the right in front of me.", ["e-scooter"]),
    ],
    ids=["contraptions", "gadgets", "thingies", "deathtraps", "toys"],
)
def test_a_vehicle_said_by_a_word_for_a_thing_is_that_vehicle(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("We looked at two car crashes; in the first a van pulled out from the left at 30 mph.", ["van"]),
        ("Doing 30 mph past the scooter bays when a cyclist pulled out from the left.", ["bicycle"]),
    ],
    ids=["car-crashes", "scooter-bays"],
)
def test_a_vehicle_before_a_plural_that_names_something_else_stays_a_modifier(text, expected):
    assert kinds(text) == expected


# --- a walker someone stops, waits or gives way for at a walkers' crossing is crossing there --------------------
@pytest.mark.parametrize(
    "text",
    [
        "I stopped at the zebra for a pedestrian at 20 mph.",
        "I was doing 20 mph and stopped at the crossing for an old man.",
        "I stopped for a pedestrian at the zebra crossing; the van behind overtook me.",
        "I gave way to an elderly lady at the crosswalk, doing 15 mph.",
        "Ego slows to a stop at the pelican crossing for a jogger, 30 km/h before.",
    ],
    ids=["zebra", "crossing-old-man", "van-behind", "gave-way-crosswalk", "pelican-jogger"],
)
def test_a_walker_waited_for_at_a_crossing_crosses(text):
    reading = read(text)
    walkers = [a for a in reading.actors if a.kind == "pedestrian"]
    assert len(walkers) == 1 and walkers[0].behaviours[0][0] == "cross_in_front"


@pytest.mark.parametrize(
    "text, behaviour",
    [
        ("A pedestrian was walking along the pavement near the zebra crossing; I was at 20 mph.", "along_road"),
        ("I passed a pedestrian standing by the zebra crossing at 20 mph.", "stop"),
        ("I waited behind a jogger on the road at 20 mph.", "along_road"),
    ],
    ids=["walking-along", "standing-by", "no-crossing-named"],
)
def test_a_walker_at_a_crossing_who_does_something_else_keeps_it(text, behaviour):
    walkers = [a for a in read(text).actors if a.kind == "pedestrian"]
    assert walkers and walkers[0].behaviours[0][0] == behaviour
