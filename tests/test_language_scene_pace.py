"""The ego's speed where the one speed of the scene was read on a road user (scene_pace)."""

from __future__ import annotations

import pytest

from tests.reading_of import ego_kph
from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def layers_ego_kph(text: str) -> float:
    """The ego's speed in the layers of ``text`` (seed 0), km/h."""
    return float(layers_from_text(text, 0)["ego"]["speed_mps"]) * 3.6


#: The ego's speed said where no grammar of the reader places it: the only speed of the scene.
SAID_OF_THE_SCENE = [
    ("Test: no AEB response to a cyclist pulling out from the left kerb @ 40 kph, dry, daylight.", 40),
    ("The bus driver said he ploughed into the moped doing about 35 km/h, he could not stop.", 35),
    ("My son was driving, he was going like 40 km/h when a boda boda came the wrong way at him.", 40),
    ("Bug: pedestrian crossing from the right spawns too late (ego straight, 60 km/h)", 60),
    ("Taxi man says he knocked the okada rider doing roughly 50kph at the junction.", 50),
]


@pytest.mark.parametrize(("text", "kph"), SAID_OF_THE_SCENE)
def test_the_one_speed_of_the_scene_is_the_egos_when_none_is_read(text: str, kph: float) -> None:
    assert layers_ego_kph(text) == pytest.approx(kph, abs=0.2)


#: Near misses: a speed the ego does not share, or one the ego's own already stands beside.
NOT_THE_EGOS = [
    # one passes the other: their speeds differ
    "A cyclist riding along the kerb ahead at 20 km/h, I overtake it with plenty of room.",
    "A van overtook me doing 90 km/h and cut in sharply.",
    # a walking pace is no traffic's
    "A pedestrian walking at 4 km/h steps off the kerb in front of me.",
    # two speeds: nothing tells whose pace the ego shares
    "A lorry at 60 km/h brakes ahead of me while a bus at 40 km/h comes the other way.",
]


@pytest.mark.parametrize("text", NOT_THE_EGOS)
def test_no_speed_of_the_scene_where_the_ego_does_not_share_it(text: str) -> None:
    r = read(text)
    assert r.ego_speed_mps is None and r.scene_pace_mps is None


def test_the_egos_own_speed_wins() -> None:
    assert layers_ego_kph("I was doing 50 km/h when a scooter at 20 km/h pulled out ahead.") == pytest.approx(
        50, abs=0.2
    )


def test_the_reading_keeps_the_egos_speed_unsaid() -> None:
    """The scene's pace is the layers' default, not a speed the text says of the ego."""
    r = read("Test: no AEB response to a cyclist pulling out from the left kerb @ 40 kph, dry, daylight.")
    assert r.ego_speed_mps is None and r.scene_pace_mps == pytest.approx(40 / 3.6)


#: A text opening with a verb's base form and a number names a numbered part of it (a heading), no speed.
HEADINGS = [
    "Drive 3 - please read carefully. A cyclist will pull out of a side road on your left.",
    "Run 2: an e-scooter rider crosses the road in front of you from the right kerb.",
    "Go 4 - a pedestrian steps out between parked cars on your left.",
    "Ride 1. A car pulls out of a driveway on your right in front of you.",
    "Drive 12 — at the crossroads a van turns across your path.",
]


@pytest.mark.parametrize("text", HEADINGS)
def test_a_heading_number_is_no_speed(text: str) -> None:
    assert ego_kph(text) is None


#: Near misses: the verb said as the narrator's own going, with its speed.
OPENED_WITH_A_SPEED = [
    ("Driving 30, a kid on a scooter shot out in front of me.", 30),
    ("Going 40 when a van pulled out of a side road on my left.", 40),
]


@pytest.mark.parametrize(("text", "kph"), OPENED_WITH_A_SPEED)
def test_a_speed_opening_a_text_is_still_the_egos(text: str, kph: float) -> None:
    assert ego_kph(text) == pytest.approx(kph, abs=0.2)


def test_a_stated_ego_speed_draws_nothing_so_every_later_draw_stays_as_it_was(monkeypatch) -> None:
    """The ego's speed is drawn only where none is read (from the text or the scene's pace): a stated
    one takes no draw, so the scenarios of a text that states it keep the details they always had."""
    from vei_scenario.language import rules_backend

    calls: list[tuple[float, float]] = []
    real = rules_backend._u

    def counting(rng, lo: float, hi: float) -> float:
        calls.append((lo, hi))
        return real(rng, lo, hi)

    monkeypatch.setattr(rules_backend, "_u", counting)
    text = "A car overtakes me and cuts back in on a straight road."
    unsaid = read(text)
    rules_backend.sample_layers(unsaid, text, 0)
    drawn_unsaid = len(calls)
    calls.clear()
    said = read("I am doing 80 km/h. " + text)
    assert said.ego_speed_mps is not None and unsaid.ego_speed_mps is None
    rules_backend.sample_layers(said, text, 0)
    assert len(calls) == drawn_unsaid - 1
