"""The words "right of way" name a priority, not a side: a road user said to have (or not to be given) the
right of way keeps the start read from where it is said to come from, and "right" there puts it on
no right-hand arm, lane or kerb. A side said plainly ("from the right", "on my right") still places it."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _relations(text: str) -> list[str | None]:
    """The spawn relations of the road users read from ``text`` (seed 0)."""
    return [a["spawn"].get("relation") for a in layers_from_text(text, 0)["adversaries"]]


@pytest.mark.parametrize(
    "text",
    [
        "I turned right at the lights, and a cyclist coming the other way went straight through. He had right of way.",
        "Turning left at the crossroads, we met a moped rider travelling in the opposite direction who kept going; "
        "she had the right of way.",
        "At the junction an oncoming van carried straight on while I waited to turn right - it had right-of-way.",
        "Waiting to turn across at the lights: the e-scooter coming towards us went straight on, "
        "as it had right of way.",
    ],
)
def test_right_of_way_leaves_an_oncoming_road_user_on_the_opposite_arm(text: str) -> None:
    relations = _relations(text)
    assert relations[:1] == ["junction_opposite"], relations


@pytest.mark.parametrize(
    ("text", "relation"),
    [  # guard cases: a side said plainly beside "right of way" still places the road user
        ("At the crossroads a cyclist came from the right; he had right of way and I stopped.", "junction_right"),
        ("At the junction a van came out from the left although I had right of way.", "junction_left"),
        ("I was turning right at the lights when a cyclist coming the other way went straight through.", None),
    ],
)
def test_a_side_said_plainly_still_places_it(text: str, relation: str | None) -> None:
    relations = _relations(text)
    assert relations[:1] == [relation or "junction_opposite"], relations
