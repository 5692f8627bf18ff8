"""The bicycle or e-scooter the narrator rides is the ego's own, no road user (narrator_ride.py)."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph, kinds

#: Writers who ride: a hire scheme's complaint, a review, a voice note, a diary, a forum post.
RIDDEN = [
    "Complaint re e-scooter 2290. I was riding it at 15 km/h on Park Road when a woman walked out in front of me.",
    "I was on one of your bikes doing about 12 mph when a jogger ran across in front of me.",
    "Grabbed a Lime outside the office, and a kid ran into the road in front of me near the school.",
    "We were on rented e-scooters when a pedestrian stepped off the kerb right in front of us.",
    "I took a hire bike along the canal path and a man with a dog walked out in front of me.",
    "Unlocked a scooter at the station. Halfway home a guy stepped out right in front of me.",
    "I was on the scooter at 20 km/h when an old man crossed in front of me without looking.",
    "Writing about the bike I had yesterday. I was riding it at 10 mph when a lady walked out in front of me.",
    "I was on a hire bike doing 20 km/h when a boy stepped off the kerb on my right.",
    "I was on an electric scooter doing 20 km/h and a man stepped out in front of me.",
    "I was cycling to college when a girl walked out in front of me. I came off the bike and cut my knee.",
    "On my moped at 30 mph a man stepped out in front of me. Scratched the bike and my leg.",
    "We were riding home at dusk and a jogger ran across in front of us; I dropped the scooter.",
]


@pytest.mark.parametrize("text", RIDDEN)
def test_the_narrators_ride_is_no_road_user(text: str) -> None:
    assert kinds(text) == ["pedestrian"]


def test_the_speed_said_of_the_ride_is_the_egos() -> None:
    text = "I was on one of your e-scooters doing 18 km/h when a man stepped out in front of me."
    assert ego_kph(text) == 18.0


#: Near misses: someone else on a bicycle or e-scooter, or one the narrator only sees.
SOMEONE_ELSES = [
    "A lad on an e-scooter came past me on the left and cut in front of me.",
    "I saw a cyclist on a hire bike run the red light in front of me.",
    "I was driving at 30 mph when a kid on a scooter shot out in front of me.",
    "On a scooter, a teenager rode out of the alley in front of me.",
    "I nearly took a cyclist out at the roundabout when he undertook me.",
    "I was on my way home when a boy on a bike rode out of a driveway in front of me.",
    "I was walking home when the bike hit me from behind.",
    "I was cycling behind a lad when he came off the bike in front of me.",
]


@pytest.mark.parametrize("text", SOMEONE_ELSES)
def test_someone_elses_ride_stays(text: str) -> None:
    assert any(k in ("bicycle", "e-scooter") for k in kinds(text))
