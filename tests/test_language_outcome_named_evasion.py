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


# a "clear" listed after the weather or the time of day is the sky, not a verdict on the pass
SKY_CLEAR = [
    "Run 12. A cyclist crosses from the right, the ego brakes hard. No contact. Morning, clear.",
    "Shot 3: the scooter cuts across the bus, the driver brakes hard, no contact. Dusk, dry, clear.",
    "Conditions: afternoon, clear. A boy ran out between cars and I swerved.",
    "Night, clear. A van cut in front of me and I braked hard.",
    "Weather dry, sunny, clear. The cyclist pulled out and I had to brake hard.",
]


@pytest.mark.parametrize("text", SKY_CLEAR)
def test_clear_after_the_weather_is_the_sky(text: str) -> None:
    assert _intent(text) == "near_miss"


# "Clear." as the writer's own word on the pass is still a safe pass
@pytest.mark.parametrize(
    "text",
    [
        "A rider came up on my left at the lights, I waited for him to go. Clear.",
        "Held back behind the cyclist until the bend was done, then went round her. Clean, clear.",
    ],
)
def test_clear_as_a_verdict_is_a_safe_pass(text: str) -> None:
    assert _intent(text) == "safe"
