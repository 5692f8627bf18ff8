"""A person going somewhere on a bicycle or e-scooter is its rider, not a walker pushing it.

"a worker going home on e-scooter was hit", "a student heading back to the depot on e-scooter": a
participle of going and where to stand between the person and "on" the vehicle; they say where the
rider goes, not who rides (the depot is no one), and the vehicle is no object of the verb as in "a
man pushing a bike" (a walker). Guards: a vehicle right after the verb stays in the walker's hands,
a walker on foot stays one, and the narrator's own ride is no road user.
"""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _types(text: str) -> list[str]:
    return [a["type"] for a in layers_from_text(text, 0)["adversaries"]]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("Yesterday a cleaner going home on e-scooter was hit by a car at the junction.", "e-scooter"),
        ("Late on Friday a porter heading back to the depot on e-scooter was struck by a taxi.", "e-scooter"),
        ("This morning a warehouse worker going home on bike was hit by a car at the crossroads.", "bicycle"),
        (
            "I was doing about 30 mph when a lad heading to school on a bike came out of a side road on my right.",
            "bicycle",
        ),
    ],
)
def test_going_somewhere_on_a_vehicle_rides_it(text: str, kind: str) -> None:
    assert _types(text) == [kind]


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("A man pushing a bike stepped off the kerb in front of a van doing 30 mph.", ["pedestrian"]),
        ("A woman crossing the road on foot was hit by a van.", ["pedestrian"]),
        ("I was going home on my bike when a van pulled out of a side road on my right.", ["van"]),
    ],
)
def test_walkers_and_the_narrators_ride_stay(text: str, kinds: list[str]) -> None:
    assert _types(text) == kinds
