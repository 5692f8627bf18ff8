"""The outcome stated as a field or a cell of a row, not in a sentence (:mod:`vei_scenario.language.outcome`):
a test matrix pasted from a spreadsheet, a ticket's fields, a report form. Wordings written for these
tests (none taken from a corpus)."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import contacts_made, stated_intent
from vei_scenario.language.reader import _tokens, read


def _intent(text: str) -> str | None:
    return stated_intent(" ".join(_tokens(text)))


# a row pasted from a spreadsheet: its cells are separated by tabs, as fields by bars
@pytest.mark.parametrize(
    "text, intent",
    [
        ("T-07\tT-junction\tEgo 40 km/h\tVan pulls out from the left\tCollision\tDay, dry", "collision"),
        ("R2\tUrban road\tEgo 30 kph\tChild runs out from behind a bus\tNear miss\tRain", "near_miss"),
        ("7\tstraight\tego 50\tcyclist along the kerb\tsafe\tdusk", "safe"),
        ("A1\tMotorway\tEgo 100 km/h\tCar cuts in\tNo collision\tFog", "near_miss"),
        ("B3\tCrossroads\tEgo 20 km/h\tScooter crosses\tno contact\tnight", "near_miss"),
        # a compound noun in a cell stays the one thing it names
        ("C9\tStraight\tEgo 60 km/h\tLead car brakes\tCollision warning fitted\tDry", None),
        ("C10\tStraight\tEgo 60 km/h\tCyclist ahead\tcollision avoidance system on\tDry", None),
    ],
    ids=["collision-cell", "near-miss-cell", "safe-cell", "no-collision-cell", "no-contact-cell", "warning", "avoid"],
)
def test_a_cell_of_a_tabbed_row_is_read_on_its_own(text, intent):
    assert read(text).intent == intent


# a field whose value denies the contact its label names ("Contact: none", "Collision: N", "zero
# contact", "0 collisions"): no contact, as "no contact" says; a value that affirms it, a collision
@pytest.mark.parametrize(
    "text, intent",
    [
        ("Cyclist cuts across the ego. Contact: none.", "near_miss"),
        ("Pedestrian steps out. Collision: no", "near_miss"),
        ("Van pulls out; impact: N; ego braked hard.", "near_miss"),
        ("E-scooter crosses in front. Collisions: 0.", "near_miss"),
        ("Moped swerves in front of us, zero contact.", "near_miss"),
        ("Ego brakes for a jogger, 0 collisions in 20 runs.", "near_miss"),
        ("Lorry turns across the cyclist. Contact: nil.", "near_miss"),
        ("Bus pulls out. Injuries: none.", "near_miss"),
        ("Cyclist cuts across the ego. Contact: yes.", "collision"),
        ("Pedestrian steps out. Collision: Y", "collision"),
        # a value that is not an answer ("n/a", a number of a unit) says nothing of the contact
        ("Car cuts in. Collision warning: none", None),
        ("Truck ahead brakes. Collision: n/a", "collision"),
    ],
    ids=["contact-none", "collision-no", "impact-n", "collisions-0", "zero-contact", "0-collisions", "nil",
         "injuries-none", "contact-yes", "collision-y", "warning-none", "n-a"],
)  # fmt: skip
def test_a_field_value_denies_or_affirms_its_contact(text, intent):
    assert _intent(text) == intent


def test_a_denied_field_is_no_contact_made():
    tokens = _tokens("Cyclist cuts across the ego. Contact: none.")
    assert contacts_made(tokens) == []


# a test row or a requirement that rates the scenario critical states that class
@pytest.mark.parametrize(
    "text, intent",
    [
        ("CS-3\tMotorway\tEgo 120 km/h\tTruck sheds its load ahead\tCritical", "critical"),
        ("ped crossing | ego 30 km/h | critical", "critical"),
        ("Cyclist swerves into the lane. Result: critical.", "critical"),
        ("Criticality: Critical. A van cuts in 10 m ahead.", "critical"),
        ("A car turns across the ego. The scenario is critical by design.", "critical"),
        ("This case is highly critical: a child runs out from between parked cars.", "critical"),
        ("Critical scenario: a motorcycle overtakes and cuts in.", "critical"),
        # near misses: critical said of something else, or denied
        ("Car cuts in. Critical: no. Ego 50 km/h.", None),
        ("A cyclist was hit by a van and is in critical condition.", "collision"),
        ("It is critical that the ego brakes for the child crossing.", None),
        # (a criticality denied says nothing came close: a safe pass, see test_language_intent5)
        ("The scenario is not critical: a cyclist rides along the kerb.", "safe"),
        ("Truck overtakes. Severity: critical. Contact: yes.", "collision"),
        ("The critical moment came when the bus pulled out in front of me.", None),
        # a contact is what happened: it outranks a rating of how close it came
        ("Ped steps out from behind a bus | ego 40 km/h | Critical | impact at 25 km/h", "collision"),
    ],
    ids=["tab-cell", "bar-cell", "result", "criticality", "scenario-is", "case-is", "label", "critical-no",
         "condition", "critical-that", "not-critical", "severity", "moment", "rated-but-hit"],
)  # fmt: skip
def test_a_scenario_rated_critical_states_critical(text, intent):
    assert _intent(text) == intent


# an arrow in a note says what follows from what ("no braking -> impact"): a break, as a comma is, so
# a negation before it does not reach past it
@pytest.mark.parametrize(
    "text, intent",
    [
        ("Van pulls out, sensor blind, no braking -> side impact with the van.", "collision"),
        ("Pedestrian steps out => no reaction => collision", "collision"),
        ("Cyclist cuts in \u2192 no AEB \u2192 crash", "collision"),
        ("Scooter crosses -> ego brakes hard -> no contact", "near_miss"),
        ("Car cuts in --> ego yields, no conflict", "safe"),
    ],
    ids=["arrow", "double-arrow", "unicode-arrow", "arrow-no-contact", "long-arrow"],
)
def test_an_arrow_ends_a_negation(text, intent):
    assert _intent(text) == intent


# a text message: an emoji ends its clause as punctuation would ("braked 😱 nobody hit")
@pytest.mark.parametrize(
    "text, intent",
    [
        ("bus pulled out right in front of me, slammed the brakes \U0001f631 nobody hit \U0001f64f", "near_miss"),
        ("lorry cut across me \U0001f621 no contact tho", "near_miss"),
        ("kid on a bike shot out \U0001f6b2 hit him \U0001f622 ambulance came", "collision"),
        ("cyclist waited for me \U0001f44d no drama", "safe"),
    ],
    ids=["brakes-nobody-hit", "no-contact", "hit-him", "no-drama"],
)
def test_an_emoji_ends_its_clause(text, intent):
    assert read(text).intent == intent


# nobody harmed, said with its auxiliary ("no one got hurt", "no-one was injured"): no injury
@pytest.mark.parametrize(
    "text, intent",
    [
        ("A cyclist swerved across the road and no one got hurt.", "near_miss"),
        ("The van swerved round a jogger; no-one was injured.", "near_miss"),
        ("A moped ran the light and someone got hurt.", "collision"),
    ],
    ids=["no-one-got-hurt", "no-one-was-injured", "someone-got-hurt"],
)
def test_nobody_harmed_with_its_auxiliary(text, intent):
    assert _intent(text) == intent


# a compound verb of contact written as two words ("rear ended", "T boned"), as a note or a message
# writes it: the verb it is; "the rear end of the van" stays a noun
@pytest.mark.parametrize(
    "text, intent",
    [
        ("a taxi rear ended me at the lights", "collision"),
        ("lorry stopped dead, rear ended it at 20mph", "collision"),
        ("we got T boned by a car at the junction", "collision"),
        ("I was rear ended by a van on the ring road", "collision"),
        ("I nearly rear ended the bus", "near_miss"),
        ("the van's rear end was sticking out into my lane when a cyclist passed", None),
        ("a cyclist came past the rear ends of the cars in a queue", None),
    ],
    ids=["rear-ended-me", "rear-ended-it", "t-boned", "passive", "nearly", "rear-end-noun", "rear-ends-noun"],
)
def test_a_compound_contact_verb_in_two_words(text, intent):
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text, kept",
    [
        ("scooter crossing L->R at 15 km/h", "from the left at"),
        ("pedestrian walks left -> right", "walks from the left"),
        ("lead car slows 50 -> 30 km/h", "slows from 50 to 30 km/h"),  # (a change: from the first value)
    ],
    ids=["l-r", "left-right", "numbers"],
)
def test_an_arrow_of_a_direction_or_a_change_of_value_is_no_break(text, kept):
    assert kept in " ".join(_tokens(text))


@pytest.mark.parametrize(
    "text, broken",
    [
        ("slammed the brakes \U0001f631 nobody hit", True),
        ("cut right in front \U0001f633\U0001f6f4 then braked", True),
        ("a lady with a pram \U0001f6bc crossed from the left", False),
        ("the bus \U0001f68c pulled out", False),
    ],
    ids=["face", "face-and-thing", "thing", "vehicle"],
)
def test_only_an_emoji_of_a_feeling_ends_a_clause(text, broken):
    from vei_scenario.language.scene import only_the_scene

    assert ("," in only_the_scene(text, lambda part: True)[0]) is broken
