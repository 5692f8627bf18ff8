"""A road user coming the other way that passes the ego ("an oncoming car passed us") meets it in its
own lane, as one that "went by" does: no overtake, and no head-on ride in the ego's lane. Said by
several kinds of writer, with near misses that must keep their head-on or overtaking reading (one said
to be on the ego's side, one that passes another road user, one from behind)."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _behaviours(text: str) -> list[str]:
    actors = read(text).actors
    assert len(actors) == 1, text
    return [b[0] for b in actors[0].behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "An oncoming car stayed on its side of the road and passed us.",  # (a witness statement)
        "Doing 40 mph on the lane, a tractor coming the other way passed me slowly.",  # (a British text)
        "Test run 3: an oncoming van passes us at 50 km/h, no conflict.",  # (a test log)
        "Then one car from opposite side passed us, nothing happen.",  # (learner English)
        "A cyclist coming towards us passed me on the descent.",  # (a club newsletter)
    ],
)
def test_an_oncoming_road_user_that_passes_the_ego_meets_it_in_its_own_lane(text: str) -> None:
    got = _behaviours(text)
    assert "wrong_way" not in got and "overtake" not in got, got


@pytest.mark.parametrize(
    "text, expected",
    [
        # on the ego's side of the road: head-on, however it passed
        ("A van coming towards us on our side of the road passed me with inches to spare.", "wrong_way"),
        # from behind: an overtake of the ego
        ("A car from behind passed us at speed.", "overtake"),
    ],
)
def test_near_misses_keep_their_reading(text: str, expected: str) -> None:
    assert expected in _behaviours(text)
