"""Two ways a crossing is said that the reader read as going along: leaving a kerb or pavement that the
writer describes ("off the dropped kerb", "from the far pavement") and a crossing stressed with "right"
("rode right across the front of my car"). Wordings written for the class in several registers (a
text, a police note, a voice note, a test spec, a forum post), none taken from a corpus; near misses
(a rider going along the road, a walker who stays on the pavement, one who waits at the kerb, a
heading said with "right") keep their readings."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


def _acts(text: str) -> list[tuple[str, list[str], str | None]]:
    """Each road user read from ``text``: its kind, its behaviours' names and where it starts."""
    return [(a.kind, [b[0] for b in a.behaviours], a.relation) for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("Kid on a bike bumped off the high curb into the street ahead of me, I was doing 25 mph.", "bicycle"),
        ("An elderly man walked off the raised kerb into the road about 20 m ahead of us.", "pedestrian"),
        (
            "A woman on a scooter went along the busy pavement on my left and off the dropped kerb across the road.",
            "e-scooter",
        ),
        (
            "Rider was coming down the footpath then came off the dropped kerb straight across in front of me. "
            "I braked hard.",
            "e-scooter",
        ),
        ("Test 4: ego 30 km/h, a pedestrian steps off the low kerb on the left 12 m ahead.", "pedestrian"),
        (
            "A youth on a bicycle rode along the footway and came off the lowered kerb into the carriageway "
            "in front of the vehicle.",
            "bicycle",
        ),
    ],
)
def test_off_a_described_kerb_crosses(text: str, kind: str) -> None:
    """Coming off a kerb or pavement the writer describes ("the dropped kerb") is coming off it, as
    "off the kerb" is: a crossing from that side, even after going along the pavement."""
    acts = _acts(text)
    assert [(k, names) for k, names, _ in acts] == [(kind, ["cross_in_front"])]
    assert (acts[0][2] or "").startswith("roadside")


@pytest.mark.parametrize(
    "text",
    [
        "A woman walked along the busy pavement on my left while I drove past at 30 km/h.",
        "A boy on a scooter rode along the wide pavement beside me as I drove at 20 mph.",
        "A cyclist was riding along the road on my left and I overtook him at 50 km/h.",
        "The cyclist hugging the kerb on my left wobbled and I braked.",
    ],
)
def test_along_a_described_pavement_is_no_crossing(text: str) -> None:
    """Going along a pavement or road, however the place is described, is no leaving of it."""
    assert all("cross_in_front" not in names for _, names, _ in _acts(text))


def test_waiting_at_a_described_kerb_is_no_crossing() -> None:
    """One who waits at the dropped kerb and does not go does not cross."""
    acts = _acts("A man stood waiting at the dropped kerb and did not go; I drove on at 30 km/h.")
    assert all("cross_in_front" not in names for _, names, _ in acts)


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A rider came right across my path at the lights.", "e-scooter"),
        ("A kid ran right across the road in front of me.", "pedestrian"),
        ("A cyclist rode right across the front of my car.", "bicycle"),
        ("lad on a scooter went right across our bows, had to stand on it", "e-scooter"),
        ("Ego 40 km/h; a pedestrian walks right across in front of the ego at 15 m.", "pedestrian"),
    ],
)
def test_right_stressing_across_is_no_side(text: str, kind: str) -> None:
    """ "Right" before "across" after a plain verb of going stresses the crossing ("came right across"):
    no side of the road, and the verb's phrase with "across" is read around it."""
    acts = _acts(text)
    assert [(k, names) for k, names, _ in acts] == [(kind, ["cross_in_front"])]


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("A van swerved right across my lane and I braked.", ("van", ["cut_in"], "right")),
        (
            "The oncoming car turned right across my path at the junction.",
            ("car", ["turn_across"], "junction_opposite"),
        ),
    ],
)
def test_a_heading_right_across_stays_a_side(text: str, want: tuple) -> None:
    """A verb of heading keeps its "right" ("swerved right across", "turned right across")."""
    assert _acts(text) == [want]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("A pedestrian went straight across the road in front of the ego at 20 m.", "pedestrian"),
        ("A lad came off the pavement and went straight across the road in front of me.", "pedestrian"),
        ("Cyclist came straight across the front of my car, I had to brake.", "bicycle"),
        ("A kid on a scooter went straight across in front of us, missed him by a foot.", "e-scooter"),
        ("A woman with a pram went straight across our path while I was doing 25 mph.", "pedestrian"),
    ],
)
def test_straight_across_crosses(text: str, kind: str) -> None:
    """ "Went straight across" is "went across", "straight" saying only how directly: a crossing, not the
    plain going the lexicon's "go straight" (the ego's route) would make it."""
    assert [(k, names) for k, names, _ in _acts(text)] == [(kind, ["cross_in_front"])]


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist went straight across the junction ahead of me.",
        "The car went straight across the junction without stopping and hit me.",
        "A cyclist went straight on along the road ahead of me.",
    ],
)
def test_straight_through_a_junction_or_on_is_no_crossing(text: str) -> None:
    """Straight across a junction is through it, a vehicle's going straight across is other rules', and
    going straight on is going along."""
    assert all("cross_in_front" not in names for _, names, _ in _acts(text))


def test_the_ego_going_straight_across_keeps_its_route() -> None:
    """The ego's "went straight across the junction" stays its route straight on."""
    reading = read("I went straight across the junction at 30 when a van pulled out from the left.")
    assert reading.ego_route == "straight"


@pytest.mark.parametrize(
    "text",
    [
        "A woman was on the zebra when I came round the corner at 25 mph and I had to brake hard.",
        "An old man was halfway over the zebra as I approached at 20 mph.",
        "Lady with a pushchair on the zebra, van didn't stop, went straight past her at 30.",
        "Ego 30 km/h; a pedestrian on the pelican 20 m ahead.",
        "There was a boy on the puffin when I came up to it at 20 mph.",
    ],
)
def test_on_a_crossing_named_by_its_kind_alone_crosses(text: str) -> None:
    """A foot crossing named by its kind alone ("the zebra", "the pelican") is the crossing: a walker on
    or halfway over it is crossing on it, as on "the zebra crossing"."""
    assert [(k, names) for k, names, _ in _acts(text)] == [("pedestrian", ["cross_in_front"])]


def test_waiting_at_a_crossing_named_by_its_kind_is_no_crossing() -> None:
    """Waiting at the puffin for the green man is no crossing."""
    acts = _acts("A man stood at the puffin waiting for the green man while I drove past at 30.")
    assert all("cross_in_front" not in names for _, names, _ in acts)
