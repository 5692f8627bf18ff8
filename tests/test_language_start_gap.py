"""Where a road user starts is the distance said where it is put in the scene: a distance said of it in a
later sentence (a threshold, a trigger point, a question about another value, how far one can see) is
when something happens, not where it starts; a gap said before it was named (of someone else) gives
way to its own."""

import pytest

from vei_scenario.language.reader import read


def _gaps(text: str) -> list[float | None]:
    return [a.distance_m for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "gap"),
    [
        # a test spec: placed, then a trigger point in the next sentence
        (
            "Ego at 100 km/h on a motorway. A lorry is parked on the hard shoulder 200 m ahead. "
            "At 60 m it pulls out into lane 1.",
            200,
        ),
        # a simulator script: spawn point, then a threshold for the trainee
        (
            "You drive at 80 km/h. A cyclist rides along the left edge about 70 m ahead of you. "
            "If you have not slowed by 25 m, the car brakes on its own.",
            70,
        ),
        # a student's question about another value
        (
            "The ego drives at 90 km/h. A car in the right lane cuts in with a 12 m gap at 70 km/h. "
            "Would it be better with 25 m?",
            12,
        ),
        # a voice note: where it was, then how far the driver could see
        (
            "I'm doing 50 and there's a tractor pulling out of a farm track on my left, maybe 40 metres up. "
            "Fog so thick you couldn't see past 100 metres.",
            40,
        ),
        # a police report: the distance at first sight, then a later one in the account
        (
            "Vehicle 1 was travelling at 30 mph when a pedestrian stepped out approx 15 metres ahead. "
            "The pedestrian was struck when vehicle 1 had travelled a further 5 m.",
            15,
        ),
    ],
)
def test_the_distance_said_where_it_is_placed_is_its_start(text: str, gap: float) -> None:
    assert gap in _gaps(text)


def test_a_gap_said_before_it_is_named_gives_way_to_its_own() -> None:
    # (the time gap is to the truck ahead; the car's own distance comes with the car)
    text = (
        "Ego is the second truck of a platoon at 80 km/h, 1 s time gap to the lead truck. "
        "A car from the left lane cuts in between them, 12 m ahead of the ego."
    )
    assert 12 in _gaps(text)


@pytest.mark.parametrize(
    ("text", "gap"),
    [
        # one sentence, one distance: unchanged
        ("A van brakes hard 25 m ahead of the ego at 60 km/h.", 25),
        # a later sentence gives its distance and none was said before: taken
        ("The ego drives at 50 km/h. A cyclist rides ahead. It is 30 m ahead of the ego.", 30),
    ],
)
def test_one_distance_is_taken_as_before(text: str, gap: float) -> None:
    assert gap in _gaps(text)


@pytest.mark.parametrize(
    "text",
    [
        "A child runs out from behind a parked car on the right when the ego is 12 m away.",
        "The ego drives at 40 km/h. A man steps out from between two parked vans when the ego is 12 m from him.",
        "A cyclist, hidden behind a row of parked cars, enters the road when the ego vehicle is 12 m away.",
        "Ego 30 mph. Jogger emerges from behind a parked bus on the left, ego 12 m away at that moment.",
        "We were doing 25 when a kid on a scooter shot out from behind a parked lorry, we were about 12 m off.",
    ],
)
def test_a_gap_said_of_the_ego_is_to_the_one_coming_out_not_its_cover(text: str) -> None:
    reading = read(text)
    movers = [a for a in reading.actors if a.kind in ("pedestrian", "bicycle", "e-scooter")]
    assert [a.distance_m for a in movers] == [12]
    assert all(a.distance_m is None for a in reading.actors if a not in movers)


def test_a_gap_to_a_parked_car_said_alone_stays_its_own() -> None:
    # (nobody comes out of it: the parked car is the one the gap is to)
    text = "The ego drives at 30 km/h. A car is parked on the left; the ego is 20 m away when it pulls out."
    assert _gaps(text) == [20]


def test_a_gap_to_one_standing_in_the_road_stays_its_own() -> None:
    # (a stopped rider in the lane is what the ego comes up to, not cover; the car went away before)
    text = (
        "The car in front of me swerved into the left lane, and a guy on a scooter was stopped in the "
        "middle of the lane. I was doing 30 and we were 10 m from him when I saw him."
    )
    assert [a.distance_m for a in read(text).actors if a.kind == "e-scooter"] == [10]
