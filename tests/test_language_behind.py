"""Whether a road user starts ahead of the ego or behind it, where the words that say so attach to the
ego or to the road user by the grammar of the clause:

- one who rear-ends the ego came from behind it ("a taxi rear-ended us", "I got rear-ended by a
  bus"); one the ego rear-ends was ahead of it ("I rear-ended a hatchback");
- a place said of nobody ("there was nothing in front of me", "no one was behind us") places no road
  user, not the next one named;
- a rider who comes up the ego's nearside or offside ("came up on my nearside", "came up the
  offside") comes from behind, as one who comes up its inside does; one who pulls up there stops
  beside it;
- "following" before a noun of spacing ("following distance", "following gap") names the spacing,
  not a road user's place.

Near misses keep their old reading: a road user said to be behind the ego, one the ego follows, one
behind a place it comes out from.
"""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import layers_from_text


def _relations(text: str) -> list[str]:
    """The start relation of each adversary the layers of ``text`` (seed 0) hold, in order."""
    return [a["spawn"].get("relation") for a in layers_from_text(text, 0)["adversaries"]]


def _first_relation(text: str) -> str:
    return _relations(text)[0]


@pytest.mark.parametrize(
    "text",
    [
        # a claim form, the ego as the object
        "Stationary at the pelican crossing when a minicab rear-ended me, no injuries.",
        # a text message, passive with "got"
        "omg just got rear-ended by a delivery van on the ring road, im fine",
        # a formal letter, passive with "was"
        "On 4 May my vehicle was rear-ended by a coach while queuing at the roundabout.",
        # a fleet note, the ego in the plural
        "Our minibus braked for a fox and a pickup rear-ended us at about 15 mph.",
    ],
)
def test_one_that_rear_ends_the_ego_starts_behind(text: str) -> None:
    assert _first_relation(text) == "behind"


def test_one_the_ego_rear_ends_starts_ahead() -> None:
    assert _first_relation("I misjudged the queue and rear-ended a hatchback at walking pace.") == "ahead"


@pytest.mark.parametrize(
    "text",
    [
        "There was nothing in front of me, then the Volvo behind me ran into my back bumper.",
        "Nobody was ahead of us. A lorry behind us failed to slow and shunted us.",
        "Clear road, no one in front of me, when the van behind me hit my car.",
    ],
)
def test_a_place_said_of_nobody_places_no_road_user(text: str) -> None:
    assert _first_relation(text) == "behind"


@pytest.mark.parametrize(
    "text",
    [
        "While I was waiting at the lights a moped came up on my nearside and clipped my mirror.",
        "A courier on an e-bike came up the nearside at speed and hit the mirror.",
        "Stuck in traffic when a motorbike came up my offside and squeezed through.",
    ],
)
def test_coming_up_the_egos_nearside_or_offside_comes_from_behind(text: str) -> None:
    assert _first_relation(text) in ("behind", "left", "right")
    assert read(text).actors[0].relation == "behind"


def test_a_nearside_said_as_where_one_waits_is_not_from_behind() -> None:
    assert read("A taxi was waiting on my nearside at the lights.").actors[0].relation != "behind"


@pytest.mark.parametrize(
    "text",
    [
        "Trip review, wet road. Following distance to lead vehicle about 25 m. Lead car braked hard for a dog.",
        "Event log: following gap to the car in front 1.2 s, then the car in front braked hard.",
    ],
)
def test_following_before_a_noun_of_spacing_is_no_place(text: str) -> None:
    assert _first_relation(text) == "ahead"


@pytest.mark.parametrize(
    ("text", "relation"),
    [
        ("A car behind me overtook at speed on the bypass.", "behind"),  # said behind the ego
        ("I pulled out behind the bus and it braked sharply.", "ahead"),  # behind it: the bus is ahead
        ("We were following a tractor at 15 mph when it turned right.", "ahead"),  # what the ego follows
        ("A motorbike right behind me tailgated me for a mile.", "behind"),
        ("I ran into the back of a van that braked in front of me.", "ahead"),  # the ego's own rear-end
    ],
)
def test_near_misses_keep_their_reading(text: str, relation: str) -> None:
    assert _first_relation(text) == relation


def test_behind_a_parked_van_is_a_hiding_place_not_a_start_behind_the_ego() -> None:
    actors = read("A boy ran out from behind a parked van right in front of me.").actors
    assert actors[0].kind == "pedestrian"
    assert actors[0].relation != "behind"


@pytest.mark.parametrize(
    "text",
    [
        "My sister was following a cement mixer on the bypass when it stopped without warning.",
        "Grandad was behind a tractor at 15 mph for three miles.",
    ],
)
def test_a_person_the_story_follows_said_behind_a_road_user_puts_it_ahead(text: str) -> None:
    assert _first_relation(text) == "ahead"
