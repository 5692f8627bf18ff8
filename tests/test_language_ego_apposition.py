"""A report names its own vehicle and then says which one it is with "the" ("V1, the Ford Transit
under examination, was travelling ...", "Ego, the white minibus, is doing 40 km/h"): that second name
is the ego again, no second road user. A list ("the ego, the van and a cyclist") stays a list."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Vehicle 1, the blue Ford Focus, was travelling at 30 mph when a cyclist swerved out in front of it.",
         ["bicycle"]),
        ("Ego, the white minibus, is doing 40 km/h when a motorbike pulls out of a side road.", ["car"]),
        ("V1, the Transit van in question, was doing 40 mph when a pedestrian stepped out in front of it.",
         ["pedestrian"]),
        ("The subject vehicle, the tipper truck involved, was reversing when a cyclist rode behind it.",
         ["bicycle"]),
        ("The ego vehicle, the grey Tesla under test, approaches at 50 km/h and a child runs out ahead of it.",
         ["pedestrian"]),
        ("The ego car, the hire car concerned, was turning left when a scooter came up its inside.", ["e-scooter"]),
    ],
    ids=["vehicle-1-the-focus", "ego-the-minibus", "in-question", "involved", "under-test", "concerned"],
)  # fmt: skip
def test_a_definite_apposition_to_the_ego_is_the_ego(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("The ego, the van, and a cyclist all reach the junction at once; the van pulls out.", "van"),
        ("The ego brakes hard, the lorry ahead swerves and stops.", "truck"),
    ],
    ids=["a-list", "a-clause"],
)
def test_a_vehicle_after_the_ego_in_a_list_or_clause_stays(text, expected):
    assert expected in kinds(text)
