"""What a counterfactual, a question or a passive says is not the road user's own act.

Three rules read a road user's act from where it goes or from the one who let it go: a walker the ego
stopped for, "for a man on the pavement to cross" (experiencer), a road user's verb "out of" the ego's
lane (out_of_the_lane) and one "behind me the whole way" (motion). None of them reads the act where
the clause does not tell it as done: under "would have" / "if ... had" (what did not happen), in a
yes/no question about the road user (which asserts nothing), or in a passive (the road user is moved,
and the doer is named after "by"). The same sentences told as done keep their reading.
"""

from __future__ import annotations

import pytest
from reading_of import acts

# --- finding 4: a crossing the ego would have stopped for -----------------------------------------

NOT_CROSSED = [
    "I would have stopped for a man on the pavement to cross but he waved me on.",
    "I would have let a woman at the kerb cross but she waved me on.",
    "We would have waited for a lady on the pavement to cross, but she waved us through.",
    "If I had stopped for a man on the pavement to cross, the van behind would have hit me.",
    "Should I have stopped for a man on the pavement to cross?",
]

CROSSED = [
    "I stopped for a man on the pavement to cross.",
    "I let a woman at the kerb cross.",
    "I had pulled up to let an old man cross when a van overtook me.",
    "We waited for a lady on the pavement to cross, then a van overtook us.",
]


@pytest.mark.parametrize("text", NOT_CROSSED)
def test_a_walker_the_ego_would_have_stopped_for_does_not_cross(text):
    walkers = [names for kind, names in acts(text) if kind == "pedestrian"]
    assert all("cross_in_front" not in names for names in walkers), acts(text)


@pytest.mark.parametrize("text", CROSSED)
def test_a_walker_the_ego_stopped_for_crosses(text):
    walkers = [names for kind, names in acts(text) if kind == "pedestrian"]
    assert walkers and walkers[0][0] == "cross_in_front", acts(text)


# --- finding 5: "out of my lane" in a counterfactual or a passive ---------------------------------

NOT_LEFT = [
    "If the van ahead had moved out of my lane I would have been fine.",
    "If the lorry in front had pulled out of our lane, I could have got past.",
    "The van in front was pulled out of my lane by the tow truck.",
    "The car in front of us was moved out of our lane by the police.",
    "The lorry ahead of me had been moved out of my lane.",
    "Did the van in front of me drift out of my lane?",
]

LEFT = [
    ("The van in front of me drifted out of my lane.", "van"),
    ("The lorry in front had moved out of our lane when I caught up with it.", "truck"),
    ("I was fine because the van ahead had moved out of my lane.", "van"),
    ("The van in front was moving out of my lane.", "van"),
]


@pytest.mark.parametrize("text", NOT_LEFT)
def test_a_move_out_of_the_ego_lane_not_told_as_done_is_no_lane_change(text):
    assert all("change_lane" not in names for _, names in acts(text)), acts(text)


@pytest.mark.parametrize(("text", "kind"), LEFT)
def test_a_move_out_of_the_ego_lane_told_as_done_is_a_lane_change(text, kind):
    assert (kind, ["change_lane"]) in acts(text)


# --- finding 7: "behind us the whole way" asked -----------------------------------------------------

ASKED = [
    "Was that van behind us the whole way?",
    "Was the white car behind me all the way to town?",
    "Is that lorry behind us the whole way?",
    "Was that van behind us for two miles?",
]

TOLD = [
    "A pickup stayed behind me the whole way.",
    "The car behind me the whole way then overtook at the lights.",
    "Why was that van behind us the whole way?",
    "A van was behind us the whole way, wasn't it?",
    "Can you make a scenario where a van stays behind me the whole way?",
]


@pytest.mark.parametrize("text", ASKED)
def test_a_road_user_asked_about_behind_the_ego_does_not_follow(text):
    assert all("follow_vehicle" not in names for _, names in acts(text)), acts(text)


@pytest.mark.parametrize("text", TOLD)
def test_a_road_user_told_behind_the_ego_the_whole_way_follows(text):
    assert any(names[0] == "follow_vehicle" for _, names in acts(text)), acts(text)
