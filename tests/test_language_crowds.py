"""People named as a crowd set the scene and are no road user: a plural person noun that nothing
counts, that only is there, goes along or stands, beside a road user that acts. And a group named in
one phrase ("two joggers") keeps all its members when the phrase's verb is handed to the first alone.
Wordings written for the class in several registers (a parent's post, a driver's story, a market-day
note, a seaside voice note, a commuter's complaint); near misses that look alike keep their walkers."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "People were walking home from the match when a car ran the red light from the right as I went"
            " through at 30.",
            ["car"],
        ),
        (
            "The pavements were full of shoppers. An e-scooter came off the kerb on the left right in front of me.",
            ["e-scooter"],
        ),
        (
            "Market day, crowds of pedestrians on both pavements, when a van pulled out of a loading bay on"
            " the left into my path at 20 km/h.",
            ["van"],
        ),
        (
            "Students were queuing at the bus stop as I drove past at 25 mph; a cyclist undertook me on the"
            " left and cut in.",
            ["bicycle"],
        ),
        (
            "Folks were strolling along the prom in the sun and this lad on a bike shot out of a side street"
            " on my right.",
            ["bicycle"],
        ),
    ],
)
def test_a_crowd_that_only_is_there_is_no_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # alone, the crowd is what the description is about
        (
            "Kids were walking along the road in the dark towards me as I came round the bend at 30 mph.",
            ["pedestrian"],
        ),
        # counted: told apart, each a road user
        (
            "Two kids were walking along the road when a car overtook me on the right.",
            ["pedestrian", "pedestrian", "car"],
        ),
        # a crowd that crosses in front of the ego acts
        (
            "The children crossed the road in front of me at the zebra while a cyclist waited on my left.",
            ["pedestrian", "bicycle"],
        ),
        (
            "There were people crossing in front of me at the lights when a scooter ran the red from the left.",
            ["pedestrian", "e-scooter"],
        ),
        # beside a vehicle that only stands there (parked), the crowd is all that acts
        (
            "Kids were walking along the road towards me past a parked van.",
            ["pedestrian", "van"],
        ),
        # one walker, not a crowd
        (
            "A jogger was running along the road when a van pulled out of a side road on my left.",
            ["pedestrian", "van"],
        ),
    ],
)
def test_a_crowd_that_acts_is_alone_or_is_counted_stays(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "I came round the bend to find two joggers in the road running towards me.",
        "Round the corner there were two cyclists in the middle of the lane riding at us.",
        "Came over the brow to find two horse riders in the lane ahead, walking towards the car.",
    ],
)
def test_a_group_named_in_one_phrase_keeps_all_its_members(text):
    r = read(text)
    assert len(r.actors) == 2
    first, second = r.actors
    assert (first.kind, first.relation, [b[0] for b in first.behaviours]) == (
        second.kind,
        second.relation,
        [b[0] for b in second.behaviours],
    )
