"""A heading line over a report (a ticket's title, a test case's name, a notice's headline) names the
road users its body then brings in afresh: the same ones, read once (heading). Wordings written for
the class: tickets whose title says what a rider or walker did and whose body tells it again with
"a" or "an". Near misses keep their road users: a first line ending as a sentence, one with a subject
pronoun, a body that brings in "another", one it names as said before, a heading's vehicle named as
someone's, a heading's road user of a kind the body never names, lines of a list."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from tests.reading_of import kinds
from vei_scenario.language import heading
from vei_scenario.language.reader import _tokens, scan
from vei_scenario.language.reading import ActorSpec, Reading


@dataclass
class _Said:
    kind: str
    det: str = ""
    named_after: str = ""
    named_end: int = -1
    counted: bool = False
    said: frozenset = frozenset()  # (what heading_named.told_apart reads: nothing said apart)
    side: str | None = None
    kerb_side: str | None = None
    lane_side: str | None = None
    edge: str | None = None
    parked: bool = False
    object_of: object = None


_TICKET = (
    "E-scooter pulls out of a side road on the left, ego brakes late\n\n"
    "We drive on along the high street at 40 km/h. An e-scooter comes out of the side road and turns"
    " into our road about 12 m ahead of us, going our way. Ego brakes gently."
)


def _fold(said: list[_Said], end: int | None) -> list[int]:
    """Where the road users left after folding were named (``named_end``)."""
    reading = Reading(actors=[ActorSpec(a.kind) for a in said])
    kept = heading.fold_told_again(list(said), reading, end)
    assert [s.kind for s in reading.actors] == [a.kind for a in kept]
    return [a.named_end for a in kept]


def _end(text: str) -> int | None:
    return heading.heading_end(text, scan(text)[3], _tokens)


def test_the_heading_ends_where_its_line_does() -> None:
    words = scan(_TICKET)[3]
    end = _end(_TICKET)
    assert end is not None and words[end - 1] == "." and words[end - 2] == "late"


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist pulled out of a side road in front of me.\nI braked hard and stopped a metre short of him.",
        "I braked for an e-scooter\nIt had come out of a side road on the left right in front of me at 20 km/h.",
        "Dear Sir,\nA cyclist rode out of a side road on the left in front of my car last Tuesday.",
        "A cyclist pulled out of a side road in front of me and I braked hard.",
        "a cyclist on the left at the lights\na van",
    ],
)
def test_no_heading(text: str) -> None:
    assert _end(text) is None


def test_a_road_user_the_body_brings_in_again_is_the_headings() -> None:
    said = [_Said("e-scooter", named_end=1), _Said("e-scooter", det="an", named_end=30), _Said("car", named_end=40)]
    assert _fold(said, 16) == [30, 40]


def test_a_counted_group_in_the_body_is_the_headings_group() -> None:
    said = [_Said("bicycle", named_end=2, counted=True)] * 2 + [_Said("bicycle", named_end=20, counted=True)] * 2
    assert _fold(said, 12) == [20, 20]


@pytest.mark.parametrize(
    "body",
    [
        _Said("e-scooter", det="another", named_end=30),  # (one more of its kind)
        _Said("e-scooter", det="the", named_end=30),  # (said before: the heading's own)
        _Said("e-scooter", named_end=30),  # (bare, as notes name one said before)
        _Said("e-scooter", det="a", named_after="second", named_end=30),
        _Said("bicycle", det="a", named_end=30),  # (another kind)
    ],
)
def test_the_headings_road_user_stays(body: _Said) -> None:
    said = [_Said("e-scooter", named_end=1), body]
    assert _fold(said, 16) == [1, 30]


def test_a_vehicle_named_as_someones_in_the_heading_stays() -> None:
    said = [_Said("van", named_after="'s", named_end=4), _Said("van", det="a", named_end=30)]
    assert _fold(said, 8) == [4, 30]


def test_no_heading_no_change() -> None:
    said = [_Said("e-scooter", named_end=1), _Said("e-scooter", det="an", named_end=30)]
    assert _fold(said, None) == [1, 30]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (_TICKET, ["e-scooter"]),
        (
            "PED-88 Pedestrian walking in our lane at night, seen late\n\nEgo at 60 km/h on a country road. A"
            " pedestrian walks along the right edge of our lane the same way as us. Seen at 35 m, ego brakes and"
            " steers left, passes with 1 m.",
            ["pedestrian"],
        ),
        (
            "Cyclist crossing from a side street, AEB late\n\nEgo at 40 km/h. A cyclist rides out of the side"
            " street on the right without stopping and crosses in front of us. AEB brakes hard 1 m short.",
            ["bicycle"],
        ),
    ],
)
def test_a_ticket_reads_its_road_user_once(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (  # (the body brings in one more)
            "E-scooter pulls out of a side road on the left, ego brakes late\n\nWe drive on along the high"
            " street at 40 km/h. Another e-scooter comes out of the side road and turns into our road about"
            " 12 m ahead of us, going our way. Ego brakes gently.",
            ["e-scooter", "e-scooter"],
        ),
        (  # (a first line with a subject pronoun: a sentence, the story's first moment)
            "I braked for an e-scooter that pulled out of a side road on the right\nWe drive on along the high"
            " street at 40 km/h. An e-scooter comes out of the side road and turns into our road about 12 m"
            " ahead of us, going our way. Ego brakes gently.",
            ["e-scooter", "e-scooter"],
        ),
        (  # (a heading's road user of a kind the body never names)
            "Van reverses out of a drive, ego stops\n\nWe go along a quiet street at 20 km/h. A pedestrian"
            " steps out from behind a hedge on the left and crosses.",
            ["van", "pedestrian"],
        ),
    ],
)
def test_near_misses_keep_their_road_users(text: str, expected: list[str]) -> None:
    assert kinds(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "How do I make an e-scooter cut in front of the ego at 25 km/h?\n\nThe ego drives at 40 km/h in the"
            " right lane. An e-scooter rides in the bike lane a bit ahead and should swerve into the ego's lane"
            " 10 m in front of it. Thanks!",
            ["e-scooter"],
        ),
        (
            "Why does my cyclist never turn across the ego?\n\nA cyclist comes the other way and should turn left"
            " into the side road right in front of the ego, which goes straight on at 30 km/h.",
            ["bicycle"],
        ),
        (
            "Can I make two pedestrians cross in front of the ego?\n\nA pedestrian crosses from the left 20 m"
            " ahead while another crosses from the right.",
            ["pedestrian", "pedestrian"],
        ),
    ],
    ids=["how-do-i", "why-does-my", "two-in-the-title"],
)
def test_a_question_set_over_a_post_as_its_title_names_the_body_s_road_user(text: str, expected: list) -> None:
    """A forum post's or an issue's title asks for what its body then tells: its road user is the body's."""
    assert kinds(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "Did you see the cyclist?\nHe came out of a side road on the left right in front of my car at 20 km/h.",
        "Did you see that van?\n\n",
        "Why did the cyclist swerve into my lane 10 m ahead when I was doing 30 mph.\n\nI braked hard.",
    ],
    ids=["no-blank-line", "no-body", "ends-as-a-sentence"],
)
def test_a_question_with_no_body_set_apart_is_no_title(text: str) -> None:
    assert _end(text) is None
