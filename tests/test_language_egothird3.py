"""The vehicle a third-person news report follows, named again through its driver, is the ego and not
one more road user: "the Toyota driver, doing about 60 mph," points back to the one vehicle brought
in as "a Toyota Hilux", so that vehicle and its speed are the ego's. Guards: two vehicles that both
carry the name leave which one is meant open; the other vehicle's driver reacting does not make it
the ego; a writer at a wheel of their own keeps the vehicle they follow as a road user."""

from __future__ import annotations

import pytest
from reading_of import ego_kph, kinds

from vei_scenario.language.rules_backend import layers_from_text


@pytest.mark.parametrize(
    ("text", "kinds_read", "kph"),
    [
        (  # a news item: the driver named by the make points back to "a Toyota Hilux"
            "A Toyota Hilux ploughed into the back of a tanker on the bypass on Monday night. Police said the "
            "tanker braked sharply and the Toyota driver, believed to be doing about 60 mph, could not stop in time.",
            ["truck"],
            96.6,
        ),
        (  # a local paper: the same, the speed in a relative clause
            "A Nissan Navara went into the back of a bin lorry on Church Street this morning. The lorry had "
            "halted suddenly and the Nissan driver, who was travelling at around 40 mph, could not avoid it.",
            ["truck"],
            64.4,
        ),
    ],
)
def test_the_vehicle_a_report_follows_through_its_driver_is_the_ego(
    text: str, kinds_read: list[str], kph: float
) -> None:
    assert kinds(text) == kinds_read
    assert ego_kph(text) == kph


def test_layers_keep_one_road_user_and_the_egos_speed() -> None:
    text = (
        "A Toyota Hilux ploughed into the back of a tanker on the bypass on Monday night. Police said the "
        "tanker braked sharply and the Toyota driver, believed to be doing about 60 mph, could not stop in time."
    )
    for seed in range(3):
        layers = layers_from_text(text, seed)
        assert [a["type"] for a in layers["adversaries"]] == ["truck"]
        assert layers["ego"]["speed_mps"] == pytest.approx(26.8, abs=0.1)


def test_two_vehicles_of_the_name_leave_the_driver_open() -> None:
    # ("a Ford Transit ... a Ford Focus ... the Ford driver": which Ford is not said; both stay)
    text = (
        "A Ford Transit overtook a Ford Focus on the bypass when a deer ran out. The Ford driver, doing "
        "about 60 mph, braked hard."
    )
    assert kinds(text)[:2] == ["van", "car"]


def test_the_other_drivers_reaction_leaves_the_followed_vehicle_the_ego() -> None:
    text = (
        "A lorry pulled out of the farm gate in front of a taxi, which was doing 30 mph. "
        "The lorry driver braked hard and stopped."
    )
    assert kinds(text) == ["truck"]
    assert ego_kph(text) == 48.3


def test_a_writer_at_a_wheel_of_their_own_keeps_the_vehicle_they_follow() -> None:
    text = (
        "I was driving behind a Toyota Hilux on the bypass when a tanker pulled out in front of it. The Toyota "
        "driver, doing about 50 mph, braked hard."
    )
    assert len(kinds(text)) == 2  # (the Hilux ahead and the tanker)
