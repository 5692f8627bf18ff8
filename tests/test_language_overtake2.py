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
        ("A silver hatchback overtook us and cut in right in front of us.", [["overtake", "cut_in"]]),
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


# A pull-in close in front of the ego told in a sentence of its own after an overtake is a cut-in of its
# own (in the overtake's own sentence too: see test_language_lanes3.py); ending nowhere near the ego, or
# of an unclear doer, it is how the overtake ends.


@pytest.mark.parametrize(
    "text",
    [
        "A taxi overtook us on the bypass. It then swerved in barely a car length in front of our bonnet.",
        "Some idiot on a motorbike came past me at the lights. He pulled in right in front of me and I had to brake.",
        "Test 12: the coach overtakes the ego at 90 km/h. Then the coach cuts in 5 m ahead of the ego.",
        "mate this van just flew past us on the dual carriageway!! then dived in front of my car with no signal",
        "A pickup overtook me on the hill. Pickup cut in right on my nose.",
    ],
)
def test_a_pull_in_told_apart_at_the_ego_is_a_cut_in_after_the_overtake(text: str) -> None:
    assert [m for m in moves(text) if "overtake" in m] == [["overtake", "cut_in"]]


@pytest.mark.parametrize(
    "text",
    [
        "A van overtook me and pulled back in a long way ahead.",
        "A car overtook me and pulled back in just in front of me.",  # (a plain return: its end)
        "A car overtakes the ego and cuts in sharply in front of it.",
        "A taxi overtook us on the bypass. It then cut back in a car length in front of us.",  # (a return: its end)
    ],
)
def test_a_pull_in_in_the_overtakes_sentence_or_of_unclear_doer_stays_its_end(text: str) -> None:
    assert [m for m in moves(text) if "overtake" in m] == [["overtake"]]


def test_an_oncoming_overtakers_return_told_apart_names_no_cut_in() -> None:
    said = moves("A lorry coming the other way overtook a tractor. The lorry pulled back in.")
    assert not any("cut_in" in m for m in said)


def test_the_cut_in_told_apart_is_in_the_layers() -> None:
    layers = layers_from_text("A pickup overtook me on the hill. Pickup cut in right on my nose.", 0)
    (adv,) = layers["adversaries"]
    assert [part["behaviour"] for part in adv["behaviour"]["sequence"]] == ["overtake", "cut_in"]


# Kept behind the ego over a stretch of road is following it; then passing it is an overtake after that.


@pytest.mark.parametrize(
    "text",
    [
        "A motorcyclist who had been sitting close behind us for some distance overtook on the offside.",
        "Old Land Rover stayed behind me for about three miles, then went past on the straight.",
        "Log 4: grey hatchback behind the ego for several minutes, then overtakes it.",
    ],
)
def test_behind_the_ego_for_a_stretch_then_past_is_following_then_overtaking(text: str) -> None:
    assert moves(text) == [["follow_vehicle", "overtake"]]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("A car came up behind me and overtook.", [["overtake"]]),  # (it only comes up: no stretch kept)
        ("I drove behind a van for two miles, then it stopped.", [["stop"]]),  # (the ego is the one behind)
        ("A bus ran into me from behind for no reason at all.", [["keep_going"]]),  # (no ego after "behind")
    ],
)
def test_behind_without_a_stretch_or_of_the_ego_is_no_following(text: str, said: list[list[str]]) -> None:
    assert moves(text) == said
