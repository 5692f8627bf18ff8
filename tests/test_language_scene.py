"""Which parts of a text describe the scene: quiz options, questions to the reader, reported questions,
counterfactuals, thread numbering and hashtags give no road user, behaviour, speed or outcome, and
their words are reported as not used; a question or a list that is the scene is still read."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read

SCENE = "I am doing 40 km/h on a straight road in the rain and a van cuts in ahead of me."


def _what(text: str):
    r = read(text)
    actors = [(a.kind, [b[0] for b in a.behaviours], a.relation, a.speed_mps, a.distance_m) for a in r.actors]
    return actors, r.ego_speed_mps, r.intent, r.weather, r.map_kind, r.time, r.density, r.lanes


@pytest.mark.parametrize(
    "wrapped, unused",
    [
        (
            SCENE + " What is the safest response?\nA) Overtake the lorry at 60 mph\nB) Brake gently\nC) Stop dead",
            "lorry",
        ),
        (SCENE + " How should the driver react? (a) Swerve past the bus (b) Ease off (c) Sound the horn", "bus"),
        (SCENE + " Which answer is right?\n1. A cyclist crosses in front\n2. Hold back and let it settle", "cyclist"),
        (SCENE + " Best course of action? A. Follow the tram closely  B. Drop back  C. Flash the lights", "tram"),
    ],
    ids=["letters", "bracketed-letters", "numbers", "inline"],
)
def test_the_answer_options_of_a_question_are_not_the_scene(wrapped, unused):
    assert _what(wrapped) == _what(SCENE)
    assert unused in read(wrapped).ignored


@pytest.mark.parametrize(
    "aside",
    [
        "Who is to blame here?",
        "Any advice??",
        "Am I overreacting?",
        "My neighbour asked whether lorries should be banned from that stretch.",
        "The club wondered if buses could use the bypass instead.",
        "If I'd left five minutes later, the whole thing would never have happened.",
        "If the lorry had been parked there, that would be a different story.",
        "My sister reckons I should've taken the bus.",
        "#VanLife #crash",
    ],
)
def test_what_is_said_about_the_scene_is_not_the_scene(aside):
    for text in (SCENE + " " + aside, aside + " " + SCENE):
        assert _what(text) == _what(SCENE), text
    assert set(read(SCENE + " " + aside).ignored) & {w.strip("#?.,").lower() for w in aside.split()}


def test_thread_numbering_gives_no_number():
    thread = "1/ Doing 40 km/h on a straight road in the rain.\n2/ A van cuts in ahead of me.\n3/ Scary stuff."
    assert _what(thread)[:2] == _what(SCENE)[:2]


@pytest.mark.parametrize(
    "text, kind, behaviour",
    [
        ("Can you build a scenario where a cyclist cuts in ahead of the ego at 30 km/h?", "bicycle", "cut_in"),
        ("What happens if a scooter runs the red at a crossroads?", "e-scooter", "run_red_light"),
        ("Scenario: A) ego at 50 km/h on a straight road, B) a van cuts in from the left.", "van", "cut_in"),
        (
            "Could we get a test where a pedestrian crosses in front of the ego from the right kerb?",
            "pedestrian",
            "cross_in_front",
        ),
    ],
    ids=["request-question", "what-if", "spec-list", "could-we"],
)
def test_a_question_or_list_that_is_the_scene_is_read(text, kind, behaviour):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert behaviour in [b[0] for b in r.actors[0].behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "Can you make a scenario where the ego drives at 50 km/h? A cyclist crosses in front of it from the right.",
        "Could the ego be doing 30 mph on a wet night? A van pulls out in front of it.",
        "What if I'm going 40 km/h? Then a bus brakes hard ahead of me.",
    ],
)
def test_a_question_that_states_the_ego_or_a_number_is_the_scene(text):
    assert read(text).ego_speed_mps is not None


def test_a_denied_counterfactual_still_says_what_happened():
    """Saying "If I hadn't braked, ..." says the narrator braked: the sentence stays and its outcome is read."""
    text = "A cyclist pulls out in front of me at 30 km/h. If I hadn't braked, I would have hit him."
    assert read(text).intent == "near_miss"


@pytest.mark.parametrize(
    "record",
    [
        "Minutes of the Parish Roads Group, Monday 4 March, 7.15pm.\nPresent: Cllrs Moss, Reyes.\n"
        "Apologies: Cllr Tan.\nThe minutes of the previous meeting were approved.\n" + SCENE + "\n"
        "RESOLVED that the bus operator be written to.",
        "Dear Highways Team,\n" + SCENE + "\nYours sincerely,\nJo Hart, who drives a lorry past there daily",
        "Dear Sir,\n\n" + SCENE + "\n\nBest regards,\nSam, cyclist and van owner",
    ],
    ids=["minutes", "letter", "letter-blank-lines"],
)
def test_the_frame_of_a_record_or_a_letter_is_not_the_scene(record):
    assert _what(record) == _what(SCENE)


@pytest.mark.parametrize(
    "text, kind, behaviour",
    [
        ("Actor: a van. Action: cuts in ahead of the ego at 40 km/h.", "van", "cut_in"),
        (
            "Dear colleagues, please build a test in which a cyclist crosses in front of the ego.",
            "bicycle",
            "cross_in_front",
        ),
        (
            "Present in the scene: a pedestrian who crosses in front of the ego from the left kerb.",
            "pedestrian",
            "cross_in_front",
        ),
    ],
    ids=["action-label", "salutation-in-the-request", "present-in-the-scene"],
)
def test_labels_that_look_like_a_record_are_still_read(text, kind, behaviour):
    r = read(text)
    assert [a.kind for a in r.actors] == [kind]
    assert behaviour in [b[0] for b in r.actors[0].behaviours]
