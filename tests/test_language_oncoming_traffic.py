"""Traffic coming the other way said in general: a bare plural of vehicles (no article, no count) that
comes the other way or is "oncoming" is the stream of traffic that keeps the ego where it is, scenery
of the road, no road user of the scene, where the text names another road user it is about. Said by
many kinds of writer (a voice note, a text, a police log, a driving instructor, a test spec), with
near misses that look alike and must keep their road user."""

from __future__ import annotations

import pytest

from tests.reading_of import kinds


@pytest.mark.parametrize(
    "text, expected",
    [
        # (an Australian voice note)
        (
            "Stuck behind a bloke on a scooter in the ute at 20 km/h, couldn't get round him cos there's cars "
            "coming the other way the whole time.",
            ["e-scooter"],
        ),
        # (a British text message)
        ("Sat behind a cyclist at 15 mph for ages, couldn't overtake as cars kept coming the other way.", ["bicycle"]),
        # (an American driver)
        ("I followed a cyclist at 20 mph and could not pass because of oncoming cars.", ["bicycle"]),
        # (a test spec)
        (
            "The ego follows a cyclist at 25 km/h and may not overtake while vehicles approach in the "
            "opposite direction.",
            ["bicycle"],
        ),
        # (an Indian report)
        ("I was behind one cyclist at 20 kmph, could not overtake since trucks were coming towards us.", ["bicycle"]),
        # (a Singaporean text)
        (
            "Behind one cyclist at 20 km/h lah, cannot overtake, got lorries coming from the other direction.",
            ["bicycle"],
        ),
    ],
)
def test_bare_plural_traffic_coming_the_other_way_is_no_road_user(text, expected):
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # (a counted plural is so many road users)
        ("I was doing 30 mph when two cars coming the other way swerved into my lane.", ["car", "car"]),
        # (one car coming the other way is a road user)
        ("I was behind a cyclist at 20 mph when a car coming the other way cut the corner.", ["bicycle", "car"]),
        # (the only road user the text names is the scene's)
        ("At 40 mph on the bend, oncoming cars kept drifting over the centre line at me.", ["car"]),
    ],
)
def test_counted_single_or_only_oncoming_vehicles_stay_road_users(text, expected):
    assert kinds(text) == expected
