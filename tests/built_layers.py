"""Layers and behaviour contexts built directly by the tests of what a scenario plays, so that each
test states only what it is about (the map, the ego, the road users) and no wording is favoured."""

from __future__ import annotations

from vei_scenario.language.behaviours.base import ActorContext


def layers_of(
    map_kind: str,
    ego: dict,
    adversaries: list[dict],
    *,
    lanes: int = 2,
    duration_s: float = 15.0,
    signals: bool = False,
) -> dict:
    """Layers of a scenario on a ``map_kind`` map with ``lanes`` lanes each way, clear at noon, no traffic."""
    road_map = {"kind": map_kind, "lanes_per_direction": lanes} | ({"traffic_signals": True} if signals else {})
    return {
        "format": "vei-layers/1",
        "description": "built by a test",
        "seed": 0,
        "intent": "unspecified",
        "duration_s": duration_s,
        "rate_hz": 20,
        "environment": {
            "map": road_map,
            "weather": {"condition": "clear"},
            "time_of_day": "12:00",
            "traffic_density": "none",
        },
        "ego": ego,
        "adversaries": adversaries,
        "background": {"vehicles": []},
    }


def junction_context(ego_route: str = "straight", map_kind: str = "crossroad") -> ActorContext:
    """A car on the arm opposite the ego at a four-arm junction, one lane each way, both at 10 m/s."""
    return ActorContext(
        actor="Adversary1",
        actor_type="car",
        ego="Ego",
        ego_speed_mps=10.0,
        actor_speed_mps=10.0,
        ego_lane_id=-1,
        actor_lane_id=-1,
        actor_road="3",
        actor_s_m=260.0,
        lanes=1,
        friction=1.0,
        map_kind=map_kind,
        exits={"right": "2", "straight": "3", "left": "4"},
        actor_exits={"straight": "1", "left": "2", "right": "4"},
        ego_route=ego_route,
    )
