"""The vehicle a third-person report is about is the ego, not a second road user.

A report with no narrator tells of one vehicle: it has a speed in a participle's aside ("the van,
travelling at 30 mph, ..."), it is the subject a verb of contact acts on in the passive ("the estate
car was rear-ended by a van"), or it is named by its owner with the apostrophe left out ("Nans
Fiesta"). That vehicle is the ego; the one acting on it is the road user. A narrator's own story and a
witness's account keep being read as before.
"""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _kinds(text: str, seed: int = 0) -> list[str]:
    return sorted(a["type"] for a in layers_from_text(text, seed)["adversaries"])


def _ego_kph(text: str, seed: int = 0) -> float:
    return float(layers_from_text(text, seed)["ego"]["speed_mps"]) * 3.6


@pytest.mark.parametrize("seed", [0, 1])
def test_speed_in_a_participle_aside_is_the_reports_vehicle(seed: int) -> None:
    text = (
        "A delivery van, travelling at 30 mph, came up behind a cyclist on a narrow lane. "
        "With an oncoming car approaching, the van slowed and waited."
    )
    assert _kinds(text, seed) == ["bicycle", "car"]
    assert _ego_kph(text, seed) == pytest.approx(48.3, abs=0.5)


def test_a_vehicle_coming_up_behind_someone_named_is_not_placed_by_someone_unsaid() -> None:
    text = (
        "Footage shows the taxi, cruising at 25 mph, coming up behind a jogger; with a van coming the "
        "other way, the taxi braked and waited."
    )
    assert _kinds(text) == ["pedestrian", "van"]
    assert _ego_kph(text) == pytest.approx(40.2, abs=0.5)


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("The estate car was rear-ended by a van at the lights.", ["van"]),
        ("Nans Fiesta was hit by a bus outside the post office.", ["truck"]),
        ("Her sisters hatchback was hit by a motorbike on the bypass.", ["car"]),
    ],
)
def test_the_vehicle_struck_in_the_passive_is_the_ego(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("A van hit me at the lights.", ["van"]),  # (the narrator's own story)
        ("I saw a car get hit by a bus at the junction.", ["car", "truck"]),  # (a witness's account)
    ],
)
def test_guards_keep_their_reading(text: str, kinds: list[str]) -> None:
    assert _kinds(text) == kinds


def test_the_striking_vehicle_with_a_speed_aside_is_the_ego_in_the_active_voice() -> None:
    assert _kinds("The lorry, travelling at 50 mph, hit a car at the crossroads.") == ["car"]
    assert _ego_kph("The lorry, travelling at 50 mph, hit a car at the crossroads.") == pytest.approx(80.5, abs=0.5)
