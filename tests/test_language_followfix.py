"""Following the ego and coming "over into" it, read only where English says so: a thing carried in the
ego's boot is no road user sat in it; a walker behind the ego for a while walks, a rider rides at its
own pace, one parked behind it stays parked; "ended up on my bumper" is where a road user ends, not a
tail; a side said keeps its side; and "came over into us" is a cut-in only from a lane beside the ego.
Guards: the readings these rules were built for keep reading so."""

from __future__ import annotations

import pytest

from tests.reading_of import acts, moves
from vei_scenario.language.rules_backend import layers_from_text


def _adversaries(text: str) -> list[dict]:
    return layers_from_text(text, 0)["adversaries"]


@pytest.mark.parametrize(
    "text",
    [
        "My son's scooter was in my boot when a car pulled out on me.",
        "The cyclist's bike was in my boot; the van hit us from behind.",
        "A cyclist's bike was in my boot; a van pulled out in front of me.",
        "A lorry's load was in my boot; a car cut in front of me.",
        "My daughter's bicycle was in the boot when a lorry cut in front of us.",
    ],
)
def test_a_thing_carried_in_the_boot_is_no_follower(text: str) -> None:
    assert all("follow_vehicle" not in names for _, names in acts(text))
    assert len(_adversaries(text)) == 1


def test_the_car_that_cuts_in_after_a_load_in_the_boot_keeps_its_side() -> None:
    (adv,) = _adversaries("A lorry's load was in my boot; a car cut in front of me.")
    assert adv["spawn"]["relation"] != "behind"


@pytest.mark.parametrize(
    "text",
    [
        "A jogger ran behind us for a while, then crossed the road in front of a van.",
        "The horse rider was behind me for a stretch, then the car overtook us both.",
        "A man walked behind me for a few minutes along the verge.",
        "My two kids were sat behind me for a while in the back seat when a car pulled out on me.",
    ],
)
def test_a_walker_behind_the_ego_for_a_stretch_is_no_car_following(text: str) -> None:
    said = acts(text)
    assert ("car", ["follow_vehicle"]) not in said
    assert all(names[:1] != ["follow_vehicle"] for _, names in said)


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist had been riding behind me for a mile when a car pulled out in front of me.",
        "A cyclist rode behind me for a while, then turned off.",
    ],
)
def test_a_rider_behind_the_ego_for_a_stretch_keeps_a_riders_pace(text: str) -> None:
    rider = next(a for a in _adversaries(text) if a["type"] == "bicycle")
    assert rider["speed_mps"] <= 10.0


@pytest.mark.parametrize(
    "text",
    [
        "A police car was parked behind me for a while, then a van overtook me.",
        "The parked lorry stayed behind us for a minute while we waited for the pedestrian to cross.",
        "A stationary bus was behind me for ages at the lights.",
    ],
)
def test_one_parked_behind_the_ego_for_a_while_follows_nothing(text: str) -> None:
    assert all("follow_vehicle" not in names for names in moves(text))


def test_a_side_said_with_the_bumper_keeps_the_side() -> None:
    (adv,) = _adversaries("A scooter came up on my bumper on the inside and undertook me.")
    assert adv["spawn"]["relation"] != "behind"
    assert moves("A scooter came up on my bumper on the inside and undertook me.")[0][-1] == "overtake"


@pytest.mark.parametrize(
    "text",
    [
        "The car ahead came over into us as it lost control on the ice.",
        "The motorcyclist behind came over into us at the lights.",
        "The car parked on the left rolled over into us.",
    ],
)
def test_over_into_the_ego_from_no_lane_beside_is_no_cut_in(text: str) -> None:
    assert all("cut_in" not in names for names in moves(text))


def test_up_against_the_tailgate_then_a_hit_is_contact_not_following() -> None:
    text = "The car behind came up against our tailgate and hit it."
    assert all("follow_vehicle" not in names for names in moves(text))


@pytest.mark.parametrize(
    "text",
    [
        "The cyclist pulled out, I hit him and he ended up on my bumper.",
        "The pedestrian stepped out and wound up on my bumper.",
    ],
)
def test_ending_up_on_the_bumper_is_no_tail(text: str) -> None:
    said = moves(text)
    assert all("follow_vehicle" not in names for names in said)
    assert all(a["spawn"]["relation"] != "behind" for a in _adversaries(text))


@pytest.mark.parametrize(
    "text",
    [
        "Cruising at 60, the estate car behind me was practically in my boot with its lights on full.",
        "Doing 50 on the bypass, a black pickup was right up on my bumper for two miles.",
        "A motorcyclist who had been sitting close behind us for some distance overtook on the offside.",
        "A coach sat behind us for a while, then swung out and overtook us.",
        "A van was virtually in my boot all the way down the hill.",
    ],
)
def test_guards_following_stays_following(text: str) -> None:
    assert moves(text)[0][0] == "follow_vehicle"


@pytest.mark.parametrize(
    "text",
    [
        "I held the centre lane at 55 mph when a tanker from the nearside lane came over into us.",
        "Lane two at 70 mph: the hatchback in lane one just came across into us.",
        "Ego in the middle lane at 100 km/h; an HGV in the left lane wanders across into me without signalling.",
    ],
)
def test_guards_over_into_the_ego_from_a_lane_is_a_cut_in(text: str) -> None:
    assert moves(text)[0][0] == "cut_in"


def test_a_rider_overtaking_a_stationary_ego_sets_off_at_a_pace() -> None:
    (adv,) = _adversaries("I was stationary at the lights when a cyclist overtook me on the inside.")
    assert adv["speed_mps"] > 0.5


def test_the_documented_time_gap_behind_follows_with_the_ego_speed_said() -> None:
    assert moves("Ego at 60 km/h. HGV behind ego at 1 s headway.") == [["follow_vehicle"]]
