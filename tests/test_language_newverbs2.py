"""Acts told in words the reader had no phrase for: a road user kept at the ego's rear in any of the
ways English says it ("up on my bumper", "in my boot", "on my tailboard"), and a road user whose going
is sideways over into the ego ("came over into us"). Guards: contact with the ego's rear stays contact,
a road user only placed beside or behind is not made to follow or cut in, and the ego's own moves stay
the ego's."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds, moves
from vei_scenario.language.rules_backend import layers_from_text


def _first_moves(text: str) -> list[str]:
    return moves(text)[0]


@pytest.mark.parametrize(
    "text",
    [
        "Doing 50 on the bypass, a black pickup was right up on my bumper for two miles.",
        "I was at 30 mph through the village and a delivery van sat on my tailboard the whole way.",
        "Cruising at 60, the estate car behind me was practically in my boot with its lights on full.",
        "Ego at 80 km/h; a coach stays right up on our rear bumper for the whole stretch.",
    ],
)
def test_a_road_user_kept_at_the_ego_rear_follows_it(text: str) -> None:
    assert "follow_vehicle" in _first_moves(text)


@pytest.mark.parametrize(
    "text",
    [
        "I held the centre lane at 55 mph when a tanker from the nearside lane came over into us.",
        "Lane two at 70 mph: the hatchback in lane one just came across into us.",
        "Ego in the middle lane at 100 km/h; an HGV in the left lane wanders across into me without signalling.",
    ],
)
def test_going_over_into_the_ego_is_a_cut_in(text: str) -> None:
    assert _first_moves(text)[0] == "cut_in"


@pytest.mark.parametrize(
    "text, absent",
    [
        # contact with the rear stays contact, no following
        ("I was stopped at the lights when a taxi went into my boot at 20 mph.", "follow_vehicle"),
        # a thing carried in the ego's boot is no road user following
        ("I was doing 30 with my bike in my boot when a van pulled out in front of me.", "follow_vehicle"),
        # going over something, not over into the ego, is no cut-in
        ("I was doing 40 when a cyclist came over the brow of the hill towards me.", "cut_in"),
    ],
)
def test_guards_keep_their_old_reading(text: str, absent: str) -> None:
    assert all(absent not in acts for acts in moves(text))


def test_a_parked_road_user_gains_no_act() -> None:
    text = "I drove past at 20 mph; a lorry was parked up on the kerb behind my car."
    assert all(b not in ("follow_vehicle", "cut_in") for acts in moves(text) for b in acts)


def test_the_ego_coming_over_is_no_road_users_cut_in() -> None:
    text = "A bus sat in lane one at 50 mph and I came over into lane one behind it."
    assert "cut_in" not in moves(text)[0]


def test_the_layers_carry_the_follow() -> None:
    layers = layers_from_text("Doing 50 on the bypass, a black pickup was right up on my bumper.", 0)
    names = str(layers["adversaries"][0]["behaviour"])
    assert "follow_vehicle" in names


@pytest.mark.parametrize(
    "text, act",
    [
        ("The plaintiff was riding at 12 mph. The respondent, driving a white van in the outside lane, "
         "moved into the plaintiff's lane.", "cut_in"),
        ("I was driving at 30 mph in the nearside lane. The other motorist, who was driving an HGV in the "
         "offside lane, moved into my lane.", "cut_in"),
        ("We were at 40 in lane one. A young lad, riding a motorbike, pulled into my lane.", "cut_in"),
    ],
)  # fmt: skip
def test_a_participle_aside_names_the_subject_vehicle(text: str, act: str) -> None:
    assert act in moves(text)[0]


def test_a_time_before_the_participle_leaves_it_the_narrator() -> None:
    text = "This morning, driving a hire van at 40 mph, I saw a cyclist pull out of a side road."
    assert kinds(text) == ["bicycle"]
    assert moves(text) == [["turn_into"]]


@pytest.mark.parametrize(
    "text",
    [
        "Ego cruising at 90 km/h; a coach behind the ego at a 0.8 s headway.",
        "Test car at 60 mph, a pickup about 1.5 seconds behind it the whole run.",
    ],
)
def test_a_road_user_behind_at_a_time_gap_follows(text: str) -> None:
    assert moves(text)[0] == ["follow_vehicle"]


@pytest.mark.parametrize(
    "text, first",
    [
        ("Ego at 90 km/h; a coach 25 m behind the ego.", "keep_going"),  # a gap in metres is a place only
        ("Ego at 90 km/h; a coach behind the ego at a 0.8 s headway overtakes it.", "overtake"),
    ],
)
def test_a_time_gap_keeps_other_readings(text: str, first: str) -> None:
    assert moves(text)[0][0] == first
