"""The cut-out as a pair on the reading: a lead vehicle that moves out of the lane, and a road user that
stands in the lane it leaves. The lead may first be said to go along (followed by the ego), may carry
the standstill said of what it reveals, and may be placed by the lane it moves into; what stands may be
placed by the side of the lane it stands in. Wordings written for the class in several registers (a
test spec, a dashcam post, a claim note, a driver's text, a fleet report), none taken from a corpus;
near misses that look alike stay lane changes."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _behaviours(text: str) -> list[tuple[str, str | None, list[str]]]:
    """(kind, relation, behaviour names) of each road user read from ``text``."""
    return [(a.kind, a.relation, [b[0] for b in a.behaviours]) for a in read(text).actors]


@pytest.mark.parametrize(
    "text",
    [
        # the lead first said to be followed, then swerving ("follows ..., then changes lane")
        "The EV follows a lead vehicle at 60 km/h. The lead vehicle abruptly changes into the left lane,"
        " revealing a stationary van in the EV's lane.",
        "A lead car is followed by the test vehicle at 70 km/h; the lead car moves into the left lane,"
        " revealing a stationary truck in the test vehicle's lane.",
        # the standstill of what is revealed read onto the lead
        "Lead vehicle swerves into the adjacent lane at TTC 2 s to a stationary object in ego lane (a dropped"
        " pallet). Ego at 110 km/h.",
        # what stands placed by the side of its lane: the lane the followed lead leaves
        "Following a Prius at 50mph in the left lane, he suddenly swerves out into the right lane and there's"
        " a broken-down car in the left lane. Had about 20 metres to stop.",
        "I was following a minibus in the right lane doing 70 mph, it darted out into the left lane and a"
        " cyclist had stopped in the right lane with a puncture.",
        "Following a van in lane 2, the van moved into lane 1, and a car was broken down in lane 2.",
    ],
)
def test_a_lead_that_moves_out_round_what_stands_is_a_cut_out(text):
    read_as = _behaviours(text)
    leads = [r for r in read_as if r[2][:1] == ["cut_out"]]
    assert len(leads) == 1, read_as
    assert leads[0][1] == "ahead"
    assert "stop" not in leads[0][2] and "sudden_stop" not in leads[0][2]  # (the stop said is the ego's)
    assert [r for r in read_as if r[2] == ["stop"] and r[1] == "ahead"], read_as


def test_what_alone_stands_is_the_obstacle_whatever_else_it_is_read_to_do():
    """Only a road user that stands beside another that stands is set aside for moving out."""
    reading = read("Lorry in front changed lane late because a stalled car stands in the lane, I see it 30 m before.")
    assert [a.behaviours[0][0] for a in reading.actors][:1] == ["cut_out"]
    assert reading.actors[0].obstacle == 1


def test_the_lead_keeps_no_standstill_of_what_it_reveals():
    reading = read(
        "Lead vehicle swerves into the adjacent lane at TTC 2 s to a stationary object in ego lane. Ego at 110 km/h."
    )
    lead = next(a for a in reading.actors if a.behaviours[0][0] == "cut_out")
    assert lead.speed_mps != 0.0


@pytest.mark.parametrize(
    "text",
    [
        # nothing stands: a lane change
        "The car ahead changed lanes to the left.",
        "I was following a lorry at 60 mph. It changed lanes to the right and carried on.",
        # what stands is in the lane the lead moves into, not in the ego's
        "Following a lorry at 50 mph, it moved into the left lane; a car had stopped in the left lane.",
        "I was following a bus when it pulled into the right lane, where a taxi was stopped in the right lane.",
        # into a lane said by number: which side it leaves is not read, so what stands may be in the new one
        "Following a van at 50 mph, it moved over into lane 1, and a car had stopped in lane 1.",
        "Following a van in lane 2, it moved into lane 1, where a car was broken down in lane 1.",
        # a vehicle beside the ego that is not followed may leave a lane that is not the ego's
        "A car in the left lane was stopped. The car ahead of me changed lanes.",
    ],
)
def test_a_lane_change_with_nothing_revealed_in_the_egos_lane_stays_one(text):
    assert not [r for r in _behaviours(text) if "cut_out" in r[2]], _behaviours(text)
