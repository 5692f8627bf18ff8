"""A vehicle named by its owner is the ego when the story is told about it: the narrator who drives
someone else's vehicle ("I was driving my dad's Corolla"), or the vehicle of one of the narrator's
party or of a named person that the story happens to ("Our daughter's hatchback was clipped by a
cyclist", "Mrs Okafor's car was hit by a lorry"). Read as one more road user, it would be an extra
adversary that is really the ego."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was driving my dad's Corolla at 30 mph when a cyclist swerved in front of me.", ["bicycle"]),
        ("We were in my sister's Polo, I was driving it, when a lorry pulled out on us.", ["truck"]),
        ("I drive my mum's Corsa sometimes. A lad on a scooter shot out from the left in front of me.", ["e-scooter"]),
        ("I was driving my mate's ute doing 60 km/h and a cyclist swerved out ahead of me", ["bicycle"]),
        ("I was driving the company's van at about 20 mph when a kid ran out in front of me.", ["pedestrian"]),
        ("i drove my uncle's car home and a bus pulled out of the stop right in front of me", ["truck"]),
    ],
    ids=["dads-corolla", "sisters-polo", "mums-corsa", "mates-ute", "companys-van", "uncles-car"],
)
def test_the_narrator_driving_someone_elses_vehicle_drives_the_ego(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was driving my dad's car behind a lorry when the lorry braked hard.", ["truck"]),
        ("I was cycling home when my neighbour's van reversed out of a drive in front of me.", ["van"]),
        ("I was driving along when my neighbour's van pulled out in front of me.", ["van"]),
    ],
    ids=["followed-lorry", "narrator-cycling", "neighbours-van-meets-me"],
)
def test_someone_elses_vehicle_that_meets_the_narrator_stays_a_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Our daughter's hatchback was hit by a cyclist who ran the red light at the crossroads.", ["bicycle"]),
        ("My husband's car was hit by a bus pulling out of the depot. He was doing about 20 mph.", ["truck"]),
        ("Mrs Okafor's car was struck on the roundabout by a lorry that never looked.", ["truck"]),
        ("our trainee's van was trundling along at 30 km/h behind a man on a scooter in the bike lane", ["e-scooter"]),
        ("Yesterday Mr Tan's taxi was hit by a moped that jumped the red light.", ["car"]),
        ("My son's Fiesta got rear-ended by a tipper truck at the lights, he's fine.", ["truck"]),
    ],
    ids=["daughters-hatchback", "husbands-car", "mrs-car", "trainees-van", "mr-taxi", "sons-fiesta"],
)
def test_the_vehicle_of_the_person_the_story_is_about_is_the_ego(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("I was behind my neighbour's car when a cyclist cut in front of it.", ["car", "bicycle"]),
        ("I was overtaking Mr Tan's taxi when it swerved into my lane.", ["car"]),
        ("My son was riding his bike when a van pulled out of a side road and hit him.", ["van"]),
    ],
    ids=["narrator-behind-it", "narrator-overtaking-it", "son-on-a-bike"],
)
def test_an_owned_vehicle_the_narrator_meets_or_no_vehicle_stays_as_read(text, expected):
    assert kinds(text) == expected


def test_the_driver_of_the_owned_vehicle_is_the_egos_driver():
    text = (
        "Our instructor's car was crawling along at 20 km/h behind a man on a bike. "
        "The driver held back until the road was clear and then overtook him wide."
    )
    assert kinds(text) == ["bicycle"]


def test_an_owned_vehicle_standing_is_read_as_without_its_owner():
    owned = "My neighbour's car was parked outside when a lorry reversed into it."
    assert kinds(owned) == kinds("The car was parked outside when a lorry reversed into it.")
