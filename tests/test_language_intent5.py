"""The outcome a measured stop states, and a denied criticality (:mod:`vei_scenario.language.outcome`).

* A stop told with the length it left to the one stopped for ("stopped about 1 m behind it",
  "halts 6 m short of the walker") states the margin: a few metres or less is a near miss, as
  before; several metres is room to spare, a safe pass, unless an emergency stop or a swerve is said
  with it ("slammed on and stopped 5 m short": still a near miss). A length behind someone in a queue
  or at a line is where one waits, no margin.
* "not critical", "nothing critical", "no criticality" deny that the scene came close: a safe pass.

Wordings written for these tests, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str | None:
    return layers_from_text(text, 0).get("intent")


# a stop with a few metres or less left to the one stopped for: a near miss
SMALL_STOP = [
    "The lead motorbike brakes to a halt. The ego car brakes and stops about 1 m behind it.",
    "A cyclist ahead of the ego stops suddenly; the ego halts 0.5 m behind.",
    "The van in front of me stopped dead and I pulled up roughly 2 metres behind it.",
]

# a stop with several metres left: room to spare, a safe pass
ROOMY_STOP = [
    "A bin lorry is parked in the ego lane. The ego decelerates and stops about 6 m behind it, then waits.",
    "A pedestrian steps onto the crossing ahead; the ego slows and halts 5 m short of him.",
    "A delivery van stops in our lane ahead, and the ego brakes and comes to a stop around 8 m before it.",
]

# a stop with several metres left after an emergency stop or a swerve: still a near miss
FORCED_ROOMY_STOP = [
    "A boy ran out from behind a parked bus and I slammed on the brakes, stopping about 5 m short of him.",
    "A deer jumped into the road in front of the ego, which braked hard and stopped about 6 m short of it.",
]

# a length behind someone in a queue or at a line: where one waits, no margin stated
QUEUED = [
    "The ego car stops 5 m behind the van at the red lights.",
    "The ego drives along a straight road and stops 3 m behind the stop line.",
]

# a criticality denied: nothing came close
NOT_CRITICAL = [
    "A van merges into the ego lane 40 m ahead; the ego eases off and the situation is not critical.",
    "The ego follows a tractor at 30 km/h on a country road. Nothing critical.",
    "Ego at 50 km/h, a cyclist crosses 60 m ahead; no criticality.",
]

# criticality said, not denied: not a safe pass
CRITICAL_SAID = [
    "A child runs out from behind a parked car in front of the ego. The scenario is critical.",
]


@pytest.mark.parametrize("text", SMALL_STOP)
def test_a_stop_a_few_metres_short_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", ROOMY_STOP)
def test_a_stop_with_several_metres_left_is_a_safe_pass(text: str) -> None:
    assert _intent(text) == "safe"


@pytest.mark.parametrize("text", FORCED_ROOMY_STOP)
def test_a_forced_stop_with_several_metres_left_is_still_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", QUEUED)
def test_a_length_in_a_queue_or_at_a_line_is_no_margin(text: str) -> None:
    assert _intent(text) not in ("near_miss", "collision")


@pytest.mark.parametrize("text", NOT_CRITICAL)
def test_a_denied_criticality_is_a_safe_pass(text: str) -> None:
    assert _intent(text) == "safe"


@pytest.mark.parametrize("text", CRITICAL_SAID)
def test_a_criticality_said_is_not_safe(text: str) -> None:
    assert _intent(text) not in ("safe", None)


# a thing hit while the ego was forced out of a road user's way, a wheel into a hollow of the road, a
# miss told by its margin after a negator: none is a contact between road users
NO_CONTACT_BETWEEN_ROAD_USERS = [
    "A lorry came at me on my side of the lane, I had to steer onto the verge, my wheel clipped the kerb, "
    "but the lorry never touched me.",
    "The lead cyclist brakes sharply, front wheel into a pothole, and the ego stops 1 m behind her.",
    "A scooter came past me from behind, no bell, nothing, missed my elbow by a hair.",
]

# contact said with the same words: still a collision
CONTACT_KEPT = [
    "A van pulled out of a side road and I had to brake hard but still hit the back of it.",
    "A cyclist came round the corner on the wrong side and did not miss me.",
    "A van braked in front of me and I went into the back of it.",
]


@pytest.mark.parametrize("text", NO_CONTACT_BETWEEN_ROAD_USERS)
def test_no_contact_between_road_users_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", CONTACT_KEPT)
def test_contact_said_stays_a_collision(text: str) -> None:
    assert _intent(text) == "collision"


# staying or slowing behind someone until another has gone by: giving way, a safe pass
HELD_BACK_UNTIL = [
    "The ego stays behind a horse rider until the oncoming van has passed, then overtakes.",
    "The test car slows behind the jogger until the oncoming truck has gone past, then pulls out round him.",
]

# slowing with no one waited for, or waiting in a queue: not a safe pass read from it
NOT_HELD_BACK = [
    "I slowed behind the cyclist and then he swerved across in front of me, I had to brake hard.",
    "The ego slows as a van comes out of a side road in front of it.",
]


@pytest.mark.parametrize("text", HELD_BACK_UNTIL)
def test_holding_back_until_another_has_passed_is_a_safe_pass(text: str) -> None:
    assert _intent(text) == "safe"


@pytest.mark.parametrize("text", NOT_HELD_BACK)
def test_slowing_alone_is_not_giving_way(text: str) -> None:
    assert _intent(text) != "safe"


# another road user had left the way before the ego came to it: the two never met, a safe pass
GONE_BEFORE_ARRIVAL = [
    "A lad on a scooter turned across ahead of me into a driveway. I lifted off and he was gone before I got there.",
    "A jogger crossed the road in front of the ego car; by the time we got there she was long gone.",
    "A cyclist rode over the junction ahead of us and she was already on the other side when we arrived.",
]

# gone before the ego could act: no time said to have been left
GONE_TOO_FAST = [
    "A cyclist cut across in front of me and was gone before I could even brake.",
]


@pytest.mark.parametrize("text", GONE_BEFORE_ARRIVAL)
def test_gone_before_the_ego_arrived_is_a_safe_pass(text: str) -> None:
    assert _intent(text) == "safe"


@pytest.mark.parametrize("text", GONE_TOO_FAST)
def test_gone_before_the_ego_could_act_is_not_a_safe_pass(text: str) -> None:
    assert _intent(text) != "safe"
