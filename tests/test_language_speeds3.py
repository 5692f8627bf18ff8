"""Numbers that are no travel speed, and a bare speed's unit told by what the road is called.

- A road called by its limit's number alone ("doing 40 in a 30", "it's a twenty", "at 30 in the 30") is
  the British name of a town road signed 20 or 30 mph: a bare speed in such a text is in mph. A 30
  "zone", a number that counts a noun ("in a 30 second window", "in a 20 tonne truck"), or a larger
  number ("in a 60") keeps km/h.
- An hour said after a part of the day by any of its names ("Tuesday arvo about 3") is a time, not a
  speed; "the left lane of 3" counts lanes.
- A speed in a participle that follows a road user and the place said of it ("a rider 30 m ahead,
  travelling at 15 km/h") is that road user's, as it is right after its name.
- In a sentence where the narrator says "I", "he" or "she" is never the narrator, even before the
  "I" ("Overtook a jogger, she was running at 8 km/h and I ...").

Every wording here is written for these tests (none is from a corpus); each reading has near misses
that look alike but must keep reading as before."""

from __future__ import annotations

import pytest

from vei_scenario.language import miles_english
from vei_scenario.language.rules_backend import layers_from_text

MPH_KPH = 1.609344


def _ego_kph(text: str) -> float:
    return float(layers_from_text(text, 0)["ego"]["speed_mps"]) * 3.6


@pytest.mark.parametrize(
    ("text", "mph"),
    [
        ("Overtook on a blind bend. I was doing 40 in a 30, fair enough, but a cyclist came the other way.", 40),
        ("We came round by the shops, it's a twenty, and I was doing twenty when a boy ran out in front of me.", 20),
        ("Driving home at 30 in the 30 last night when a cyclist pulled out of a side road on my left.", 30),
        ("I was only doing about 25 in a 20. A jogger stepped out from behind a parked van.", 25),
    ],
)
def test_a_road_called_by_its_limit_makes_a_bare_speed_mph(text, mph):
    assert _ego_kph(text) == pytest.approx(mph * MPH_KPH, abs=0.3)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        # (a 30 zone is said where km/h is signed too)
        ("I was doing 30 in a 30 zone when a cyclist pulled out of a side road on my left.", 30),
        # (the number counts what follows it: no road)
        ("I was doing about 40 in a 30 tonne truck when a cyclist pulled out of a side road on my left.", 40),
        # (a limit of an open road is signed in km/h as well)
        ("I was doing 70 in a 60 when a cyclist pulled out of a side road on my left.", 70),
        # (a unit said in the text comes first)
        ("I was doing 40 km/h in a 30 when a cyclist pulled out of a side road on my left.", 40),
        # (no road named by a limit at all)
        ("I was doing about 40 when a scooter came off the footpath on my left and crossed in front of me.", 40),
    ],
)
def test_without_such_a_road_a_bare_speed_keeps_its_unit(text, kph):
    assert _ego_kph(text) == pytest.approx(kph, abs=0.3)


def test_road_called_by_its_limit_reads_the_words():
    assert miles_english.road_called_by_its_limit(["he", "was", "doing", "40", "in", "a", "30", "."])
    assert miles_english.road_called_by_its_limit(["it", "'s", "a", "twenty", ","])
    assert not miles_english.road_called_by_its_limit(["in", "the", "30", "seconds"])
    assert not miles_english.road_called_by_its_limit(["on", "the", "30", "bus"])
    assert not miles_english.road_called_by_its_limit(["in", "a", "30", "zone"])


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("Weds arvo about 3, busy road. Our sweeper was doing 30 km/h when a kid ran out from the footpath.", 30),
        ("Our sweeper was doing 25 km/h in the left lane of 3 when a man walked out in front of it.", 25),
    ],
)
def test_an_hour_or_a_count_of_lanes_is_no_speed(text, kph):
    assert _ego_kph(text) == pytest.approx(kph, abs=0.3)


def test_a_bare_number_after_at_still_a_speed_without_a_part_of_the_day():
    # (the guard: "about 30" with no part of the day before it is a speed)
    assert _ego_kph("Monday, about 30 on the speedo, when a kid ran out from the footpath in front of me.") == (
        pytest.approx(30, abs=0.3)
    )


def _speeds(text: str) -> tuple[float, list[float]]:
    layers = layers_from_text(text, 0)
    return float(layers["ego"]["speed_mps"]) * 3.6, [float(a["speed_mps"]) * 3.6 for a in layers["adversaries"]]


@pytest.mark.parametrize(
    "text",
    [
        "We drive at 60 km/h when we spot a cyclist 40 m ahead, riding the same way at 18 km/h.",
        "The test car goes at 60 km/h; it sees a cyclist 40 m ahead travelling in the same direction at 18 km/h.",
    ],
)
def test_a_participle_after_a_placed_road_user_is_its_own(text):
    ego, others = _speeds(text)
    assert ego == pytest.approx(60, abs=0.3)
    assert others == [pytest.approx(18, abs=0.3)]


def test_a_participle_right_after_its_name_as_before():
    # (the guard: no place between, the participle is the road user's as it was)
    ego, others = _speeds("We drive at 60 km/h when we spot a cyclist riding the same way at 18 km/h.")
    assert (ego, others) == (pytest.approx(60, abs=0.3), [pytest.approx(18, abs=0.3)])


def test_a_comma_with_no_place_between_keeps_its_reading():
    # (the guard: "I overtook a cyclist, doing 50 km/h" is still the narrator's 50)
    ego, _ = _speeds("I overtook a cyclist, doing 50 km/h.")
    assert ego == pytest.approx(50, abs=0.3)


@pytest.mark.parametrize(
    ("text", "kph"),
    [
        ("Overtook a jogger on the lane this morning, she was running at about 10 km/h and I went wide.", 10),
        ("Came up behind a cyclist by the park, he was riding at about 16 km/h so I waited for a gap.", 16),
    ],
)
def test_he_or_she_is_not_the_narrator_before_i_is_said(text, kph):
    ego, others = _speeds(text)
    assert others == [pytest.approx(kph, abs=0.3)]
    assert ego != pytest.approx(kph, abs=0.3)


def test_he_in_a_story_told_of_others_as_before():
    # (the guard: no "I" anywhere, "he" is the one the story is about, the ego, as before)
    ego, _ = _speeds("The ego drives at 40 km/h. He brakes for a cyclist who pulls out of a side road on the left.")
    assert ego == pytest.approx(40, abs=0.3)


def test_he_in_a_story_about_someone_with_no_i_beside_it_as_before():
    # (the guard: a story about Ben in an organisation's words, "our", and no "I" beside "he": Ben)
    text = (
        "Ben's story. Ben was riding his bike home at 20 km/h on a dry evening. As he reached the lights, a "
        "van turned left across his path. Our campaign asks drivers to look twice."
    )
    layers = layers_from_text(text, 0)
    assert [a["type"] for a in layers["adversaries"]] == ["van"]
