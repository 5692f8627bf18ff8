"""Readings of contact fixed after a review of the outcome reader's light-contact rules, with guards that
the readings those rules were made for still hold:

* a light knock heard or felt is a contact only when nothing locates it elsewhere: on a body part, a
  window or a thing that is not a vehicle's part or a road user ("a tap on my shoulder", "a clunk from
  the engine", "a knock from the boot") it is no contact; and a miss or a safe pass said outranks it
  ("I felt a tap but it was just a pothole; the cyclist passed safely");
* "the line of cars" is a queue, not a painted line: the object is what comes after "of";
* a verb with a particle before "right under the wheels" still heads the path ("ran out right under
  the wheels of the van": a contact);
* "into my corner of the junction" is the writer's share of a place, not the ego's car's corner;
* "came out right under my bonnet" is a near miss, as describe.md says.
"""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str | None:
    return layers_from_text(text, 0).get("intent")


def _reads(text: str, intent: str | None) -> None:
    """``text`` reads as ``intent``; with None, as anything but a collision."""
    got = _intent(text)
    if intent is None:
        assert got != "collision"
    else:
        assert got == intent


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("I heard a knock on the window and a pedestrian was standing there; a car passed slowly.", None),
        (
            "I felt a tap on my shoulder from my passenger as a cyclist pulled out in front; I braked and missed him.",
            "near_miss",
        ),
        ("I heard a clunk from the engine as a cyclist pulled out in front of me; I braked in time.", "near_miss"),
        (
            "We heard a knock on the door at home. The next day a van cut in front of me and missed me by inches.",
            "near_miss",
        ),
        ("I heard a knock from the boot as a van cut in front of me; I braked and it missed.", "near_miss"),
        ("I felt a tap but it was just a pothole; the cyclist passed safely.", "safe"),
        ("I heard a tap on my window from a cyclist and then he rode off.", None),
        ("I felt a tap on my arm from my son as a moped squeezed past.", None),  # (own variant: a body part)
    ],
)
def test_a_knock_located_elsewhere_or_outranked_is_no_collision(text: str, intent: str | None) -> None:
    _reads(text, intent)


@pytest.mark.parametrize(
    "text",
    [
        "I heard a clunk as the van's mirror hit mine.",
        "A boy on a bike rode out between the parked cars and I felt a small knock on the front.",
        "I braked as the scooter crossed, but I still heard a soft clunk from the bumper.",
        "The taxi squeezed past on my right and I felt the nudge on my door.",
        "A jogger came out from behind the bus. I braked, and then felt the tap.",
        "A cyclist filtered past and I felt a tap on my wing mirror.",  # (own variant)
        "I heard a knock from the van as it went past me.",  # (own variant: from a road user)
    ],
)
def test_a_light_knock_on_the_vehicle_stays_a_collision(text: str) -> None:
    assert _intent(text) == "collision"


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("He hit the line of cars waiting at the lights.", "collision"),
        ("The van clipped the line of parked cars and the cyclist behind it braked.", "collision"),
        ("The car hit the line of traffic cones and then a cyclist swerved round it.", "collision"),
        ("The bus clipped the line of bollards and a cyclist swerved.", "collision"),  # (own variant)
        # guards: a painted line is still no contact, also named after "of"
        ("A white van drifted across and its nearside wheel touched the white line, then it tucked back in.", None),
        ("The bus touched the edge of the white line and carried on past me.", None),  # (own variant)
        ("Coming round the bend the lorry clipped the centre line with its trailer and carried on past me.", None),
    ],
)
def test_a_line_of_things_is_met_a_painted_line_is_not(text: str, intent: str | None) -> None:
    _reads(text, intent)


@pytest.mark.parametrize(
    "text",
    [
        "A kid ran out right under the wheels of the van.",
        "A cyclist fell off right under the wheels of the bus.",
        "The cyclist slid off right under the lorry.",
        "A kid ran out from between parked cars right under the wheels of my car.",
        "The boy stepped back right under the wheels of the bus.",  # (own variant)
        # guards: a verb before "right", and the adverb after the verb
        "The cyclist wobbled and went right under the wheels of the lorry.",
        "The boy slid straight under the front of my car.",
    ],
)
def test_a_particle_before_right_under_the_wheels_keeps_the_contact(text: str) -> None:
    assert _intent(text) == "collision"


@pytest.mark.parametrize(
    "text",
    [
        "He came out of the side road right under my bonnet.",
        "A van came out of the side road right under my bonnet.",
        "A cyclist pulled out right under my bonnet.",
        "A van came out right under my nose.",
        "A lad on a scooter came flying out of the side road right under my bonnet. I braked hard.",
        "The moped rides out onto the roundabout right under the bonnet, and I stamp on the brake.",
    ],
)
def test_came_out_right_under_my_bonnet_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("The cyclist rode into my corner of the junction.", None),
        ("The van pulled into our corner of the car park and a kid ran out.", None),
        ("The cyclist rode into my corner of the box junction and stopped.", None),
        ("A taxi swung into our corner of the roundabout and a cyclist braked.", None),  # (own variant)
        # guards: a corner owned by a road user, or the ego's own
        ("A car reversed into our rear corner.", "collision"),
        ("The cyclist rode into the corner of my car.", "collision"),
        ("A cyclist rode into the rear corner of the taxi.", "collision"),
        ("A cyclist ran the red light and went into my rear corner.", "collision"),  # (own variant)
        ("A lorry pulled into the corner of the car park ahead of me and I waited.", "safe"),
    ],
)
def test_my_corner_of_a_place_is_no_part(text: str, intent: str | None) -> None:
    _reads(text, intent)
