"""Review fixes to the rule that a report's vehicle braking for one from whose side it came is the
ego (protagonist._reactor_among): the origin said in an unpunctuated relative counts as one set off by
commas; the braking vehicle must be the one said to come from the other's side; and a braking verb the
other's sentence joins on with "and" keeps the two a tie."""

from __future__ import annotations

import pytest
from reading_of import kinds

from vei_scenario.language import protagonist
from vei_scenario.language.reader import read


def _sides(text: str) -> list[tuple[str, str | None]]:
    return [(a.kind, a.relation) for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (  # the reviewer's: the participle aside without commas
            "A black SUV ran the red. A taxi approaching from the SUV's right braked to a halt.",
            [("car", "junction_left")],
        ),
        (  # the reviewer's: "which was coming" without commas
            "A lorry pulled out of the side road. A car which was coming from the lorry's right braked hard.",
            [("truck", "junction_left")],
        ),
        (
            "A white saloon went through the red light at the crossroads. A minicab coming from the saloon's "
            "left had to stop.",
            [("car", "junction_right")],
        ),
        (
            "A van came out of the side road. A hatchback that was approaching from the van's right braked "
            "and stopped a metre short of the van's door.",
            [("van", "junction_left")],
        ),
    ],
    ids=["participle", "which-was-coming", "minicab-had-to-stop", "that-was-approaching"],
)
def test_an_origin_said_without_commas_counts_as_one_set_off_by_them(text, expected):
    assert _sides(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        # an object relative: the bus is the one that braked, not the taxi
        "A black SUV ran the red. A taxi that the bus braked for came from the SUV's right.",
        # the aside's own verb is not the taxi's reaction when another clause comes between
        "A black SUV ran the red. A taxi approaching from the SUV's right hit it and a bus braked.",
    ],
    ids=["object-relative", "another-clause"],
)
def test_a_reaction_past_the_relative_is_the_mentions_only_when_it_is_its_verb(text):
    assert len(read(text).actors) >= 2


@pytest.mark.parametrize(
    "text",
    [
        # the reviewer's: the taxi came from the SUV's side, the bus braked
        "A black SUV ran the red. A taxi came from the SUV's right. A bus braked to a halt.",
        "A lorry pulled out of the side road. A van came from the lorry's left. A car braked hard.",
        "A white saloon went through the red light. A minicab was coming from the saloon's right. A bus had to stop.",
    ],
    ids=["bus-brakes", "car-brakes", "bus-had-to-stop"],
)
def test_the_braking_vehicle_must_be_the_one_said_to_come_from_the_others_side(text):
    assert len(read(text).actors) == 3


def test_the_one_from_the_side_that_brakes_is_still_the_ego_when_said_in_its_own_sentence():
    assert _sides("A black SUV ran the red. A taxi came from the SUV's right and braked to a halt.") == [
        ("car", "junction_left")
    ]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (  # the reviewer's: the SUV brakes too, by a coordinated verb
            "A black SUV ran the red and braked. A taxi, which was approaching from the SUV's right, braked to a halt.",
            ["car", "car"],
        ),
        (
            "A lorry pulled out of the side road but stopped. A car, coming from the lorry's right, braked hard.",
            ["car", "truck"],
        ),
        (
            "A van came out of the side road and swerved. A hatchback, which was approaching from the van's "
            "right, braked.",
            ["car", "van"],
        ),
    ],
    ids=["suv-ran-and-braked", "lorry-but-stopped", "van-and-swerved"],
)
def test_two_that_brake_stay_a_tie(text, expected):
    assert sorted(kinds(text)) == expected


def test_a_noun_after_its_article_is_no_verb_of_reacting_past_the_relative():
    tokens = "a bus pulling away from a stop and then cut in".split()
    assert protagonist._past_bare_relative(tokens, 2) == 0
    assert protagonist._past_bare_relative("a taxi approaching from the right braked".split(), 2) == 6
