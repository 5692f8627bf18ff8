"""Whose side a kerb side word is: the ego's own nearside or offside, said with the ego's possessive
("on the test car's offside", "on V1's nearside"), is a side of the road beside the ego, as "on my
offside" is; another vehicle's side, or the ego's side where it was struck, stays a part of a vehicle."""

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def relation(text: str) -> str | None:
    return read(text).actors[0].relation


@pytest.mark.parametrize(
    "text, expected",
    [
        # a test line, with the ego called "the ego vehicle", "the test car" or "the ego"
        ("The ego vehicle travels at 30 mph. A pedestrian steps out on the ego's offside and crosses.",
         "roadside_right"),
        ("The test car drives at 20 mph. A boy runs out on the test car's offside.", "roadside_right"),
        ("The ego drives at 20 mph. A boy runs out on the ego's nearside.", "roadside_left"),
        # a report in the third person, the ego named by a label of its own
        ("The subject vehicle was doing 25 mph when a child darted out on the subject vehicle's offside.",
         "roadside_right"),
        ("Vehicle 1 was travelling at 30 mph when a jogger came off the pavement on V1's offside.",
         "roadside_right"),
        # metric speeds in a present-tense test line follow the right-hand convention: the offside is the left
        ("The ego drives at 40 km/h. A girl runs out on the ego's offside.", "roadside_left"),
    ],
)  # fmt: skip
def test_the_egos_own_kerb_side_is_beside_the_ego(text, expected):
    assert relation(text) == expected


def test_the_egos_offside_holds_on_every_seed():
    text = "The test car drives at 20 mph. A boy runs out on the test car's offside and crosses."
    for seed in (0, 1, 2):
        (adv,) = layers_from_text(text, seed)["adversaries"]
        assert adv["spawn"]["relation"] == "roadside_right"


@pytest.mark.parametrize(
    "text, expected",
    [
        # guards: another vehicle's side says nothing of where it is beside the ego (the near kerb stays)
        ("The ego drives at 20 mph. A boy runs out on the bus's offside.", "roadside_left"),
        # where the ego was struck is a part of it, not a place a road user starts from
        ("The ego drives at 20 mph. A boy runs out into the ego's offside.", "roadside_left"),
        # the ego's own possessive before "my"-style wording keeps reading as it did
        ("I was doing 30 mph when a jogger stepped off the kerb on my offside.", "roadside_right"),
    ],
)
def test_a_side_of_another_vehicle_or_a_struck_side_stays_a_part(text, expected):
    assert relation(text) == expected
