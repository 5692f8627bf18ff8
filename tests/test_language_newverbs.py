"""What a road user does said in words the reader did not take as a behaviour: an act said as a noun
after a light verb ("made a sudden swerve into my lane"), a noun made of a phrasal verb ("an oncoming
van turn-across"), and a move across from a lane followed by going on ("came across in front of me and
drove on"). Guards: a light verb denied or only supposed, a light verb whose noun is no act, the ego's
own act, a compound naming a place, and going on with no move across."""

from __future__ import annotations

import pytest

from tests.reading_of import acts as _acts


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 40 mph when a van on my left made a sudden swerve into my lane.",
        "me 50kph, bus in the left lane makes a sudden swerve into my lane, horn, brakes",
        "Ego at 60 km/h in lane 1. The car in lane 2 performs a swerve into the ego's lane 10 m ahead.",
    ],
)
def test_an_act_said_as_a_noun_after_a_light_verb_is_done(text: str) -> None:
    assert _acts(text)[0][1] == ["cut_in"], _acts(text)


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 40 mph when a van on my left didn't make a swerve into my lane.",
        "I was doing 40 mph when a van on my left could have made a swerve into my lane.",
    ],
)
def test_a_light_verb_denied_or_supposed_is_not_done(text: str) -> None:
    assert _acts(text)[0][1] == ["keep_going"], _acts(text)


def test_a_light_verb_whose_noun_is_no_act_says_nothing() -> None:
    assert _acts("A man in a car on my left made a phone call while I drove past at 30 mph.")[0][1] == ["keep_going"]


def test_the_egos_own_act_said_as_a_noun_is_not_the_road_users() -> None:
    acts = _acts("I made a sudden swerve into the left lane at 50 km/h to avoid a van that had stopped ahead of me.")
    assert acts[0][1] != ["cut_in"], acts


@pytest.mark.parametrize(
    "text",
    [
        "Test log: oncoming van turn-across at the junction, ego straight at 50 km/h.",
        "oncoming motorbike pulls a turn-across at the crossroads while ego goes straight on at 40 kph",
        "At the junction an oncoming truck did a turn-across in front of us while we went straight on at 30 km/h.",
    ],
)
def test_a_noun_of_a_phrasal_verb_names_its_act(text: str) -> None:
    assert _acts(text)[0][1] == ["turn_across"], _acts(text)


@pytest.mark.parametrize(
    "text, kind, names",
    [
        ("A car was waiting at the cross-over as I drove past at 30 km/h.", "car", ["stop"]),
        ("A van was parked in the pull-in on my left as I passed at 30 mph.", "van", ["stop"]),
    ],
)
def test_a_phrasal_compound_after_a_preposition_of_place_is_the_place(text: str, kind: str, names: list) -> None:
    acts = _acts(text)
    assert acts[0][0] == kind and "cut_in" not in acts[0][1] and "run_red_light" not in acts[0][1], acts


@pytest.mark.parametrize(
    "text",
    [
        "I was in the left lane doing 50 mph and a van in the right lane came across in front of me. The van drove on.",
        "Two lanes, me in the left one at 40 mph; a taxi from the right lane came across in front of me and just "
        "kept going.",
        "At 45 km/h in the right lane. A bus in the left lane came across in front of us, it didn't even stop.",
    ],
)
def test_going_on_after_a_move_across_from_a_lane_leaves_the_cut_in(text: str) -> None:
    assert _acts(text)[0][1] == ["cut_in"], _acts(text)


def test_what_it_does_after_the_move_across_is_kept() -> None:
    text = "I was in the left lane at 50 km/h. A van in the right lane came across in front of me and then turned left."
    assert _acts(text)[0][1] == ["forced_turn"], _acts(text)


def test_going_on_beside_the_ego_is_no_cut_in() -> None:
    text = "I was doing 40 mph and a lorry in the right lane came alongside me and carried on."
    assert _acts(text)[0][1] == ["keep_going"], _acts(text)
