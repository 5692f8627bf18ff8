"""Every road user's final spawn lies within the range the layers hold (-150 .. 250 m), whatever
moves it after its first placement (parked cars that hide a crossing, red-light runners timed again
for an ego that starts farther back)."""

from __future__ import annotations

from vei_scenario.language.layers import schema_problems
from vei_scenario.language.reading import ActorSpec, Reading
from vei_scenario.language.rules_backend import MAX_SPAWN_M, MIN_SPAWN_M, sample_layers


def _spec(kind, relation, behaviour, distance_m=None, speed_mps=None):
    return ActorSpec(kind, relation, distance_m, speed_mps, [(behaviour, {}, None, "sequence")])


def _spawns(layers: dict) -> list[float]:
    return [float(a["spawn"].get("longitudinal_m", 0.0)) for a in layers["adversaries"]]


def test_parked_cars_beside_a_far_crossing_stay_within_range():
    # a child crossing from behind parked cars at the farthest start the layers allow (a fast ego):
    # the car placed after it would stand beyond it
    reading = Reading(
        map_kind="straight",
        ego_speed_mps=44.0,
        actors=[
            _spec("pedestrian", "roadside_right", "cross_in_front", distance_m=MAX_SPAWN_M),
            _spec("car", "roadside_right", "keep_going"),
            _spec("van", "roadside_right", "keep_going"),
            _spec("truck", "roadside_right", "keep_going"),
        ],
    )
    for seed in range(5):
        layers = sample_layers(reading, "a child steps out from behind parked cars far ahead", seed)
        assert all(-MIN_SPAWN_M <= s <= MAX_SPAWN_M for s in _spawns(layers)), _spawns(layers)
        assert schema_problems(layers) == []


def test_red_light_runner_timed_again_for_a_far_ego_stays_within_range():
    # a fast runner of the red, timed again after a slow cyclist far ahead moves the ego's start back
    reading = Reading(
        map_kind="crossroad",
        ego_speed_mps=8.0,
        actors=[
            _spec("car", "junction_left", "run_red_light", speed_mps=40.0),
            _spec("bicycle", "ahead", "along_road", distance_m=200.0, speed_mps=2.0),
        ],
    )
    for seed in range(5):
        layers = sample_layers(reading, "a car runs the red while a cyclist rides far ahead", seed)
        assert all(-MIN_SPAWN_M <= s <= MAX_SPAWN_M for s in _spawns(layers)), _spawns(layers)
        assert schema_problems(layers) == []
