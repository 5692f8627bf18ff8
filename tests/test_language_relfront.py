"""Where a road user starts along the road: ahead of the ego, behind it, or coming the other way.

* "behind" with an object that is no road user ("stopped behind a fallen tree") places the road user by
  that thing, not behind the ego: the ego comes upon it ahead;
* a phrase of where a road user comes from, fronted before it after a comma ("I was turning right, from
  the opposite direction a moped went straight on"), is that road user's, not the narrator's;
* what an oncoming road user overtakes comes the other way too, where a speed adjective or the "of" of
  a noun of passing stands between them ("overtook a slow lorry", "began an overtake of a coach").

The guards keep the readings that were right: "behind me", "behind my car", behind a road user, "came
up behind", "from behind the bus", and what a road user going the ego's way overtakes."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _starts(text: str) -> list[tuple[str, str]]:
    return [(a["type"], a["spawn"]["relation"]) for a in layers_from_text(text, 0)["adversaries"]]


BEHIND_A_THING = [
    ("I came upon a van stopped behind a fallen tree.", "van"),
    ("We came over the hill and found a bus standing in lane behind a crash.", "truck"),
    ("Round the corner there was a lorry waiting behind a broken gate, and I braked.", "truck"),
]


@pytest.mark.parametrize(("text", "kind"), BEHIND_A_THING)
def test_a_road_user_behind_a_thing_starts_ahead_of_the_ego(text, kind):
    assert _starts(text) == [(kind, "ahead")]


FRONTED_FROM = [
    (
        "I was turning right at the crossroads, from the opposite direction a moped went straight on and hit my wing.",
        ("junction_opposite",),
    ),
    (
        "I was doing 60 on the main road, from the opposite direction a van drifted over the line towards me.",
        ("oncoming",),
    ),
]


@pytest.mark.parametrize(("text", "starts"), FRONTED_FROM)
def test_a_fronted_from_phrase_after_a_comma_is_the_road_users(text, starts):
    [(_, relation)] = _starts(text)
    assert relation in starts


OVERTAKEN_BY_ONCOMING = [
    "On a country road an oncoming motorbike overtook a slow lorry and came into my lane.",
    "I was heading east at 40 mph. A motorbike heading west began an overtake of a coach and came into my lane.",
]


@pytest.mark.parametrize("text", OVERTAKEN_BY_ONCOMING)
def test_what_an_oncoming_road_user_overtakes_comes_the_other_way(text):
    starts = _starts(text)
    assert ("truck", "oncoming") in starts
    assert all(relation == "oncoming" for _, relation in starts)


GUARDS = [
    ("A taxi behind me hooted.", [("car", "behind")]),
    ("A van behind my car braked late and hit it.", [("van", "behind")]),
    ("A lorry behind the bus overtook us.", [("truck", "behind")]),
    ("A moped came up behind the shuttle and overtook it.", [("car", "behind")]),
    ("A car overtook a slow lorry and cut in front of me.", [("car", "behind"), ("truck", "ahead")]),
    ("I overtook a slow lorry when an oncoming van appeared.", [("truck", "ahead"), ("van", "oncoming")]),
    ("I was driving down the lane at 40 mph, the other way a tractor came round the bend.", [("truck", "oncoming")]),
]


@pytest.mark.parametrize(("text", "starts"), GUARDS)
def test_starts_that_stay(text, starts):
    assert _starts(text) == starts


def test_the_object_of_from_behind_is_not_fronted():
    """ "from behind the bus a cyclist ...": the bus is the object of "behind", not behind the ego."""
    starts = _starts("I was waiting at the lights, from behind the bus a cyclist shot out.")
    assert ("truck", "behind") not in starts
