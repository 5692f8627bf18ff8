"""A road user told going onto a roundabout from an arm on the ego's left or right, with no light or
signal said, joins the ring in front of the ego: a turn into the ego's way round (which crosses its
path), not a run of a red light that is not there. Sentences written for the rule in several
registers (a forum post, a fleet note, a witness statement, a test log), none taken from a corpus;
near misses keep their readings: a refused give-way told as the act itself, a light said, a
crossroads, a road user going round beside the ego, one leaving by an exit."""

from __future__ import annotations

import pytest

from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text


def _first(text: str, seed: int = 0) -> tuple[str, str]:
    """The first road user of ``text``: its first behaviour and its spawn relation."""
    adv = layers_from_text(text, seed)["adversaries"][0]
    names = [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])]
    return names[0], adv["spawn"]["relation"]


@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("I was already going round the roundabout at 15 mph when a cyclist shot onto it from the left "
         "without giving way.", "left"),
        ("Fleet note: our van was circulating on the roundabout at 20 km/h and a taxi rolled onto it "
         "from the road on its right without yielding.", "right"),
        ("Witness: the silver hatchback was on the roundabout when a moped came in from the left and "
         "did not stop.", "left"),
        ("Run 4: ego circulates on the roundabout at 25 km/h; a car drives onto it from the right-hand "
         "arm without slowing.", "right"),
    ],
)  # fmt: skip
def test_a_road_user_going_onto_the_roundabout_from_an_arm_turns_into_the_egos_way(text: str, side: str) -> None:
    for seed in (0, 1):
        assert _first(text, seed) == ("turn_into", f"junction_{side}")


@pytest.mark.parametrize(
    "text",
    [
        # the refusal is the act told: read as driving through the entry, as before
        "Roundabout, a lorry coming in from the left does not give way.",
        "At a roundabout a coach entering from the right fails to yield to us.",
        # a light said: a red there is run
        "At the signal-controlled roundabout a car ran the red light from the left and hit me.",
        "On the roundabout a van from the right went through on red without stopping.",
        # no roundabout: straight through the crossroads
        "At the crossroads a car came from the right without stopping and hit my door.",
        # the ego has left the roundabout: the meeting is at the junction after it
        "We left the roundabout and at the next junction a lorry came from the right without stopping.",
    ],
)
def test_a_refusal_a_light_or_a_crossroads_keeps_the_run(text: str) -> None:
    assert _first(text)[0] == "run_red_light"


def test_a_rider_going_round_beside_the_ego_is_no_entry() -> None:
    name, relation = _first("On the roundabout a cyclist kept going round beside me on my left.")
    assert (name, relation) == ("keep_going", "left")


def test_a_side_said_as_the_exit_taken_is_no_entry() -> None:
    """A side said only as where the road user is ("the exit on the left") is where it leaves."""
    assert _first("At the roundabout a coach takes the exit on the right.")[0] != "turn_into"
