"""A text addressed to a road user ("To the jogger on Elm St - you ran across ...") tells that road user
what they did as "you". Wordings written for the class (a community post, a thank-you note, a text
read out on the radio, a noticeboard note), none taken from a corpus; near misses where "to" is no
address keep their readings."""

from __future__ import annotations

import pytest

from vei_scenario.language import addressee
from vei_scenario.language.reader import _kind_at, read


def _acts(text: str) -> list[tuple[str, list[str]]]:
    return [(a.kind, [b[0] for b in a.behaviours]) for a in read(text).actors]


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("To the jogger on Elm St at 6am - you ran across the road right in front of my car.", "pedestrian"),
        ("To the lady with the pram yesterday - you stepped out without looking. I was doing 30.", "pedestrian"),
        ("To the lad in the red hoodie near the school, you walked out in front of my van!!", "pedestrian"),
        ("To the cyclist outside Tesco this morning - you rode across in front of me. Lights, please.", "bicycle"),
        ("To that runner by the park gates, you dashed across the road in front of me in the fog.", "pedestrian"),
    ],
)
def test_the_one_addressed_does_what_you_did(text: str, kind: str) -> None:
    """What "you" did is the addressed road user's: here a crossing."""
    assert (kind, ["cross_in_front"]) in _acts(text)


@pytest.mark.parametrize(
    "text",
    [
        "To the station I drove, and a cyclist cut in front of me.",  # (a place, no road user)
        "A jogger ran across the road. To the left a cyclist rode along the kerb.",  # (no "you")
        "I was talking to the cyclist when you called.",  # (no opening "to")
    ],
)
def test_no_address_keeps_its_to(text: str) -> None:
    tokens = text.lower().replace(".", " .").replace(",", " ,").split()
    assert addressee.spoken_to(tokens, _kind_at) == tokens


def test_an_address_loses_its_to() -> None:
    tokens = "to the jogger on elm st - you ran across".split()
    assert addressee.spoken_to(tokens, _kind_at) == tokens[1:]
