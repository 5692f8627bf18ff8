"""Fixes after a review: a pull-in told apart after an overtake, "As a <vehicle> driver" without a
comma, and British "clock" (to notice).

* A pull-in told in a sentence of its own after an overtake is a cut-in of its own only where its own
  place phrase ends at the ego ("in front of me", "on my nose"), not in front of or behind someone else
  ("behind a lorry well ahead of me"), and only where it is said to be close ("just in front of me",
  "dived in", "5 m ahead of the ego"); with no margin said, or a wide one, it is how the overtake ends.
  A sentence ends at ". ! ?": a pull-in after ";" or ":" is told in the overtake's sentence.
* "As a taxi driver in a hurry cut in I braked": the "as" clause has a verb of its own ("cut", also a
  noun) after the role's phrase; "as" is "while", and the taxi is someone else.
* "I only clocked the cyclist at 30 mph": the narrator noticed the cyclist while doing 30 mph; the
  speed is the ego's. A police officer or a camera that clocks a road user at a speed measures its speed.
"""

from __future__ import annotations

import pytest

from tests.reading_of import kinds, moves
from vei_scenario.language.rules_backend import layers_from_text


def _overtaker(text: str) -> list[list[str]]:
    return [m for m in moves(text) if "overtake" in m]


# --- F7: the pull-in's own place phrase ends at the ego, not at someone else -----------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A van overtook me on the motorway. Later it pulled in behind a lorry well ahead of me.",
        "A van overtook me. After half a mile it pulled in in front of the car ahead of me.",
        "A coach overtook us on the A1. Later it pulled in behind a tractor just ahead of us.",
    ],
)
def test_a_pull_in_in_front_of_or_behind_someone_else_is_the_overtakes_end(text: str) -> None:
    assert _overtaker(text) == [["overtake"]]


def test_a_pull_in_behind_the_ego_is_no_cut_in() -> None:
    said = moves("A motorbike overtook the car behind me. It pulled in just behind me.")
    assert not any("cut_in" in m for m in said)


# --- F8: a pull-in with no closeness said, or a wide one, is how the overtake ends ------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A lorry overtook me. It moved in ahead of me after a mile.",
        "A car overtook me. It pulled in ahead of me with plenty of room.",
        "A car overtook me safely. It pulled in a long way in front of me.",
        "The motorbike overtook me. It cut in front of my car by a good 50 metres.",
        "Test 3: the van overtakes the ego. The van then pulls in 40 m ahead of the ego.",
        "A minibus overtook us on the dual carriageway. It moved over in front of us soon after.",
    ],
)
def test_a_pull_in_with_no_closeness_said_is_the_overtakes_end(text: str) -> None:
    assert _overtaker(text) == [["overtake"]]


def test_a_plain_pull_in_after_an_overtake_is_no_dangerous_cut_in() -> None:
    (adv,) = layers_from_text("A lorry overtook me. It moved in ahead of me after a mile.", 0)["adversaries"]
    assert adv["behaviour"]["behaviour"] == "overtake"


@pytest.mark.parametrize(
    "text",
    [
        "A hatchback overtook me on the ring road. Then it dived in front of my car.",
        "Test 5: the van overtakes the ego at 80 km/h. The van then cuts in 3 m ahead of the ego.",
        "A van overtook me. It pulled in right on my nose and I had to brake hard.",
    ],
)
def test_a_close_pull_in_told_apart_at_the_ego_stays_a_cut_in(text: str) -> None:
    assert _overtaker(text) == [["overtake", "cut_in"]]


# --- F9: a hard brake after a pull-in keeps its criticality -----------------------------------------------
def test_a_hard_brake_after_a_pull_in_keeps_its_criticality() -> None:
    text = "The BMW overtook me at speed. It pulled in and then braked hard in front of me."
    (adv,) = layers_from_text(text, 0)["adversaries"]
    parts = adv["behaviour"]["sequence"]
    assert [p["behaviour"] for p in parts] == ["overtake", "sudden_stop"]
    assert parts[-1]["config"]["criticality"] == "dangerous"


def test_a_hard_brake_after_a_cut_in_told_apart_keeps_its_criticality() -> None:
    text = "The BMW overtook me at speed. It cut in right in front of me and then braked hard."
    (adv,) = layers_from_text(text, 0)["adversaries"]
    parts = adv["behaviour"]["sequence"]
    assert [p["behaviour"] for p in parts] == ["overtake", "cut_in", "sudden_stop"]
    assert parts[-1]["config"]["criticality"] == "dangerous"


# --- C9: a close pull-in is a cut-in whether ". ; :" or ", then" ends the overtake's clause ---------------
@pytest.mark.parametrize(
    "text",
    [
        "A car overtook me. It then cut in just in front of me.",
        "A car overtook me; it then cut in just in front of me.",
        "A car overtook me: it cut in right in front of my bonnet.",
        "A car overtook me, then it cut in just in front of me.",
    ],
)
def test_a_close_pull_in_reads_the_same_after_any_clause_end(text: str) -> None:
    assert _overtaker(text) == [["overtake", "cut_in"]]


# --- F19: "As a <vehicle> driver <phrase> cut(s) ... I ...": "as" is "while" --------------------------------
@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("As a taxi driver in a hurry cut in I braked.", "car"),
        ("As a van driver on his phone cut across I swerved.", "van"),
        ("As a taxi driver in the right lane cuts across I brake.", "car"),
        ("As a lorry driver in the outside lane cut me up I braked hard.", "truck"),
        ("As a van driver in the next lane cut across I hit the brakes.", "van"),
    ],
)
def test_a_role_with_a_verb_that_is_also_a_noun_is_someone_else(text: str, kind: str) -> None:
    assert kinds(text) == [kind]
    assert any("cut_in" in m for m in moves(text))


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("As a taxi driver I see a lot. Last night a van cut in front of me and I braked hard.", ["van"]),
        ("As a bus driver on the school run I had a van cut in front of me.", ["van"]),
        ("As a bus driver of twenty years I would ask cyclists to think.", []),
        ("As a cyclist who rides every day I was passed too close by a lorry.", ["truck"]),
    ],
)
def test_a_role_without_a_comma_stays_the_narrators(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


# --- F24: British "clock" = notice: the speed of a narrator who clocks someone is the ego's ----------------
@pytest.mark.parametrize(
    "text",
    [
        "I only clocked the cyclist at 30 mph when he was right in front of me.",
        "We only clocked the horse rider at 30 mph as we came round the bend.",
    ],
)
def test_a_narrator_who_clocks_a_road_user_at_a_speed_is_doing_that_speed(text: str) -> None:
    layers = layers_from_text(text, 0)
    (adv,) = layers["adversaries"]
    assert layers["ego"]["speed_mps"] == pytest.approx(13.41, abs=0.05)
    assert adv["speed_mps"] != pytest.approx(13.41, abs=0.05)


@pytest.mark.parametrize(
    "text",
    [
        "The officer clocked the van at 45 mph as it passed me.",
        "A speed camera clocked the van at 45 mph.",
        "I estimated the van at 45 mph as it passed me.",
    ],
)
def test_one_who_measures_or_judges_a_road_users_speed_says_its_speed(text: str) -> None:
    (adv,) = layers_from_text(text, 0)["adversaries"]
    assert adv["speed_mps"] == pytest.approx(20.12, abs=0.05)
