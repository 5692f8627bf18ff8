"""Outcomes told in constructions the outcome reader once misread (:mod:`vei_scenario.language.outcome`):
the sound of a hard brake, a harm denied of a subject its clause leaves out, a contact only thought
of, a negation whose verb is left out, and a stop short of a road marking. Wordings written for these tests,
none taken from a corpus; the guards keep the old reading of their near neighbours."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import stated_intent
from vei_scenario.language.reader import _tokens
from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


# the sound of locked tyres, told as what happened: someone braked as hard as they could
BRAKING_SOUNDS = [
    "We were crawling along at 15 mph behind a bin lorry when a jogger crossed ahead of it. Screeeech. Everyone okay.",
    "A pensioner stepped off the kerb ahead of the minibus, brakes squealing, and she shuffled on across.",
    "The taxi stopped with a screech of tyres as the lad on the scooter rolled out of the alley.",
    "Tyres screeched. The dog trotted back to its owner and the van went on.",
]


@pytest.mark.parametrize("text", BRAKING_SOUNDS)
def test_a_braking_sound_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


BRAKING_SOUND_GUARDS = {
    "I heard tyres screech behind me and then the van slammed into my back bumper.": "collision",
    "The kids squealed with delight, and we waited while the ice-cream van pulled away.": "safe",
}


@pytest.mark.parametrize(("text", "intent"), BRAKING_SOUND_GUARDS.items())
def test_a_braking_sound_leaves_a_contact_and_other_squeals(text: str, intent: str) -> None:
    assert _intent(text) == intent


# a harm denied of a subject the clause leaves out, carried from the clause before ("... and was not hurt")
ELIDED_SUBJECT = [
    "Driving at 30 mph, a toddler ran out between parked cars ahead of me. The little lad stumbled back "
    "onto the pavement and was not hurt.",
    "A woman on a bike wobbled off the kerb in front of our bus, then fell sideways onto the verge and was unhurt.",
]


@pytest.mark.parametrize("text", ELIDED_SUBJECT)
def test_unhurt_with_its_subject_left_out(text: str) -> None:
    assert _intent(text) == "near_miss"


def test_a_contact_before_unhurt_stays_a_collision() -> None:
    assert _intent("A cyclist swerved into my lane, clipped my wing mirror and was not hurt.") == "collision"


def test_the_ego_unhurt_is_no_verdict() -> None:
    # (the writer unhurt says nothing of a road user: the old reading, no intent)
    assert _intent("I drove home at 40 mph after work and was not hurt.") is None


# a contact only thought of: the subject of a denied or impossible thought
THOUGHT_OF = [
    "A lorry overtook me on the bend at 50 mph and cut back in ahead of me. No contact, but a crash with the "
    "kids in the back does not bear thinking about.",
    "The van squeezed past at 60 with no room at all; a collision at that speed is unthinkable.",
]


@pytest.mark.parametrize("text", THOUGHT_OF)
def test_a_contact_only_thought_of_is_no_collision(text: str) -> None:
    assert _intent(text) == "near_miss"


def test_a_crash_that_happened_stays_one() -> None:
    text = "A lorry cut back in ahead of me on the bend. The crash sent me into the hedge and I still think about it."
    assert _intent(text) == "collision"


# a negation whose verb is left out ("the truck does not"): it denies nothing after it
ELLIPTICAL = [
    "Car ahead stops dead. We stop in time, the van behind us does not → we get rear-ended.",
    "Lead car brakes hard. Ego stops in time … the truck did not the ego is struck from behind.",
]


@pytest.mark.parametrize("text", ELLIPTICAL)
def test_an_elliptical_negation_denies_nothing_after_it(text: str) -> None:
    assert _intent(text) == "collision"


def test_a_negated_verb_is_still_denied() -> None:
    assert _intent("Lead car brakes hard. Ego stops in time, the truck behind does not hit the ego.") == "near_miss"


# a stop short of a road marking (a line, a box junction) is where one stopped, not a margin to anyone
SHORT_OF_A_MARKING = [
    "The lights went amber, so I slowed and stopped short of the stop line. The cyclist beside me went on. No drama.",
    "Taxi from the left saw our blues, stopped short of the box and we went through without incident.",
]


@pytest.mark.parametrize("text", SHORT_OF_A_MARKING)
def test_stopped_short_of_a_marking_is_no_margin(text: str) -> None:
    assert _intent(text) == "safe"


SHORT_OF_SOMEONE = [
    "A kid darted out and I stopped just short of him.",
    "The bus braked and I pulled up short of its back bumper.",
]


@pytest.mark.parametrize("text", SHORT_OF_SOMEONE)
def test_stopped_short_of_someone_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


def test_the_layers_carry_the_braking_sound() -> None:
    text = "I was doing 20 mph past the school when a boy stepped out. Screech! He just grinned and walked on."
    assert all(layers_from_text(text, seed)["intent"] == "near_miss" for seed in range(3))


def test_an_opinion_after_a_crash_hedges_nothing() -> None:
    assert _intent("The crash happened so fast I did not think about braking.") == "collision"


def test_stopped_short_of_a_crossing_as_someone_came_out_stays_close() -> None:
    text = "A girl on a scooter shot out of the park and I had to stop short of the crossing. All okay."
    assert _intent(text) == "near_miss"
