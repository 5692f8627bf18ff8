"""A bare speed said with a guess between its verb and its number: the way people talk ("I was doing,
I don't know, 40", "he was going I reckon 60", "we were at probably 30") and write notes ("doing max
40", "going close to 50"). The guess leaves the number a speed, in the unit the text carries.

Every wording here is written for these tests (none is from a corpus); each reading has near misses
that look alike but must not read so."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    "text",
    [
        "A bus pulled out in front of me, I was doing I think 40.",  # (a voice note)
        "A bus pulled out in front of me, I was going, I don't know, 40.",  # (talk radio)
        "A bus pulled out in front of me, I was doing, I'd say, 40.",  # (a witness)
        "A bus pulled out in front of me, I was doing I reckon 40.",  # (Australian)
        "A bus pulled out in front of me, I was doing probably 40.",  # (a text message)
        "A bus pulled out in front of me, I was travelling at perhaps 40 when it stopped.",  # (British letter)
        "A bus pulled out in front of me, I was driving at possibly 40.",  # (an insurance form)
        "A bus pulled out in front of me, I was doing, uh, 40.",  # (a transcript)
        "A bus pulled out in front of me, I was going close to 40.",  # (American)
        "A bus pulled out in front of me, I was doing max 40.",  # (Indian English)
        "A bus pulled out in front of me, I was doing barely 40.",  # (a forum post)
        "A bus pulled out in front of me, I was doing I guess 40.",
        "A bus pulled out in front of me, I was doing, what, 40?",
    ],
)
def test_a_guess_between_the_verb_and_a_bare_number_keeps_it_a_speed(text):
    assert ego_kph(text) == pytest.approx(40, abs=0.2)


def test_a_guessed_speed_of_a_road_user_is_its_own():
    text = "A car ran the red light from my right, he was going, I don't know, 60, and I braked hard."
    speeds = [a.speed_mps for a in read(text).actors]
    assert speeds and speeds[0] == pytest.approx(60 / 3.6, abs=0.1)


def test_the_guessed_number_takes_the_unit_the_text_carries():
    text = "A cyclist was riding at 12 mph ahead of me and I was doing I reckon 25 when I passed him."
    assert ego_kph(text) == pytest.approx(40.2, abs=0.2)


@pytest.mark.parametrize(
    "text",
    [
        "A bus pulled out in front of me. I think 40 people were on it.",  # (a count, no verb of going)
        "A bus pulled out in front of me, I was going to say 40 times sorry.",  # ("going to say": no going)
        "A bus pulled out in front of me while I was driving, I think 40 cars were queued behind.",
        "A bus pulled out in front of me, I was doing, what, 3 tasks at once.",  # (a count after the guess)
    ],
)
def test_a_guess_before_a_number_that_is_no_speed_reads_none(text):
    assert ego_kph(text) is None


# --- a number said with "speed" after it: how South Asian English gives a speed ----------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was going 40 speed only and one auto rickshaw cut in front.", 40),
        ("Sir I was coming 50 speed, bike came from left side and hit me.", 50),
        ("I was going with 60 speed on the flyover and a bus braked in front of me.", 60),
        ("I was driving in 30 speed near the school when a boy ran across.", 30),
        ("I was moving at 45 speed when the truck in front braked suddenly.", 45),
    ],
)
def test_a_number_with_speed_after_it_is_a_speed(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


@pytest.mark.parametrize(
    "text",
    [
        "It is a 40 speed limit road and a van pulled out in front of me.",  # (the road's limit)
        "My 5 speed gearbox jammed and a van pulled out in front of me.",  # (gears)
        "I was riding my 21 speed bike when a van pulled out in front of me.",
        "There are 3 speed bumps before the school and a van pulled out in front of me.",
    ],
)
def test_a_number_naming_a_thing_of_speed_is_no_speed(text):
    assert ego_kph(text) is None


# --- an hour of the day said bare beside a part of the day: a time, no speed --------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "Today morning, around 7, a cyclist came in front of me from the left side.",  # (Indian English)
        "At about 6 this evening a cyclist came out in front of me from the left.",
        "A cyclist came out in front of me at 9 last night with no lights.",
        "A cyclist came out in front of me yesterday at 8 in the morning.",
        "Tonight around 10 a cyclist came out in front of me with no lights.",
    ],
)
def test_a_bare_hour_beside_a_part_of_the_day_is_no_speed(text):
    r = read(text)
    assert r.ego_speed_mps is None and all(a.speed_mps is None for a in r.actors)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("This morning I was doing around 30 when a cyclist came out in front of me.", 30),
        ("Last night I was going at 50 and a cyclist came out in front of me with no lights.", 50),
        ("A cyclist came out in front of me this evening, I was at 20.", 20),
    ],
)
def test_a_speed_said_near_a_part_of_the_day_stays_a_speed(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


# --- a bare speed after the object of a passing verb: the passer's, as with a unit -----------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("A motorbike overtook us doing 100 and cut straight in.", 100),
        ("A BMW flew past me doing 90 on the inside and swerved in front.", 90),
        ("I was at 50 mph when a lorry came past me doing 60 odd and pulled in too early.", 96.6),
        ("The coach passed me going 40, then stopped suddenly in front of me.", 40),
        ("A van undertook us doing 70 and cut in.", 70),
    ],
)
def test_a_bare_speed_after_the_one_passed_is_the_passers(text, kph):
    (passer,) = read(text).actors
    assert passer.speed_mps * 3.6 == pytest.approx(kph, abs=0.2)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was doing 60 when a van overtook me and cut in.", 60),
        ("A van overtook me and cut in, I was doing 60.", 60),
        ("Going past the school doing 30, a boy ran out in front of me.", 30),
    ],
)
def test_the_egos_bare_speed_beside_a_passing_stays_the_egos(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


# --- the limit said, then its number: the speed kept to --------------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was doing the limit, seventy, when a ute pulled out of a driveway.", 70),  # (Australian, on air)
        ("I was doing the speed limit (60) when a truck pulled out of a driveway.", 60),  # (a claim form)
        ("We were sticking to the limit - 50 - when a truck pulled out of a driveway.", 50),
        ("I was driving at the limit, 100 km/h, when a truck pulled out of a driveway.", 100),
        ("Was going the limit, eighty, and a truck pulled out of a driveway.", 80),
    ],
)
def test_the_limit_kept_to_then_its_number_is_the_egos_speed(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


@pytest.mark.parametrize(
    "text",
    [
        "I was doing the limit when a truck pulled out of a driveway 30 m ahead.",
        "I was doing the limit, 3 cars behind a truck, when it braked hard.",
    ],
)
def test_the_limit_with_no_number_of_its_own_reads_no_speed(text):
    assert ego_kph(text) is None


# --- numbers in words in a guess and before "speed" ----------------------------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("A bus pulled out in front of me, I was doing, I don't know, forty.", 40),
        ("A bus pulled out in front of me, I was going probably forty.", 40),
        ("I was going on the ring road, sixty speed, and a bus braked in front of me.", 60),
    ],
)
def test_a_number_in_words_after_a_guess_or_before_speed_is_a_speed(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


# --- a number with a measure of something else after it: no speed ------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "A cyclist squeezed past me with about 50 cm to spare.",
        "A cyclist squeezed past me with about 6 inches to spare.",
        "About 20 minutes later a cyclist squeezed past me.",
        "A man of about 60 years stepped out in front of me.",
        "A lorry of about 40 tonnes pulled out in front of me.",
        "A cyclist squeezed past me at around 10 past 5.",
        "A cyclist squeezed past me, I had been driving for about 45 mins.",
    ],
)
def test_a_number_measuring_something_else_is_no_speed(text):
    r = read(text)
    assert r.ego_speed_mps is None and all(a.speed_mps is None for a in r.actors)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was doing about 30 past the school when a cyclist squeezed past me.", 30),
        ("I was doing about 30 in the rain when a cyclist squeezed past me.", 30),
    ],
)
def test_a_speed_before_a_place_is_still_a_speed(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


# --- telegraphic notes: "<who> at <number>" opening a clause is that one's speed, with a unit or bare ---------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("Lead car at 50, me at 60, 2 second gap, and it brakes hard.", 60),
        ("Truck ahead at 80, us at 100, it pulls out to pass a caravan.", 100),
        ("Him at 30, me at 50, he turned right across my lane.", 50),
        ("Bus in front at 40. Me at 50. It stopped without warning.", 50),
        ("Ego at 70, target at 40, cut-in at 20 m.", 70),
    ],
)
def test_a_bare_speed_after_the_ego_opening_a_note_is_the_egos(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


def test_a_bare_speed_after_a_road_user_opening_a_clause_is_its_own():
    (van,) = read("The van at 60 overtakes me and cuts in.").actors
    assert van.speed_mps * 3.6 == pytest.approx(60, abs=0.2)


def test_a_bare_speed_after_the_ego_as_an_object_is_not_said_of_it():
    assert ego_kph("A bus pulled out at 20 and stopped in front of me at 9 metres.") is None


# --- the ego at rest said by a motion denied: speed 0 --------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "I wasn't moving at all when the bus reversed into me.",
        "We weren't moving when a van hit us from behind.",
        "I was not moving, waiting to turn right, when a cyclist hit my door.",  # (a statement)
        "We were not moving at the time the lorry ran into the back of us.",  # (British)
        "Honestly I was not moving, just sitting in traffic, when a van hit me.",
    ],
)
def test_the_ego_not_moving_as_the_scene_opens_is_at_rest(text):
    assert ego_kph(text) == 0


@pytest.mark.parametrize(
    "text",
    [
        "The van wasn't moving when I hit it.",  # (the van stands, not the ego)
        "I wasn't going to stop, so I swerved round the van.",  # (an intention, no state)
        "A man was standing in the road and I swerved round him.",  # (the man stands)
    ],
)
def test_someone_else_standing_or_a_denied_intention_is_not_the_ego_at_rest(text):
    assert ego_kph(text) != 0
