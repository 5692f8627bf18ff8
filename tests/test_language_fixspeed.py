"""A speed given under the name of the speed at impact ("Impact speed V1 approx. 28 km/h") is what was
left when the two met: it does not replace the ego's speed said before it, and the other road user's
speed said with it stays that road user's."""

from __future__ import annotations

import pytest
from reading_of import ego_kph

from vei_scenario.language.reader import read

REPORT = (
    "Ref 88. V1 (hatchback) at approx. 47 km/h on the ring road. P2 (cyclist) came out of a side turning "
    "and was struck by V1. Impact speed V1 approx. 31 km/h, P2 approx. 12 km/h."
)


def test_the_speed_at_impact_does_not_replace_the_ego_s_speed_said_before():
    assert ego_kph(REPORT) == 47.0


def test_the_other_road_user_s_speed_at_impact_stays_its_own():
    [cyclist] = read(REPORT).actors
    assert cyclist.speed_mps == pytest.approx(12 / 3.6, abs=0.01)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        # (no speed of the ego before it: the speed at impact is the only one said, and is read)
        ("Impact speed V1 approx. 31 km/h. P2 (cyclist) came out of a side turning.", 31.0),
        # (a speed that is not named as the impact's keeps replacing as before)
        ("V1 at approx. 47 km/h. A cyclist came out of a side turning. V1 approx. 52 km/h at the turning.", 52.0),
    ],
)
def test_near_misses(text, kph):
    assert ego_kph(text) == kph
