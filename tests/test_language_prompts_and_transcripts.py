"""Two styles a description arrives in: a prompt written for a text-to-video generator (negative prompts,
weights, settings, "the camera car"), and a meeting transcript or log whose lines carry stamps (a
running time or a clock of the record, not the time the scene happened).

Every wording here is written for these tests (none is from a corpus). Each rule has wordings that must
read and near misses that look alike but must not."""

from __future__ import annotations

import pytest

from vei_scenario.language.generation_prompt import without_prompt_syntax
from vei_scenario.language.reader import read
from vei_scenario.language.settings import clock_in_words, line_stamps, speakers

KPH = 1 / 3.6
MPH = 0.44704


# --- what a generator must not show is not the scene ------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "dashcam, rainy dusk, a delivery van pulls out of a driveway on the right and we slow and let it go\n"
        "Negative prompt: crash, collision, debris, cartoon",
        "dashcam, a van pulls out of a driveway on the right, we slow down and let it go. negative prompt: crash",
        '{"prompt": "dashcam, a van pulls out of a driveway on the right, the car slows and lets it go", '
        '"negative_prompt": "crash, smashed glass, blurry", "seed": 42}',
        "dashcam, a van pulls out of a driveway on the right, we slow down and let it go --ar 16:9 --no crash, gore",
        "dashcam, a van pulls out of a driveway on the right, we slow down and let it go\n - neg: collision, 3d render",
    ],
)
def test_a_negative_prompt_is_not_read_as_the_scene(text):
    r = read(text)
    assert r.intent != "collision", text
    assert [a.kind for a in r.actors] == ["van"]
    assert {"crash", "collision"} & set(r.ignored), r.ignored  # (said to be not used)


@pytest.mark.parametrize(
    "text, intent",
    [
        (
            "a cyclist pulls out of a side road on the left and we hit him. No negative effects on the rider.",
            "collision",
        ),
        ("The test was negative: a cyclist pulls out of a side road on the left and we hit him.", "collision"),
        ("a van cuts in and we crash into it, (crash:1.3), dashcam", "collision"),
    ],
)
def test_negative_words_outside_a_prompts_label_stay_the_scene(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text, kept, cut",
    [
        ("(wrong-way driver:1.4) on a motorway, (night:1.1)", "wrong-way driver on a motorway, night", []),
        ("((near miss)) with a cyclist, [heavy rain:0.8]", "near miss with a cyclist, heavy rain", []),
        ("a van brakes hard ahead::2 fog::0.5", "a van brakes hard ahead, fog,", []),
        ("a bus pulls out --ar 16:9 --seed 1207 --motion 6", "a bus pulls out", ["ar", "seed", "motion"]),
        # near misses: clocks, dates and brackets of an ordinary text are kept as they are
        ("[18:12] Ellie: mum nearly hit a scooter guy", "[18:12] Ellie: mum nearly hit a scooter guy", []),
        ("Obs. 7 (Thu 21 Sept, 14:32) a cyclist crossed", "Obs. 7 (Thu 21 Sept, 14:32) a cyclist crossed", []),
        ("at 50 km/h (about 30 mph) -- then the car braked", "at 50 km/h (about 30 mph) -- then the car braked", []),
    ],
)
def test_weights_and_settings_of_a_prompt(text, kept, cut):
    out, aside = without_prompt_syntax(text)
    assert " ".join(out.split()) == kept
    assert aside == cut


def test_a_weighted_behaviour_is_read_as_the_behaviour():
    r = read("(wrong-way driver:1.4) on a dark dual carriageway, camera car in the left lane at 110 km/h, "
             "(near miss:1.2), night")  # fmt: skip
    assert [b[0] for b in r.actors[0].behaviours] == ["wrong_way"]
    assert r.intent == "near_miss"


# --- the camera car is the ego --------------------------------------------------------------------------
def test_the_speed_of_the_camera_car_is_the_egos():
    r = read("On a dark dual carriageway, camera car in the left lane at 110 km/h, a car comes straight at us "
             "in our lane.")  # fmt: skip
    assert r.ego_speed_mps == pytest.approx(110 * KPH)
    assert [(a.kind, a.speed_mps) for a in r.actors] == [("car", None)]


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("Camera car stopped at the lights. A van behind us fails to stop and hits the camera car.", ["van"]),
        ("Camera vehicle doing 30 mph. A man walks out on the left right in front of the camera vehicle.",
         ["pedestrian"]),
    ],
)  # fmt: skip
def test_the_camera_car_is_no_road_user_of_its_own(text, kinds):
    r = read(text)
    assert [a.kind for a in r.actors] == kinds
    assert "camera" not in r.ignored


# --- a line's stamp is when it was said or logged --------------------------------------------------------
@pytest.mark.parametrize(
    "text, part",
    [
        (
            "[00:03:05] Nadia: ok so the cyclist one. Late afternoon, low sun.\n"
            "[00:03:11] Piet: we're doing about 40?\n"
            "[00:03:14] Nadia: 40 k, and a cyclist comes out of a side road on the left, we brake hard.",
            (12, 17),
        ),
        (
            "Speaker 1 (02:40): the scooter at the school gates, early morning, we're at 20 mph\n"
            "Speaker 2 (02:52): and he just rode off the kerb on the right in front of us?\n"
            "Speaker 1 (02:55): yep, no contact",
            (6, 11),
        ),
        (
            "Grete Olsen  1:02\nRight, the bus. It was in the evening, raining, the bus pulls out from a stop on "
            "our left.\n\nMo Tran  1:15\nand we stop behind it",
            (18, 22),
        ),
    ],
)
def test_a_part_of_the_day_said_wins_over_the_stamps_of_the_lines(text, part):
    hour = int(read(text).time.split(":")[0])
    assert part[0] <= hour <= part[1], read(text).time


@pytest.mark.parametrize(
    "text, clock",
    [
        # a log or a live chat whose stamps are the clock, with no part of the day said: the stamp
        ("[17:52] Sam: a lad on a scooter just shot out of a side road on my left\n[17:53] Sam: missed him", "17:52"),
        # a clock said in a line, not a stamp of it
        ("Time: 14:30\nA car pulls out of a side road on the left. Light rain, afternoon.", "14:30"),
        ("Last Tuesday I left at 8:15\nA car pulled out of a side road on my left, in the morning rush.", "08:15"),
    ],
)
def test_a_stamp_with_no_part_said_or_a_clock_said_stays_the_time(text, clock):
    assert read(text).time == clock


def test_line_stamps_are_found_by_their_place_in_the_line():
    text = (
        "[00:12:40] Sophie: right\nSpeaker 2 (00:31): so\nMarcus Feld  0:03\nGrace T  [10:31]\nNoor 15:02: a "
        "cyclist\n00:00:02.100 --> 00:00:06.400\n07:48 Op observes\nTime: 14:30\nAt 7:40 a van\nI left at 9:15"
    )
    assert line_stamps(text) == {"00:12", "00:31", "00:03", "10:31", "15:02", "00:00", "07:48"}


# --- a clock said as two numbers, and a greeting that opens a turn ----------------------------------------
@pytest.mark.parametrize(
    "said, clock",
    [
        ("it was one-forty in the morning , a", "01:40"),
        ("about seven thirty at night", "19:30"),
        ("ten fifteen pm", "22:15"),
        ("six forty-five in the evening", "18:45"),
        ("one forty cars a day", None),  # (no half of the day said: not a clock)
        ("at six fifteen we turned", None),
    ],
)
def test_an_hour_and_its_minutes_said_before_the_half_of_the_day(said, clock):
    assert clock_in_words(said, []) == clock


def test_a_greeting_opening_a_speakers_turn_is_no_time():
    text = (
        "INSPECTOR: Evening. Tell me what happened at the junction.\n"
        "RIDER: I was cycling along and a car pulled out of the side road on my right at one-forty in the "
        "morning.\nINSPECTOR: Go on."
    )
    assert speakers(text) == {"inspector"}  # (a label that opens two lines or more)
    assert read(text).time == "01:40"


def test_a_part_of_the_day_after_a_fields_label_is_the_time():
    assert read("Time: evening.\nA car pulls out of a side road on the left.").time == "20:00"


@pytest.mark.parametrize(
    "text, part",
    [
        # a clock said in a turn after a question (which is set aside) wins over the stamps
        (
            "Speaker 1 (01:10): the van from Elm Road\nSpeaker 2 (01:14): it pulls out of Elm Road on our left "
            "in front of us, we brake hard.\nSpeaker 1 (01:20): ok. When?\nSpeaker 2 (01:22): rush hour, 8:40, "
            "dry.\nSpeaker 1 (01:30): thanks",
            (8, 8),
        ),
        # a clock in words, after stamps
        (
            "[00:00:00] Recording started\n[00:00:04] Ola: a cyclist turns out of a side road on the right in "
            "front of us.\n[00:00:15] Ola: It was ten past five, still light.",
            (17, 17),
        ),
        # a part of the day that opens a turn and is told ("Evening, about 7") is the time, not a greeting
        (
            "[00:05:01] Bea: the jogger one, a jogger steps off the kerb on the left in front of us.\n"
            "[00:05:09] Kofi: and the light?\n[00:05:12] Bea: Evening, about 7, still light.\n[00:05:20] Kofi: ok",
            (18, 20),
        ),
        ("Wednesday, seven a.m. roughly, a car pulls out of a side road on the left in front of us.", (7, 7)),
    ],
)
def test_a_time_told_in_a_transcript(text, part):
    hour = int(read(text).time.split(":")[0])
    assert part[0] <= hour <= part[1], read(text).time


def test_a_greeting_with_a_comma_and_news_is_the_time():
    text = "ANA: Morning, about 9, sunny. A van cut in.\nANA: that's all\nBEN: thanks"
    assert 6 <= int(read(text).time.split(":")[0]) <= 11


# --- near misses a review found: prose dashes, a describing word before "camera car", a log's own clock -----
@pytest.mark.parametrize(
    "text, speed",
    [
        ("The van --no lights, no indicator-- pulled straight out in front of me and I hit it at 30.", None),
        ("I was going 30 --maybe 35-- when the car ahead stopped dead and I hit it.", 35 * MPH),
    ],
)
def test_a_double_dash_inside_prose_is_a_dash_not_a_setting(text, speed):
    r = read(text)  # (read, not refused)
    assert r.actors and r.actors[0].behaviours
    if speed is not None:
        assert r.ego_speed_mps == pytest.approx(speed, rel=0.01)


def test_a_breath_test_negative_is_not_a_prompt():
    out, aside = without_prompt_syntax("Breath test, negative: the driver said he braked for the cyclist.")
    assert aside == [] and "the driver said" in out


@pytest.mark.parametrize(
    "text",
    [
        "4k photoreal dashcam. A motorbike filters between the lanes and clips our mirror.",
        "dashcam clip, 8K, HDR, a motorbike filters between the lanes and clips our mirror",
    ],
)
def test_a_resolution_tag_is_no_speed(text):
    assert read(text).ego_speed_mps is None


@pytest.mark.parametrize(
    "text",
    [
        "The Street View camera car in front of me stopped suddenly at 30 mph and I went into the back of it.",
        "A police camera car was parked in the lay-by when a cyclist swerved out in front of me.",
    ],
)
def test_a_camera_car_described_as_someone_elses_is_a_road_user(text):
    assert "car" in [a.kind for a in read(text).actors]


@pytest.mark.parametrize(
    "text, clock",
    [
        ("Night shift log\n02:14 Patrol saw a car going the wrong way on the slip road. A lorry swerved.", "02:14"),
        ("EVENING SHIFT HANDOVER\n18:05 Unit 12: a car changed lanes into a motorcycle on the A40.", "18:05"),
        ("[07:41] Dave: morning lads, just seen a cyclist get doored on Park Lane\n[07:42] Dave: he's ok", "07:41"),
        # a running time (a stamp with the hour 0) against a part said: the part
        ("[00:05:12] Jake: late at night, pitch black, a guy on a scooter comes out of nowhere, I hit him.", "23:00"),
    ],
)
def test_a_stamp_within_the_part_said_is_the_time_unless_it_runs_a_recording(text, clock):
    assert read(text).time == clock


@pytest.mark.parametrize(
    "said, parts, clock",
    [
        ("twelve thirty at night , empty motorway", [], "00:30"),
        ("two-oh-five in the morning", [], "02:05"),
    ],
)
def test_midnight_and_oh_minutes_said_in_words(said, parts, clock):
    assert clock_in_words(said, parts) == clock


def test_a_later_hour_in_the_half_the_part_says():
    assert read("[00:01:10] Witness: It was about 9:15 at night, and a van ran the red light and hit a car.").time == (
        "21:15"
    )


@pytest.mark.parametrize(
    "text, part",
    [
        ("LAWYER: What time of day was it?\nWITNESS: Evening.\nLAWYER: And then?\nWITNESS: A taxi ran the red "
         "light and hit a cyclist.", (18, 22)),
        ("Q: Time of day?\nA: Afternoon. A child ran out between parked cars and I hit her.\nQ: Lighting?\nA: Good.",
         (12, 17)),
    ],
)  # fmt: skip
def test_a_part_of_the_day_that_answers_a_question_is_the_time(text, part):
    hour = int(read(text).time.split(":")[0])
    assert part[0] <= hour <= part[1]


def test_standing_road_users_are_left_out_first():
    text = (
        "Queue at the lights: a bus, a taxi, a van, a lorry, a white car, a red car, a pickup and a minibus "
        "were all waiting. Then a cyclist came up the inside and a pedestrian stepped out in front of me."
    )
    kinds = [a.kind for a in read(text).actors]
    assert "bicycle" in kinds and "pedestrian" in kinds, kinds


# --- near misses a second review found -----------------------------------------------------------------
@pytest.mark.parametrize(
    "text, speed",
    [
        ("Setup? Ego car at 50 km/h follows a van at 45 km/h. Van brakes, ego stops 3 m behind.", 50 * KPH),
        ("Who is liable here?\nMy car at 30 mph was following a bus at 20 mph. The bus braked and I went into it.",
         30 * MPH),
    ],
)  # fmt: skip
def test_a_question_set_aside_before_a_speed_leaves_it_the_subjects(text, speed):
    assert read(text).ego_speed_mps == pytest.approx(speed)


@pytest.mark.parametrize(
    "text, clock",
    [
        ("1:40 in the morning, empty streets. A taxi ran the red light and I T-boned it at 30 mph.", "01:40"),
        ("4:50 - afternoon rush. A motorcyclist filtering at 30 mph clipped my mirror.", "16:50"),
        ("7:15 at night, foggy. The lorry in front braked hard and I went into the back of it.", "19:15"),
        ("8:40 in the evening, raining. A cyclist turned right across me and I hit him.", "20:40"),
    ],
)
def test_one_clock_opening_a_text_is_said_not_stamped(text, clock):
    assert read(text).time == clock


@pytest.mark.parametrize(
    "text, part",
    [
        ("INVESTIGATOR: Start with the time of day.\nWITNESS: Afternoon. Sunny.\nINVESTIGATOR: And then?\n"
         "WITNESS: A cyclist went through the red light and a car hit him.", (12, 17)),
        ("Handler: Tell me when it happened, roughly.\nCustomer: Morning. School run.\nHandler: And what happened?\n"
         "Customer: The car in front stopped and I went into it.", (6, 11)),
    ],
)  # fmt: skip
def test_a_part_of_the_day_that_answers_a_request_is_the_time(text, part):
    hour = int(read(text).time.split(":")[0])
    assert part[0] <= hour <= part[1]


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A car pulled out of a side road in front of me at 30 mph --hit it square on", "collision"),
        ("A cyclist came out of nowhere at the lights, I was doing 20 --stopped just in time", "near_miss"),
    ],
)
def test_a_dash_at_a_lines_end_before_words_is_prose(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text",
    [
        "Positive: good mirror checks and road position.\nNegative: when the cyclist pulled out of the junction at "
        "15 mph you braked late and stopped only a metre short.",
        "Drugs wipe, negative: the driver of the van that rear-ended me was sober, he was doing 40. I was stopped.",
    ],
)
def test_a_negative_label_before_a_sentence_is_no_prompt(text):
    out, aside = without_prompt_syntax(text)
    assert aside == [] and out == text
    assert read(text).actors


def test_a_speed_in_k_after_a_road_user_is_no_resolution_tag():
    r = read("Cyclist 16k, ego 50k. Cyclist swerves into the ego lane 10 m ahead.")
    assert r.actors[0].speed_mps == pytest.approx(16 * KPH)


# --- near misses a third review found ------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A motorbike squeezed past at 40 mph and tagged it as it went by. My mirror.",
        "The lorry tagged them as it went past, both mirrors gone.",
    ],
)
def test_tagged_as_it_went_by_is_contact(text):
    assert read(text).intent == "collision"


@pytest.mark.parametrize(
    "text, intent",
    [
        ("A van pulled out of a side road in front of me, I was doing 30 mph --hit it", "collision"),
        ("A kid ran out in front of me at 20 mph --missed him", "near_miss"),
    ],
)
def test_one_dashed_word_group_at_a_lines_end_is_prose(text, intent):
    assert read(text).intent == intent


def test_a_speed_in_k_after_a_label_is_a_speed():
    r = read("Ego speed: 50k. Cyclist speed: 16k. The cyclist swerves into the ego lane 10 m ahead.")
    assert r.actors[0].speed_mps == pytest.approx(16 * KPH)


@pytest.mark.parametrize(
    "text",
    [
        "The camera car in front of me braked suddenly at 30 mph and I rear-ended it.",
        "I was following a camera car at 30 km/h when it braked hard.",
    ],
)
def test_a_camera_car_placed_from_the_narrator_is_another_road_user(text):
    assert [a.kind for a in read(text).actors] == ["car"]


@pytest.mark.parametrize(
    "text, clock",
    [
        ("At 9:20 we set off. The night before it had snowed. A van slid across into our lane.", "09:20"),
        ("At 11:10, after the night shift, I cycled home and a car pulled out of a side road.", "11:10"),
    ],
)
def test_night_said_apart_from_a_clock_leaves_its_half(text, clock):
    assert read(text).time == clock


@pytest.mark.parametrize(
    "text",
    [
        "Pika prompt: a cyclist swerves in front of a car, dusk, aspect ratio 9:16, cinematic",
        "dashcam, a cyclist swerves in front of the camera car, evening, 9:16 vertical",
    ],
)
def test_an_aspect_ratio_is_no_clock(text):
    r = read(text)
    assert r.time is None or not r.time.endswith(":16")


def test_the_road_user_that_manoeuvres_is_kept_over_those_going_on():
    text = (
        "Rush hour: a taxi at 20 km/h, a bus at 15 km/h, a cyclist at 15 km/h, a car at 30 km/h, another car at "
        "25 km/h, a van at 25 km/h, a lorry at 20 km/h and a motorbike at 35 km/h were all going round. Then a "
        "tractor pulled out in front of me and I hit it."
    )
    assert any(b[0] in ("cut_in", "turn_into") for a in read(text).actors for b in a.behaviours)


def test_feedback_with_a_positive_label_keeps_its_negative():
    out, aside = without_prompt_syntax("Driving test feedback. Positive: good mirrors. Negative: hit a cyclist.")
    assert aside == [] and "hit a cyclist" in out


def test_sat_in_traffic_contracted_is_at_rest():
    assert read("We're sat in traffic on the bypass when a van rolls into our back bumper.").ego_speed_mps == 0.0
