"""Review findings 6, 7, 8, 11, 12 and 15 on the passing-in-front rules (motion.passing_in_front).

A walker or rider that "passed in front" with the ego unsaid crosses the ego's path, unless that very
road user was said to come from behind the ego (then it overtakes), it went on to end up ahead in the
ego's lane (a pass and pull-in), or it also passed the ego in the same run of words. "Past the front"
with no owner is the ego's front unless an owner is said after a coordination."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _moves(text: str) -> list[tuple[str, list[str]]]:
    return [(a.kind, [b[0] for b in a.behaviours]) for a in read(text).actors]


def _rider(text: str, kind: str = "bicycle") -> list[str]:
    return next(b for k, b in _moves(text) if k == kind)


# 6: "behind" is the ego's only when no one else's behind is said, and it holds of that one road user.
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came out from behind a parked lorry and passed in front with a metre to spare.",
        "A jogger stepped out from behind a parked van and passed in front with a metre to spare.",
        "A cyclist came up from behind me on the hill and rode off. Much later, on the long way home through"
        " the town centre after work, a different cyclist passed in front with a metre to spare.",
        "A cyclist came up from behind me and rode off. Later another cyclist passed in front with a metre to spare.",
    ],
)
def test_behind_someone_else_or_another_rider_from_behind_still_crosses(text):
    kind = "pedestrian" if "jogger" in text else "bicycle"
    assert any("cross_in_front" in moves for k, moves in _moves(text) if k == kind)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came up from behind me and passed in front with a metre to spare.",
        "A cyclist came up from behind me. The cyclist passed in front with a metre to spare.",
        "A cyclist came up from behind me. He passed in front with a metre to spare.",
    ],
)
def test_the_one_from_behind_the_ego_still_overtakes(text):
    rider = _rider(text)
    assert "overtake" in rider and "cross_in_front" not in rider


# 7: a pronoun subject is the walker or rider named before it.
@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A cyclist came out of a driveway. He passed in front with a metre to spare.", "bicycle"),
        ("A cyclist was waiting behind the bus shelter. He passed in front with a metre to spare.", "bicycle"),
        ("A woman was standing at the kerb. She passed in front with a metre to spare.", "pedestrian"),
    ],
)
def test_a_pronoun_for_a_walker_or_rider_crosses(text, kind):
    rider = _rider(text, kind)
    assert "cross_in_front" in rider and "overtake" not in rider


def test_a_pronoun_for_a_vehicle_keeps_its_reading():
    assert "cross_in_front" not in _rider("A van came out of a driveway. It passed in front and carried on.", "van")


# 8: another pass blocks the rule only when it is said of the same road user.
@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A cyclist passed in front of us. Then another cyclist passed in front with a metre to spare.", "bicycle"),
        ("A jogger passed in front of us, then a cyclist passed in front with a metre to spare.", "bicycle"),
        ("A pedestrian passed in front and a car passed behind.", "pedestrian"),
    ],
)
def test_a_pass_by_someone_else_nearby_does_not_block_the_crossing(text, kind):
    assert (kind, ["cross_in_front"]) in _moves(text)


def test_an_overtake_of_the_ego_by_the_same_rider_still_blocks():
    assert "cross_in_front" not in _rider("A cyclist overtook me and passed in front with a metre to spare.")


# 11: an owner said after a coordination is the front's owner.
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist went past the front and then the back of the parked bus.",
        "A jogger ran past the front and the side of the parked van.",
    ],
)
def test_past_the_front_with_an_owner_after_a_coordination_is_not_the_egos(text):
    kind = "pedestrian" if "jogger" in text else "bicycle"
    assert "cross_in_front" not in _rider(text, kind)


def test_past_the_front_with_no_owner_still_crosses():
    text = "A boy on a bike came out of a drive, I braked and he went past the front a metre off the bumper."
    assert "cross_in_front" in _rider(text)


# 12: a rider that ends up ahead in the ego's lane passed and pulled in.
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist passed in front and rode off ahead of me in my lane.",
        "A cyclist passed in front and carried on ahead of us.",
        "The e-scooter passed in front, then stayed in my lane.",
    ],
)
def test_a_rider_ending_ahead_in_the_egos_lane_does_not_cross(text):
    kind = "e-scooter" if "scooter" in text else "bicycle"
    assert "cross_in_front" not in _rider(text, kind)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist passed in front and rode off.",
        "A cyclist passed in front and went into the other lane.",
        "I braked hard as the e-scooter passed in front with a metre to spare.",
    ],
)
def test_a_rider_going_on_elsewhere_still_crosses(text):
    kind = "e-scooter" if "scooter" in text else "bicycle"
    assert "cross_in_front" in _rider(text, kind)


# 15: both rules take the same walker or rider.
def test_the_ego_walking_past_the_front_of_a_bus_keeps_its_reading():
    assert _moves("I walked past the front of the bus.") == [("truck", ["keep_going"])]
