"""A gap the text states reaches the layers: a crossing sets off when the ego is that far away (its
crossing speed, unless stated, adjusted so its timing still fits), or, too close for that, is in the
ego's path when the ego is that far away; where neither holds the run says why."""

import pytest

from vei_scenario.language.behaviours.cross_in_front import trigger_distance
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.reader import read
from vei_scenario.language.rules_backend import sample_layers
from vei_scenario.language.scenario_writer import TYPES

LANE_M = 3.5


def _crossing(layers: dict) -> tuple[dict, dict]:
    for adv in layers["adversaries"]:
        for _, node in behaviour_nodes(adv["behaviour"]):
            if node["behaviour"] == "cross_in_front":
                return adv, node["config"]
    raise AssertionError("no crossing")


def _kept(layers: dict, gap: float) -> bool:
    """The gap as the ego's distance when the crosser sets off, or when it is in the ego's lane."""
    cfg = _crossing(layers)[1]
    in_path = float(layers["ego"]["speed_mps"]) * cfg["arrival_gap_s"]
    return abs(_set_off_distance(layers) - gap) < 0.3 or abs(in_path - gap) < 0.3


def _set_off_distance(layers: dict) -> float:
    """The ego's distance when the crosser sets off, from the layers' own values."""
    adv, cfg = _crossing(layers)
    lanes = layers["environment"]["map"]["lanes_per_direction"]
    k = int(layers["ego"]["lane"])
    right = adv["spawn"]["relation"] == "roadside_right"
    cross = (k - 0.5) * LANE_M + 1.0 if right else (2 * lanes - k + 0.5) * LANE_M + 1.0
    speed = float(cfg.get("crossing_speed_mps", 1.5 if adv["type"] == "pedestrian" else 4.0))
    return trigger_distance(
        float(layers["ego"]["speed_mps"]), cross, speed, TYPES[adv["type"]][4], cfg["arrival_gap_s"]
    )


@pytest.mark.parametrize(
    "text, gap",
    [
        ("A boy dashes out from between parked cars on the right 8 m ahead of the ego at 40 km/h.", 8.0),
        ("Ego 50 km/h; a woman steps off the kerb on the right only 12 m in front of the car.", 12.0),
        ("At 30 km/h a cyclist shoots out from the right kerb 6 m in front of us.", 6.0),
        ("Ego at 20 km/h. Toddler wanders off the pavement on the right 55 m ahead.", 55.0),
    ],
)
def test_a_stated_crossing_gap_is_where_it_sets_off(text, gap):
    reading = read(text)
    for seed in range(3):
        layers = sample_layers(reading, text, seed)
        _, cfg = _crossing(layers)
        assert cfg.get("distance_m") == gap
        assert _kept(layers, gap)


def test_a_stated_gap_no_crossing_can_keep_is_said_with_its_reason(tmp_path, capsys):
    """80 m ahead at 10 km/h: even at a slow walk it would be across half a minute before the ego
    comes. The run says the gap is not kept, and why."""
    from vei_scenario.cli import main

    text = "Ego at 10 km/h. A man steps off the right kerb 80 m in front of the ego."
    notes: list[str] = []
    layers = sample_layers(read(text), text, 0, notes)
    assert "distance_m" not in _crossing(layers)[1]
    assert len(notes) == 1 and "stated gap of 80 m" in notes[0] and "more slowly than a pedestrian can" in notes[0]
    assert main(["describe", text, "-o", str(tmp_path / "x"), "--count", "2", "--layers-only"]) == 0
    said = capsys.readouterr().out
    assert "not kept in 2 of 2 scenario(s): Adversary1: the pedestrian's stated gap of 80 m" in said


def _overtake_gap(text: str) -> float | None:
    spec = read(text).actors[0]
    return next((cfg.get("gap_m") for name, cfg, _, _ in spec.behaviours if name == "overtake"), None)


@pytest.mark.parametrize(
    "text, gap",
    [
        ("A sports car overtakes me at 80 km/h and pulls back in only 3 m ahead of my bumper.", 3.0),
        ("Doing 50 mph when a van passes us and cuts back in with about 10 feet to spare.", 3.05),
        ("ego 100 km/h, motorbike overtake me and come back in my lane 5 m in front", 5.0),
    ],
)
def test_a_gap_said_after_an_overtake_is_where_it_cuts_back_in(text, gap):
    assert _overtake_gap(text) == pytest.approx(gap, abs=0.06)
    layers = sample_layers(read(text), text, 0)
    assert layers["adversaries"][0]["spawn"]["longitudinal_m"] < -10.0  # (it starts behind the ego, not at the gap)


def test_a_gap_said_before_an_overtake_is_where_it_starts():
    text = "A car 20 m behind me overtakes me at 90 km/h."
    assert _overtake_gap(text) is None
    assert sample_layers(read(text), text, 0)["adversaries"][0]["spawn"]["longitudinal_m"] == -20.0


@pytest.mark.parametrize(
    "text",
    [
        "A coupe overtakes me at 110 km/h on the motorway and then leaves at the next exit.",
        "Doing 60 mph, a van passes me and then takes the exit.",
        "A bike overtakes us and turns off into the exit ahead.",
    ],
)
def test_an_arm_said_after_an_overtake_is_where_it_goes(text):
    assert not read(text).actors[0].relation or not read(text).actors[0].relation.startswith("junction")


@pytest.mark.parametrize(
    "text, gap",
    [
        ("A hatchback noses out of a side road on the right 25 m ahead of the ego, ego at 40 km/h.", 25.0),
        ("Ego 60 km/h; a tractor pulls out from a minor road on the left 30 m in front of us.", 30.0),
        ("Moped emerges from the side street on my right, maybe 12 metres ahead of me; I was at 30 mph.", 12.0),
        ("I was doing 40 mph when a Mini shot out of a side road on my left barely 25 m ahead.", 25.0),
    ],
)
def test_a_stated_gap_of_a_road_user_pulling_out_of_a_side_road_is_where_it_sets_off(text, gap):
    from vei_scenario.language.behaviours.base import time_to_cover
    from vei_scenario.language.behaviours.turn_into import paths_m
    from vei_scenario.language.placement import lane_id
    from vei_scenario.language.scenario_writer import TYPES

    reading = read(text)
    for seed in range(3):
        layers = sample_layers(reading, text, seed)
        adv = layers["adversaries"][0]
        cfg = adv["behaviour"]["config"]
        assert adv["behaviour"]["behaviour"] == "turn_into" and cfg["distance_m"] == gap
        lanes = layers["environment"]["map"]["lanes_per_direction"]
        path, ego_path = paths_m(adv["spawn"]["relation"] == "junction_left", lane_id(lanes, layers["ego"]["lane"]))
        # (the writer's trigger: its reference point half its length behind the stop line, at what its
        # vehicle can reach)
        (length, _, _), _, _, top, accel, _ = TYPES[adv["type"]]
        v, a = min(cfg.get("speed_mps", 10.0), 8.0, top), min(cfg.get("accel_mps2", 2.5), accel)
        t_actor = time_to_cover(path + length / 2, v, a, 0.0)
        # the ego is the stated distance before the side road's mouth when it sets off, or (too close
        # for that) that far from where it joins when it is there
        to_mouth = layers["ego"]["speed_mps"] * (t_actor + cfg["arrival_gap_s"]) - ego_path
        in_road = layers["ego"]["speed_mps"] * cfg["arrival_gap_s"]
        assert to_mouth == pytest.approx(gap, abs=0.05) or in_road == pytest.approx(gap, abs=0.05)


@pytest.mark.parametrize(
    "text, gap",
    [
        ("A girl runs out from the left 9 m ahead of me; I'm doing 30 km/h.", 9.0),
        ("Ego 40 km/h. An old man shuffles off the far kerb about 25 m in front of the ego.", 25.0),
        ("at 25 mph a lad on a bike darts out from the left-hand pavement 10 metres ahead", 10.0),
    ],
)
def test_a_far_side_crossing_at_a_stated_gap_keeps_it_on_a_road_the_text_leaves_open(text, gap):
    reading = read(text)
    layers = sample_layers(reading, text, 0)
    assert layers["environment"]["map"]["lanes_per_direction"] == 1
    assert _crossing(layers)[1].get("distance_m") == gap
    assert _kept(layers, gap)


def test_the_lanes_the_text_states_stay():
    text = "Two lanes each way, ego 60 km/h: a girl runs out from the left 6 m ahead of the ego."
    layers = sample_layers(read(text), text, 0)
    assert layers["environment"]["map"]["lanes_per_direction"] == 2 and _kept(layers, 6.0)


# --- a length said in feet or yards, in words ------------------------------------------------------------
@pytest.mark.parametrize(
    "text, gap",
    [
        ("A lorry brakes hard to a stop ahead of me, maybe forty feet in front, I'm doing 30 mph.", 12.2),
        ("An e-scooter rider came at me head-on in my lane, about a hundred feet off, at 20 mph.", 30.5),
        ("Twenty yards ahead a van stops dead in my lane; I was at 40 km/h.", 18.3),
    ],
    ids=["forty-feet", "a-hundred-feet", "twenty-yards"],
)
def test_a_length_in_feet_or_yards_said_in_words_is_the_gap(text, gap):
    """A number in words before feet or yards is a length as its digits are ("forty feet": 12.2 m):
    an American or British driver says a gap in feet far more often than in metres."""
    [a] = read(text).actors
    assert a.distance_m == pytest.approx(gap, abs=0.1)


def test_a_size_in_feet_said_before_a_noun_is_no_gap():
    """ "a six-foot hedge" is how tall the hedge is: no gap to the child who runs out from behind it."""
    [a] = read("From behind a six-foot hedge on the left, a child runs out in front of me at 30 mph.").actors
    assert a.distance_m is None


# --- the ego said to be some way behind or ahead of a road user named after it --------------------------
@pytest.mark.parametrize(
    "text, gap",
    [
        ("Ego at 40 km/h roughly 20 metres behind a bus. The bus brakes hard and stops.", 20.0),
        ("We were at 50 km/h some 25 m behind a tipper lorry when the lorry slammed on its brakes.", 25.0),
        ("The ego, doing 60 km/h, is 30 m behind a minibus that stops suddenly.", 30.0),
        ("I was about 10 metres ahead of a cyclist in the same lane at 25 km/h, the cyclist kept going.", 10.0),
    ],
    ids=["ego-at-behind", "we-behind", "ego-is-behind", "ahead-of"],
)
def test_a_gap_said_of_the_ego_to_a_road_user_named_after_it_is_that_road_user_s(text, gap):
    """ "<ego> N m behind <road user>": the gap between the two, said from the ego's side; the road user
    named after the preposition is the one at that gap (not one named before, not nobody)."""
    [a] = read(text).actors
    assert a.distance_m == pytest.approx(gap)


def test_a_gap_said_of_the_ego_to_a_place_is_no_road_user_s():
    """ "20 m behind the stop line" places the ego, not the van named before it."""
    r = read("A van ahead brakes hard to a stop. The ego at 40 km/h is 20 m behind the stop line.")
    assert [a.distance_m for a in r.actors] == [None]


# --- a stated gap kept whatever the road user's first behaviour places it by -----------------------------
@pytest.mark.parametrize(
    "text, gap",
    [
        ("Two lanes each way, ego at 50 km/h. A van in the right-hand lane 15 m ahead slows down to 30 km/h.", 15.0),
        ("Ego 80 km/h on a motorway, two lanes each way. A car in the left lane 25 m ahead keeps its lane.", 25.0),
        ("Ego at 70 km/h in the left lane, a lorry in the right lane 30 metres ahead brakes hard to a stop.", 30.0),
        ("Ego at 60 km/h in the right lane; a bus in the left lane 20 m ahead of it slows gently to a stop.", 20.0),
    ],
    ids=["change-speed-right", "keep-lane-left", "sudden-stop-right", "stop-left"],
)
def test_a_road_user_in_the_next_lane_at_a_stated_gap_starts_there(text, gap):
    """A road user in a lane beside the ego's, said to be N m ahead, starts N m ahead: its behaviour's
    own placement is for when the text leaves the gap open."""
    for seed in (0, 1, 2):
        layers = sample_layers(read(text), text, seed)
        [adv] = layers["adversaries"]
        assert adv["spawn"]["relation"] in ("left", "right")
        assert abs(float(adv["spawn"]["longitudinal_m"])) == pytest.approx(gap), seed


# --- a gap said in a clause whose only subject is the ego, seeing the other ------------------------------
@pytest.mark.parametrize(
    "text, gap",
    [
        ("An oncoming van swung into my lane at 30 mph. Maybe 40 feet off when I noticed it.", 12.2),
        ("A cyclist was coming the wrong way in my lane at night. Roughly 20 m away when I first saw him.", 20.0),
        ("A lorry ahead of us braked hard to a stop; about 25 metres out when we clocked it, at 50 km/h.", 25.0),
    ],
    ids=["feet-noticed", "metres-saw", "metres-clocked"],
)
def test_a_gap_said_before_the_ego_sees_the_road_user_is_that_road_user_s(text, gap):
    """ "N m away when I saw him": no one's gap but the one seen; the ego named as the one who sees
    it has no gap to itself."""
    [a] = read(text).actors
    assert a.distance_m == pytest.approx(gap, abs=0.1)


def test_where_the_ego_stops_is_no_gap_of_the_road_user_it_stops_behind():
    """ "I stopped 2 m short" of a van going along the ego's road is how the narrator's stop went, not
    where the van was; of one that pulled out across its path it is how near that came (its gap, see
    tests/test_language_quantity.py)."""
    [a] = read("The van in front braked hard. I stopped 2 m short of it at 20 mph.").actors
    assert a.distance_m is None
    [a] = read("A van pulled out of a side road on my left. I stopped 2 m short of it at 20 mph.").actors
    assert a.distance_m == pytest.approx(2.0)


# --- a red-light runner at a stated gap -----------------------------------------------------------------
@pytest.mark.parametrize(
    "text, gap",
    [
        ("At the crossroads at 40 km/h, a car from the left runs the red light about 15 m in front of me.", 15.0),
        ("Ego at 50 km/h. A van from the right ignores its red signal and shoots across 20 metres ahead of us.", 20.0),
        ("I'm at 30 mph approaching the lights; a pickup jumps the red from the left, maybe 60 feet ahead.", 18.3),
    ],
    ids=["car-left", "van-right", "pickup-feet"],
)
def test_a_red_light_runner_at_a_stated_gap_is_in_the_ego_s_path_when_the_ego_is_that_far(text, gap):
    """ "runs the red 15 m in front of me": it is in the ego's path when the ego is that far from it,
    so it reaches the conflict that distance's time at the ego's speed before the ego does."""
    r = read(text)
    for seed in (0, 1, 2):
        layers = sample_layers(r, text, seed)
        [adv] = layers["adversaries"]
        [(_, node)] = list(behaviour_nodes(adv["behaviour"]))
        assert node["behaviour"] == "run_red_light"
        cfg = node["config"]
        assert cfg["distance_m"] == pytest.approx(gap, abs=0.1)
        speed = float(layers["ego"]["speed_mps"])
        assert cfg["arrival_gap_s"] == pytest.approx(-gap / speed, abs=0.01)
