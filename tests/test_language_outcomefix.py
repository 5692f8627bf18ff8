"""Misreadings of the outcome found by review (findings 15-23) and their guards: a model's name or a
pushed thing hit is met (15), a vehicle hitting a bridge on its own crashed (16), a speed before a
verb of contact counts nothing (17), crashes counted as they happen in this scene are no statistic
(18), "could have killed" says what a contact did (19), "I'd have to say" hedges nothing (20), "1 m
clear" of a place, a line or a third party is no margin (21), a reaction early followed by a hard
brake is no safe pass (22), and "zero issues until" is no safe cue (23). Wordings written for these
tests, the review's sentences among them."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _intent(text: str) -> str | None:
    return layers_from_text(text, 0)["intent"]


CASES = [
    # 15: a model's name, or something pushed or towed, hit
    ("A Golf pulled out of a side road 10 m ahead and I hit the Golf at 30 mph.", "collision"),
    ("A Polo pulled out of a side road 10 m ahead and I hit the Polo at 30 mph.", "collision"),
    ("A woman pushed a pram out 10 m ahead of me at 30 km/h and I hit the pram.", "collision"),
    ("A man stepped out with a wheelbarrow 10 m ahead at 20 mph and I hit the wheelbarrow.", "collision"),
    ("A woman crossed 15 m ahead of me at 30 km/h and I hit the trolley she was pushing.", "collision"),
    ("A car towing a caravan pulled out 20 m ahead at 40 mph and I hit the caravan.", "collision"),
    # 15 guard: a control or a possession is no road user
    (
        "A lad on a scooter rode along ahead of me at 20 km/h, so I knocked the siren off and followed him.",
        "!collision",
    ),
    # 16: a vehicle hitting a bridge on its own crashed
    ("The lorry hit the bridge ahead of me at 20 mph and I stopped behind it.", "collision"),
    # 17: a speed said before a verb of contact counts nothing
    ("Ego drives at 50 km/h. A van pulling out at 20 hits the ego.", "collision"),
    ("Ego drives at 50 km/h. The ego at 30 strikes the pedestrian crossing ahead.", "collision"),
    ("Ego drives at 60 km/h. A truck at 80 bumps the ego from behind.", "collision"),
    ("Ego drives at 40 km/h. A cyclist at 20 knocks the ego's mirror.", "collision"),
    # 17 guard: a number before a plural noun of contact counts it
    ("A van cut in at 30 mph. About 40 crashes a year happen on this road.", "!collision"),
    # 18: crashes that happen in this scene, counted
    ("The bus braked and there were 3 crashes as the cars behind piled in at 40 mph.", "collision"),
    ("The bus braked at 40 mph and 4 collisions followed within seconds, one of them with my car.", "collision"),
    # 18 guard: a statistic
    (
        "A lorry overtook me at 50 mph. Council figures show 31 recorded collisions on this road since May.",
        "!collision",
    ),
    # 19: a modal perfect after a contact noun says what the contact did or could have been
    ("A van pulled out 10 m ahead of me at 30 mph. The crash could have killed my son.", "collision"),
    (
        "A van pulled out 10 m ahead of me at 30 mph. The collision might have been avoided if he had looked.",
        "collision",
    ),
    ("A van pulled out 10 m ahead of me at 30 mph. The impact would have been worse if I had not braked.", "collision"),
    # 19 guard: a supposed contact
    ("The target car brakes at 40 km/h; the impact would come at 40 km/h if the ego did nothing.", "!collision"),
    # 20: "I'd have to say" hedges nothing
    ("I'd have to say the van hit me pretty hard at 30 mph after pulling out.", "collision"),
    ("A van pulled out at 30 mph and I'd have to say we collided pretty hard.", "collision"),
    # 20 guard: "I'd have" + a participle of contact is a counterfactual
    ("Two riders shot across the junction at 20 km/h. I'd have driven straight into them. I waited.", "near_miss"),
    # 21: "clear of" a place, a line or a third party
    ("A cyclist rode 1 m clear of the parked cars 30 m ahead as I followed at a safe distance at 20 mph.", "safe"),
    ("The bus stopped with its nose a metre clear of the stop line and I passed it at 20 mph.", "!near_miss"),
    # 21 guard: clear of the other
    ("The walker kept going at 5 km/h, about 1 m clear of the test car.", "near_miss"),
    # 22: a hard brake after a move made early
    ("The van moved into my lane early and then slammed on its brakes 10 m ahead of me at 40 mph.", "!safe"),
    ("The car changed lanes early and then braked hard 10 m ahead of me at 40 mph.", "!safe"),
    # 22 guard
    (
        "A walker stepped out 30 m ahead. The shuttle at 30 km/h detected her early and slowed smoothly; she crossed.",
        "safe",
    ),
    # 23: "zero issues until" is no safe cue
    ("There were zero issues until a van pulled out 10 m ahead of me at 30 mph and I had to swerve.", "near_miss"),
    ("No problems till a van pulled out 10 m ahead of me at 30 mph and I had to swerve.", "near_miss"),
    # 23 guard
    ("A van pulled out 40 m ahead of me at 30 mph. Zero issues, it went on its way.", "safe"),
]


@pytest.mark.parametrize("text,intent", CASES)
def test_outcome(text: str, intent: str) -> None:
    got = _intent(text)
    if intent.startswith("!"):
        assert got != intent[1:], (text, got)
    else:
        assert got == intent, (text, got)


def test_id_have_to_say_keeps_the_ego_speed() -> None:
    layers = layers_from_text("I'd have to say the van hit me pretty hard at 30 mph after pulling out.", 0)
    assert abs(layers["ego"]["speed_mps"] - 13.411) < 0.01
