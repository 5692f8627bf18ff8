"""A road user coming towards the ego that is said to go back to its own side or lane ("swerved back
over", "pulled back in at the last second") was out of it: on the ego's side, head-on, a wrong-way
ride or drive that returns. Said by many kinds of writer, with near misses that must keep their own
reading: one that only comes the other way, one that goes back but never came towards the ego, a
walker stepping back."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _first(text: str) -> tuple[str, list[str], dict]:
    """The first road user's kind, its behaviours and its first behaviour's settings."""
    a = read(text).actors[0]
    return a.kind, [b[0] for b in a.behaviours], a.behaviours[0][1]


@pytest.mark.parametrize(
    "text",
    [
        # (a British text message)
        "doing 20 when a lad on an e-scooter came straight at me round the corner, swerved back at the last second",
        # (an American voice note)
        "I was going like 25 mph and this cyclist is coming right towards me, then he cuts back over. Scary.",
        # (a test spec)
        "Ego at 30 km/h. A cyclist approaches head-on at 15 km/h and steers back to its side with 1 s to go.",
        # (an Australian police log)
        "Driver travelling at 50 km/h. A motorcyclist came towards the vehicle and pulled back in at the last moment.",
        # (an Indian English report)
        "I was driving at 40 kmph, one bike was coming towards me and at the last moment he went back to his side.",
        # (a Nigerian English account)
        "I was driving at 40 km/h when a okada rider came towards my car and quickly swung back to his own side.",
    ],
)
def test_coming_at_the_ego_and_going_back_to_its_side_is_the_wrong_way(text):
    kind, names, cfg = _first(text)
    assert kind != "pedestrian"
    assert names[0] == "wrong_way"
    assert cfg.get("returns")


@pytest.mark.parametrize(
    "text, not_expected",
    [
        # coming the other way, no going back: it keeps to its own side
        ("I was doing 30 mph and a cyclist came towards me in the other lane.", "wrong_way"),
        # getting back up or on after a fall is no going back to its side
        (
            "I was doing 20 mph, a cyclist coming towards me hit a pothole, fell off and got straight back up.",
            "wrong_way",
        ),
        ("Doing 30 mph; an oncoming moped rider skidded, fell and got back on his bike.", "wrong_way"),
        # the return is the overtaker's, not the oncoming van's it meets
        ("Riding at 15 mph, a car behind me tried to overtake, met an oncoming lorry and had to pull back in.", None),
        # a walker stepping back is no ride against the traffic
        ("I was doing 30 mph when a man walked out, saw me and stepped back onto the kerb.", "wrong_way"),
    ],
)
def test_near_misses_keep_their_reading(text, not_expected):
    if not_expected is None:  # no road user goes the wrong way
        assert not any(b[0] == "wrong_way" for a in read(text).actors for b in a.behaviours)
        return
    _, names, _ = _first(text)
    assert not_expected not in names


@pytest.mark.parametrize(
    "text",
    [
        # (a radio call)
        "I'm at 20 mph, a kid on a scooter going the wrong way came head-on at me and swerved out at the last second.",
        # (a test spec)
        "Ego 30 km/h. Cyclist rides against the traffic towards the ego in its lane and swerves out at 10 m.",
        # (a British text)
        "cyclist coming the wrong way towards me in my lane, swerved out of my lane just in time. was doing 25",
        # (an Australian voice note)
        "A motorbike came the wrong way towards us in our lane and swerved out at the last moment. We were doing 40.",
    ],
)
def test_swerving_out_of_the_ego_lane_while_coming_head_on_is_the_wrong_way(text):
    _, names, _ = _first(text)
    assert names[0] == "wrong_way"


@pytest.mark.parametrize(
    "text",
    [
        # (a text message; the swerve is the narrator's)
        "e-bike came the wrong way round the corner, im doing 25, swerved and missed him",
        # (an American note)
        "Going 20 mph when a cyclist riding against traffic swerved into my lane.",
        # (a police log)
        "Vehicle at 40 km/h. A scooter rider travelling in the wrong direction veered across into the car's lane.",
    ],
)
def test_a_rider_going_the_wrong_way_that_swerves_comes_head_on(text):
    _, names, _ = _first(text)
    assert names[0] == "wrong_way"


@pytest.mark.parametrize(
    "text",
    [
        # riding the wrong way on the pavement, then off it into the road: a move across, not head-on
        "Doing 20 mph when a cyclist riding the wrong way along the pavement swerved into my lane.",
        # in a cycle lane of its own against the traffic, then into the ego's lane from beside it
        "At 30 km/h a cyclist in the contraflow cycle lane on my right swerved into my lane.",
    ],
)
def test_a_rider_the_wrong_way_off_a_path_of_its_own_is_no_head_on_ride(text):
    _, names, _ = _first(text)
    assert names[0] != "wrong_way"


def test_a_standstill_said_beside_a_wrong_way_road_user_is_not_its_speed() -> None:
    """One that comes at the ego moves: a stop said near it ("He stopped", the driver it met) is not
    its speed, which would leave it standing where it should come head-on."""
    [spec] = read(
        "A van came at me on my side of the road, overtaking a queue. He stopped; the van pulled back in."
    ).actors
    assert spec.behaviours[0][0] == "wrong_way"
    assert spec.speed_mps != 0.0
