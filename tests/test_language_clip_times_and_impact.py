"""Dash-cam and helmet-cam posts: a clock that points into the clip is no time of day, the speed the ego
hits someone at is not its speed where a higher one was said before, and a contact supposed in a past
condition ("if I had hit her") did not happen.

Every wording here is written for these tests (none is from a corpus). Each rule has wordings that must
read and near misses that look alike but must not."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read

MPH = 0.44704
KPH = 1 / 3.6


# --- a point in the clip is no time of day ------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Dashcam. At 0:09 a car pulls out of the side road on my left. At 1:06 a cyclist swings out.",
        "From 0:30 to 1:05 a pickup sits on my tail, then at 1:06 it overtakes me.",
        "Helmet cam. You can see my light at 1:11, and at 1:12 a black Golf pulls out of the side road.",
        "Rear cam from the start. At 3:20 a lorry cuts in front of me, at 3:24 it brakes hard.",
        "Watch the clip. 1:14 - a scooter rider rolls off the kerb in front of me, 1:16 he waves.",
        "The overlay says 41 at 1:24, when a man walks across my lane; at 1:26 he is gone.",
        "Voice note (1:12): a child ran out from between parked cars on the left, then at 1:40 she waved.",
    ],
)
def test_a_clock_pointing_into_the_clip_is_no_time_of_day(text):
    assert read(text).time is None


@pytest.mark.parametrize(
    "text, clock",
    [
        ("At 3:15 a cyclist swings out in front of me outside the school.", "15:15"),
        ("Dashcam from this morning at 8:20am: a cyclist swings out in front of me.", "08:20"),
        ("At 17:45 a van pulls out of a side road on my left. Dashcam footage attached.", "17:45"),
        ("The driver checks the dash clock. 8:47. A cyclist swerves in front of the car.", "08:47"),
        ("Dashcam. At 9:40 pm a cyclist swings out in front of me. The clip ends at 9:41 pm.", "21:40"),
        ("Dashcam. At 2:30 in the morning a cyclist swings out in front of me.", "02:30"),
        ("Caught this on my dashcam on the way to work at 7:40. A van pulled out of a side road.", "07:40"),
        ("Cycling to work at 7:20, a lorry overtakes and clips my elbow with its mirror, at 7:21 it is gone.", "07:20"),
        ("On a video call at 8:10, I look up and a van pulls out of a side road, 8:11 exactly.", "08:10"),
        ("It was 3:10 on a Sunday morning when a car ran the red light in front of me.", "03:10"),
        ("Driving home after a night shift. At 7:40 a van pulled out of a side road.", "07:40"),
    ],
)
def test_a_clock_of_the_day_stays(text, clock):
    assert read(text).time == clock


# --- the speed at impact is not the ego's speed where its speed was said ------------------------------------
@pytest.mark.parametrize(
    "text, mps",
    [
        ("I was doing 65. A car cut in front of me and I hit him at 15.", 65 * MPH),
        (
            "I'm in the fast lane at 65 with a decent gap. A Charger cuts in front of me, then slams his brakes. "
            "I couldn't stop and hit him at maybe 15-20.",
            65 * MPH,
        ),
        ("Going along at 50 km/h, a van pulled out and we hit it at about 20 km/h.", 50 * KPH),
        ("I was at 40 mph. The cyclist swerved out and I struck him at 25 mph.", 40 * MPH),
        ("I was doing 50 km/h when a pedestrian stepped out and I hit her at 30 km/h.", 50 * KPH),
    ],
)
def test_the_speed_the_ego_hits_at_is_not_its_speed_said_before(text, mps):
    assert read(text).ego_speed_mps == pytest.approx(mps, abs=0.05)


@pytest.mark.parametrize(
    "text, mps",
    [
        ("A car cut in front of me and I hit him at 15 mph.", 15 * MPH),  # (the only speed said)
        ("I was doing 30 mph. A car cut in front of me at 50 mph.", 30 * MPH),
        ("We hit the van at 20 km/h after it pulled out.", 20 * KPH),
        # (a higher speed at impact than said before: the ego sped up after it)
        ("Crawling along in the queue at 5 mph, it cleared, a kid ran out and I hit him at 35 mph.", 35 * MPH),
    ],
)
def test_a_speed_at_impact_with_no_speed_before_it_stays_the_egos(text, mps):
    assert read(text).ego_speed_mps == pytest.approx(mps, abs=0.05)


def test_another_road_users_speed_at_impact_after_the_egos_is_not_its_own():
    """A test-track log: the target's speed is the one given with it, not the speed of impact."""
    r = read("VUT 50 kph, e-scooter target crossing from the left at 15 kph. Impact at approx 18 kph.")
    assert r.ego_speed_mps == pytest.approx(50 * KPH, abs=0.05)
    (scooter,) = [a for a in r.actors if a.kind == "e-scooter"]
    assert scooter.speed_mps == pytest.approx(15 * KPH, abs=0.05)


# --- a contact in a past condition did not happen -------------------------------------------------------------
NO_CONTACT = "A van came through the red and the car in front did an emergency stop. No contact, somehow. "


@pytest.mark.parametrize(
    "question",
    [
        "Question: if I had hit her, would the van driver carry any of the blame?",
        "Question: if I HAD hit the Fiesta, would the van carry the blame?",
        "My question: had I hit her, who would be at fault?",
        "Question: if the van had actually clipped her, who pays?",
        "Question: if I had already hit her, would the van be to blame?",
    ],
)
def test_a_contact_supposed_in_a_past_condition_did_not_happen(question):
    assert read(NO_CONTACT + question).intent == "near_miss"


@pytest.mark.parametrize(
    "text",
    [
        "A kid ran out between parked cars. I got out to see if I had hit him and he was holding his leg.",
        "A cyclist pulled out. By the time I braked I had hit him.",
        "A cyclist pulled out and I hit him. The police asked me if I had already hit him before he fell.",
        "A cyclist pulled out and I hit him. I honestly can't say if I had already hit him when he fell.",
        "Parked my car outside work and a reversing lorry hit it. Had it hit by a lorry last year too.",
        "A cyclist pulled out in front of me. I braked but I had already hit him.",
        "A cyclist pulled out and I hit him. If I had braked sooner I would have missed him.",
        "A cyclist pulled out and I hit him. Question: if I had not hit him, would he have fallen anyway?",
    ],
)
def test_a_contact_told_in_the_past_perfect_or_beside_a_condition_stays(text):
    assert read(text).intent == "collision"


def test_a_place_hit_at_a_speed_is_no_impact_with_a_road_user():
    text = "I was on the motorway at 70, came off at the junction and hit the roundabout at 40 as a car came round."
    assert read(text).ego_speed_mps < 60 * MPH


# --- a rolled stop sign ----------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist rolls the stop sign right in front of me.",
        "A van rolled through the stop sign in front of me.",
        "The scooter rider just rolled a stop sign and crossed in front of us.",
    ],
)
def test_rolling_a_stop_sign_is_running_it(text):
    assert "run_red_light" in [b[0] for a in read(text).actors for b in a.behaviours]


def test_rolling_to_a_stop_at_the_stop_sign_stays_a_stop_there():
    (a,) = read("A car rolled to a stop at the stop sign.").actors
    assert a.behaviours[0][0] == "keep_going"
