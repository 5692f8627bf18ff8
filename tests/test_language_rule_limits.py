"""Ordinary sentences near the reader's rules for rear-ending, named riders, following, passing by the
ego's front and coming up a side: each names a road user and says what it does in words those rules
look at, and each must keep the reading its grammar gives, not the rule's."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _read(text: str) -> list[tuple[str, str, list[str]]]:
    """(kind, start relation, behaviours) of each road user on seed 0."""
    out = []
    for a in layers_from_text(text, 0)["adversaries"]:
        said = a["behaviour"]
        acts = [b["behaviour"] for b in said["sequence"]] if "sequence" in said else [said["behaviour"]]
        out.append((a["type"], a["spawn"]["relation"], acts))
    return out


@pytest.mark.parametrize(
    "text",
    [
        "Sam stepped on the brake when a van pulled out in front of me.",
        "Gemma stepped on the gas and a cyclist came across in front of her car.",
        "Sarah was riding in the car with me when a van cut us up.",
        "Lucy was riding with me in the van when a car pulled out.",
        "Jake was riding the clutch in traffic when a cyclist cut in front.",
    ],
)
def test_a_named_driver_or_passenger_is_no_rider_or_walker(text: str) -> None:
    """Stepping on a pedal and riding in a car or with the writer say no road user of their own."""
    assert len(_read(text)) == 1


@pytest.mark.parametrize(
    ("text", "acts"),
    [
        ("A van following directions stopped in front of me.", ["stop"]),
        ("A taxi following the satnav turned right across my path.", ["forced_turn"]),
        ("A hatchback was following at 2 s when I braked.", ["follow_vehicle"]),
        ("A van was following me at 1 s on the motorway.", ["follow_vehicle"]),
    ],
)
def test_following_something_named_is_not_following_the_ego(text: str, acts: list[str]) -> None:
    """ "Following" with an object of its own, or beside a stop or a turn of its own, is not following
    the ego; with none, or with the ego as its object, it is."""
    assert _read(text)[0][2] == acts


@pytest.mark.parametrize(
    "text",
    [
        "A motorbike passed inches from my front wheel as it overtook me.",
        "A motorbike passed about a metre from my bumper on the outside.",
    ],
)
def test_a_close_pass_along_the_side_stays_an_overtake(text: str) -> None:
    """Close by a part of the front ("my front wheel") or along a side is passing beside the ego."""
    assert "overtake" in _read(text)[0][2]


def test_a_close_pass_across_the_front_after_coming_out_is_a_crossing() -> None:
    assert _read("A cyclist came out of the car park and passed inches from my bumper.")[0][2] == ["cross_in_front"]


@pytest.mark.parametrize(
    ("text", "relation"),
    [
        ("A lorry pulled up on the nearside and a cyclist rode into it.", "left"),
        ("A cyclist came up on my nearside and turned across me.", "behind"),
    ],
)
def test_pulling_up_beside_is_standing_there_not_coming_from_behind(text: str, relation: str) -> None:
    assert _read(text)[0][1] == relation


@pytest.mark.parametrize(
    ("text", "relation"),
    [
        ("The taxi that I rear-ended had stopped for a cat.", "ahead"),
        ("The van I rear-ended was waiting for a cyclist.", "ahead"),
        ("The van ahead of me was rear-ended by a taxi.", "ahead"),
        ("A minicab rear-ended me at the lights.", "behind"),
        ("Just got rear-ended by a van on the A40.", "behind"),
    ],
)
def test_rear_ending_places_only_its_own_parties(text: str, relation: str) -> None:
    """The one rear-ended is the verb's object or, passive, its subject, never a noun past another verb
    or the object of a place ("ahead of me")."""
    read = _read(text)
    assert read[0][1] == relation and all(kind != "pedestrian" for kind, _, _ in read)
