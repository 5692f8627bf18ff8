"""One of the narrator's party (a family word, a friend) who has a vehicle out drives the ego: "My dad
took the car into town. He was turning right ..." tells that car's story, not another road user's."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph, kinds
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    "text, kind, route",
    [
        (
            "My dad took the car into town. He was turning right out of the car wash when a cyclist hit him.",
            "bicycle",
            "right",
        ),
        (
            "Your grandad had the Volvo out. He was turning left into the lane when a lad on a bike clipped him.",
            "bicycle",
            "left",
        ),
        (
            "my mum had the car today, she was turning left at the lights when a scooter came up her inside",
            "e-scooter",
            "left",
        ),
        (
            "Our daughter borrowed the hatchback. She was turning right at the crossroads when a bus ran the red.",
            "truck",
            "right",
        ),
        (
            "My brother drove the ute to the tip and was turning right off the highway when a cyclist came past.",
            "bicycle",
            "right",
        ),
    ],
    ids=["my-dad-took", "your-grandad-had", "mum-had-lowercase", "daughter-borrowed", "brother-drove-the-ute"],
)
def test_the_partys_vehicle_is_the_ego_with_its_turn(text, kind, route):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert r.ego_route == route


def test_the_partys_speed_is_the_egos():
    text = "Our son borrowed my car last night. He was doing 40 mph on the bypass when a van cut in front of him."
    assert kinds(text) == ["van"]
    assert ego_kph(text) == pytest.approx(64.4, abs=0.2)


@pytest.mark.parametrize(
    "text, expected",
    [
        ("My dad took a taxi home. A van pulled out in front of the taxi.", ["van"]),
        ("My dad saw the car hit a cyclist.", ["car", "bicycle"]),
        (
            "I was driving home. My brother took the van behind me and a cyclist pulled out in front of me.",
            ["van", "bicycle"],
        ),
    ],
    ids=["a-taxi-is-new", "seeing-is-not-having", "placed-behind-the-narrator"],
)
def test_a_vehicle_the_party_only_meets_or_rides_in_stays_as_read(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, kind",
    [
        ("Grandad's Volvo pulled up at the lights, then a cyclist ran the red from the left.", "bicycle"),
        ("Dad's car was waiting at the give way line when a motorbike came fast from the right.", "car"),
        ("Mummy's SUV stopped at the crossing and a boy ran out from the left.", "pedestrian"),
        ("Papa's taxi halted at the signal and a scooter rider jumped the red from the right.", "e-scooter"),
        ("Auntie's minivan stopped at the lights, then a cyclist ran the red from the right.", "bicycle"),
        ("Grandma's Micra stopped for the lights while a boy on a bike ran the red from the left.", "bicycle"),
    ],
    ids=["grandad-uk", "dad-give-way", "mummy-zebra", "papa-signal-in", "auntie-minivan", "grandma-panel"],
)
def test_the_partys_vehicle_named_as_a_name_is_the_ego(text, kind):
    """A party word called as a name, with no "my" ("Mum's car", "Grandad's Volvo"), owns the vehicle
    the story is told about as much as "my mum's car" does: it is the ego, even where it only stops."""
    assert kinds(text) == [kind]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("The boy's dad's van stopped at the lights and a cyclist ran the red from the left.", ["van", "bicycle"]),
        ("I stopped behind Mum's car at the lights when a cyclist ran the red from the left.", ["car", "bicycle"]),
    ],
    ids=["someone-elses-dad", "narrator-behind-it"],
)
def test_a_party_word_that_is_someone_elses_or_a_narrator_apart_stays_as_read(text, expected):
    """ "the boy's dad" is another's party, not the narrator's; a narrator in the story behind the
    vehicle ("I stopped behind Mum's car") is in another one."""
    assert kinds(text) == expected
