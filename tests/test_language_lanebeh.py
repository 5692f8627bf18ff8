"""Three lane behaviours said by where a road user is, not by the verb:

* a road user that goes "out of" the ego's lane ("the lorry in front drifted out of our lane") changes
  lanes out of it, whatever the verb, and with something standing in the lane it leaves it is the
  cut-out that reveals it;
* a road user kept behind the ego over a stretch said as a bare noun phrase ("behind me the whole way",
  "behind us all the way to town") follows it, as one "behind me for two miles" does;
* an overtaker of the ego that swings back in ("swung back in", "swung in again") close in front of it
  cuts in, as one that swerves or cuts back in does.

The guards keep the ego's own move, a walker, a lane that is not the ego's, a move out to overtake, a
denied move, a rider at its own pace and a vehicle parked behind."""

from __future__ import annotations

import pytest
from play_layers import play_layers
from reading_of import acts

from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.rules_backend import layers_from_text

OUT_OF_THE_EGO_LANE = [
    ("The lorry in front of us drifted slowly out of our lane.", [("truck", ["change_lane"])]),
    ("On the bypass the estate car ahead of me moved out of my lane.", [("car", ["change_lane"])]),
    ("The coach ahead of the ego pulled out of the ego's lane.", [("truck", ["change_lane"])]),
]

REVEALED = [
    "Cruising at 70 km/h, the hatchback ahead of me moved out of my lane and showed me a stalled car.",
    "The delivery van in front of us slid out of our lane, revealing a broken-down lorry.",
]


@pytest.mark.parametrize(("text", "expected"), OUT_OF_THE_EGO_LANE)
def test_a_move_out_of_the_ego_lane_is_a_lane_change(text, expected):
    assert acts(text) == expected


@pytest.mark.parametrize("text", REVEALED)
def test_a_lead_out_of_the_ego_lane_past_something_standing_is_a_cut_out(text, tmp_path):
    layers = layers_from_text(text, 0)
    names = [a["behaviour"].get("behaviour") for a in layers["adversaries"]]
    assert "cut_out" in names
    assert played_problems(play_layers(layers, tmp_path), layers) == []


KEEPS_ITS_READING = [
    # the ego's own move out of its lane
    ("I moved out of my lane to let a fire engine through.", "change_lane", False),
    # out of a lane that is not the ego's, into the ego's: a cut-in
    ("A cyclist swerved out of the bike lane into my lane.", "cut_in", True),
    # a move out made to overtake: the overtake is the move
    ("The car in front of me pulled out of my lane to overtake a tractor.", "overtake", True),
    # a denied move
    ("The van ahead of me never moved out of my lane.", "change_lane", False),
]


@pytest.mark.parametrize(("text", "name", "present"), KEEPS_ITS_READING)
def test_near_misses_of_a_move_out_of_the_ego_lane_keep_their_reading(text, name, present):
    names = [n for _, moves in acts(text) for n in moves]
    assert (name in names) == present


BEHIND_FOR_A_STRETCH = [
    "A pickup stayed behind me the whole way.",
    "A black SUV was right behind us all the way to the ring road.",
    "The lorry sat behind me the entire journey, far too close.",
    "A taxi was behind me for the whole trip.",
]


@pytest.mark.parametrize("text", BEHIND_FOR_A_STRETCH)
def test_a_vehicle_behind_the_ego_over_a_stretch_said_bare_follows_it(text):
    [(_, moves)] = acts(text)
    assert moves == ["follow_vehicle"]


NOT_FOLLOWING = [
    # a rider behind for a stretch rides at its own pace
    "A cyclist was behind me the whole way.",
    # a vehicle standing behind the ego
    "A lorry was parked behind me the whole time.",
    # a move of its own
    "A hatchback behind me overtook me in the end.",
]


@pytest.mark.parametrize("text", NOT_FOLLOWING)
def test_near_misses_of_following_over_a_stretch_do_not_follow(text):
    assert all("follow_vehicle" not in moves for _, moves in acts(text))


SWUNG_BACK_IN = [
    "On the dual carriageway a coach passed me and swung back in directly in front of my car.",
    "A tipper truck overtook us on the bypass and swung in again right in front of us.",
]


@pytest.mark.parametrize("text", SWUNG_BACK_IN)
def test_an_overtaker_swinging_back_in_close_in_front_of_the_ego_cuts_in(text):
    [(_, moves)] = acts(text)
    assert moves == ["overtake", "cut_in"]


ONLY_THE_OVERTAKE = [
    # a plain return, not a swing
    "A tipper truck overtook us on the bypass and pulled in again in front of us.",
    # back in far ahead
    "A tipper truck overtook us on the bypass and swung in again well ahead of us.",
    # one lane each way: coming back in is how every overtake there ends
    "On a single carriageway a coach passed me and swung back in right in front of me.",
    # the pass is of someone else
    "A coach overtook the tractor and swung back in right in front of me.",
]


@pytest.mark.parametrize("text", ONLY_THE_OVERTAKE)
def test_near_misses_of_swinging_back_in_stay_an_overtake(text):
    assert all("cut_in" not in moves for _, moves in acts(text))
