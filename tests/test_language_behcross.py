"""A walker or rider who passes across the ego's front is read as crossing its path.

A verb of passing with no object that goes on "across in front of" the ego ("the cyclist passed across
in front of the car"), "in front" of it with the ego left unsaid ("the scooter passed in front with a
metre to spare"), or "past the front" with no owner said ("he went past the front a metre off the
bumper") tells a road user going across where the ego is heading, not one overtaking it: an overtake
takes the one it passes as its object and goes along a side. The guards keep what already read: a
pass of the ego along a side, a pass of someone else, a vehicle that passes in front, and a pass in
front of something other than the ego."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _moves(text: str) -> list[tuple[str, list[str]]]:
    return [(a.kind, [b[0] for b in a.behaviours]) for a in read(text).actors]


CROSSES = [
    # across in front of the ego, the ego named as its vehicle
    ("I was turning left and braked as the cyclist passed across in front of the car.", "bicycle"),
    ("We slowed right down and a jogger passed across in front of our van.", "pedestrian"),
    # in front, the ego left unsaid
    ("I braked hard as the e-scooter passed in front with a metre to spare.", "e-scooter"),
    ("The bus braked hard; the scooter rider passed right in front with about a metre of clearance.", "e-scooter"),
    # past the front, no owner said
    ("A boy on a bike came out of a drive, I braked and he went past the front a metre off the bumper.", "bicycle"),
]


@pytest.mark.parametrize(("text", "kind"), CROSSES)
def test_a_walker_or_rider_passing_across_the_egos_front_crosses(text, kind):
    moves = _moves(text)
    rider = next(b for k, b in moves if k == kind)
    assert "cross_in_front" in rider
    assert "overtake" not in rider


GUARDS = [
    # a pass of the ego along its side
    ("A cyclist passed me on the right and rode on ahead.", "bicycle"),
    ("The scooter overtook us on the inside.", "e-scooter"),
    # a pass in front of another road user, not the ego
    ("A cyclist passed in front of the van ahead of me.", "bicycle"),
    ("The cyclist passed across in front of the lorry.", "bicycle"),
]


@pytest.mark.parametrize(("text", "kind"), GUARDS)
def test_a_pass_along_a_side_or_in_front_of_another_keeps_its_reading(text, kind):
    moves = _moves(text)
    rider = next(b for k, b in moves if k == kind)
    assert rider == ["overtake"]


def test_a_vehicle_passing_in_front_with_the_ego_unsaid_keeps_its_reading():
    assert _moves("A van passed in front and carried on.") == [("van", ["overtake"])]


def test_a_vehicle_going_by_in_front_of_a_stopped_ego_still_goes_on():
    assert _moves("We stopped at the lights and a van passed in front of us.") == [("van", ["keep_going"])]
