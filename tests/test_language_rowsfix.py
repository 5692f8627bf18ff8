"""Review findings 7-14 and 26 of the merged round: a move said of a parked row past an adverb, "then"
or "one of which"; a speed hung on a row that is the ego's; "one of them e-bikes"; a plural that
"couldn't" or "would not" is still told doing something; the side of a cover that does not stand.
The review's sentences and variants; guards keep the readings the rules were built for."""

from __future__ import annotations

import pytest

from vei_scenario.language.rules_backend import layers_from_text


def _users(text: str) -> list[tuple[str, str, str, float]]:
    """Each road user of ``text``: type, start relation, behaviour and speed."""
    return [
        (a["type"], a["spawn"].get("relation"), a["behaviour"]["behaviour"], float(a["speed_mps"]))
        for a in layers_from_text(text, 0)["adversaries"]
    ]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("Two parked cars suddenly pulled out in front of a cyclist 20 m ahead of me at 20 mph.", "car"),
        ("The parked vans then started up and one pulled out and hit a cyclist ahead of me at 20 mph.", "van"),
        ("Past the parked cars, one of which then pulled out, a cyclist swerved 15 m ahead at 25 mph.", "car"),
        ("Two parked vans both pulled out in front of a cyclist 20 m ahead of me at 20 mph.", "van"),
        ("Past the parked vans, one of them suddenly pulled out, a cyclist braked 15 m ahead at 25 mph.", "van"),
    ],
)
def test_a_move_said_of_a_parked_row_past_an_adverb_is_its_own(text: str, kind: str) -> None:
    assert any(k == kind and b == "cut_in" for k, _, b, _ in _users(text))


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("Past the parked cars, one of which was empty, a cyclist swerved 15 m ahead at 25 mph.", "car"),
        ("I was doing about 25 when a little boy ran into the road from between two parked cars on my right.", "car"),
        ("Cars parked both sides as usual, and a kid on a bike suddenly shot out in front of me at 20 mph.", "car"),
    ],
)
def test_a_parked_row_of_which_nothing_moves_still_stands(text: str, kind: str) -> None:
    assert all(b == "stop" and v == 0.0 for k, _, b, v in _users(text) if k == kind)


def test_a_speed_hung_on_a_parked_row_is_the_ego_s() -> None:
    layers = layers_from_text("Past the parked lorries a cyclist swerved into my lane 15 m ahead at 25 mph.", 0)
    assert layers["ego"]["speed_mps"] == pytest.approx(11.176, abs=0.01)
    assert all(a["speed_mps"] == 0.0 for a in layers["adversaries"] if a["type"] == "truck")


def test_a_speed_hung_on_a_parked_row_beside_the_egos_own_stays_off_the_ego() -> None:
    text = "I was doing 20 mph past the parked vans at 30 mph when a cyclist swerved out 15 m ahead."
    assert layers_from_text(text, 0)["ego"]["speed_mps"] == pytest.approx(8.941, abs=0.01)


def test_a_row_that_pulls_away_slowly_moves_and_leaves_the_ego_its_speed() -> None:
    text = "Parked lorries slowly pulled away from the depot, and a cyclist ahead of me at 15 km/h wobbled."
    layers = layers_from_text(text, 0)
    assert layers["ego"]["speed_mps"] != 0.0
    assert any(a["type"] == "truck" and a["behaviour"]["behaviour"] != "stop" for a in layers["adversaries"])


@pytest.mark.parametrize(
    "text",
    [
        "A kid on one of them e-bikes pulled out 10 m ahead of me at 30 mph.",
        "A girl on one of them e-bikes came off the pavement 10 m ahead of me at 30 mph.",
    ],
)
def test_one_of_them_e_bikes_is_a_bicycle(text: str) -> None:
    assert [k for k, *_ in _users(text)] == ["bicycle"]


@pytest.mark.parametrize(
    "text",
    [
        "The joggers couldn't hear me and ran across the road 20 m ahead at 30 km/h while a jogger on the "
        "pavement watched.",
        "The pedestrians would not wait for the green man, and a man stepped out 10 m ahead of me at 30 km/h.",
        "The cyclists could not stop and rode into the junction 20 m ahead at 30 km/h while a cyclist on the "
        "path waited.",
    ],
)
def test_a_plural_that_could_not_or_would_not_is_still_there(text: str) -> None:
    kinds = [k for k, *_ in _users(text)]
    assert len(kinds) == 2 and len(set(kinds)) == 1


@pytest.mark.parametrize(
    "text",
    [
        "Those scooters should not be allowed on the pavement; a lad on a scooter came off the kerb in front of me.",
        "Cyclists must stop at red lights, but a cyclist rode through the red light 20 m ahead at 30 km/h.",
    ],
)
def test_a_plural_under_should_or_must_is_the_kind_in_general(text: str) -> None:
    assert len(_users(text)) == 1


def test_cover_that_does_not_stand_gives_no_side() -> None:
    text = "A van on my left was turning into a driveway and a cyclist came out from behind the van at 30 km/h."
    assert [r for k, r, *_ in _users(text) if k == "bicycle"] == ["roadside_right"]


def test_cover_parked_at_a_side_gives_its_side() -> None:
    text = "A van is parked on the left and a child runs out from behind the van at 30 km/h."
    assert [r for k, r, *_ in _users(text) if k == "pedestrian"] == ["roadside_left"]
