"""Review findings on the ego's own road: the ego pulling out gives the way only from a place one joins
a road from, in its own sentence or the next, before another junction comes in, and not on a green
light or a participle that is a road user's (ego_emerges.py); a later "the <noun>" of the ego's
vehicle kind that is plainly another ("the other van", "the Tesla from the next lane", after "two
vans") stays a road user (discourse._named_again_as_ego); "in front of her" is the ego only where no
person she fits was named since (sides.told_of_the_ego)."""

from __future__ import annotations

import pytest

from vei_scenario.language.ego_emerges import ego_pulls_out
from vei_scenario.language.rules_backend import layers_from_text


def _read(text: str, seed: int = 0) -> list[tuple[str, str, list[str]]]:
    """Each adversary's type, start relation and behaviour names, as the layers carry them."""
    out = []
    for adv in layers_from_text(text, seed)["adversaries"]:
        b = adv["behaviour"]
        names = [n["behaviour"] for n in b["sequence"]] if "sequence" in b else [b["behaviour"]]
        out.append((adv["type"], adv["spawn"]["relation"], names))
    return out


def _names(text: str) -> list[str]:
    return [name for _, _, names in _read(text) for name in names]


@pytest.mark.parametrize(
    "text",
    [
        # C1: the ego on its own green, pulling out into the junction
        "The lights turned green and I pulled out into the junction when a car came from the right.",
        "On green I pulled out into the crossroads and a van came from the left at speed.",
        "My light went green, I edged out into the junction and a car came from the right.",
        "The filter arrow came on, I pulled out onto the junction and a motorbike came from the left.",
        # C1: out of no place one joins a road from
        "As I came out of the tunnel, a car came from the left at the junction.",
        "I came out of the bend and a car came from the right at the crossroads.",
        "I pulled out of the way and a lorry came from the right through the junction.",
        "We came out of the roundabout and a cyclist came from the left at the next junction.",
        # C2: another junction, later
        "I had just pulled out of the petrol station. At the next crossroads a car came from the left and hit me.",
        "I pulled out of my road and drove a mile to the lights. At the crossroads a van came from the right and "
        "hit me.",
        "This morning I came out of the house and drove to work; at the junction by the school a car came from the "
        "left.",
        # variants: a later sentence that brings in the lights; the ego out of an underpass
        "I pulled out of the side road and went on for a mile. At the lights a car came from the right.",
        "We came out of the underpass and a van came from the left at the crossroads.",
        "As I emerged from the tunnel a car came from the left at the crossroads.",
    ],
)
def test_a_crosser_the_ego_does_not_give_way_to_reads_as_before(text):
    assert "run_red_light" in _names(text), (text, _read(text))


@pytest.mark.parametrize(
    "text",
    [
        # guards: the pull-out from a place one joins a road from, its sentence or the next
        "I had just pulled out of the petrol station when a car came from the left and hit me.",
        "I pulled out of the side road. A car came from the right and hit me.",
        "I pulled out of the side road onto the main road and a car came from the right at speed.",
        "Yesterday I edged out of the junction at the lights and a motorbike came from the left and clipped my bumper.",
        "Pulling out of the car park, I saw a car come from the right and it hit me.",
    ],
)
def test_the_pull_out_it_was_built_for_still_gives_the_way(text):
    read = _read(text)
    assert read and "run_red_light" not in read[0][2] and read[0][2][0] in ("keep_going", "along_road"), (text, read)


def test_a_participle_before_a_road_user_is_its_own():
    # C3 / code note 6: the opening participle takes the main clause's subject, the car
    assert (
        ego_pulls_out("emerging from the junction , a car came from the right".split(), set(), frozenset({6})) is None
    )
    assert ego_pulls_out("pulling out of the car park , i saw a car".split(), {8}, frozenset({10})) == 0
    assert ego_pulls_out("pulled out to turn left and a van came".split(), set(), frozenset({7})) == 0


@pytest.mark.parametrize(
    "text, expected",
    [
        # D1: another of the kind is a road user, not the ego again
        ("A white van, the ego, approaches the lights. The other van pulls out of a side road.", ["van"]),
        ("A silver Tesla - the hero car - rolls up. The Tesla from the next lane cuts in.", ["car"]),
        # variants
        ("A red Polo, the subject vehicle, waits at 0 km/h. The second Polo overtakes it.", ["car"]),
        ("A white van, the ego, waits. Vans are parked along the kerb. The van pulls out.", ["van"]),
    ],
)  # fmt: skip
def test_another_of_the_egos_kind_stays_a_road_user(text, expected):
    assert [t for t, _, _ in _read(text)] == expected, (text, _read(text))


def test_the_van_said_after_two_vans_is_one_of_them():
    read = _read("A white van, the ego, approaches the lights. Two vans wait ahead. The van on the left pulls out.")
    assert [t for t, _, _ in read] == ["van", "van"] and "turn_into" in [n for _, _, ns in read for n in ns], read


def test_the_van_said_after_vans_are_parked_pulls_out():
    read = _read("A white van, the ego, waits. Vans are parked along the kerb. The van pulls out.")
    assert read[0][2][0] == "cut_in", read


@pytest.mark.parametrize(
    "text, expected",
    [
        # guards: the ego's vehicle named again stays the ego
        ("A silver Tesla - the hero car - rolls up to the lights at 25 mph. From the right a rider on an "
         "e-scooter runs the red. The Tesla brakes hard.", ["e-scooter"]),
        ("A white van, the ego vehicle, is at 40 km/h. A jogger crosses in front of it and the van stops.",
         ["pedestrian"]),
    ],
)  # fmt: skip
def test_the_egos_vehicle_named_again_stays_the_ego(text, expected):
    assert [t for t, _, _ in _read(text)] == expected


@pytest.mark.parametrize(
    "text",
    [
        # H1: "her" is the woman just named, not the ego
        "A woman is walking along the kerb in lane 1. A cyclist in front of her in lane 1 swerves into lane 2.",
        "A girl is jogging along the verge in lane 1. A van in front of her in lane 1 brakes hard.",
    ],
)
def test_in_front_of_a_person_just_named_is_not_the_egos_lane(text):
    assert "ahead" not in [rel for _, rel, _ in _read(text)[1:]], (text, _read(text))


@pytest.mark.parametrize(
    "text",
    [
        # guards: an ego told of as "her" with no other woman named
        "Mem said the lorry in front of her in lane 1 slammed on, she went for lane 2 to avoid it.",
        "Police say the van in front of her in the outside lane braked hard at 60 mph.",
    ],
)
def test_in_front_of_an_ego_told_as_her_stays_the_egos_lane(text):
    assert [rel for _, rel, _ in _read(text)] == ["ahead"]
