"""Outcomes and mirroring read as what they are, not as behaviours: a stop that a road user makes
after it has struck someone is how the incident ended, not a manoeuvre of the scenario. Each
construction is pinned by wordings of our own (none from a corpus), read through the whole reader,
with near misses that look alike but must read otherwise."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def behaviours(text: str) -> list[list[str]]:
    return [[b[0] for b in a.behaviours] for a in read(text).actors]


# --- a stop after a contact is the aftermath of the crash, not a behaviour ------------------------------
@pytest.mark.parametrize(
    "text, expected",
    [
        (
            "I was driving at 50 km/h when a van pulled out of a side road in front of me and hit me. "
            "The van then carried on for about 100 m before stopping on the verge.",
            [["turn_into"]],
        ),
        (
            "I was driving at 50 km/h when a car merged in front of me and clipped my wing. "
            "The car kept going for a bit before pulling up on the shoulder.",
            [["cut_in"]],
        ),
        (
            "At 30 mph a hatchback cut in ahead of us and struck our front bumper, then stopped further up the road.",
            [["cut_in"]],
        ),
    ],
    ids=["carried-on-before-stopping", "kept-going-before-pulling-up", "struck-then-stopped"],
)
def test_a_stop_after_a_contact_is_the_aftermath(text, expected):
    assert behaviours(text) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        # the stop comes before the contact: it is what the road user did
        ("I was doing 40 km/h when the car ahead of me stopped suddenly and I hit it.", ["stop"]),
        # the contact is another road user's, after the stop
        ("At 50 km/h the van ahead of me stopped dead, and a moment later a cyclist hit my car.", ["stop"]),
    ],
    ids=["stop-before-contact", "stop-before-another-contact"],
)
def test_a_stop_not_after_a_contact_stays(text, expected):
    got = behaviours(text)
    assert any(set(expected) & {b.split("_")[-1] for b in bs} for bs in got), got


def test_a_lead_that_stops_dead_in_front_stops():
    assert behaviours("I was following a car at 60 km/h when it stopped dead in front of me.") == [["sudden_stop"]]


def test_a_follower_that_slowed_then_overtook_overtakes():
    got = behaviours("I was driving at 40 km/h. A lorry behind me slowed and then overtook me.")
    assert got and "overtake" in got[0]


# --- a road user's act that repeats the ego's ("every time I slowed he slowed") is following ------------
@pytest.mark.parametrize(
    "text",
    [
        "I was doing 40 mph when a van behind me sat on my bumper. Every time I slowed he slowed.",
        "At 60 km/h a hatchback tailgated me for miles, braking whenever I braked.",
        "I was on the bypass at 50 mph with a lorry tailgating me; each time we slowed down it slowed down too.",
    ],
    ids=["every-time", "whenever", "each-time-we"],
)
def test_copying_the_ego_is_following(text):
    assert behaviours(text) == [["follow_vehicle"]]


@pytest.mark.parametrize(
    "text, expected",
    [
        # the ego answers the road user: the road user's braking is its own
        ("I was doing 40 mph behind a van and I braked when the van braked hard.", "sudden_stop"),
        # a different act from the ego's
        ("I was doing 40 mph. When I slowed, the cyclist ahead of me stopped dead.", "sudden_stop"),
    ],
    ids=["ego-answers", "different-act"],
)
def test_an_act_not_copying_the_ego_stays(text, expected):
    got = behaviours(text)
    assert any(expected in bs for bs in got), got
