"""A first-person writer who is in no motor vehicle of their own (who watches, reports, signs, is
told, is the parent of the one hit, or walks or rides) tells the story as a report with no narrator
would: the one motor vehicle that meets the walker or rider is the ego, not one more road user.
Wordings written for the class in several registers (a parent's post, a petition, a parish note, a
witness appeal, a text message, a council email), none taken from a corpus; near misses where the
writer is at a wheel of their own keep the other vehicle."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds

#: The writer is outside any vehicle: only the walker or rider is left.
OUTSIDE = [
    "My daughter was on her bike in the cycle lane when a car doing about 30 mph clipped her.",
    "We are told that a taxi travelling at 40 mph struck a boy who ran into the road.",
    "Our son, 12, ran out from behind a hedge and was hit by a van doing 25.",
    "We the undersigned note that a child crossing to the park was hit by a car travelling at 35 mph.",
    "I have been informed that a cyclist came off the kerb and a car doing around 30 mph clipped him.",
    "my lad was on his scooter on the high st and a car going like 40 hit him, hes ok",
]
#: The writer is at a wheel of their own: the other vehicle stays a road user.
AT_A_WHEEL = [
    "I was driving at 30 mph when a cyclist swerved out and a car doing 40 mph hit him.",
    "We were doing 50 when a walker stepped out and a van doing 40 mph struck him.",
    "A cyclist swerved out in front of me and a taxi doing 40 mph clipped him.",
    "My car was stopped at the lights when a cyclist was hit by a van travelling at 30 mph.",
]


@pytest.mark.parametrize("text", OUTSIDE)
def test_the_one_vehicle_of_a_writer_outside_is_the_ego(text: str) -> None:
    assert not any(k in ("car", "van", "truck") for k in kinds(text)), kinds(text)


@pytest.mark.parametrize("text", AT_A_WHEEL)
def test_a_writer_at_a_wheel_keeps_the_other_vehicle(text: str) -> None:
    assert any(k in ("car", "van", "truck") for k in kinds(text)), kinds(text)
