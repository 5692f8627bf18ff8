"""Words of a review meeting and of a spoken account: labelling an event ("Safe, tag it"), an overtaker
back in "too early", and a vehicle said with its rider's or driver's possessive ("his bike").

Every wording here is written for these tests (none is from a corpus). Each rule has wordings that must
read and near misses that look alike but must not."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import read


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist at a T junction on our left waits at the line and lets us go past. Safe, tag it.",
        "We went past the cyclist with two metres to spare. Tagging as safe pass.",
        "A van pulls out of the side road well ahead of us, plenty of room. Ok, tag it as a positive.",
        "The pedestrian waits at the kerb and we drive past. So tag this one, and move on.",
    ],
)
def test_labelling_the_event_is_no_contact(text):
    assert read(text).intent != "collision", text


@pytest.mark.parametrize(
    "text",
    [
        "A van pulled out of a side road and tagged it.",
        "A van pulled out and tagged my bumper.",
        "A cyclist swerved out; we braked but still tagged him.",
        "The e-scooter came off the kerb and tagged our mirror.",
    ],
)
def test_a_tag_of_a_road_user_or_a_vehicle_is_contact(text):
    assert read(text).intent == "collision", text


@pytest.mark.parametrize(
    "text, cut_in",
    [
        ("An artic comes past us in the right lane and cuts back in way too early.", True),
        ("A van overtook us on the right and cut back in too soon.", True),
        ("A van overtook a cyclist ahead of me and cut in too soon.", False),  # (in front of the cyclist)
        ("A coach swept past us and cut back in much too sharply.", True),
        ("A lorry overtook us and cut back in, well ahead.", False),
        ("An artic comes past us in the right lane and pulled back in.", False),
    ],
)
def test_back_in_too_early_is_a_cut_in_after_the_overtake(text, cut_in):
    names = [b[0] for b in read(text).actors[0].behaviours]
    assert names[0] == "overtake"
    assert ("cut_in" in names) is cut_in, names


@pytest.mark.parametrize(
    "text, kinds",
    [
        ("A cyclist swerved in front of us. His bike was a metre from our bumper.", ["bicycle"]),
        ("An artic overtook us. His trailer was eight metres ahead of our bumper.", ["truck"]),
        ("My insured was in the junction when a sedan ran the red and struck his car.", ["car"]),
        ("Two cyclists rode out of the park. Their bikes were a metre from our bumper.", ["bicycle", "bicycle"]),
        # near misses: a walker's animal, and a vehicle of a kind nobody before is, are road users of their own
        (
            "A woman jogged along the edge with her dog; the dog ran across in front of us.",
            ["pedestrian", "pedestrian"],
        ),
    ],
)
def test_a_vehicle_said_with_its_owners_possessive_is_theirs(text, kinds):
    assert sorted(a.kind for a in read(text).actors) == sorted(kinds)


@pytest.mark.parametrize(
    "text, speed",
    [
        ("We're fully stopped at the lights when a Golf comes up behind us and stops a foot off our bumper.", 0.0),
        ("I'm stopped in the queue when a van behind me rolls into my back bumper.", 0.0),
        ("We're stationary at the zebra when a cyclist comes up the inside.", 0.0),
        # near misses: a contraction before a verb of going keeps the ego moving
        ("We're doing 30 mph when a cyclist pulls out of a side road on the left.", 30 * 0.44704),
    ],
)
def test_a_contracted_be_before_a_state_keeps_the_ego_at_rest(text, speed):
    assert read(text).ego_speed_mps == pytest.approx(speed)
