"""Mends of the review of the merged round (findings 7, 8 and 14):

* "had right of way" says that a road user went on, its priority (it is no side): a text that tells
  only that of it is read, not refused;
* a vehicle said only to stop, whose stop a "when"/"as" clause times by someone getting into its path,
  is the ego only where no narrator tells the story and nothing sets the vehicle apart ("I overtook
  it", "the target vehicle", "the car in the other lane", "a cyclist behind it");
* describe.md's example of a faster road user passing a standing ego reads as the guide says."""

from __future__ import annotations

import inspect
from pathlib import Path

import pytest

from vei_scenario.language import ego_double
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import layers_from_text


def _kinds(text: str) -> list[str]:
    return sorted(a["type"] for a in layers_from_text(text, 0)["adversaries"])


def _names(adv: dict) -> list[str]:
    return [node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("The cyclist had right of way and I stopped for him.", "bicycle"),
        ("The cyclist had the right of way, so I stopped for him.", "bicycle"),
        ("The pedestrian had right of way and I waited for her.", "pedestrian"),
        ("A cyclist had right of way at the crossing and I stopped for him.", "bicycle"),
    ],
)
def test_a_road_user_said_to_have_right_of_way_goes_on(text: str, kind: str) -> None:
    [adv] = layers_from_text(text, 0)["adversaries"]
    assert adv["type"] == kind
    assert _names(adv)  # (it does something: it goes on)
    assert adv["spawn"].get("relation") not in ("right", "junction_right")  # ("right" of way is no side)


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        # a narrator at a wheel is the ego: the van they hit, overtake or pass is someone else
        (
            "The van came to a stop when a boy stepped out. I was behind it and went into the back of it.",
            ["pedestrian", "van"],
        ),
        ("The van came to a stop when a boy stepped out and I overtook it.", ["pedestrian", "van"]),
        ("The van came to a stop as a cyclist cut across. I was coming the other way.", ["bicycle", "van"]),
        (
            "The van came to a halt when a pedestrian crossed; a cyclist behind it swerved into me.",
            ["bicycle", "pedestrian", "van"],
        ),
        ("The van came to a stop, and when a kid ran out I braked.", ["pedestrian", "van"]),
        ("The bus came to a stop when a girl stepped out, and I went round it.", ["pedestrian", "truck"]),
        # the words set it apart: a test's target, a lane beside another, a road user behind "it"
        ("The target vehicle shall come to a stop when a pedestrian steps out in front of it.", ["car", "pedestrian"]),
        (
            "The van came to a stop when a boy stepped out and the cyclist behind it swerved.",
            ["bicycle", "pedestrian", "van"],
        ),
        ("The car in the other lane came to a stop when a pedestrian stepped out.", ["car", "pedestrian"]),
    ],
)
def test_a_stop_timed_by_when_keeps_a_vehicle_set_apart_from_the_ego(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    ("text", "kinds"),
    [  # guards: what the rule was built for still reads the stopping vehicle as the ego
        ("The van came to a stop when a boy stepped out on the left.", ["pedestrian"]),
        ("The vehicle shall stop without contact when a pedestrian steps out on the right, 15 m away.", ["pedestrian"]),
        ("The taxi came to a halt as a man stepped out on the right.", ["pedestrian"]),
        ("The bus came to a stop when a girl ran out in front of it.", ["pedestrian"]),
        # a spec that gives the ego's speed ("ego" there names no vehicle of its own); the car left is the
        # parked ones the pedestrian steps out from, not the vehicle under test
        (
            "The vehicle shall stop without contact when a pedestrian steps out from between parked cars on the"
            " left at a distance of 12 m, at an ego speed of 30 km/h.",
            ["car", "pedestrian"],
        ),
    ],
)
def test_a_stop_timed_by_when_in_an_unnarrated_text_is_still_the_ego(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds


def test_no_caller_can_leave_out_the_words_the_stop_rule_reads() -> None:
    """``tokens`` is required: a caller that forgot it would switch the rule off."""
    for fn in (ego_double.merge_into_ego, ego_double.stops_when_someone_comes, ego_double._double):
        assert inspect.signature(fn).parameters["tokens"].default is inspect.Parameter.empty, fn.__name__
    assert inspect.signature(ego_double.merge_into_ego).parameters["unnamed"].default is inspect.Parameter.empty


DOC_EXAMPLE = "the ego car is stationary at a red signal; a cyclist overtakes it and then stops"


def test_describe_md_s_faster_overtaker_example_reads_as_the_guide_says() -> None:
    guide = Path(__file__).resolve().parents[1] / "docs" / "guides" / "describe.md"
    assert DOC_EXAMPLE in " ".join(guide.read_text(encoding="utf-8").split())
    layers = layers_from_text(DOC_EXAMPLE[0].upper() + DOC_EXAMPLE[1:] + ".", 0)
    assert float(layers["ego"]["speed_mps"]) == 0.0
    [adv] = layers["adversaries"]
    assert _names(adv) == ["overtake", "stop"]
    assert float(adv["speed_mps"]) > 1.0
    assert float(adv["spawn"]["longitudinal_m"]) < -25.0  # (further back than one at the ego's speed, -18.2)
