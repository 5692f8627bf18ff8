"""Contacts and amounts of traffic as machine translations and plain accounts say them: a blow said
with a preposition before the part it landed on ("hit in the right side of my car", "hit to the rear
door"), someone shoved into or onto a road user ("pushed us into the car ahead"), and the traffic's
amount in other words ("the traffic was medium", "traffic small")."""

from __future__ import annotations

import pytest

from vei_scenario.language.outcome import stated_intent
from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came out of the side street and the cyclist hit in the left side of my car.",
        "The minibus pulled away from the stop and its front corner hit to the rear door of my car.",
        "We were queuing when a lorry behind failed to stop and pushed us into the car ahead.",
        "The van behind drove up on me, whereby I was pushed onto the taxi in front.",
        "The coach shunted me and shoved my car into the back of the bus.",
    ],
)
def test_a_contact_said_through_a_preposition_or_a_shove_is_a_collision(text):
    assert read(text).intent == "collision"


@pytest.mark.parametrize(
    "said",
    [
        "she pushed her pram into the road .",
        "a man pushed his bike onto the crossing .",
        "i was pushed into the kerb by the wind .",
        "the gust pushed the van into the next lane .",
        "the ball hit in the garden .",
        "the rain hit to the windscreen .",
    ],
)
def test_a_shove_into_a_place_or_a_blow_to_nothing_of_a_road_user_is_no_contact(said):
    assert stated_intent(said) != "collision"


@pytest.mark.parametrize(
    ("text", "density"),
    [
        ("A taxi cut in front of me. The traffic was medium.", "moderate"),
        ("A taxi cut in front of me. Conditions: dusk, road dry, traffic small.", "light"),
        ("A taxi cut in front of me on the ring road, traffic dense.", "heavy"),
    ],
)
def test_an_amount_of_traffic_in_other_words(text, density):
    assert read(text).density == density


def test_a_traffic_light_is_no_amount():
    assert read("A taxi cut in front of me. The traffic light was red.").density is None


@pytest.mark.parametrize(
    "said",
    [
        "i stop with room to spare . follow for more london cabbie clips .",
        "subscribe for many more helmet cam clips .",
        "i stopped in time . those two dashcam clips are on my channel .",
    ],
)
def test_clips_after_a_determiner_only_a_plural_takes_are_videos_not_a_contact(said):
    assert stated_intent(said) != "collision"


@pytest.mark.parametrize("said", ["the cabbie clips my mirror .", "then some idiot clips my mirror ."])
def test_clips_after_its_subject_is_still_a_contact(said):
    assert stated_intent(said) == "collision"


@pytest.mark.parametrize(
    "said",
    [
        "the low sun hit in my windscreen and i lost sight of him .",
        "the headlights of the coach hit in my mirror .",
        "a man pushed his way onto the bus .",
        "the commuters pushed onto the tram at the stop .",
        "a boy pushed his scooter onto the tram tracks .",
    ],
)
def test_light_that_hits_and_people_who_board_are_no_contact(said):
    assert stated_intent(said) != "collision"


@pytest.mark.parametrize(
    "text",
    [
        "Traffic was high speed on the ring road and a car cut in front of me.",
        "The traffic small roundabout was empty when a cyclist came round.",
    ],
)
def test_a_traffic_word_that_is_no_amount(text):
    assert read(text).density in (None, "none")


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came out from the right in front of me and I hit to the brakes.",
        "The e-scooter turned into my lane, I hit in the brake pedal and we stopped one metre before him.",
        "A pedestrian ran out between the parked cars and I hit at the brakes with all force.",
    ],
)
def test_the_brakes_hit_with_a_preposition_are_no_contact_but_a_hard_stop(text):
    assert read(text).intent == "near_miss"
