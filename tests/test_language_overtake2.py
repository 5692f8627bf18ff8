"""Who passes whom: the object of a verb of passing is the one passed, never the one that passes.

A walker or rider going along the road that the ego passes, where the ego is told by a role the
reader holds as no road user ("our rider overtakes it", "the learner overtook him"): the walker or
rider goes along ahead, it overtakes no one. A turn said as an opening participle before "and" is
the narrator's, and a road user named after "when" is no vehicle the narrator drives. Wordings
written for the class in several registers (a test spec, a log line, a diary, a driving lesson
note); near misses where a road user does pass someone (the ego, another road user) keep their
overtake.
"""

from __future__ import annotations

import pytest

from tests.reading_of import moves
from vei_scenario.language import whose_act
from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist ahead is riding at 15 km/h along the kerb and our rider overtakes him with room to spare.",
        "Spec 7: a jogger runs along the verge in front at 8 km/h; the subject vehicle then passes her.",
        "A kid on a bike was wobbling along the gutter, and the learner overtook him wide.",
        "Lesson notes: an old man was walking along the edge of the lane ahead, and my pupil went round him nicely.",
        "Log: e-scooters on the high street. 14:10, fleet van passed e-scooter at the kerb with 2 m to spare.",
        "An e-scooter rider was going along the bus lane at 20 km/h, and our driver overtook it with plenty of room.",
    ],
)
def test_the_one_passed_goes_along_ahead(text: str) -> None:
    assert moves(text) == [["along_road"]]


def test_the_one_passed_starts_ahead_in_the_layers() -> None:
    text = "A cyclist ahead is riding at 15 km/h along the kerb and our rider overtakes him with room to spare."
    for seed in range(3):
        (adv,) = layers_from_text(text, seed)["adversaries"]
        assert adv["spawn"]["relation"] in ("ahead", "roadside_left", "roadside_right")
        assert adv["behaviour"]["behaviour"] == "along_road"


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("A van came up behind me and overtook me.", [["overtake"]]),
        ("I was driving home when a cyclist overtook me on the inside.", [["overtake"]]),
        ("Two cyclists were riding ahead, and one of them overtook the other.", [["along_road"], ["overtake"]]),
        ("A silver hatchback overtook us and cut in right in front of us.", [["overtake"]]),
        ("I was driving along when a car overtook me.", [["overtake"]]),
    ],
)
def test_a_road_user_that_passes_someone_keeps_its_overtake(text: str, said: list[list[str]]) -> None:
    assert moves(text) == said


def test_a_subject_read_as_a_road_user_keeps_its_pass() -> None:
    from vei_scenario.language.reader import scan

    text = "A cyclist was riding ahead and a lorry overtook him."
    clauses, _, _, tokens = scan(text)
    assert whose_act.unread_subjects_passes(clauses, tokens) == {}
    text = "A cyclist was riding ahead and our rider overtook him."
    clauses, _, _, tokens = scan(text)
    assert list(whose_act.unread_subjects_passes(clauses, tokens).values()) == [True]


@pytest.mark.parametrize(
    "text",
    [
        "Turning left at the junction and a cyclist was coming up on my inside.",
        "turning right into the retail park and a lad on a scooter was coming up the inside of me",
    ],
)
def test_a_turn_said_as_a_participle_before_and_is_the_narrators(text: str) -> None:
    reading = read(text)
    assert reading.ego_route in ("left", "right")
    assert all(b[0] != "forced_turn" for a in reading.actors for b in a.behaviours)


def test_a_participle_said_with_a_comma_may_be_the_road_users_turn() -> None:
    assert moves("Turning left out of the junction, a cyclist swerved round me.") == [["forced_turn"]]


def test_a_clause_after_when_is_no_vehicle_the_narrator_drives() -> None:
    (cyclist,) = read("I was driving when a cyclist overtook me on the inside.").actors
    assert cyclist.kind == "bicycle" and [b[0] for b in cyclist.behaviours] == ["overtake"]
