"""One road user read as two: named again with words the reader did not tie back to it. The noun
phrase's determiner is read past its modifiers ("the injured cyclist"), a singular noun alone is one
named before, as notes write it ("into path of HGV"), and a road user brought back with "this" or
"the" whose reading is an earlier one's is that one. Wordings written for the class in several
registers (a test spec, a driver's text, a police note, a voice note), none taken from a corpus; near
misses that name two road users keep both."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds
from vei_scenario.language.reader import read
from vei_scenario.language.reading import NotUnderstood
from vei_scenario.language.rules_backend import layers_from_text


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        (
            "Ego goes straight over the crossroads at 50 km/h while an oncoming car turns right across its"
            " path. The opposing vehicle's speed is 20 km/h.",
            "car",
        ),
        (
            "A white van pulled out of a side road on my left while I was doing 30. The white van then"
            " stopped dead in front of me.",
            "van",
        ),
        (
            "I was doing about 40 when a lorry came out of the yard on the right. The same lorry then"
            " slammed on in the middle of the road.",
            "truck",
        ),
        (
            "Officer's note: a cyclist came off the left kerb into the path of the patrol car at 25 mph."
            " The injured cyclist was treated at the scene.",
            "bicycle",
        ),
    ],
)
def test_a_definite_phrase_past_its_modifiers_names_the_one_named_before(text: str, kind: str) -> None:
    assert kinds(text) == [kind]


@pytest.mark.parametrize(
    "text",
    [
        "Rural road, night, ego 80 km/h, oncoming HGV in its own lane. Ego drifts into path of HGV. Severity"
        " high (night + wet + oncoming HGV).",
        "Urban road, ego 30 km/h. Child runs out from the left kerb. Ego brakes late and strikes child."
        " Injuries to child minor.",
        "Ego at 60 km/h on the motorway, lead truck brakes hard. Ego stops behind truck; gap to truck 2 m.",
        "Test: ego 40 km/h, cyclist rides along the right edge ahead. Ego overtakes cyclist with 1 m to"
        " spare, then cuts back in front of cyclist.",
        "Notes: moped came out of a driveway on the right at 20 km/h, ego 35 km/h, ego braked, no contact with moped.",
    ],
)
def test_a_singular_noun_alone_in_notes_is_the_one_named_before(text: str) -> None:
    assert len(read(text).actors) == 1, kinds(text)


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30 when a car ran the red light. This guy in a red SUV blew through the red and I T-boned him.",
        "I was at 40 when a van ran the red from the left. The guy in the white Transit went through the"
        " red light from the left and I clipped him.",
        "Was doing 30 when a car ran the red light. That driver in the grey Golf ran the red light and hit me.",
    ],
)
def test_a_road_user_brought_back_with_this_and_read_as_before_is_one(text: str) -> None:
    assert len(read(text).actors) == 1, kinds(text)


@pytest.mark.parametrize(
    ("text", "n"),
    [
        ("A car ran the red light and another car ran it too while I was doing 30.", 2),
        ("Two teenagers on one e-scooter, plus their mate on another, came straight at me.", 2),
        ("Two cyclists rode out of the side road on the left; one of them swerved in front of me.", 2),
        ("Cyclists were riding two abreast ahead of me at 20 mph.", 1),
        ("Ego 50 km/h behind lead car. Lead car brakes hard, ego changes lane and passes other car on the right.", 2),
        ("I was doing 30 when a car pulled out on the left, and a second car pulled out behind it.", 2),
    ],
)
def test_road_users_told_apart_stay_apart(text: str, n: int) -> None:
    assert len(read(text).actors) == n, kinds(text)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "I was doing 30 mph when out of nowhere a man, a man on an e-scooter, came off the kerb right in"
            " front of me.",
            ["e-scooter"],
        ),
        (
            "Voice note: so I'm driving along at like 40 k and this guy, this guy riding a Lime, just cuts"
            " across my bonnet from the left.",
            ["e-scooter"],
        ),
        (
            "Witness: the vehicle was travelling at about 20 mph when a lad, a lad on a pushbike, rode out"
            " from the side road on its left.",
            ["bicycle"],
        ),
        (
            "Something came out of the dark at me, a kid, a kid on one of those scooters, straight across"
            " the road. I was doing 50 km/h.",
            ["e-scooter"],
        ),
    ],
)
def test_one_said_again_at_once_with_more_is_one(text: str, expected: list[str]) -> None:
    """A speaker's self-repair, the same words said again at once and then told apart ("a man, a man on
    an e-scooter"), names one road user: the fuller mention."""
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "Two scooters came off the kerb on the left, a scooter, a scooter and then a car behind them,"
            " while I was doing 30 mph.",
            3,
        ),
        (
            "A car, a red car, pulled out of the side road on the left in front of me while I was doing 30 mph.",
            1,
        ),
    ],
)
def test_self_repair_near_misses(text: str, expected: int) -> None:
    """Near misses: the same words said again with no modifier after them (a count, "a scooter, a
    scooter and ..."), and a repair that adds an adjective (already one road user), keep their counts."""
    assert len(read(text).actors) == expected


def test_a_person_word_that_ends_the_text_is_read_without_error() -> None:
    """ "... the one-way fella" ends the text: what follows the person's word is asked for past the
    last word, and is nothing (an ojek, a motorbike taxi, is the road user)."""
    assert kinds("ojek against the one-way fella") == ["car"]


@pytest.mark.parametrize("text", ["Van:", ": cyclist :", "x: van :"])
def test_a_label_that_ends_the_text_is_refused_not_an_error(text: str) -> None:
    """A road user's label whose colon is the last word has no value after it to read: the text names
    no act, so it is refused like any other, not an IndexError."""
    with pytest.raises(NotUnderstood):
        layers_from_text(text, 0)
