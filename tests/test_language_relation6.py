"""Where a road user starts, read from words tied to it that the reader used to miss: a place beside
the road with "ahead" between it and its side, a place it comes out of said after "in front", a kerb
a parked vehicle pulls out from, "in front of her" of an ego told in the third person, and the
footway words of a writer who keeps left."""

import pytest

from vei_scenario.language.rules_backend import layers_from_text
from vei_scenario.language.sides import drives_on_left, past_how_far_along


def starts(text: str) -> list[str]:
    """The start relation of each adversary, as the layers carry it."""
    return [a["spawn"]["relation"] for a in layers_from_text(text, 0)["adversaries"]]


@pytest.mark.parametrize(
    "text, expected",
    [
        # "ahead" between a place beside the road and its side: the side is still the place's
        ("Driving at 60 km/h, I saw a van in the lay-by ahead on the left, and it pulled out in front of me.",
         "roadside_left"),
        ("At 30 mph a tractor came out of a field gate just ahead on the right.", "roadside_right"),
        ("Test: a car waits in the parking bay up ahead on the right and pulls out as the ego approaches at 40 km/h.",
         "roadside_right"),
        # the ego's lane said before the road user: the lay-by is the road user's place, the lane the ego's
        ("At 68 mph in lane 1, I noticed an HGV in the lay-by on the left. I moved out to lane 2 early so the HGV "
         "could pull out, which it did.", "roadside_left"),
    ],
)  # fmt: skip
def test_a_place_ahead_keeps_its_side(text, expected):
    assert starts(text) == [expected]


def test_ahead_before_a_side_is_skipped_only_when_a_side_follows():
    tokens = "a van in the lay-by just ahead on the left pulled out".split()
    assert past_how_far_along(tokens, 5) == 7  # (at "on": the side's link)
    bare = "a van in the lay-by ahead pulled out".split()
    assert past_how_far_along(bare, 5) == 5  # (no side after it: "ahead" stays a place of its own)


@pytest.mark.parametrize(
    "text, expected",
    [
        # "in front" said before the place it comes out of: the place says where it was
        ("One foggy morning, barely able to see in front, a tractor pulled out of a field gate on his left "
         "right in front of him at 20 mph.", "roadside_left"),
        ("In front of me, at 25 mph, a bus pulled out of the stop on the right.", "roadside_right"),
        # a vehicle parked at a kerb said with its side, pulling out: from that kerb
        ("On the high street at 20 mph, a car parked at the kerb on the left suddenly pulled out in front of us.",
         "roadside_left"),
        ("A delivery van parked at the curb on the right pulled out in front of me at 30 km/h.", "roadside_right"),
    ],
)  # fmt: skip
def test_the_place_it_leaves_is_where_it_starts(text, expected):
    assert starts(text) == [expected]


@pytest.mark.parametrize(
    "text, expected",
    [
        # guard: a parked car said only on a side keeps that side's lane
        ("At 40 km/h a parked car on the right pulls out into the ego's lane.", "right"),
        # guard: a lay-by with no side said keeps its old reading
        ("I was doing 40 mph when a van in the lay-by ahead pulled out.", "ahead"),
        # guard: "ahead on the left" of no place is no place's side
        ("A car ahead on the left braked hard as I passed at 50 km/h.", "ahead"),
    ],
)  # fmt: skip
def test_guards_keep_their_reading(text, expected):
    assert starts(text) == [expected]


@pytest.mark.parametrize(
    "text",
    [
        "Mem said the lorry in front of her in lane 1 slammed on, she went for lane 2 to avoid it.",
        "Police say the van in front of her in the outside lane braked hard at 60 mph.",
    ],
)
def test_in_front_of_an_ego_told_in_the_third_person_puts_it_in_the_egos_lane(text):
    assert starts(text) == ["ahead"]


@pytest.mark.parametrize(
    "text, left",
    [
        # footway words of a writer telling their own drive: British, the kerb side is the left
        ("A scooter rider came along the pavement on the far side and rode across as I turned right.", True),
        ("I stopped when a boy ran off the footway into the road.", True),
        # a present-tense test line with metric speeds keeps the right-hand convention
        ("The e-scooter crosses from the far side pavement at 15 km/h in front of the ego.", False),
        # an American writer's words win with miles per hour
        ("I was doing 25 mph downtown when a kid ran off the sidewalk.", False),
    ],
)
def test_footway_words_say_the_writers_side(text, left):
    tokens = text.lower().replace(",", " ,").replace(".", " .").split()
    assert drives_on_left(tokens, text) is left


def test_far_pavement_of_a_writer_who_keeps_left_is_on_the_right():
    text = (
        "A scooter rider came along the pavement on the far side and rode across the side road as I turned "
        "right off the A38."
    )
    assert starts(text) == ["roadside_right"]
