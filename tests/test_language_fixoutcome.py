"""Review fixes in the outcome reader (:mod:`vei_scenario.language.outcome`).

* A heading or a sentence with no clause of its own ("Van and cyclist" read as "and .") no longer
  shifts the sentences a clause is looked up in: no crash, and the reading of the body stands.
* A verb of pressing the brakes (one shared list: "hit", "stomped", "mashed", "slammed on") before a
  measured stop makes it the end of a hard stop: a near miss, however long the length.
* An emergency said anywhere in the description (AEB or an emergency brake triggered, a high
  criticality stated, "could have been critical", fear) keeps a near miss over a roomy stop.
* A thing hit while forced out of someone's way, told by a pronoun ("scraped it"), is no contact.
* A roomy stop made by another road user short of someone other than the ego is no margin of the ego's.

Wordings written for these tests, besides the reviewer's own sentences."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str | None:
    return layers_from_text(text, 0).get("intent")


def _kinds(text: str) -> list[tuple[str, str]]:
    layers = layers_from_text(text, 0)
    return sorted((a["type"], a["behaviour"]["behaviour"]) for a in layers["adversaries"])


# finding 1: a sentence with no clause (a heading's leftover) must not crash the outcome reader
HEADED = {
    "Van and cyclist\nA van overtook me and then a cyclist crossed.": [
        ("bicycle", "cross_in_front"),
        ("van", "overtake"),
    ],
    "Van and cyclist. A van overtook me and then a cyclist crossed.": [
        ("bicycle", "cross_in_front"),
        ("van", "overtake"),
    ],
    "Van and cyclist\nA van came past and then a cyclist went through.": None,
    "Van, then cyclist.\nA cyclist crossed in front of me and he was gone before I got there.": None,
}


@pytest.mark.parametrize(("text", "kinds"), HEADED.items())
def test_a_sentence_without_a_clause_does_not_crash(text: str, kinds: list | None) -> None:
    layers = layers_from_text(text, 0)
    if kinds is not None:
        assert _kinds(text) == kinds
    assert layers["intent"] in (None, "safe", "near_miss", "unspecified")


def test_gone_before_arrival_still_read_after_a_heading() -> None:
    assert _intent("Cyclist.\nA cyclist crossed in front of me and he was gone before I got there.") == "safe"
    assert (
        _intent("A cyclist rode over the junction ahead of us and she was already on the other side when we arrived.")
        == "safe"
    )


# finding 3: a verb of pressing the brakes before a measured stop
PRESSED_THEN_STOPPED = [
    "A child ran out. I hit the brakes and stopped 6 m short of her.",
    "A child ran out. I stomped on the brakes and stopped 6 m short of her.",
    "A child ran out. I mashed the brakes and stopped 6 m short of her.",
    "A dog ran into the road, I jumped on the brakes and stopped about 5 metres short of it.",
    "A boy stepped out between parked cars and I stood on the brakes, stopping 7 m short of him.",
]
# no pressing of the brakes: a roomy stop is a safe pass; a pressing verb on something else is no brake
NOT_PRESSED = [
    "A pedestrian steps onto the crossing ahead; the ego slows and halts 5 m short of him.",
    "A van stands still in the lane; I eased off and stopped 6 m short of it.",
]


@pytest.mark.parametrize("text", PRESSED_THEN_STOPPED)
def test_pressing_the_brakes_before_a_measured_stop_is_a_near_miss(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", NOT_PRESSED)
def test_a_measured_stop_without_pressing_stays_safe(text: str) -> None:
    assert _intent(text) == "safe"


# finding 4: an emergency said anywhere keeps a near miss over a roomy stop
EMERGENCY_SAID = [
    "A pedestrian crossed. Ego stops 4 m short. Criticality: high.",
    "A pedestrian crossed. Ego stops 5 m short. AEB triggered.",
    "A child darted out. I stopped 5 m short, heart pounding.",
    "A child ran out. I stopped 5 m short. Could have been critical.",
    "A jogger stepped out and the AEB kicked in; the ego stopped 6 m short of him.",
    "A cyclist swung into the lane. The test car halts 5 m behind her. High criticality.",
    "A girl ran out after a ball. I stopped 6 m short of her, my heart racing.",
]
# no emergency said: the roomy stop is a safe pass; a low criticality is none
NO_EMERGENCY = [
    "A child ran out. I stopped 5 m short.",
    "A pedestrian crossed. Ego stops 5 m short. Criticality: low.",
    "A pedestrian crossed. Ego stops 5 m short. AEB not triggered.",
]


@pytest.mark.parametrize("text", EMERGENCY_SAID)
def test_an_emergency_said_keeps_a_near_miss_over_a_roomy_stop(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", NO_EMERGENCY)
def test_a_roomy_stop_with_no_emergency_is_safe(text: str) -> None:
    assert _intent(text) == "safe"


def test_a_hedged_criticality_alone_is_a_near_miss_and_a_denied_one_is_not() -> None:
    assert _intent("A cyclist pulled out of a side road in front of me. Could have been critical.") == "near_miss"
    assert _intent("A cyclist waited at the side road as I passed. It could never have been critical.") != "near_miss"


# finding 10: furniture named by a pronoun, hit in a forced move
FURNITURE_BY_PRONOUN = [
    "I had to pull in to the hedge, scraped it, but the lorry never touched me.",
    "A van came straight at me so I had to swerve towards the fence and clipped it, but the van missed me.",
    "A tractor came round the bend on my side so I had to swerve into the wall, scraped it, but the tractor missed me.",
]
# a road user named by the pronoun, or hit outright: still a collision
ROAD_USER_BY_PRONOUN = [
    "A van pulled out of a side road and I had to brake hard but still hit it.",
    "A car stopped in front of me by the hedge, I had to brake and clipped it.",
    "I had to pull in to the hedge and the lorry clipped my mirror.",
]


@pytest.mark.parametrize("text", FURNITURE_BY_PRONOUN)
def test_furniture_told_by_a_pronoun_is_no_contact(text: str) -> None:
    assert _intent(text) == "near_miss"


@pytest.mark.parametrize("text", ROAD_USER_BY_PRONOUN)
def test_a_road_user_told_by_a_pronoun_is_still_hit(text: str) -> None:
    assert _intent(text) == "collision"


# finding 12: a roomy stop made by another road user, short of someone else: not the ego's margin
ANOTHERS_STOP = [
    "A child crossed. The bus stopped 4 m behind her, I was behind the bus.",
    "The rider jumps off as the car stops 5 m short of him.",
    "A man stepped onto the zebra; the taxi in front of me stopped 6 m short of him.",
]
# the ego's own stop, or another's stop short of the ego: its margin
EGOS_MARGIN = [
    "A man stepped onto the zebra and I stopped 6 m short of him.",
    "I was crossing on my bike and the car stopped 5 m short of me.",
    "A delivery van stops in our lane ahead, and the ego brakes and comes to a stop around 8 m before it.",
]


@pytest.mark.parametrize("text", ANOTHERS_STOP)
def test_another_road_users_roomy_stop_is_not_a_safe_pass(text: str) -> None:
    assert _intent(text) != "safe"


@pytest.mark.parametrize("text", EGOS_MARGIN)
def test_the_egos_own_roomy_stop_is_a_safe_pass(text: str) -> None:
    assert _intent(text) == "safe"
