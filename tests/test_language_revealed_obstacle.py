"""A lead vehicle that moves out of the ego's lane and so shows something lying in it: a cut-out, with
what lies there as its obstacle, however the thing and its lying there are said."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _lead(text: str):
    """The reading's first road user that moves (the lead), and the reading."""
    r = read(text)
    movers = [a for a in r.actors if any(b[0] not in ("stop", "keep_going") for b in a.behaviours)]
    return (movers[0] if movers else r.actors[0]), r


@pytest.mark.parametrize(
    "text",
    [
        # a British motorway report: a thing "lying across" the lane
        "I was following a lorry on the motorway at 60 mph when it pulled out into lane two and there was a sofa "
        "lying across lane one.",
        # a dashcam caption: "revealing" what lay there
        "Two lanes each way, 50 mph. The pickup in front of me darted into the right lane, revealing a spare "
        "tyre in my lane.",
        # a test spec with the thing named in brackets
        "Ego follows a bus at 40 km/h on a road with two lanes per direction; the bus changes to the left lane "
        "and a static obstacle (a fallen tree) is in the ego lane.",
        # an Australian text: "sitting in my lane"
        "doing 100 behind a ute on the highway, two lanes, he swung out to the right and theres a roadworks "
        "barrier sitting in my lane",
        # a learner's English: the thing "fallen from" a lorry after it
        "Highway 3 lanes, I was in 2nd lane at 90 km/h following a SUV. Suddenly the SUV changed to 3rd lane "
        "and there were bricks fallen from some truck in my lane.",
        # an Indian English voice note: "exposing" what lay there
        "Sir I was going behind one lorry at 60 on the expressway, two lanes, the lorry suddenly shifted to the "
        "right lane exposing a wooden crate on the road.",
        # a Singaporean forum post: two things said together
        "Following one lorry at 70 on the expressway, two lanes, then the lorry suddenly changed lanes and got "
        "a line of cones and a roadworks barrier in my lane, almost kena.",
    ],
)
def test_a_lead_moving_out_to_show_a_thing_lying_in_the_lane_is_a_cut_out(text):
    lead, r = _lead(text)
    assert lead.behaviours[0][0] == "cut_out", [(a.kind, a.behaviours) for a in r.actors]
    assert lead.obstacle is not None


@pytest.mark.parametrize(
    "text",
    [
        # nothing lies in the lane: a lane change
        "Two lanes each way, 50 mph. The pickup in front of me moved into the right lane and I carried on.",
        # a load carried on the lead's own trailer lies in no lane
        "Two lanes each way, 50 mph. A lorry with a load of bricks on its trailer ahead of me moved into the "
        "right lane.",
    ],
)
def test_a_lead_moving_out_with_nothing_lying_in_the_lane_is_a_lane_change(text):
    lead, r = _lead(text)
    assert lead.behaviours[0][0] == "change_lane", [(a.kind, a.behaviours) for a in r.actors]


def test_a_road_user_shown_by_the_lead_stays_a_road_user():
    r = read("Two lanes each way, 50 mph. The van ahead moved into the right lane, revealing a cyclist in my lane.")
    assert "bicycle" in [a.kind for a in r.actors]


def test_a_thing_by_the_road_is_no_obstacle():
    r = read("A tree on the left and a sign on the right; a van ahead moves into the right lane at 50 mph.")
    assert [a.kind for a in r.actors] == ["van"]


@pytest.mark.parametrize(
    "text",
    [
        "I was at 90 km/h following a SUV. Suddenly the SUV changed to lane 3.",
        "Following a bus at 40 km/h, the bus changes over to the right lane.",
        "Behind a taxi at 50 km/h when the taxi changed into the left lane.",
        "Following a van at 60 km/h, the van is changing to the 2nd lane.",
    ],
)
def test_changing_to_a_lane_named_is_a_lane_change(text):
    assert [b[0] for b in read(text).actors[0].behaviours] == ["change_lane"]


def test_a_light_changing_to_a_colour_is_no_lane_change():
    r = read("The light changed to red and a van ahead of me stopped.")
    assert [b[0] for b in r.actors[0].behaviours] == ["stop"]


def test_no_signs_on_the_road_is_no_obstacle():
    r = read("There were no signs on the road and a van ahead braked hard.")
    assert [a.kind for a in r.actors] == ["van"]
