"""A first line over a body is folded into the body's road user only where it restates it (heading,
through heading_named.told_apart): a first line that tells its own road user, parked, waiting, in
another place or doing its own act, keeps it, as chat lines written without full stops do. Wordings
written for the rule; the near misses are headings that restate the body's road user."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (  # (parked, and the body's one comes the other way)
            "van parked on the left with hazards on\na van came the other way and I had to squeeze between them",
            ["van", "van"],
        ),
        (  # (ahead of the ego, and the body's one comes from the lane beside)
            "there was a lorry ahead of me braking hard\nthen a lorry from the left lane cut in front of me and"
            " I had to brake too",
            ["truck", "truck"],
        ),
        (  # (waiting on one side, and the body's one runs out from the other)
            "a pedestrian waiting at the zebra on the right\nas I slowed a pedestrian ran out from the left"
            " without looking",
            ["pedestrian", "pedestrian"],
        ),
        (
            "car parked on the right with its door open\na car came towards me and I had to stop",
            ["car", "car"],
        ),
        (
            "a cyclist waiting at the lights on the right\nthen a cyclist came from the left and rode across"
            " in front of me",
            ["bicycle", "bicycle"],
        ),
    ],
)
def test_a_first_line_that_tells_its_own_road_user_keeps_it(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "cyclist pulled out of a driveway on the right\na cyclist came out of a driveway on the right in"
            " front of me and I braked hard",
            ["bicycle"],
        ),
        (
            "lorry cutting in on the motorway\nI was doing 110 in lane two when a lorry from lane one cut in"
            " front of me and I had to brake",
            ["truck"],
        ),
        (  # (the heading tells one of the body's acts: a summary of it)
            "Cyclist crossing from a side street, AEB late\n\nEgo at 40 km/h. A cyclist rides out of the side"
            " street on the right without stopping and crosses in front of us. AEB brakes hard 1 m short.",
            ["bicycle"],
        ),
        (
            "Child runs out from the left, ego brakes\n\nWe drive at 30 km/h along a residential street. A child"
            " runs out from the left and crosses in front of us.",
            ["pedestrian"],
        ),
    ],
)
def test_a_heading_that_restates_the_bodys_road_user_is_folded(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected
