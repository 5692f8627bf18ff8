"""A lead said ahead of the ego that moves out of the lane, while a road user or a thing stands in the
lane on the other side: a cut-out revealing what stands there. A road user said ahead of the ego with no
lane of its own is in the ego's lane (the reading places it there), as a lead the ego follows is, so the
lane it leaves is the ego's, and what stands in the lane said by the side it leaves is in the ego's way.
Near misses stay lane changes: what stands in the lane the lead moves into, a lead said in a lane beside
the ego's, a move whose side is not said, a car parked at the kerb."""

from __future__ import annotations

import pytest

from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def _read_as(text: str) -> list[tuple[str, str | None, list[str]]]:
    """(kind, relation, behaviour names) of each road user read from ``text``."""
    return [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in read(text).actors]


@pytest.mark.parametrize(
    "text",
    [
        "The car ahead swerved into the right lane, revealing a mattress lying in the left lane.",
        "Ahead of us a grey hatchback darted out into the left lane, and a broken-down van sat in the right lane.",
        "Dual carriageway at 60 mph. The coach in front of me pulled out into the right lane and a cyclist had"
        " stopped in the left lane with a flat tyre.",
    ],
)
def test_a_lead_ahead_leaving_the_lane_beside_what_stands_is_a_cut_out(text: str) -> None:
    r = read(text)
    leads = [a for a in r.actors if a.behaviours and a.behaviours[0][0] == "cut_out"]
    assert len(leads) == 1, _read_as(text)
    assert leads[0].relation == "ahead" and leads[0].obstacle is not None
    revealed = r.actors[leads[0].obstacle]
    assert revealed.relation == "ahead" and [b[0] for b in revealed.behaviours] in (["stop"], ["keep_lane"])


def test_the_cut_out_and_its_obstacle_are_in_the_layers() -> None:
    text = "The car ahead swerved into the right lane, revealing a mattress lying in the left lane."
    for seed in range(3):
        advs = layers_from_text(text, seed)["adversaries"]
        names = {a["name"]: [n for _, n in behaviour_nodes(a["behaviour"])] for a in advs}
        (lead,) = [a for a in advs if names[a["name"]][0]["behaviour"] == "cut_out"]
        obstacle = names[lead["name"]][0]["config"]["obstacle"]
        assert obstacle in names and obstacle != lead["name"]


@pytest.mark.parametrize(
    "text",
    [
        # what stands is in the lane the lead moves into, not in its way
        "The car ahead moved into the left lane, and a van had stopped in the left lane.",
        # a lead said in a lane beside the ego's may leave a lane that is not the ego's
        "The van in the left lane moved into the right lane, and a car was stopped in the left lane.",
        # the side the lead moves to is not said
        "The car ahead changed lanes and a van was stopped in the left lane.",
        # a car parked at the kerb stands in no lane
        "The car ahead moved into the right lane. A car was parked on the left.",
        # nothing stands
        "The car ahead swerved into the right lane and carried on.",
    ],
)
def test_a_lane_change_with_nothing_left_standing_in_the_egos_lane_stays_one(text: str) -> None:
    assert not [r for r in _read_as(text) if "cut_out" in r[2]], _read_as(text)
