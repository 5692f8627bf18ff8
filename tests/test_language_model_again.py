"""A vehicle named by make and model is named again by its model alone ("a silver Toyota Prius ... the
Prius braked"): that is the same vehicle, so a report about it finds it the vehicle the report is told
from, the ego, and does not list it as one more road user."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    "text, expected",
    [
        ("The witness says the white Ford Focus had a green light when a van came from the Focus's left "
         "through the red. The Focus was doing about 30 mph.", ["van"]),
        ("CCTV shows a silver Toyota Prius travelling at 40 km/h when a cyclist pulls out in front of the "
         "Prius. The Prius brakes hard.", ["bicycle"]),
        ("A red Mazda Demio was doing 50 km/h when a child ran into the path of the Demio. The Demio "
         "swerved.", ["pedestrian"]),
        ("the black VW Polo was doing 25 when a scooter cut across the Polo's bonnet and the Polo stopped",
         ["e-scooter"]),
        ("Officers state a grey Hyundai Tucson was travelling at 30 mph when a bus pulled out into the "
         "Tucson's path. The Tucson braked.", ["truck"]),
    ],
    ids=["focus-witness", "prius-cctv", "demio", "polo-lowercase", "tucson-police"],
)  # fmt: skip
def test_a_vehicle_named_again_by_its_model_is_one_vehicle(text, expected):
    assert kinds(text) == expected


def test_a_model_word_after_another_make_is_not_the_same_vehicle():
    text = "A blue Ford Focus was doing 30 mph when a Renault Clio pulled out of a side road in front of the Focus."
    assert len(kinds(text)) == 1
