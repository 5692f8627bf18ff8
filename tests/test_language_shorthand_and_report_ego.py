"""Shortened words of notes, a note's one-word verdict, and the vehicle a third-person report is about
(in apposition to its label, named twice in brackets, or threatened by another vehicle); a person
crossing after "struck a pedestrian crossing ..."."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import _tokens, read


def _read(text: str) -> list[tuple[str, str | None, list[str]]]:
    return [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in read(text).actors]


@pytest.mark.parametrize(
    ("said", "read_as"),
    [("e-scoot", "e-scooter"), ("e-scoots", "e-scooters"), ("oncmg", "oncoming"), ("rdbt", "roundabout")],
)
def test_a_shortened_noun_is_read_as_the_word_it_shortens(said, read_as):
    assert read_as in _tokens(f"the {said} was there")


def test_shortened_road_users_and_places_are_read_in_a_note():
    assert _read("oncmg e-scoot turns across ego path into side rd, ego @40") == [
        ("e-scooter", "junction_opposite", ["turn_across"])
    ]
    assert read("rdbt, ego circulating at 30, a cyclist enters from the right").map_kind == "roundabout"


@pytest.mark.parametrize(
    "text",
    [
        "Another car passes us on the left and pulls back in smoothly.",  # ("passes": no "passe"-s)
        "He had passed his test four months earlier and a car came round the bend.",  # ("four": a word)
        "Hazardous event: insufficient decel, a van cuts in at 8 m.",  # (a verb's noun: no act)
        "The ACC and the LKA were on when a van cut in.",  # (capitals: acronyms)
        "The cyc path ends here, a van cut in.",  # (three letters: too many other words)
    ],
)
def test_words_that_shorten_nothing_are_left_as_written(text):
    read_as = set(_tokens(text))
    assert not {"passersby", "four-way", "decelerate", "cyclist"} & read_as
    assert {"passes", "four", "decel", "acc", "cyc"} & read_as


def test_a_notes_one_word_verdict_ends_it_safe():
    text = "T-junction, ego at 45 kph. an e-scooter on the side road on the left stops and waits -> ego passes -> ok"
    assert read(text).intent == "safe"
    assert read("a cyclist waits at the line, ego passes, okay.").intent == "safe"


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("ok so the e-scooter crossed in front of me", None),  # (a discourse marker opens it)
        ("a cyclist pulled out, I hit him, he was ok", "collision"),  # (how the person was: unhurt)
        ("a cyclist pulled out, I hit him, ok.", "collision"),  # (the contact stands)
    ],
)
def test_ok_that_is_no_verdict_leaves_the_outcome(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text",
    [
        "Vehicle 1, a car travelling east, struck a pedestrian walking in the same direction. "
        "The driver said he was doing about 50 mph.",
        "Unit 1, a passenger car northbound in the left lane, struck a pedestrian walking in the same direction.",
    ],
)
def test_a_vehicle_said_in_apposition_to_a_reports_label_with_what_it_did_is_the_ego(text):
    assert _read(text) == [("pedestrian", "ahead", ["along_road"])]


def test_a_road_user_in_apposition_that_is_not_a_vehicle_stays():
    text = "Vehicle 1, a cyclist riding east, was struck by a car."
    assert [kind for kind, _, _ in _read(text)] != []
    assert "bicycle" in [kind for kind, _, _ in _read(text)]


def test_a_reports_vehicle_named_twice_in_brackets_is_the_ego():
    text = "Vehicle 1 (rigid HGV, skip lorry) turning left into Mill Lane struck a pedestrian crossing the road."
    reading = read(text)
    assert [a.kind for a in reading.actors] == ["pedestrian"] and reading.ego_route == "left"
    text = "Vehicle 1 (HGV, a cyclist) turning left struck a pedestrian."  # (someone else in the brackets)
    assert "bicycle" in [a.kind for a in read(text).actors]


def test_a_pedestrian_crossing_said_after_a_verb_of_hitting_is_a_person():
    assert _read("I turned right and struck a pedestrian crossing in the crosswalk.") == [
        ("pedestrian", "roadside_right", ["cross_in_front"])
    ]
    text = "I made a right turn on red and struck a pedestrian crossing Broadway on the walk signal."
    assert [kind for kind, _, _ in _read(text)] == ["pedestrian"]
    text = "There is a pedestrian crossing in front of the school and a cyclist rode across it."
    assert [kind for kind, _, _ in _read(text)] == ["bicycle"]  # (a place: no one crossing)


def test_the_vehicle_a_report_tells_another_vehicle_threatening_is_the_ego():
    text = (
        "A white van was observed following a car in lane 1 aggressively close, with both vehicles travelling at "
        "around 50 mph. The van then pulled out into lane 2, passed the car and cut back in immediately in front "
        "of it, forcing the car driver to brake."
    )
    reading = read(text)
    assert [(a.kind, a.relation) for a in reading.actors] == [("van", "behind")]
    assert reading.ego_speed_mps == pytest.approx(50 * 0.44704, abs=0.1)


@pytest.mark.parametrize(
    "text",
    [
        # (a narrator in the scene: the narrator's vehicle is the ego)
        "I saw a white van following a car closely. The van then passed the car and cut in front of it, "
        "forcing the car driver to brake.",
        # (the one passed then turns: not only what the ego does)
        "A van passed a car and cut in in front of it; the car then turned left into a side road.",
        # (the reader addressed is the ego)
        "Lesson notes – Chloe – lesson 14 (dual carriageways)\nJoining the A34 from the Botley slip. You built "
        "your speed up nicely to about 55 on the slip. The car in lane 1 (blue Qashqai) saw you and sped up rather "
        "than letting you in – annoying but it happens. You spotted it, eased off and merged in behind it rather "
        "than forcing it. Exactly right, nice and calm.\nThen lane discipline: you sat in lane 2 for too long "
        "after overtaking the lorry – back to lane 1 as soon as it's safe.\nWeather dry, traffic busy-ish.",
    ],
)
def test_a_threatened_vehicle_is_not_taken_for_the_ego_otherwise(text):
    kinds = [a.kind for a in read(text).actors]
    assert "car" in kinds and ("lorry" not in text or "truck" in kinds)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("Of 63 cyclist crossings observed, none resulted in a conflict. A car stopped for a cyclist.", None),
        ("We counted about 40 vehicles an hour. A car slowed and stopped for a cyclist.", None),
        ("I was doing about 40 miles an hour when a cyclist pulled out.", 64.4),  # (a unit, no count)
        ("we were at 30 when a cyclist pulled out", 30.0),
    ],
)
def test_a_bare_number_that_counts_a_plural_noun_is_no_speed(text, kph):
    speed = read(text).ego_speed_mps
    assert speed is None if kph is None else round(speed * 3.6, 1) == kph


def test_a_reports_vehicle_that_moves_out_to_pass_a_rider_is_the_ego():
    text = (
        "An e-scooter rider was riding along the kerbside lane. A B-double following moved fully into the right "
        "lane in good time and passed the rider at about 50 km/h with roughly 2 m clearance. No conflict."
    )
    reading = read(text)
    assert [a.kind for a in reading.actors] == ["e-scooter"]
    assert round(reading.ego_speed_mps * 3.6) == 50


def test_a_lane_change_with_no_pass_is_the_vehicles_own():
    text = "A car changed lanes and then braked hard in front of a van."
    assert "car" in [a.kind for a in read(text).actors]


def test_road_users_counted_by_a_survey_are_no_road_users():
    text = (
        "In the two-hour video survey, 212 vehicles turned in from Mortimer Road and no conflicts were recorded. "
        "A representative example: a car turning in slowed and gave way to an e-scooter rider crossing the side road."
    )
    assert [a.kind for a in read(text).actors] == ["e-scooter"]
    text = "Three cars turned in from Mortimer Road. A car gave way to an e-scooter rider crossing."
    assert len(read(text).actors) > 1  # (a few, told as road users: they stay)
