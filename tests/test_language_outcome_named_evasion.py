"""A hard brake or a swerve said of a road user named by its noun, or of the ego named by its vehicle
("the Prius swerved", "the bus driver stood on the brakes", "SUT braked hard"), where a road user is
read coming into another's path, is one party's escape from the other: with no contact and no safe
pass said, a near miss (:func:`vei_scenario.language.outcome.decide`). A lead vehicle's hard brake with
no one coming into a path is its own act, no escape. Wordings written for these tests, none taken
from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _intent(text: str) -> str | None:
    return read(text).intent


# the same escape told by different people, the vehicle that escapes named by its noun or its make
NAMED_ESCAPE = [
    # a British witness: the car that escapes named by its make
    "I was waiting at the bus stop. A lad on a scooter came off the pavement and the Corsa swerved round him.",
    # an American passenger's text
    "a guy on a bike blew the stop sign right in front of our uber, the driver slammed on the brakes lol",
    # a test log: the ego by its role
    "Run 4. SUT 30 km/h straight. Target pedestrian steps out from behind the van at 15 m. SUT brakes hard.",
    # a screenplay: the hero car by its make
    "EXT. HIGH STREET - NIGHT. The taxi cruises at 20 mph. A CYCLIST darts out of a side road. The taxi brakes hard.",
    # an Australian report from the footpath
    "Saw a ute doing about 50 when a kid on a scooter shot across from the park. The ute stood on the brakes.",
    # a Nigerian account from a danfo
    "An okada cut in from the left, the danfo driver swerved quickly to the right.",
    # an Indian report
    "A cyclist suddenly crossed in front of the school bus and the bus driver applied the brakes hard.",
]


@pytest.mark.parametrize("text", NAMED_ESCAPE)
def test_a_named_road_users_hard_escape_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


# near misses of the rule: no escape said, or said of no event
NOT_AN_ESCAPE = [
    # a participle: a hazard named, no act
    ("A car braking hard ahead of you is the commonest hazard on this road.", None),
    # an infinitive of instruction
    ("A boy ran across the road in front of me. Drivers should be ready to brake hard near the school.", None),
    # a condition: nothing was done
    ("If the van had swerved there, nobody would have noticed.", None),
    # denied
    ("A boy ran out and the van never braked.", None),
    # a swerve round a thing on the road, not a road user
    ("The taxi swerved round a pothole and carried on.", None),
    # contact still wins
    ("The cyclist swerved but the car hit him.", "collision"),
    # a safe pass said wins over the escape
    ("A boy ran across and the van braked hard, plenty of room in the end, no problem at all.", "safe"),
    # a lead vehicle's hard brake, no one in a path: its own act, the outcome left open
    ("Ego follows the lead car at 80 km/h with a 2 s gap. The lead car brakes hard to a standstill.", None),
    ("Following a lorry on the dual carriageway at 50 mph when the lorry braked hard.", None),
]


@pytest.mark.parametrize(("text", "want"), NOT_AN_ESCAPE)
def test_no_escape_where_none_is_told(text: str, want: str | None) -> None:
    assert _intent(text) == want
