"""Road users only mentioned beside one that acts are no road users: one of which nothing is said but
that it goes on, nowhere it is, no speed, no gap, no one's object ("a car my dad adored"). Wordings
written for the class (a driver's story that opens with an old car, readings built in several
shapes); near misses keep their road users: what stands there, what is placed, timed, or done to,
two riders that both act, a tailgater behind, a road user alone."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from tests.reading_of import kinds
from vei_scenario.language.bystanders import drop_bystanders
from vei_scenario.language.reading import ActorSpec, Reading


def _gathered(**said) -> SimpleNamespace:
    """What the reader gathers of a road user of which nothing more than ``said`` is said."""
    return SimpleNamespace(
        **{"stationary": False, "acted_on": False, "object_of": None, "said": set(), "seen": False, "det": "a", **said}
    )


def _goes_on(**spec) -> ActorSpec:
    return ActorSpec("car", behaviours=[("keep_going", {}, None, "sequence")], **spec)


def _crosses() -> ActorSpec:
    return ActorSpec("pedestrian", relation="roadside_left", behaviours=[("cross_in_front", {}, None, "sequence")])


def _kept(specs: list[ActorSpec], gathered: list[SimpleNamespace]) -> list[str]:
    reading = Reading(actors=specs)
    drop_bystanders(gathered, reading)
    return [s.kind for s in reading.actors]


def test_a_car_only_named_in_the_story_is_no_road_user() -> None:
    text = (
        "I sold my old Volvo last spring, a car my dad adored. Driving to work at 40 mph on Tuesday, a cyclist"
        " pulled out of a side road on my left right in front of me."
    )
    assert kinds(text) == ["bicycle"]


@pytest.mark.parametrize("first", [True, False])
def test_only_named_beside_one_that_acts_leaves_wherever_it_is_named(first: bool) -> None:
    specs, gathered = [_goes_on(), _crosses()], [_gathered(), _gathered()]
    if not first:
        specs.reverse()
    assert _kept(specs, gathered) == ["pedestrian"]


def test_every_one_only_named_leaves_and_obstacles_keep_pointing() -> None:
    swerver = ActorSpec("van", relation="ahead", behaviours=[("cut_out", {}, None, "sequence")], obstacle=3)
    standing = ActorSpec("truck", relation="ahead", speed_mps=0.0, behaviours=[("stop", {}, None, "sequence")])
    specs = [_goes_on(), swerver, _goes_on(), standing]
    reading = Reading(actors=specs)
    drop_bystanders([_gathered(), _gathered(), _gathered(), _gathered(stationary=True)], reading)
    assert [s.kind for s in reading.actors] == ["van", "truck"]
    assert reading.actors[0].obstacle == 1


@pytest.mark.parametrize(
    ("spec", "gathered"),
    [
        (_goes_on(relation="behind"), _gathered()),  # (placed: behind the ego)
        (_goes_on(speed_mps=13.0), _gathered()),  # (timed: it goes at a speed of its own)
        (_goes_on(distance_m=20.0), _gathered()),  # (a gap said of it)
        (_goes_on(), _gathered(acted_on=True)),  # (someone does something to it: "hit a car")
        (_goes_on(), _gathered(said={"oncoming"})),  # (said to come towards the ego)
        (_goes_on(), _gathered(stationary=True)),  # (said to stand there)
    ],
)
def test_a_road_user_told_anything_of_its_own_stays(spec: ActorSpec, gathered: SimpleNamespace) -> None:
    assert _kept([spec, _crosses()], [gathered, _gathered()]) == ["car", "pedestrian"]


def test_one_only_named_and_alone_stays() -> None:
    assert _kept([_goes_on()], [_gathered()]) == ["car"]


def test_two_going_on_and_nobody_acting_stay() -> None:
    assert _kept([_goes_on(), _goes_on()], [_gathered(), _gathered()]) == ["car", "car"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("A lorry was parked on the verge. A child ran out from behind it on the left.", ["truck", "pedestrian"]),
        (
            "Two e-scooter riders came off the pavement on the left and both crossed in front of me.",
            ["e-scooter", "e-scooter"],
        ),
        (
            "A car was tailgating me on the motorway at 70 mph when a lorry pulled out from the left lane.",
            ["car", "truck"],
        ),
        ("The van behind tailgated me for a mile and then overtook on a bend.", ["van"]),
        ("I hit a car at the lights.", ["car"]),
        (
            "A cyclist was riding ahead of me in the bike lane and a bus overtook me on the right and cut in.",
            ["bicycle", "truck"],
        ),
    ],
)
def test_road_users_that_act_or_are_placed_stay(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("My mum saw the van hit a jogger.", ["pedestrian", "van"]),
        ("A lorry went through on red, and another lorry followed it through a second later.", ["truck", "truck"]),
    ],
    ids=["watched-doing-something", "one-more-of-its-kind"],
)
def test_a_vehicle_watched_or_told_apart_as_another_stays(text, expected):
    """A vehicle whose deed the reader has no verb for stays when it is watched doing it, or told as one
    more of its kind: it is in the situation, not only named."""
    assert sorted(kinds(text)) == expected
