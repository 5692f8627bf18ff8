"""A walker or rider said to come off the kerb or out from cover, of whom nothing more is said than a
brake (the ego's, with no subject or said of the driver), crosses the ego's road; the brake is the
ego's. Wordings written for the class in several registers (a text, a police note, a voice note, a
script, a test log, a forum post), none taken from a corpus; near misses keep their readings."""

from __future__ import annotations

import pytest

from vei_scenario.language import kerb_crossing
from vei_scenario.language.crossing_reaction import MARK
from vei_scenario.language.reader import read


def _acts(text: str) -> list[tuple[str, list[str], str | None]]:
    """Each road user read from ``text``: its kind, its behaviours' names and where it starts."""
    return [(a.kind, [b[0] for b in a.behaviours], a.relation) for a in read(text).actors]


def _mover(text: str) -> tuple[str, list[str], str | None]:
    """The first road user read from ``text`` that is no parked vehicle."""
    return next(x for x in _acts(text) if x[1] != ["stop"])


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("boy on bike came out between parked vans i braked just missed him", "bicycle"),
        ("Kid on bike came out between parked cars. Braked hard, missed him.", "bicycle"),
        ("A lad on an e-scooter flew off the footpath, hit the brakes, missed him by a foot.", "e-scooter"),
        ("Jogger came off the curb on the right, braked hard.", "pedestrian"),
        ("One cyclist came off the footpath suddenly, applied brakes fully.", "bicycle"),
        ("A woman with a pram came off the pavement on the left, braked hard, stopped in time.", "pedestrian"),
    ],
)
def test_out_of_cover_then_a_brake_crosses(text: str, kind: str) -> None:
    """Out from cover and then the ego's brake: a crossing from the kerb, the brake no act of its own."""
    got_kind, names, relation = _mover(text)
    assert (got_kind, names) == (kind, ["cross_in_front"])
    assert relation is not None and relation.startswith("roadside")


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist came off the pavement and stopped at the kerb.",  # (its own stop, placed)
        "A cyclist came from behind a bus and overtook me.",  # (its move is said)
        "A man was standing between two parked cars.",  # (no coming out)
        "A van came out from behind a parked lorry, I braked.",  # (a vehicle joins the traffic)
        "A jogger came off the footpath and ran down the middle of the road towards us, braked.",  # (at the ego)
    ],
)
def test_near_misses_keep_their_reading(text: str) -> None:
    """No crossing where the road user's own move or stop is said, it does not come out, or it drives."""
    assert all(names[:1] != ["cross_in_front"] for _, names, _ in _acts(text))


def test_only_going_and_free_brakes() -> None:
    """The pass reads bare goings and free brakes only, of walkers and riders only, quiet ones only."""
    free = ("sudden_stop", {MARK: 1.0}, None, "sequence")
    going = ("keep_going", {}, None, "sequence")
    own = ("sudden_stop", {}, None, "sequence")
    assert kerb_crossing.crossing_then_brakes("pedestrian", [going, free], True, False) == [
        ("cross_in_front", {}, None, "sequence"),
        free,
    ]
    assert kerb_crossing.crossing_then_brakes("e-scooter", [free], True, True) is not None  # ("darts off")
    assert kerb_crossing.crossing_then_brakes("e-scooter", [free], True, False) is None  # (no move said)
    assert kerb_crossing.crossing_then_brakes("pedestrian", [going, own], True, False) is None  # (its own stop)
    assert kerb_crossing.crossing_then_brakes("car", [going, free], True, False) is None  # (a vehicle)
    assert kerb_crossing.crossing_then_brakes("pedestrian", [going, free], False, False) is None  # (not quiet)
    assert kerb_crossing.crossing_then_brakes("pedestrian", [going], True, False) is None  # (no brake)


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A boy on a bike came off the pavement on the right. It stopped and waited for him.", "bicycle"),
        ("A lady came off the kerb on my left and it slowed right down for her.", "pedestrian"),
        ("Some kids came off the pavement, it stopped for them.", "pedestrian"),
        ("A man on a bike came off the footpath, he braked and waited for him.", "bicycle"),
        ("Lad on a scooter came off the sidewalk. It halted for him, no drama.", "e-scooter"),
    ],
)
def test_a_stop_made_for_the_one_road_user_is_the_egos(text: str, kind: str) -> None:
    """A pronoun that stops or waits "for him/her/them", the only road user named, is not that road user."""
    got_kind, names, relation = _mover(text)
    assert (got_kind, names) == (kind, ["cross_in_front"])
    assert relation is not None and relation.startswith("roadside")


@pytest.mark.parametrize(
    "text",
    [
        "A girl on a bike came off the pavement. She stopped and waited for him.",  # (another person)
        "A van pulled out. It stopped and waited for her.",  # (a vehicle is no "her")
        "A cyclist came off the pavement. He stopped and waited for the bus.",  # (no pronoun object)
    ],
)
def test_a_stop_for_someone_else_stays(text: str) -> None:
    """Another person's pronoun, a vehicle or a named object: the stop keeps its reading."""
    assert all(names[:1] != ["cross_in_front"] for _, names, _ in _acts(text))


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        (
            "A man on a bike rode along the footpath, then went off the kerb and across the road in front of me.",
            "bicycle",
        ),
        ("Rider on a scooter rides along the pavement on my left, then swings off the kerb and across.", "e-scooter"),
        ("Pedestrian walking along the footpath, then came from the kerb across the road.", "pedestrian"),
        (
            "Bloke on a bike cruising down the sidewalk, then he's come off the curb straight across my bonnet.",
            "bicycle",
        ),
        ("Cyclist was riding on the footpath then came off the kerb in front of us.", "bicycle"),
    ],
)
def test_along_the_pavement_then_off_the_kerb_crosses(text: str, kind: str) -> None:
    """Going along the pavement, then off the kerb with the subject left out: the kerb it leaves is its
    own, and leaving it is a crossing (the pavement is off the road, no going along the ego's road)."""
    got_kind, names, relation = _mover(text)
    assert (got_kind, names) == (kind, ["cross_in_front"])
    assert relation is not None and relation.startswith("roadside")


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist rode along the pavement.",  # (stays on it)
        "A cyclist was riding along the pavement, then on the road ahead of us.",  # (no leaving said)
        "A lad rode along the footpath beside me, past the kerb, all the way to the shops.",  # (no leaving)
    ],
)
def test_along_the_pavement_and_staying_is_no_crossing(text: str) -> None:
    """Riding along the pavement with no leaving of it said: no crossing."""
    assert all(names[:1] != ["cross_in_front"] for _, names, _ in _acts(text))
