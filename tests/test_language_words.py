"""Words read as something else than they are: "right" stressing a particle ("came right up behind
me") and "left" the past of "leave" ("as we left the roundabout") are no side of the road."""

import pytest

from vei_scenario.language.reader import read
from vei_scenario.language.sides import not_a_side


def _sides(text: str) -> list:
    """Every side the reading gives: the ego's and each road user's relation."""
    r = read(text)
    return [r.ego_relation, *(a.relation for a in r.actors)]


@pytest.mark.parametrize(
    "text",
    [
        "A motorbike went right through the red light in front of me at the crossroads.",
        "A taxi drove right up behind us at the lights and sounded its horn.",
        "A jogger ran right past my wing mirror while I waited at the junction.",
        "A delivery van crept right up to my rear bumper in the queue.",
        "A cyclist rolled right onto the crossing as I approached.",
        "A learner driver stalled and rolled right back into my bonnet on the hill.",
    ],
)
def test_right_stressing_a_particle_is_no_side(text):
    assert not {"right", "junction_right"} & set(_sides(text))  # (a side from another cue may stand)


@pytest.mark.parametrize(
    "text",
    [
        "We had only just left the petrol station when a tractor braked hard ahead of us.",
        "As I left the motorway a minibus ahead of me slowed to a stop.",
        "Moments after they left the lay-by, a cyclist ahead of them wobbled and fell.",
    ],
)
def test_left_the_verb_is_no_side(text):
    assert "left" not in _sides(text)


@pytest.mark.parametrize(
    "text, expected",
    [
        # near misses: the same words where they are a side
        ("A moped came from the right across the crossroads in front of me.", "right"),
        ("An oncoming van turned right across my bonnet into a side road.", None),
        ("A lorry turned right into the side street as I approached.", None),  # (its turn, no start side)
        ("On the left the petrol station had a car waiting to pull out.", None),
    ],
)
def test_near_misses_still_read_a_side(text, expected):
    tokens = text.lower().replace(".", " .").split()
    k = tokens.index("right") if "right" in tokens else tokens.index("left")
    assert not not_a_side(tokens, k)


def test_side_after_a_determiner_is_kept():
    assert read("A moped came from the right across the crossroads in front of me.").actors[0].relation in (
        "right",
        "junction_right",
    )


@pytest.mark.parametrize(
    "text, ego, each",
    [
        ("Two skateboarders were ahead of me on the hill. I was rolling at 30 km/h and they were at about 12.", 30, 12),
        ("A pair of horses ahead of us on the lane; we were doing 25 mph, they were at barely 5 mph.", 25, 5),
        ("Four joggers were ahead along the kerb. I was at 20 km/h and they were running at 10 km/h.", 20, 10),
    ],
)
def test_they_after_the_narrators_speed_is_the_group(text, ego, each):
    """ "they" beside the narrator's own speed names the group said before: each of it takes the speed."""
    r = read(text)
    unit = 0.44704 if "mph" in text else 1 / 3.6
    assert r.ego_speed_mps == pytest.approx(ego * unit)
    assert [a.speed_mps for a in r.actors] == pytest.approx([each * unit] * len(r.actors))


@pytest.mark.parametrize(
    "text",
    [
        # near misses: "we" is the narrator's party, "them" an object: neither gives the group a speed
        "Two cyclists were ahead of us. We were doing 40 km/h and we passed them.",
        "Two cyclists were ahead of me; I was at 40 km/h when I overtook them.",
    ],
)
def test_the_narrators_speed_stays_the_narrators(text):
    r = read(text)
    assert r.ego_speed_mps == pytest.approx(40 / 3.6)
    assert all(a.speed_mps is None for a in r.actors)
