"""The forms of test cases and study protocols: the outcome an event is designed for, Gherkin Scenario
Outlines filled in from their Examples table, and a title or step that tells the ego what to do.
Wordings written for these tests."""

from __future__ import annotations

import pytest

from vei_scenario.language.designed_outcome import designed_outcome
from vei_scenario.language.gherkin_outline import filled_outline
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        # the class designed, over what one participant's run or a wish says
        (
            "A van pulls out of the side road on the right. The event is designed as a near miss; most drivers "
            "stopped, two hit the van.",
            "near_miss",
        ),
        (
            "Event 3 was scripted as a near-crash: a cyclist crosses from the left kerb 20 m ahead, and a crash "
            "is not wanted.",
            "near_miss",
        ),
        (
            "A child runs out from between parked cars. The timing was intended to be just avoidable with an "
            "immediate full stop; P12 still struck the child.",
            "near_miss",
        ),
        ("A jogger crosses at the zebra from the right when the car is 70 m away. No criticality intended.", "safe"),
        (
            "Baseline drive: a lorry ahead slows for a junction. The event is intended as a benign control event, "
            "all drivers braked hard anyway.",
            "safe",
        ),
        (
            "A scooter rider rides off the kerb into the lane 8 m ahead of the car. Contact was unavoidable by "
            "design, for the airbag study.",
            "collision",
        ),
        (
            "The hatchback runs the red light from the left; the run was planned so that the collision is "
            "unavoidable without braking.",
            "collision",
        ),
    ],
)
def test_the_class_an_event_is_designed_for_is_its_intent(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("A cyclist pulled out and I hit him. The AEB is designed to help avoid collisions.", "collision"),
        ("With ACC set to 100 km/h a car cut in 20 m ahead and I braked hard, missing it by a metre.", "near_miss"),
        ("A pedestrian stepped out and the car stopped well short, as intended.", "safe"),
    ],
)
def test_design_said_of_something_else_leaves_the_outcome_as_told(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    ("tokens", "found"),
    [
        # what the design is for names no class: collision words of a test's purpose
        ("the run was tuned so that the time to collision at onset is 1.4 s .", None),
        ("this case is intended to assess collision avoidance by the aeb .", None),
        ("the test is designed to check whether an impact occurs .", None),
        # denied, or said of a thing, not the event
        ("the event is not designed as a near miss .", None),
        ("the roundabout was designed as a benign low-speed zone .", None),
        ("the warning is designed as a benign nudge .", None),
        ("acc set to 100 km/h .", None),
        # backwards only right before it
        ("the kerb is benign as intended .", None),
        ("damage non-critical by design of the bumper .", None),
        ("no criticality intended .", "safe"),
        # two designs: a redesign wins, two events that disagree say nothing, a contrast tells what happened
        ("originally designed as a near miss , the case was re-parameterised as a collision .", "collision"),
        ("event 1 intended as a near miss . event 2 intended as benign .", None),
        ("designed as a near miss but actually it ended in a collision .", None),
        ("the event was designed as a near miss .", "near_miss"),
        ("designed such that the impact is unavoidable .", "collision"),
        ("a van , designed as non-critical ; drivers just let it in", "safe"),
        ("the aeb is designed to prevent a crash .", None),
        ("designed , as you know , by a team in turin : a near miss happened", None),
        ("a near miss , not intended", None),
    ],
)
def test_designed_outcome_reads_only_what_the_design_is_for(tokens, found):
    assert designed_outcome(tokens.split()) == found


OUTLINE = """Scenario Outline: Lead car brakes
  Given the ego follows a lead car at <v_ego> km/h with a gap of <gap> m
  When the lead car brakes at <decel> m/s^2
  Then <result>

  Examples:
    | v_ego | gap | decel | result                      |
    | 64    | 22  | 6     | the ego stops without contact |
    | 80    | 30  | 8     | the ego hits the lead car   |
"""


def test_an_outline_is_filled_from_the_first_row_of_its_examples():
    filled = filled_outline(OUTLINE)
    assert "at 64 km/h with a gap of 22 m" in filled and "Then the ego stops without contact" in filled
    assert "Examples" not in filled and "|" not in filled and "80" not in filled


def test_an_outline_is_read_with_its_row_s_values():
    r = read(OUTLINE)
    assert round(r.ego_speed_mps * 3.6) == 64
    assert [a.kind for a in r.actors] == ["car"] and r.actors[0].distance_m == 22
    assert r.intent != "collision"


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist <rider> crossed in front of me.",  # (no table)
        "A car at <v> mph cut in.\nExamples:\n| v | w |\n",  # (a header and no row)
        "A van at <v> mph.\nExamples:\n| v | w |\n| 30 |\n",  # (a row that does not fit its header)
    ],
)
def test_text_that_is_no_outline_is_left_as_it_is(text):
    assert filled_outline(text) == text


def test_a_placeholder_no_row_names_stays_as_it_is():
    filled = filled_outline("The van at <x> km/h, the rider at <v> km/h.\nScenarios:\n| v | w |\n| 12 | 3 |\n")
    assert filled == "The van at <x> km/h, the rider at 12 km/h."


@pytest.mark.parametrize(
    ("text", "kind", "relation"),
    [
        ("Follow a braking lorry at 2 s headway.", "truck", "ahead"),
        ("Step 2: overtake a cyclist riding at 15 km/h with at least 1.5 m clearance.", "bicycle", "ahead"),
        (
            "TC-114  Follow a slowing lorry\nThe VUT drives behind a lorry at 70 km/h; the lorry slows to 40 km/h.",
            "truck",
            "ahead",
        ),
        (
            "Overtake a slow cyclist on the climb\nThe car drives at 60 km/h and a cyclist rides ahead at 18 km/h.",
            "bicycle",
            "ahead",
        ),
        (
            "Objective: approach a broken-down van\nThe test car drives at 80 km/h; a van stands 120 m ahead.",
            "van",
            "ahead",
        ),
    ],
)
def test_a_title_that_tells_the_ego_what_to_do_names_the_road_user_it_is_done_to(text, kind, relation):
    r = read(text)
    assert [(a.kind, a.relation) for a in r.actors] == [(kind, relation)]
    assert all(b[0] not in ("follow_vehicle", "overtake") for b in r.actors[0].behaviours)


@pytest.mark.parametrize(
    "text",
    [
        "Pass criteria: a cyclist crosses 20 m ahead and the ego stops.",
        "Follow-up: a van pulled out of the side road on the left.",
        "A van will follow the ego at 10 m and overtake it.",
        "Detection range test",
    ],
)
def test_no_command_where_none_is_given(text):
    from vei_scenario.language.imperative import imperative_as_ego

    assert imperative_as_ego(text.lower()) == text.lower()


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        (
            "A cyclist rides ahead in the lane at 15 km/h, VUT at 50 km/h. Expected: AEB full braking, the VUT "
            "stops behind the cyclist, no impact.",
            "near_miss",
        ),
        (
            "VUT 40 km/h, a van stands in the lane. Pass if the AEB brakes hard and the VUT stays clear of the van.",
            "near_miss",
        ),
        (
            "A child runs out from behind a parked van 15 m ahead. Expected: AEB full braking, the car stops 1 m "
            "before the dummy, no contact.",
            "near_miss",
        ),
        (
            "The cyclist swerves into the lane 10 m ahead; the AEB brakes hard and the VUT stops short of him.",
            "near_miss",
        ),
        (
            "A pedestrian crosses from the left 25 m ahead at 5 km/h. Pass: emergency braking by the AEB, no impact.",
            "near_miss",
        ),
        ("A van slows down gently ahead; the ACC brakes gently and keeps the gap, no warning.", "safe"),
        ("A scooter crossed from the right. The AEB did not brake and the car hit the scooter.", "collision"),
    ],
)
def test_the_ego_s_own_emergency_brake_braking_is_the_ego_s_escape(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text",
    [
        "FP-31: a cyclist rides along the verge on the right at 15 km/h, VUT 70 km/h. Pass criteria: no FCW, "
        "no AEB activation.",
        "Scenario: parked van on the left\n  Given the VUT drives at 40 km/h past a van parked on the left\n"
        "  Then the AEB shall not activate\n  And no warning shall be issued",
        "A walker stands at the kerb on the right, 30 m ahead. Expected result:\n- no false activation\n"
        "- the car keeps its 50 km/h",
    ],
)
def test_an_expected_result_that_the_ego_s_systems_stay_quiet_is_a_safe_pass(text):
    assert read(text).intent == "safe"


@pytest.mark.parametrize(
    "text",
    [
        "A van pulls out with no warning 15 m ahead; the SuT shall brake hard and stop.",
        "AEB test with no driver intervention: a child runs out from the right 12 m ahead. Expected: no collision.",
        "Hazard: no AEB intervention when a cyclist crosses from the right in front of the HV.",
        "A cyclist pulled out in front of me, no FCW, I braked hard and stopped a foot short.",
    ],
)
def test_a_missing_warning_that_is_no_expected_result_is_no_safe_pass(text):
    assert read(text).intent != "safe"


def test_every_examples_block_goes_and_each_outline_takes_its_own_first_row():
    text = (
        "Scenario Outline: Pedestrian from the right\r\n"
        "  Given the ego drives at <v> km/h\r\n"
        "  When a pedestrian crosses <d> m ahead\r\n"
        "  Then the ego <result>\r\n"
        "  Examples: nominal\r\n"
        "    # speeds from the test plan\r\n"
        "    | v  | d  | result          |\r\n"
        "    |----|----|-----------------|\r\n"
        "    | 40 | 25 | stops in time   |\r\n"
        "  Examples: edge\r\n"
        "    | v  | d  | result            |\r\n"
        "    | 60 | 8  | hits the pedestrian |\r\n"
        "Scenario Outline: Cyclist ahead\n"
        "  Given a cyclist rides ahead at <w> km/h\n"
        "  Examples:\n"
        "    | w  |\n"
        "    | 18 |\n"
    )
    filled = filled_outline(text)
    assert "drives at 40 km/h" in filled and "crosses 25 m ahead" in filled and "the ego stops in time" in filled
    assert "rides ahead at 18 km/h" in filled
    assert "|" not in filled and "hits" not in filled and "<" not in filled and "\r" not in filled


def test_a_traffic_participant_is_no_ego():
    r = read("Another traffic participant stepped off the kerb on the right in front of me.")
    assert [a.kind for a in r.actors] == ["pedestrian"]


@pytest.mark.parametrize(
    "text",
    [
        "cyclist: pass the ego on the left while it waits at the lights.",  # (a road user's line)
        "target car: overtake the vut at 90 km/h and cut in 12 m ahead.",
        "a van was trying to\novertake a cyclist on the bend when it swerved.",  # (prose wrapped mid-sentence)
        "follow the signs for the ring road and at the roundabout a lorry cut in.",  # (no road user after it)
    ],
)
def test_a_command_that_is_not_the_ego_s_is_left_as_it_is(text):
    from vei_scenario.language.imperative import imperative_as_ego

    assert imperative_as_ego(text) == text


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("A car cuts in 40 m ahead of us on the motorway and the ACC brakes to keep its distance.", None),
        ("Their AEB braked hard when the cyclist came out; we were well behind them and stopped fine.", "safe"),
        ("It was meant to be a quiet Sunday drive, but a van pulled out of a side road and hit me.", "collision"),
        ("The run was set to be non-critical, but the car still hit the target at 15 km/h.", "collision"),
        ("The jogger then stepped out from between two parked vans, giving no warning at all.", None),
        ("Then the lead car carries on at 20 km/h, no braking, while the ego closes in from 80 m.", None),
    ],
)
def test_words_of_a_test_said_in_a_story_leave_its_outcome_as_told(text, intent):
    assert read(text).intent == intent


@pytest.mark.parametrize(
    "text",
    [
        "REQ-41: When a car in the right lane changes into the ego lane 25 m ahead, the ACC shall reduce speed "
        "without triggering a collision warning.",
        "TC-12 | bus pulls out of a stop on the right 60 m ahead, ego 50 km/h | Expected: gentle decel, "
        "max 1.5 m/s2, no takeover",
        "SR-7: When a walker steps onto the zebra ahead while the ego approaches at 20 mph, the system shall "
        "bring the ego to a controlled stop before the line.",
        "While the ego follows a tractor at 40 km/h on a country lane, when the tractor turns off, the ACC shall"
        " adapt speed smoothly.",
        "Postconditions: the ego has passed the cyclist riding at the kerb without FCW.",
        "A cyclist crosses 40 m ahead of the ego at 30 km/h. Expected: controlled stop, no crash alert.",
        "A van cuts in 30 m ahead. Expected: comfortable braking; time to collision stays above 3 s.",
    ],
    ids=[
        "without-collision-warning",
        "gentle-decel",
        "controlled-stop",
        "adapt-speed-smoothly",
        "without-fcw",
        "no-crash-alert",
        "time-to-collision",
    ],
)
def test_an_expected_everyday_response_of_the_ego_is_a_safe_pass(text):
    """A requirement or expected result that the ego responds as in everyday driving (smoothly, to a
    controlled stop, with no warning of its own) makes the case a safe pass."""
    assert read(text).intent == "safe"


@pytest.mark.parametrize(
    "text",
    [
        "A scooter shot out without warning 8 m ahead of me and I slowed smoothly, but still clipped him.",
        "Expected: the AEB performs an emergency stop without a collision warning when the child runs out.",
        "The van ahead slowed smoothly, then a cyclist cut in and I braked hard, stopping a foot short.",
        "Expected result: the ego brakes smoothly but the e-scooter still hits its front wing.",
        "REQ-9: When a lorry cuts in 6 m ahead, the AEB shall brake hard to avoid contact without a takeover request.",
    ],
    ids=["story-not-expected", "emergency-stop", "another-slows-smoothly", "contact-said", "hard-in-the-sentence"],
)
def test_a_smooth_or_silent_response_said_outside_an_expectation_or_beside_a_hard_one_is_no_safe_pass(text):
    assert read(text).intent != "safe"


@pytest.mark.parametrize(
    "text",
    [
        "A boy runs out between parked cars 12 m ahead of the ego at 30 km/h. Expected: the AEB activates and"
        " the ego comes to a controlled stop.",
        "A car ahead at 70 km/h stops suddenly. Expected result: after the FCW the ego makes a controlled stop.",
        "A van cuts in 6 m ahead. Expected: the ego avoids it with moderate braking and an evasive swerve.",
        "A walker crosses 20 m ahead of the ego at 40 km/h. Expected: the ego keeps a gap of at least 1 m to"
        " the walker.",
        "I expected the van to keep its gap, but it braked hard 8 m ahead of me at 50 km/h.",
        "The lead car brakes at 8 m/s2. The planner shall not brake later than 0.5 s after it.",
        "The assistant shall not brake unless the TTC to the cyclist ahead is below 2 s.",
        "Test conditions shall be: smooth dry asphalt. A child dummy crosses from the nearside at 5 km/h."
        " Expected result: the vehicle shall stop before the dummy.",
        "The test shall be run in moderate rain. A walker steps out from behind a parked van 15 m ahead.",
        "Precondition: the ACC shall maintain the set time gap of 1.8 s. The lead car then brakes at 8 m/s2."
        " Expected: FCW followed by AEB.",
        "The test driver shall not brake during the run; the target car cuts in 8 m ahead.",
        "Target car brakes at 6 m/s2 in front of the ego at 60 km/h. Expected result: the ego comes to a"
        " controlled stop, collision avoided.",
        "Ego at 50 km/h, a child runs out 8 m ahead. Expected: controlled stop, no contact.",
    ],
    ids=[
        "aeb-activates",
        "after-the-fcw",
        "evasive",
        "least-distance",
        "i-expected",
        "not-later-than",
        "unless",
        "smooth-asphalt",
        "moderate-rain",
        "keeps-the-gap-then-aeb",
        "a-driver-shall-not-brake",
        "collision-avoided",
        "no-contact",
    ],
)
def test_a_response_beyond_everyday_driving_a_bound_or_a_story_s_expectation_is_no_safe_pass(text):
    """A smooth word beside a warning, the emergency brake or an evasive move, a least distance to
    someone, a story's "I expected", and a bound on braking ("not later than", "unless") are no
    expected quiet."""
    assert read(text).intent != "safe"
