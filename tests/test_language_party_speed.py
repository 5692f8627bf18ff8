"""The ego's speed said where its sentence does not name the ego as its subject the usual way.

- One of the narrator's party at the wheel, where the sentence does not open on them: after a time
  ("Last night my son was driving home, maybe 25 km/h"), with an adverb before the verb ("Mum was
  probably going 30 km/h"), in an aside after their name ("Jen, driving us to work at 30 km/h, ..."),
  or in a note after the verb. The one of the party who drives drives the narrator's vehicle, the ego.
- A sentence with no subject and no verb, only where and how fast, before "when" and what happened
  ("Already on the roundabout at about 30 km/h when a taxi came in"): the narrator's.
- The reader addressed with what they will or must do ("You'll be driving at around 80 km/h").

Every wording here is written for these tests (none is from a corpus); each reading has near misses
that look alike but must not read so: the party member as an object or after a preposition, a road
user as the subject, one the party follows (its speed stays its own), "you" told what they may do."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph, kinds
from vei_scenario.language.reader import read


# --- after a time that opens the sentence, a road user named before -----------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("A scooter rider keeps racing up our street at night. Last night my son was driving home, maybe 25 km/h,"
         " and it came round the bend at him.", 25),
        ("A lorry was parked half on the pavement. On Friday my wife was doing about 50 km/h past it when a cyclist"
         " pulled out in front of her.", 50),
        ("There is a boda boda that rides on the wrong side here. This morning our daughter was going around 40 km/h"
         " and it came straight at her.", 40),
        ("Kids on bikes use our road as a racetrack. Yesterday evening my dad was driving at 30 mph down it when one"
         " shot out.", 48.3),
    ],
    ids=["last-night-note", "on-friday", "this-morning", "yesterday-evening"],
)  # fmt: skip
def test_the_partys_speed_after_a_time_is_the_egos(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("A bus pulled out right in front of us. My mum was probably going 30 km/h at most.", 30),
        ("A van reversed out of a drive into our path. Our dad was maybe doing 20 km/h.", 20),
    ],
    ids=["probably", "maybe"],
)
def test_an_adverb_before_the_partys_verb_keeps_it_theirs(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("An e-scooter rider on the shared path went straight across the road. Jen, driving us to work at 30 km/h,"
         " had to brake hard.", 30),
        ("A kid on a bike came off the pavement. Grandma, going maybe 20 mph past the school, stopped our car just in"
         " time.", 32.2),
    ],
    ids=["first-name", "grandma"],
)  # fmt: skip
def test_the_partys_speed_in_an_aside_after_their_name_is_the_egos(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("A scooter rider keeps racing up our street. Last night a van overtook my son, doing maybe 70 km/h.", 70),
        ("A cyclist was on the kerb. The car in front of my husband was doing 60 km/h when it braked hard.", 60),
        ("A lorry was parked on the corner. Last week a van hit my dad, going 60 km/h, near our house.", 60),
    ],
    ids=["object-of-a-verb", "after-a-preposition", "object-then-aside"],
)  # fmt: skip
def test_a_speed_not_said_of_the_party_at_the_wheel_is_not_the_egos(text, kph):
    assert ego_kph(text) != pytest.approx(kph, abs=0.2)


# --- a sentence with no subject and no verb, only where and how fast, before what happened ----------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("A bus was stopped at the kerb. Already on the roundabout at about 30 km/h when a taxi came in from the"
         " left.", 30),
        ("Van cut me up today. On the M6 at 70 mph when a white van swerved across from lane two.", 112.7),
        ("Kids on bikes everywhere. Just past the school, maybe 30 km/h, when one of them rode out from the left.",
         30),
        ("A lorry was parked on the bridge. Halfway over it at 50 km/h as a cyclist pulled out from behind it.", 50),
        ("Proper scare tonight. Down the hill at 40 km/h while a kid on a scooter came straight out of a"
         " driveway.", 40),
    ],
    ids=["already-on-the-roundabout", "on-the-motorway", "just-past-a-place", "halfway-over-it", "down-the-hill"],
)  # fmt: skip
def test_a_subjectless_setting_before_what_happened_is_the_narrators(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


@pytest.mark.parametrize(
    "text",
    [
        "A bus pulled out. At 40 km/h the van behind it pulled out too.",
        "A car at 40 mph when the lights changed went straight through.",
        "I saw a van at 40 mph when the lights changed.",
        "A bus was ahead. It was at 40 km/h when the lights changed.",
    ],
    ids=["no-clause-after", "a-road-user-before", "seen-road-user", "it-opens"],
)
def test_a_speed_with_a_subject_of_its_own_is_not_the_narrators(text):
    assert ego_kph(text) != pytest.approx(40 * (1.609 if "mph" in text else 1), abs=0.2)


# --- the reader addressed before a modal: "You'll be driving at around 80 km/h" -----------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        ("You will follow the red car in front of you. You'll be driving at around 80 km/h on a country road.", 80),
        ("A red car is ahead of you. You will be travelling at about 80 km/h on a country road.", 80),
        ("A cyclist is on the left. You should be doing around 50 km/h. The cyclist will swerve.", 50),
        ("Your task: a van is parked on the right. You must keep to 40 km/h. A child will run out from behind it.", 40),
        ("A bus is stopped ahead. You'd be going about 30 mph when a kid runs out from behind it.", 48.3),
    ],
    ids=["youll-be-driving", "you-will-be-travelling", "you-should-be-doing", "you-must-keep-to", "youd-be-going"],
)
def test_the_reader_addressed_before_a_modal_is_the_ego(text, kph):
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


@pytest.mark.parametrize(
    "text",
    [
        "A truck ahead of you will brake at 60 km/h. You will see it stop.",
        "A bus is ahead. Thank you. It will brake at 60 km/h.",
    ],
    ids=["you-as-object", "thank-you"],
)
def test_a_speed_of_the_road_user_stays_its_own_beside_you(text):
    assert ego_kph(text) != pytest.approx(60)


def test_you_dismissed_is_no_narrator_in_the_scene():
    """ "then you can go": permission, said to listeners, who are not in the story."""
    text = (
        "Right, listen up, then you can go. Sunday one of our vans was turning left out of the yard at 10 km/h"
        " and an e-scooter came along the cycle lane from the left and went under the front."
    )
    assert kinds(text) == ["e-scooter"]


def test_the_speed_of_one_the_party_follows_stays_its_own():
    """ "My wife was following a lorry at 90 km/h": the lorry's speed, which the one following keeps."""
    r = read("My wife was following a lorry at about 90 km/h when it pulled out and there was a tyre in our lane.")
    assert r.actors[0].kind == "truck" and r.actors[0].speed_mps == pytest.approx(90 / 3.6)
