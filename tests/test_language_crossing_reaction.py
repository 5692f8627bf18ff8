"""A brake or a stop said after a road user came across the ego's way is the ego's reaction, not a
second behaviour of that road user. Wordings written for the class in several registers (a voice
note, a fleet log, a text message, a driving-school note, an exam question, a news line), none taken
from a corpus; near misses where the stop is the road user's own keep it."""

from __future__ import annotations

import pytest

from tests.reading_of import moves
from vei_scenario.language import crossing_reaction

_STOPS = {"stop", "sudden_stop", "change_speed"}


@pytest.mark.parametrize(
    "text",
    [
        # a parent's story: the ego's driver said again as "she"
        "My mum was driving us to school at about 20 mph when a van came out of a side street on her left"
        " right in front of her. She braked and just missed it.",
        # an Indian English account: the driver as "he", after the one crossing was named
        "Uncle was driving at 40 when one auto came out from the left side road just in front. He applied"
        " brakes suddenly, thank god nothing happened.",
        # a witness: the ego's driver after a red-light runner
        "Taxi driver doing 30 on Queen St, a cyclist rode straight through the red light across his"
        " bonnet. He slammed the brakes on, no harm done.",
        # a voice note: the subject said, the narrator's
        "doing about 25 down the high street and this kid on a bike flies out of a side road in front of"
        " me, I slammed the brakes on and he just rode off",
        # a fleet log: a subjectless brake after the crossing
        "Unit 7, 40 km/h, urban. Pedestrian stepped off the kerb on the right into our path. Braked hard, no contact.",
        # a text message: the ego said as "we"
        "omg a car just ran the red at the lights right in front of us, we stopped with like a metre to spare",
        # a driving-school note: the learner named by a pronoun
        "Lesson 9. A van came out of the junction on our left without looking. She stopped in good time, well done.",
        # an exam question: the stop asked about
        "A cyclist turns out of a side road 15 m ahead of a car travelling at 10 m/s. Can the car stop in time?",
        # a news line: the other driver named as the ego's
        "A woman on an e-scooter rode across the road from the pavement on the left; the driver of the"
        " Astra braked but could not avoid her.",
    ],
)
def test_a_brake_after_a_crossing_is_the_egos(text: str) -> None:
    acts = moves(text)
    assert acts, text
    assert not any(set(a) & _STOPS for a in acts), acts


@pytest.mark.parametrize(
    ("text", "stop"),
    [
        # placed in the road: it stands there
        ("A cyclist pulled out of the side road on the left and stopped dead in the middle of our lane.", True),
        ("at 30 mph a lad on a scooter comes off the kerb on my right and stops in the road right ahead", True),
        # joined to its move by "then"
        ("A pedestrian steps out from between parked cars on the left, then stops and looks at us.", True),
    ],
)
def test_its_own_stop_stays(text: str, stop: bool) -> None:
    acts = moves(text)
    assert any(set(a) & {"stop", "sudden_stop"} for a in acts) is stop, acts


@pytest.mark.parametrize(
    "text",
    [
        # a lane move then a brake: a brake check, its own
        "On the motorway at 70 mph a BMW cut in front of me from the right and then braked hard.",
        "A van overtook us on the dual carriageway, pulled in ahead and slammed on its brakes.",
    ],
)
def test_a_brake_after_a_lane_move_stays(text: str) -> None:
    acts = moves(text)
    assert any("sudden_stop" in a for a in acts), acts


def test_placed_in_road() -> None:
    assert crossing_reaction.placed_in_road(["dead", "in", "our", "lane"])
    assert crossing_reaction.placed_in_road(["at", "the", "kerb"])
    assert not crossing_reaction.placed_in_road(["short", "of", "him", ",", "no"])
    assert not crossing_reaction.placed_in_road(["with", "a", "metre", "to", "spare"])


def test_speeding_up_is_no_reaction() -> None:
    tokens = ["he", "accelerated", ",", "we"]
    free = crossing_reaction.said_free("change_speed", {"speed_delta_mps": 3.0}, tokens, 1, 2, lambda w: False)
    assert not free
