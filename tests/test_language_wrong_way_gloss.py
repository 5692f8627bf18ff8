"""A bracket after a road user that names it a wrong-way driver ("NPC sedan (wrong-way driver)",
"Vehicle B (ghost driver)") says what it does, as the noun does when it names the road user itself:
it drives the wrong way. A bracket that only names its type ("(a rental car)", "(white van)") says
nothing of its way."""

from __future__ import annotations

import pytest

from tests.reading_of import moves


@pytest.mark.parametrize(
    "text",
    [
        # a game designer's encounter note
        "NPC sedan (wrong-way driver) spawns 200 m ahead in the player's lane, 80 km/h toward the player.",
        # a test specification
        "Vehicle B (ghost driver) approaches the ego in the ego lane at 80 km/h; the ego brakes.",
        # a claim form
        "The other car (wrong-way driver) was heading at us in our lane and we swerved.",
        # a German engineer's English
        "Target car (ghost driver) drives towards the ego in its lane with 60 km/h.",
        # a fleet report
        "A white BMW (a wrong-way driver) was coming down our lane at us; our driver braked hard.",
    ],
)
def test_a_wrong_way_driver_named_in_brackets_goes_the_wrong_way(text: str) -> None:
    assert moves(text)[0][0] == "wrong_way"


@pytest.mark.parametrize(
    "text",
    [
        "Vehicle B (white van) approaches in the oncoming lane at 80 km/h.",
        "The other car (a rental car) came towards us and went by.",
    ],
)
def test_a_bracket_of_its_type_says_nothing_of_its_way(text: str) -> None:
    assert "wrong_way" not in moves(text)[0]
