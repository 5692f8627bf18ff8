"""Review findings 9-13 on the overtake-then-cut-in, "past our bonnet" and roundabout-entry rules.

* A brake said after the cut-in that ends an overtake is the overtaker's own sudden stop, as it was
  after a return: an overtaker is faster than the ego and has nothing to settle (finding 9).
* A wide margin said anywhere in the sentence ("leaving plenty of room") leaves a sudden return the
  overtake's end (finding 10).
* On a single carriageway, or with an oncoming road user in the chain, a return in front of the ego is
  how the overtake ends (finding 11).
* A vehicle going past the ego's bonnet with no junction said cuts across in front of it; it runs no
  red at an invented crossroads (finding 12).
* A road user said to be on the roundabout already rides the ring: it does not start at rest at a side
  arm (finding 13); the reader tells ring_entry a refused give-way by a flag of its own.
"""

from __future__ import annotations

import pytest

from tests.reading_of import moves
from vei_scenario.language import ring_entry
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text


def _names(adv: dict) -> list[str]:
    return [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])]


def _first(text: str, seed: int = 0) -> dict:
    return layers_from_text(text, seed)["adversaries"][0]


# --- finding 9: the brake after a cut back in


@pytest.mark.parametrize(
    "text",
    [
        "A car overtook me and cut back in front of me, then braked.",
        "A car overtook me on the motorway and cut back in front of me, then braked.",
        "A car overtook me on the dual carriageway and cut back in front of me, then braked.",
        "A car overtook me in lane 2 and cut back in front of me, then braked.",
        "A van undertook me and swerved back in directly in front of me and then braked.",
    ],
)
def test_a_brake_after_the_cut_in_that_ends_an_overtake_is_a_stop_of_its_own(text: str) -> None:
    for seed in (0, 1):
        assert _names(_first(text, seed)) == ["overtake", "cut_in", "sudden_stop"]


@pytest.mark.parametrize(
    "text",
    [
        "A car cut in front of me and braked.",
        "A van cut in front of us, then braked.",
    ],
)
def test_a_plain_brake_after_a_cut_in_alone_is_how_it_settles(text: str) -> None:
    assert moves(text) == [["cut_in"]]


def test_a_hard_brake_after_the_cut_back_in_stays_a_sudden_stop() -> None:
    text = "A car overtook me and cut back in front of me, then braked hard."
    assert _names(_first(text)) == ["overtake", "cut_in", "sudden_stop"]


# --- finding 10: a wide margin later in the sentence


@pytest.mark.parametrize(
    "text",
    [
        "A van overtook me and cut back in front of me, leaving plenty of room.",
        "A van overtook me and cut back in front of me, there was plenty of room.",
        "A car overtook me and swerved back in front of me, with loads of space.",
    ],
)
def test_a_sudden_return_with_a_wide_margin_said_after_it_stays_the_overtakes_end(text: str) -> None:
    assert [m for m in moves(text) if "overtake" in m] == [["overtake"]]


@pytest.mark.parametrize(
    "text",
    [
        "A motorbike came past on my right and cut straight back in front of me, far too early.",
        "A car overtook me and cut back in front of me, leaving me no room.",
    ],
)
def test_a_sudden_return_with_no_wide_margin_stays_a_cut_in(text: str) -> None:
    assert [m for m in moves(text) if "overtake" in m] == [["overtake", "cut_in"]]


# --- finding 11: one lane each way, or an oncoming road user


@pytest.mark.parametrize(
    "text",
    [
        "The motorbike overtook me and swerved back in front of me to avoid an oncoming car.",
        "On a single carriageway road, a van overtook me and cut back in right in front of me.",
        "A car overtook me on a single-carriageway road and cut back in right in front of me.",
        "The van overtook us and cut back in right in front of us to miss an oncoming bus.",
    ],
)
def test_a_return_on_a_two_way_road_stays_the_overtakes_end(text: str) -> None:
    assert [m for m in moves(text) if "overtake" in m] == [["overtake"]]


@pytest.mark.parametrize(
    "text",
    [
        "On the motorway a car overtook me and cut back in right in front of me.",
        "Obs: HGV undertook our unit in lane 2 and swerved back into lane 3 directly in front of us.",
    ],
)
def test_a_sudden_return_on_a_road_of_several_lanes_stays_a_cut_in(text: str) -> None:
    assert [m for m in moves(text) if "overtake" in m] == [["overtake", "cut_in"]]


# --- finding 12: a vehicle past the ego's bonnet, no junction said


@pytest.mark.parametrize("text", ["A van went past our bonnet.", "A car went right past my bonnet."])
def test_a_vehicle_past_the_bonnet_with_no_junction_cuts_across(text: str) -> None:
    layers = layers_from_text(text, 0)
    assert layers["environment"]["map"]["kind"] != "crossroad"
    assert _names(layers["adversaries"][0]) == ["cut_in"]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist went past our bonnet as we waited at the lights.",
        "A boy on a bike went right past our bonnet as we pulled out of the junction.",
    ],
)
def test_a_rider_past_the_bonnet_still_crosses(text: str) -> None:
    assert [m for m in moves(text) if m] == [["cross_in_front"]]


def test_a_vehicle_past_the_bonnet_at_a_junction_crosses_it() -> None:
    assert _names(_first("A van went past our bonnet at the junction.")) != ["cut_in"]


# --- finding 13: a road user already on the ring


@pytest.mark.parametrize(
    "text",
    [
        "A car on the roundabout came round from the right and hit me as I entered.",
        "A taxi on the roundabout came from the left and clipped me as I joined.",
    ],
)
def test_a_road_user_on_the_roundabout_rides_the_ring(text: str) -> None:
    for seed in (0, 1):
        adv = _first(text, seed)
        assert _names(adv)[0] not in ("turn_into", "run_red_light")


def test_going_onto_the_roundabout_from_an_arm_still_joins_the_ring() -> None:
    assert _names(_first("A car came onto the roundabout from the left without giving way."))[0] == "turn_into"


def test_ring_entry_takes_the_refusal_and_the_priority_as_flags() -> None:
    run = [("run_red_light", {"arrival_gap_s": 2.0}, None, None)]
    joined = ring_entry.joins_the_ring("roundabout", False, "junction_left", False, False, False, run)
    assert joined[0][0] == "turn_into"
    refused = ring_entry.joins_the_ring("roundabout", False, "junction_left", True, False, False, run)
    assert refused[0][0] == "run_red_light"
    on_the_ring = ring_entry.joins_the_ring("roundabout", False, "junction_left", False, True, False, run)
    assert on_the_ring[0][0] == "run_red_light"
