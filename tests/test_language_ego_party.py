"""One of the narrator's party (a family word, a friend) who has a vehicle out drives the ego: "My dad
took the car into town. He was turning right ..." tells that car's story, not another road user's."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph, kinds
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    "text, kind, route",
    [
        (
            "My dad took the car into town. He was turning right out of the car wash when a cyclist hit him.",
            "bicycle",
            "right",
        ),
        (
            "Your grandad had the Volvo out. He was turning left into the lane when a lad on a bike clipped him.",
            "bicycle",
            "left",
        ),
        (
            "my mum had the car today, she was turning left at the lights when a scooter came up her inside",
            "e-scooter",
            "left",
        ),
        (
            "Our daughter borrowed the hatchback. She was turning right at the crossroads when a bus ran the red.",
            "truck",
            "right",
        ),
        (
            "My brother drove the ute to the tip and was turning right off the highway when a cyclist came past.",
            "bicycle",
            "right",
        ),
    ],
    ids=["my-dad-took", "your-grandad-had", "mum-had-lowercase", "daughter-borrowed", "brother-drove-the-ute"],
)
def test_the_partys_vehicle_is_the_ego_with_its_turn(text, kind, route):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.ego_route == route


def test_the_partys_speed_is_the_egos():
    text = "Our son borrowed my car last night. He was doing 40 mph on the bypass when a van cut in front of him."
    assert kinds(text) == ["van"]
    assert ego_kph(text) == pytest.approx(64.4, abs=0.2)


@pytest.mark.parametrize(
    "text, expected",
    [
        ("My dad took a taxi home. A van pulled out in front of the taxi.", ["van"]),
        ("My dad saw the car hit a cyclist.", ["car", "bicycle"]),
        (
            "I was driving home. My brother took the van behind me and a cyclist pulled out in front of me.",
            ["van", "bicycle"],
        ),
    ],
    ids=["a-taxi-is-new", "seeing-is-not-having", "placed-behind-the-narrator"],
)
def test_a_vehicle_the_party_only_meets_or_rides_in_stays_as_read(text, expected):
    assert kinds(text) == expected
