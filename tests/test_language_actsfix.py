"""Acts said as nouns, where they are none: a causative "make + road user + bare verb" ("a bus made a
car swerve": two road users, the car swerving), a light verb in an alternative set aside ("rather than
make a swerve": not done), and a verb + particle compound after a vehicle's word governed by a
preposition of place ("in the bus pull-in": a place). Guards: the light-verb and compound readings the
rules were built for."""

from __future__ import annotations

import pytest

from tests.reading_of import acts as _acts


@pytest.mark.parametrize(
    ("text", "causer", "causee"),
    [
        ("A bus made a car swerve into my lane and I hit it.", "truck", "car"),
        ("A bus pulling out made a car swerve into my lane.", "truck", "car"),
        ("The van made a cyclist swerve into the kerb.", "van", "bicycle"),
        ("A dog made a cyclist fall off in front of me.", "pedestrian", "bicycle"),
        ("A lorry made a cyclist brake hard in front of me.", "truck", "bicycle"),
        ("A van pulled out and made a cyclist swerve into my path.", "van", "bicycle"),
    ],
)
def test_a_causative_make_keeps_both_road_users(text: str, causer: str, causee: str) -> None:
    kinds = [kind for kind, _ in _acts(text)]
    assert causer in kinds and causee in kinds, _acts(text)


@pytest.mark.parametrize(
    "text",
    [
        "Rather than make a swerve, I braked hard.",
        "Instead of making a swerve I stopped.",
        "Instead of making a sudden swerve, I stayed in my lane at 30 mph.",
        "Rather than swerve, I braked hard.",
    ],
)
def test_a_light_verb_in_an_alternative_set_aside_is_not_done(text: str) -> None:
    assert all("cut_in" not in names for _, names in _acts(text)), _acts(text)


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A car was parked in the bus pull-in on the left and I went past at 30 mph.", "car"),
        ("A cyclist was waiting in the bus pull-in and I drove past.", "bicycle"),
        ("A taxi stopped in the taxi pull-in on the right and a man got out.", "car"),
        ("A van was parked at the lorry pull-in on the left.", "van"),
        ("There was a bus in the bus pull-in on the left; a pedestrian stepped out from behind it.", "truck"),
        ("A lorry sat in a big bus pull-in as I passed at 40 mph.", "truck"),
    ],
)
def test_a_compound_after_a_vehicle_word_in_a_place_is_the_place(text: str, kind: str) -> None:
    acts = _acts(text)
    assert acts[0][0] == kind and "cut_in" not in acts[0][1], acts


@pytest.mark.parametrize(
    ("text", "act"),
    [
        ("I was doing 40 mph when a van on my left made a sudden swerve into my lane.", "cut_in"),
        ("A van on my left made a swerve into my lane rather than brake.", "cut_in"),
        ("Test log: oncoming van turn-across at the junction, ego straight at 50 km/h.", "turn_across"),
        ("At the junction an oncoming truck did a turn-across in front of us while we went straight on at 30 km/h.",
         "turn_across"),
    ],
)  # fmt: skip
def test_guard_acts_said_as_nouns_are_still_read(text: str, act: str) -> None:
    assert act in _acts(text)[0][1], _acts(text)
