"""A narrator who introduces themselves by a role ("As a taxi driver I ...", "As a bus driver of
twenty years I ...", "As a Bus Nordwest driver I ...") drives the vehicle the role names: a later "the
taxi" is the ego, not one more road user. A road user brought in with "as" that does something of its
own ("As a van pulled out I braked"), a role said of someone else ("as a bus driver he"), and a vehicle of
the role's kind introduced as new ("a taxi came past me") stay road users."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    "text, expected",
    [
        # the role, then "I" with no comma between
        (
            "As a taxi driver I see a lot. Last night I was pulling away from the rank at 10 km/h when a "
            "cyclist came past the taxi on the right and cut in across the front of it. I braked hard.",
            ["bicycle"],
        ),
        # the role with a phrase of its own ("of twenty years") before "I"
        (
            "As a bus driver of twenty years I would ask cyclists to think. Last week I was pulling away "
            "from a stop at 10 km/h when a cyclist came past the bus on the right and cut in across the "
            "front of it. I braked hard.",
            ["bicycle"],
        ),
        # the operator's name between the vehicle and its driver
        (
            "As a Bus Nordwest driver I have seen it all. This morning I was leaving the stop at walking "
            "pace when a lad on an e-scooter came past the bus on the left and cut in across the front of it.",
            ["e-scooter"],
        ),
        # the role set off by a comma, as before
        (
            "As a bus driver, I would ask cyclists to think. Last week I was pulling away from a stop at "
            "10 km/h when a cyclist came past the bus on the right and cut in across the front of it.",
            ["bicycle"],
        ),
    ],
)
def test_narrators_role_names_the_egos_vehicle(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # "as" is "while": the van has a verb of its own
        (
            "As a van pulled out of the side road I braked hard and it stopped in front of me.",
            ["van"],
        ),
        # a role the narrator takes, and a vehicle of that kind introduced as new: two vehicles
        (
            "As a taxi driver I see a lot. Last night a taxi came past me on the right and cut in sharply. "
            "I braked hard.",
            ["car"],
        ),
        # the role said of someone else ("as a bus driver he"): not the narrator's vehicle
        (
            "As a bus driver he should have known better: the bus pulled out of the stop right in front "
            "of me and I braked hard.",
            ["truck"],
        ),
    ],
)
def test_others_stay(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected
