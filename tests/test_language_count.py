"""How many road users a description names: the road users other than the ego that act on the road,
not the people a story mentions who are no road users of the scene, and each road user once however
often or however differently it is named. Each construction is pinned by wordings of our own (none of
them from a corpus), read through the whole reader, with near misses that look alike but must read
otherwise."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def kinds(text: str) -> list[str]:
    return sorted(a.kind for a in read(text).actors)


# --- a person's noun before a road user's noun modifies it: one road user, of the head noun's type ----
@pytest.mark.parametrize(
    "text, expected",
    [
        ("A schoolboy cyclist rode across from the right just ahead of me.", ["bicycle"]),
        ("A woman cyclist swung out from the left kerb in front of me.", ["bicycle"]),
        ("An adult pedestrian dummy walks across from the right at 5 km/h in front of the ego.", ["pedestrian"]),
        ("A girl pedestrian ran out from the left in front of me at dusk.", ["pedestrian"]),
        ("A scooter kid rode straight across from the right in front of me.", ["e-scooter"]),
        ("The van target brakes hard 20 m ahead of the ego.", ["van"]),
    ],
    ids=["schoolboy-cyclist", "woman-cyclist", "adult-dummy", "girl-pedestrian", "scooter-kid", "van-target"],
)
def test_a_person_noun_before_a_road_user_noun_is_one_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("A child and a cyclist crossed from the left in front of me.", ["bicycle", "pedestrian"]),
        ("As I passed the jogger, a cyclist came out from the left in front of me.", ["bicycle", "pedestrian"]),
    ],
    ids=["joined-by-and", "separate-clauses"],
)
def test_two_road_user_nouns_apart_stay_two(text, expected):
    assert kinds(text) == expected


# --- animals on the road are walkers ---------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cow wandered across the road from the left in front of me.",
        "Cattle were crossing the lane from the left ahead of me.",
        "There was a kangaroo hopping across from the right about 20 m ahead.",
    ],
    ids=["cow", "cattle", "kangaroo"],
)
def test_an_animal_on_the_road_is_a_pedestrian(text):
    assert kinds(text) == ["pedestrian"]


def test_animals_named_as_a_place_are_no_road_users():
    assert kinds("I drove past a field of cows when a cyclist pulled out from the left in front of me.") == ["bicycle"]
