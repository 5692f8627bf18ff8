"""Road users said in general are not road users of the event: "other" before a bare plural sets the
scene's road users against everyone else on the road; a counted or definite group stays."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _others(text: str) -> list[str]:
    return [a.kind for a in read(text).actors if a.kind != "ego"]


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("I was doing 30 mph when a van cut in front of me, so other cars had to brake too.", ["van"]),
        ("A scooter rider pulled out in front of me; like other motorists I braked hard.", ["e-scooter"]),
        ("A boy on a bike swerved into my lane and some other cyclists behind him had to stop.", ["bicycle"]),
        (
            "I came up behind a cyclist riding along the edge of the lane at 20 km/h, and I and other"
            " drivers had to pull out to get past.",
            ["bicycle"],
        ),
    ],
    ids=["so-other-cars", "like-other-motorists", "some-other-cyclists", "i-and-other-drivers"],
)
def test_other_before_a_bare_plural_is_people_in_general(text, kinds):
    assert _others(text) == kinds


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("Two other cyclists overtook me at 20 km/h.", ["bicycle", "bicycle"]),
        (
            "A jogger ran across in front of me while the other joggers waited at the kerb.",
            ["pedestrian", "pedestrian"],
        ),
        ("Other cyclists overtook me at 20 km/h.", ["bicycle"]),
    ],
    ids=["counted", "definite", "only-road-user"],
)
def test_counted_definite_or_only_other_plural_stays(text, kinds):
    assert _others(text) == kinds
