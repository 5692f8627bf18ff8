"""A vehicle that pulls out of a private way (a driveway, a gate, a car park, a forecourt, a farm track)
onto the ego's road turns into it; one leaving a stop, a lay-by or a parking space cuts into the lane."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _first(text: str) -> tuple[str | None, list[str]]:
    """The first road user's start and behaviour names read from ``text``."""
    a = read(text).actors[0]
    return a.relation, [b[0] for b in a.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "Doing 40 km/h when a hatchback pulled out of a driveway on my right right in front of me.",
        "a ute drove straight out of a farm gate on the left just ahead of us at 80 k",
        "Vehicle 2 exited the supermarket car park on the driver's left and pulled out in front of Vehicle 1.",
        "me 25mph, taxi pulls out of a drive on the left without looking, had to brake",
        "I was at 50 km/h and a pickup came out of a petrol station forecourt on my left into my path.",
        "Ego at 60 kph; a tractor pulls out of the farm track on the right 30 m ahead.",
    ],
)
def test_a_vehicle_out_of_a_private_way_turns_into_the_road(text: str) -> None:
    relation, names = _first(text)
    assert names[:1] == ["turn_into"], names
    assert (relation or "").startswith(("roadside", "junction")), relation


@pytest.mark.parametrize(
    "text",
    [
        "A bus pulled out of the stop on my left right in front of me, I was at 25 mph.",
        "a car pulled out of a parking space on the left just ahead of me at 30 km/h",
        "Doing 50, a lorry pulled out of the lay-by on my left into my lane.",
    ],
)
def test_a_vehicle_leaving_the_roads_edge_still_cuts_in(text: str) -> None:
    assert _first(text)[1][:1] == ["cut_in"]


def test_a_rider_out_of_a_driveway_is_not_turned() -> None:
    names = _first("A cyclist came out of a driveway on the right and rode along ahead of me.")[1]
    assert "turn_into" not in names
