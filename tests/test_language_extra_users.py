"""Road users the reader must not make twice or out of talk: a person in a vehicle whose verb can
also be a noun ("a guy in a Charger blows past") is one road user; a person said in apposition right
after the road user they ride or drive ("an e-scooter, bloke in a hi-vis") is that road user; a
road-user noun that says what everybody or nobody is ("not everyone is a bad driver") is no road user."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds

# ---- a person in a vehicle, then a verb that can also be a noun -------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "I'm doing 65 on the interstate and a guy in a Mustang blows past me on the left.",
        "Doing 70 in lane two when some bloke in a BMW shoots past me on the inside.",
        "I was at 50 km/h and a woman in a silver hatchback whips across in front of me.",
        "Driving at 60 km/h, a lad in a Corsa tears past me on the right and cuts in.",
        "We were at 40 mph when a man in a pickup flies past us on the outside.",
        "Cruising at 90 km/h, a fellow in a white van darts out in front of me from the left.",
    ],
)
def test_a_person_in_a_vehicle_with_a_verb_that_is_also_a_noun_is_one_road_user(text: str) -> None:
    assert len(kinds(text)) == 1


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # near misses: the word after the vehicle is a noun of the phrase, not the person's verb
        ("A baby in a car seat was in the back of the van that pulled out in front of me at 30 mph.", ["van"]),
        ("I was at 30 mph when a guy in a hatchback pulled out in front of me.", ["car"]),
    ],
)
def test_a_person_in_a_vehicle_near_misses(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


# ---- a person in apposition to the road user just named ---------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "Doing 30 mph. There's a cyclist ahead, lad in a hoodie, about 20 m in front, and he just stops dead.",
        "I was at 25 mph when an e-scooter came off the kerb, young guy with headphones, right in front of me.",
        "At 40 km/h a moped pulled out of the side road, bloke in a yellow jacket, and I braked hard.",
        "I was doing 20 when a bike cut across, teenage boy with no helmet, and I had to stop.",
        "Doing 30 mph on the high street, a scooter ahead of me, woman in a long coat, suddenly braked.",
    ],
)
def test_a_person_in_apposition_is_the_road_user_named_before(text: str) -> None:
    assert len(kinds(text)) == 1


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # near misses: a second person with a verb of their own, after "and" or as a new clause
        (
            "I was doing 30 when a cyclist pulled out in front of me, and a man on foot stepped out behind him.",
            ["bicycle", "pedestrian"],
        ),
        ("I was at 25 mph when a cyclist came past. A pedestrian then stepped out in front of me.", None),
        ("I was doing 30 mph. A car was parked on the left, child behind it, and he ran out in front of me.", None),
        ("I was doing 30 mph when a van pulled up ahead, old man crossing behind it, and I braked.", None),
    ],
)
def test_a_person_in_apposition_near_misses(text: str, expected: list[str] | None) -> None:
    got = kinds(text)
    assert len(got) == 2
    if expected is not None:
        assert got == expected


# ---- a road-user noun that says what everyone or nobody is ------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "I passed a cyclist at 30 km/h with plenty of room. Not everyone is bad driver!",
        "I passed a cyclist at 30 km/h with plenty of room. Nobody is a perfect driver.",
        "I passed a cyclist at 30 km/h with plenty of room. Everybody is a learner driver once.",
        "I passed a cyclist at 30 km/h with plenty of room. Anyone can be a careless driver.",
        "I passed a cyclist at 30 km/h with plenty of room. No one is the perfect motorist.",
    ],
)
def test_what_everyone_or_nobody_is_is_no_road_user(text: str) -> None:
    assert kinds(text) == ["bicycle"]


def test_what_a_named_road_user_is_near_miss() -> None:
    """A road user introduced with "there is" stays one (the copula's subject is no quantifier)."""
    assert kinds("I was doing 30 mph. There is a van stopped ahead of me and I braked.") == ["van"]


def test_a_list_of_road_users_is_not_an_apposition() -> None:
    text = "Three road users came through the crossing: a van, woman in a red coat, and a cyclist, all at 10 mph."
    assert len(kinds(text)) == 3


# ---- a vehicle steered in a log with no subject ------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "Departing the depot at 20 km/h when a cyclist swerved in front. Braked hard and brought the bus "
            "to a halt.",
            ["bicycle"],
        ),
        (
            "Pulling away from the stop at 10 mph. A pedestrian stepped off the kerb 5 m ahead. Sounded the horn "
            "and stopped the bus just short.",
            ["pedestrian"],
        ),
        (
            "Doing 30 in a 30. A lad on a bike came out of a side road. Steered the van left and missed him.",
            ["bicycle"],
        ),
        (
            "Shift start. Left the depot at 15 km/h; a jogger ran across the track ahead. Rang the bell and "
            "brought the tram to a stop.",
            ["pedestrian"],
        ),
        ("Slowed to 20 km/h as a kid chased a ball into the road, pulled the lorry over and waited.", ["pedestrian"]),
    ],
)
def test_a_vehicle_steered_in_a_log_with_no_subject_is_the_writers(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # near misses: the steering verb has a subject of its own, or the vehicle is where the writer stops
        ("Doing 20 km/h. A bus driver pulled out from the stop and stopped the bus across my lane.", ["truck"]),
        ("Waiting at the lights. A taxi driver pulled up beside me and parked the cab on the zigzags.", ["car"]),
        ("Doing 20 km/h. Saw a lorry driver ahead of me stop the lorry across the road.", ["truck"]),
        ("Doing 30 mph. Stopped behind the van at the lights, and a cyclist came up the inside.", None),
    ],
)
def test_a_vehicle_steered_in_a_log_near_misses(text: str, expected: list[str] | None) -> None:
    got = kinds(text)
    assert got == expected if expected is not None else len(got) == 2


@pytest.mark.parametrize(
    "text",
    [
        "Doing 35 mph past the estate entrance when a cyclist pulled out in front of me.",
        "I was at 20 km/h on the forecourt of the car dealership when a cyclist cut across in front of me.",
        "Turning into the car entrance at 10 mph, a cyclist came up on my left.",
    ],
)
def test_a_place_named_after_a_vehicle_is_no_road_user(text: str) -> None:
    assert kinds(text) == ["bicycle"]


# ---- the writer's vehicle shaken by what passes it ---------------------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("A lorry came past me at speed on the motorway, I was doing 60, and the whole car shook.", ["truck"]),
        ("I was doing 50 mph when a coach overtook me and the van rocked in its wake.", ["truck"]),
        ("We were sitting at 40 mph when a bus passed us and the whole car wobbled.", ["truck"]),
        ("I'm at 70 in lane one, an artic flies by on the right and the car shudders.", ["truck"]),
        ("I was at 30 mph when a tanker went past, the hatchback swayed a bit but I held my line.", ["truck"]),
    ],
)
def test_the_writers_vehicle_shaken_by_what_passes_is_the_ego(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # near misses: a vehicle placed apart from the writer, or introduced before, shakes on its own
        ("I was doing 30 mph when the car ahead of me shook and swerved into the kerb.", ["car"]),
        ("I was at 40 mph behind a car when a lorry passed us and the car swayed towards the verge.", None),
    ],
)
def test_the_writers_vehicle_shaken_near_misses(text: str, expected: list[str] | None) -> None:
    got = kinds(text)
    assert got == expected if expected is not None else len(got) == 2


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30 with an e-scooter ahead, bloke in a hi-vis, a",
        "I was doing 30 with an e-scooter ahead, bloke in a hi-vis,",
    ],
)
def test_a_person_in_apposition_at_the_very_end_is_read_without_error(text: str) -> None:
    assert kinds(text) == ["e-scooter"]


# ---- a person named by a relative clause of riding or driving is the vehicle -------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Do you know the lad who rides the red e-scooter? He shot out in front of my car at 30 mph.", ["e-scooter"]),
        (
            "I was doing 40 km/h when a woman that was riding a bicycle pulled out from the left in front of me.",
            ["bicycle"],
        ),
        (
            "A girl who was on an electric scooter came off the footpath on the left and crossed in front of me.",
            ["e-scooter"],
        ),
        ("At 25 mph a bloke who drives a white van for the council pulled out of a side road on my left.", ["van"]),
        (
            "The boy that always rides his bike down our street came out of a driveway on the right, I was at 20 mph.",
            ["bicycle"],
        ),
    ],
    ids=["who-rides", "that-was-riding", "who-was-on", "who-drives", "that-always-rides"],
)
def test_a_person_who_rides_a_vehicle_is_that_vehicle(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # no vehicle after the verb: the person's clause says how they move, and they stay a person
        ("A woman who was walking home crossed in front of me from the right at 30 km/h.", ["pedestrian"]),
        ("A kid who was on the pavement stepped out in front of me from the left, I was at 20 mph.", ["pedestrian"]),
    ],
    ids=["walking", "on-the-pavement"],
)
def test_a_person_who_rides_near_misses(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


# ---- a road user named again in apposition, then a participle or place of its own, is one --------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("There was a woman on a scooter, an e-scooter, riding toward me in my lane.", ["e-scooter"]),
        ("Then a bike, a racing bike, coming the wrong way in my lane at me, I was doing 25 mph.", ["bicycle"]),
        ("I was at 40 mph and there's a car, a silver hatchback, coming straight at me in my lane.", ["car"]),
        ("Doing 30 km/h, and a lorry, a big tipper, turning left across me at the junction.", ["truck"]),
        ("At 50 km/h a scooter, an e-scooter, riding the wrong way toward me.", ["e-scooter"]),
    ],
    ids=["escooter-riding", "bike-coming", "car-coming", "lorry-turning", "scooter-riding"],
)
def test_a_road_user_named_again_in_apposition_then_a_participle_is_one(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a list: "and" goes on with another road user
        ("I was at 30 mph, a car, a van and a bus coming toward me in the other lane.", ["car", "truck", "van"]),
        # a second one added by a word before its article ("plus", "then")
        ("Doing 20 mph, a bike, plus a bike, coming the wrong way toward me.", ["bicycle", "bicycle"]),
    ],
    ids=["a-list", "plus-another"],
)
def test_a_road_user_in_apposition_near_misses(text: str, expected: list[str]) -> None:
    assert sorted(kinds(text)) == expected


# ---- the people a writer or speaker addresses are no road users ---------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "Morning guys! So I'm doing 30 mph and a cyclist pulls out from the left in front of me.",
        "And on the right, ladies and gentlemen, the old mill - sorry folks - a cyclist just cut across in front "
        "of the bus from the left, I was at 20 mph.",
        "Hi everyone, hi folks. At 40 km/h a cyclist swerved out from the left in front of me. Scary, you guys.",
        "Evening all. Thanks guys for the views. Doing 25 mph when a cyclist came out of a side road on my left.",
        "Listen people, I was at 20 mph and a cyclist pulled out from the left in front of me.",
    ],
    ids=["morning-guys", "ladies-and-gentlemen", "you-guys", "thanks-guys", "listen-people"],
)
def test_the_people_a_speaker_addresses_are_no_road_users(text: str) -> None:
    assert kinds(text) == ["bicycle"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # people who do something, or with a determiner or count, stay road users
        ("At 20 mph, kids ran out from the left in front of me.", ["pedestrian"]),
        (
            "I was doing 20 mph. Two pedestrians, a man and a woman, crossed in front of me from the right.",
            ["pedestrian", "pedestrian"],
        ),
    ],
    ids=["kids-ran", "counted"],
)
def test_the_people_addressed_near_misses(text: str, expected: list[str]) -> None:
    assert kinds(text)[: len(expected)] == expected and set(kinds(text)) == {"pedestrian"}


# ---- people inside the ego's vehicle, by where they are in it, are no road users -----------------------


@pytest.mark.parametrize(
    "text",
    [
        "Doing 25 mph in the bus when a car pulled out from the left; I braked hard and a lady went over on the "
        "lower deck.",
        "I drive the 73. A car pulled out of a side road on my left at 20 mph, I stopped hard, and a man on the top "
        "deck fell.",
        "I was driving the coach at 40 km/h when a van cut in from the right; I braked and a woman in the aisle fell.",
        "On the ferry shuttle at 30 km/h a car pulled out from the left and a child in the cabin got thrown about.",
        "At 15 mph a taxi pulled out from the right in front of my bus; an old man standing in the gangway fell.",
    ],
    ids=["lower-deck", "top-deck", "aisle", "cabin", "gangway"],
)
def test_people_inside_the_egos_vehicle_are_no_road_users(text: str) -> None:
    assert kinds(text) in (["car"], ["van"])


# ---- a proper name that ends in a person's or animal's noun is a place -------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "We set off from the Green Man at 20 mph and a cyclist pulled out from the left in front of me.",
        "Passing the Black Horse at 30 mph, a cyclist pulled out from the left in front of me.",
        "I was doing 25 mph by the Old Man Inn when a cyclist pulled out from the left in front of me.",
        "Outside the Jolly Farmer I was at 30 mph and a cyclist came out from the left in front of me.",
        "Heading past the Dog and Duck, I was at 30 mph, a cyclist came out from the left in front of me.",
    ],
    ids=["green-man", "black-horse", "old-man-inn", "jolly-farmer", "dog-and-duck"],
)
def test_a_proper_name_ending_in_a_person_or_animal_is_no_road_user(text: str) -> None:
    assert kinds(text) == ["bicycle"]


def test_a_capital_person_noun_alone_is_still_a_road_user() -> None:
    assert kinds("I was doing 30 mph when a Man stepped out from the left in front of me.") == ["pedestrian"]


# ---- a person said back by who they are ("the lad", "the idiot") is the road user named last ---------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("At 20 mph a cyclist came out of a driveway on the left, and the boy rode off without stopping.", ["bicycle"]),
        ("A scooter rider shot out from the right at 30 km/h; the teenager never even looked at me.", ["e-scooter"]),
        ("I was at 40 mph when a van cut in from the right, and then the idiot slammed on his brakes.", ["van"]),
        ("Doing 25 mph, an e-scooter pulled out from the left in front of me and the guy just laughed.", ["e-scooter"]),
        ("A motorbike overtook me on the right at 60 mph, then the lunatic cut straight back in.", ["car"]),
    ],
    ids=["the-boy", "the-teenager", "the-idiot", "the-guy", "the-lunatic"],
)
def test_a_person_said_back_by_who_they_are_is_the_road_user_named_last(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # someone placed or described where named, or after a walker was named: someone else
        (
            "A cyclist came past me on the right, then the man on the crossing stepped out from the left.",
            ["bicycle", "pedestrian"],
        ),
        (
            "A woman crossed from the left at 20 mph and a cyclist came round her, and the woman waved.",
            ["pedestrian", "bicycle"],
        ),
    ],
    ids=["placed", "walker-before"],
)
def test_a_person_said_back_near_misses(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected
