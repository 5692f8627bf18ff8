"""Someone the reader has no kind for (a "rider", "someone", "a figure") who comes out from between or
from behind something at the side of the road crosses the ego's road, as a walker or a cyclist said so
does; a vehicle coming out so still pulls out into the traffic. Sentences written for the rule in
several registers (a manual's example, a dashcam post, a witness note, a test log), none taken from a
corpus; near misses that look alike keep their readings."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _first(text: str) -> tuple[str, str, str]:
    """The first moving road user of ``text`` (seed 0): its type, first behaviour and spawn relation."""
    for adv in layers_from_text(text, 0)["adversaries"]:
        node = adv["behaviour"]
        name = node["sequence"][0]["behaviour"] if "sequence" in node else node["behaviour"]
        if name != "stop":
            return adv["type"], name, adv["spawn"]["relation"]
    raise AssertionError(f"no moving road user read from {text!r}")


@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("Example: you are driving at 50 km/h and a rider comes out from between parked cars on your right.", "right"),
        ("Dashcam, 30 mph on Elm Road, and a rider shot out from behind a parked van on my left.", "left"),
        ("I was doing about 25 when someone came out from between two parked cars on the left.", "left"),
        ("Test 12: ego at 40 km/h, a rider rolls out from behind the stationary bus on the right.", "right"),
    ],
)
def test_unnamed_road_user_out_from_cover_crosses(text: str, side: str) -> None:
    """Out from between or behind cover at the kerb: a crossing from that side, not a cut-in."""
    _, name, relation = _first(text)
    assert name == "cross_in_front"
    assert relation == f"roadside_{side}"


@pytest.mark.parametrize(
    ("text", "name"),
    [
        # a vehicle coming out from cover pulls out into the traffic
        ("I was driving at 30 mph when a car came out from between two parked vans on my left.", "cut_in"),
        ("Doing 40 km/h, a van pulled out from behind a parked lorry on my right.", "cut_in"),
    ],
)
def test_vehicle_out_from_cover_keeps_its_reading(text: str, name: str) -> None:
    """A vehicle that comes out from cover is no crossing."""
    assert _first(text)[1] == name


def test_riding_between_without_coming_out_is_no_crossing() -> None:
    """A rider riding between two lorries comes out of nothing: no crossing is read."""
    assert _first("I was driving at 30 mph and a rider was riding between two lorries ahead of me.")[1] != (
        "cross_in_front"
    )


def test_walker_out_from_cover_still_crosses() -> None:
    """The walker said so crosses as before."""
    assert _first("At 20 mph a woman came out from between parked cars on my left.")[1] == "cross_in_front"


@pytest.mark.parametrize(
    ("text", "side"),
    [
        (
            "The automatic emergency brake was demonstrated. With the test car at 40 km/h, a child stepped out "
            "from behind a parked minivan on the left.",
            "left",
        ),
        (
            "Emergency braking, run 3. Ego at 30 km/h; a boy on a scooter came out from behind a parked van on "
            "the right.",
            "right",
        ),
        (
            "Braking test today. Car at 35 km/h and a woman stepped off the kerb on the right into the road.",
            "right",
        ),
    ],
)
def test_brake_said_before_the_crosser_is_the_egos(text: str, side: str) -> None:
    """A brake said before a walker or rider who comes out from cover or off the kerb is named is the
    ego's, not a stop of theirs before they cross: they cross from that kerb, and hid there, not
    behind the ego."""
    layers = layers_from_text(text, 0)
    moving = [a for a in layers["adversaries"] if a["behaviour"].get("behaviour") != "stop"]
    assert [a["behaviour"].get("behaviour") for a in moving] == ["cross_in_front"]
    assert moving[0]["spawn"]["relation"] == f"roadside_{side}"


def test_crosser_who_then_stops_in_the_road_keeps_the_stop() -> None:
    """A stop said of the walker, placed in the road after the crossing, is theirs (guard)."""
    layers = layers_from_text(
        "I was doing 20 mph when a man stepped out from behind a bus and stopped dead in the middle of the road.", 0
    )
    node = layers["adversaries"][0]["behaviour"]
    names = [n["behaviour"] for n in node["sequence"]] if "sequence" in node else [node["behaviour"]]
    assert names[0] == "cross_in_front" and "stop" in " ".join(names)
