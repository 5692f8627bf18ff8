"""Fixes after review of the "while ... then" rule and the closest approach kept as along_road's gap:

- a narrator's main clause that only says the narrator's speed or state ("I was doing 30 while a cyclist
  rode along the kerb, then swerved into my lane"), or a "then" clause said of the narrator ("then cut
  in front of me"), lets the "while" clause's subject go on; a road user's main clause still goes on;
- a rider said beside the ego ("2 m behind me on my left") or in a lane of its own ("in the cycle lane")
  starts at the short distance said (a left hook); one in the ego's lane keeps it as how near it came."""

import pytest

from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text


def _acts(adv: dict) -> list[str]:
    return [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])]


def _first(adv: dict) -> dict:
    return next(node for _, node in behaviour_nodes(adv["behaviour"]))


def _of(text: str, kind: str) -> dict:
    advs = [a for a in layers_from_text(text, 0)["adversaries"] if a["type"] == kind]
    assert len(advs) == 1, layers_from_text(text, 0)["adversaries"]
    return advs[0]


@pytest.mark.parametrize(
    ("text", "kind", "act"),
    [
        # review E1: the narrator's speed or state, then a verb said of the narrator
        ("I was doing 30 while a cyclist rode along the kerb, then swerved into my lane.", "bicycle", "cut_in"),
        ("I was doing 40 while a van sat in the left lane, then cut in front of me.", "van", "cut_in"),
        (
            "I was cruising at 60 while a lorry was in the inside lane, then pulled out in front of me.",
            "truck",
            "cut_in",
        ),
        (
            "I kept my speed while the cyclist rode on the kerb, then swerved out in front of me.",
            "bicycle",
            "cross_in_front",
        ),
        # review E2: "following a bus" is the narrator's state; the cyclist overtakes, not the bus
        ("I was following a bus while a cyclist rode alongside, then overtook it.", "bicycle", "overtake"),
        # variants: a narrator's act (not a state), then a verb said of the narrator
        ("I slowed down while a cyclist rode along the kerb, then swerved into my lane.", "bicycle", "cut_in"),
        ("We were doing 50 while a van sat in the left lane, then cut in front of us.", "van", "cut_in"),
    ],
)
def test_after_a_narrators_background_the_while_clauses_subject_goes_on(text, kind, act):
    assert act in _acts(_of(text, kind))


def test_the_bus_followed_does_not_overtake():
    assert "overtake" not in _acts(
        _of("I was following a bus while a cyclist rode alongside, then overtook it.", "truck")
    )


@pytest.mark.parametrize(
    ("text", "kind", "act", "mps"),
    [
        # guards: a road user's main clause goes on (the rule's own cases)
        ("A lorry pulled out in front of me while I was doing 50, then crawled along at 15 mph.", "truck", None, 6.706),
        (
            "A pedestrian waited at the kerb while I slowed to 20, then stepped out.",
            "pedestrian",
            "cross_in_front",
            None,
        ),
    ],
)
def test_a_road_users_main_clause_still_goes_on(text, kind, act, mps):
    adv = _of(text, kind)
    if act is not None:
        assert act in _acts(adv)
    if mps is not None:
        assert adv["speed_mps"] == pytest.approx(mps, abs=0.01)


@pytest.mark.parametrize(
    ("text", "start"),
    [
        # review F1: beside the ego, a short distance is where it starts
        ("A cyclist was riding in the cycle lane on my left about 2 m ahead of me when I turned left.", 2.0),
        ("A cyclist was 2 metres behind me on my left when I turned left into a side road.", -2.0),
        # variant: a bike lane with no side said
        ("A cyclist was riding in the bike lane 2 m ahead of me when I turned right.", 2.0),
    ],
)
def test_a_rider_beside_the_ego_starts_at_the_short_distance_said(text, start):
    adv = _of(text, "bicycle")
    assert float(adv["spawn"]["longitudinal_m"]) == pytest.approx(start)
    assert "gap_m" not in _first(adv)["config"]


@pytest.mark.parametrize(
    ("text", "near"),
    [
        # guards: in the ego's lane (at its kerb, or passed), a short distance is how near it came
        (
            "We were doing 40 km/h. A cyclist was riding along the kerb on our left ahead of us and we went "
            "round him giving about 1.5 m.",
            1.5,
        ),
        ("I passed a cyclist riding on my left, giving him 1.5 m.", 1.5),
    ],
)
def test_a_rider_in_the_egos_lane_keeps_the_short_distance_as_how_near_it_came(text, near):
    adv = _of(text, "bicycle")
    assert _first(adv)["config"].get("gap_m") == pytest.approx(near)
    assert abs(float(adv["spawn"]["longitudinal_m"])) > 5.0
