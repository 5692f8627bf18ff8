"""The vehicle a third-person report is about brakes in more words than "braked": a verb of pressing
said of the brakes ("slammed on", "hit the brakes", "stood on everything") or a verb of motion that ends
in a stop ("eased to a stop", "came to a standstill"). Told of a vehicle after another road user came
its way, that is the reaction that makes it the one the report is told from, the ego, and not a road
user too many. So is a driver named by that vehicle ("the bus driver" after "the school bus"): the same
vehicle, whatever type the word "driver" alone would give the phrase, not a second one that leaves
whose the report's bare "Driver braked" is in doubt.

The guards keep a vehicle that slams into something, hits someone, stands on something or pulls up
to a stop sign, and one that comes to a stop before anyone is named, as the road user it was."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _kinds(text: str) -> list[str]:
    return [adv["type"] for adv in layers_from_text(text, 0)["adversaries"]]


TOLD_FROM = [
    (
        "The bus was pulling in when a girl on an e-scooter rolled off the kerb on the left and went across"
        " in front of it. The driver slammed on and missed her by a foot.",
        ["e-scooter"],
    ),
    (
        "The bus was pulling away from the stop when a cyclist rode across in front of it. The driver hit the brakes.",
        ["bicycle"],
    ),
    (
        "A delivery lorry was pulling away from the lights when a cyclist rode across in front of it."
        " The lorry eased to a halt a metre short of him.",
        ["bicycle"],
    ),
    (
        "The minibus was pulling away from the stop when a jogger ran across in front of it. The minibus"
        " came to a complete standstill just short of her.",
        ["pedestrian"],
    ),
    (
        "The pickup was reversing out of a drive when a boy on a bike came along the pavement behind it."
        " The pickup jammed on and the boy rode round it.",
        ["bicycle"],
    ),
]


@pytest.mark.parametrize("text,kinds", TOLD_FROM)
def test_a_vehicle_that_brakes_for_another_road_user_is_the_ego(text, kinds):
    assert _kinds(text) == kinds


STAYS = [
    # slamming into something is contact, no braking (the van is the one the report is about, as before)
    ("A van slammed into the back of a cyclist who had stopped at the lights.", ["bicycle"]),
    # a verb of pressing with a road user after it
    ("A lorry hit a cyclist who was riding along the kerb.", ["bicycle"]),
    # a stop sign is a place, not a stop
    (
        "A lorry pulled up to a stop sign and a cyclist rode across in front of it. The lorry waited.",
        ["truck", "bicycle"],
    ),
    # a stop before anyone came its way is no reaction
    (
        "A lorry came to a stop at the lights, and a cyclist squeezed past it on the left.",
        ["truck", "bicycle"],
    ),
]


@pytest.mark.parametrize("text,kinds", STAYS)
def test_a_vehicle_that_does_not_brake_for_anyone_stays_a_road_user(text, kinds):
    assert _kinds(text) == kinds


DRIVER_NAMED_BY_ITS_VEHICLE = [
    (
        "The school bus was pulling in when a lad on a bike came off the pavement on the left and went"
        " across in front of it. Driver braked hard and missed him by a foot. The bus driver was brilliant.",
        ["bicycle"],
    ),
    ("A van pulled out of a side road in front of a bus. The bus driver braked hard and stopped in time.", ["van"]),
]


@pytest.mark.parametrize("text,kinds", DRIVER_NAMED_BY_ITS_VEHICLE)
def test_a_driver_named_by_the_vehicle_is_that_vehicle(text, kinds):
    assert _kinds(text) == kinds


def test_a_driver_of_another_vehicle_stays_apart():
    # the van driver is no driver of the bus: a road user of its own, as before
    text = (
        "A cyclist was riding along Park Road when a bus pulled out of the stop. A van driver behind the bus"
        " braked hard."
    )
    assert _kinds(text) == ["bicycle", "truck", "van"]


@pytest.mark.parametrize(
    "text",
    [
        "The bus braked at 20 km/h when one e-scooter rider crossed in front of it.",
        "A tram pulled away at 15 km/h and one bike rider rode into the tram side. Tram driver not to blame.",
    ],
)
def test_a_rider_named_by_a_rider_word_is_someone_the_reports_vehicle_meets(text):
    """ "One e-scooter rider" is a road user the report's one vehicle meets, so that vehicle is the ego."""
    from vei_scenario.language import protagonist
    from vei_scenario.language.reader import _kind_at, _known, _tokens

    assert "ego" in protagonist.frame(list(_tokens(text, brackets=True)), _kind_at, _known, [])
