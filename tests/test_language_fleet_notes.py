"""Fleet managers' and driver coaches' notes on what a dash-cam clip shows: the bare "Driver" of such a
note is the ego's own driver, whatever the driver does (brakes, holds back, waits), not one more car."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    "text",
    [
        "Reviewed clip: cyclist riding in the bus lane on our nearside, doing nothing wrong. Driver held back, "
        "waited for a safe gap and went round him with plenty of room.",
        "Coach note: pedestrian stepped out from behind the ice cream van. Driver waited until she was across, "
        "then moved off. Good anticipation.",
        "An e-scooter came down the hill on our side. Driver stopped and waited for him to pass.",
    ],
)
def test_the_bare_driver_who_waits_is_the_egos(text):
    reading = read(text)
    assert [a.kind for a in reading.actors if a.kind in ("car", "van", "truck")] == []


def test_a_driver_of_a_vehicle_named_before_stays_theirs():
    reading = read("A taxi stopped at the kerb ahead of us. The driver waited, then pulled out in front of us.")
    assert [a.kind for a in reading.actors] == ["car"]


@pytest.mark.parametrize(
    ("text", "relation"),
    [
        (
            "Taxi going straight on over the junction on green. An e-scooter comes out of Hauptstr. from the "
            "right against his red and shoots across in front of the taxi. Driver brakes hard.",
            "junction_right",
        ),
        (
            "Van heading north. A cyclist pulled out of Station Rd. on the left without looking. Driver braked.",
            "junction_left",
        ),
    ],
)
def test_an_abbreviations_point_ends_no_sentence(text, relation):
    assert [a.relation for a in read(text).actors] == [relation]


def test_a_writer_in_lower_case_ends_sentences_with_points():
    from vei_scenario.language.normalise import abbreviation_points

    text = "came round the bend. a cyclist was on my side. he swerved."
    assert abbreviation_points(text) == text
    assert abbreviation_points("It was dark. Then it rained. A van left Station Rd. on the right.") == (
        "It was dark. Then it rained. A van left Station Rd on the right."
    )


def test_an_acronym_before_a_missing_capital_still_ends_its_sentence():
    from vei_scenario.language.normalise import abbreviation_points

    text = "I was behind a VW. the cyclist ahead of it swerved. It was raining. We stopped."
    assert abbreviation_points(text) == text
