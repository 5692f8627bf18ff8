"""A generated scenario plays what its layers say: each test writes a small scenario, plays it with
vei run's interpreter and checks from the trajectories that the behaviour happened (the checks of
:func:`~vei_scenario.language.corpus_check.played_problems`, and where they are loose, a stricter
one of the behaviour's own definition)."""

from __future__ import annotations

import math

import pytest
from play_layers import play_layers

from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.rules_backend import layers_from_text


def _turned_rad(trace) -> float:
    """How far a road user's heading turned from its first sample to its last (rad, -pi..pi)."""
    return float((trace.yaw[-1] - trace.yaw[0] + math.pi) % (2 * math.pi) - math.pi)


@pytest.mark.parametrize(
    ("side", "ego_route"),
    # (not from the right with the ego turning right: on the right-hand side of the road the ego's
    # right turn stays in the junction's near corner, which straight traffic from the right never crosses)
    [("left", "left"), ("left", "right"), ("left", "straight"), ("right", "left"), ("right", "straight")],
)
def test_a_red_light_runner_drives_straight_on_across_the_ego_s_path_whichever_way_the_ego_turns(
    side, ego_route, tmp_path
):
    """Running the red is driving straight through the junction: the runner leaves on the arm
    opposite its own (it had taken the exit the ego goes straight to, turning into it), and meets the
    ego's path, whether the ego goes straight or turns."""
    layers = layers_from_text(f"At a crossroad with lights a van approaching from the {side} runs the red.", 0)
    layers["ego"]["route"] = ego_route
    [adv] = layers["adversaries"]
    assert adv["behaviour"]["behaviour"] == "run_red_light" and adv["spawn"]["relation"] == f"junction_{side}"
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert abs(_turned_rad(result.traces["Adversary1"])) < 0.2


@pytest.mark.parametrize("kind", ["bicycle", "e-scooter", "truck"])
@pytest.mark.parametrize("side", ["left", "right"])
def test_a_slow_vehicle_pulling_out_of_a_side_road_comes_out_ahead_of_the_ego(kind, side, tmp_path):
    """A road user pulling out of a side road sets off when the ego is as far as its own time to the
    ego's lane needs: that time is worked out at the speed and acceleration its vehicle has (a
    rider or a lorry timed as a car came out behind the ego)."""
    word = {"bicycle": "a cyclist", "e-scooter": "a rider on an e-scooter", "truck": "a lorry"}[kind]
    text = (
        f"The ego drives straight over a crossroad. {word.capitalize()} pulls out of the side road on the {side}"
        " into the ego's lane just in front of it."
    )
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert (adv["type"], adv["behaviour"]["behaviour"]) == (kind, "turn_into"), adv
    adv["spawn"]["relation"] = f"junction_{side}"
    for seed_gap in (0.0, 0.6, 2.0):
        adv["behaviour"]["config"]["arrival_gap_s"] = seed_gap
        assert played_problems(play_layers(layers, tmp_path), layers) == [], seed_gap


@pytest.mark.parametrize(
    "text",
    [
        "Approaching a roundabout, a moped rider on the wrong side comes head-on towards the ego.",
        "At 70 km/h the ego nears a crossroad while a cyclist pedals along the kerb in front of it.",
        "The ego waits to turn left at the crossroads; a car approaches from the other direction and drives on.",
    ],
)
def test_what_starts_ahead_of_the_ego_before_a_junction_fits_on_the_ego_s_road(text, tmp_path):
    """A road user placed ahead of the ego (by its timing or as oncoming traffic) stands on the ego's
    road before the junction or roundabout: the ego starts far enough back for it to fit there,
    instead of the spawn falling beyond the road's end and nothing being written."""
    from vei_scenario.language.corpus_check import play_case

    for seed in (0, 1, 2):
        layers = layers_from_text(text, seed)
        assert layers["environment"]["map"]["kind"] in ("crossroad", "roundabout")
        assert play_case({"text": text}, layers_from_text, tmp_path, seed) == [], seed


@pytest.mark.parametrize(
    "text",
    [
        "The ego turns right at the crossroads while a cyclist rides along the kerb ahead of it.",
        "The ego takes the second exit of a roundabout behind a cyclist riding along the kerb.",
        "Turning left at a crossroad, the ego comes up behind a rider on an e-scooter going along the kerb.",
    ],
)
def test_a_rider_along_the_ego_s_road_keeps_to_it_when_the_ego_turns_off(text, tmp_path):
    """Going along the road is going along the ego's road: the rider keeps its lane and goes straight
    on through the junction (not the junction's first link, a turn), and it is judged while the ego is
    on that road too: once the ego turns off, the rider going on straight is not leaving the ego's
    lane."""
    for seed in (0, 1):
        layers = layers_from_text(text, seed)
        [adv] = layers["adversaries"]
        assert adv["behaviour"]["behaviour"] == "along_road"
        result = play_layers(layers, tmp_path)
        assert played_problems(result, layers) == [], seed
        if layers["environment"]["map"]["kind"] == "crossroad":  # (in a roundabout the run ends in its ring)
            assert abs(_turned_rad(result.traces["Adversary1"])) < 0.2


@pytest.mark.parametrize(
    "text",
    [
        "I was stopped at the lights when an e-scooter rider crossed in front of me from the right.",
        "Our bus was stationary at the stop and a lad ran across the road in front of it from the left.",
        "The ego stands still at 0 km/h; a cyclist rides across in front of it from the right.",
    ],
)
def test_a_crossing_in_front_of_an_ego_that_stands_gets_across(text, tmp_path):
    """A crossing is timed to meet the ego as it comes; an ego that stands never comes closer, so the
    road user crosses in front of it at once rather than waiting at the kerb for ever."""
    layers = layers_from_text(text, 0)
    assert layers["ego"]["speed_mps"] == 0.0
    [adv] = layers["adversaries"]
    assert adv["behaviour"]["behaviour"] == "cross_in_front"
    assert played_problems(play_layers(layers, tmp_path), layers) == []


@pytest.mark.parametrize(
    "text",
    [
        "On a twisty road at 90 km/h a fox darts across from the right in front of the ego.",
        "The ego rounds a long bend at 70 km/h when a man steps out from the left verge and walks across.",
        "Driving 75 km/h through a sweeping curve, the ego meets a boy running over the road from the left.",
    ],
)
def test_a_crossing_on_a_curved_road_reaches_the_ego_s_path(text, tmp_path):
    """On a curved road the crossing need not lie before the bend (as it must before a junction, where
    the ego's road ends): a slow crosser facing a fast ego starts as far ahead as its timing needs,
    on the bend if need be, and gets across the ego's path."""
    for seed in (0, 1):
        layers = layers_from_text(text, seed)
        assert layers["environment"]["map"]["kind"] == "curve"
        [adv] = layers["adversaries"]
        assert adv["behaviour"]["behaviour"] == "cross_in_front"
        assert played_problems(play_layers(layers, tmp_path), layers) == [], seed


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist waiting at the right kerb swerves into the ego's lane.",
        "An e-scooter rider on the right kerb swerves into the ego's lane.",
        "On a straight road at 50 km/h a cyclist on the right kerb swerves into the ego's lane.",
    ],
)
def test_a_rider_at_the_kerb_swerving_into_the_road_ends_in_the_ego_s_lane(text, tmp_path):
    """A rider at the kerb on the ego's side that swerves into the road starts on the kerb lane's
    edge (beyond the kerb it is on no lane, and the scenario could not be played) and ends in the
    ego's lane, ahead of it."""
    from vei_scenario.language.corpus_check import _ego_frame

    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert adv["spawn"]["relation"] == "roadside_right"
    assert adv["behaviour"]["behaviour"] in ("change_lane", "cut_in")
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    lon, lat = _ego_frame(result, "Adversary1")
    assert lon[-1] > 0 and abs(lat[-1]) < 0.5


@pytest.mark.parametrize(
    "text",
    [
        "Creeping along at 12 km/h, the ego is cut up dangerously by a cyclist from the lane on its left.",
        "At 15 km/h in a queue, an e-scooter rider from the left lane cuts in right in front of the ego.",
        "The ego edges forward at 10 km/h when a car in the left lane cuts in sharply right in front of it.",
    ],
)
def test_a_slow_cut_in_ends_in_the_ego_s_lane(text, tmp_path):
    """A cut-in brakes as it comes over, by ``brake_delta_mps``: from a crawl that would bring it to a
    stand halfway across (a road user standing still moves sideways no further, turned across the
    lane), so it keeps moving until it is in."""
    for seed in (0, 1, 2):
        layers = layers_from_text(text, seed)
        [adv] = layers["adversaries"]
        assert adv["behaviour"]["behaviour"] == "cut_in"
        adv["behaviour"]["config"]["criticality"] = "dangerous"
        assert played_problems(play_layers(layers, tmp_path), layers) == [], seed


@pytest.mark.parametrize(
    "text",
    [
        "An e-scooter rider in the cycle lane on the right ahead of the ego turns left across our lane into a "
        "side road; ego at 40 km/h.",
        "Ego at 30 mph. A lad on a bike on the right-hand kerb ahead slows right down, then suddenly swings out "
        "into our lane.",
        "Ego at 25 km/h. A jogger on the right verge ahead slows down, then overtakes a parked van.",
    ],
    ids=["forced-turn", "slows-then-swings-out", "change-speed-then-overtake"],
)
def test_a_road_user_at_the_kerb_that_changes_lane_later_starts_on_a_lane(text, tmp_path):
    """Whatever it does first, a road user at the kerb of the ego's side that at some point moves over
    into the road (a lane change, an overtake, a turn across the lanes) starts on the kerb lane's edge:
    beyond the kerb it is on no lane and the player refuses the lane change."""
    layers = layers_from_text(text, 0)
    adv = layers["adversaries"][0]  # (a van it goes round stands beyond the kerb)
    assert adv["spawn"]["relation"] == "roadside_right"
    assert played_problems(play_layers(layers, tmp_path), layers) == []


@pytest.mark.parametrize(
    "text, gap",
    [
        ("Round a bend at 30 mph a moped came the other way on my side of the road, about forty feet off.", 12.2),
        ("At 50 km/h a cyclist riding the wrong way came at us head-on in our lane, some 20 m away.", 20.0),
        ("Ego at 40 km/h. An oncoming e-scooter rider drifts onto our side of the road 15 metres ahead.", 15.0),
    ],
    ids=["moped-feet", "cyclist-wrong-way", "scooter-drifts"],
)
def test_a_wrong_way_road_user_at_a_short_stated_gap_is_head_on_in_the_ego_s_lane(text, gap, tmp_path):
    """At a gap too short to drift over from its own lane before they meet, the road user the text puts
    on the ego's side at that gap is there already, facing the ego, and meets it head-on."""
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert adv["behaviour"]["behaviour"] == "wrong_way"
    assert abs(float(adv["spawn"]["longitudinal_m"])) == pytest.approx(gap, abs=0.1)
    assert played_problems(play_layers(layers, tmp_path), layers) == []


@pytest.mark.parametrize(
    "text",
    [
        "A cyclist flies past me on the inside and cuts in right in front of my car.",
        "An e-scooter rider undertakes us at the junction, then pulls in ahead of us.",
        "Some lad on a bike overtook the ego on the right and swung in front of it.",
    ],
    ids=["cyclist-inside", "scooter-undertakes", "bike-overtook"],
)
def test_a_rider_passing_the_ego_at_a_speed_the_text_leaves_open_gets_ahead(text, tmp_path):
    """A bicycle or an e-scooter that passes the ego can do so only where the ego is slower than the
    rider's top speed: where the text leaves the ego's speed open it is one the rider can pass."""
    for seed in (0, 1):
        layers = layers_from_text(text, seed)
        assert "overtake" in str(layers["adversaries"][0]["behaviour"])
        assert played_problems(play_layers(layers, tmp_path), layers) == [], seed


@pytest.mark.parametrize(
    "text",
    [
        "Motorway, two lanes each way, I'm in the outside lane at 110 km/h. The car ahead of me suddenly swerves "
        "out round a stalled lorry in my lane.",
        "Dual carriageway, two lanes each way, ego in the fast lane at 100 km/h. The car in front of us swerves "
        "out to avoid a broken-down van in our lane.",
        "Two lanes each way, ego in the overtaking lane at 90 km/h; the lead car pulls out of the lane suddenly "
        "to reveal a stationary car ahead of us.",
    ],
    ids=["outside-lane", "fast-lane", "overtaking-lane"],
)
def test_a_lead_car_leaving_the_innermost_lane_by_an_unsaid_side_goes_where_a_lane_is(text, tmp_path):
    """The side of a cut-out the text leaves open is the one with a lane in its direction: from the
    innermost lane of a road with two lanes each way, to the right."""
    layers = layers_from_text(text, 0)
    assert played_problems(play_layers(layers, tmp_path), layers) == []


@pytest.mark.parametrize(
    "text",
    [
        "At a roundabout at 20 km/h, a car from the left entry cuts across in front of us.",
        "Going round the roundabout at 25 km/h, a van joining from the entry on our left pulls out right in "
        "front of us.",
        "At the roundabout at 20 km/h a car joining from the right pulls out in front of us.",
    ],
    ids=["car-left-entry", "van-left-entry", "car-right-entry"],
)
def test_a_road_user_joining_a_roundabout_in_front_of_the_ego_sets_off_and_meets_it(text, tmp_path):
    """A road user waiting at another entry of a roundabout sets off when the ego is as far from it as
    the ring's geometry says (its arms end well out from the centre, not at a crossroad's corner), so
    it joins the ego's way in front of it."""
    for seed in (0, 1):
        layers = layers_from_text(text, seed)
        adv = layers["adversaries"][0]
        assert layers["environment"]["map"]["kind"] == "roundabout"
        assert adv["behaviour"]["behaviour"] == "turn_into"
        assert played_problems(play_layers(layers, tmp_path), layers) == [], seed


STANDING_AT_THE_LIGHTS = [
    ("I was stopped at the lights at a crossroads when a car from the left ran the red right in front of me.", "left"),
    ("Waiting at a red light at the junction, first in the queue, a van came through from the right on red.", "right"),
    ("Ego stationary at the stop line of a signalised crossroad; a truck from the left runs the red light.", "left"),
    ("We were sat at the lights at the crossroads and a taxi from the right jumped the red.", "right"),
]  # fmt: skip


@pytest.mark.parametrize(("text", "side"), STANDING_AT_THE_LIGHTS)
def test_a_red_light_runner_crosses_in_front_of_an_ego_standing_at_its_line(text, side, tmp_path):
    """An ego said to stand at the lights stands at its line, and one running the red from a side
    crosses the junction in front of it within the run: its way is timed from the start, not from
    an ego that would have to arrive."""
    import numpy as np

    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert layers["ego"]["speed_mps"] == 0.0 and adv["spawn"]["relation"] == f"junction_{side}"
    assert layers["ego"]["distance_m"] < 10.0  # (at its line, not far up its arm)
    result = play_layers(layers, tmp_path)
    ego, tr = result.traces[result.ego], result.traces["Adversary1"]
    dx, dy = tr.x - ego.x[0], tr.y - ego.y[0]
    lon = dx * math.cos(ego.yaw[0]) + dy * math.sin(ego.yaw[0])
    lat = -dx * math.sin(ego.yaw[0]) + dy * math.cos(ego.yaw[0])
    ahead = (lon > 0) & (lon < 30.0)
    assert (np.sign(lat[ahead]) != np.sign(lat[ahead][0])).any()  # (across the ego's way ahead of it)
    assert played_problems(result, layers) == []


def _roadside_turn_in(side: str, ego_kph: float, gap_s: float, map_kind: str) -> dict:
    """Layers of an ego at ``ego_kph`` and a car standing beside its road on ``side`` that turns into
    it (out of a driveway), timed ``gap_s`` ahead of the ego, on a ``map_kind`` map."""
    where = {"straight": "On a straight road I was doing", "crossroad": "Approaching a crossroads at"}.get(
        map_kind, "Coming round a bend at"
    )
    layers = layers_from_text(f"{where} {ego_kph:g} km/h when a car pulled out of a driveway on my {side}.", 0)
    [adv] = layers["adversaries"]
    assert (adv["spawn"]["relation"], adv["behaviour"]["behaviour"]) == (f"roadside_{side}", "turn_into"), adv
    assert layers["environment"]["map"]["kind"] == map_kind
    adv["behaviour"]["config"]["arrival_gap_s"] = gap_s
    return layers


@pytest.mark.parametrize("map_kind", ["straight", "crossroad", "curve"])
@pytest.mark.parametrize("ego_kph", [30, 60, 90])
@pytest.mark.parametrize("side", ["left", "right"])
def test_a_vehicle_turning_out_of_a_place_beside_the_road_ends_ahead_in_the_ego_s_lane(
    side, ego_kph, map_kind, tmp_path
):
    """A turn into the road from beside it (a driveway, a field gate: a roadside start, no side road)
    is written and played: the road user comes across the kerb line (from the far side across the
    oncoming lanes) into the ego's lane ahead of the ego, and drives on there the ego's way, not its
    own lane's the wrong way, and nobody is hit at a gap the ego can brake for."""
    for gap_s in (0.0, 0.6, 2.0):
        layers = _roadside_turn_in(side, ego_kph, gap_s, map_kind)
        result = play_layers(layers, tmp_path)
        assert played_problems(result, layers) == [], gap_s
        if map_kind == "curve":  # (on the bend the one ahead is off the ego's heading: the check above holds)
            continue
        ego, car = result.traces[result.ego], result.traces["Adversary1"]
        dx, dy = car.x[-1] - ego.x[-1], car.y[-1] - ego.y[-1]
        lon = dx * math.cos(ego.yaw[-1]) + dy * math.sin(ego.yaw[-1])
        lat = -dx * math.sin(ego.yaw[-1]) + dy * math.cos(ego.yaw[-1])
        heading = (car.yaw[-1] - ego.yaw[-1] + math.pi) % (2 * math.pi) - math.pi
        assert lon > 0 and abs(lat) < 1.2 and abs(heading) < 0.2, (gap_s, lon, lat, heading)
        if gap_s >= 0.6:
            assert result.collisions == [], (gap_s, result.collisions)


@pytest.mark.parametrize(("ego_kph", "metres"), [(30, 15), (90, 20), (90, 60)])
@pytest.mark.parametrize("side", ["left", "right"])
def test_a_vehicle_turning_out_of_a_place_beside_the_road_at_a_stated_distance_still_gets_in_ahead(
    side, ego_kph, metres, tmp_path
):
    """A car "pulled out of a driveway 20 m ahead" at speed: it sets off when the ego is that far away where
    it can still get in ahead, else it is in the ego's lane that far ahead; either way the distance is
    in its layers and it plays as a turn into the ego's lane ahead of the ego."""
    text = f"At {ego_kph} km/h a car pulled out of a driveway on my {side} {metres} m ahead of me."
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert adv["behaviour"]["behaviour"] == "turn_into" and adv["behaviour"]["config"]["distance_m"] == metres
    assert played_problems(play_layers(layers, tmp_path), layers) == []
