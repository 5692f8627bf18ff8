"""A road user's kind from the person who rides or walks: a named rider or walker, a person's noun that
rides ("the boy rode off"), someone knocked off their own ride; and a brand before a place noun."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _kinds(text: str) -> list[str]:
    return [a["type"] for a in layers_from_text(text, 0)["adversaries"]]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        # a name that is the subject of a verb of riding: the kind it rides, or what the verb says
        ("Last week Ngozi was cycling home along Station Road when a bus came past her far too close.", "bicycle"),
        ("Dr Helen Marsh was pedalling up the hill in the bike lane when a lorry passed her.", "bicycle"),
        ("Kemal was scooting along the high street when a taxi overtook him.", "e-scooter"),
        ("A delivery van overtook Oskar (on a Lime) on the hill.", "e-scooter"),
        ("The hire firm's scooters log their speed. A van came past Tunde, who was riding home.", "e-scooter"),
        # a name that is the subject of a verb of going on foot, past an apposition
        ("Mrs Okafor, aged 74, of Hilltop, was walking along the B1040 when a van struck her.", "pedestrian"),
        # a person's noun that rides is its rider, one road user with what it rides
        ("A boy rode his bike across the road right in front of me.", "bicycle"),
        ("The girl scooted out of the alleyway just ahead of my car.", "e-scooter"),
        ("The boy rode out of the driveway in front of me without looking.", "bicycle"),
        ("A minicab knocked a student off her e-scooter at the lights.", "e-scooter"),
    ],
)
def test_the_person_who_rides_or_walks_is_one_road_user_of_their_kind(text: str, kind: str) -> None:
    assert _kinds(text) == [kind]


def test_a_name_said_again_is_the_same_road_user() -> None:
    text = "Mr Ellery was walking along the verge at dusk. A pickup travelling at 50 mph struck Mr Ellery."
    assert _kinds(text) == ["pedestrian"]


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # a named driver is no rider: the cyclist they meet stays the one road user
        ("Hannah was driving to work when a cyclist pulled out of a side road in front of her.", ["bicycle"]),
        # a name in apposition to a road user's noun is that road user, not one more
        ("The cyclist, Ms Avery, was riding downhill when a car pulled out in front of her.", ["bicycle", "car"]),
        # a person who rides a bus is a passenger, no cyclist
        ("A man rode the bus into town and a woman walked out in front of me.", ["pedestrian", "pedestrian"]),
        # a walker stays a walker
        ("A woman walked out in front of me from the pavement on my left.", ["pedestrian"]),
        # a motorbike's rider keeps the motor two-wheeler's reading
        ("A man rode his motorbike out of the junction in front of me.", ["car"]),
    ],
)
def test_guards_keep_the_old_reading(text: str, kinds: list[str]) -> None:
    assert sorted(_kinds(text)) == sorted(kinds)


def test_a_brand_before_a_place_noun_names_the_place_not_a_car() -> None:
    # "garage" is a verb too; before it a name is the place's brand, and the truck is the road user
    text = "Yesterday a truck came out of the Shell garage straight into the road in front of me."
    assert _kinds(text) == ["truck"]


def test_a_name_that_ends_its_phrase_before_a_verb_is_still_a_car() -> None:
    assert _kinds("A silver Mokka pulled out of the garage in front of me.") == ["car"]
