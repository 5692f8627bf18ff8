"""A road user coming into the road from its side and across or into the ego's path: the class of
its move and where it starts. Wordings written for each construction, none taken from a corpus; each
group has near misses that look alike and must not be read so."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _one(text: str):
    (actor,) = read(text).actors
    return actor


def _names(text: str) -> list[str]:
    return [b[0] for b in _one(text).behaviours]


# "VERB the red (light)": any verb with the red as its object runs it (the verb says only how).
@pytest.mark.parametrize(
    "text",
    [
        "Doing 30 mph through town when a courier on a scooter shot the red at the crossroads in front of me.",
        "We were at 40 km/h and a taxi blasted the red light at the next junction, right across our bows.",
        "At the lights on Park Lane a cyclist barrelled the red as I drove through at 25 mph and I nearly hit him.",
    ],
)
def test_a_verb_with_the_red_as_its_object_runs_it(text):
    actor = _one(text)
    assert actor.behaviours[0][0] == "run_red_light"
    assert actor.relation.startswith("junction_")


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30 mph when a van overtook the red car ahead of me and cut in.",
        "A cyclist waited at the red while I drove through at 25 mph.",
    ],
)
def test_the_red_as_a_colour_or_a_place_to_wait_is_no_run(text):
    assert "run_red_light" not in [b[0] for a in read(text).actors for b in a.behaviours]


# "have/get + a road user + a bare verb": the road user does the verb, not the one who "had" it.
@pytest.mark.parametrize(
    ("text", "expected", "relation"),
    [
        (
            "We had a van pull out of a side street on the left right in front of us at the crossroads.",
            "turn_into",
            "junction_left",
        ),
        (
            "I had a lad on a bike roll off the kerb on the right into my path at 20 mph.",
            "cross_in_front",
            "roadside_right",
        ),
        (
            "At 15 mph I had a cyclist come out of a driveway on the left just in front of me.",
            "cut_in",
            "roadside_left",
        ),
    ],
)
def test_a_road_user_had_doing_something_does_it(text, expected, relation):
    actor = _one(text)
    assert actor.behaviours[0][0] == expected
    assert actor.relation == relation


def test_having_a_road_user_with_no_verb_after_it_is_no_act_of_its():
    reading = read("I had a cyclist ahead of me at 20 km/h and I overtook him at 40 km/h.")
    (actor,) = reading.actors
    assert actor.behaviours[0][0] in ("along_road", "keep_going", "keep_lane")
