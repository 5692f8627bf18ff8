"""Readings of clauses that put a place, a participle or a state where the reader's usual order does
not: a place before its verb and the road user after it (as machine translations from German, Polish
or Turkish and some English say it), a narrator's opening participle with a bare speed after another
sentence, and a state of the ego held "the whole time" told after what others did."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _actor(reading, kind):
    return next(a for a in reading.actors if a.kind == kind)


@pytest.mark.parametrize(
    ("text", "kind", "behaviour", "speed_kph"),
    [
        (
            "The test car drives with 50 km/h straight through the junction. From the opposite direction comes a "
            "cyclist with 18 km/h and at the junction he turns to his left in front of the test car.",
            "bicycle",
            "turn_across",
            18,
        ),
        (
            "We were driving at 40 km/h. Out of the car park on the right shot a van at 15 km/h and it stopped "
            "hard in our lane.",
            "van",
            "sudden_stop",
            15,
        ),
    ],
)
def test_a_road_user_after_its_verb_is_the_subject_of_what_follows(text, kind, behaviour, speed_kph):
    reading = read(text)
    actor = _actor(reading, kind)
    assert behaviour in [b[0] for b in actor.behaviours]
    assert actor.speed_mps == pytest.approx(speed_kph / 3.6)
    assert reading.ego_speed_mps != pytest.approx(speed_kph / 3.6)


def test_a_vehicle_said_after_its_verb_behind_us_is_behind():
    reading = read(
        "My car goes at 50 km/h in the right lane. Behind us drove a minibus very close, which then braked hard."
    )
    bus = reading.actors[0]
    assert bus.relation == "behind" and "sudden_stop" in [b[0] for b in bus.behaviours]


def test_a_time_said_first_stays_first():
    reading = read(
        "I turned right on green. At that moment came a cyclist from behind on the cycle path at my right side, "
        "through the red light."
    )
    assert reading.actors[0].relation in ("behind", "right", "roadside_right")


@pytest.mark.parametrize(
    "text",
    [
        "At the lights passed a cyclist on the left and carried on.",  # (the narrator passed: no subject said)
        "On the way home drove a hire van to the depot at 30 mph.",  # (the narrator drove it)
        "In the lane the car followed a cyclist for a while.",  # (the car follows)
    ],
)
def test_a_clause_that_drops_its_subject_is_not_turned_round(text):
    from vei_scenario.language.located_first import said_in_order
    from vei_scenario.language.reader import _actor_noun_in

    assert said_in_order(text.lower(), _actor_noun_in) == text.lower()


def test_a_narrators_opening_participle_with_a_bare_speed_after_another_sentence():
    reading = read(
        "Bus driver brakes for nothing. Doing about 30 along the seafront, a lad on a hire scooter pulls out "
        "from the kerb on my left."
    )
    assert reading.ego_speed_mps == pytest.approx(30 / 3.6)
    assert _actor(reading, "e-scooter").speed_mps is None


@pytest.mark.parametrize(
    "text",
    [
        "A taxi came past me on the outside and cut across. I was stationary the whole time.",
        "A cyclist squeezed past on my left, far too close. I was stopped at the time.",
        "A van reversed into my front bumper. We were parked there the whole time.",
        "A courier on a bike caught my wing mirror as he went by. I was stopped at the time.",
        "The e-scooter rider struck the side of my car. We were stationary at that point.",
    ],
)
def test_a_state_held_the_whole_time_is_the_ego_at_rest(text):
    assert read(text).ego_speed_mps == 0.0


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist swerved out in front of me and I was stopped just in time.",  # (a stop in reply)
        "A van pulled out on me. I stopped and waited for him to clear.",
        "A cyclist caught my wing mirror as he went by. I stopped a bit further on to check it.",
    ],
)
def test_a_stop_made_in_reply_is_no_state_held(text):
    assert read(text).ego_speed_mps != 0.0


@pytest.mark.parametrize(
    "text",
    [
        "Out of the fog came a tractor on my side of the road and I swerved.",
        "Out of nowhere came a taxi and cut straight in front of me.",
    ],
)
def test_a_road_user_out_of_sight_is_not_turned_into_one_pulling_out_of_a_place(text):
    from vei_scenario.language.located_first import said_in_order
    from vei_scenario.language.reader import _actor_noun_in

    assert said_in_order(text.lower(), _actor_noun_in) == text.lower()


@pytest.mark.parametrize(
    ("text", "kind", "behaviour"),
    [
        ("Behind the lorry was a cyclist who pulled out into my lane without looking.", "bicycle", "cut_in"),
        ("In front of me was a van which stopped suddenly, and I went into the back of it.", "van", "sudden_stop"),
    ],
)
def test_a_relative_clause_after_the_road_user_stays_its_own(text, kind, behaviour):
    reading = read(text)
    assert [b[0] for b in _actor(reading, kind).behaviours] == [behaviour]
    assert all(a.kind == kind for a in reading.actors)
