"""The one motor vehicle of a report with no narrator, beside walkers or riders only, is the ego: an
exam question, a parliamentary question, an inquest, a fleet log or a news line is told about the
vehicle that meets the walker or rider, even where it says "your" to its reader or names the ego by
a phrase. Wordings written for the class in several registers, none taken from a corpus; near misses
that look alike keep their road users."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds

#: The report's vehicle meets a walker or rider and goes on or brakes: only the walker or rider is left.
REPORTS = [
    (
        "A bus is moving at 10 m/s when the driver spots a cyclist 20 m ahead riding at 3 m/s in the same"
        " direction. Calculate the time before the bus reaches the cyclist. Give your answer to 2 d.p.",
        ["bicycle"],
    ),
    (
        "A pedestrian stepped out from behind a parked lorry on the right and a car travelling at about"
        " 30 mph hit her. Show your working.",
        ["pedestrian", "truck"],  # (the parked lorry stays, as scenery)
    ),
    (
        "A lorry is travelling at 12 m/s when the driver notices a cyclist 25 m ahead moving the same way"
        " at 4 m/s. Work out whether the lorry must brake. Show your method.",
        ["bicycle"],
    ),
    (
        "To ask the Minister what her Department has learnt from the driverless bus trial, after reports"
        " that on 5 May a trial vehicle travelling at about 7 metres per second struck a cyclist who rode"
        " off the pavement into its path.",
        ["bicycle"],
    ),
    (
        "Mrs Osei was driving straight ahead through the crossroads in her Kia at about 25 mph on a green"
        " light. The cyclist came into the junction from her left. Despite braking, she hit him.",
        ["bicycle"],
    ),
    (
        "A Ford Fiesta driven by Ms R. Okoro was leaving the car park along the service road at about"
        " 20 mph; the cyclist came from her left. She braked but could not avoid him.",
        ["bicycle"],
    ),
    (
        "Mr Lee, a taxi driver, was going straight on at the junction in his Prius at 30 km/h. The"
        " e-scooter came in from his right. He braked but collided with it.",
        ["e-scooter"],
    ),
    (
        # (only braking for the one who brakes ahead of it: the vehicle the scenario is told from)
        "A cyclist brakes hard in front of a car and the car hits the brakes.",
        ["bicycle"],
    ),
]


@pytest.mark.parametrize(("text", "expected"), REPORTS)
def test_the_report_vehicle_is_the_ego(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


#: Near misses: a narrator in the scene on a bike has the ego, and the vehicle is someone else (a
#: writer on foot is in no vehicle: tests/test_language_writer_on_foot.py); two motor vehicles (either
#: may be the report's); a parked vehicle that hides someone.
NEAR_MISSES = [
    ("We were cycling along the canal road when a van going about 30 mph clipped my friend's bike.", "van"),
    (
        "A car travelling at 30 mph braked hard for a cyclist crossing ahead, and a van behind it ran into"
        " its back. Explain your answer.",
        "car",
    ),
    ("A cyclist rode out from behind a parked bus into the road. Was your brake test fair?", "truck"),
    ("A bus was parked at the stop when a child ran out from in front of it. Show your working.", "truck"),
]


@pytest.mark.parametrize(("text", "kept"), NEAR_MISSES)
def test_near_misses_keep_the_vehicle(text: str, kept: str) -> None:
    assert kept in kinds(text)


def test_a_vehicle_ahead_that_brakes_for_a_walker_stays() -> None:
    got = kinds(
        "Car A was doing about 25 mph behind Car B, a silver Astra, when Car B stopped sharply for a child"
        " who had run into the road."
    )
    assert "car" in got and "pedestrian" in got


def test_a_new_vehicle_beside_an_ego_phrase_stays() -> None:
    got = kinds(
        "The subject vehicle drives at 40 km/h. A van travelling at 50 km/h and a pedestrian crossing from the left."
    )
    assert "van" in got
