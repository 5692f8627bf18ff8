"""A road user named bare in a heading (a scenario's title, a ticket's summary, a post's subject line)
and then brought in by the text with "a" or "an" is one road user, told twice. Wordings written for
the class in several registers (a Gherkin scenario, a bug ticket, a forum title, a Singapore driver's
post, a Nigerian newspaper's headline, a test plan), none taken from a corpus; near misses whose words
or reading set two road users of one kind apart keep both."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        (
            "Scenario: Cyclist swerves into the ego lane\n  Given the ego drives at 40 km/h on a straight road\n"
            "  When a cyclist on the right swerves into the ego lane 10 m ahead\n  Then the ego brakes",
            "bicycle",
        ),
        (
            "[BUG] Lorry cutting in from lane 2 not handled\nSteps: ego at 80 km/h on the motorway, a lorry from"
            " the right lane cuts in 8 m ahead. Actual: no braking.",
            "truck",
        ),
        (
            "E-scooter rider runs red at Kingsway lights!! Doing about 30 mph through the green when a lad on"
            " an e-scooter came flying across from the right through the red.",
            "e-scooter",
        ),
        (
            "Lorry suddenly jam brake on PIE, nearly langgar\nJust now I driving 70 km/h, a lorry in front of me"
            " suddenly jam brake, I also emergency brake lor.",
            "truck",
        ),
        (
            "Pedestrian steps off kerb in front of test vehicle. The test vehicle travels at 30 km/h. A"
            " pedestrian steps off the left kerb 15 m ahead and walks across at 5 km/h.",
            "pedestrian",
        ),
        (
            "Test 7 - oncoming van turns right across ego path. Ego goes straight on at 50 km/h; an oncoming"
            " van turns right across its path at 20 km/h.",
            "van",
        ),
    ],
)
def test_a_road_user_named_in_a_heading_then_brought_in_is_one(text: str, kind: str) -> None:
    assert kinds(text) == [kind]


def test_the_heading_gives_its_speed_where_the_text_gives_none() -> None:
    text = (
        "Scenario: lead car at 60 km/h brakes hard\n  Given the ego follows at 70 km/h\n"
        "  When a lead car 30 m ahead brakes hard to a stop"
    )
    (car,) = read(text).actors
    assert round(car.speed_mps * 3.6) == 60


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (  # each said to start somewhere the other is not
            "Cyclist ahead of me signalled left. A cyclist behind me then overtook me on the right.",
            ["bicycle", "bicycle"],
        ),
        (  # the later one said to be someone else
            "Car cut in from the left lane. Then a second car cut in from the right lane.",
            ["car", "car"],
        ),
        (  # one parked, the other moving
            "Parked van on the left. I was doing 20 when a van reversed out of a driveway on my right.",
            ["van", "van"],
        ),
        (  # a note's bare noun, said to start elsewhere than the later one
            "Car pulled out of side road on left, I braked. A car behind me went into my back.",
            ["car", "car"],
        ),
        (  # each doing a different thing of its own
            "Taxi cut me up at the lights then a taxi behind him ran the red.",
            ["car", "car"],
        ),
        (  # one crossing, the other waiting, on either side
            "Pedestrian crossed from the left. A pedestrian on the right waited at the kerb.",
            ["pedestrian", "pedestrian"],
        ),
        (  # not bare: brought back with "the"
            "The bus ahead of me stopped at the stop. A bus behind me then overtook both of us.",
            ["truck", "truck"],
        ),
    ],
)
def test_two_road_users_of_one_kind_told_apart_stay(text: str, expected: list[str]) -> None:
    assert sorted(kinds(text)) == sorted(expected)
