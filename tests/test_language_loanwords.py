"""Vehicle and road-user words of the writers' other languages, kept in translated or non-native
English ("a Lkw changed onto my lane", "a guy on a patinete", "the piéton crossed"): each names its
kind as the English word does. Near misses: English words that look like one stay what they are."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds

#: Five and more ways writers from other languages name the kind, each in a sentence of its own.
LOANWORD_CASES = [
    # trucks: German, French, Spanish, Portuguese, Polish and Turkish words, and the TIR plate
    ("I drove at 100 km/h on the motorway when a Lkw changed abruptly onto my lane from the right.", "truck"),
    ("On the autoroute at 110 a camion came out of the right lane in front of me.", "truck"),
    ("Going at 80 on the highway, a camión pulled from the right lane into mine.", "truck"),
    ("I was at 90 in the second lane and a TIR cut into my lane from the right.", "truck"),
    ("At 70 km/h on the ring road a caminhão changed into my lane without signal.", "truck"),
    ("I was driving at 60 when a Sattelzug came into my lane from the right.", "truck"),
    # vans
    ("I was driving at 50 when a camionnette pulled out of a side road on my right.", "van"),
    ("At 40 km/h a furgoneta came out of the side street on my left in front of me.", "van"),
    ("I was going at 50 when a furgone pulled out of a side road on my right.", "van"),
    # e-scooters
    ("I was driving at 40 when a guy on a patinete came off the sidewalk in front of me.", "e-scooter"),
    ("I drove at 30 km/h and a trottinette came off the pavement on my right in front of me.", "e-scooter"),
    ("Driving at 30, a boy on a monopattino crossed in front of me from the left.", "e-scooter"),
    ("I was doing 30 when a hulajnoga came off the pavement on my right and crossed in front of me.", "e-scooter"),
    ("I was doing 30 when a VMP came down from the sidewalk on my left in front of me.", "e-scooter"),
    ("At 30 km/h an E-Roller came off the pavement from the right in front of me.", "e-scooter"),
    # bicycles
    ("I was driving at 30 when a Radfahrer came out on my right and crossed in front of me.", "bicycle"),
    ("Driving at 30 km/h, a ciclista crossed in front of me from the right.", "bicycle"),
    ("I drove at 30 and a cycliste came out from the left in front of me.", "bicycle"),
    ("At 30 km/h a fietser crossed in front of me from the right.", "bicycle"),
    # motorbikes and mopeds (a motor two-wheeler is read as a car)
    ("I was going slowly at 20 in a one-way street and the moto came against me in my lane.", "car"),
    ("I was going at 30 when a motorino came out of a side road on my right in front of me.", "car"),
    # pedestrians
    ("I drove at 30 km/h when a Fußgänger stepped onto the road from the right in front of me.", "pedestrian"),
    ("I was driving at 30 when a piéton crossed in front of me from the left.", "pedestrian"),
    ("Driving at 30, a peatón crossed in front of me from the right.", "pedestrian"),
    ("I was driving at 30 when a pedone crossed in front of me from the right.", "pedestrian"),
]


@pytest.mark.parametrize(("text", "kind"), LOANWORD_CASES)
def test_a_loanword_names_its_kind(text: str, kind: str) -> None:
    assert kinds(text) == [kind]


#: English words that look like one of them, where no road user of that kind is meant.
NEAR_MISSES = [
    # "rower" (Polish for a bicycle) is an English word for someone who rows: not read
    ("I was driving at 30 when a car came out of a side road on my right; a rower watched from the bank.", ["car"]),
    # "auto" (a car in many languages) goes on English nouns: an auto repair shop is no car
    ("Driving at 30 past the auto repair shop, a cyclist crossed in front of me from the right.", ["bicycle"]),
    # "step" (Dutch for a scooter) is an English word
    ("I was driving at 30 when a man took a step into the road in front of me from the right.", ["pedestrian"]),
]


@pytest.mark.parametrize(("text", "expected"), NEAR_MISSES)
def test_an_english_word_that_looks_like_one_stays_english(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


def test_accents_are_read_as_plain_letters() -> None:
    from vei_scenario.language.normalise import plain_letters

    assert plain_letters("piéton Fußgänger Hoża ciężarówka Øresund") == "pieton Fussganger Hoza ciezarowka Oresund"
    assert plain_letters("½ mile – 30 °C, “quoted” → ok") == "½ mile – 30 °C, “quoted” → ok"  # (symbols stay)
    assert plain_letters("plain ascii") == "plain ascii"
    # (letters of other scripts that decompose into parts of their own stay whole: the words not used
    # are shown as written)
    assert plain_letters("자전거 가 が ガ") == "자전거 가 が ガ"


#: A name with an accent is one word, not two: "Hoża" read letter by letter was "ho" and "a", an article.
ACCENTED_NAMES = [
    ("At the Hoża junction a blue Skoda turned right across me while I drove at 30.", ["car"]),
    ("On Marszałkowska, doing 40, a cyclist came out from the right in front of me.", ["bicycle"]),
    ("Near the café on Rue de l'Église a piéton crossed in front of me from the left; I drove at 30.", ["pedestrian"]),
]


@pytest.mark.parametrize(("text", "expected"), ACCENTED_NAMES)
def test_an_accented_word_is_one_word(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


#: A shared e-scooter named by its operator, before where it is or before its rider.
OPERATOR_CASES = [
    ("Our taxi was doing 30 when a lad on a Lime in the cycle lane to our right swerved into our lane.", ["e-scooter"]),
    ("I was driving at 30 km/h when a Voi user cut across in front of me.", ["e-scooter"]),
    ("Doing 40, a Tier rider came off the pavement on my left and crossed in front of me.", ["e-scooter"]),
    ("I was doing 30 when a Dott across the crossing came into my path from the right.", ["e-scooter"]),
    ("Driving at 30, two Bird riders came off the kerb on my right in front of me.", ["e-scooter", "e-scooter"]),
]


@pytest.mark.parametrize(("text", "expected"), OPERATOR_CASES)
def test_an_operator_names_a_shared_scooter(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


#: Where the operator's name is no e-scooter: a ride-hail "Bolt" taken to a place, its driver, a street.
OPERATOR_NEAR_MISSES = [
    ("I took a Bolt to the airport; at 50 km/h a cyclist crossed in front of us from the right.", ["bicycle"]),
    ("I was driving at 30 when the Bolt driver in front braked hard.", ["car"]),
    ("On Lime Street in the rain, doing 30, a pedestrian stepped out in front of me from the left.", ["pedestrian"]),
]


@pytest.mark.parametrize(("text", "expected"), OPERATOR_NEAR_MISSES)
def test_an_operator_name_that_is_no_scooter(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected
