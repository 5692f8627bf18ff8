"""A person said to sit in a motor vehicle ("the man in the car", "a woman in a van") is that vehicle's
occupant: the vehicle, one road user, as "the driver of the car" is. A person in what is no motor
vehicle (a wheelchair, a coat, the bike lane) stays a road user of their own kind."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _kinds(text: str) -> list[str]:
    return [a["type"] for a in layers_from_text(text, 0)["adversaries"]]


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # a person in a vehicle said before: that vehicle, no walker of their own
        (
            "The hatchback ahead of us spun on the ice and stopped sideways."
            " The lady in the hatchback got out and she was fine.",
            ["car"],
        ),
        ("A tipper braked hard in front of me. The bloke in the tipper waved sorry afterwards.", ["truck"]),
        ("The van in front stopped dead at the lights. The guy in the van got out to check his load.", ["van"]),
        # the person and the vehicle said at once
        ("The lad in the white Audi swerved across into my lane.", ["car"]),
        ("A woman in a small hatchback pulled out of the side road right in front of us.", ["car"]),
        ("The old man in the camper van pulled out of the lay-by into our path.", ["van"]),
    ],
)
def test_a_person_in_a_vehicle_is_that_vehicle(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # what a person is "in" is no motor vehicle: they are a road user of their own kind
        ("An old man in a wheelchair rolled off the kerb in front of me.", ["pedestrian"]),
        ("A boy in a bright yellow raincoat ran into the road ahead of us.", ["pedestrian"]),
        ("A cyclist in the bike lane wobbled out in front of me.", ["bicycle"]),
        # a vehicle said "in" a place is not sat in
        ("A lorry in the outside lane drifted across into mine.", ["truck"]),
        # the driver of a vehicle, as before
        ("The taxi stopped suddenly. The driver of the taxi jumped out.", ["car"]),
        # a person who is no one's occupant stays a walker beside the vehicle
        (
            "A van stopped on the zebra and a woman with a pushchair walked around it in front of me.",
            ["van", "pedestrian"],
        ),
    ],
)
def test_what_is_no_vehicle_keeps_its_own_kind(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # a brand said before a noun it only names the make of (clothing) is no car in a vehicle's place
        ("A courier in a Deliveroo jacket stepped off the kerb in front of me.", ["pedestrian"]),
        ("A man in a Barbour coat walked out in front of me.", ["pedestrian"]),
        ("A jogger in a Nike top ran out in front of me.", ["pedestrian"]),
        # a name ending its noun phrase, before a verb, is still read as a car
        ("A silver Mokka pulled out of the side road in front of me.", ["car"]),
        ("A kid in a red Mini cut in front of me.", ["car"]),
    ],
)
def test_a_brand_before_a_noun_names_no_vehicle(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds


def test_modal_and_negating_words_between_everyone_and_be() -> None:
    """ "Nobody can ever be a careless cyclist": the pronoun, its modal and "ever", then "be": the
    cyclist is people in general, left out of the scene's road users."""
    from vei_scenario.language import discourse, reader

    dropped: list[str] = []
    tokens = "nobody can ever be a careless cyclist .".split()
    out = discourse._what_everyone_is(tokens, reader._kind_at, reader._known, dropped)
    assert "cyclist" not in out
    assert "cyclist" in dropped
