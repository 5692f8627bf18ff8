"""The vehicle a film's run sheet, a game's encounter or a regulation's test is built round, named by
its role ("the hero car", "our hero", "player vehicle", "Player: delivery van", "the ALKS vehicle"):
it is the ego, with its speed, and no road user of its own."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph, kinds
from vei_scenario.language.normalise import normalise
from vei_scenario.language.reader import _actor_noun_in

ROLE_NAMED = [
    # (a film's stunt sheet, a game designer's encounter, a sim spec, a regulation paraphrase; each with
    # another vehicle beside it, which the role word tells from the ego)
    ("Hero van (a white Transit) pulls up to the lights at 20 km/h. A stunt car jumps the red from hero's left "
     "at 50 km/h.", 20.0, ["car"]),
    ("Shot 4: hero taxi cruising at 30 km/h; stunt motorbike overtakes hero and cuts in, hero brakes.", 30.0,
     ["car"]),
    ("Our hero, a little red tractor, putters along at 15 km/h. A big lorry overtakes him at 60 km/h.", 15.0,
     ["truck"]),
    ("Player vehicle: pickup truck doing 50 kph towards the junction. Spawn NPC car from the right at 30 kph, "
     "it runs the red.", 50.0, ["car"]),
    ("Player: city bus, pulling out of a stop at 15 km/h. NPC 1: a cyclist passing on the right at 20 km/h.",
     15.0, ["bicycle"]),
    ("player = stolen sports car, ~100 km/h on the motorway. NPC truck in the left lane moves across in front "
     "of the player.", 100.0, ["truck"]),
    ("ALKS follows a lead car at 60 km/h in lane 1; the lead car changes lane to reveal a stopped truck.", 60.0,
     ["car", "truck"]),
]  # fmt: skip


@pytest.mark.parametrize(("text", "speed", "users"), ROLE_NAMED)
def test_a_role_named_vehicle_is_the_ego(text: str, speed: float, users: list[str]) -> None:
    assert ego_kph(text) == speed
    assert kinds(text) == users


NEAR_MISSES = [
    # (a hero said in scorn is another road user; a sports player on foot is a walker)
    ("Some absolute hero in an Audi overtook me at 80 km/h on the bend.", ["car"]),
    ("I was doing 30 km/h when a football player ran into the road after his ball.", ["pedestrian"]),
    ("Some hero cyclist ran the red in front of me while I was doing 40 km/h.", ["bicycle"]),
]


@pytest.mark.parametrize(("text", "users"), NEAR_MISSES)
def test_a_role_word_said_otherwise_is_no_ego(text: str, users: list[str]) -> None:
    assert kinds(text) == users


def test_the_target_vehicle_stays_a_road_user() -> None:
    text = "ALKS vehicle at 60 km/h. The target vehicle ahead at 30 km/h brakes hard."
    assert ego_kph(text) == 60.0
    assert kinds(text) == ["car"]


def test_the_role_noun_said_again_is_the_ego() -> None:
    text = "Hero bus at 25 km/h round the roundabout. A cyclist cuts across the front of the bus; bus brakes."
    assert ego_kph(text) == 25.0
    assert kinds(text) == ["bicycle"]


def test_another_of_the_role_kind_keeps_its_own_mentions() -> None:
    text = "Hero taxi at 30 km/h. A second taxi pulls out of a rank ahead; the taxi stops."
    assert ego_kph(text) == 30.0
    assert kinds(text) == ["car"]


def test_a_distance_after_the_role_is_kept() -> None:
    text = "Player vehicle: hatchback at 30 km/h. Trigger: player within 20m of the crossing -> NPC pedestrian crosses."
    assert "within 20 m" in normalise(text.lower(), _actor_noun_in)
