"""A kind of walker or rider named in general ("e-scooters are a menace", "cyclists never look",
"riders come off the path at full speed") beside one of that kind that the description is about is no
road user of its own: the plural says what such road users do, the singular (or the counted ones) is
the one in the scene. Wordings written for the class in several registers (a petition, a voice note,
a council newsletter, a forum post, a text message, a police note); near misses keep their road users."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "These e-scooters are a menace on our street. This morning a rider shot off the pavement on my"
            " left right in front of my car at 25 mph.",
            ["e-scooter"],
        ),
        (
            "Cyclists ride straight through the red here all the time. Yesterday a cyclist came out of the"
            " side road on the right and across my bonnet while I was doing 30.",
            ["bicycle"],
        ),
        (
            "Scooter riders keep coming off the cycle track without looking. Last week a rider came off the"
            " track on my left and across in front of me as I drove along at 20 mph.",
            ["e-scooter"],
        ),
        (
            "What's wrong, mate, is the scooters. I was doing 40 down the high street and a kid on a scooter"
            " came straight out from the right in front of me.",
            ["e-scooter"],
        ),
        (
            "Pedestrians cross wherever they like on this road. Driving at 30 km/h, a man stepped off the"
            " kerb on the right without looking and I braked hard.",
            ["pedestrian"],
        ),
        (
            "E-bikes are everywhere now lol. one came flying out of a driveway on my left at like 20, i was"
            " doing 30, missed him by inches",
            ["bicycle"],
        ),
    ],
)
def test_a_kind_named_in_general_beside_one_of_it_is_no_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # counted: two riders stay two
        (
            "Two cyclists were riding side by side ahead of me at 20 km/h when one swerved into my lane.",
            ["bicycle", "bicycle"],
        ),
        # a rider and a walker are two
        (
            "Cyclists were riding along the lane ahead of me, and a pedestrian stepped out from the left"
            " in front of me at 30 km/h.",
            ["bicycle", "pedestrian"],
        ),
        # told as doing something then or now: those ones are there
        (
            "Kids on scooters were racing down the hill towards me, and a kid on a scooter swerved out in"
            " front of me at 20 mph.",
            ["e-scooter", "e-scooter"],
        ),
        (
            "Cyclists are riding two abreast in the lane ahead of me and a cyclist on the left pulls out.",
            ["bicycle", "bicycle"],
        ),
        # set apart: the other ones are others there
        (
            "A cyclist cut across in front of me from the left while the other cyclists waited at the lights.",
            ["bicycle", "bicycle"],
        ),
        # alone, the plural is what the description is about
        (
            "E-scooter riders came off the path on my left and across in front of me as I drove at 20 mph.",
            ["e-scooter"],
        ),
    ],
)
def test_counted_alone_or_of_another_kind_stay(text, expected):
    assert kinds(text) == expected
