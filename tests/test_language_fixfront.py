"""Where a road user comes from, fronted or as what an oncoming road user overtakes.

* a phrase of where a road user comes from, fronted before it after a comma, is complete when it ends in
  its own noun ("from the other way"), as "from the other direction" is, though the reader counts "way"
  among the words that carry nothing alone; one that ends in a preposition ("from behind the bus a
  cyclist ...") is not fronted;
* a walker or rider that an oncoming road user overtakes comes towards the ego along the road, as one
  said to come the other way does; a vehicle so overtaken starts in the oncoming lane.

The guards keep the readings that were right."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _starts(text: str) -> list[tuple[str, str, str]]:
    return [
        (a["type"], a["spawn"]["relation"], a["spawn"].get("facing", "with"))
        for a in layers_from_text(text, 0)["adversaries"]
    ]


FRONTED_WAY = [
    "I was turning right, from the other way a van went straight on.",
    "I was turning right at the junction, from the other way a van came straight through.",
    "We were waiting to turn right, from the other way a lorry carried straight on.",
    "I was turning right at the lights, from the other way a taxi went straight across.",
]


@pytest.mark.parametrize("text", FRONTED_WAY)
def test_from_the_other_way_after_a_comma_is_the_road_users(text):
    [(_, relation, _)] = _starts(text)
    assert relation in ("junction_opposite", "oncoming")


FRONTED_GUARDS = [
    # (read as "direction" was before: the same as "way" now)
    ("I was turning right, from the other direction a van went straight on.", ("junction_opposite", "oncoming")),
    # (no comma: a clause of the narrator's own, as before)
    ("A van turned in ahead of me from the other way.", None),
]


@pytest.mark.parametrize(("text", "starts"), FRONTED_GUARDS)
def test_fronted_readings_that_stay(text, starts):
    if starts is not None:
        [(_, relation, _)] = _starts(text)
        assert relation in starts


def test_the_object_of_from_behind_stays_unfronted():
    starts = _starts("I was waiting at the lights, from behind the bus a cyclist shot out.")
    assert all(relation != "behind" for kind, relation, _ in starts if kind == "truck")


OVERTAKEN_RIDERS = [
    ("An oncoming van overtook a cyclist.", "bicycle"),
    ("An oncoming van overtook a slow cyclist, I had to brake.", "bicycle"),
    ("A car coming the other way overtook a cyclist on the narrow lane.", "bicycle"),
    ("An oncoming van overtook a horse rider and I had to brake.", "pedestrian"),
    ("On the lane a tractor coming towards me overtook a jogger.", "pedestrian"),
]


@pytest.mark.parametrize(("text", "kind"), OVERTAKEN_RIDERS)
def test_a_walker_or_rider_an_oncoming_road_user_overtakes_comes_towards_the_ego(text, kind):
    starts = _starts(text)
    assert (kind, "ahead", "against") in starts


OVERTAKEN_GUARDS = [
    ("An oncoming van overtook a slow lorry.", [("van", "oncoming", "with"), ("truck", "oncoming", "with")]),
    ("A van overtook a cyclist.", [("bicycle", "ahead", "with")]),
    ("I overtook a cyclist and a car came towards me.", [("bicycle", "ahead", "with"), ("car", "oncoming", "with")]),
]


@pytest.mark.parametrize(("text", "starts"), OVERTAKEN_GUARDS)
def test_what_a_road_user_going_the_egos_way_overtakes_goes_its_way(text, starts):
    assert _starts(text) == starts


DETERMINED = [
    ("An oncoming van overtook another slow lorry.", ("truck", "oncoming", "with")),
    ("Round the bend a van stood behind some roadworks.", ("van", "ahead", "with")),
    ("Round the bend a van stood behind another fallen tree.", ("van", "ahead", "with")),
]


@pytest.mark.parametrize(("text", "start"), DETERMINED)
def test_any_determiner_opens_the_noun_phrase(text, start):
    assert start in _starts(text)
