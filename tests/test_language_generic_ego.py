"""The ego of a text that speaks of drivers in general (vei_scenario.language.generic_ego) and the
ego's speed said by a limit it keeps or of traffic in general (vei_scenario.language.ego_speed):
the driver in general is the ego, never one more car, unless it does something to someone in traffic
named as generally, who is then the ego."""

from __future__ import annotations

import pytest
from reading_of import ego_kph as _ego_kph
from reading_of import kinds

from vei_scenario.language.ego_speed import at_the_limit, of_traffic
from vei_scenario.language.generic_ego import frame
from vei_scenario.language.reader import _kind_at, _known, _tokens, read


def _kinds(text: str) -> list[str]:
    return sorted(kinds(text))


# A driver said in general ("a driver", "drivers", "motorists") who does the scenario's driving is the
# ego: the road users it meets stay actors, and its speed is the ego's.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("Usual pattern here: a driver coming down the hill at around 35 mph finds a pedestrian stepping out "
         "from the right.", ["pedestrian"], 56.3),
        ("Motorists leaving the village at 50 km/h meet a tractor pulling out of a farm track on the left.",
         ["truck"], 50.0),
        ("What happens most evenings: drivers travelling at 30 mph on the bypass are overtaken by a van "
         "that cuts in sharply.", ["van"], 48.3),
        ("Picture a driver at 60 km/h on the ring road when a cyclist swerves out of the cycle lane ahead.",
         ["bicycle"], 60.0),
    ],
)  # fmt: skip
def test_a_driver_in_general_is_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


# A narrator who only reports or sees what drivers go through is no road user; the driver is the ego.
@pytest.mark.parametrize(
    "text",
    [
        "We often see drivers heading into town at 40 mph surprised by a jogger crossing from the left.",
        "I have had several complaints about motorists at 30 mph meeting a cyclist who rides out of the park.",
        "We get reports of drivers at 50 km/h that hit a deer crossing from the right.",
    ],
)
def test_a_narrator_who_only_reports_leaves_the_driver_the_ego(text):
    assert len(read(text).actors) == 1
    assert _ego_kph(text) is not None


# What a driver in general does to someone in traffic named as generally ("a vehicle", "traffic")
# happens to that one, the ego: the driver is the actor.
@pytest.mark.parametrize(
    "text, kinds",
    [
        ("Typically a driver on the slip road pushes in front of a vehicle in the inside lane.", ["car"]),
        ("A driver leaving the car park reverses out into passing traffic.", ["car"]),
        ("Now and then a driver turns right across oncoming traffic without looking.", ["car"]),
    ],
)
def test_what_a_driver_does_to_traffic_happens_to_the_ego(text, kinds):
    r = read(text)
    assert _kinds(text) == kinds
    assert r.actors[0].behaviours, "the driver is the actor and does what is said"


# Near misses: a driver in particular ("a drunk driver", "the bus driver", "the driver of the van"),
# "the driver" of a vehicle named before, or any text that names its ego ("I", "you", "my") keeps its
# words: no one is said the ego.
@pytest.mark.parametrize(
    "text",
    [
        "A drunk driver swerves into the oncoming lane at night.",
        "The bus driver pulls out from the stop in front of a cyclist.",
        "A van pulls out of a side road and the driver waves a cyclist across.",
        "The driver of the lorry brakes hard for a pedestrian.",
        "You are following a driver who brakes suddenly.",
        "A driver pulls out of a side road in front of my car.",
        "A wrong-way driver comes straight at a cyclist on the bypass.",
    ],
)
def test_a_driver_in_particular_is_no_ego(text):
    tokens = _tokens(text, brackets=True)
    assert frame(tokens, _kind_at, _known, []) == tokens


# Going at a limit is going at that speed; a limit said of the road alone is no speed of going.
@pytest.mark.parametrize(
    "tokens, said",
    [
        ("drivers doing the 30 limit brake late", "drivers doing 30 brake late"),
        ("i was sitting at the 50 mph limit", "i was sitting at 50 mph"),
        ("keeping to the 40 km/h speed limit the ego meets", "keeping to 40 km/h the ego meets"),
        ("a road with the 30 limit", "a road with the 30 limit"),
        ("the ego exceeds the 20 limit", "the ego exceeds the 20 limit"),
        ("going at a 60 limit", "going at a 60 limit"),
    ],
)
def test_going_at_the_limit_is_that_speed(tokens, said):
    assert " ".join(at_the_limit(tokens.split())) == said


def test_a_driver_keeping_to_the_limit_has_that_speed():
    assert _ego_kph("I was keeping to the 40 mph limit when a deer jumped out from the right.") == 64.4


# Traffic in general ("Cars are usually doing 20 mph here") goes at the ego's speed; the speed of
# particular cars ("the cars", "two cars") is theirs.
@pytest.mark.parametrize(
    "tokens, kph",
    [
        ("vehicles typically travel at about 40 mph through the village .", 64.4),
        ("it is quiet . traffic is normally moving at 25 km/h here .", 25.0),
        ("on this stretch , motorists are usually doing 60 km/h .", 60.0),
        ("the cars are doing 50 km/h .", None),
        ("two cars are doing 50 km/h .", None),
        ("cars parked at 50 m intervals .", None),
    ],
)
def test_the_speed_of_traffic_in_general(tokens, kph):
    mps = of_traffic(tokens.split())
    assert (None if mps is None else round(mps * 3.6, 1)) == kph


def test_traffic_speed_is_the_ego_speed_where_none_is_said_of_it():
    text = "Vehicles usually travel at about 30 mph on this street. A cyclist often pulls out from the left."
    assert _ego_kph(text) == 48.3
    assert _ego_kph("I was doing 20 km/h. Cars usually travel at 50 km/h here. A cyclist pulls out.") == 20.0


# A speed after a participle whose subject follows "with" is that subject's ("with us coming at 80
# km/h": the ego's, as the text is told from it; "with a bus coming at 30 mph": the bus's).
@pytest.mark.parametrize(
    "text, kph",
    [
        ("A delivery van reverses out of a driveway on the right with us coming at 45 km/h.", 45.0),
        ("A jogger crosses from the left kerb with me driving at 20 mph.", 32.2),
        ("A cyclist drifts into the lane, with the ego approaching at 60 km/h.", 60.0),
    ],
)
def test_the_speed_of_a_participle_after_with_is_its_subjects(text, kph):
    assert _ego_kph(text) == kph
    assert all(a.speed_mps is None for a in read(text).actors)


def test_the_speed_after_with_of_another_road_user_is_its_own():
    r = read("A pedestrian steps out with a bus coming at 30 mph behind the ego.")
    assert r.ego_speed_mps is None
    assert [round(a.speed_mps * 3.6, 1) for a in r.actors if a.speed_mps] == [48.3]


# A numbered reference in square brackets says no quantity of the scene ("the taxonomy of [12]").
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Following the method of [14], a cyclist crosses from the left in front of the ego.", None),
        ("As described in [3, 5], the ego drives at 40 km/h and a pedestrian steps out from the right.", 40.0),
        ("Going by [7], a van cuts in front of the ego.", None),
    ],
)
def test_a_citation_is_no_speed(text, kph):
    assert _ego_kph(text) == kph


def test_a_bracketed_label_with_words_stays():
    from vei_scenario.language.quantities import citations

    assert citations("see [12] and [3-4]") == "see   and  "
    assert citations("[ALERT] lane 2 [a]") == "[ALERT] lane 2 [a]"


# Where no vehicle is named that a driver could be at the wheel of, "the driver" is the driver spoken
# of in general, the ego: its side is the ego's side, and it is never one more car.
@pytest.mark.parametrize(
    "text, kerb_side",
    [
        ("Set it up so that a boy on a bike rides out of a gate on the driver's right.", "right"),
        ("A dog darts out from behind the hedge on the driver's left. Drivers on this lane go too fast.", "left"),
        ("Typical report: a jogger steps off the kerb on the driver's left. Motorists only see her late.",
         "left"),
    ],
)  # fmt: skip
def test_the_driver_with_no_vehicle_to_drive_is_the_ego(text, kerb_side):
    r = read(text)
    assert len(r.actors) == 1 and r.actors[0].kind != "car"
    assert kerb_side in (r.actors[0].relation or "")


def test_the_driver_of_a_vehicle_named_is_that_vehicles():
    tokens = _tokens("A lorry reverses out of a yard and the driver waves a cyclist past.", brackets=True)
    assert frame(tokens, _kind_at, _known, []) == tokens


# A bare plural of vehicles opening its sentence on the move ("Cars coming down the hill ...") is
# traffic in general: the ego, not one more car; vehicles standing ("Cars were parked") are not.
@pytest.mark.parametrize(
    "text, kinds, kph",
    [
        ("Cars coming down the hill at 40 mph have little time to stop when a pedestrian steps out from the left.",
         ["pedestrian"], 64.4),
        ("Near the school gates. Vehicles pulling away from the lights at 30 km/h meet children crossing "
         "from the right.", ["pedestrian"], 30.0),
        ("Cars overtake a cyclist on this bend while a van comes the other way. Cars travel at 50 mph.",
         ["bicycle", "van"], 80.5),
    ],
)  # fmt: skip
def test_traffic_in_general_on_the_move_is_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


@pytest.mark.parametrize(
    "text",
    [
        "Cars were parked on both sides. A child runs out from between them.",
        "The cars coming down the hill brake for a pedestrian.",
        "Two cars come down the hill and a pedestrian steps out.",
        "Cars coming down the hill meet me at the bend.",
    ],
)
def test_vehicles_in_particular_or_standing_are_no_ego(text):
    tokens = _tokens(text, brackets=True)
    assert frame(tokens, _kind_at, _known, []) == tokens


# Once a road user is said right ahead of the ego, "the following driver" (car, vehicle) is the one
# following it: the ego, not one more car behind.
@pytest.mark.parametrize(
    "text, kinds",
    [
        ("The lorry ahead of me pulls out round a parked bus and the following car has to brake hard.",
         ["truck", "truck"]),
        ("The van in front of you stops dead at a bus stop, and the following driver swerves.",
         ["van"]),
        ("A bus right ahead of the ego brakes, and the following vehicle stops just in time.", ["truck"]),
    ],
)  # fmt: skip
def test_the_follower_of_the_ego_lead_is_the_ego(text, kinds):
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist brakes hard and the following car runs into her.",
        "The van ahead of the cyclist brakes and the following car hits it.",
    ],
)
def test_a_follower_of_someone_else_stays_a_road_user(text):
    tokens = _tokens(text, brackets=True)
    assert frame(tokens, _kind_at, _known, []) == tokens


def test_a_narrator_who_has_a_driver_do_something_is_the_ego():
    tokens = _tokens("I had a driver pull out right in front at the junction.", brackets=True)
    assert frame(tokens, _kind_at, _known, []) == tokens
    tokens = _tokens("We get complaints about drivers speeding past a cyclist.", brackets=True)
    assert frame(tokens, _kind_at, _known, []) != tokens


# Advice told to "you" often opens with what road users of a kind are like ("Motorbikes are quick and
# easy to miss"): a bare plural with a present "are" and no verb of its own after it is the kind in
# general, not one more road user, when the scene then introduces one of that kind ("a motorbike").
# "Cyclists are riding two abreast ahead of me" (a verb of its own) is those cyclists.
@pytest.mark.parametrize(
    "text, kinds",
    [
        (
            "Motorbikes are quick and easy to miss. Say you are waiting to turn right out of a side road and "
            "a motorbike comes from your left at 40 mph.",
            ["car"],
        ),
        (
            "Buses are long and slow to stop. Imagine you are doing 30 mph and a bus pulls out from a stop "
            "on your left.",
            ["truck"],
        ),
    ],
)
def test_a_kind_said_in_general_before_one_of_it_is_no_road_user(text, kinds):
    assert [a.kind for a in read(text).actors] == kinds


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("Cyclists are riding two abreast ahead of me and a cyclist on the right swerves out.", 2),
        ("Motorbikes are coming towards me in the other lane and a motorbike pulls out to overtake.", 2),
    ],
)
def test_a_plural_doing_something_now_is_road_users(text, kinds):
    assert len(read(text).actors) == kinds
