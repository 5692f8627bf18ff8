"""A walker or rider coming onto the road off a place beside it that the lexicon has no word for (a
promenade, a shared path, a churchyard, a shop lot, a towpath) crosses from that roadside, as one coming
off "the pavement" does. Wordings written for the class in several registers and Englishes (a text
message, a voice note, a police line, a test spec, a Singaporean and an Indian review), none taken
from a corpus; near misses that look alike keep what they say. Also: a rider named with a word
before "rider" ("a Voi rider", "a delivery rider") is a rider; "RH kerb", "L/H footway", "N/S lane"
are a side said short."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds
from vei_scenario.language import off_a_place
from vei_scenario.language.normalise import normalise
from vei_scenario.language.reader import FUNCTION_WORDS, read, scan


def _crosser(text: str):
    """The one walker or rider read from ``text``."""
    users = [a for a in read(text).actors if a.kind in ("pedestrian", "bicycle", "e-scooter")]
    assert len(users) == 1, [(a.kind, a.behaviours) for a in read(text).actors]
    return users[0]


@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("omg some guy on a scooter shot off the boardwalk right in front of me, i was doing 40", None),
        ("Driving at 30 mph when a jogger ran out of the car wash straight into my path.", None),
        ("The pedal cyclist rode off the towpath and across the carriageway in front of the police vehicle.", None),
        (
            "so this cyclist just like swings off the seafront path on my left and across the road in front of me",
            "left",
        ),
        ("Ego at 40 km/h. A pedestrian emerges from the hotel grounds on the right into the road 15 m ahead.", "right"),
        (
            "Very scary, one uncle with e-scooter come out from the food court in front of our car, driver brake.",
            None,
        ),
        ("A school boy on cycle came suddenly out of the temple premises into the road in front of our car.", None),
        ("We were doing 50 when a kid on a bike came flying off the village green and across in front of us.", None),
    ],
)
def test_off_a_place_nobody_named_crosses_from_that_roadside(text: str, side: str | None) -> None:
    user = _crosser(text)
    assert [b[0] for b in user.behaviours] == ["cross_in_front"]
    assert user.relation in (("roadside_" + side,) if side else ("roadside_left", "roadside_right"))


def _places(text: str) -> list[str]:
    """The noun phrases :func:`off_a_place.onto_the_road_off_a_place` reads as a kerb come off."""
    clauses, _, _, tokens = scan(text)
    before = {(m.start, m.slot) for _, ms in clauses for m in ms}
    after = off_a_place.onto_the_road_off_a_place(clauses, tokens, FUNCTION_WORDS)
    return [m.words for _, ms in after for m in ms if m.slot == "kerb" and (m.start, m.slot) not in before]


def test_the_place_is_read_as_a_kerb() -> None:
    assert _places("A cyclist shot off the promenade and across the road in front of us.") == ["the promenade"]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist was riding along the promenade ahead of me.",  # (along, no leaving)
        "A lad fell off his scooter right in front of me.",  # (a road user's vehicle)
        "A woman got off the bus and walked across in front of me.",  # (a vehicle)
        "A cyclist came off the roundabout in front of me.",  # (the road)
        "A cyclist came off the bridge and into my lane.",  # (a part of the road)
        "A kid jumped out of the back of a van into the road in front of me.",  # (a part of something else)
        "A cyclist came out of nowhere right in front of me.",  # (no place)
        "A family walking back from the beach waved at me.",  # (no coming onto the road)
        "A van came out of the car wash right in front of me.",  # (a vehicle joins the traffic: others read it)
        "A jogger from the running club crossed in front of me.",  # (no verb of leaving)
    ],
)
def test_near_misses_read_no_place(text: str) -> None:
    assert _places(text) == []


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30 when a Voi rider shot out in front of me.",
        "A delivery rider cut across in front of us at the lights.",
        "Last night a Deliveroo rider swerved into my lane.",
        "She had a Dott rider swing out in front of her.",
    ],
)
def test_a_word_before_rider_says_what_is_ridden(text: str) -> None:
    assert kinds(text) == ["e-scooter"]


def test_a_thing_had_is_no_road_user() -> None:
    assert kinds("Had a fright today, a cyclist came out of nowhere from the left.") == ["bicycle"]


@pytest.mark.parametrize(
    ("said", "full"),
    [
        ("from rh kerb", "right-hand kerb"),
        ("off the l/h footway", "off the left-hand footway"),
        ("in the o/s lane", "in the offside lane"),
        ("on the n/s verge", "on the nearside verge"),
        ("on the rhs", "on the right-hand side"),
    ],
)
def test_a_side_said_short(said: str, full: str) -> None:
    assert full in normalise(said)


def test_relative_humidity_is_no_side() -> None:
    assert "rh 88 %" in normalise("weather: rh 88 %, dry")


def test_rh_kerb_crossing() -> None:
    user = _crosser("Ego @ 50 km/h. E-scooter rider enters carriageway from RH kerb approx. 15 m ahead of ego.")
    assert (user.relation, [b[0] for b in user.behaviours]) == ("roadside_right", ["cross_in_front"])


@pytest.mark.parametrize(
    ("text", "first"),
    [
        ("A lad on a scooter came out of a farm track on the left and across in front of me.", "cross_in_front"),
        ("A boy on a bike came out of a driveway on the right, I stopped in time.", "cross_in_front"),
        ("A cyclist came out of a driveway on the right and rode along ahead of me.", "cut_in"),
    ],
)
def test_a_rider_out_of_a_place_crosses_unless_it_rides_on(text: str, first: str) -> None:
    assert _crosser(text).behaviours[0][0] == first


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 30 km/h. An e-scooter rider enters the crosswalk from the west curb against the signal.",
        "I was doing 20 mph when a jogger entered the zebra crossing from the right just ahead of me.",
        "A pedestrian entered the pelican crossing as I approached at 40 km/h.",
    ],
)
def test_entering_a_foot_crossing_is_crossing_on_it(text: str) -> None:
    assert [b[0] for b in _crosser(text).behaviours] == ["cross_in_front"]


def test_waiting_at_a_foot_crossing_is_no_entering() -> None:
    assert "cross_in_front" not in [b[0] for b in _crosser("A cyclist was waiting at the crosswalk.").behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist rode out of the village on the road ahead of us.",
        "A cyclist rode out of the quarry on the road ahead of us.",
        "A man on an e-scooter came off the towpath along the road ahead of us.",
    ],
)
def test_going_on_along_the_road_after_leaving_a_place_is_no_crossing(text):
    """Said to go on along the road first, the road user is already on it: "ahead of us" is where it
    rides, not a move across in front."""
    assert all(b[0] != "cross_in_front" for a in read(text).actors for b in a.behaviours)
