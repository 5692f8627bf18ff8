"""Every class of layers the reader can produce plays what it says, whatever the map, the speeds and
the other road users: each test builds layers directly (not from a sentence, so no wording is
favoured), writes and plays them with vei run's interpreter, and checks the trajectories with
:func:`~vei_scenario.language.corpus_check.played_problems`."""

from __future__ import annotations

from pathlib import Path

import pytest
from built_layers import layers_of
from play_layers import play_layers

from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.scenario_writer import write_scenario


def _layers(kind: str, lanes: int, ego: dict, adversaries: list[dict], duration_s: float = 20.0) -> dict:
    """Layers of a scenario on a ``kind`` map with ``lanes`` lanes each way."""
    placement = {"straight": "straight", "curve": "on_curve", "crossroad": "before_junction"}[kind]
    ego = {"placement": placement, "lane": 1, "agent": "cap"} | ego
    if kind != "straight":
        ego.setdefault("distance_m", 60.0)
    return layers_of(kind, ego, adversaries, lanes=lanes, duration_s=duration_s)


def _play(layers: dict, tmp_path: Path) -> list[str]:
    return played_problems(play_layers(layers, tmp_path), layers)


@pytest.mark.parametrize("kind", ["straight", "curve"])
@pytest.mark.parametrize("speed", [6.0, 12.0, 20.0])
def test_a_lead_swerving_out_on_a_road_with_one_lane_each_way_goes_into_the_oncoming_lane(kind, speed, tmp_path):
    """With one lane each way a lead has no lane of its own direction to swerve into: it goes round
    what stands in its lane the way drivers do, over the centre line into the oncoming lane."""
    lead_gap = 4.6 + 1.5 * speed
    layers = _layers(
        kind,
        1,
        {"speed_mps": speed},
        [
            {
                "name": "Adversary1",
                "type": "car",
                "spawn": {"relation": "ahead", "longitudinal_m": lead_gap},
                "speed_mps": speed,
                "behaviour": {"behaviour": "cut_out", "config": {"obstacle": "Adversary2", "reveal_ttc_s": 4.0}},
            },
            {
                "name": "Adversary2",
                "type": "car",
                "spawn": {"relation": "ahead", "longitudinal_m": lead_gap + 5.0 * speed + 20.0},
                "speed_mps": 0.0,
                "behaviour": {"behaviour": "stop", "config": {}},
            },
        ],
    )
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_a_lane_change_to_a_side_with_no_lane_of_its_own_direction_is_refused_in_one_line(direction, tmp_path):
    """Near miss: a plain lane change told to go where its road has no lane in its direction is not
    turned into a swerve across the centre line (that is a cut-out's way round an obstacle, not a lane
    change): the writer says which road user and why."""
    layers = _layers(
        "straight",
        1,
        {"speed_mps": 12.0},
        [
            {
                "name": "Adversary1",
                "type": "car",
                "spawn": {"relation": "ahead", "longitudinal_m": 25.0},
                "speed_mps": 12.0,
                "behaviour": {"behaviour": "change_lane", "config": {"direction": direction}},
            }
        ],
    )
    with pytest.raises(ValueError, match="Adversary1 has no lane to the"):
        write_scenario(layers, "scenario")


def _crosser(relation: str, lon: float, speed: float, nodes: list[dict], kind: str = "bicycle") -> dict:
    behaviour = nodes[0] if len(nodes) == 1 else {"sequence": nodes}
    return {
        "name": "Adversary1",
        "type": kind,
        "spawn": {"relation": relation, "longitudinal_m": lon},
        "speed_mps": speed,
        "behaviour": behaviour,
    }


@pytest.mark.parametrize(
    ("relation", "ego_lane", "lanes", "before"),
    [
        ("right", 2, 2, [{"behaviour": "cut_in", "config": {"gap_m": 20.0}}]),  # (out of a side way, then across)
        ("right", 2, 2, []),  # (already on the road at the ego's right)
        ("left", 1, 2, []),  # (in the lane on the ego's left: across to the kerb side)
        ("oncoming", 1, 1, []),  # (on the far side of the road)
        ("ahead", 1, 1, [{"behaviour": "keep_going", "config": {}}]),  # (in the ego's lane: across to the far side)
    ],
    ids=["after-cut-in", "from-right-lane", "from-left-lane", "from-oncoming-lane", "from-ego-lane"],
)
@pytest.mark.parametrize(("ego_speed", "kind"), [(6.0, "bicycle"), (11.0, "e-scooter"), (16.0, "pedestrian")])
def test_a_road_user_already_on_the_road_crosses_the_ego_s_path(
    relation, ego_lane, lanes, before, ego_speed, kind, tmp_path
):
    """A crossing by a road user that starts in a lane (it rode out of a driveway and along, or is on
    the road already) has no kerb to set off from: it moves across the ego's lane to the other side
    of it, ahead of the ego, at its crossing pace."""
    speed = 0.0 if kind == "pedestrian" else 4.0
    nodes = before + [{"behaviour": "cross_in_front", "config": {"arrival_gap_s": 2.0}}]
    layers = _layers(
        "straight",
        lanes,
        {"speed_mps": ego_speed, "lane": ego_lane},
        [_crosser(relation, 30.0 + ego_speed, speed, nodes, kind)],
    )
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize(("relation", "ego_lane"), [("right", 2), ("left", 1)])
def test_background_traffic_keeps_out_of_the_lanes_a_road_user_crosses_from_a_lane_into(
    relation, ego_lane, seed, tmp_path
):
    """Background vehicles keep to lanes nobody uses; one crossing from a lane uses the lanes on both
    sides of the ego (where it crosses to), so none drives through it."""
    import random

    from vei_scenario.language.rules_backend import background

    nodes = [{"behaviour": "cross_in_front", "config": {"arrival_gap_s": 2.0}}]
    layers = _layers("straight", 2, {"speed_mps": 10.0, "lane": ego_lane}, [_crosser(relation, 40.0, 4.0, nodes)])
    layers["environment"]["traffic_density"] = "heavy"
    layers["background"]["vehicles"] = background(random.Random(seed), layers)
    assert _play(layers, tmp_path) == []


def _runner(relation: str, speed: float, then: list[dict], ego: dict, kind: str, lanes: int = 1) -> dict:
    """Layers of a road user running the red (or entering without stopping) from ``relation``, timed
    by the rules backend's own placement, then doing ``then``."""
    from vei_scenario.language.rules_backend import place_adversary

    placement = {"crossroad": "before_junction", "roundabout": "before_roundabout"}[kind]
    ego = {"placement": placement, "lane": 1, "agent": "cap"} | ego
    cfg = {"arrival_gap_s": 0.0}
    spawn, speed = place_adversary("car", relation, "run_red_light", cfg, ego, lanes, speed, None)
    nodes = [{"behaviour": "run_red_light", "config": cfg}] + then
    adv = {"name": "Adversary1", "type": "car", "spawn": spawn, "speed_mps": speed}
    adv["behaviour"] = nodes[0] if len(nodes) == 1 else {"sequence": nodes}
    layers = _layers("straight", lanes, {}, [adv], duration_s=40.0)
    layers["environment"]["map"]["kind"] = kind
    layers["ego"] = ego
    return layers


@pytest.mark.parametrize("then", ["", "sudden_stop", "stop"])
@pytest.mark.parametrize("relation", ["junction_left", "junction_right"])
@pytest.mark.parametrize(("ego_speed", "speed"), [(5.0, 12.0), (10.0, 9.0), (14.0, 6.0)])
@pytest.mark.parametrize("kind", ["crossroad", "roundabout"])
def test_a_red_light_runner_meets_the_ego_s_path_and_what_it_does_next_comes_after(
    kind, ego_speed, speed, relation, then, tmp_path
):
    """Running the red (entering a roundabout without stopping) takes the runner to the ego's path
    whatever the ego's and its own speed; a stop told after it comes once it is there, and is held."""
    after = [{"behaviour": then, "config": {"decel_mps2": 8.0, "delay_s": 0.5}}] if then else []
    ego = {"speed_mps": ego_speed, "distance_m": 60.0, "route": "straight"}
    layers = _runner(relation, speed, after, ego, kind)
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize("kind", ["e-scooter", "bicycle", "truck"])
@pytest.mark.parametrize("ego_speed", [7.0, 11.0, 16.0])
@pytest.mark.parametrize("map_kind", ["straight", "curve"])
def test_an_overtake_gets_ahead_of_the_ego_whatever_its_kind_s_usual_top_speed(kind, ego_speed, map_kind, tmp_path):
    """An overtake the layers give a road user passes the ego: it is given the speed that takes (the
    ego's and the pass's gain), even past what its kind usually does (a tuned e-scooter, a lorry on
    a fast road), and the time."""
    layers = _layers(
        map_kind,
        1,
        {"speed_mps": ego_speed},
        [
            {
                "name": "Adversary1",
                "type": kind,
                "spawn": {"relation": "behind", "longitudinal_m": -18.0},
                "speed_mps": ego_speed,
                "behaviour": {"behaviour": "overtake", "config": {"gap_m": 10.0, "lane_change_s": 2.0}},
            }
        ],
        duration_s=25.0,
    )
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize("stop", ["sudden_stop", "stop"])
@pytest.mark.parametrize(
    ("kind", "agent"), [("e-scooter", "sfm"), ("bicycle", "sfm"), ("e-scooter", None), ("pedestrian", None)]
)
@pytest.mark.parametrize("ego_speed", [6.0, 11.0, 15.0])
def test_a_crosser_told_to_stop_after_crossing_comes_to_a_standstill(stop, kind, agent, ego_speed, tmp_path):
    """A stop after a crossing is reached and held, whoever drives the crossing: a rider the social
    force model steers hands its speed back to the scenario when the stop begins (the model would
    keep it at its own pace)."""
    cross = {"behaviour": "cross_in_front", "config": {"arrival_gap_s": 2.0, "crossing_speed_mps": 4.0}}
    if agent:
        cross["config"]["agent"] = agent
    nodes = [cross, {"behaviour": stop, "config": {"decel_mps2": 6.0, "delay_s": 0.5}}]
    adv = _crosser("roadside_right", 40.0 + 2 * ego_speed, 0.0, nodes, kind)
    layers = _layers("straight", 1, {"speed_mps": ego_speed}, [adv], duration_s=25.0)
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize("relation", ["junction_left", "junction_right"])
@pytest.mark.parametrize(("first_m", "then_m"), [(60.0, 150.0), (50.0, 220.0), (80.0, 120.0)])
def test_a_red_light_runner_is_timed_again_when_the_ego_starts_farther_back(relation, first_m, then_m, tmp_path):
    """A runner's spawn is timed from where the ego starts; when the ego is moved back to make room
    for someone ahead of it, the runner is timed again, so they still meet. One whose distance the
    text states keeps it."""
    from vei_scenario.language.rules_backend import retime_junction_runs

    ego = {"speed_mps": 12.0, "distance_m": first_m, "route": "straight"}
    layers = _runner(relation, 10.0, [], ego, "crossroad", lanes=2)
    layers["ego"]["distance_m"] = then_m  # (moved back after the runner was placed)
    stated = {"name": "Adversary9", "spawn": {"relation": relation, "longitudinal_m": 33.0}}
    stated |= {"speed_mps": 10.0, "behaviour": {"behaviour": "run_red_light", "config": {}}}
    retime_junction_runs(layers["ego"], layers["adversaries"] + [stated], 2, {"Adversary1"})
    assert stated["spawn"]["longitudinal_m"] == 33.0
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    ego, runner = result.traces[result.ego], result.traces["Adversary1"]
    import numpy as np

    assert float(np.hypot(ego.x - runner.x, ego.y - runner.y).min()) < 12.0  # (they meet: it was timed to)


@pytest.mark.parametrize("kind", ["truck", "bicycle", "car"])
@pytest.mark.parametrize("relation", ["junction_left", "junction_right"])
@pytest.mark.parametrize(("ego_speed", "distance_m"), [(22.0, 60.0), (18.0, 45.0), (12.0, 30.0)])
def test_a_road_user_pulling_out_ahead_of_a_fast_ego_has_the_room_to_do_it(
    kind, relation, ego_speed, distance_m, tmp_path
):
    """A road user pulling out of a side road in front of the ego sets off when the ego is as far as
    its own time to the ego's lane needs; a fast ego starting too near the junction is moved back so
    that far (a lorry needs five seconds to come out: at 80 km/h that is over 100 m)."""
    import random

    from vei_scenario.language.rules_backend import make_room_to_pull_out, place_adversary

    ego = {"placement": "before_junction", "lane": 1, "agent": "cap", "speed_mps": ego_speed}
    ego |= {"distance_m": distance_m, "route": "straight"}
    cfg = {"arrival_gap_s": random.Random(ego_speed).uniform(0.0, 0.6)}
    spawn, speed = place_adversary(kind, relation, "turn_into", cfg, ego, 1, None, None)
    adv = {"name": "Adversary1", "type": kind, "spawn": spawn, "speed_mps": speed}
    adv["behaviour"] = {"behaviour": "turn_into", "config": cfg}
    make_room_to_pull_out(ego, [adv])
    layers = _layers("crossroad", 1, ego, [adv], duration_s=30.0)
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize("relation", ["roadside_left", "roadside_right"])
@pytest.mark.parametrize(("ego_speed", "kind"), [(7.0, "e-scooter"), (11.0, "bicycle"), (14.0, "e-scooter")])
def test_a_rider_at_either_kerb_who_swerves_in_and_turns_at_the_junction_sets_off_from_a_lane_of_the_ego_s_way(
    relation, ego_speed, kind, tmp_path
):
    """A rider at the kerb that swerves into the road starts on the edge of a lane of the ego's
    direction (at the left kerb, the lane next to the centre line): its route through the junction
    starts in that lane, not in the lane across the centre line it stood beside."""
    layers = _layers(
        "crossroad",
        2,
        {"speed_mps": ego_speed},
        [
            _crosser(
                relation,
                15.0,
                min(ego_speed - 1.0, 6.5),
                [{"behaviour": "forced_turn", "config": {"turn": "right", "gap_m": 4.0}}],
                kind,
            )
        ],
    )
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize("map_kind", ["straight", "curve"])
@pytest.mark.parametrize(
    ("ego_speed", "speed", "kind"), [(6.0, 6.0, "e-scooter"), (12.0, 10.0, "van"), (20.0, 18.0, "car")]
)
def test_an_oncoming_road_user_that_overtakes_comes_over_to_the_ego_s_side_and_gets_back_in(
    map_kind, ego_speed, speed, kind, tmp_path
):
    """Overtaking, seen by the ego, of a road user coming the other way: it pulls out onto the ego's
    side of the road, ahead of the ego and facing it, and is back in its own lane when they meet."""
    import numpy as np

    from vei_scenario.language.behaviours.overtake import place_oncoming
    from vei_scenario.language.corpus_check import _ego_frame

    cfg = {"gap_m": 15.0, "lane_change_s": 1.5}
    lon = place_oncoming(ego_speed, speed, 4.6 + 4.6, cfg)
    adv = {
        "name": "Adversary1",
        "type": kind,
        "spawn": {"relation": "oncoming", "longitudinal_m": round(min(lon, 250.0), 3)},
        "speed_mps": speed,
        "behaviour": {"behaviour": "overtake", "config": cfg},
    }
    layers = _layers(map_kind, 1, {"speed_mps": ego_speed}, [adv], duration_s=25.0)
    result = play_layers(layers, tmp_path)
    assert played_problems(result, layers) == []
    assert not result.collisions
    if map_kind == "straight":  # (on a bend the ego's frame bends away from the road)
        lon_t, lat_t = _ego_frame(result, "Adversary1")
        assert ((lon_t > 0) & (np.abs(lat_t) < 1.0)).any()  # on the ego's side, ahead of it
        closest = int(np.argmin(np.hypot(lon_t, lat_t)))
        assert abs(lat_t[closest]) > 2.5  # back in its own lane when they meet


def test_an_overtake_read_from_the_far_arm_of_a_junction_starts_on_the_ego_s_road(tmp_path):
    """Near the ego's junction, one coming the other way from beyond it that overtakes starts on the
    ego's road, not before the opposite arm's start (outside the road)."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    for seed in (0, 1, 2):
        reading = Reading(
            map_kind="crossroad",
            actors=[ActorSpec("van", "junction_opposite", None, None, [("overtake", {}, None, "sequence")])],
        )
        layers = sample_layers(reading, "built by a test", seed)
        assert layers["adversaries"][0]["spawn"]["relation"] == "oncoming"
        assert layers["adversaries"][0]["spawn"]["longitudinal_m"] > 0
        assert played_problems(play_layers(layers, tmp_path), layers) == []


@pytest.mark.parametrize("relation", ["junction_left", "junction_right"])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_red_light_runner_read_at_a_standstill_still_drives_through_and_meets_the_ego_s_path(
    relation, seed, tmp_path
):
    """A run of the red is a drive through it: a runner whose reading gives it no speed (0) is given a
    road pace, and meets the ego's path; one with a speed keeps it (near miss below)."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    def runner(speed):
        actor = ActorSpec("car", relation, None, speed, [("run_red_light", {}, None, "sequence")])
        return sample_layers(Reading(map_kind="crossroad", actors=[actor]), "built by a test", seed)

    layers = runner(0.0)
    assert layers["adversaries"][0]["speed_mps"] > 5.0
    assert played_problems(play_layers(layers, tmp_path), layers) == []
    assert runner(8.0)["adversaries"][0]["speed_mps"] == 8.0


@pytest.mark.parametrize("relation", ["roadside_right", "roadside_left"])
@pytest.mark.parametrize(
    ("ego_speed", "kind", "first"),
    [(7.0, "bicycle", "cut_in"), (10.0, "e-scooter", "cut_in"), (12.0, "bicycle", "change_lane")],
)
def test_a_rider_at_the_kerb_who_swerves_in_and_then_crosses_sets_off_from_a_lane(
    relation, ego_speed, kind, first, tmp_path
):
    """A rider at the kerb whose first move is a swerve into the road (then across it) starts on the
    kerb lane's edge, where a lane change can start, and crosses from that lane; beyond the kerb it
    is on no lane and its swerve cannot be played."""
    nodes = [{"behaviour": first, "config": {"gap_m": 20.0}}, {"behaviour": "cross_in_front", "config": {}}]
    layers = _layers("straight", 2, {"speed_mps": ego_speed}, [_crosser(relation, 30.0, 4.0, nodes, kind)])
    assert _play(layers, tmp_path) == []


@pytest.mark.parametrize(
    ("meets", "relation"),
    [("run_red_light", "junction_left"), ("run_red_light", "junction_right"), ("turn_into", "junction_right")],
)
@pytest.mark.parametrize(
    ("seed", "ego_speed", "stop"), [(0, 9.0, "sudden_stop"), (1, 12.5, "stop"), (2, 16.0, "sudden_stop")]
)
def test_a_vehicle_ahead_that_stops_does_not_hold_the_ego_short_of_the_junction_where_someone_meets_it(
    meets, relation, seed, ego_speed, stop, tmp_path
):
    """A vehicle ahead of the ego that stops (when, not said) while someone is to meet the ego at its
    junction stops once through the junction: the ego reaches the junction and the other meets its
    path. A stop whose time is said keeps it (near miss), and so does one on a road with no junction."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    def reading(stop_cfg, map_kind="crossroad", other=True):
        actors = [ActorSpec("car", "ahead", None, None, [(stop, stop_cfg, None, "sequence")])]
        if other:
            actors.append(ActorSpec("car", relation, None, None, [(meets, {}, None, "sequence")]))
        return Reading(map_kind=map_kind, ego_speed_mps=ego_speed, actors=actors)

    layers = sample_layers(reading({}), "built by a test", seed)
    assert played_problems(play_layers(layers, tmp_path), layers) == []
    kept = sample_layers(reading({"delay_s": 1.5}), "built by a test", seed)
    assert kept["adversaries"][0]["behaviour"]["config"]["delay_s"] == 1.5
    plain = sample_layers(reading({}, "straight", other=False), "built by a test", seed)
    assert plain["adversaries"][0]["behaviour"]["config"].get("delay_s", 1.0) < 5.0


@pytest.mark.parametrize("relation", ["roadside_left", "roadside_right"])
@pytest.mark.parametrize("kind", ["e-scooter", "bicycle"])
@pytest.mark.parametrize("lanes", [1, 2])
def test_a_rider_at_the_kerb_who_runs_the_red_rides_through_the_junction(relation, kind, lanes, tmp_path):
    """A rider at the kerb beside an ego waiting at the lights who rides on through the red rides up
    past the ego and on through the junction: it rides at its pace, not as a crosser standing at the
    kerb, and on the kerb lane's edge of the ego's direction, where its route can start (beyond the
    kerb, or on the far kerb's lane, no chain of roads leads it through the junction)."""
    from vei_scenario.language.corpus_check import _ego_frame
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec(kind, relation, None, None, [("run_red_light", {}, None, "sequence")])
    layers = sample_layers(Reading(map_kind="crossroad", lanes=lanes, ego_speed_mps=0.0, actors=[rider]), "test", 0)
    assert layers["adversaries"][0]["spawn"]["relation"] == relation
    result = play_layers(layers, tmp_path)
    along, _ = _ego_frame(result, "Adversary1")
    assert along[0] < 0.0  # (it comes up from behind the waiting ego, and passes it)
    assert along[-1] > float(layers["ego"]["distance_m"]) + 14.0  # (through the junction, beyond its middle)
    if lanes == 1:  # (in the one lane of its way it passes right by the ego's path; with two, a lane apart)
        assert played_problems(result, layers) == []


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("ego_speed", [22.0, 27.0, 33.0])
def test_a_road_user_from_behind_a_fast_ego_far_before_its_junction_starts_on_the_road(seed, ego_speed, tmp_path):
    """An ego set far before its junction (fast, with an overtaker to give room) starts near its road's
    start: a road user said to come from behind starts as far behind as the road allows, on it."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    moves = [("overtake", {}, None, "sequence"), ("cut_in", {}, None, "sequence")]
    lorry = ActorSpec("truck", "behind", None, None, moves)
    reading = Reading(map_kind="crossroad", lanes=3, ego_speed_mps=ego_speed, actors=[lorry])
    layers = sample_layers(reading, "test", seed)
    written = write_scenario(layers, "scenario")
    assert written.xosc


def _passes_beside(result, side: float):
    """The rider starts behind the ego and, while beside it, keeps clear of it on ``side`` (+1 left,
    -1 right) by more than a quarter metre: half the car's width, half the rider's, and room."""
    import numpy as np

    from vei_scenario.language.corpus_check import _ego_frame

    assert result.collisions == []
    along, across = _ego_frame(result, "Adversary1")
    assert along[0] < 0.0
    beside = np.abs(along) < 3.0  # (while the two are side by side: ego's and rider's half lengths)
    assert np.all(side * across[beside] > 1.85 / 2 + 0.3 + 0.25)
    return along


@pytest.mark.parametrize("kind", ["e-scooter", "bicycle"])
@pytest.mark.parametrize("lanes", [1, 2])
@pytest.mark.parametrize("ego_speed", [0.0, 5.0])
@pytest.mark.parametrize("lateral", [None, -1.2, 1.2])
def test_a_rider_from_behind_who_runs_the_red_rides_past_the_ego(kind, lanes, ego_speed, lateral, tmp_path):
    """A rider said to come up behind the ego who runs the red ("came up the inside and went through on
    red") rides past the ego on the side said (else the kerb side) and on through the junction: in the
    ego's lane, or at the edge the reader gives a side ("on the inside": 1.2 m), it ran into an ego
    waiting at the lights. Filtering past, it keeps about a third of a metre from it."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec(kind, "behind", None, None, [("run_red_light", {}, None, "sequence")], lateral_m=lateral)
    reading = Reading(map_kind="crossroad", lanes=lanes, ego_speed_mps=ego_speed, actors=[rider])
    layers = sample_layers(reading, "test", 0)
    assert layers["adversaries"][0]["spawn"]["relation"] == "behind"
    along = _passes_beside(play_layers(layers, tmp_path), 1.0 if lateral and lateral > 0 else -1.0)
    assert along[-1] > 0.0 if ego_speed else along[-1] > float(layers["ego"]["distance_m"]) + 14.0


@pytest.mark.parametrize("behaviour", ["run_red_light", "along_road"])
def test_a_rider_from_behind_said_to_hit_the_ego_keeps_to_its_lane(behaviour, tmp_path):
    """Where the text says the rider from behind hit the ego ("came up behind me at the lights and went
    into my back"), it keeps to the ego's lane: the contact the text states comes."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec("bicycle", "behind", None, None, [(behaviour, {}, None, "sequence")])
    reading = Reading(map_kind="crossroad", lanes=1, ego_speed_mps=0.0, actors=[rider], intent="collision")
    layers = sample_layers(reading, "test", 0)
    assert abs(layers["adversaries"][0]["spawn"].get("lateral_m", 0.0)) < 1.0
    assert play_layers(layers, tmp_path).collisions


@pytest.mark.parametrize(
    ("kind", "ego_speed"),
    [("e-scooter", 0.0), ("e-scooter", 3.0), ("bicycle", 0.0), ("bicycle", 3.0), ("pedestrian", 0.0)],
)
@pytest.mark.parametrize("lanes", [1, 2])
@pytest.mark.parametrize("lateral", [None, -1.2, 1.2])
def test_a_rider_coming_up_behind_along_the_road_passes_the_ego(kind, lanes, ego_speed, lateral, tmp_path):
    """One said to come up behind the ego along the road ("a cyclist came up behind me along the kerb")
    is faster than the ego and passes it with room, on the side said (else the kerb side): drawn
    anywhere in the kerb half of the ego's lane, or at the edge the reader gives a side (1.2 m from
    the lane's centre), it ran into the ego's back or flank."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec(kind, "behind", None, None, [("along_road", {}, None, "sequence")], lateral_m=lateral)
    reading = Reading(map_kind="straight", lanes=lanes, ego_speed_mps=ego_speed, actors=[rider])
    layers = sample_layers(reading, "test", 0)
    along = _passes_beside(play_layers(layers, tmp_path), 1.0 if lateral and lateral > 0 else -1.0)
    assert along[-1] > 0.0  # (to ahead of the ego)


@pytest.mark.parametrize("kind", ["e-scooter", "bicycle"])
@pytest.mark.parametrize(
    ("behaviour", "map_kind"), [("along_road", "straight"), ("along_road", "curve"), ("run_red_light", "crossroad")]
)
@pytest.mark.parametrize("seed", [0, 1])
def test_a_rider_coming_up_behind_an_ego_of_unsaid_speed_passes_it(kind, behaviour, map_kind, seed, tmp_path):
    """Where the text leaves the ego's speed open, a rider said to come up behind it ("an e-scooter came
    up the inside along the kerb") tells of an ego slower than the rider: drawn at the road's pace
    (10-17 m/s), the ego drew away from a rider capped at its top speed, which never came up."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec(kind, "behind", None, None, [(behaviour, {}, None, "sequence")])
    reading = Reading(map_kind=map_kind, lanes=1, actors=[rider])
    layers = sample_layers(reading, "test", seed)
    assert float(layers["ego"]["speed_mps"]) < float(layers["adversaries"][0]["speed_mps"])
    along = _passes_beside(play_layers(layers, tmp_path), -1.0)
    assert along[-1] > 0.0


@pytest.mark.parametrize("behaviour", ["run_red_light", "along_road"])
def test_a_rider_from_behind_said_to_hit_an_ego_of_unsaid_speed_reaches_it(behaviour, tmp_path):
    """ "A cyclist came up behind me and went into my back", the ego's speed not said: the rider is
    faster than the ego, and the contact the text states comes."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec("bicycle", "behind", None, None, [(behaviour, {}, None, "sequence")])
    map_kind = "crossroad" if behaviour == "run_red_light" else "straight"
    reading = Reading(map_kind=map_kind, lanes=1, actors=[rider], intent="collision")
    layers = sample_layers(reading, "test", 0)
    assert play_layers(layers, tmp_path).collisions


@pytest.mark.parametrize("stated_mps", [4.0, 6.0])
def test_a_rider_at_a_stated_speed_coming_up_behind_sets_the_ego_below_it(stated_mps):
    """A rider said to come up behind at a stated speed ("doing 15 km/h") passes an ego of unsaid speed
    only if the ego is slower than that speed, not slower than the rider's top speed."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec("bicycle", "behind", None, stated_mps, [("along_road", {}, None, "sequence")])
    layers = sample_layers(Reading(map_kind="straight", lanes=1, actors=[rider]), "test", 0)
    assert float(layers["ego"]["speed_mps"]) < stated_mps


def test_a_bicycle_coming_up_behind_an_ego_waiting_at_the_lights_rides_at_a_rider_s_pace():
    """A bicycle behind an ego waiting at the lights that runs the red rides at a cyclist's pace, not at
    a bicycle's top speed (36 km/h) drawn from the road's."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec("bicycle", "behind", None, None, [("run_red_light", {}, None, "sequence")])
    for seed in range(5):
        reading = Reading(map_kind="crossroad", lanes=1, ego_speed_mps=0.0, actors=[rider])
        assert float(sample_layers(reading, "test", seed)["adversaries"][0]["speed_mps"]) < 7.0


@pytest.mark.parametrize(
    ("speed", "kind"), [(-0.6, "bicycle"), (-1.3, "bicycle"), (1.4, "bicycle"), (-0.6, "e-scooter")]
)
def test_a_rider_coming_up_behind_at_a_speed_word_or_a_low_speed_is_faster_than_the_ego(speed, kind):
    """ "came up behind me slowly", "... fast", "... at 5 km/h": the rider is still faster than an ego of
    unsaid speed (a speed word is a factor on the rider's default speed, not its top speed; a low stated
    speed bounds the ego below it)."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec(kind, "behind", None, speed, [("along_road", {}, None, "sequence")])
    layers = sample_layers(Reading(map_kind="straight", lanes=1, actors=[rider]), "test", 0)
    assert float(layers["ego"]["speed_mps"]) < float(layers["adversaries"][0]["speed_mps"])


def test_a_rider_behind_a_scene_ahead_does_not_set_the_ego_s_pace():
    """ "A cyclist behind me, and the car ahead braked hard": the scene is the car's; the ego keeps the
    road's pace, as it does with no rider."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    rider = ActorSpec("bicycle", "behind", None, None, [("along_road", {}, None, "sequence")])
    lead = ActorSpec("car", "ahead", None, None, [("sudden_stop", {}, None, "sequence")])
    alone = sample_layers(Reading(map_kind="straight", lanes=1, actors=[lead]), "test", 0)
    both = sample_layers(Reading(map_kind="straight", lanes=1, actors=[rider, lead]), "test", 0)
    assert both["ego"]["speed_mps"] == alone["ego"]["speed_mps"]


@pytest.mark.parametrize("kind", ["bicycle", "e-scooter"])
@pytest.mark.parametrize("relation", ["roadside_right", "roadside_left"])
def test_a_rider_said_to_stand_at_the_kerb_then_run_the_red_sets_off(kind, relation, tmp_path):
    """ "A cyclist stopped at the kerb on the right, then ran the red": its stop is the wait before it
    sets off. Read as a standstill it never ends, it stood at the kerb for the whole run."""
    import numpy as np

    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    moves = [("stop", {}, None, "sequence"), ("run_red_light", {}, None, "sequence")]
    rider = ActorSpec(kind, relation, None, None, moves)
    layers = sample_layers(Reading(map_kind="crossroad", lanes=1, ego_speed_mps=10.0, actors=[rider]), "test", 0)
    result = play_layers(layers, tmp_path)
    trace = result.traces["Adversary1"]
    assert float(np.hypot(np.ptp(trace.x), np.ptp(trace.y))) > 20.0
    assert played_problems(result, layers) == []


def test_a_red_light_runner_that_never_sets_off_is_a_played_problem(tmp_path):
    """The played check names a red-light runner that stands where it starts for the whole run (here
    held by a wait longer than the run)."""
    layers = layers_of(
        "crossroad",
        {"placement": "before_junction", "lane": 1, "speed_mps": 10.0, "distance_m": 60.0, "route": "straight"},
        [
            {
                "name": "Adversary1",
                "type": "bicycle",
                "spawn": {"relation": "roadside_right", "longitudinal_m": 40.0},
                "speed_mps": 0.0,
                "behaviour": {
                    "sequence": [
                        {"behaviour": "stop", "config": {"delay_s": 60.0}},  # (longer than the run)
                        {"behaviour": "run_red_light", "config": {"arrival_gap_s": 1.2}},
                    ]
                },
            }
        ],
        lanes=1,
        signals=True,
    )
    assert "Adversary1: run_red_light but never set off" in played_problems(play_layers(layers, tmp_path), layers)


@pytest.mark.parametrize("kind", ["bicycle", "e-scooter"])
def test_a_rider_said_to_come_up_behind_fast_is_no_slower_than_one_with_no_word(kind):
    """ "came up fast behind me": the speed word is a factor on the pace it comes up at, so it is at
    least as fast as the same rider with no word, and still faster than the ego."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    def layers(speed):
        rider = ActorSpec(kind, "behind", None, speed, [("along_road", {}, None, "sequence")])
        return sample_layers(Reading(map_kind="straight", lanes=1, actors=[rider]), "test", 0)

    plain, fast = layers(None), layers(-1.3)
    assert float(fast["adversaries"][0]["speed_mps"]) >= float(plain["adversaries"][0]["speed_mps"])
    assert float(fast["ego"]["speed_mps"]) < float(fast["adversaries"][0]["speed_mps"])


@pytest.mark.parametrize("kind", ["bicycle", "e-scooter"])
def test_a_speed_word_on_an_overtaking_rider_slows_no_ego(kind):
    """ "A cyclist overtook me fast on the inside": the pass is timed on the ego's speed, so the word
    sets the ego no lower bound than the same rider with no word."""
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    def ego(speed):
        rider = ActorSpec(kind, "behind", None, speed, [("overtake", {}, None, "sequence")])
        return float(
            sample_layers(Reading(map_kind="straight", lanes=1, actors=[rider]), "test", 0)["ego"]["speed_mps"]
        )

    assert ego(-1.3) == ego(None) > ego(-0.6)  # ("overtook me slowly as I crawled along": a slower ego)


@pytest.mark.parametrize("kind", ["bicycle", "e-scooter"])
def test_a_rider_at_the_kerb_who_runs_the_red_past_a_waiting_ego_rides_at_a_rider_s_pace(kind):
    """Beside an ego waiting at the lights, a rider at the kerb who runs the red rides at its own
    pace, not at its kind's top speed drawn from the road's pace (a bicycle at 36 km/h)."""
    from vei_scenario.language.behaviours.along_road import PACE_MPS
    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    for moves in (
        [("run_red_light", {}, None, "sequence")],
        [("stop", {}, None, "sequence"), ("run_red_light", {}, None, "sequence")],
    ):
        rider = ActorSpec(kind, "roadside_right", None, None, moves)
        reading = Reading(map_kind="crossroad", lanes=1, ego_speed_mps=0.0, actors=[rider])
        assert float(sample_layers(reading, "test", 0)["adversaries"][0]["speed_mps"]) == PACE_MPS[kind]


@pytest.mark.parametrize("route", ["straight", "right"])
@pytest.mark.parametrize("kind", ["e-scooter", "bicycle", "pedestrian"])
def test_one_who_crosses_from_the_kerb_and_then_runs_the_red_keeps_going(route, kind, tmp_path):
    """ "came off the pavement on my right and went straight through his red light": after crossing from
    the kerb, where it started standing, it runs the red at its own pace; held at the standstill it
    started in, it stopped a few metres out and never made the run."""
    import numpy as np

    from vei_scenario.language.reading import ActorSpec, Reading
    from vei_scenario.language.rules_backend import sample_layers

    moves = [("cross_in_front", {}, None, "sequence"), ("run_red_light", {}, None, "sequence")]
    rider = ActorSpec(kind, "roadside_right", None, None, moves)
    reading = Reading(map_kind="crossroad", lanes=1, ego_speed_mps=4.5, ego_route=route, actors=[rider])
    layers = sample_layers(reading, "test", 0)
    result = play_layers(layers, tmp_path)
    trace = result.traces["Adversary1"]
    assert float(np.hypot(np.ptp(trace.x), np.ptp(trace.y))) > 20.0
    assert not any("never set off" in p for p in played_problems(result, layers))
