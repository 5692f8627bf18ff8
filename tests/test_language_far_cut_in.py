"""A road user parked beyond the far kerb (across the oncoming lanes of this right-hand-traffic road)
that pulls out into the ego's lane: it starts there nosed out towards the road the ego's way, not in
the oncoming lane facing the other way, comes across the oncoming lanes along the turn a road user
turning out of a place beside the road takes, and is in the ego's lane ahead of the ego at its gap.
A parked car pulling out of the near kerb, a rider riding along the far kerb and a car turning out
of a drive on the far side are written as before."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from play_layers import play_layers

from vei_scenario.language.corpus_check import played_problems
from vei_scenario.language.rules_backend import layers_from_text, place_adversary
from vei_scenario.language.scenario_writer import TYPES, write_scenario

WHERE = {
    "straight": "On a straight road I was doing",
    "curve": "Coming round a bend at",
    "crossroad": "Approaching a crossroads at",
}


def _pull_out(map_kind: str, ego_kph: float, kind: str, gap_m: float | None, side: str = "left") -> dict:
    """Layers of an ego at ``ego_kph`` on a ``map_kind`` map and a ``kind`` parked at the roadside on
    ``side`` that pulls out into the ego's lane (``gap_m`` ahead of it, when said). An e-scooter rider
    standing there is the car's layers with the rider in its place, placed by the sampler as standing."""
    said = f" {gap_m:g} m ahead of me" if gap_m else ""
    noun = "car" if kind == "e-scooter" else kind
    place = f"a parking space on the {side} side of the road"
    text = f"{WHERE[map_kind]} {ego_kph:g} km/h when a {noun} pulled out of {place} into my lane{said}."
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert (adv["spawn"]["relation"], adv["behaviour"]["behaviour"]) == (f"roadside_{side}", "cut_in"), adv
    assert layers["environment"]["map"]["kind"] == map_kind
    if gap_m:
        assert adv["behaviour"]["config"]["gap_m"] == gap_m
    if kind == "e-scooter":
        lanes = layers["environment"]["map"]["lanes_per_direction"]
        cfg = adv["behaviour"]["config"]
        spawn, speed = place_adversary(kind, adv["spawn"]["relation"], "cut_in", cfg, layers["ego"], lanes, 0.0, None)
        adv.update(type=kind, spawn=spawn, speed_mps=speed)
    return layers


def _in_ego_frame(result, name: str = "Adversary1"):
    """(longitudinal, lateral, heading) of ``name`` against the ego at every step."""
    ego, tr = result.traces[result.ego], result.traces[name]
    dx, dy = tr.x - ego.x, tr.y - ego.y
    c, s = np.cos(ego.yaw), np.sin(ego.yaw)
    heading = (tr.yaw - ego.yaw + np.pi) % (2 * np.pi) - np.pi
    return dx * c + dy * s, -dx * s + dy * c, heading


def _start_of(xosc: bytes, name: str = "Adversary1") -> ET.Element:
    """The position element ``name`` is teleported to in Init."""
    root = ET.fromstring(xosc)
    private = next(p for p in root.iter("Private") if p.get("entityRef") == name)
    return next(iter(private.find("PrivateAction/TeleportAction/Position")))


@pytest.mark.parametrize(
    "text",
    [
        "I was driving at 40 km/h when a car pulled out of a parking space on the left side of the road into my lane"
        " ahead of me.",
        "Doing 50 km/h down the high street, a van pulled out of a parking space on the left side of the road into"
        " my lane.",
        "The lorry was parked on the left side of the road and pulled out of its parking space into my lane while I"
        " was at 35 km/h.",
        "Twenty miles an hour, bus pulls out from a stop on the left into my lane in front of me.",
    ],
)
def test_a_vehicle_parked_at_the_far_kerb_starts_there_nosed_out_the_ego_s_way(text, tmp_path):
    """Whatever the wording, the road user parked across the oncoming lanes starts beyond the far kerb,
    facing the ego's way turned out towards the road (not square to it, not the oncoming lane's way)."""
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    said = (adv["spawn"]["relation"], adv["behaviour"]["behaviour"], adv["speed_mps"])
    assert said == ("roadside_left", "cut_in", 0.0)
    assert _start_of(write_scenario(layers, "scenario").xosc).tag == "WorldPosition"
    result = play_layers(layers, tmp_path)
    lon, lat, heading = _in_ego_frame(result)
    lanes, lane = layers["environment"]["map"]["lanes_per_direction"], layers["ego"]["lane"]
    far_edge = (2 * lanes - lane + 0.5) * 3.5  # (from the ego's lane centre to the far edge of the road)
    assert lat[0] > far_edge, (lat[0], far_edge)
    assert -math.pi / 2 + 0.1 < heading[0] < -0.1, heading[0]
    assert played_problems(result, layers) == []


@pytest.mark.parametrize("map_kind", ["straight", "curve", "crossroad"])
@pytest.mark.parametrize("ego_kph", [30, 60, 90])
@pytest.mark.parametrize("kind", ["car", "van", "e-scooter"])
def test_a_road_user_pulling_out_of_the_far_kerb_ends_ahead_in_the_ego_s_lane(map_kind, ego_kph, kind, tmp_path):
    """It comes across the oncoming lanes into the ego's lane ahead of the ego and drives on there the
    ego's way, with a gap said or not; nobody is hit (no criticality here makes it a crash), except
    on a bend at 90 km/h: the road before the bend is too short for it to be in the lane before it,
    and on the bend the ego's planner brakes late for what is ahead of it there."""
    for gap_m in (None, 20.0):
        layers = _pull_out(map_kind, ego_kph, kind, gap_m)
        result = play_layers(layers, tmp_path)
        if map_kind == "curve" and ego_kph == 90:
            assert [p for p in played_problems(result, layers) if not p.startswith("background")] == [], gap_m
            continue
        assert played_problems(result, layers) == [], gap_m
        assert not [c for c in result.collisions if "Ego" in c[1:]], (gap_m, result.collisions)
        lon, lat, heading = _in_ego_frame(result)
        assert lat[0] > 3.5 * layers["environment"]["map"]["lanes_per_direction"]  # (it came from the far side)
        if map_kind == "curve":  # (on the bend the one ahead is off the ego's heading: played_problems holds)
            continue
        came_in = (lon > 0) & (np.abs(lat) < 0.5) & (np.abs(heading) < 0.1)
        assert came_in.any(), gap_m


@pytest.mark.parametrize(("ego_kph", "gap_m"), [(30, 10.0), (60, 20.0), (90, 30.0)])
def test_a_pull_out_from_the_far_kerb_is_in_the_ego_s_lane_at_about_its_gap(ego_kph, gap_m, tmp_path):
    """Timed for an ego that keeps its speed (no braking of its own to widen the gap): when it has come
    into the ego's lane, the free space between them is about the gap it pulls out at."""
    layers = _pull_out("straight", ego_kph, "car", gap_m)
    layers["ego"]["agent"] = "lane_keep"
    result = play_layers(layers, tmp_path)
    lon, lat, heading = _in_ego_frame(result)
    k = int(np.argmax((np.abs(lat) < 0.3) & (np.abs(heading) < 0.02)))
    free = lon[k] - TYPES["car"][0][0]
    assert gap_m - 3.0 < free < gap_m + 0.4 * gap_m + 3.0, free


def test_a_car_pulling_out_of_the_near_kerb_still_changes_lane_from_beside_it():
    """Guard: from the near kerb the ego's lane is a lane change away, as it was: it starts on its lane
    beside the kerb and changes into the ego's lane, no path across."""
    layers = _pull_out("straight", 40, "car", None, side="right")
    written = write_scenario(layers, "scenario").xosc
    start = _start_of(written)
    assert start.tag == "LanePosition" and int(start.get("laneId")) < 0
    assert b"LaneChangeAction" in written and b"Trajectory" not in written


def test_a_rider_riding_along_the_far_kerb_still_swerves_from_a_lane_of_the_ego_s_way():
    """Guard: a rider that rides along at the left kerb (no standing start) swerves in from the left
    edge of the ego's direction, as before: a lane change, not the pull-out path."""
    layers = _pull_out("straight", 30, "car", None)
    [adv] = layers["adversaries"]
    adv.update(type="e-scooter", speed_mps=4.0)
    written = write_scenario(layers, "scenario").xosc
    start = _start_of(written)
    assert start.tag == "LanePosition" and start.get("laneId") == "-1"
    assert b"LaneChangeAction" in written and b"Trajectory" not in written


def test_a_car_turning_out_of_a_drive_on_the_far_side_still_starts_square_to_the_kerb(tmp_path):
    """Guard: a turn into the road out of a drive on the far side starts facing across the road, as
    before; only a parked one pulling out is nosed out."""
    text = "On a straight road I was doing 40 km/h when a car pulled out of a driveway on my left."
    layers = layers_from_text(text, 0)
    [adv] = layers["adversaries"]
    assert (adv["spawn"]["relation"], adv["behaviour"]["behaviour"]) == ("roadside_left", "turn_into")
    lon, lat, heading = _in_ego_frame(play_layers(layers, tmp_path))
    assert abs(heading[0] + math.pi / 2) < 0.15, heading[0]  # (its first step along the turn)


def test_a_walker_at_the_far_kerb_is_no_pull_out():
    """Guard: a walker standing at the far kerb steps out (a crossing); the pull-out is a vehicle's or
    a rider's."""
    from vei_scenario.language.behaviours import cut_in

    assert not cut_in.pulls_out_across("pedestrian", "roadside_left", 0.0)
    assert cut_in.pulls_out_across("e-scooter", "roadside_left", 0.0)
    assert not cut_in.pulls_out_across("car", "roadside_right", 0.0)
