"""A vehicle said only to stop, with the time of its stop told by a "when"/"as" clause whose road user
gets into its path, is the ego stopping for that road user, not one more road user."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _kinds(text: str) -> list[str]:
    return sorted(a["type"] for a in layers_from_text(text, 0)["adversaries"])


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("The van came to a stop when a boy stepped out on the left.", ["pedestrian"]),
        ("The vehicle shall stop without contact when a pedestrian steps out on the right, 15 m away.", ["pedestrian"]),
        ("The minibus braked to a stop when a man stepped out on the left.", ["pedestrian"]),
    ],
)
def test_a_vehicle_that_stops_when_someone_gets_into_its_path_is_the_ego(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # its stop told before anyone comes, joined by "and": it stopped for its own reason, and stands there
        ("The bus stops at a bus stop and a pedestrian walks out in front of it.", ["pedestrian", "truck"]),
        # the one told in the "when" clause does not get into its path
        ("I was doing 30. The van ahead stopped when a cyclist rode into the back of it.", ["bicycle", "van"]),
    ],
)
def test_a_stop_told_apart_from_someone_entering_its_path_keeps_both(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds
