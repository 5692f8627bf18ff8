"""The ego's own vehicle named as if it were one more road user: a vehicle that nothing places and that
only goes on or brakes, beside road users that act, is the ego. Wordings written for the class in
several registers (a fleet memo, a parish note, a passenger's text, a news line, a radio log), none
taken from a corpus; near misses that look alike keep their road users."""

from __future__ import annotations

import pytest

from vei_scenario.language import ego_double, report_vehicle
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    ("text", "kind", "ego_kph"),
    [
        ("Bus was doing around 45 when a cyclist swerved in front of it from the left lane.", "bicycle", 45),
        (
            "The school minibus was doing about thirty when a lorry pulled out of a farm gate on the left"
            " into its path.",
            "truck",
            30,
        ),
        (
            "RE: incident. The pool car was moving at about 60km/hr when a danfo bus cut in from the right"
            " lane and stopped abruptly. Driver could not avoid hitting it.",
            "truck",
            60,
        ),
        (
            "Our Uber was going about 50 kph along the seafront when a guy on a scooter came off the pavement"
            " on the left right in front of us. The driver braked hard.",
            "e-scooter",
            50,
        ),
        (
            "Police said the Corsa was travelling at around 30 mph when a pedestrian stepped out from the"
            " right into the road just ahead of it.",
            "pedestrian",
            48.3,
        ),
        (
            "0215 hrs. Patrol van proceeding north at 20 mph. Cyclist riding towards us on the wrong"
            " side of the road, swerved back at the last moment.",
            "bicycle",
            32.2,
        ),
    ],
)
def test_the_vehicle_the_story_is_told_from_is_the_ego(text, kind, ego_kph):
    reading = read(text)
    assert [a.kind for a in reading.actors] == [kind]
    assert reading.ego_speed_mps is not None and abs(reading.ego_speed_mps * 3.6 - ego_kph) < 1.0


@pytest.mark.parametrize(
    "text",
    [
        "Bus was doing around 45 when a cyclist swerved in front of it from the left lane.",
        "The school minibus was doing about thirty when a lorry pulled out of a farm gate on the left into its path.",
    ],
)
def test_without_the_rule_the_ego_would_be_a_road_user_of_its_own(text, monkeypatch):
    """The wordings above need this module: the rest of the reader reads the ego's vehicle apart."""
    monkeypatch.setattr(ego_double, "merge_into_ego", lambda actors, reading, unnamed, tokens: actors)
    monkeypatch.setattr(
        report_vehicle,
        "merge_report_vehicle",
        lambda actors, reading, text, ego_phrase=False, outside=False: actors,
    )
    reading = read(text)
    assert len(reading.actors) == 2 and reading.ego_speed_mps is None


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # another road user's object: the overtaken bus is there, ahead of the overtaker
        ("A lorry overtook a slow-moving bus and pulled in right in front of me.", ["truck", "truck"]),
        # named in a group: two cars ahead, a cyclist between them
        ("Two cars were ahead of me and a cyclist cut in between them.", ["car", "car", "bicycle"]),
        # standing: what someone steps out from behind is parked scenery, not the ego
        ("A child ran out from behind a parked van on the left right in front of me.", ["pedestrian", "van"]),
        # new to the story: the ego, whose story it is, is never brought in with "a"
        ("A car was going at 40 km/h and an e-scooter crossed in front of me.", ["car", "e-scooter"]),
        ("A big white van was going at 40 km/h and an e-scooter crossed in front of me.", ["van", "e-scooter"]),
        # seen: what someone watches is watched from outside
        ("My dad saw the car hit a cyclist.", ["car", "bicycle"]),
        # only stopping: it may be standing there
        ("The bus was stopped at the stop when a cyclist rode into the back of it.", ["truck", "bicycle"]),
        # the text calls the ego by that name
        (
            "The car in the next lane brakes hard while a pedestrian crosses 20 m ahead of the ego.",
            ["car", "pedestrian"],
        ),
        # placed: a car said to be behind the ego is not the ego
        ("A car behind me was doing 50 when a cyclist crossed in front of us.", ["car", "bicycle"]),
    ],
)
def test_a_vehicle_the_words_set_somewhere_stays_a_road_user(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


def test_two_vehicles_read_alike_cannot_be_told_apart_and_both_stay():
    text = "A taxi was going at 30 and a van was going at 40 when a pedestrian stepped out from the right."
    assert sorted(a.kind for a in read(text).actors) == ["car", "pedestrian", "van"]


def test_only_one_that_does_nothing_of_its_own_is_not_taken_for_the_ego():
    """With nobody else acting there is no one for the scenario to be with: it stays what it is."""
    reading = read("A van was doing 40 mph down the high street.")
    assert [a.kind for a in reading.actors] == ["van"]


def test_a_gap_said_of_the_ego_s_vehicle_is_the_gap_to_the_one_it_meets():
    reading = read("Bus was doing 40 only 3 m from a cyclist when the cyclist swerved into the lane.")
    (cyclist,) = reading.actors
    assert cyclist.kind == "bicycle" and cyclist.distance_m == 3.0
    assert abs(reading.ego_speed_mps * 3.6 - 40) < 1e-6


#: A passenger's story of the ride, told in several Englishes and registers (none from a corpus): the
#: driver named with no vehicle of their own is the ego's driver; (wording, the road users it has).
PASSENGERS = [
    # a Nigerian passenger's review: the driver's overtake is the ego's
    (
        "The driver no patience at all. On the road to Ikeja one cyclist riding slowly by the left side, our car"
        " follow behind him, then driver overtake very close.",
        ["bicycle"],
    ),
    # a British hotel review: the driver's hard braking is the ego's, not a car ahead braking
    (
        "Booked the resort's shuttle. Driver very polite but on the motorway a lorry from the next lane swerved"
        " into our lane just in front of us. Driver braked hard.",
        ["truck"],
    ),
    # an American rideshare review
    (
        "My uber driver was going way too fast on the freeway and a pickup merged into our lane right in front"
        " of us. Driver slammed the brakes.",
        ["van"],
    ),
    # a Singaporean text message
    (
        "Grabcar today. Driver cut into the next lane and a motorcycle behind us had to brake hard. Driver never"
        " even signal.",
        ["car"],
    ),
    # an Indian traveller's note, the chauffeur
    (
        "Transfer to the hotel in Pune. The chauffeur overtook a tractor near the flyover and a bus came head on"
        " towards us in our lane.",
        ["truck", "truck"],
    ),
]


@pytest.mark.parametrize(("text", "kinds"), PASSENGERS)
def test_the_driver_of_a_passenger_s_story_is_the_ego(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


def test_without_the_rule_the_ego_s_driver_would_be_a_road_user(monkeypatch):
    """The first wordings above need this rule: the rest of the reader reads the driver apart."""
    monkeypatch.setattr(ego_double, "merge_ego_driver", lambda actors, reading: actors)
    assert [len(read(text).actors) for text, _ in PASSENGERS[:3]] == [2, 2, 2]


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # new to the story: "a driver" is someone the story brings in
        ("A driver ran the red light on the right and hit a cyclist crossing in front of me.", ["car", "bicycle"]),
        # someone else: "the other driver"
        (
            "A cyclist swerved round me and the other driver pulled out of the side road on the left.",
            [
                "bicycle",
                "car",
            ],
        ),
        # placed: the driver behind me is behind the ego
        ("I was doing 30 when the driver behind me pulled out and overtook me.", ["car"]),
        # placed: the driver of an oncoming car
        ("We were turning right when an oncoming driver flashed us and a cyclist came through.", ["car", "bicycle"]),
    ],
)
def test_a_driver_the_words_set_apart_stays_a_road_user(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


#: Third-person reports that name no ego at all bring the vehicle they are about in as new ("a ..."):
#: a council bulletin, a police appeal, a parliamentary question, an insurer's note, a news brief.
#: (wording, the road users it has, the ego's speed in km/h).
REPORTS = [
    (
        "Last month a resident driving home at 30 mph was hit when an oncoming car turned right across her.",
        ["car"],
        48.3,
    ),
    (
        "A pensioner's car, travelling at about 30 mph on a green light, was struck by a lorry that ran the red.",
        ["truck"],
        48.3,
    ),
    (
        "A car in self-driving mode doing 50 mph failed to slow for a lorry that braked sharply ahead of it.",
        ["truck"],
        80.5,
    ),
    (
        "Police are appealing for witnesses after a taxi doing about 40 km/h was hit by a van that ran the red"
        " light on the left.",
        ["van"],
        40,
    ),
    (
        "Breaking: a minibus travelling at 50 km/h on the N1 was struck by a truck that pulled out of a side road"
        " on the right.",
        ["truck"],
        50,
    ),
]


@pytest.mark.parametrize(("text", "kinds", "ego_kph"), REPORTS)
def test_a_report_that_names_no_ego_brings_its_vehicle_in_as_new(text, kinds, ego_kph):
    reading = read(text)
    assert sorted(a.kind for a in reading.actors) == sorted(kinds)
    if ego_kph is not None:
        assert reading.ego_speed_mps is not None and abs(reading.ego_speed_mps * 3.6 - ego_kph) < 1.0


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # the ego named by a phrase: a new vehicle is another road user
        (
            "The VUT drives at 50 km/h. A car travelling at 60 km/h and a cyclist crossing from the left.",
            [
                "car",
                "bicycle",
            ],
        ),
        (
            "Host vehicle at 50 km/h. A truck travelling at 60 km/h and a pedestrian stepping out from the right.",
            [
                "truck",
                "pedestrian",
            ],
        ),
        # two alike: neither can be told for the ego
        ("A bus and a car were both doing 30 when a cyclist swerved out.", ["truck", "car", "bicycle"]),
    ],
)
def test_a_new_vehicle_stays_a_road_user_where_the_ego_is_named(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


def test_without_the_unnamed_ego_a_report_keeps_its_vehicle(monkeypatch):
    """The first report needs the reading of a text that names no ego ("a ..." would set the vehicle
    apart); the others the reader frames as the ego before (a speed of its own, struck by)."""
    monkeypatch.setattr(ego_double, "ego_unnamed", lambda tokens, clauses, writer_outside=False: False)
    assert [len(read(text).actors) for text, _, _ in REPORTS] == [2, 1, 1, 1, 1]


#: "Both" after someone acted names the ego and that one together: an insurer's note, a text message,
#: a forum post, a witness statement, a radio caller (wording, the road users it has).
BOTH = [
    (
        "Insured was doing 40 mph on a bend when a van coming the other way cut the corner onto his side. Both"
        " drivers braked hard and the vehicles stopped a few feet apart.",
        ["van"],
    ),
    ("A lorry pulled out of a farm gate on the left in front of me and both drivers slammed on.", ["truck"]),
    (
        "I was going about 30 when a ute came round the bend on my side of the road. Both drivers braked and"
        " stopped just in time.",
        ["van"],
    ),
    ("Taxi cut across from the right lane right in front of me, both cars braked hard, no contact.", ["car"]),
    ("Bus pulled out from the stop on my left just ahead of me. Both drivers had to stop dead.", ["truck"]),
]


@pytest.mark.parametrize(("text", "kinds"), BOTH)
def test_both_after_someone_acted_is_the_ego_and_that_one(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # both do something to another: two more road users
        ("A cyclist was riding in the lane and both cars overtook him at speed.", ["bicycle", "car", "car"]),
        # placed: both lorries behind me are two more
        (
            "A van pulled out of a side road in front of me. Both lorries behind me braked hard.",
            ["van", "truck", "truck"],
        ),
        # "two", not "both": new to the story
        ("A van cut the corner onto my side and two cars behind it braked hard.", ["van", "car", "car"]),
    ],
)
def test_both_that_the_words_set_apart_stays_two_road_users(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


def test_without_the_rule_both_would_be_two_more(monkeypatch):
    monkeypatch.setattr(ego_double, "drop_both_said_again", lambda actors, reading: actors)
    assert [len(read(text).actors) for text, _ in BOTH] == [3, 3, 3, 3, 3]


#: The ego's vehicle said again as the one that stops for someone who gets into its path, in several
#: registers (a test spec, a fleet note, a parent's post, a radio log, a trial report), none from a
#: corpus: (wording, the road users it has).
STOPS_FOR_SOMEONE = [
    # a test specification: the vehicle under test stops for the child
    ("A child runs out from the right and the vehicle shall stop without contact.", ["pedestrian"]),
    # a Singaporean driver's text: the lorry said again stops for the uncle crossing
    ("Lorry doing 40 lah then one uncle cross in front suddenly, the lorry stop just in time.", ["pedestrian"]),
    # an operator's post: the shuttle said again as "the vehicle"
    (
        "Our shuttle was doing 18 km/h when a cyclist cut across in front of it and the vehicle came to a"
        " halt well short.",
        ["bicycle"],
    ),
    # a fleet note in Indian English: the truck brakes for a bike coming the wrong way
    ("Our truck was going at 40 when one biker came wrong side and the truck stops in time.", ["bicycle"]),
    # a trial report: the pod stops for a jaywalker
    ("We were at 25 km/h when a man stepped off the kerb on the left and the pod stopped smoothly.", ["pedestrian"]),
    # a dashcam log: the car stops when the van ahead brakes hard
    ("Doing 50. The van in front slammed its brakes on and the car stops with room to spare.", ["van"]),
]


@pytest.mark.parametrize(("text", "kinds"), STOPS_FOR_SOMEONE)
def test_the_vehicle_that_stops_for_someone_in_its_path_is_the_ego(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # the one stopping is hit from behind: it stands in the road, it does not answer anyone
        ("The bus was stopped at the stop when a cyclist rode into the back of it.", ["truck", "bicycle"]),
        # someone goes past it or along it: nothing got into its path
        ("The lorry stopped and a cyclist went up its inside.", ["truck", "bicycle"]),
        ("The taxi stopped and an e-scooter rider overtook it on the right.", ["car", "e-scooter"]),
        # it stops before anyone gets in its way: for its own reason, standing there
        ("The bus stops at a bus stop and a pedestrian walks out in front of it.", ["truck", "pedestrian"]),
        ("The minibus pulled up at the kerb and a boy ran out from in front of it.", ["van", "pedestrian"]),
        # brought in as new: never the ego
        ("A van stopped suddenly when a child ran out in front of me.", ["van", "pedestrian"]),
        # the text calls the ego by name
        ("The car in the next lane stops while a pedestrian crosses 20 m ahead of the ego.", ["car", "pedestrian"]),
    ],
)
def test_a_vehicle_that_only_stops_with_nothing_in_its_path_stays_a_road_user(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("A pedestrian crosses 20 m ahead of the ego.", True),
        ("The ego vehicle brakes for a cyclist.", True),
        ("Ego at 50 km/h; a van cuts in.", True),
        ("The ego's speed is 40 km/h and a child runs out.", True),
        # "ego" as a modifier of what the ego has (its speed, its lane) names no road user apart from others
        ("The vehicle shall stop when a child runs out, at an ego speed of 30 km/h.", False),
        ("Ego velocity 40 km/h. The car brakes when a cyclist cuts in.", False),
        ("The bus must stop for a man who crosses from the left; ego-speed 25 km/h.", False),
    ],
)
def test_ego_as_the_name_of_a_road_user_not_of_its_speed(text, named):
    assert ego_double.names_the_ego(text) is named


def test_a_spec_that_gives_only_the_ego_s_speed_takes_the_stopping_vehicle_for_the_ego():
    text = "A girl steps out from the left and the vehicle shall stop in time, at an ego speed of 20 km/h."
    assert [a.kind for a in read(text).actors] == ["pedestrian"]
