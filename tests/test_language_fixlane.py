"""Review findings 9 and 10 of round 27.

9. A lead ahead that swerves out of the ego's lane reveals what stands in the lane it leaves only if
   that stands there now, on the ego's road: not in a lane of the other carriageway or a slip road, not
   at another time ("earlier ... had broken down"), not something since taken away ("had been towed
   away"). Those stay lane changes; what stands in the lane of the ego's road is still revealed.
10. An overtaker from behind that starts at a moving ego's speed passes at its stated speed: its
    overtake's ``speed_gain_mps`` is the stated speed less the ego's, within the parameter's bounds.
"""

from __future__ import annotations

import re

import pytest

from vei_scenario.language.behaviours import overtake
from vei_scenario.language.reader import read


def _leads(text: str) -> list[str]:
    """The first behaviour of each road user read from ``text``."""
    return [a.behaviours[0][0] if a.behaviours else "" for a in read(text).actors]


@pytest.mark.parametrize(
    "text",
    [
        "The car ahead swerved into the right lane, and I saw a mattress lying in the left lane of the other"
        " carriageway.",
        "The car ahead swerved into the right lane, revealing a mattress lying in the left lane of the slip road.",
        "The car ahead swerved into the right lane; earlier a lorry had broken down in the left lane but had been"
        " towed away.",
        "The van ahead moved into the left lane, and a lorry stood in the right lane of the opposite carriageway.",
        "The car ahead swerved into the right lane; a lorry had broken down in the left lane but had been towed away.",
        "The car ahead swerved into the right lane; yesterday a lorry had broken down in the left lane.",
    ],
)
def test_what_stands_on_another_road_or_at_another_time_is_not_revealed(text: str) -> None:
    r = read(text)
    assert [a.obstacle for a in r.actors] == [None] * len(r.actors), _leads(text)
    assert "cut_out" not in _leads(text)
    assert _leads(text)[0] == "change_lane"


@pytest.mark.parametrize(
    "text",
    [
        "The car ahead swerved into the right lane, revealing a mattress lying in the left lane.",
        "The car ahead swerved into the right lane, revealing a mattress lying in the left lane of the carriageway.",
        "The car ahead swerved into the right lane, revealing a lorry that had broken down in the left lane.",
        "Ahead of us a grey hatchback darted out into the left lane, and a broken-down van sat in the right lane.",
    ],
)
def test_what_stands_in_the_lane_of_the_egos_road_is_still_revealed(text: str) -> None:
    r = read(text)
    leads = [a for a in r.actors if a.behaviours and a.behaviours[0][0] == "cut_out"]
    assert len(leads) == 1 and leads[0].obstacle is not None, _leads(text)


@pytest.mark.parametrize(
    ("ego", "speed", "gain"),
    [
        (50 / 3.6, 120 / 3.6, 70 / 3.6),  # the reviewer's motorbike at 120 past an ego at 50
        (100 / 3.6, 130 / 3.6, 30 / 3.6),  # a car at 130 past an ego at 100 on the motorway
        (10.0, 50.0, 20.0),  # more than the parameter allows: its top
        (10.0, 10.5, 1.0),  # less: its bottom
    ],
)
def test_an_overtaker_started_at_the_egos_speed_passes_at_its_own(ego: float, speed: float, gain: float) -> None:
    cfg = overtake.stated_gain({"gap_m": 10.0}, ego, speed, "behind")
    assert cfg["speed_gain_mps"] == pytest.approx(gain, abs=1e-3)
    assert cfg["gap_m"] == 10.0


@pytest.mark.parametrize(
    ("cfg", "ego", "speed", "relation"),
    [
        ({"speed_gain_mps": 3.0}, 10.0, 30.0, "behind"),  # a gain set is kept
        ({}, 20.0, 15.0, "behind"),  # slower than the ego: starts at its own speed
        ({}, 0.0, 8.0, "behind"),  # past an ego that stands: starts at its own speed
        ({}, 10.0, 30.0, "left"),  # not behind: starts at its own speed
    ],
)
def test_a_gain_set_or_a_start_at_its_own_speed_is_kept(cfg: dict, ego: float, speed: float, relation: str) -> None:
    assert overtake.stated_gain(cfg, ego, speed, relation) == cfg


def test_the_written_scenario_passes_at_the_stated_speed() -> None:
    from vei_scenario.language.rules_backend import layers_from_text
    from vei_scenario.language.scenario_writer import write_scenario

    layers = layers_from_text("The ego drives at 50 km/h. A motorbike at 120 km/h overtakes it from behind.", 0)
    xosc = write_scenario(layers, "scenario").xosc.decode()
    targets = [float(v) for v in re.findall(r'<AbsoluteTargetSpeed value="([\d.]+)"', xosc)]
    assert max(targets) == pytest.approx(120 / 3.6, abs=0.01)  # (ego 13.889 + gain 19.444, not ego + 5)
