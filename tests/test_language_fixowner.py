"""A vehicle named by its owner's name (owned_by_name): a second owner's vehicle is someone else, a
shop's or company's vehicle that acts on another road user is told from outside, and the module's own
example reads as its docstring says."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _adversaries(text: str) -> list[tuple[str, str, str]]:
    layers = layers_from_text(text, 1)
    return [(a["type"], a["spawn"]["relation"], str(a["behaviour"])) for a in layers["adversaries"]]


@pytest.mark.parametrize(
    "text",
    [
        "John's car and Mary's car collided at the junction.",
        "John's car was hit by Mary's car at the junction.",
        "Priya's car was struck by Omar's car on the roundabout.",
        "Sam's van and Kate's van collided in the car park exit.",
        "Mrs Okafor's car and Mr Tan's car collided at the junction.",
        "Our son's car was hit by Mr Tan's car at the junction.",
    ],
)
def test_a_second_owners_vehicle_is_another_road_user(text: str) -> None:
    assert len(_adversaries(text)) == 1


@pytest.mark.parametrize(
    "text",
    [
        "McDonald's lorry pulled out in front of a cyclist.",
        "McDonald's lorry cut up a cyclist.",
        "Tesco's lorry cut up a cyclist on the high street.",
        "The supermarket's lorry pulled out in front of a bus at the lights.",
    ],
)
def test_a_shops_vehicle_acting_on_another_is_told_from_outside(text: str) -> None:
    assert any(t == "truck" and "cut_in" in b for t, _, b in _adversaries(text))


@pytest.mark.parametrize(
    "text",
    [
        "Mem's car, rear tyre. Mem said a lad on an e-scooter came off the kerb and he had to swerve.",
        "The survey team's van was doing 30 when a cyclist pulled out in front of it.",
        "Lena's car was overtaken by a lorry, which then cut in.",
    ],
)
def test_the_followed_owners_vehicle_stays_the_ego(text: str) -> None:
    found = _adversaries(text)
    assert len(found) == 1 and found[0][0] in {"bicycle", "e-scooter", "truck"}


def test_a_vehicle_named_after_someone_else_is_still_met() -> None:
    found = _adversaries("A cyclist was riding along when Tesco's lorry pulled out.")
    assert {t for t, _, _ in found} == {"bicycle", "truck"}


def test_the_docstring_example_reads_as_it_says() -> None:
    found = _adversaries("Lena's car in the outside lane. In her mirror, a white van was tailgating her.")
    assert len(found) == 1 and found[0][0] == "van" and "follow_vehicle" in found[0][2]
