"""A contact denied in so many words as the verdict on the scene ("No contact.", "nobody touched", "I
didn't hit him") outranks a word of contact said in an earlier sentence: that word was of another
event, a risk, a name or a figure of speech (:func:`vei_scenario.language.outcome.outcome_cues`).
Wordings written for these tests, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import outcome_cues, stated_intent
from vei_scenario.language.reader import _tokens


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


# a contact word in an earlier sentence, then the verdict that there was none: a near miss
VERDICT_AFTER = [
    # a British voice note: "rammed" is a crowded road
    "The high street was absolutely rammed. A delivery rider cut across my bonnet and I stood on the brakes. "
    "No contact.",
    # a bus driver's radio log: the crash is another job
    "Control said there was a crash on the ring road so we went the back way. A kid on a scooter shot out in front "
    "of us and we braked hard, no collision.",
    # a road safety audit: a risk, then what was seen
    "Summary: risk of turning vans striking cyclists here. On the visit a van turned across a rider, who braked "
    "sharply. No contact occurred.",
    # an American text message
    "need to report an accident. some guy on a bike came out of nowhere. i braked so i didnt hit him",
    # a social post that names its topic
    "Car vs pedestrian?? Driver doing 30, lady steps off the kerb without looking, car brakes, nobody touches.",
    # a Nigerian account: the crash was earlier, elsewhere
    "Traffic was heavy because a bus had crashed near the market. An okada swerved across my lane and I braked "
    "sharply. There was no contact at all.",
    # a Singaporean message
    "Wah the jam so bad after the accident on the expressway. Then a PMD fella cut in front of me, I jam brake. "
    "Never hit him lah.",
    # an Indian report
    "Last month one accident happened at this signal itself. Today one auto cut in front of my car suddenly and "
    "I applied brake hard. We did not touch.",
]


@pytest.mark.parametrize("text", VERDICT_AFTER)
def test_a_verdict_of_no_contact_outranks_an_earlier_contact_word(text):
    assert _intent(text) == "near_miss", outcome_cues(" ".join(_tokens(text)))


# near misses of the reading: a contact that stands
STANDS = [
    # a contact said after the verdict: the second one was hit
    "No contact with the first cyclist. The second one hit my bumper.",
    # the verdict said of a third road user, not of the scene
    "The van braked and I rear-ended it. The lorry behind me pulled up without contact.",
    # the contact in the verdict's own sentence: the denial is partial
    "He clipped my mirror, but no contact with the rider himself.",
    # no negator: a time before the impact
    "The driver braked 0.6 s before impact. The collision occurred at 30 km/h.",
    # a denial of harm, not of contact
    "The scooter hit my door. Nobody was hurt.",
    # a contact denied only in its degree
    "I clipped the cyclist's back wheel. I did not hit him hard.",
    "A moped shunted me at the lights. No serious collision, just a dent.",
]


@pytest.mark.parametrize("text", STANDS)
def test_a_contact_that_no_verdict_denies_stays_a_collision(text):
    assert _intent(text) == "collision", outcome_cues(" ".join(_tokens(text)))


# the other's denial of touching the ego is a verdict too
@pytest.mark.parametrize(
    "text",
    [
        "Some idiot said on the group chat that a crash happened here. The van swerved at me but it never touched me.",
        "The junction is an accident black spot. A cyclist ran the red and swerved, and he did not hit us.",
    ],
)
def test_the_other_denied_touching_the_ego_is_a_verdict(text):
    assert _intent(text) == "near_miss", outcome_cues(" ".join(_tokens(text)))


# the scene named a near miss is a verdict too; many near misses, or one before a later contact, are not
@pytest.mark.parametrize(
    "text, intent",
    [
        ("Control: RTC on the bypass, all units avoid. Unit 12 here, just had a near miss at the lights, a car "
         "pulled out and I braked hard.", "near_miss"),
        ("There was a smash on the high road earlier. Mine was a close call: a moped cut across me.", "near_miss"),
        ("A car hit me at the junction. Locals say there have been loads of near misses here.", "collision"),
        ("After last week's close call, today a scooter actually hit my door.", "collision"),
    ],
)  # fmt: skip
def test_a_near_miss_named_is_a_verdict_on_the_scene(text, intent):
    assert _intent(text) == intent, outcome_cues(" ".join(_tokens(text)))
