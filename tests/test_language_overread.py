"""A behaviour the text does not tell: the ego pulling out of a side road or a drive is the one that
gives way, so a road user coming along from a side keeps going on its road and runs no red light;
one that itself pulls out, or goes through against a light, reads as before."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _behaviours(text: str, seed: int = 0) -> list[list[str]]:
    layers = layers_from_text(text, seed)
    out = []
    for adv in layers["adversaries"]:
        b = adv["behaviour"]
        out.append([n["behaviour"] for n in b["sequence"]] if "sequence" in b else [b["behaviour"]])
    return out


@pytest.mark.parametrize(
    "text",
    [
        "I pulled out of a side road to turn left and a cyclist came along from the right; I nearly hit him.",
        "We were pulling out of our drive to turn right when a car came over the hill from our right at 50 mph.",
        "Yesterday I edged out of the junction and a motorbike came from the left and clipped my bumper.",
        "Pulled out to turn left today and a van I had not seen came along from the right, missed it by inches.",
        "You were emerging from the side road when a cyclist rode down the hill from your right.",
    ],
)
def test_a_road_user_on_the_road_the_ego_pulls_out_onto_keeps_going(text: str) -> None:
    for seed in (0, 1):
        behaviours = _behaviours(text, seed)
        assert behaviours, text
        assert "run_red_light" not in behaviours[0], (text, behaviours)
        assert behaviours[0][0] in ("keep_going", "along_road"), (text, behaviours)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the road user is the one coming out: it turns into the ego's road
        ("A van pulled out of a side road on the left in front of me.", "turn_into"),
        # a run of a red told as the road user's own act
        ("I was driving through the junction when a van ran the red light from the left and hit me.", "run_red_light"),
        ("At the crossroads a lorry went through on red from the right, right in front of us.", "run_red_light"),
        ("A taxi jumped the lights from the left as I drove across the junction.", "run_red_light"),
        # the ego pulls out to pass, not out of a side road: the crossing car is still read as before
        (
            "I pulled out to pass a tractor and a car came from the right at the junction and went straight across.",
            "run_red_light",
        ),
    ],
)
def test_guards_keep_their_reading(text: str, expected: str) -> None:
    assert expected in [name for names in _behaviours(text) for name in names], (text, _behaviours(text))


def test_an_overtake_that_cuts_in_stays_one() -> None:
    assert _behaviours("A car overtook me and cut in.")[0][0] == "overtake"
