"""Overtakes that end close in front of the ego, and passes across the ego's front.

A road user that goes past the ego and, in the same sentence, gets into the ego's lane close in front
of it ("came past on my right and cut in right in front of me") makes two moves the ego meets: the
overtake, then a cut-in. Near misses keep the overtake alone: a pull-in that ends nowhere near the ego,
one said as a plain return ("came back in"), or one in front of someone else.

A verb + "past" whose object is the front of the ego's vehicle ("shot right past our bonnet") goes by
across the ego's front: a crossing, not an overtake. Past a side ("past my front wheel", "past my
bumper on the outside") it is still an overtake.
"""

from __future__ import annotations

import pytest

from tests.reading_of import moves
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text


def _overtakers(text: str) -> list[list[str]]:
    return [m for m in moves(text) if "overtake" in m]


@pytest.mark.parametrize(
    "text",
    [
        "A taxi swept past me on the right and cut in directly in front of my car.",
        "Incident 4: motorcycle overtakes the ego from behind and cuts in front of the ego dangerously close.",
        "honestly this moped flew past us and swerved in right in front of our bonnet, I had to brake",
        "Driving home on the bypass, a sports car overtook me and pulled in barely a metre in front of my car.",
        "The courier passed me on the inside and then cut straight in front of me.",
    ],
)
def test_a_close_pull_in_said_with_the_overtake_is_a_cut_in_after_it(text: str) -> None:
    assert _overtakers(text) == [["overtake", "cut_in"]]


@pytest.mark.parametrize(
    "text",
    [
        "A lorry overtook me on the hill and came back in just in front of me.",
        "A van overtook me on the bypass and pulled back in with plenty of room.",
        "A van overtook me and pulled back in a long way ahead.",
        "A coach overtook us and pulled in.",
        "A car overtakes the ego and cuts in sharply in front of it.",
    ],
)
def test_a_return_or_a_pull_in_away_from_the_ego_stays_the_overtakes_end(text: str) -> None:
    assert _overtakers(text) == [["overtake"]]


@pytest.mark.parametrize(
    "text",
    [
        "A motorbike came past on my right and cut straight back in front of me, far too early.",
        "Obs: HGV undertook our unit in lane 2 and swerved back into lane 3 directly in front of us.",
        "The scooter overtook and then swerved into our lane approx 4 m ahead.",
    ],
)
def test_a_sudden_cut_back_close_in_front_of_the_ego_is_a_cut_in_after_the_overtake(text: str) -> None:
    assert _overtakers(text) == [["overtake", "cut_in"]]


@pytest.mark.parametrize(
    "text",
    [
        "A car overtook me and pulled back in right in front of me.",
        "A van overtook me and cut back in well ahead.",
        "The scooter overtook and then swerved into our lane some 40 m ahead.",
        "Country road, one lane each way: a van overtook me and cut back in right in front of me.",
    ],
)
def test_a_plain_or_distant_return_stays_the_overtakes_end(text: str) -> None:
    assert _overtakers(text) == [["overtake"]]


@pytest.mark.parametrize(
    "text",
    [
        "A car overtook the lorry ahead and cut back in right in front of me.",
        "A car coming the other way overtook a van and cut back in right in front of me.",
    ],
)
def test_a_return_after_a_pass_of_someone_else_is_no_cut_in(text: str) -> None:
    assert not any("cut_in" in m for m in moves(text))


def test_the_cut_in_after_the_overtake_is_in_the_layers() -> None:
    text = "A taxi swept past me on the right and cut in directly in front of my car."
    for seed in range(3):
        (adv,) = layers_from_text(text, seed)["adversaries"]
        assert [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])] == ["overtake", "cut_in"]


def test_a_crossing_in_front_does_not_become_a_cut_in() -> None:
    assert moves("A man stepped off the kerb right in front of my car.") == [["cross_in_front"]]


@pytest.mark.parametrize(
    "text",
    [
        "A boy on a bike went right past our bonnet as we pulled out of the junction.",
        "The lights changed and a scooter shot past my bumper, missing it by inches.",
        "We stopped hard and the cyclist whizzed past our nose.",
    ],
)
def test_going_past_the_egos_front_is_a_crossing(text: str) -> None:
    assert [m for m in moves(text) if m] == [["cross_in_front"]]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came past my front wheel.",
        "A lorry went past us on the outside.",
        "A van came past my bumper on the outside.",
    ],
)
def test_going_past_a_side_of_the_ego_stays_an_overtake(text: str) -> None:
    assert moves(text) == [["overtake"]]
