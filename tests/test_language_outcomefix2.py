"""Review findings G1-G7 on the outcome rules (:mod:`vei_scenario.language.outcome`): a stop made to
give way is a wait, not a forced stop; "a good" before a length only makes it a lower bound; "well
before/back" is a wide margin only after a stop and before a road user; a car's length in a queue is no
near miss; "if"/"whether" after "not sure/clear" hedges a contact; "sharp" is hard only on the brake;
"let us" opening a text is a wish. The review's sentences plus variants; guards keep the readings the
rules were built for."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str:
    return layers_from_text(text, 0)["intent"]


# G1: a stop made to let someone go, for a road user or at a place of giving way is a wait
GIVE_WAY_STOP = [
    "I had to stop to let a pedestrian cross at the zebra.",
    "I had to stop and let the bus pull out from the stop.",
    "A pedestrian stepped onto the zebra so I had to stop, and she crossed.",
    "I had to stop at the give way line and a cyclist went past.",
    "We had to stop to let an ambulance through and a car behind us waited.",
    "I had to stop for the pedestrians at the crossing and then carried on.",
    "A car pulled out; I had to stop and let it go.",
    "I had to stop for a cyclist at the junction and then drove on.",
]
# G2: "a good" makes its length a lower bound; the thresholds then apply
GOOD_LENGTH = {
    "The bus passed me with a good foot to spare.": "near_miss",
    "A lorry passed the cyclist with a good 30 cm to spare.": "near_miss",
    "A car overtook me with a good metre to spare.": "near_miss",
    "A van overtook the cyclist with a good 2 metres to spare.": "safe",
    "The bus overtook me on the hill with a good two metres, nice and steady.": "safe",
}
# G3: "well before/back" after a pull-out (not a stop), or before a place or a clause, is no margin
NOT_WELL_BEFORE = {
    "A lorry pulled out well before the junction and I had to brake hard.": "near_miss",
    "The van pulled out well before I got there and I braked hard.": "near_miss",
}
WELL_BEFORE_GUARDS = {
    "A child chased a ball into the road and I stopped well before her.": "safe",
    "A cyclist swerved into the road and I pulled up well back from him.": "safe",
}
# G4: a car's length behind a vehicle queued ahead is no near miss
QUEUE_LENGTH = [
    "I pulled up a car's length behind the bus at the lights and a cyclist filtered past.",
]
LENGTH_GUARDS = {
    "The van pulled out of the side road and we stopped maybe a car's length from it.": "near_miss",
}
# G5: "if"/"whether" after a word of knowing or certainty hedges the contact
UNSURE_CONTACT = [
    "It's not clear if the car touched the cyclist.",
    "I wasn't sure if the van hit the cyclist or not.",
    "I don't know whether the bus clipped the cyclist.",
]
UNSURE_GUARDS = {
    "He never even checked if the road was clear and hit me.": "collision",
}
# G6: "sharp" before a noun other than a brake or a stop is no hard brake
SHARP = {
    "I braked for a sharp bend and a cyclist came the other way.": "unspecified",
}
SHARP_GUARDS = {
    "A dog ran out and I braked sharp.": "near_miss",
    "A child stepped out and I stopped sharp.": "near_miss",
}
# G7: "let us" opening a sentence is a wish, but "Let us through" is a call to be let go, given way to
HORTATIVE = {
    "Let us through, I shouted, and the van stopped.": "safe",
    "Mr Lane had to brake hard when a scooter shot off the pavement in front of him. No harm done. "
    "Let us all be careful out there.": "near_miss",
}


@pytest.mark.parametrize("text", GIVE_WAY_STOP)
def test_a_stop_to_give_way_is_a_wait(text: str) -> None:
    assert _intent(text) == "safe"


@pytest.mark.parametrize("text,intent", {**GOOD_LENGTH, **NOT_WELL_BEFORE, **WELL_BEFORE_GUARDS}.items())
def test_margins(text: str, intent: str) -> None:
    assert _intent(text) == intent


def test_a_pull_out_well_back_from_a_junction_is_no_safe_margin() -> None:
    assert _intent("The car pulled out well back from the junction and then raced across.") != "safe"


def test_a_car_pulling_out_a_good_metre_in_front_is_not_safe() -> None:
    assert _intent("A car pulled out a good metre in front of my bumper.") != "safe"


@pytest.mark.parametrize("text", QUEUE_LENGTH)
def test_a_cars_length_in_a_queue_is_no_near_miss(text: str) -> None:
    assert _intent(text) != "near_miss"


@pytest.mark.parametrize("text,intent", {**LENGTH_GUARDS, **UNSURE_GUARDS, **SHARP, **SHARP_GUARDS}.items())
def test_readings(text: str, intent: str) -> None:
    assert _intent(text) == intent


@pytest.mark.parametrize("text", UNSURE_CONTACT)
def test_an_unsure_contact_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text,intent", HORTATIVE.items())
def test_let_us_opening_a_sentence_is_a_wish(text: str, intent: str) -> None:
    assert _intent(text) == intent


def test_the_hortative_reads_let_us_as_written() -> None:
    # "us" as the reader's words leave it, or as "the ego": a wish either way
    from vei_scenario.language.outcome import _hortative

    assert _hortative(["let", "us", "all", "take", "care"], 0)
    assert _hortative(["let", "the", "ego", "all", "take", "care"], 0)
    assert not _hortative(["let", "us", "through"], 0)


def test_forced_stops_stay_forced() -> None:
    # the guards of the forced-stop rule: a stop with nothing given way to, then "all fine", is close
    assert (
        _intent(
            "A scooter shot across the junction against the lights. I'd pulled forward and had to stop in the "
            "middle. All fine."
        )
        == "near_miss"
    )
    assert _intent("On the ring road the taxi ahead of us jammed on, and our driver had to brake. All fine.") == (
        "near_miss"
    )
