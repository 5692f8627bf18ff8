"""Lengths that are no gap to the ego, found by review after lengths in words were read as figures: a
length "visibility" does not govern (the road user's own distance in a clause after a visibility), a
pass's look-back across "and" into a new clause, side room off a vehicle's door or mirror after a verb
of passing, a length before or from a line, a crossing or the kerb; and words that only look like a
length ("a foot off the brake", "a foot passenger", "a meter maid", "1,5 cm")."""

from __future__ import annotations

import pytest

from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.normalise import normalise
from vei_scenario.language.rules_backend import layers_from_text


def _lengths(text: str) -> list[float]:
    """Every road user's start distance and every distance its behaviours carry (seed 0)."""
    out = []
    for adv in layers_from_text(text, 0)["adversaries"]:
        out.append(abs(float(adv["spawn"].get("longitudinal_m", float("nan")))))
        for _, node in behaviour_nodes(adv["behaviour"]):
            out += [float(node["config"][k]) for k in ("gap_m", "distance_m") if k in node["config"]]
    return out


def _has(text: str, length: float) -> bool:
    return any(abs(g - length) < 0.05 for g in _lengths(text))


@pytest.mark.parametrize(
    ("text", "length", "visibility"),
    [
        ("Visibility was good and a lorry braked 30 m ahead of me at 80 km/h.", 30.0, None),
        ("With visibility at 50 m a lorry braked 30 m ahead of me at 80 km/h.", 30.0, 50.0),
        ("In poor visibility a car pulled out 20 m ahead of me at 50 km/h.", 20.0, None),
        ("I was driving at 40 mph with about 30 m visibility when a deer ran out 15 m ahead.", 15.0, 30.0),
        # (variants)
        ("In bad visibility a van stopped 25 m ahead of me; I was at 60 km/h.", 25.0, None),
        ("Visibility was down to 40 m and a cyclist swerved 12 m ahead of me at 30 km/h.", 12.0, 40.0),
    ],
)  # fmt: skip
def test_a_length_visibility_does_not_govern_is_the_road_users(text: str, length: float, visibility: float) -> None:
    """ "Visibility" heads only the length it governs (after was/at/down to, or "N m visibility"); a verb
    or a new clause between them gives the length to the road user of that clause."""
    assert _has(text, length), _lengths(text)
    if visibility is not None:
        assert not _has(text, visibility), _lengths(text)


@pytest.mark.parametrize(
    "text",
    [
        "Visibility was down to about 50 metres in the fog when a cyclist came towards me.",
        "Visibility was reduced to 50 m in the rain when a cyclist came towards me at 20 km/h.",
        "The visibility in the spray was under 50 m when a cyclist came towards me at 20 km/h.",
    ],
)
def test_a_length_visibility_governs_stays_no_gap(text: str) -> None:
    assert _lengths(text) and not _has(text, 50.0), _lengths(text)


@pytest.mark.parametrize(
    ("text", "length"),
    [
        ("The car passed me and with 10 m between us it braked hard at 50 mph.", 10.0),
        ("The van passed us and then with 12 m between us it stopped dead at 40 mph.", 12.0),
    ],
)
def test_a_length_after_with_in_a_new_clause_is_no_pass_room(text: str, length: float) -> None:
    assert _has(text, length), _lengths(text)


@pytest.mark.parametrize(
    ("text", "length"),
    [
        ("I stopped at a parking meter and a cyclist came past a metre from my door at 25 km/h.", 1.0),
        ("A motorcyclist overtook me at 60 mph, passing a metre from my mirror.", 1.0),
        ("A truck came past me a foot from my mirror at 50 mph.", 0.3),
        # (variants)
        ("A bus squeezed past us 50 cm from the wing mirror at 30 mph.", 0.5),
        ("I was doing 20 mph when a motorbike went by a couple of feet from my door.", 0.61),
        # (guard: the "with" case the rule follows)
        ("I was riding at 20 km/h and a van came towards me and passed with half a metre to spare.", 0.5),
    ],
)
def test_side_room_off_a_door_or_mirror_on_a_pass_is_no_gap(text: str, length: float) -> None:
    assert _lengths(text) and not _has(text, length), _lengths(text)


@pytest.mark.parametrize(
    ("text", "length"),
    [
        ("A car ahead of me stopped a metre before the stop line; I was at 40 km/h.", 1.0),
        ("A car ahead of me stopped, visibility being bad, a couple of metres from the crossing; I was at "
         "40 km/h.", 2.0),
        # (variants)
        ("A van in front of me pulled up 3 m short of the zebra crossing while I was doing 30 mph.", 3.0),
        ("A cyclist in front of me stopped 2 m before the lights; I was at 20 km/h.", 2.0),
    ],
)  # fmt: skip
def test_a_length_before_a_line_or_crossing_is_no_gap(text: str, length: float) -> None:
    assert _lengths(text) and not _has(text, length), _lengths(text)


def test_a_length_to_the_ego_said_in_words_stays_a_gap() -> None:
    """(guard: what spoken lengths were read for)"""
    assert _has("Doing 25 mph through the estate, a lad ran out between two vans. I stopped a metre from him.", 1.0)


@pytest.mark.parametrize(
    ("said", "digits"),
    [
        ("one car length and a half back", "1.5 car lengths back"),
        ("a metre and a half", "1.5 metres"),
        ("1,5 cm from him", "0.015 m from him"),
        ("about a foot from him", "about 0.3 m from him"),
    ],
)
def test_a_length_in_words_is_said_in_digits(said: str, digits: str) -> None:
    assert digits in normalise(said), normalise(said)


@pytest.mark.parametrize(
    "said",
    [
        "he took a foot off the brake",
        "just a foot passenger",
        "only a foot bridge",
        "a meter maid",
        "like a foot bridge",
    ],
)
def test_a_foot_or_meter_that_names_a_thing_stays_a_word(said: str) -> None:
    text = normalise(said)
    assert " m " not in f" {text} " and "0.3" not in text and "1 meter" not in text, text
