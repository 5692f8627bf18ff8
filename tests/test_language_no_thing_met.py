"""A word of contact whose object is no road user: a place ridden into ("rode into the crosswalk"),
light or dark gone into ("vanished into the night"), the vehicle's own fittings ("tucked into the
sun visor"), street furniture a walker or a rider hits on their own ("wobbled and hit the kerb"), or
a plural noun said as a label ("Tags:"). None of these is a collision; a road user or a part of one
met stays one. Each case is written for the rule, not taken from a corpus."""

from __future__ import annotations

import pytest

from vei_scenario.language.reader import _tokens
from vei_scenario.language.stated import stated_outcome


def _outcome(text: str) -> str | None:
    return stated_outcome(" ".join(_tokens(text)))


@pytest.mark.parametrize(
    "text",
    [
        "A guy rode into the crosswalk against the light and I braked.",
        "The kid shot off the pavement and into the zebra crossing; I stopped in time.",
        "Bloke on a bike pulled into the cycleway right in front of me, I stood on the brakes.",
        "Ped walked into the crosswalk on DONT WALK, ego braked hard.",
        "The scooter rider cut into the bus lane ahead of us and I had to brake sharply.",
    ],
)
def test_a_place_ridden_into_is_no_contact(text):
    assert _outcome(text) != "collision"


@pytest.mark.parametrize(
    "text",
    [
        "He swerved round my bumper and vanished into the night.",
        "The scooter was gone into the darkness before I could react.",
        "The cyclist rode off into the rain without looking back.",
        "She darted across and disappeared into the fog, I slammed on.",
        "Rider weaves past my bonnet and off into the gloom, no lights at all.",
    ],
)
def test_light_and_dark_gone_into_is_no_contact(text):
    assert _outcome(text) != "collision"


@pytest.mark.parametrize(
    "text",
    [
        "A photo is tucked into the sun visor. A cyclist came up my inside and I stopped dead.",
        "My phone was jammed into the dashboard holder when a jogger ran out and I braked.",
        "I shoved the parking ticket into the glovebox; then a cyclist pulled out and I braked hard.",
    ],
)
def test_the_vehicles_own_fittings_are_no_contact(text):
    assert _outcome(text) != "collision"


@pytest.mark.parametrize(
    "text",
    [
        "A kid on a bike came off the footpath, hit the kerb and landed in front of me. I braked hard.",
        "The rider wobbled, clipped the curb and came off. I stopped well short.",
        "She lost her balance, struck a bollard and fell in front of my car.",
        "Lad on a Lime bounced off the pavement, hit the kerb and ended up under my nose, I stood on it.",
        "The jogger tripped, hit the verge and went down; I swerved round him.",
        "I swerved into the hedge to miss him.",
    ],
)
def test_furniture_a_walker_or_rider_hits_is_no_contact(text):
    assert _outcome(text) != "collision"


@pytest.mark.parametrize(
    "text",
    [
        "Tags: #cyclist #nearmiss #dashcam",
        "Hits: 0. A scooter came out from the right and I braked.",
    ],
)
def test_a_plural_label_is_no_contact(text):
    assert _outcome(text) != "collision"


@pytest.mark.parametrize(
    "text",
    [
        "I hit the scooter.",
        "The van went into the side of us.",
        "I went into the back of the van.",
        "I clipped his handlebar.",
        "The lorry knocked her off.",
        "I went into the dark blue van.",
        "A scooter went into the back of the pickup in the dark.",
        "The pickup did not stop, hit the kerb and rolled.",
        "The cyclist hit the kerb and went into the side of my car.",
        "He hits.",
    ],
)
def test_a_road_user_met_stays_a_collision(text):
    assert _outcome(text) == "collision"


@pytest.mark.parametrize(
    "text",
    [
        "Dad took me out on the country lanes. A tractor came round the bend and I pulled over, all fine.",
        "My instructor took me out on the dual carriageway today.",
        "Mum takes us out on the motorway on Sundays.",
        "Grandad took me out round the estate in his Corsa.",
        "My brother took me out after tea for a practice.",
    ],
)
def test_one_of_the_narrators_party_taking_them_out_is_a_drive(text):
    assert _outcome(text) != "collision"


@pytest.mark.parametrize(
    "text",
    ["A van took me out on the roundabout.", "The cyclist took me out.", "Dad took out a cyclist on the bend."],
)
def test_being_taken_out_by_a_road_user_stays_a_collision(text):
    assert _outcome(text) == "collision"


@pytest.mark.parametrize(
    "text",
    [
        "She wobbled and came off on her own: grazed knees and a cut elbow.",
        "The rider fell by himself, scraped palms, nothing worse.",
        "Kid tripped on the kerb in front of us, bumped head but fine.",
    ],
)
def test_an_injury_said_before_a_bare_body_part_is_no_contact(text):
    assert _outcome(text) != "collision"


def test_a_blow_to_a_part_with_its_owner_named_stays_a_collision():
    assert _outcome("My mirror clipped his elbow as I passed.") == "collision"
