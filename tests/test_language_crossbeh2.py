"""A walker or rider the ego had stopped (or slowed) to let cross: the crossing is the scene.

"I had stopped to let a boy cross when a bus went round me" tells a scene that opens on the ego
standing, with the one it let go crossing in front of it while something else happens. The crossing
is read (``cross_in_front``, in front of the standing ego) and plays so. The guards keep what a stop
in the past perfect for anything else says: a vehicle let pull out, reverse or go past did its move
before the scene, and so does anyone let out of the ego's car. Where the one let across waits may be
said between it and its crossing ("stopped for a man on the pavement to cross").
"""

from __future__ import annotations

import pytest
from play_layers import play_layers
from reading_of import acts

from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.rules_backend import layers_from_text

LET_ACROSS = [
    "I had pulled up at the zebra to let a lad cross when a motorbike came past me on the outside.",
    "We had stopped to let an elderly man with a stick cross.",
    "I had slowed right down to let a jogger cross, then I carried on at 20 mph.",
    "We had pulled up to let a woman with a buggy cross when a van overtook us.",
]


@pytest.mark.parametrize("text", LET_ACROSS)
def test_a_walker_let_across_by_a_stopped_ego_crosses_in_front(text):
    walkers = [names for kind, names in acts(text) if kind == "pedestrian"]
    assert walkers and walkers[0] == ["cross_in_front"]


def test_a_rider_let_across_crosses_in_front_too():
    assert acts("I had braked to let a kid on a scooter cross.") == [("e-scooter", ["cross_in_front"])]


def test_the_one_let_across_crosses_in_front_of_the_standing_ego_and_the_pass_still_plays(tmp_path):
    layers = layers_from_text("I had stopped to let a boy cross when the taxi behind me pulled out round me.", 0)
    assert float(layers["ego"]["speed_mps"]) == 0.0
    assert [(a["type"], a["behaviour"]["behaviour"]) for a in layers["adversaries"]][0] == (
        "pedestrian",
        "cross_in_front",
    )
    assert played_problems(play_layers(layers, tmp_path), layers) == []


LET_SOMETHING_ELSE = [
    ("I had stopped to let a bus pull out when a cyclist rode up my inside.", ("truck", ["keep_going"])),
    ("I had stopped to let a lorry reverse into a yard.", ("truck", ["keep_going"])),
    ("I had stopped to let a cyclist go past.", ("bicycle", ["along_road"])),
    ("I had stopped to let a woman out of my car.", ("pedestrian", ["along_road"])),
]


@pytest.mark.parametrize(("text", "first"), LET_SOMETHING_ELSE)
def test_a_stop_in_the_past_for_any_other_move_still_opens_the_scene(text, first):
    """Guards: what the ego had stopped to let a vehicle do, or to let someone out, came before the
    scene, and is read as it was."""
    assert acts(text)[0] == first


@pytest.mark.parametrize(
    "text",
    ["I stopped to let a girl cross.", "I let a girl cross.", "I waited for a man to cross."],
)
def test_letting_across_in_the_simple_past_reads_as_it_did(text):
    assert acts(text)[0] == ("pedestrian", ["cross_in_front"])


WAITING_SOMEWHERE = [
    "I was doing 20 mph and stopped for a man on the pavement to cross.",
    "I had stopped to let a woman at the kerb cross.",
    "I slowed down to let a girl on the zebra cross.",
]


@pytest.mark.parametrize("text", WAITING_SOMEWHERE)
def test_where_the_one_let_across_waits_keeps_the_crossing_its_own(text):
    """A short phrase of where the walker waits, between the walker and the crossing ("a man on the
    pavement to cross"), says where the crossing starts: the crossing is still the walker's."""
    assert acts(text) == [("pedestrian", ["cross_in_front"])]


@pytest.mark.parametrize(
    ("text", "first"),
    [
        ("I stopped for a man on the pavement.", ("pedestrian", ["along_road"])),
        ("I waited for a woman by the bus stop to get on the bus.", ("pedestrian", ["along_road"])),
        ("I saw a cyclist on the pavement ahead of me.", ("bicycle", ["along_road"])),
        ("I had a van in the next lane pull out.", ("van", ["keep_going"])),
    ],
)
def test_a_place_after_a_road_user_with_no_crossing_after_it_reads_as_it_did(text, first):
    """Guards: with no crossing after it, a place said after the road user changes nothing."""
    assert acts(text)[0] == first
