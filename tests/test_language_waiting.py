"""Anyone staying put while another road user goes, or sending one on, is giving way: a safe pass
when nothing else is said (:func:`vei_scenario.language.outcome._lets_another_go`). Wordings written
for these tests in many registers, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import outcome_cues, stated_intent
from vei_scenario.language.reader import _tokens


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


# whoever stays put for another road user, behind one or while one goes, gives way
STAYS_FOR_ANOTHER = [
    "The robotaxi waited for the old man with his walking frame.",  # US, a sighting
    "Saw the test pod at the lights on Kent St, it sat there patiently while two schoolkids crossed.",  # AU text
    "The lorry driver stopped and waited while the cyclist went through.",  # UK
    "Subject vehicle held back behind the cyclist for the length of the bridge.",  # a test spec
    "The autorickshaw fellow paused until the aunty crossed over.",  # Indian English
    "That taxi man sat behind the okada for one whole kilometre, no wahala.",  # Nigerian English
    "The bus uncle waited for the cyclist, very patient one.",  # Singaporean English
    "Vehicle 1 stopped while Ms Okoro walked across to the pharmacy.",  # a police report
    "A delivery van idled behind me all the way up the climb instead of squeezing past.",  # a rider's thanks
    "I just sat behind the scooter till the junction.",  # a voice note
]
# a signal that sends a person on: the one who gives it gives way
SENDS_ANOTHER_ON = [
    "The cabbie waved me through at the narrow bit.",
    "A farmer in a pickup flashed us out of the side road.",
    "The bus driver beckoned the boy across.",
    "The lady in the hatchback motioned him on with a smile.",
    "We waved the cyclists past on the single track.",
]


@pytest.mark.parametrize("text", STAYS_FOR_ANOTHER + SENDS_ANOTHER_ON)
def test_staying_put_for_another_or_sending_one_on_is_a_safe_pass(text):
    assert _intent(text) == "safe", outcome_cues(" ".join(_tokens(text)))


# near misses: a wait that is no giving way, or one not made
NOT_GIVING_WAY = [
    "A man was waiting at the kerb to cross.",  # where he is, not what he does for anyone
    "We waited in the queue behind the bus for ten minutes.",  # one's turn in traffic
    "The car waited at the lights behind a cyclist.",  # at the lights: one's turn
    "The van waited for a gap in the traffic.",  # a stay for a gap, not a road user
    "The taxi did not wait for the pedestrian.",  # denied
    "The lorry driver flashed his lights at me.",  # a signal that sends nobody on
    "The cyclist waved at us.",  # a greeting
    "He sat in the car for a while.",  # sitting, not waiting on anyone
]


@pytest.mark.parametrize("text", NOT_GIVING_WAY)
def test_a_wait_that_is_no_giving_way_states_no_safe_pass(text):
    assert _intent(text) != "safe", outcome_cues(" ".join(_tokens(text)))


def test_a_stop_forced_by_a_sudden_move_stays_a_near_miss():
    text = "A kid shot out between the parked cars and I slammed on the brakes and waited while he crossed."
    assert _intent(text) == "near_miss"


def test_contact_after_a_wait_is_still_a_collision():
    assert _intent("The van waited for the cyclist and then hit him as he passed.") == "collision"
