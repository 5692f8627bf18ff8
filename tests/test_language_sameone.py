"""Vehicles named in the plural as parked ("cars parked both sides", "the parked vans", "two parked
cars") line the road: they stand at the kerb, and what the text tells of someone else is not hung on
them. Wordings made up for the class in several registers (a neighbourhood post, a review, a witness
note, a driver's log); near misses that look alike keep their readings."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read, scan
from vei_scenario.language.reading import stands_there
from vei_scenario.language.rules_backend import layers_from_text


def _acting(text: str) -> list[tuple[str, list[str]]]:
    """Each road user of ``text`` that does something (not standing scenery): kind and behaviours."""
    return [(a.kind, [b[0] for b in a.behaviours]) for a in read(text).actors if not stands_there(a)]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        (
            "Drove along Mill Street at 20 mph last night, vans parked both sides as always, and a kid on a "
            "bike shot out of a gap on my left right in front of me.",
            "bicycle",
        ),
        (
            "One star. You can't see anything past the parked lorries when you pull out of the car park, "
            "and yesterday a woman on an e-scooter came down the pavement and straight off the kerb in "
            "front of me.",
            "e-scooter",
        ),
        (
            "I was doing about 25 when a little boy ran into the road from between two parked cars on my "
            "right. I braked hard and stopped just short of him.",
            "pedestrian",
        ),
        (
            "Log 14:02. Street lined with parked taxis. Jogger stepped out in front of our unit, we stopped in time.",
            "pedestrian",
        ),
    ],
)
def test_parked_rows_stand(text: str, kind: str) -> None:
    assert [k for k, _ in _acting(text)] == [kind]


def test_parked_rows_stand_in_the_layers() -> None:
    text = (
        "Coming past the shops at 20 mph, cars parked both sides as usual, and a lad on a scooter "
        "came flying out on my right straight across in front of me."
    )
    layers = layers_from_text(text, 0)
    moving = [a for a in layers["adversaries"] if float(a.get("speed_mps", 0.0)) != 0.0 or a["type"] != "car"]
    assert [a["type"] for a in moving] == ["e-scooter"]
    assert all(a["type"] == "e-scooter" or float(a["speed_mps"]) == 0.0 for a in layers["adversaries"])


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # a parked vehicle said to move is a road user
        ("A parked car pulled out right in front of me as I came past at 30 mph.", [("car", "cut_in")]),
        # two parked vehicles that move, the verb said of them as subject
        ("Two parked vans pulled out in front of me one after the other.", [("van", "cut_in")] * 2),
        # a plural that is not said to be parked keeps its reading
        ("Two e-scooters came through side by side on my left and cut across in front of me.", None),
    ],
)
def test_what_moves_keeps_its_moves(text: str, want: list[tuple[str, str]] | None) -> None:
    acting = _acting(text)
    if want is None:
        assert [k for k, _ in acting] == ["e-scooter", "e-scooter"]
        return
    assert [(k, names[0]) for k, names in acting] == want


@pytest.mark.parametrize(
    ("text", "said"),
    [
        (
            "A car braked for a man on the zebra and a girl on one of the hire e-scooters rode straight "
            "into the back of it.",
            "a hire e-scooter rode",
        ),
        ("Doing 40 when a bloke on one of them scooters swung out across the lanes.", "a scooter swung"),
        ("I was turning left when a lad on one of those rental bikes came up the inside.", "a rental bike came"),
    ],
)
def test_one_picked_out_of_many_is_one(text: str, said: str) -> None:
    """ "On one of the hire e-scooters" is on one e-scooter: the rider is said as one, in the singular
    (a plural would be read as the kind in general, or as more than one)."""
    assert said in " ".join(scan(text)[3])


def test_one_picked_out_of_many_beside_the_kind_in_general() -> None:
    text = (
        "A car stopped for a woman on the zebra and a young man on one of the hire e-scooters went straight "
        "into the back of it. Those scooters should not be allowed in the market."
    )
    assert [k for k, _ in _acting(text)].count("e-scooter") == 1


@pytest.mark.parametrize(
    ("text", "riders"),
    [
        # a kind in general, said with a modal, beside the one in the scene
        (
            "A kid on an e-scooter shot out of an alley on my right in front of me. Those scooters should "
            "be banned from the pavement.",
            1,
        ),
        (
            "A cyclist came through the red light from the left in front of me. Cyclists must stop at "
            "red lights like everyone else.",
            1,
        ),
        # two the text counts stay two
        ("Two e-scooters came through side by side from the left and cut across in front of me.", 2),
    ],
)
def test_a_kind_said_with_a_modal_is_in_general(text: str, riders: int) -> None:
    assert len([k for k, _ in _acting(text) if k in ("e-scooter", "bicycle")]) == riders
