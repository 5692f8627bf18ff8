"""The vehicle a third-person report is about is the ego (news, witness statements, logs, minutes,
exam questions), found by what the text says of it: a speed of its own, a reaction, another road user
placed by its path or side; never a parked vehicle, nor one met by an ego the text leaves unsaid."""

from __future__ import annotations

import pytest
from reading_of import ego_kph as _ego_kph
from reading_of import kinds

from vei_scenario.language import protagonist
from vei_scenario.language.reader import _kind_at, _known, _tokens


def _kinds(text: str) -> list[str]:
    return sorted(kinds(text))


@pytest.mark.parametrize(
    ("text", "kinds", "kph"),
    [
        (  # a witness statement: its speed, a rider into its path, its reaction
            "The witness says she saw a red Skoda Fabia heading south at about 30 mph. A boy on a bicycle "
            "rode out of a driveway into the path of the Skoda, and the Skoda braked hard.",
            ["bicycle"],
            48.3,
        ),
        (  # an exam question: the one vehicle with a speed of its own
            "A lorry moves along a level road at 15 m/s. A jogger runs into the road 30 m ahead.",
            ["pedestrian"],
            54.0,
        ),
        (  # a fleet log: a heading names the vehicle, its bare driver has the speed and reacts
            "Log 14/2, school minibus. Driver was leaving the depot at 10 mph when a jogger ran across the front of "
            "the minibus. Driver stopped.",
            ["pedestrian"],
            16.1,
        ),
        (  # minutes: the one vehicle whose driver reacts, with a speed in a relative aside
            "Members heard about a council gritter, which was doing 20 mph, on Mill Hill. A teenager on an "
            "e-scooter came towards the gritter on the wrong side. The driver stopped.",
            ["e-scooter"],
            32.2,
        ),
        (  # a news item: the vehicle named by its driver, past an apposition, reacts
            "A dog ran into the road in front of a Fiat on Tuesday. The driver of the Fiat, a retired "
            "teacher, swerved and nobody was hurt.",
            ["pedestrian"],
            None,
        ),
    ],
)
def test_the_vehicle_a_third_person_report_is_about_is_the_ego(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


@pytest.mark.parametrize(
    "text",
    [
        "The lead van slows gently and stops.",  # (no one else: an unsaid ego meets it)
        "A cyclist riding at 25 km/h is overtaken by a bus.",  # (the cyclist's story, not the bus's)
        "A van and a car collided at the junction.",  # (neither is told about)
        "The car in front pulls out round a broken-down lorry, 60 km/h.",  # (placed; the speed is the ego's)
        "Two buses doing 30 mph met a cyclist who braked.",  # (many, not one)
        "The tram halts at its platform and a boy runs out in front of it.",  # (its own stop, no reaction)
    ],
)
def test_a_vehicle_no_report_is_about_stays_a_road_user(text):
    tokens = _tokens(text, brackets=True)
    assert protagonist.frame(list(tokens), _kind_at, _known, []) == tokens


def test_a_parked_vehicle_is_never_the_ego():
    text = (
        "A witness sitting in a parked car saw a pedestrian step out in front of a lorry that was doing "
        "30 mph. The lorry braked."
    )
    assert _ego_kph(text) == 48.3
    assert "truck" not in _kinds(text)


@pytest.mark.parametrize(
    ("text", "kinds", "kph"),
    [
        (
            "The caller, who was the back-seat passenger in the silver minibus, states that the minibus was doing "
            "40 mph when a cyclist swerved into its path. The minibus driver braked.",
            ["bicycle"],
            64.4,
        ),
        (
            "Sam, driving a blue tipper lorry, says the lorry was at 25 mph when a jogger stepped out. The "
            "lorry driver stopped.",
            ["pedestrian"],
            40.2,
        ),
        (
            "The witness, who was the rear passenger in the black cab, states that the cab was going at 20 mph "
            "when a man on a moped pulled out in front of the cab driver.",
            ["car"],
            32.2,
        ),
    ],
)
def test_the_vehicle_a_person_is_in_stays_the_ego_when_said_again(text, kinds, kph):
    assert _kinds(text) == kinds
    assert _ego_kph(text) == kph


def test_another_vehicle_and_its_driver_stay_a_road_user():
    text = (
        "The caller, who was the back-seat passenger in the silver minibus, states that a lorry overtook the "
        "minibus at 50 mph. The lorry driver waved."
    )
    assert _kinds(text) == ["truck"]


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        (
            "Just seen a girl on a hire scooter go through a red, the bus driver had to brake really hard.",
            ["e-scooter"],
        ),
        ("A man on a push bike jumped the lights on Market St and the van driver had to swerve.", ["bicycle"]),
        ("Witnessed a jogger dart across the road. The taxi driver braked just in time.", ["pedestrian"]),
        ("kid on a bmx came flying off the kerb, lorry driver braked, no contact", ["bicycle"]),
        ("A cyclist swung out into the road and the coach driver had to brake sharply.", ["bicycle"]),
        ("An elderly man stepped off the pavement without looking and the minibus driver swerved.", ["pedestrian"]),
    ],
)
def test_a_vehicle_driver_who_reacts_is_the_ego_vehicle(text, kinds):
    """ "The bus driver had to brake" is the bus reacting: a witness's report is about that vehicle."""
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    "text",
    [
        "The bus driver was parked at the stand when a man on a scooter rode into the shelter.",
    ],
)
def test_a_vehicle_driver_who_does_not_react_stays_a_road_user(text):
    assert len(_kinds(text)) == 2


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("I saw a lad on a bike go straight through the red and the taxi driver had to brake hard.", ["bicycle"]),
        ("I've just seen a woman on a hire scooter shoot off the kerb, the bus had to brake sharply.", ["e-scooter"]),
        ("We watched a jogger run out into the road and the delivery van swerved.", ["pedestrian"]),
        ("I was outside the chemist and saw a boy on a scooter jump the lights, the cab driver braked.", ["e-scooter"]),
        ("I noticed a cyclist pull out of the side road and the minibus had to stop sharply.", ["bicycle"]),
    ],
)
def test_a_writer_who_only_watched_is_a_witness(text, kinds):
    """A writer who is only the one who saw it is no road user: the vehicle that reacts is the ego."""
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    "text",
    [
        "I saw a kid on a scooter run out and I braked hard, the bus behind me stopped too.",
        "I saw a cyclist jump the lights in front of my car and the van driver braked.",
        "I saw the van in front brake hard for a cyclist.",
    ],
)
def test_a_writer_in_the_traffic_stays_the_ego(text):
    from vei_scenario.language import protagonist

    assert protagonist.without_witness(_tokens(text), []) == _tokens(text)


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("A jogger darted across the road. The taxi driver stopped just in time.", ["pedestrian"]),
        ("A kid on a bike shot out of a driveway, the van stopped a metre from him.", ["bicycle"]),
        ("A woman stepped off the kerb without looking and the lorry stopped inches from her.", ["pedestrian"]),
    ],
)
def test_a_vehicle_that_stopped_for_someone_is_the_ego(text, kinds):
    """ "The van stopped" is its reaction, not a stopped (standing) van."""
    assert _kinds(text) == kinds


def test_a_vehicle_said_stopped_still_stands():
    text = "The bus was stopped at the stop when a cyclist rode into the back of it."
    assert len(_kinds(text)) == 2
