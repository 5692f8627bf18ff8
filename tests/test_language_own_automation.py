"""The writer's own car acting by itself: a first-person writer who says "the car braked by itself" tells
of the car they sit in (its automation), never introduced with "a": that car, and its make said
before ("the Tesla"), is the ego, no road user. Said by many kinds of writer, with near misses where
the car acting by itself is someone else's (placed, or introduced as new)."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    "text, expected",
    [
        # (an American text message, the make first)
        (
            "so the tesla did a weird thing on the interstate. going 70, a pickup merged into our lane "
            "and the car just slammed the brakes by itself.",
            ["van"],
        ),
        # (a British driver)
        ("We were at 30 mph when a lad ran out between the shops and the car stopped on its own.", ["pedestrian"]),
        # (an Australian voice note)
        ("Doin' about 80 on the highway, a road train moved over on us and the ute braked by itself.", ["truck"]),
        # (an Indian message)
        ("Going 60 kmph on the expressway, one bike cut in from left and the car applied brake automatically.",
         ["bicycle"]),
        # (a review of a new car)
        ("At 40 mph in town a cyclist swerved out in front of us and the Volvo braked of its own accord.",
         ["bicycle"]),
    ],
)  # fmt: skip
def test_the_writers_car_acting_by_itself_is_the_ego(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # (placed: the car ahead is someone else's)
        ("I was doing 30 when a kid on a bike came out in front of me and the car in front braked by itself.",
         ["bicycle", "car"]),
        # (a car introduced with "a" is someone new, and "the car" is that one again)
        ("I was doing 30 when a car pulled out of a side road in front of me; the car then stopped on its own.",
         ["car"]),
    ],
)  # fmt: skip
def test_a_placed_or_introduced_car_acting_by_itself_stays_a_road_user(text, expected):
    assert kinds(text) == expected


# --- a writer who leaves out the article: "I stop car", what the writer steers is the writer's ------
@pytest.mark.parametrize(
    "text, expected",
    [
        # (a Singaporean text)
        ("The scooter fella ride against traffic on my side, I stop car let him go past lor.", ["e-scooter"]),
        # (an Indian email)
        ("One cyclist came suddenly from the left side, I stopped vehicle immediately, no contact.", ["bicycle"]),
        # (a Nigerian message)
        ("One boy on bicycle just cross in front of me for Wuse, I park car quick quick, nothing happen.",
         ["bicycle"]),
        # (a text message)
        ("kid on a bike shot out, i slowed van right down, he was fine", ["bicycle"]),
        # (a spoken note)
        ("Jogger ran out at the lights, we stopped car dead, no harm done.", ["pedestrian"]),
    ],
)  # fmt: skip
def test_the_bare_vehicle_a_writer_steers_is_the_ego(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # (someone else steers it)
        ("A cyclist came out of the side road; the lorry driver stopped lorry right on the crossing.",
         ["bicycle", "truck"]),
        # (a new one is someone's: "stopped a car")
        ("I was cycling at 15 km/h when the police stopped a car in front of me.", ["car"]),
    ],
)  # fmt: skip
def test_a_vehicle_steered_by_someone_else_stays_a_road_user(text, expected):
    assert kinds(text) == expected
