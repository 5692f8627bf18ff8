"""Where a rider starts who is said to come *from* a side at a junction and crosses the ego's path.

A rider takes the road as a vehicle does: at a crossroads or a T-junction, "a cyclist coming from my
right" comes along the crossing road, out of that arm, as a van said so does; a walker from a side
still steps off that side's kerb, and a rider placed on a kerb, footway or path starts there. Wordings
are written for this file (none taken from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _start(text: str) -> list[tuple[str, str]]:
    return [(a["type"], a["spawn"]["relation"]) for a in layers_from_text(text, 0)["adversaries"]]


FROM_A_SIDE_AT_A_JUNCTION = [
    ("At the crossroads a cyclist approaching from my right crossed in front of me at 20 mph.", "right"),
    ("Going straight over the junction at 25 mph, a lad on an e-scooter coming from the left shot across.", "left"),
    ("We were at 30 km/h through the intersection when a bike arriving from our left rode across our bonnet.", "left"),
    ("At the T-junction a girl on a bicycle came from the right and pedalled straight across my path.", "right"),
]


@pytest.mark.parametrize("text, side", FROM_A_SIDE_AT_A_JUNCTION)
def test_a_rider_from_a_side_at_a_junction_comes_out_of_that_arm(text, side):
    starts = _start(text)
    assert len(starts) == 1
    assert starts[0][1] == f"junction_{side}"


# near misses: on foot, on a kerb or footway, with no junction said, or at a roundabout (where what
# comes from a side comes round the ring), the crossing starts at the kerb of that side
AT_THE_KERB = [
    ("Going round the roundabout at 20 mph, a cyclist came across from the right in front of me.", "roadside_right"),
    ("At the crossroads a man coming from my right walked across in front of me.", "roadside_right"),
    ("At the crossroads a cyclist on the footway coming from the left rode across my path.", "roadside_left"),
    ("On the straight a cyclist coming from the left rode across the road in front of me at 20 mph.", "roadside_left"),
    (
        "A boy on a scooter came off the pavement on my right at the junction and crossed in front of me.",
        "roadside_right",
    ),
]


@pytest.mark.parametrize("text, relation", AT_THE_KERB)
def test_a_walker_or_rider_placed_at_a_kerb_keeps_it(text, relation):
    assert [rel for _, rel in _start(text)] == [relation]
