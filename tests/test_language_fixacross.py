"""A bare "across" is a crossing only where it is a going: not one of looking, calling or waving
("looked across", "shouted across"), not one denied ("Not across, just waiting"), and not one in front
of another road user, who stays one ("then across, in front of the van"). A side said in a participle
phrase of the vehicle a walker crosses before is the vehicle's ("in front of the van coming from the
left"). Sentences of my own, the reviewer's, and near misses that keep their readings."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _users(text: str) -> list[tuple[str, str, str]]:
    """Each road user of ``text`` (seed 0): type, first behaviour, relation."""
    out = []
    for adv in layers_from_text(text, 0)["adversaries"]:
        node = adv["behaviour"]
        name = node["sequence"][0]["behaviour"] if "sequence" in node else node["behaviour"]
        out.append((adv["type"], name, adv["spawn"]["relation"]))
    return out


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist waited at the kerb, then looked across.",
        "A woman on the pavement shouted across.",
        "A boy on the footway glanced across and then stood still.",
        "An old man at the bus stop waved across to a friend.",
        "A pedestrian on the left. Not across, just waiting.",
        "A jogger on the right kerb, never across, just stretching.",
    ],
)
def test_looking_calling_or_a_denied_across_is_no_crossing(text: str) -> None:
    assert all(name != "cross_in_front" for _, name, _ in _users(text)), _users(text)


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A man in a hi-vis jacket appeared from nowhere. Straight across.", "pedestrian"),
        ("A kid on a bike looked left, then straight across in front of me.", "bicycle"),
        ("A woman on the right kerb. Not waiting, straight across.", "pedestrian"),
    ],
)
def test_a_going_across_is_still_a_crossing(text: str, kind: str) -> None:
    """Guards: a going across stays a crossing, also after a look or a denial of something else."""
    assert (kind, "cross_in_front") in [u[:2] for u in _users(text)], _users(text)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist ahead of me. Then across, in front of the van.",
        "A cyclist ahead of me. Then across, in front of the bus.",
        "A girl on a scooter ahead of me. Then across, in front of a lorry.",
    ],
)
def test_the_vehicle_crossed_in_front_of_stays_a_road_user(text: str) -> None:
    kinds = [k for k, _, _ in _users(text)]
    assert any(k in ("van", "truck", "bus") for k in kinds), _users(text)


def test_across_the_front_of_the_egos_own_cab_stays_a_crossing() -> None:
    """Guard: the cab is the ego's own; the cyclist crosses in front of the ego."""
    text = (
        "Depot report: lorry moving off from the lights at 8 mph when a cyclist came off the footway on "
        "the nearside and across the front of the cab. Driver stopped, no contact."
    )
    assert _users(text)[0] == ("bicycle", "cross_in_front", "roadside_left")


@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("A man crossed in front of the van coming from the left.", "left"),
        ("A woman crossed in front of a lorry approaching from the right.", "right"),
        ("A boy ran across in front of the bus that came from the left.", "left"),
    ],
)
def test_a_side_in_the_landmarks_participle_phrase_is_the_landmarks(text: str, side: str) -> None:
    """The vehicle comes from that side and stays a road user; the walker still crosses."""
    users = _users(text)
    vehicles = [u for u in users if u[0] in ("van", "truck", "bus")]
    assert vehicles and vehicles[0][2] == side, users
    assert ("pedestrian", "cross_in_front") in [u[:2] for u in users], users


@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("An old man crossed in front of the lorry from the left.", "roadside_left"),
        ("A woman crossed in front of the bus from the right.", "roadside_right"),
    ],
)
def test_a_side_after_the_landmark_is_still_the_crossers(text: str, side: str) -> None:
    """Guard: with no verb of the landmark's own, "from the left" goes with the crossing."""
    assert ("pedestrian", "cross_in_front", side) in _users(text), _users(text)
