"""A speaker's comment clause ("I reckon", "I'd say", "which I would guess") before the clause of a speed.

"I reckon he was doing 90" says the speed of "he": the "I" only judges it. Read with the "I", the
narrator (the ego) took the speed too. Every wording here is written for these tests (none is from a
corpus): first the comment clause before another road user's speed, which the ego must not take; then
near misses, where the clause after the comment is the narrator's own ("I think I was doing 40") or the
comment comes after the speed, which stay the ego's.
"""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _ego_kph(text: str) -> float:
    return round(layers_from_text(text, 0)["ego"]["speed_mps"] * 3.6, 1)


def _adversary_kph(text: str) -> list[float]:
    return [round(a["speed_mps"] * 3.6, 1) for a in layers_from_text(text, 0)["adversaries"]]


@pytest.mark.parametrize(
    "text, kph",
    [
        (
            "I had pulled over onto the verge to let it by. The tractor, which I would guess was doing 40 km/h,"
            " clipped my wing mirror.",
            40,
        ),
        (
            "I was waiting to turn right. A motorbike came round the bend and I reckon he was going 90 km/h when"
            " he shot past me.",
            90,
        ),
        ("I had stopped at the lights. A courier van clipped my door; I think it was doing 30 km/h.", 30),
        (
            "We had stopped for the school crossing and a pickup, which we reckon was doing 60 km/h, hit us.",
            60,
        ),
    ],
    ids=["which-i-would-guess", "and-i-reckon-he", "i-think-it", "which-we-reckon"],
)
def test_a_speed_judged_in_a_comment_clause_is_not_the_narrators(text, kph):
    assert _ego_kph(text) != kph
    assert kph in _adversary_kph(text)


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I think I was doing about 40 km/h when a dog ran out in front of me.", 40),
        ("I reckon we were doing 60 km/h when the lorry ahead braked hard.", 60),
        ("I was doing 50 km/h, I think, when a cyclist pulled out in front of me.", 50),
        ("I'd say I was going 45 km/h when a cyclist pulled out in front of me.", 45),
        ("I reckon I was at 35 km/h when the bus in front stopped dead.", 35),
    ],
    ids=["i-think-i", "i-reckon-we", "comment-after", "id-say-i", "i-reckon-i-at"],
)
def test_the_narrators_own_speed_after_a_comment_stays_the_egos(text, kph):
    assert _ego_kph(text) == kph


# --- a comment right beside another road user's speed, with no clause of its own ----------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        (
            "I was driving at 40 km/h. A girl on an e-scooter came towards me on the wrong side, very fast, I would"
            " say 25 km/h.",
            25,
        ),
        ("Doing 50 km/h on the bypass when a motorbike went past me, I reckon about 100 km/h, and cut in.", 100),
        ("I was on 30 km/h when a delivery van came past at 70 km/h I'd say, then braked.", 70),
        ("We were at 45 km/h. A cyclist came down the hill the wrong way, I'd guess at around 35 km/h.", 35),
    ],
    ids=["id-would-say-after-comma", "i-reckon-about", "id-say-after-the-speed", "id-guess-at-around"],
)
def test_a_comment_beside_anothers_speed_leaves_it_theirs(text, kph):
    assert kph in _adversary_kph(text)
    assert _ego_kph(text) != kph


@pytest.mark.parametrize(
    "text, kph",
    [
        ("I was going along quite quickly, I'd say 60 km/h, when a van pulled out of a side road on my left.", 60),
        ("A cyclist was ahead of me. I'd say 30 km/h was my speed when he braked.", 30),
        ("I'd say I was doing 40 km/h when a scooter came out from the right.", 40),
    ],
    ids=["narrators-own-clause", "comment-opens-a-sentence", "comment-before-its-clause"],
)
def test_a_comment_beside_the_narrators_speed_leaves_it_the_egos(text, kph):
    assert _ego_kph(text) == kph


# --- "<judge> <road user> at <speed>": the speed is the object's ----------------------------------------
@pytest.mark.parametrize(
    "text, kph",
    [
        (
            "A driver reports a cyclist coming at them on the wrong side of the road. The driver estimates the"
            " cyclist at about 20 km/h and says they had to stop.",
            20,
        ),
        (
            "The bus driver says a moped came out of the side road on his left. He puts the moped at 40 km/h and"
            " says he braked hard.",
            40,
        ),
    ],
    ids=["estimates-the-cyclist-at", "puts-the-moped-at"],
)
def test_a_speed_a_road_user_is_judged_at_is_that_road_users(text, kph):
    assert kph in _adversary_kph(text)


def test_a_length_judged_in_a_clause_is_no_speed_of_the_road_user():
    text = "The driver estimates the cyclist was about 20 m ahead when she braked."
    assert 20 not in _adversary_kph(text)
