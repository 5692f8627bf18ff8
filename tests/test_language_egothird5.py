"""The ego's own vehicle said in apposition to its name, and then named again by its noun: "The ego, a
blue Passat, ... The Passat stops short", "A silver Tesla, the hero car, ... The Tesla brakes hard".
Both names are the ego, and so is a later "the <noun>" that repeats the vehicle's noun, until a
vehicle of that kind is brought in as new ("a Passat in the next lane", "another van"). A list ("a
van, the ego, and a cyclist") is no apposition."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds
from vei_scenario.language.rules_backend import layers_from_text


@pytest.mark.parametrize(
    "text, expected",
    [
        ("The ego, a blue Passat, travels at 40 km/h. A pedestrian steps out from the left. The Passat stops short.",
         ["pedestrian"]),
        ("Subject vehicle, a grey Passat estate, is doing 50 km/h when a cyclist swings out of a side road on "
         "the right; the Passat brakes hard.", ["bicycle"]),
        ("A silver Tesla - the hero car - rolls up to the lights at 25 mph. From the right a rider on an "
         "e-scooter runs the red. The Tesla brakes hard.", ["e-scooter"]),
        ("A red Polo, the subject vehicle, travels at 30 km/h when a child runs out from the right. The Polo "
         "stops just short.", ["pedestrian"]),
        ("A white van, the ego vehicle, is at 40 km/h. A jogger crosses in front of it and the van stops.",
         ["pedestrian"]),
    ],
    ids=["ego-then-passat", "label-then-estate", "tesla-then-hero-car", "polo-then-subject", "van-then-ego"],
)  # fmt: skip
def test_the_egos_vehicle_named_again_is_the_ego(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("The ego, a blue Passat, travels at 40 km/h. A Passat in the next lane cuts in front of it.", ["car"]),
        ("The ego, a white van, is at 40 km/h. A cyclist pulls out and another van overtakes the cyclist; "
         "the van then cuts in.", ["bicycle", "van"]),
        ("A van, the ego, and a cyclist are on the road. The van stops.", ["van"]),
        ("The ego, a blue Passat, travels at 40 km/h. The car ahead brakes hard.", ["car"]),
    ],
    ids=["a-new-passat", "another-van", "a-list", "placed-car"],
)  # fmt: skip
def test_another_of_the_kind_stays_a_road_user(text, expected):
    assert kinds(text) == expected


def test_the_layers_hold_the_one_road_user_and_the_egos_speed():
    layers = layers_from_text(
        "A silver Tesla - the hero car - rolls up to the lights at 25 mph. From the right a rider on an "
        "e-scooter runs the red. The Tesla brakes hard.",
        0,
    )
    assert [a["type"] for a in layers["adversaries"]] == ["e-scooter"]
    assert round(layers["ego"]["speed_mps"] * 3.6) == 40
