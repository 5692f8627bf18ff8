"""Outcome readings a review found wrong after the braking-sound, short-of-a-marking, thought-of,
elided-verb and inherited-subject rules (:mod:`vei_scenario.language.outcome`): a screech that is no
brake, a squeal told as a habit, a "line of" people, an adjective of the unthinkable said of something
else, "I cannot bear to think about" a real crash, a time adverbial after "does not", and a harm
hedged by "nearly". The review's sentences and variants written for these tests; the guards keep the
readings the rules were made for."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str | None:
    return layers_from_text(text, 0)["intent"]


def _behaviours(adversary: dict) -> list[dict]:
    told = adversary["behaviour"]
    return told["sequence"] if "sequence" in told else [told]


# F1: a screech that is no hard brake (an animal, a machine part, a tram on a curve, a cornering screech)
NOT_A_BRAKE = {
    "The pedestrian crossed the road in front of me. A parrot screeched in the pet shop.": "unspecified",
    "A fox screeched in the hedge; a pedestrian crossed a long way ahead.": "unspecified",
    "The owl screeched as a deer crossed in front of me; I braked gently and it walked on.": "safe",
    "A bus pulled out ahead of me in good time; my fan belt screeched as I accelerated.": "unspecified",
    "The tram screeched round the curve as the cyclist crossed well ahead of it.": "unspecified",
    "The tyres screeched as I took the bend too fast, but nothing else happened.": "safe",
    "A seagull screeched overhead while the cyclist waited at the lights.": "unspecified",
    # F2: a squeal told as a habit or a fault
    "My brakes squeal a bit in the wet; a pedestrian crossed well ahead of me.": "unspecified",
    "My brakes always squeal; the cyclist crossed well ahead of me.": "unspecified",
}


@pytest.mark.parametrize(("text", "intent"), NOT_A_BRAKE.items())
def test_a_screech_or_squeal_that_is_no_hard_brake(text: str, intent: str) -> None:
    assert _intent(text) == intent


def test_a_squeal_for_no_reason_leaves_a_wide_overtake_safe() -> None:
    layers = layers_from_text("The van overtook me with room to spare, brakes squealing for no reason.", 0)
    (van,) = layers["adversaries"]
    overtake = next(b for b in _behaviours(van) if b["behaviour"] == "overtake")
    assert overtake["config"]["criticality"] == "safe"


BRAKING_SOUNDS = [
    "The van screeched to a halt as the boy ran out.",
    "The car stopped with a screech as the dog ran out in front of it.",
    "A cyclist shot out of the side road and the tyres screeched.",
    "A kid ran out after a ball, there was a screech of brakes and the car stopped.",
    "The pensioner stepped out in front of the bus, its brakes squealing.",
]


@pytest.mark.parametrize("text", BRAKING_SOUNDS)
def test_a_braking_sound_stays_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


# F3: "short of a line of <people/vehicles>" and of a foot crossing's markings is a margin left to someone
SHORT_OF_SOMEONE = {
    "The bus stopped inches short of a line of schoolchildren crossing the road.": "near_miss",
    "The van stopped a metre short of the line of cyclists waiting at the lights.": "near_miss",
    "I stopped just short of a line of pedestrians on the zebra.": "near_miss",
    "The lorry stopped a foot short of the line of traffic.": "near_miss",
    "I stopped inches short of the zebra lines as a child stepped onto them.": "near_miss",
    "I stopped just short of the crossing markings as the pedestrian walked out.": "near_miss",
    "The taxi stopped just short of a queue of children at the crossing.": "near_miss",
}


@pytest.mark.parametrize(("text", "intent"), SHORT_OF_SOMEONE.items())
def test_short_of_a_line_of_people_is_a_margin(text: str, intent: str) -> None:
    assert _intent(text) == intent


SHORT_OF_A_MARKING = [
    "The lights went amber, so I slowed and stopped short of the stop line. The cyclist beside me went on. No drama.",
    "Taxi from the left saw our blues, stopped short of the box and we went through without incident.",
    "The van stopped short of the give way line and the cyclist rode past. No drama.",
]


@pytest.mark.parametrize("text", SHORT_OF_A_MARKING)
def test_stopped_short_of_a_marking_stays_no_margin(text: str) -> None:
    assert _intent(text) == "safe"


# F4, F5, C10: a contact told, with a thought after it that is not of it
TOLD_CONTACTS = [
    "The cyclist's crash into my door left him with an inconceivable injury.",
    "My collision with the cyclist at the junction is something I cannot bear to think about.",
    "The crash with the van was so sudden that I did not have time to think.",
    "The collision with the cyclist was so sudden I had no time to think.",
]


@pytest.mark.parametrize("text", TOLD_CONTACTS)
def test_a_told_contact_is_not_only_thought_of(text: str) -> None:
    assert _intent(text) == "collision"


THOUGHT_OF = [
    "A lorry overtook me on the bend at 50 mph and cut back in ahead of me. No contact, but a crash with the "
    "kids in the back does not bear thinking about.",
    "The van squeezed past at 60 with no room at all; a collision at that speed is unthinkable.",
    "The van squeezed past me with inches to spare; a collision at that speed would have been unimaginable.",
]


@pytest.mark.parametrize("text", THOUGHT_OF)
def test_a_contact_only_thought_of_stays_no_collision(text: str) -> None:
    assert _intent(text) == "near_miss"


# F6: a time adverbial between "does not" and its verb: the verb is not left out
NEGATED_WITH_A_TIME = [
    "The car does not this time hit the pedestrian; it stops short.",
    "The van did not that morning hit the cyclist; it stopped just short of him.",
]


@pytest.mark.parametrize("text", NEGATED_WITH_A_TIME)
def test_a_time_adverbial_after_does_not_keeps_the_denial(text: str) -> None:
    assert _intent(text) == "near_miss"


def test_the_pedestrian_not_hit_this_time_stops() -> None:
    layers = layers_from_text("The car does not this time hit the pedestrian; it stops short.", 0)
    names = [b["behaviour"] for a in layers["adversaries"] for b in _behaviours(a)]
    assert "stop" in names


ELLIPTICAL = [
    "Car ahead stops dead. We stop in time, the van behind us does not → we get rear-ended.",
    "Lead car brakes hard. Ego stops in time … the truck did not the ego is struck from behind.",
    "Car ahead stops dead. I stop in time but the van behind does not, the van hits me.",
]


@pytest.mark.parametrize("text", ELLIPTICAL)
def test_an_elliptical_negation_still_denies_nothing_after_it(text: str) -> None:
    assert _intent(text) == "collision"


# F23: a harm hedged by "nearly" with its subject left out
def test_nearly_killed_with_its_subject_left_out_is_no_collision() -> None:
    assert _intent("The boy stepped back and was nearly killed.") != "collision"
    assert _intent("The cyclist swerved out and was almost hurt.") != "collision"


UNHURT_INHERITED = {
    "The cyclist fell off and was not hurt.": "near_miss",
    "A cyclist swerved into my lane, clipped my wing mirror and was not hurt.": "collision",
}


@pytest.mark.parametrize(("text", "intent"), UNHURT_INHERITED.items())
def test_unhurt_with_its_subject_left_out_keeps_its_reading(text: str, intent: str) -> None:
    assert _intent(text) == intent
