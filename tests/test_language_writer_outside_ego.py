"""A first-person writer who is in no vehicle of their own ("we are writing on behalf of", "I am writing
about my mum", "in our newsletter") names no ego with their "I" and "we": the story is told as a
report with no narrator is, and the vehicle it is about, brought in as new ("a taxi doing 30 mph was
struck by ...", "a lorry driver was turning left when ..."), is the ego. Wordings written for the
class in several registers (a union letter, a family complaint, a newsletter, a residents' note, a
solicitor's line), none taken from a corpus; near misses keep their road users."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph, kinds
from vei_scenario.language import ego_double
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    ("text", "kind", "ego"),
    [
        (
            "We are writing on behalf of our member. A taxi doing 30 mph was struck by a bus that ran the red"
            " light at the junction.",
            "truck",
            48.3,
        ),
        (
            "We were told that a courier van travelling at 40 km/h was hit when a car pulled out of a side road.",
            "car",
            40.0,
        ),
        ("I am writing about my mum. A minicab doing 20 mph was hit by a lorry that ran the red light.", "truck", 32.2),
        (
            "Our members ask the council to act: a delivery driver doing 25 mph was hit when a van pulled out"
            " of the retail park into his path.",
            "van",
            40.2,
        ),
        (
            "We act for the family. Their car was proceeding at 50 km/h when a lorry came through the red"
            " light from the right.",
            "truck",
            50.0,
        ),
    ],
)
def test_the_vehicle_a_writer_outside_reports_on_is_the_ego(text, kind, ego):
    assert kinds(text) == [kind]
    assert ego_kph(text) == ego


def test_the_turning_lorry_of_a_newsletter_is_the_ego_and_its_turn_the_route():
    r = read(
        "In our newsletter this month: a lorry driver was turning left at the lights when a cyclist came up"
        " on his inside."
    )
    assert [a.kind for a in r.actors] == ["bicycle"]
    assert r.ego_route == "left"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the writer drives: their "we" is the ego, and a car brought in as new is someone else
        (
            "We were driving home at 30 mph when a car doing 40 km/h came past us and a van pulled out of a"
            " side road in front of us.",
            ["car", "van"],
        ),
        # the writer at a wheel of their own: "my car" is the ego, the van doing 30 someone else
        (
            "I was in my car at the lights when a van doing 30 mph went past and a lorry pulled out of a side"
            " road in front of it.",
            ["van", "truck"],
        ),
    ],
)
def test_a_writer_in_the_scene_keeps_the_new_vehicle_a_road_user(text, expected):
    assert kinds(text) == expected


def test_a_text_that_says_you_has_named_the_ego():
    """The reader reads "your" as its narrator's word; the text as written addressed its reader."""
    text = (
        "A car doing 30 mph braked for a cyclist crossing ahead and a van behind it ran into it. Explain your answer."
    )
    assert "car" in kinds(text)
    assert ego_double.addressed(text) and not ego_double.addressed("We act for the family of the young rider.")


def test_the_writer_s_own_words_name_no_ego_only_when_they_are_outside():
    tokens = "we are told a taxi doing 30 was hit".split()
    assert not ego_double.ego_unnamed(tokens, [])
    assert ego_double.ego_unnamed(tokens, [], writer_outside=True)
    assert not ego_double.ego_unnamed([*tokens, "you"], [], writer_outside=True)  # ("you" names the ego)
