"""How aggressively a road user acts, read from the scales of closeness, margin and timing with their
degree words and negation (:mod:`vei_scenario.language.manner`). Each group is one construction, in
wordings written for it (none taken from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.manner import stated_manner
from vei_scenario.language.reader import _tokens, read

# a closeness graded by a mild degree word, or more than wished: moderate
MILD_CLOSENESS = {
    "moderate": [
        "The taxi merged in front of me slightly close, I lifted off.",
        "A courier van nosed out of the side street a little too, er, a little close for comfort.",
        "The minibus came back in somewhat closer than I wanted.",
        "The pickup overtook and tucked in a little too close for comfort.",
    ],
}
# a closeness graded by a strong degree word: dangerous
STRONG_CLOSENESS = {
    "dangerous": [
        "The pickup swung in uncomfortably close to my bonnet.",
        "A lorry squeezed past way too tight.",
        "The estate car slotted in dangerously close in the fog.",
    ],
}
# a danger denied: safe alone, moderate beside a mild closeness
DENIED_DANGER = {
    "safe": [
        "The tractor pulled out of the farm gate ahead of us, nothing scary at all.",
        "A delivery van merged into the lane, it was not aggressive in any way.",
        "Cyclist crossed the lane in front. Never anything dramatic.",
    ],
    "moderate": [
        "The coach moved over a little close, though nothing alarming.",
        "A hatchback slotted in a bit tight but nothing mad.",
        "The jogger stepped out slightly close to my wing, nothing risky though.",
    ],
}
# a wide margin, said as a quantity of room or as a distance "well"/"a good way" off: safe
WIDE_MARGIN = {
    "safe": [
        "The horse rider crossed the lane a long way off.",
        "The moped pulled out a fair way ahead of us.",
        "The jogger crossed miles ahead of me.",
        "A camper van moved over well in front of us.",
        "The jogger crossed with heaps of space to my bumper.",
    ],
}
# a level stated under a label
LABELLED = {
    "dangerous": ["Case 12 | target: car, lane 2 | manoeuvre: cut-in | criticality: high"],
    "moderate": ["Cut-in by a van from the left lane, severity medium."],
    "safe": ["Pedestrian crossing at 30 m, crit low, dry road."],
}
# timing: an act done "very late" or "too late" is dangerous; "late afternoon" is a time
LATE = {
    "dangerous": [
        "The SUV in front swerved round the debris really late.",
        "A moped indicated and cut across too late for comfort.",
    ],
    None: ["A cyclist rode along the kerb in the late afternoon sun."],
}
# scales that disagree state no single class: the lexicon's reading of each clause stands
DISAGREEING = {
    None: [
        "A hatchback cut in aggressively, though a long way ahead of me.",
        "The van squeezed past a bit close, then pulled in well ahead.",
    ],
}
# closeness to a place is where a road user keeps, not a margin to the ego
POSITION = {
    "safe": [
        "A boy on a bike kept close to the verge all the way and I gave him heaps of room.",
        "The mobility scooter hugged the wall, tight to the kerb, and we passed with masses of space.",
        "A walker stayed close to the hedge, and I went by with plenty of room.",
    ],
}


def _cases(*groups: dict) -> list:
    return [(text, cls) for group in groups for cls, texts in group.items() for text in texts]


ALL = _cases(MILD_CLOSENESS, STRONG_CLOSENESS, DENIED_DANGER, WIDE_MARGIN, LABELLED, LATE, POSITION, DISAGREEING)


@pytest.mark.parametrize("text, cls", ALL)
def test_the_manner_is_read_from_its_scale(text, cls):
    assert stated_manner(_tokens(text)) == cls


@pytest.mark.parametrize("text, cls", [(t, c) for t, c in ALL if c is not None])
def test_the_one_road_user_takes_the_stated_manner(text, cls):
    specs = read(text).actors
    classes = {b[2] for s in specs for b in s.behaviours if b[2] is not None}
    assert classes == {cls}, [(s.kind, s.behaviours) for s in specs]


# a manner said in a clause whose subject is another road user is that road user's, not the encounter's
OTHERS_MANNER = [
    "A hatchback pulled out of the side road and we collided. A minibus behind me stopped safely.",
    "The moped swung out from the kerb into my path. A cyclist further back pulled up gently.",
    "A pickup nosed out of the farm track into my lane; the tractor following it waited politely.",
]


@pytest.mark.parametrize("text", OTHERS_MANNER)
def test_a_manner_said_of_another_road_user_is_not_the_encounters(text):
    first = read(text).actors[0]
    assert all(b[2] != "safe" for b in first.behaviours), first.behaviours


# an act that ends right at the ego ("cut straight in front of us", "swung directly across our bonnet"):
# dangerous; the same words naming where a road user stands ("the car directly in front of me") say no manner
@pytest.mark.parametrize(
    "text, cls",
    [
        ("A courier van swerved straight in front of us on the flyover.", "dangerous"),
        ("The taxi swung out directly across our bonnet.", "dangerous"),
        ("A jogger darted bang in front of the ego.", "dangerous"),
        ("The moped went across my front bumper from the left.", "dangerous"),
        ("The car directly in front of me braked gently for the lights.", None),
        ("A pickup stood right in front of us at the lights.", None),
    ],
    ids=["swerved-straight-in-front", "directly-across-our-bonnet", "bang-in-front", "across-my-bumper",
         "the-car-directly-in-front", "stood-right-in-front"],
)  # fmt: skip
def test_an_act_ending_right_at_the_ego_is_dangerous(text, cls):
    assert stated_manner(_tokens(text)) == cls


def _class(text: str) -> str | None:
    return stated_manner(_tokens(text))


@pytest.mark.parametrize(
    "text",
    [
        "The lorry merged into my lane, forcing me to brake hard.",
        "A hatchback overtook and came back in, forced us onto the verge.",
        "The bus pulled out from the stop and forces the ego into the next lane.",
    ],
    ids=["forcing-me-to", "forced-us-onto", "forces-the-ego-into"],
)
def test_forcing_the_ego_into_a_reaction_is_dangerous(text):
    assert _class(text) == "dangerous"


@pytest.mark.parametrize(
    "text",
    [
        "A taxi cut in ahead of us with about 3 metres to spare.",
        "The pickup slotted in front of me with maybe 8 feet to spare.",
        "A moped pulled across with just 2 m to spare.",
    ],
    ids=["3-metres-to-spare", "8-feet-to-spare", "2-m-to-spare"],
)
def test_a_few_metres_to_spare_is_dangerous(text):
    assert _class(text) == "dangerous"


@pytest.mark.parametrize(
    "text",
    [
        "A van pulled out of a side road and I had to stamp on the brakes.",
        "A cyclist swerved out in front of me and I swerved hard to miss him.",
        "The car ahead cut in; we braked sharply.",
    ],
    ids=["stamp-on-the-brakes", "swerved-hard", "braked-sharply"],
)
def test_the_egos_hard_evasion_makes_the_act_dangerous(text):
    assert _class(text) == "dangerous"


@pytest.mark.parametrize(
    "text, cls",
    [
        ("A cyclist crossed ahead of the ego with 40 metres to spare.", None),
        ("A van pulled out well ahead and I braked gently.", "safe"),
        ("Cross-traffic forced its way through but a truck stopped in its lane.", None),
        ("The van cut in a bit close, I braked hard.", "moderate"),
    ],
    ids=["40-metres-to-spare", "braked-gently", "forced-its-way-not-the-ego", "mild-closeness-wins"],
)
def test_a_wide_margin_a_mild_reaction_or_a_stated_closeness_is_not_made_dangerous(text, cls):
    assert _class(text) == cls


@pytest.mark.parametrize(
    "text, crit",
    [
        ("Doing 60 mph on the motorway when a coach barged into my lane about 15 feet ahead of me.", "dangerous"),
        ("Ego at 90 km/h; a hatchback cuts in 12 m in front of it.", "dangerous"),
        ("Ego at 30 km/h; a hatchback cuts in 25 m in front of it.", None),
        ("Ego at 90 km/h; a hatchback cuts in gently, 12 m in front of it, leaving plenty of room.", "safe"),
    ],
    ids=["coach-15-feet", "spec-12-m", "slow-ego", "said-safe"],
)
def test_a_cut_in_under_a_second_ahead_is_dangerous(text, crit):
    cut_in = [b for a in read(text).actors for b in a.behaviours if b[0] == "cut_in"]
    assert cut_in and cut_in[0][2] == crit


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 90 km/h; a hatchback cuts in 12 m in front of it. The outcome should be safe.",
        "Ego at 90 km/h; a motorbike at 120 km/h cuts in 12 m in front of it.",
    ],
    ids=["said-safe-outcome", "faster-cutter"],
)
def test_a_tight_cut_in_said_safe_or_pulling_away_is_not_made_dangerous(text):
    cut_in = [b for a in read(text).actors for b in a.behaviours if b[0] == "cut_in"]
    assert cut_in and cut_in[0][2] != "dangerous"
