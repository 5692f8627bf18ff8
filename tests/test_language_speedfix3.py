"""The ego's speed, where a review found the last round read too much into a bare number: two numbers with
a comma between where the second counts people or things ("doing 30, 35 people were on the pavement"), a
count before its noun after "at a <modifier>" ("at a very quiet 4 way stop"), and a past "did 15" said
of another occasion ("I did 15 on that road once").

The review's sentences, then variants written for these tests; each construction keeps guards, wordings
the round's rules were built for, which must keep their reading."""

from __future__ import annotations

import pytest

from vei_scenario.language import vocabulary as V
from vei_scenario.language.rules_backend import layers_from_text

KPH = V.SPEED_UNITS["km/h"]


def _ego_kph(text: str) -> float:
    return layers_from_text(text, 0)["ego"]["speed_mps"] / KPH


# --- "doing 30, 35 people ...": a comma range ends where its second number does ------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "We were doing 30, 35 people were on the footpath, when a kid ran out.",
        "I was at 30, 40 kids were at the school gate, and one ran out.",
        "I was going 30, 45 degrees to the road, when a car hit me.",
        "We were going 30, 45 cyclists were on the path, when one swerved into the road.",
    ],
    ids=["people", "kids", "degrees", "cyclists"],
)
def test_a_comma_before_a_count_is_no_range(text):
    assert _ego_kph(text) == pytest.approx(30, abs=0.05)


def test_the_child_picked_from_a_counted_group_still_crosses():
    (kid,) = layers_from_text("I was at 30, 40 kids were at the school gate, and one ran out.", 0)["adversaries"]
    assert (kid["spawn"]["relation"], kid["behaviour"]["behaviour"]) == ("roadside_right", "cross_in_front")


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30, 35 max, when a kid ran out in front of me.",
        "We were doing 30, 35. A kid ran out in front of us.",
        "I was going about 30, 35 when a kid on a bike shot out from the left.",
        "I was travelling 30, 35 km/h through the village when a jogger stepped out in front of me.",
    ],
    ids=["max", "full-stop", "when", "unit-then-place"],
)
def test_a_comma_range_that_ends_its_phrase_is_still_a_range(text):
    assert _ego_kph(text) == pytest.approx(32.5, abs=0.05)


# --- "at a very quiet 4 way stop": a count before the noun it counts is no speed -------------------------
@pytest.mark.parametrize(
    "text, count",
    [
        ("I was at a very quiet 4 way stop when a car came from the left.", 4),
        ("We were at a really busy 3 way junction when a van pulled out from the right.", 3),
        ("I was doing a very slow 3 point turn when a cyclist came round the corner.", 3),
        ("I was doing a really careful 3 point turn when a car came from the right.", 3),
        ("I stopped at a very quiet 4 way stop and a car came from the left.", 4),
        ("I stopped at a quiet 4 way stop and a car came from the left.", 4),
        ("We parked at a nice 5 star hotel and a car reversed into us.", 5),
        ("I was at a busy 5 way junction when a cyclist ran the red in front of me.", 5),
        ("We stayed at a lovely 20 room hotel and a car reversed into us in the car park.", 20),
        ("We stayed at a lovely twenty room hotel and a car reversed into us in the car park.", 20),
    ],
    ids=[
        "very-quiet-4-way",
        "really-busy-3-way",
        "very-slow-3-point",
        "really-careful-3-point",
        "stopped-very-quiet",
        "stopped-quiet",
        "5-star",
        "busy-5-way",
        "20-room",
        "twenty-room",
    ],
)
def test_a_count_before_its_noun_after_at_a_modifier_is_no_speed(text, count):
    assert round(_ego_kph(text)) != count


def test_a_road_user_keeps_its_own_speed_beside_a_three_point_turn():
    layers = layers_from_text("I was doing a really careful 3 point turn when a car came from the right.", 0)
    (car,) = layers["adversaries"]
    assert round(car["speed_mps"] / KPH) != 3


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was at a nice steady 50 on the bypass when a car pulled out in front of me.", 50),
        ("I was at a nice steady 50 today when a car pulled out in front of me.", 50),
        ("Doing a really gentle 20 past the school, I saw a boy run out in front of me.", 20),
        ("We sat at a very calm eighty-five on the ring road when a van cut in front of us.", 85),
    ],
    ids=["on-the-bypass", "today", "past-the-school", "in-words"],
)
def test_a_speed_after_modifiers_is_still_a_speed(text, kph):
    assert _ego_kph(text) == pytest.approx(kph, abs=0.05)


# --- "I did 15 on that road once": the speed of another occasion -----------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I did 15 on that road once, and today a car pulled out in front of me.", 15),
        ("I did 50 on this road before, and today a lorry pulled out in front of me.", 50),
        ("We did 80 on the motorway last year, but today a van cut in front of us.", 80),
    ],
    ids=["once", "before", "last-year"],
)
def test_did_a_number_on_another_occasion_is_no_speed_of_this_one(text, kph):
    assert round(_ego_kph(text)) != kph


@pytest.mark.parametrize(
    "text, kph",
    [
        ("We did 40 along the main road until a cyclist swerved in front of us.", 40),
        ("I did 60 on the ring road once the lights changed, and a van cut in front of me.", 60),
    ],
    ids=["along-until", "once-as-a-conjunction"],
)
def test_did_a_number_on_this_occasion_is_still_a_speed(text, kph):
    assert _ego_kph(text) == pytest.approx(kph, abs=0.05)


# --- the verbs before a hedged bare speed are those before a bare range -----------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("We went 50ish when a van cut in front of us.", 50),
        ("I drove 30-35 through the village when a jogger stepped out in front of me.", 32.5),
        ("We did 30-35 through the village when a jogger stepped out in front of us.", 32.5),
        ("Did 40-ish along the main road until a cyclist swerved in front of me.", 40),
    ],
    ids=["went-ish", "drove-range", "did-range", "did-ish"],
)
def test_a_hedged_or_ranged_bare_speed_after_a_past_verb_of_going(text, kph):
    assert _ego_kph(text) == pytest.approx(kph, abs=0.05)
