"""A word of contact states this scene's collision only when it is said of this scene's road users:
not when its object is a thing no road user is ("knocked the radio off", "hit my bonus"), not when
it is a plural noun counted or listed (statistics, "two clips a day"), not when it is the subject of
a modal ("the impact would come at ..."), the destination of a call ("Cat 1 to an RTC"), or under
"near enough" or "I'd have" (a counterfactual). A length left "off" a vehicle's part, or "clear" of
the other, is a margin; a reaction made early or smoothly is no escape. Wordings written for these
tests."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import stated_intent
from vei_scenario.language.reader import _tokens
from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


NOT_A_COLLISION = [
    # a contact verb whose object is a thing, not a road user nor a vehicle's part
    ("A cyclist wobbled out in front of me. I knocked the music off so I could hear him.", None),
    ("The van cut in and I stood on the brakes, stopped a foot off his bumper. Will this hit my bonus?", "near_miss"),
    ("A bus pulled out ahead of us; the driver hit the siren late and we braked gently.", "safe"),
    # plural nouns of contact that count or list many events, not this one
    ("A lorry overtook me close. Council figures show 31 recorded collisions on this road since May.", "close"),
    ("A scooter crossed ahead and I braked hard. My instructor says watch the clips he sent me.", "near_miss"),
    ("A pedestrian stepped out and I stopped in time. Practise two clips a day, she said.", "near_miss"),
    # a contact noun as the subject of a modal: a supposed event
    ("The target car brakes; the impact would come at 40 km/h if the ego did nothing.", None),
    # "near enough" hedges the contact that follows it
    ("A taxi cut across and near enough took my front end off.", "near_miss"),
]

STILL_A_COLLISION = [
    ("A van pulled out and hit the cyclist.", "collision"),
    ("The car clipped my wing mirror and drove off.", "collision"),
    ("He hit him almost head on.", "collision"),
    ("A scooter rider knocked the boy off his bike.", "collision"),
    ("The lorry went into the back of the bus.", "collision"),
    ("The taxi struck a jogger crossing at the lights.", "collision"),
    ("There was one collision: the van hit the cyclist.", "collision"),
    ("I nearly hit a kid on a scooter.", "near_miss"),
    ("I hit the brakes and the cyclist went past.", None),
    ("No collisions were recorded at the junction that day; a van stopped for a walker.", "safe"),
]

COUNTERFACTUAL_AND_PLACE = [
    # "'d have" is "would have": what did not happen
    ("Two riders shot across the junction. I'd have driven straight into them. I waited.", "near_miss"),
    ("We'd have hit the van if Dad hadn't grabbed the wheel.", "near_miss"),
    ("I'd hit the cyclist before I even saw him.", "collision"),
    # a contact noun as where a call goes, not what happened here
    ("Responding, Cat 1 to an RTC. A cyclist rode ahead of us and we slowed smoothly behind him.", "safe"),
    ("The van's late braking led to a collision with the cyclist.", "collision"),
    # "versus" names a collision only between road users
    ("Report: taxi versus cyclist at the lights.", "collision"),
    ("Swerving versus braking: the car braked and a pedestrian crossed ahead.", None),
]

PLANNED_REACTIONS = [
    ("A walker stepped out 30 m ahead. The shuttle detected her early and slowed smoothly; she crossed.", "safe"),
    ("The learner spotted the bike early and eased off; it went by.", "safe"),
    ("A kid ran out and I spotted him early, but I still had to slam on and stopped inches off him.", "near_miss"),
    ("He should have slowed early; instead he clipped the cyclist.", "collision"),
    ("A rider pulled across ahead of us. Zero drama, we had seen him.", "safe"),
    ("Don't worry! A rider pulled across ahead, I braked really hard, no contact.", "near_miss"),
    ("Conditions fine and dry. A van cut into my lane.", None),
]

MARGINS = [
    ("The rider shot across and I stopped about half a metre off his front wheel.", "near_miss"),
    ("A car swung across our lane and pulled up a foot off our front bumper.", "near_miss"),
    ("The walker kept going, about 1 m clear of the test car.", "near_miss"),
    ("The cyclist went past with 3 m clear and the car held its speed.", None),
]


def _kind(intent: str | None) -> str | None:
    return {"close": "near_miss"}.get(intent or "", intent)


CASES = NOT_A_COLLISION + STILL_A_COLLISION + COUNTERFACTUAL_AND_PLACE + PLANNED_REACTIONS + MARGINS


@pytest.mark.parametrize("text,intent", CASES)
def test_contact_is_read_of_the_scenes_road_users(text: str, intent: str | None) -> None:
    got = _intent(text)
    if intent == "close":
        assert got != "collision", text
    else:
        assert got == intent, text


def test_a_thing_knocked_off_gives_no_collision_layers() -> None:
    text = "A lad on a scooter rode along ahead of me at 20 km/h, so I knocked the siren off and followed him."
    assert layers_from_text(text, 0)["intent"] != "collision"


def test_a_cyclist_knocked_off_gives_collision_layers() -> None:
    text = "A van pulled out of a side road at 30 km/h and knocked a cyclist off her bike."
    assert layers_from_text(text, 0)["intent"] == "collision"


def test_all_fine_after_a_cut_in_is_a_near_miss() -> None:
    """Reassurance after a road user came into the ego's lane says the danger was real."""
    text = "I was doing 50 km/h when a van cut into my lane right in front of me. We're all fine."
    assert layers_from_text(text, 0)["intent"] == "near_miss"


def test_all_fine_after_a_plain_pass_stays_safe() -> None:
    text = "I was doing 50 km/h and a van passed me in the other lane. We're all fine."
    assert layers_from_text(text, 0)["intent"] != "near_miss"
