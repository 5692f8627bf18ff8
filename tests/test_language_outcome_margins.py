"""The margin a description states as a length (:mod:`vei_scenario.language.outcome`): what was left
ahead after a stop or a cut-in ("stopped, two metres to spare", "with about a metre left"), a length
bounded from above ("1 m max", "half a metre at most"), a pass's small clearance ("passed me with
maybe 50 cm"); and a post's sign-off ("stay safe, guys"), which wishes the reader well and states no
outcome. Wordings written for these tests, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import stated_intent
from vei_scenario.language.reader import _tokens


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


# what was left ahead once the ego stopped (said in a clause of its own, or as "left" or "spare"),
# or once someone cut in: a gap ahead, a near miss
GAP_AHEAD = [
    "The lorry in front slammed on and we stopped, what, two metres to spare.",
    "Braked as hard as I could, and pulled up, maybe 2 m to spare.",
    "The bus stopped with about a metre left.",
    "Ego halts w/ ~2 m left to the pedestrian.",
    "Hit the brakes and stopped with 3 feet left.",
    "I managed to stop with a car length spare.",
    "Auto came to a stop, hardly 1.5 metre spare.",
    "A taxi cut in front of me with 2 metres to spare at 60 mph.",
    "The truck merged into my lane with 3 m to spare.",
]


@pytest.mark.parametrize("text", GAP_AHEAD)
def test_a_gap_left_ahead_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


# a length bounded from above, or a pass's clearance of a metre or less: a near miss
SMALL_CLEARANCE = [
    "The lorry passed me, 1 m max.",
    "He overtook me with half a metre at most.",
    "The bus passes me with maybe 50 cm, then pulls in.",
    "The car went by with 30cm tops.",
    "Van overtook the cyclist with about 2 feet, if that.",
    "Got passed by a tipper with 60 cm or less.",
]


@pytest.mark.parametrize("text", SMALL_CLEARANCE)
def test_a_small_clearance_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


# near-miss negatives: a pass's wide clearance, a length that is a size or a distance still to go,
# "left" as a side, a wide bound
NOT_SMALL = [
    ("The van overtook the cyclist with 2 metres to spare.", "safe"),
    ("I passed the rider with about two metres to spare.", "safe"),
    ("The van stopped at the lights and I passed it with 2 m to spare.", "safe"),
    ("She pulled up with 200 m left to go.", None),
    ("The car went by with 2 m at least.", None),
    ("A cyclist with a 50 cm wide trailer rode past me.", None),
    ("The scooter was 1 m left of the lane line.", None),
    ("I stopped with 2 m left of the stop line showing.", "safe"),  # (a plain stop: it gave way)
    ("We stopped with 50 m left to run before the junction.", "safe"),
    ("The bus stopped with 2 m left to the stop line.", None),
    ("A cyclist was riding with 50 cm to the kerb when I passed him wide.", "safe"),
]


@pytest.mark.parametrize(("text", "intent"), NOT_SMALL)
def test_no_small_margin(text: str, intent: str | None) -> None:
    assert _intent(text) == intent


# a sign-off wishing the reader well states no outcome: what else is said decides
SIGN_OFFS = [
    ("A van cut across me at the lights, brakes saved me, 1 m max. Stay safe guys", "near_miss"),
    ("Scooter came off the pavement, I had to swerve. Drive safe out there everyone!", "near_miss"),
    ("A bus turned across my lane, I missed it by a whisker. Ride safely all", "near_miss"),
    ("A kid ran out after a ball and I braked hard. Get home safe, folks.", "near_miss"),
    ("Be safe out there x", None),
]


@pytest.mark.parametrize(("text", "intent"), SIGN_OFFS)
def test_a_sign_off_states_no_outcome(text: str, intent: str | None) -> None:
    assert _intent(text) == intent


# near-miss negatives: safety said of someone, or an instruction about a path or a spacing
SAID_OF_SOMEONE = [
    "The cyclist stayed safe.",
    "I stayed safe the whole time.",
    "Keep a safe distance from the rider.",
    "Drive safely past the cyclist.",
    "The ego passes the jogger safely.",
]


@pytest.mark.parametrize("text", SAID_OF_SOMEONE)
def test_safety_said_of_someone_is_safe(text: str) -> None:
    assert _intent(text) == "safe"


#: "a good" length after "for", "over" or "along" is a stretch of road gone along, no margin: what else
#: is said decides
STRETCH_GONE_ALONG = [
    ("I sat 2 m behind the van for a good 200 m. It braked sharply and I had to brake hard.", "near_miss"),
    ("He tailgated me for a good 300 metres, then overtook and cut in.", None),
    ("The cyclist rode in front of us over a good 100 m, then swerved and I braked hard. No contact.", "near_miss"),
]
#: the margin of a pass or a stop with "a good" length stays a wide one
GOOD_MARGIN_KEPT = [
    "She passed the cyclist with a good 2 metres.",
    "The van passed me with a good 2 metres to spare.",
    "I stopped a good 10 metres away from her.",
]


@pytest.mark.parametrize("text, intent", STRETCH_GONE_ALONG)
def test_a_good_stretch_gone_along_is_no_margin(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize("text", GOOD_MARGIN_KEPT)
def test_a_good_margin_is_still_wide(text):
    assert _intent(text) == "safe"
