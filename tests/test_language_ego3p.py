"""A report about two vehicles, one of which runs a red or pulls out while the other, said to come
from the first one's side, brakes for it: the braking one is the vehicle the story happens to (the
ego), not one more road user. Where the ego comes from the other's side, the other is on the ego's
opposite side. A tie on anything else (a path said of one, two that brake) stays as it was read."""

from __future__ import annotations

import pytest
from reading_of import kinds

from vei_scenario.language.reader import read


def _sides(text: str) -> list[tuple[str, str | None]]:
    return [(a.kind, a.relation) for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "A white saloon went through the red light at the crossroads. A minicab, which was coming from "
            "the saloon's right, braked to a halt.",
            [("car", "junction_left")],
        ),
        (
            "A grey estate ran the lights on Mill Road. A cab, coming from the estate's left at 20 mph, "
            "braked hard and stopped just short of the estate's back door.",
            [("car", "junction_right")],
        ),
        (
            "A van came out of the side road. A hatchback, which was approaching from the van's right, "
            "braked and stopped a metre short of the van's door.",
            [("van", "junction_left")],
        ),
        (
            "A taxi, which was coming from the bus's right, braked hard when the bus pulled out.",
            [("truck", "left")],
        ),
        (  # "the saloon's driver" is the saloon's, not a driver of a report's own vehicle
            "A white saloon went through the red light at the crossroads. A minicab, which was coming from the "
            "saloon's right, braked to a halt just short of the saloon's driver's door.",
            [("car", "junction_left")],
        ),
    ],
    ids=[
        "minicab-from-the-right",
        "cab-from-the-left-with-speed",
        "hatchback-short-of-the-van",
        "taxi-by-the-bus",
        "short-of-its-drivers-door",
    ],
)
def test_the_vehicle_that_brakes_for_the_one_from_whose_side_it_came_is_the_ego(text, expected):
    assert _sides(text) == expected


def test_its_speed_is_not_given_to_the_vehicle_whose_side_names_where_it_came_from():
    reading = read(
        "A grey estate ran the lights on Mill Road. A cab, coming from the estate's left at 20 mph, braked hard."
    )
    assert [a.kind for a in reading.actors] == ["car"]
    assert reading.ego_speed_mps is not None and round(reading.ego_speed_mps * 3.6) == 32


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the one that came from the other's side acts itself: it is the road user
        (
            "A pickup approaching from the Civic's right went through the red light. The Civic braked.",
            ["van"],
        ),
        # two vehicles that both brake: nothing tells them apart
        ("A bus braked hard at the lights. A taxi, coming from the bus's right, braked too.", ["car", "truck"]),
        # a writer at a wheel is the ego: the braking taxi stays someone else
        (
            "I was waiting at the lights when a van ran the red. A taxi, coming from the van's right, braked hard.",
            ["car", "van"],
        ),
    ],
    ids=["mover-from-the-side", "two-braking", "narrator-at-a-wheel"],
)
def test_near_misses_keep_their_road_users(text, expected):
    assert sorted(kinds(text)) == expected
