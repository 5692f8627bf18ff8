"""The ego's own vehicle told as the one that turns across a walker or rider (ego_turner.py): a
report, a case study or a test log about a motor vehicle that turns across a cyclist, an e-scooter
rider or a pedestrian makes that vehicle the ego, with its turn as the ego's route."""

from __future__ import annotations

import pytest
from reading_of import kinds

from vei_scenario.language.reader import read

#: The same thing said by different writers: a news item, a campaign's case study, a police note, a
#: study's log, a witness, a fleet report. Each: the text, the ego's route, the road users left.
TURNERS = [
    ("The truck turned right and a cyclist came up its inside.", "right", ["bicycle"]),
    (
        "A lorry turning left at a crossroads struck a cyclist who had ridden up the inside of its cab.",
        "left",
        ["bicycle"],
    ),
    (
        "In 2019 a bin lorry was turning left at the lights when a cyclist, who had come up on its inside, went "
        "straight on and was hit.",
        "left",
        ["bicycle"],
    ),
    (
        "HGV turning left at junction. Cyclist on nearside continued straight ahead. Contact with nearside wheels.",
        "left",
        ["bicycle"],
    ),
    (
        "The instrumented vehicle turns right at a signalised T-junction. The driver stops abruptly when a shared "
        "e-scooter rider travelling straight on in the cycle lane appears in the mirror.",
        "right",
        ["e-scooter"],
    ),
    (
        "A delivery van was turning right into a side road when it hit a pedestrian crossing the side road.",
        "right",
        ["pedestrian"],
    ),
]


@pytest.mark.parametrize(("text", "route", "left"), TURNERS)
def test_the_vehicle_turning_across_a_walker_or_rider_is_the_ego(text: str, route: str, left: list[str]) -> None:
    reading = read(text)
    assert reading.ego_route == route
    assert [a.kind for a in reading.actors] == left


#: Near misses: a turning vehicle that is someone else's.
KEPT = [
    # placed: ahead of the narrator's vehicle
    ("I was driving down Elm St when a car in front turned left across a cyclist.", ["car", "bicycle"]),
    # a second motor vehicle acts: the turner may be anyone's
    ("A car turned right across a cyclist and a van behind it braked hard.", ["car", "bicycle", "van"]),
    # the ego has a turn of its own
    ("Turning left at the lights, I watched a van turn right across a cyclist.", ["van", "bicycle"]),
    # placed: it overtook the narrator first
    ("I was riding my bike when a van overtook me and turned left across me.", ["van"]),
    # brought in as new where a narrator is in the scene
    (
        "We were waiting at the lights when a lorry turning left hit a cyclist who had come up its inside.",
        ["truck", "bicycle"],
    ),
    # placed: oncoming
    ("An oncoming car turned right across a cyclist.", ["car", "bicycle"]),
]


@pytest.mark.parametrize(("text", "expected"), KEPT)
def test_a_turning_vehicle_placed_or_beside_a_narrator_stays_a_road_user(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


#: The vehicle a walker or rider overtakes while it pulls away or goes on, said by different writers:
#: a court report, a bus company's incident note, a driver's training note.
OVERTAKEN = [
    (
        "Bus pulling out from stop. E-scooter rider overtaking the bus on its offside made contact with the front "
        "corner.",
        ["e-scooter"],
    ),
    ("Cyclists will often overtake a bus as it pulls away from a stop and then cut in.", ["bicycle"]),
    (
        "A double-decker was pulling away from the stop when a cyclist overtaking the bus on the right clipped its "
        "mirror.",
        ["bicycle"],
    ),
]


@pytest.mark.parametrize(("text", "expected"), OVERTAKEN)
def test_the_vehicle_a_rider_overtakes_as_it_pulls_away_is_the_ego(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


#: Near misses: the overtaken vehicle is someone else's.
OVERTAKEN_KEPT = [
    # the narrator is met: the narrator is the ego
    ("A cyclist overtook a bus pulling away from the stop and cut in front of me.", ["bicycle", "truck"]),
    # parked: it stands at the side
    ("A cyclist overtook a parked bus and swerved.", ["bicycle", "truck"]),
    # placed ahead of the narrator
    ("A cyclist overtook the bus ahead of us.", ["bicycle", "truck"]),
    # slower than the traffic
    ("A cyclist overtook a slow-moving bus and then braked.", ["bicycle", "truck"]),
]


@pytest.mark.parametrize(("text", "expected"), OVERTAKEN_KEPT)
def test_an_overtaken_vehicle_placed_or_beside_a_narrator_stays_a_road_user(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected
