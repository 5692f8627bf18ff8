"""A walker or rider told to go "across" with no way named after it crosses the ego's road: the adverb
alone ("straight across", "across in front", "and across the front of the lorry"), with no verb, a
plain going or a verb the reader has no word for, is the crossing. Sentences written for the rule in
several registers (a clipped note, a comic's panels, a voiceover, a depot report), none taken from a
corpus; near misses that look alike keep their readings: a way named after "across", a crossing told
behind the ego, a vehicle, the ego itself, and a rider going along the road."""

from __future__ import annotations

import pytest

from vei_scenario.language import across_alone, reader
from vei_scenario.language.rules_backend import layers_from_text


def _moving(text: str) -> list[tuple[str, str, str]]:
    """The road users of ``text`` (seed 0) that do more than stand: type, first behaviour, relation."""
    out = []
    for adv in layers_from_text(text, 0)["adversaries"]:
        node = adv["behaviour"]
        name = node["sequence"][0]["behaviour"] if "sequence" in node else node["behaviour"]
        if name != "stop":
            out.append((adv["type"], name, adv["spawn"]["relation"]))
    return out


def _first(text: str) -> tuple[str, str, str]:
    moving = _moving(text)
    assert moving, f"no moving road user read from {text!r}"
    return moving[0]


@pytest.mark.parametrize(
    ("text", "kind", "side"),
    [
        (
            "Note 14, 17:40, 20 mph on a terraced street: kid on a bike out from behind a parked lorry on my "
            "right, straight across in front, I braked, no contact.",
            "bicycle",
            "right",
        ),
        (
            "Panel 1: Tuesday, half eight, Maureen's Fiesta at 25 mph. Panel 2: A jogger off the right kerb "
            "from nowhere. Straight across. Panel 3: Brakes.",
            "pedestrian",
            "right",
        ),
        (
            "So we're doing about 30 down the high street and a lad on an e-scooter just launches himself "
            "off the footway on the left, no look, straight across. Cammer brakes, misses him.",
            "e-scooter",
            "left",
        ),
        (
            "Depot report: lorry moving off from the lights at 8 mph when a cyclist came off the footway on "
            "the nearside and across the front of the cab. Driver stopped, no contact.",
            "bicycle",
            "left",
        ),
    ],
)
def test_a_bare_across_of_a_walker_or_rider_is_a_crossing(text: str, kind: str, side: str) -> None:
    """ "Across" with nothing crossed named after it, told of a walker or rider: a crossing of the
    ego's road from the side it came off."""
    assert _first(text) == (kind, "cross_in_front", f"roadside_{side}")


def test_the_crossing_is_given_to_the_rider_not_the_parked_vehicle_it_came_from() -> None:
    """The vans it came out from between stand; the rider is the one that goes across."""
    moving = _moving(
        "Clip: 18 mph, residential, a scooter out from between two parked vans on my left straight across in front."
    )
    assert moving[0][:2] == ("e-scooter", "cross_in_front")
    assert all(kind != "van" or name != "cross_in_front" for kind, name, _ in moving)


@pytest.mark.parametrize(
    ("text", "reading"),
    [
        # a vehicle said to go straight across comes out of its side road
        (
            "At the crossroads I was doing 30 mph when a van came out of the side road on my left, straight across.",
            ("van", "turn_into", "junction_left"),
        ),
        # the ego is the one that goes across; the cyclist only rides ahead
        (
            "A cyclist was riding ahead of me along the road. At the lights I went straight across.",
            ("bicycle", "along_road", "ahead"),
        ),
        # a rider going along the road, waved on by the ego
        (
            "I was doing 20 mph behind a cyclist riding along the road; I waved and she carried on.",
            ("bicycle", "along_road", "ahead"),
        ),
    ],
)
def test_near_misses_keep_their_readings(text: str, reading: tuple[str, str, str]) -> None:
    """Guards: a vehicle, the ego going across, a rider going along: read as before."""
    assert _first(text) == reading


@pytest.mark.parametrize(
    "text",
    [
        "I was driving at 40 km/h while a cyclist rode across the car park beside the road.",
        "A boy on a scooter was riding along the pavement across the junction from us.",
    ],
)
def test_an_across_with_a_way_of_its_own_is_left_alone(text: str) -> None:
    """Guard: what "across" crosses is named after it, so the bare-across rule adds nothing."""
    clauses, _, _, scanned = reader.scan(text)
    assert across_alone.across_alone(clauses, scanned) == [(link, list(ms)) for link, ms in clauses]


def test_across_behind_is_left_to_the_rest_of_the_reader() -> None:
    """Guard: "across behind" puts the move behind the ego, so the bare-across rule adds no crossing
    (what the clause says is left as scanned)."""
    text = "I was reversing out slowly when a kid on a scooter came off the pavement and across behind me."
    clauses, _, _, scanned = reader.scan(text)
    assert across_alone.across_alone(clauses, scanned) == [(link, list(ms)) for link, ms in clauses]


def test_a_verbless_across_joins_the_road_user_named_before_it() -> None:
    """ "Straight across." with no subject of its own: the walker named in the sentence before it."""
    clauses, _, _, scanned = reader.scan("A man in a hi-vis jacket appeared from nowhere. Straight across.")
    out = across_alone.across_alone(clauses, scanned)
    added = [m for _, ms in out for m in ms if m.slot == "behaviour" and m.words == "across"]
    assert [m.value[0] for m in added] == ["cross_in_front"]


def test_a_rider_turning_across_keeps_its_turn() -> None:
    """Guard: a rider in a lane who swings across the front of the ego to an exit turns; the bare-across
    rule adds no crossing to the turn."""
    text = (
        "On the ring road roundabout I was going straight on when a cyclist in the cycle lane on my left "
        "swung right across the front of my car to get to the next exit. I braked."
    )
    names = [
        node["behaviour"]
        for adv in layers_from_text(text, 0)["adversaries"]
        for node in (adv["behaviour"]["sequence"] if "sequence" in adv["behaviour"] else [adv["behaviour"]])
    ]
    assert "cross_in_front" not in names
