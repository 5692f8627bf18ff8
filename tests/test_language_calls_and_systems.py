"""Emergency-call transcripts and owners' accounts of their car's assistance systems: the caller's speed
given as an answer, a bare speed set off by how one went, the vehicles a call asks for, the police of a
km/h country, and the car whose warning or braking only the ego's system gives.

Every wording here is written for these tests (none is from a corpus). Each rule has wordings that must
read and near misses that look alike but must not."""

from __future__ import annotations

import pytest

from vei_scenario.language.description_text import readable_description
from vei_scenario.language.reader import read

MPH = 0.44704
KPH = 1 / 3.6


def _ego(text: str) -> float | None:
    return read(text).ego_speed_mps


def _kinds(text: str) -> list[str]:
    return sorted(a.kind for a in read(text).actors)


# --- the answer to "how fast were you going?" is the caller's speed -----------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        (
            "CT: What happened?\nC: A cyclist came the wrong way round the bend, in my lane.\n"
            "CT: How fast were you going?\nC: Forty? Not more. Forty.",
            40,
        ),
        (
            "Q: Tell me what you saw.\nA: A kid on an e-scooter came off the kerb in front of me.\n"
            "Q: What speed were you doing?\nA: 30, about.",
            30,
        ),
        (
            "Operator: How fast were you travelling? Caller: Fifty, sixty. A van pulled out of a side road "
            "right in front of me.",
            55,
        ),
        (
            "A van cut in front of me on the ring road.\n[10:02] Dispatcher: And your speed?\n"
            "[10:02] Driver: Seventy, it's a seventy road.",
            70,
        ),
        (
            "BY MR. ABRAMS:\nQ. How fast were you going?\nA. Thirty. Thirty-five at the most.\n"
            "Q. Then what happened?\nA. She swerved round a pothole into my lane on her e-scooter.",
            30,
        ),
        (
            "THE COURT: Ms. Lindqvist, your speed?\nMS. LINDQVIST: Twenty-five, Your Honor.\n"
            "THE COURT: And the pedestrian stepped off on your left.",
            25 * 1.609344,  # (a bare 25 is a limit only mph signs: 25 mph)
        ),
        (
            "THE COURT: Thank you. Officer Ruiz, your speed?\nOFFICER RUIZ: Forty, sir.\n"
            "THE COURT: And the scooter came off the curb in front of you.",
            40 * 1.609344,  # (a curb: an American road, where a bare speed is in mph)
        ),
        (
            "MS DOYLE: Speed?\nA. Twenty-ish. No more.\nMS DOYLE: What did you see?\n"
            "A. An e-scooter came across from my left, through the red.",
            20,
        ),
        (
            "MS FRY: You were following a cyclist. How far behind?\nA. Four or five metres.\n"
            "MS FRY: Four or five metres. At what speed?\nA. Fifteen.\nMS FRY: And then he stopped.",
            15,
        ),
        (
            "Officer: Where were you?\nDriver: On Mill Road, heading into town.\nOfficer: Speed?\n"
            "Driver: 30. Then a kid on an e-scooter shot out in front of me.",
            30,
        ),
        (
            "DC Smith: You were on the M25 when the lorry pushed a Mini into the barrier.\n"
            "DC Smith: What speed were you doing?\nSuspect: 90 kilometres. The truck is limited.",
            90,
        ),
    ],
    ids=[
        "question-mark-answer",
        "figures",
        "same-line-range",
        "your-speed",
        "deposition-q-and-a",
        "put-to-a-name",
        "put-to-a-name-after-a-sentence",
        "a-question-of-its-own",
        "at-what-speed",
        "speakers-labels-name-no-one",
        "a-length-per-hour",
    ],
)
def test_the_answer_to_a_question_of_the_callers_speed_is_their_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, abs=0.05)


@pytest.mark.parametrize(
    "text",
    [
        # the question is of another's speed: the answer is not the caller's
        "A van cut in front of me.\nCT: How fast was he going?\nC: Sixty at least.",
        # the answer gives a length, not a speed
        "A van cut in front of me.\nCT: How fast were you going?\nC: I don't know, he was twenty metres ahead.",
        # no other speaker answers: a question asked in a story
        "A van cut in front of me. How fast were you going, my wife asked later. I had no idea.",
        # the answer's number is of something else: an age, the limit, a count, another's speed
        "CT: How fast were you going?\nC: I'm 82, I don't drive fast. A cyclist came out in front of me.",
        "CT: Do you know your speed?\nC: No idea, but the limit is 30 there. A van hit me.",
        "CT: How fast were you going?\nC: I wasn't, I was parked. He did 50 easily and hit my door.",
        # asked in a story, not a transcript's turn
        "I stopped and asked the e-scooter rider: how fast were you going?\nRider: 25, it's limited.",
        "Driver: I was moving off. The cop asked how fast were you going?\nCop: 55, the radar said. A van cut in.",
        # "your speed" inside another question; two questions at once; a distance or a time answered
        "Q: Was the lorry faster than your speed?\nA: Yes, 70 maybe. It overtook me and cut in.",
        "Officer: What speed were you doing, and how old are you?\nMe: 17, sir. A cyclist came out and I hit him.",
        "CT: How fast were you going?\nC: 40 miles, from Leeds, we'd been driving. A van cut in.",
        "CT: How fast were you going?\nC: Yeah, 5 or so minutes ago. A van cut in.",
        # a question of its own about another road user; a question told by a speaker
        "Q. A van cut in front of you. And the van, how fast?\nA. 40.",
        "Driver: A van cut in. The cop asked, how fast were you going?\nCop: 55.",
        "Caller: A motorbike flew past me on the inside and hit a pedestrian.\nCT: How fast?\nCaller: 100 at least.",
        "Q. A van cut in. And the van? How fast?\nA. 40.",
        # asked with a question of how far; a question on a line of its own with no speaker
        "CT: A van hit me on the ring road. How far from the exit? How fast?\nC: 3 miles.",
        "Other vehicle: white van, cut in from the left.\nSpeed?\nEstimate: 40.",
        # words before the question that name no one it is put to; a list's items, not a deposition's answers
        "Driver: A van cut in. Then He Asked, how fast were you going?\nCop: 55.",
        "A van cut in front of the ego. Note: At what speed?\na. 30 km/h\nb. 50 km/h",
    ],
    ids=[
        "his-speed",
        "a-length",
        "no-turn",
        "an-age",
        "the-limit",
        "anothers",
        "asked-in-a-story",
        "told-in-a-turn",
        "inside-another-question",
        "two-questions",
        "a-distance",
        "a-time",
        "anothers-of-its-own",
        "told-with-a-comma",
        "of-its-own-after-a-road-user",
        "of-its-own-after-its-noun",
        "with-how-far",
        "no-speakers-turn",
        "capitals-of-a-clause",
        "a-list",
    ],
)
def test_no_answer_of_the_callers_speed_reads_none(text):
    assert _ego(text) is None


# --- a bare speed set off by how one went, and number words of slow speeds ------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was going up slowly, forty, and a cyclist came down the hill in my lane.", 40),
        ("I was going past the bus, slowly, maybe forty, and a woman walked out from in front of it.", 40),
        ("I was going slowly, 40, and a cyclist came the wrong way in my lane.", 40),
        ("I was doing like twelve on the cycle path and a car pulled out of a driveway into me.", 12),
        ("I was driving up to the school, doing ten, fifteen tops, and a car pulled out right in front of me.", 12.5),
    ],
    ids=["particle-words", "place-hedged", "figures", "slow-hedged-word", "comma-range-words"],
)
def test_a_bare_speed_after_a_verb_of_going_and_how_one_went_is_the_egos(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH, abs=0.05)


@pytest.mark.parametrize(
    "text",
    [
        "I was going slowly, 3 kids ran out in front of me from behind a van.",
        "We were going home, slowly, 4 of us in the car, when a van cut in front of us.",
        "We set off at ten, and a van cut in front of us on the bypass.",
        "I was driving home carefully, seventeen and just passed my test, when a van pulled out in front of me.",
        "I was doing like ten things at once, and a cyclist came out of a side road in front of me.",
        "We were going around eleven, after the pub shut, and a car pulled out in front of us.",
        "I was driving home carefully, 17, only passed my test last month, when a van pulled out in front of me.",
        "We were going home slowly, 4, 5 of us in the car, when a van cut in front of us.",
        "I was driving slowly, twenty, thirty metres behind the van when it braked hard and I hit it.",
    ],
    ids=[
        "a-count",
        "a-count-of",
        "a-clock",
        "an-age",
        "things-done",
        "an-hour-going",
        "an-age-figures",
        "a-range-of-us",
        "a-range-of-metres",
    ],
)
def test_a_count_or_an_hour_after_how_one_went_is_no_speed(text):
    assert _ego(text) is None


# --- the vehicles a call asks for or sends are no road users ----------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist pulled out in front of me and I nearly hit him. Can I get an ambulance? He's holding his arm.",
        "CT: I'm sending an ambulance.\nC: A cyclist pulled out in front of me, I nearly hit him.",
        "Ambulance service, is the patient breathing? Yes, a cyclist pulled out in front of me.",
        "A cyclist pulled out in front of me. Do you want an ambulance? I asked him. He said no.",
        "A cyclist pulled out in front of me and I nearly hit him. I've got a fire engine started my way.",
        "CT: Ambulance, is the patient breathing?\nC: Yes, she's breathing. Cyclist. We've collided, I was passing "
        "her and she turned right across me without a signal.",
        "CT: Emergency, which service?\nC: Ambulance. Cyclist. We've collided, I was passing her and she turned "
        "right across me without a signal.",
    ],
    ids=["get", "send", "service", "want", "got-started", "service-named", "service-asked-for"],
)
def test_a_vehicle_asked_for_or_sent_is_no_road_user(text):
    assert _kinds(text) == ["bicycle"]


@pytest.mark.parametrize(
    "text",
    [
        "I was stopped at the lights when an ambulance came through the red with its sirens on.",
        "I've got an ambulance behind me and a cyclist pulled out in front of me.",
        "We need a bigger car, my wife said, as an ambulance cut across our lane on the ring road.",
        "I needed the ambulance behind me to get through so I mounted the kerb.",
        "Ambulance, blue lights on, came through the red and hit the back of a bus.",
        "Other vehicle: Ambulance. Came through the red light and hit my passenger side.",
        "We couldn't get a fire engine down the street because a van was parked across both lanes.",
    ],
    ids=[
        "on-the-road",
        "got-behind",
        "need-another",
        "needed-the-one-there",
        "opening-a-sentence",
        "a-field",
        "get-placed",
    ],
)
def test_an_ambulance_on_the_road_stays_a_road_user(text):
    assert "van" in _kinds(text)


# --- the police of a km/h country set the unit of a bare speed --------------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("About a mile past the village I was doing eighty and a tractor pulled out of a gate. The gardai came.", 80),
        ("On the A7 I was going maybe 130 and a truck pulled out to overtake. The Polizei took my statement.", 130),
        ("A mile past the bridge I was doing 70 and a van cut in front of me. The politie came after ten minutes.", 70),
    ],
    ids=["gardai", "polizei", "politie"],
)
def test_a_police_of_a_km_h_country_makes_a_bare_speed_km_h(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


def test_a_british_road_without_such_police_keeps_mph():
    assert _ego("On the A7 I was doing 60 and a truck pulled out to overtake.") == pytest.approx(60 * MPH)


# --- the car whose warning or braking only the ego's system gives is the ego ----------------------------------
@pytest.mark.parametrize(
    "text, kinds",
    [
        (
            "An e-scooter came off the pavement in front of me. Car beeps, flashes and does a pre-brake jerk.",
            ["e-scooter"],
        ),
        ("A cyclist turned across me. The car still flashes the red warning and gives a brake jolt.", ["bicycle"]),
        (
            "A kid on a scooter shot out of a side road. Van flashed the red light on the dash and braked itself.",
            ["e-scooter"],
        ),
        ("A jogger was running at the edge of the road. The car didn't even show her on the screen.", ["pedestrian"]),
    ],
    ids=["beeps", "flashes-red", "braked-itself", "did-not-show"],
)
def test_the_vehicle_whose_act_is_the_egos_system_is_the_ego(text, kinds):
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist turned across me and the car in front beeped at him.",
        "A cyclist turned across me. Then the car beeped at me from behind.",
        "A cyclist turned across me and a car came up behind us. Then the car flashed its lights at him.",
        "A car was waiting at the give way line. The car did nothing for a few seconds, then pulled out.",
        "A car was tailgating me. The car gave me a warning flash of its headlights and overtook me.",
        "A cyclist was ahead. Then the car beeped twice at him and pulled out around me.",
        "I was riding my e-scooter on the road. The car beeped and overtook me far too close.",
        "I was on my bike at the junction. The car did not detect me and turned into me.",
    ],
    ids=[
        "placed",
        "beeped-at",
        "its-lights",
        "brought-in-before",
        "a-warning-flash",
        "beeped-twice-at",
        "narrator-on-a-scooter",
        "narrator-on-a-bike",
    ],
)
def test_another_car_that_beeps_or_flashes_stays_a_road_user(text):
    assert "car" in _kinds(text)


# --- a setting's step or a place out of a small total is no speed ---------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Kia EV6, ACC at 3 of 5. I was doing 50 mph in lane 1 when a van cut in front of me.", 50 * MPH / KPH),
        ("Time gap set to 2 (of 4). On the motorway at 100 km/h a van cut in front of me.", 100),
        ("ACC at 3 bars, doing 60 km/h on the ring road, and a van cut in front of me.", 60),
    ],
    ids=["of-a-total", "in-brackets", "bars"],
)
def test_a_settings_step_is_no_speed(text, kph):
    assert _ego(text) == pytest.approx(kph * KPH)


def test_a_speed_out_of_its_limit_is_a_speed():
    assert _ego("I was doing 30 of 30 in the village when a cat ran out in front of me.") == pytest.approx(30 * KPH)


def test_vei_describe_keeps_a_transcripts_turns():
    """``vei describe`` reads a pasted transcript line by line, as the library does: its escapes and
    control characters go, its line breaks stay."""
    text = "CT: How fast were you going?\r\n\x1b[31mC:\x1b[0m Forty?\tNot more.\n\nC: A cyclist came the wrong way."
    said = readable_description(text)
    assert said == "CT: How fast were you going?\nC: Forty? Not more.\n\nC: A cyclist came the wrong way."
    assert _ego(said) == pytest.approx(40 * KPH)
    assert "doing" not in read(said).ignored  # (the words that say the answer as a speed are not the writer's)


@pytest.mark.parametrize(
    "text, said",
    [
        ("A cyclist came\nout of a side road on my left.", "A cyclist came out of a side road on my left."),
        ("Time: 08:10\nweather: rain\n- a van cuts in", "Time: 08:10\nweather: rain\n- a van cuts in"),
        ("A van\x1c hit me.\nIt drove off.", "A van hit me.\nIt drove off."),
    ],
    ids=["wrapped-sentence", "fields-and-items", "separator-is-no-break"],
)
def test_vei_describe_keeps_breaks_that_end_or_open_and_joins_wrapped_lines(text, said):
    assert readable_description(text) == said


@pytest.mark.parametrize(
    "text, said",
    [
        ("Examples:\n  | v | d |\n  | 70 | 45 |", "Examples:\n| v | d |\n| 70 | 45 |"),
        (
            "And a van parks on the right\n\n  # our own name for it\n  Scenario: x",
            "And a van parks on the right\n\n# our own name for it\nScenario: x",
        ),
        ("> what did the lorry do\nIt pulled out", "what did the lorry do\nIt pulled out"),
        ("> the car in front of me\n> braked hard", "the car in front of me braked hard"),
        ("the car\n\nahead of me braked hard", "the car ahead of me braked hard"),
        ("it was going at\n>50 km/h", "it was going at >50 km/h"),
        ("Near miss at the school\n\n\n\nA boy ran out", "Near miss at the school\n\nA boy ran out"),
        ("## ACC test\n\n**Purpose:** follow a van", "## ACC test\n\n**Purpose:** follow a van"),
    ],
    ids=[
        "table-rows",
        "comment-after-blank-line",
        "quoted-line",
        "quoted-wrapped-lines",
        "wrapped-over-a-blank-line",
        "more-than",
        "blank-lines-as-one",
        "markdown-title",
    ],
)
def test_vei_describe_keeps_rows_comments_and_paragraphs_and_reads_quotes_as_text(text, said):
    assert readable_description(text) == said


def test_vei_describe_reads_an_outline_as_the_library_does():
    """A feature file's Scenario Outline, pasted into ``vei describe``, is read with its Examples row's
    values, as :func:`read` reads the file as written: its table's rows each a line of their own."""
    text = (
        "Scenario Outline: Car pulls out of a minor road on the left\n"
        "  Given the ego drives at <v_ego> km/h on a rural main road\n"
        "  When a car pulls out of the minor road on the left <d> m ahead\n\n"
        "  Examples:\n    | v_ego | d  |\n    | 70    | 45 |\n"
    )
    assert _ego(readable_description(text)) == pytest.approx(70 * KPH) == pytest.approx(_ego(text))
