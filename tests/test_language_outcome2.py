"""The outcome read from a few more constructions (:mod:`vei_scenario.language.outcome`): a stop the
situation forced, a margin told as "a good" measure, one vehicle's length or "well before", a touch of a
part named by "mine", a verb of touching a part, a negation of a noun phrase only, a condition's own
scope, a hortative "let us" and letting someone across. Wordings written for these tests; each group
has guards that must keep their reading."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _intent(text: str) -> str | None:
    return read(text).intent


# a stop or a brake someone had to make is forced, not a wait: with "all fine" after it, a near miss
FORCED_STOP = [
    "A scooter shot across the junction against the lights. I'd pulled forward and had to stop in the middle. "
    "All fine.",
    "On the ring road the taxi ahead of us jammed on, and our driver had to brake. All fine.",
    "A lad on a bike came out of the park gates and I had to stop short of the crossing, all ok in the end.",
]
# a stop at the lights or in a queue stays one's turn
FORCED_STOP_GUARDS = {
    "I drove into town behind a cyclist and had to stop at the lights; I waited for him and he went.": "safe",
}


@pytest.mark.parametrize("text", FORCED_STOP)
def test_a_forced_stop_then_all_fine_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text,intent", FORCED_STOP_GUARDS.items())
def test_a_stop_in_a_queue_keeps_its_reading(text: str, intent: str) -> None:
    assert _intent(text) == intent


# "a good" before a measure makes it a lower bound; a car's length left by a stop is close;
# "well before" after a stop is a wide margin
MARGINS = {
    "The bus overtook me on the hill with a good two metres, nice and steady.": "safe",
    # ("a good metre" is at least a metre, under a pass's 1.5 m: review G2)
    "A cyclist wobbled past my car with a good metre to spare.": "near_miss",
    "The van pulled out of the side road and we stopped maybe a car's length from it.": "near_miss",
    "A child chased a ball into the road and I stopped well before her.": "safe",
    "A man reversed off his drive into my path and stopped about a foot away from me.": "near_miss",
}
MARGIN_GUARDS = {
    "A cyclist wobbled past my car with a metre to spare.": "near_miss",
    "A child ran out after a ball and I stopped just in time.": "near_miss",
}


@pytest.mark.parametrize("text,intent", {**MARGINS, **MARGIN_GUARDS}.items())
def test_margins(text: str, intent: str) -> None:
    assert _intent(text) == intent


# a verb of touching a part, a part named by "mine", a part of a bike: contact
CONTACT = [
    "The delivery van's rear corner contacted our front bumper as it turned.",
    "A motorbike filtering between the lanes caught my passenger's side mirror.",
    "A lorry came through the gap and its wing mirror knocked mine clean off.",
    "A rider went between me and the hedge, clipping my basket.",
]
# the ego's own control, told as "mine" with no part named before it, is no contact
OWN_CONTROL = [
    "A van cut across in front of us. My son did brake, but late, and I had to touch mine as well. "
    "We stopped just short.",
]


@pytest.mark.parametrize("text", CONTACT)
def test_a_part_touched_is_a_collision(text: str) -> None:
    assert _intent(text) == "collision"


@pytest.mark.parametrize("text", OWN_CONTROL)
def test_the_egos_own_control_is_no_contact(text: str) -> None:
    assert _intent(text) != "collision"


# "not" before a possessed noun denies that noun, not the verb after it
NOUN_NEGATED = [
    "I stopped behind the lorry, but the car behind me, not my brother's, rear-ended me.",
    "A pickup, not our customer's truck, ran into the back of him at the lights.",
]
NOUN_NEGATED_GUARDS = {
    "The van behind did not hit me; it stopped a metre short.": "near_miss",
    "The lorry pulled out and I did not hit it, I stopped in time.": "near_miss",
}


@pytest.mark.parametrize("text", NOUN_NEGATED)
def test_a_negated_noun_leaves_the_contact(text: str) -> None:
    assert _intent(text) == "collision"


@pytest.mark.parametrize("text,intent", NOUN_NEGATED_GUARDS.items())
def test_a_denied_verb_stays_denied(text: str, intent: str) -> None:
    assert _intent(text) == intent


# a negation before "if" does not reach into its condition ("do not hesitate ... if you have any
# problems": nothing said of trouble); "let us" opening a clause is a wish, not giving way; letting
# someone across is giving way
SCOPES = {
    "A rider came the wrong way round the roundabout and you had to brake sharply to avoid him. "
    "Please do not hesitate to call us if you have any further problems.": "near_miss",
    "Mr Lane had to brake hard when a scooter shot off the pavement in front of him. No harm done. "
    "Let us all be careful out there.": "near_miss",
    "The car stopped at the zebra and let the old man across. No contact.": "safe",
}
SCOPE_GUARDS = {
    "A cyclist waited at the kerb and let me go past before crossing. No problems at all.": "safe",
    "I pulled up and waved the jogger across.": "safe",
}


@pytest.mark.parametrize("text,intent", {**SCOPES, **SCOPE_GUARDS}.items())
def test_scopes(text: str, intent: str) -> None:
    assert _intent(text) == intent


# a brake made gently or progressively, by anyone, is a reaction in good time: a safe pass
GENTLE_BRAKE = [
    "Camera car doing 30. A scooter rider turns out of the side road into its lane; the camera car brakes gently.",
    "A taxi pulled out from the rank ahead of the bus and the driver braked progressively behind it.",
]
GENTLE_BRAKE_GUARDS = [
    "A taxi pulled out ahead of the bus and the driver braked gently, then slammed on its brakes.",
    "I was doing 40 when a van cut in and I braked gently, but I still clipped its bumper.",
]


@pytest.mark.parametrize("text", GENTLE_BRAKE)
def test_a_gentle_brake_is_a_safe_pass(text: str) -> None:
    assert _intent(text) == "safe"


@pytest.mark.parametrize("text", GENTLE_BRAKE_GUARDS)
def test_a_gentle_brake_then_more_is_not_safe(text: str) -> None:
    assert _intent(text) != "safe"


# the guards of the brief: their readings stay
@pytest.mark.parametrize(
    "text,intent",
    [
        ("A van pulled out of a side road and hit me.", "collision"),
        ("A Golf pulled out of the junction and I hit the Golf.", "collision"),
        ("Two scooters came through the junction; I'd have gone right into them, but I waited.", "near_miss"),
    ],
)
def test_guards(text: str, intent: str) -> None:
    assert _intent(text) == intent


def test_zero_issues_until_a_van_pulled_out_is_not_safe() -> None:
    assert _intent("Zero issues until a van pulled out right in front of me and I had to swerve.") != "safe"
