"""What a road user in or beside the ego's lane does, told apart from what only happened to it or what
the ego did: a collision nearly had is the outcome, not a fall or a stop of the road user's; a hard
braking said as a noun a road user makes is its hard stop. Wordings written for each construction in
the styles of different writers, none taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _behaviours(text: str) -> list[str]:
    """The behaviours of the one road user ``text`` names."""
    (actor,) = read(text).actors
    return [b[0] for b in actor.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "ego turn right at the crossroads, oncoming van go straight, nearly crash.",
        "I was turning left at the junction when an oncoming lorry kept coming, we almost crashed.",
        "Oncoming car carried straight on through the junction as I turned; very nearly collided.",
        "Turning right at 15 km/h, the oncoming motorbike didn't slow and we were almost colliding.",
        "test: ego turns left across an oncoming SUV at the intersection; SUV continues straight; almost crash",
    ],
)
def test_a_crash_nearly_had_is_no_stop_of_the_road_user(text):
    assert "sudden_stop" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist ahead of me at 20 km/h hit a pothole and crashed.",
        "The moped rider in front lost control and crashed onto the road while I was doing 30 mph.",
    ],
)
def test_a_crash_of_its_own_is_still_its_fall(text):
    assert "sudden_stop" in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "The ego vehicle drives at 100 km/h. A truck in front makes an emergency braking.",
        "I'm at 80 km/h behind a bus when the bus make an emergency braking.",
        "Ego 60 km/h; the lead vehicle performs a hard braking to standstill.",
        "Following a van at 50 mph, it did a full emergency braking right in front of me.",
        "The car ahead of the ego initiates heavy braking at 70 km/h.",
        "We were doing 90 behind a tanker which suddenly applied emergency braking.",
    ],
)
def test_a_hard_braking_made_is_a_hard_stop(text):
    assert _behaviours(text) == ["sudden_stop"]


@pytest.mark.parametrize(
    "text",
    [
        "The ego vehicle drives at 50 km/h. A bus in front makes a stop at the bus stop.",
        "I'm at 40 km/h behind a van which makes a gentle braking before the lights.",
    ],
)
def test_a_gentle_braking_or_a_stop_made_is_no_hard_stop(text):
    assert "sudden_stop" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 30 when a cyclist swerved in front of me. Did an emergency stop, no contact.",
        "Doing 40 mph, a van cut in ahead of me. Made an emergency braking and missed it.",
        "We were at 50 km/h when a moped pulled out in front of us. Performed a hard stop, all fine.",
        "Was doing about 25 when a kid on a scooter swung into my lane. Did an emergency stop.",
        "I'm at 60 km/h; a car cuts in front of me. Do an emergency stop!",
    ],
)
def test_the_narrators_hard_stop_said_as_a_noun_is_not_the_road_users(text):
    assert "sudden_stop" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist was riding ahead of the tram at 20 km/h and wobbled. Emergency brake applied; no contact.",
        "Bus at 30 km/h. A cyclist in front of the bus rode along the kerb. Brakes applied hard, no contact.",
        "Tram at 25 km/h, a pedestrian walked along the tracks ahead. The emergency brakes were applied at once.",
        "Test vehicle at 15 m/s; target car ahead in the same lane. Emergency braking initiated, stopped 2 m short.",
        "Van at 40 mph, a cyclist riding ahead. Evasive braking performed; safe.",
    ],
)
def test_a_reaction_said_in_the_passive_with_no_agent_is_the_egos(text):
    assert "sudden_stop" not in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 70 km/h behind a bus. The bus carried out an emergency stop.",
        "I'm doing 50 km/h behind a lorry when the lorry performed an emergency stop.",
        "Ego at 80 km/h following a car; the car made an emergency braking.",
    ],
)
def test_a_hard_stop_said_of_the_road_user_stays_its_own(text):
    assert "sudden_stop" in _behaviours(text)


@pytest.mark.parametrize(
    "text",
    [
        "I'm behind a bus at 30 km/h on the high street; it pulls in and stops at the next stop.",
        "Ego follows a city bus at ~20 m, 40 km/h. Bus pulls in and stops at its stop.",
        "we were behind a taxi doing 25 km/h, it pulled in and stopped to let a passenger out",
        "Following a delivery van at 20 mph, the van drew in and halted outside a shop.",
        "Behind a van at 30 km/h on a high street; the van pulls in, then stops.",
    ],
)
def test_pulling_in_to_stop_is_a_stop_at_the_kerb(text):
    assert _behaviours(text) == ["stop"]


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 40 km/h when a car from the right lane pulled in and braked.",
        "I was doing 40 km/h when a car pulled in right in front of me and stopped.",
        "At 50 km/h on the dual carriageway, a van pulled in ahead of me from the outside lane.",
    ],
)
def test_pulling_in_before_the_ego_stays_a_cut_in(text):
    assert _behaviours(text)[0] == "cut_in"


@pytest.mark.parametrize(
    "text",
    [
        "scenario: bike_follow_overtake_07\nego speed 40 km/h\ncyclist 25 m ahead in ego lane at 15 km/h",
        "Test ID cyclist_cutin_hardbrake_2. A cyclist rides 20 m ahead of the ego at 15 km/h; ego at 30 km/h.",
        "run: ped_follow_pass_11 | the ego at 20 km/h | a cyclist riding ahead along the kerb at 12 km/h",
    ],
)
def test_the_words_of_a_scenario_identifier_are_no_behaviour(text):
    assert _behaviours(text) == ["along_road"]


def test_a_numbered_road_user_keeps_its_noun():
    assert [a.kind for a in read("Ego at 50 km/h. car_1 cuts in from the left lane 15 m ahead.").actors] == ["car"]


def _oncoming(text: str) -> list[str]:
    """The behaviours of the road user ``text`` says comes the other way."""
    (actor,) = [a for a in read(text).actors if a.relation == "oncoming"]
    return [b[0] for b in actor.behaviours]


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 60 km/h behind a tractor. Once the oncoming bus had passed, ego overtook the tractor.",
        "I was doing 50 on a country lane; a car coming the other way passed, then I overtook the horse rider.",
        "A van approaches in the opposite lane at 80 km/h. The ego passes the cyclist after the van has passed.",
        "at 40 mph behind a tractor, waited for an oncoming lorry which went past, then overtook",
        "Ego 70 km/h behind a cyclist. An oncoming truck passes by, then the ego overtakes the cyclist.",
    ],
)
def test_an_oncoming_road_user_that_passes_no_one_goes_by(text):
    assert _oncoming(text) == ["keep_lane"]


@pytest.mark.parametrize(
    "text",
    [
        "I was doing 60 on a country road when an oncoming car pulled out to overtake and came at me in my lane.",
        "I was doing 60 on a country road when a car coming the other way overtook and ended up in my lane.",
    ],
)
def test_an_oncoming_overtaker_still_comes_into_the_egos_lane(text):
    assert _oncoming(text) == ["wrong_way"]


@pytest.mark.parametrize(
    "text",
    [
        "ego on ACC following lead veh (grey SUV) at 2 s, both 80 km/h; lead hard brakes to 0",
        "ego following a car at 50 km/h, 15 m gap; then the lead suddenly stops.",
        "Ego behind a bus at 30 km/h. Lead brakes hard.",
        "AEB run: ego 60 km/h, lead car 30 m ahead at 60 km/h; leader slams on the brakes.",
    ],
)
def test_lead_said_alone_as_the_subject_is_the_lead_vehicle(text):
    assert _behaviours(text) == ["sudden_stop"]


@pytest.mark.parametrize(
    "text",
    [
        "Ego at 50 km/h following a van. Braking late could lead to a crash.",
        "ego 60 km/h, lead 40 m ahead at 60 km/h, constant speed.",
    ],
)
def test_lead_as_a_verb_or_a_place_is_no_new_subject(text):
    assert "sudden_stop" not in _behaviours(text)


def test_a_road_user_coming_head_on_in_the_egos_lane_that_passes_is_still_the_wrong_way_driver():
    text = (
        "I was heading north at 40 mph in lane 1 when a lorry came southbound towards me, head-on in my lane. "
        "I moved over to lane 2 and the lorry passed without touching me."
    )
    assert "keep_lane" not in [b[0] for a in read(text).actors for b in a.behaviours]


def test_an_oncoming_road_user_that_passes_something_named_is_no_one_going_by():
    reading = read("A bus passed a parked lorry and was coming straight at us.")
    assert [b[0] for b in reading.actors[0].behaviours] == ["wrong_way"]
