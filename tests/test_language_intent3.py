"""Outcomes told in four constructions the reader missed, and the near misses of each that must keep
their old reading:

* a verb of contact whose object is a marking painted on the road ("its wheel touched the white
  line") meets no one: no collision;
* a light knock ("tap", "knock", "clunk", "nudge") felt or heard is a contact, as a thud is
  ("I felt a small knock on the front");
* a sentence made only of a small margin ("Inches.", "Literally centimetres!") is a near miss, as
  "Just." is a hedge;
* "right under the bonnet" after a path, with no verb before its "right", is where the other came,
  in front of the ego, not under it ("went right under the lorry" keeps its verb: a contact);
* an impact sound that is a clause of its own at its sentence's end, after a dash or a comma ("I
  braked, too late - crunch."), is a contact, as it is as a sentence of its own;
* "near" right before a verb of contact is the adverb "nearly" ("he near hit me"): a hedge;
* a noun and "'s" before a vehicle's part own it as a possessive does ("caught my driver's side
  mirror", read with the ego's name before "'s"); a lorry's "trailer" is met when something goes
  into it; "into the passing place" is a place;
* a denied contact wondered at ("how nobody got hit I'll never know") came very close: a near miss;
  a squeeze denied ("I was not going to squeeze past him") is no close pass;
* a noun that names a vehicle's part as well as a place ("corner") is the part when a road user owns
  it ("rode into the rear corner of the van"), and stays a place otherwise ("into the corner of the
  car park").
"""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str | None:
    return layers_from_text(text, 0).get("intent")


@pytest.mark.parametrize(
    "text",
    [
        "A white van drifted across and its nearside wheel touched the white line, then it tucked back in.",
        "Coming round the bend the lorry clipped the centre line with its trailer and carried on past me.",
        "The car in lane two wandered until a tyre touched the lane markings, and I held back.",
    ],
)
def test_touching_a_road_marking_is_no_collision(text: str) -> None:
    assert _intent(text) != "collision"


@pytest.mark.parametrize(
    "text",
    [
        "A boy on a bike rode out between the parked cars and I felt a small knock on the front.",
        "I braked as the scooter crossed, but I still heard a soft clunk from the bumper.",
        "The taxi squeezed past on my right and I felt the nudge on my door.",
        "A jogger came out from behind the bus. I braked, and then felt the tap.",
    ],
)
def test_a_light_knock_felt_or_heard_is_a_collision(text: str) -> None:
    assert _intent(text) == "collision"


@pytest.mark.parametrize(
    "text",
    [
        "A moped shot out of the side road in front of me. Inches.",
        "The taxi swung across my bonnet at the lights. Literally centimetres!",
        "A cyclist darted out between two vans and I stamped on the brake. A whisker.",
    ],
)
def test_a_sentence_of_a_small_margin_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("A kid ran out from the bus and I stopped dead. How nobody got hit I'll never know.", "near_miss"),
        ("A moped came through the red light at me and I don't know how he didn't hit me.", "near_miss"),
        (
            "A van was parked on the left with a cyclist beside it, so I was not going to squeeze past; I waited.",
            "safe",
        ),
        ("A cyclist jumped the lights and I don't know how he hit me, I was stopped.", "collision"),
    ],
)
def test_wonder_and_a_denied_squeeze(text: str, intent: str) -> None:
    assert _intent(text) == intent


@pytest.mark.parametrize(
    "text",
    [
        "A rider on an e-scooter came along the footpath and rode into the front left corner of the car.",
        "A cyclist ran the red light and went into the rear corner of my van.",
    ],
)
def test_into_the_corner_of_a_road_user_is_a_collision(text: str) -> None:
    assert _intent(text) == "collision"


@pytest.mark.parametrize(
    "text",
    [
        "A lad on a scooter came flying out of the side road right under my bonnet. I braked hard.",
        "The moped rides out onto the roundabout right under the bonnet, and I stamp on the brake.",
    ],
)
def test_right_under_the_bonnet_after_a_path_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("The estate in front stopped dead. I was on the brakes, far too late - crunch.", "collision"),
        ("A cyclist came the wrong way and swerved the same way as me, bang. Nobody hurt.", "collision"),
        ("A lad on a quad bike near hit me at the farm gate, then missed the post by a hair.", "near_miss"),
        ("A courier weaving through the queue and his pannier caught my driver's side mirror.", "collision"),
        ("The lorry braked on the ice and the car behind it slid into the trailer.", "collision"),
        ("I pulled into the passing place to let a tractor come by, and it went past slowly.", "safe"),
    ],
)
def test_said_in_a_clause_a_possessor_or_an_old_adverb(text: str, intent: str) -> None:
    assert _intent(text) == intent


@pytest.mark.parametrize(
    ("text", "intent"),
    [
        ("The van behind touched my rear bumper at the lights.", "collision"),  # (a part met: still contact)
        ("A cyclist pulled out and I clipped his back wheel.", "collision"),
        ("I gave the brakes a quick tap and the cyclist crossed ahead of me.", None),  # (a tap of a pedal)
        ("A lorry pulled into the corner of the car park ahead of me and I waited.", "safe"),  # (a place)
        ("A van pulled out of the junction and missed me by inches.", "near_miss"),
        ("The cyclist wobbled and went right under the wheels of the lorry.", "collision"),
        ("The boy slid straight under the front of my car.", "collision"),  # (its verb past "straight")
        ("The gap to the lead car was 30 cm.", None),
        ("That was a near hit with the cyclist at the lights.", None),  # ("a near hit": the noun)
        (
            "The drums in the van went bang, bang, and I drove on.",
            None,
        ),  # (a sound not at its sentence's end)  # (a measure, not a margin told alone)
    ],
)
def test_guards_keep_their_reading(text: str, intent: str | None) -> None:
    got = _intent(text)
    if intent is None:
        assert got != "collision"
    else:
        assert got == intent
