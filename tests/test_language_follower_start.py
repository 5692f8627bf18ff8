"""A road user said right behind another one, or to follow it, starts where that one starts: out of the
same side road, driveway or kerb, doing what it does there. Wordings written for the class in several
registers (a test spec, a driver's text, a police note, an insurance claim, a voice note), none taken
from a corpus; near misses where the follower is placed by itself, or follows the ego, keep their
reading."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _starts(text: str) -> list[tuple[str, str | None, str | None]]:
    """(kind, start, first act) of each road user read from ``text``."""
    return [(a.kind, a.relation, a.behaviours[0][0] if a.behaviours else None) for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "start", "act"),
    [
        (
            "Ego at 50 km/h. A car pulls out of a side street on the right 30 m ahead and an e-scooter rider"
            " follows it out of the street.",
            "junction_right",
            "turn_into",
        ),
        (
            "A van pulled out of a side road on the left and a cyclist followed it out. I was doing 40 km/h.",
            "junction_left",
            "turn_into",
        ),
        (
            "A car came out of the junction on my right with a scooter right behind it. I was doing 30 km/h.",
            "junction_right",
            "turn_into",
        ),
        (
            "Driver states vehicle 2 emerged from the minor road on his left at 20 mph, and a moped came out"
            " close behind it.",
            "junction_left",
            None,
        ),
        (
            "A lorry came out of a side road on my left, and a cyclist was following it. I was at 30 km/h.",
            "junction_left",
            "turn_into",
        ),
        (
            "so this car pulls out of a driveway on my right and a kid on a bike is right behind it, I was"
            " doing maybe 20 mph",
            "roadside_right",
            None,
        ),
        (
            "Test spec: an e-bike tailgates the delivery van that pulls out of the side street on the right;"
            " ego at 40 km/h.",
            "junction_right",
            None,
        ),
        (
            "A woman crossed from the left kerb with a little boy running behind her. I was doing 30 km/h.",
            "roadside_left",
            "cross_in_front",
        ),
    ],
)
def test_the_follower_starts_where_the_followed_one_does(text: str, start: str, act: str | None) -> None:
    first, follower = _starts(text)[:2]
    assert follower[1] == first[1] == start
    assert follower[2] == first[2]
    assert act is None or follower[2] == act


@pytest.mark.parametrize(
    ("text", "kind", "start"),
    [
        # behind the ego, not behind the one that came out
        ("A car pulled out of a side road on the left. A van behind us hooted. I was at 30 km/h.", "van", "behind"),
        # following the ego: behind it, whoever else comes out
        (
            "A car was following me and a van pulled out of a side road on the left. I was doing 30 km/h.",
            "car",
            "behind",
        ),
        # a side of its own: its own start
        (
            "A car pulled out of the side road on the left, and a cyclist behind it came from the right."
            " I was doing 30 km/h.",
            "bicycle",
            "junction_right",
        ),
    ],
)
def test_a_follower_placed_otherwise_keeps_its_start(text: str, kind: str, start: str) -> None:
    assert [s for k, s, _ in _starts(text) if k == kind] == [start]


def test_one_behind_a_car_on_the_egos_road_is_not_moved() -> None:
    """The one followed is ahead on the ego's own road: the follower is not taken out of a side road."""
    kinds_starts = _starts("I was doing 40 km/h behind a bus, and a cyclist was right behind it. The bus braked.")
    assert all(not (s or "").startswith(("junction", "roadside")) for _, s, _ in kinds_starts)
