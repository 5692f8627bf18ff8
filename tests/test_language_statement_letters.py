"""An accident statement's parties by letter: the other party's letter in the sketch is its road user."""

from __future__ import annotations

import pytest

from vei_scenario.language.lettered_parties import lettered_parties
from vei_scenario.language.reader import read


def _noun(phrase: str) -> str | None:
    """A stand-in for the reader's road-user nouns, enough for these texts."""
    words = phrase.replace("(", " ").replace(")", " ").split()
    return next((w for w in reversed(words) if w in {"van", "e-scooter", "cyclist", "car", "vehicle"}), None)


def _read(text: str) -> list[tuple[str, str | None, list[str]]]:
    return [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in read(text).actors]


def test_the_other_partys_letter_is_the_road_user_its_line_names():
    text = (
        "Date: 3 May 2024, 10:15\nVehicle A: me, Skoda Octavia\nVehicle B: Ford Transit van, plumber\n"
        "A: none\nB: 14 - reversing\nSketch: I was driving along Mill Lane at 20 mph when B backed out of a "
        "driveway on my left into my path and I hit its rear corner."
    )
    read_as = _read(text)
    assert [kind for kind, _, _ in read_as] == ["van"]  # one road user: B is the van, the Skoda is the ego's
    assert read_as[0][1] == "left"


def test_a_statement_in_another_languages_labels():
    text = (
        "Véhicule A: Renault Clio, conducteur: moi\nVéhicule B: e-scooter, rider young man\nCirconstances B: 17\n"
        "Sketch: I drive on avenue Jean Jaurès, B comes off the pavement on my right and crosses in front of me, "
        "I brake but touch him."
    )
    assert _read(text) == [("e-scooter", "roadside_right", ["cross_in_front"])]


def test_the_writers_label_is_the_ego_and_a_letter_in_brackets_is_dropped():
    text = (
        "vehicle a: me, mazda 3\nvehicle b: no vehicle, it is a trottinette (e-scooter)\nthe rider (b) fell. b hit me."
    )
    out = lettered_parties(text, _noun)
    assert out.splitlines()[0] == "the ego: me, mazda 3"
    assert out.splitlines()[1].startswith("vehicle b: no vehicle")  # (the other's label stays; "no vehicle" names none)
    assert out.splitlines()[2] == "the rider fell. the e-scooter hit me."


@pytest.mark.parametrize(
    "text",
    [
        # one letter only labelled: no statement by letters ("plan b", "a b-road")
        "b: took plan b on the b-road, a van cut in.",
        # the writer is B: the other's letter is "a", which is also the article
        "vehicle a: ford fiesta van\nvehicle b: me, kia ceed\na pulled out of a side road on my left.",
        # the other party's line names no road user
        "vehicle a: me\nvehicle b: 2-abd-118\nb pulled out.",
        # letters that label variants or speakers, with no word of the form's
        "variants:\na: the lead van brakes hard.\nb: the lead van turns left.\nthe ego follows at 50 km/h.",
    ],
    ids=["one-label", "writer-is-b", "no-noun", "variants"],
)
def test_no_statement_by_letters_is_left_as_written(text):
    assert lettered_parties(text, _noun) == text


def test_the_letter_is_the_party_only_where_it_names_one():
    text = (
        "vehicle a: skoda octavia\nvehicle b: ford transit van, came from a driveway on my left\n"
        "leaving the b&q car park b reversed. exit b, lane a/b, point b. the b driver said 3(b). the van (b) hit me."
    )
    out = lettered_parties(text, _noun).splitlines()
    assert out[0] == "the ego: skoda octavia"  # ("my left" in B's line does not make B the writer)
    assert out[2] == (
        "leaving the b&q car park the van reversed. exit b, lane a/b, point b. "
        "the van driver said 3(b). the van hit me."
    )
