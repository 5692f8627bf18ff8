"""Vehicle words of more of the writers' languages, kept in translated or non-native English: Hungarian,
Czech and South Slavic ("kamion"), Swedish, Norwegian, Danish and Finnish ("lastbil", "elsparkcykel"),
Russian in Latin letters ("samokat", "fura"), Indonesian and Malay ("truk", "skuter listrik") and
Vietnamese ("xe tải", "xe máy"), and the local names of motorcycle taxis ("bendskin", "zemidjan", "xe
ôm"). Each names its kind as the English word does. Near misses: an English
word inside such a phrase ("roller", "container") or a word of one ("xe") alone names no road user."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds

LOANWORD_CASES = [
    # trucks
    ("I was doing 90 on the motorway when a kamion came over from the left lane into mine.", "truck"),
    ("At 90 on the motorway, one of the kamioni in the right lane pulled out in front of me.", "truck"),
    ("Doing 100 in the right lane, a lastbil behind me sat on my bumper for ten minutes.", "truck"),
    ("At 80 on the highway, a truk in the left lane swung suddenly into my lane.", "truck"),
    ("Rain all night; at 90 the fura in front of me in my lane braked hard to a stop.", "truck"),
    ("I was going 60 on the expressway and a xe tải in the right lane moved into my lane.", "truck"),
    ("Going 70, the xe container beside me on the right drifted into my lane.", "truck"),
    # e-scooters
    (
        "Leaving the yard at walking pace, a samokat shot across in front of me from the left.",
        "e-scooter",
    ),
    (
        "Leaving the stop at 15 km/h, an elsparkcykel came past on the left and cut in front of the bus.",
        "e-scooter",
    ),
    ("A boy on an elsparkesykkel crossed in front of me from the right at the roundabout.", "e-scooter"),
    ("I was doing 30 when an elektromos roller came off the pavement on my left in front of me.", "e-scooter"),
    (
        "I was driving at 20 when a kid on a skuter listrik came out of an alley on my left in front of me.",
        "e-scooter",
    ),
    ("At 25 km/h a romobil came off the sidewalk from the right in front of my car.", "e-scooter"),
    # a motor two-wheeler (read as a car) and a bicycle
    ("At 40 km/h a xe máy came out of a side street on my right in front of me.", "car"),
    ("I was driving at 30 when a xe đạp crossed in front of me from the left.", "bicycle"),
    # motorcycle taxis by their local names (a motor two-wheeler is read as a car)
    ("The light was green for me when a bendskin with two passengers ran the red from my left.", "car"),
    ("I was driving at 40 when a zemidjan came out of a side road on my right in front of me.", "car"),
    ("A xe ôm cut across in front of my car from the left and its rider braked.", "car"),
]


def test_a_local_motorbike_named_again_as_the_bike_is_one_road_user() -> None:
    text = "At 30 km/h a pikipiki came out of a lane on my right; the bike stopped just short of me."
    assert kinds(text) == ["car"]


@pytest.mark.parametrize(("text", "kind"), LOANWORD_CASES)
def test_a_loanword_names_its_kind(text: str, kind: str) -> None:
    assert kinds(text) == [kind]


def test_a_plural_loanword_names_each_rider_kind() -> None:
    text = "Two kids on rental samokaty came off the pavement in front of my car."
    assert kinds(text) == ["e-scooter", "e-scooter"]


#: English words of those phrases, said alone, where no road user of that kind is meant.
NEAR_MISSES = [
    # "roller" alone is an English word (a road roller, a paint roller): only "elektromos roller" is a scooter
    ("I was driving at 30 when a cyclist came out from the right past a roller parked by the roadworks.", ["bicycle"]),
    # "container" alone is a box, not a container lorry
    ("At 50 km/h a van pulled out in front of me from behind a skip container on the left.", ["van"]),
    # "xe" alone (a vehicle) names no kind: the ego's own "xe" is no road user
    ("I was driving my xe at 40 when a pedestrian crossed in front of me from the right.", ["pedestrian"]),
]


@pytest.mark.parametrize(("text", "expected"), NEAR_MISSES)
def test_an_english_word_of_such_a_phrase_stays_english(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected
