"""A vehicle named first by its owner's name ("Priya's Fiesta", "the survey team's van") in a story with
no narrator in it is the vehicle the story follows: the ego, not a road user of its own."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph, kinds


@pytest.mark.parametrize(
    ("text", "want_kinds", "want_kph"),
    [
        (
            "Job 4, ring road. Colm's Corsa, front nearside tyre. Colm said a lad on an e-scooter came off "
            "the kerb on his right and he had to swerve round him. Reckons he was doing 35 mph.",
            ["e-scooter"],
            56.3,
        ),
        (
            "Callout 12. Bea's Clio, dented wing. Bea was doing 20 mph past the school when a boy on a bike "
            "came out of a driveway on her right. She stopped short.",
            ["bicycle"],
            32.2,
        ),
        (
            "During the visit the safety team's van was waiting at the lights when a scooter rider came "
            "through the red from the left.",
            ["e-scooter"],
            0.0,
        ),
        (
            "Priya's Fiesta was heading down Church Street at about 25 mph when a cyclist swung out of a "
            "driveway on her left. She braked hard and stopped a metre short.",
            ["bicycle"],
            40.2,
        ),
    ],
)
def test_a_vehicle_named_by_its_owner_is_the_ego(text: str, want_kinds: list[str], want_kph: float) -> None:
    assert kinds(text) == want_kinds
    assert ego_kph(text) == want_kph


@pytest.mark.parametrize(
    ("text", "want_kinds"),
    [
        # the narrator is in the story: the owned vehicle is someone the narrator meets
        ("I was doing 30 when Priya's Fiesta pulled out of a driveway on my left.", ["car"]),
        # a road user named before it: the owned vehicle is met by that one
        (
            "A cyclist was riding along Mill Lane at 12 mph when Tesco's lorry pulled out of the yard in front "
            "of him. He braked hard.",
            ["bicycle", "truck"],
        ),
        # a time, not an owner
        ("Friday's bus pulled out of the stop as a boy on a bike came past at 15 mph.", ["truck", "bicycle"]),
    ],
)
def test_near_misses_keep_their_reading(text: str, want_kinds: list[str]) -> None:
    assert kinds(text) == want_kinds
