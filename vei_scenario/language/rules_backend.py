"""The offline backend: a description → layers. Reading is :mod:`vei_scenario.language.reader`'s
(what the text says: actors, where they start, what they do, how critically, and of the road, the
weather and the ego); what a reading is lives in :mod:`vei_scenario.language.reading`; this module fills in the rest.

Filling: what the text leaves open (speeds, gaps, weather, time of day, background traffic, a
behaviour's configuration within the range of its criticality class) is drawn from
``random.Random(seed)``, so one description gives many scenarios and the same seed the same ones.
Words it cannot place are reported (:class:`~vei_scenario.language.reading.NotUnderstood`), never skipped silently.
"""

from __future__ import annotations

import random

from vei_scenario.language.behaviours import BEHAVIOURS
from vei_scenario.language.behaviours.base import value
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.maps import ARM_LENGTH_M
from vei_scenario.language.placement import DEFAULT_FEATURE_DISTANCE_M, junction_conflict_m, lane_id
from vei_scenario.language.reader import read as read_text
from vei_scenario.language.reading import Reading
from vei_scenario.language.scenario_writer import DEFAULT_RATE_HZ, TYPES

CRITICALITY_CLASSES = ("dangerous", "moderate", "safe")


def read(text: str) -> Reading:
    """Parse ``text`` (:func:`vei_scenario.language.reader.read`);
    :class:`~vei_scenario.language.reading.NotUnderstood` lists the words it could not place."""
    return read_text(text)


# --- sampling -------------------------------------------------------------------------------------------
def _u(rng: random.Random, lo: float, hi: float) -> float:
    return round(lo + (hi - lo) * rng.random(), 3)


def _config(rng: random.Random, name: str, given: dict, crit: str | None) -> tuple[dict, str | None]:
    mod = BEHAVIOURS[name]
    profiles = mod.PROFILES
    cls = crit if crit in profiles else (rng.choice(CRITICALITY_CLASSES) if profiles else None)
    cfg: dict[str, object] = {}
    ranges = profiles.get(cls, {}) if cls else {}
    for pname in mod.PARAMETERS:
        if pname in given:
            cfg[pname] = given[pname]
        elif pname in ranges:
            cfg[pname] = _u(rng, *ranges[pname])
    for k, v in given.items():
        cfg.setdefault(k, v)
    if "lead_s" in mod.PARAMETERS and "lead_s" not in cfg:
        cfg["lead_s"] = _u(rng, 2.0, 3.0)
    if cls:
        cfg["criticality"] = cls
    return cfg, cls


def sample_layers(reading: Reading, text: str, seed: int) -> dict:
    """The layers of one scenario of ``reading``, details drawn from ``seed``."""
    rng = random.Random(seed)
    behaviour_names = [b[0] for a in reading.actors for b in a.behaviours]
    kind = reading.map_kind
    if kind is None:
        kind = "crossroad" if {"run_red_light", "forced_turn"} & set(behaviour_names) else "straight"
    lanes = reading.lanes or 2
    relations = {
        a.relation or getattr(BEHAVIOURS[a.behaviours[0][0]], "DEFAULT_SPAWN", {}).get("relation")
        for a in reading.actors
        if a.behaviours
    }
    to_right = any(
        b[0] == "change_lane" and float(b[1].get("direction", 1.0)) < 0 for a in reading.actors for b in a.behaviours
    )
    if (("right" in relations and "left" not in relations) or to_right) and reading.lanes is None:
        lanes = max(lanes, 2)  # (someone on the ego's right, or moving over to the right: a lane there)
    ego_lane = 1
    if reading.ego_relation == "left" or ("right" in relations and "left" not in relations) or to_right:
        ego_lane = min(2, lanes)
    placement = {
        "straight": "straight",
        "crossroad": "before_junction",
        "curve": "on_curve",
        "roundabout": "before_roundabout",
    }[kind]
    lo, hi = {"straight": (13.0, 17.0), "curve": (11.0, 15.0)}.get(kind, (10.0, 13.0))
    ego_speed = reading.ego_speed_mps if reading.ego_speed_mps is not None else _u(rng, lo, hi)
    ego_speed = min(max(ego_speed, 0.0), MAX_SPEED_MPS)
    weather = reading.weather or rng.choice(["clear", "clear", "cloudy"])
    time = reading.time or f"{rng.randint(7, 18):02d}:{rng.choice([0, 15, 30, 45]):02d}"
    density = reading.density or rng.choice(["none", "light"])
    ego_distance = round(DEFAULT_FEATURE_DISTANCE_M + _u(rng, -10.0, 10.0), 3)
    ego = {"placement": placement, "lane": ego_lane, "speed_mps": round(ego_speed, 3), "agent": "cap"}
    if kind in ("crossroad", "roundabout", "curve"):
        ego["distance_m"] = ego_distance
    if kind in ("crossroad", "roundabout"):
        ego["route"] = reading.ego_route if reading.ego_route in ("straight", "left", "right") else "straight"
    intent = reading.intent or "unspecified"
    adversaries = []
    for spec in reading.actors:
        behaviours = spec.behaviours or [("keep_going", {}, None, "sequence")]  # (the reading stays as read)
        name = f"Adversary{len(adversaries) + 1}"
        nodes = []
        first_cfg: dict = {}
        for idx, (bname, given, crit, link) in enumerate(behaviours):
            if crit is None and intent in ("near_miss", "collision"):
                crit = "dangerous"
            elif crit is None and intent == "safe":
                crit = "safe"
            cfg, _ = _config(rng, bname, given, crit)
            if idx == 0:
                first_cfg = cfg
            nodes.append((link, {"behaviour": bname, "config": cfg}))
        topology = _topology(nodes)
        first = BEHAVIOURS[behaviours[0][0]]
        relation = spec.relation or getattr(first, "DEFAULT_SPAWN", {}).get("relation", "ahead")
        given_speed = spec.speed_mps
        if given_speed is not None and given_speed < 0:  # a speed word: a factor on the default speed
            given_speed = _default_speed(spec.kind, relation, ego_speed) * -given_speed
        if given_speed is None and relation in ("junction_left", "junction_right"):
            given_speed = _u(rng, 9.0, 13.0)
        if (
            given_speed
            and given_speed > 0
            and relation.startswith("roadside")
            and "crossing_speed_mps" in first.PARAMETERS
        ):
            first_cfg["crossing_speed_mps"] = round(given_speed, 3)  # a crosser's stated speed is its crossing speed
        spawn, speed = place_adversary(
            spec.kind, relation, first.NAME, first_cfg, ego, lanes, given_speed, spec.distance_m
        )
        speed = min(max(speed, 0.0), MAX_SPEED_MPS)  # (within what the layers hold)
        adversaries.append(
            {"name": name, "type": spec.kind, "spawn": spawn, "speed_mps": round(speed, 3), "behaviour": topology}
        )
    layers = {
        "format": "vei-layers/1",
        "description": text,
        "seed": seed,
        "intent": intent,
        "duration_s": max(
            MIN_DURATION_S,
            min(120.0, round(max((topology_time_s(a["behaviour"], ego_speed) for a in adversaries), default=0) + 5, 1)),
        ),
        "rate_hz": DEFAULT_RATE_HZ,
        "environment": {
            "map": {"kind": kind, "lanes_per_direction": lanes}
            | ({"traffic_signals": True} if kind == "crossroad" else {}),
            "weather": {"condition": weather},
            "time_of_day": time,
            "traffic_density": density,
        },
        "ego": ego,
        "adversaries": adversaries,
        "background": {"vehicles": []},
    }
    layers["background"]["vehicles"] = background(rng, layers)
    return layers


#: The fastest speed the layers hold (m/s).
MAX_SPEED_MPS = 45.0
#: The run lasts at least this long (the paper's 15 s), longer when the behaviours need it.
MIN_DURATION_S = 15.0


def behaviour_time_s(name: str, cfg: dict, ego_speed: float) -> float:
    """About how long behaviour ``name`` with ``cfg`` takes to play out, from its own parameters: the
    waits, lane changes, closing and braking it is made of (the run is made long enough for every
    stated behaviour to happen)."""
    params = BEHAVIOURS[name].PARAMETERS

    def v(key: str) -> float:
        return value(cfg, params, key)

    if name == "overtake":  # catch up from behind, pass, and cut back in ahead
        return v("delay_s") + 2 * v("lane_change_s") + (25.0 + v("gap_m")) / max(v("speed_gain_mps"), 0.5)
    if name in ("cut_in", "forced_turn"):
        return v("lead_s") + v("lane_change_s") + 3.0
    if name in ("sudden_stop", "stop"):
        return v("delay_s") + ego_speed / max(v("decel_mps2"), 0.5) + 2.0
    if name == "change_speed":
        return v("delay_s") + abs(v("speed_delta_mps")) / max(v("rate_mps2"), 0.2) + 1.0
    if name == "change_lane":
        return v("delay_s") + v("lane_change_s") + 1.0
    if name in ("follow_vehicle", "keep_going", "keep_lane"):
        return v("hold_s") or 4.0
    return 8.0  # (crossings and red-light runs are timed to meet the ego within a few seconds)


def topology_time_s(node: dict, ego_speed: float) -> float:
    """Time of a behaviour topology: a sequence adds up, a parallel group takes its longest."""
    if "behaviour" in node:
        return behaviour_time_s(node["behaviour"], node.get("config", {}), ego_speed)
    times = [topology_time_s(child, ego_speed) for child in node.get("sequence", node.get("parallel", []))]
    return (sum(times) if "sequence" in node else max(times, default=0.0)) if times else 0.0


def _default_speed(kind: str, relation: str, ego_speed: float) -> float:
    if TYPES[kind][1] not in ("pedestrian", "bicycle"):
        return ego_speed
    return 0.0 if relation.startswith("roadside") else 4.0


def place_adversary(
    kind: str,
    relation: str,
    behaviour_name: str,
    cfg: dict,
    ego: dict,
    lanes: int,
    speed: float | None = None,
    distance_m: float | None = None,
) -> tuple[dict, float]:
    """(spawn, speed) of an adversary whose first behaviour is ``behaviour_name`` with ``cfg``: the
    behaviour's own placement (a cut-in ahead by its gap plus closing), the timing of a junction
    crossing or a kerb-side crossing, or ``distance_m`` as said. Refinement calls it again after
    changing the configuration."""
    mod = BEHAVIOURS[behaviour_name]
    ego_speed = float(ego["speed_mps"])
    lengths = TYPES["car"][0][0] + TYPES[kind][0][0]
    spawn: dict[str, object] = {"relation": relation}
    out_speed = _default_speed(kind, relation, ego_speed) if speed is None else speed
    if relation in ("junction_left", "junction_right"):
        spawn["longitudinal_m"] = round(_junction_spawn(ego, lanes, relation, out_speed, ego_speed, cfg), 3)
    elif relation.startswith("roadside"):
        v = max(float(cfg.get("crossing_speed_mps", 1.5 if kind == "pedestrian" else 4.0)), 0.3)
        cfg.setdefault("crossing_speed_mps", v)
        k = int(ego["lane"])
        cross = (k - 0.5) * 3.5 + 1.0 if relation == "roadside_right" else (2 * lanes - k + 0.5) * 3.5 + 1.0
        trigger = ego_speed * (cross / v + float(cfg.get("arrival_gap_s", 0.5)))
        lon = trigger + 15.0 + lengths / 2
        if "distance_m" in ego:  # before a junction: the crossing lies on the ego's way to it
            lon = min(lon, float(ego["distance_m"]) - 5.0)
        spawn["longitudinal_m"] = round(lon, 3)
        out_speed = 0.0
    elif distance_m is not None and relation in ("ahead", "behind", "oncoming") and behaviour_name != "cut_in":
        spawn["longitudinal_m"] = -distance_m if relation == "behind" else distance_m  # as the text says
    elif behaviour_name == "cut_in" and speed is not None and speed > ego_speed + mod.FASTER_MPS:
        spawn["longitudinal_m"] = 0.0  # a faster car starts alongside: it draws ahead, then cuts in
    elif behaviour_name == "cut_in" and speed is not None and speed < mod.STANDING_MPS:
        # a parked car that pulls out: far enough ahead for the ego to close in for lead_s first
        lead = float(cfg.get("lead_s", 2.5))
        spawn["longitudinal_m"] = round(lengths / 2 + mod.pull_out_distance_m(ego_speed, cfg) + ego_speed * lead, 3)
    elif hasattr(mod, "place"):
        lon, placed_speed = mod.place(ego_speed, lengths, cfg)
        if relation == "behind" and lon > 0:
            lon = -lon
        spawn["longitudinal_m"] = round(lon, 3)
        out_speed = placed_speed if speed is None else speed
    elif distance_m is not None:
        spawn["longitudinal_m"] = distance_m if relation != "behind" else -distance_m
    return spawn, round(out_speed, 3)


def _topology(nodes: list[tuple[str, dict]]) -> dict:
    """Nodes with their links → a topology: runs of "parallel" join the node before them."""
    groups: list[list[dict]] = []
    for link, node in nodes:
        if link == "parallel" and groups:
            groups[-1].append(node)
        else:
            groups.append([node])
    items = [g[0] if len(g) == 1 else {"parallel": g} for g in groups]
    return items[0] if len(items) == 1 else {"sequence": items}


def _junction_spawn(ego: dict, lanes: int, relation: str, speed: float, ego_speed: float, cfg: dict) -> float:
    """Distance before its junction entry that brings the actor to the ego's path ``arrival_gap_s``
    after the ego (both at constant speed)."""
    from vei_scenario.language.maps import MapInfo

    info = MapInfo("crossroad", lanes, "1", ARM_LENGTH_M, feature_s_m=ARM_LENGTH_M)
    ego_to, actor_to = junction_conflict_m(info, lane_id(lanes, ego["lane"]), relation, -lanes)
    t_ego = (float(ego.get("distance_m", DEFAULT_FEATURE_DISTANCE_M)) + ego_to) / max(ego_speed, 0.5)
    d = speed * (t_ego + float(cfg.get("arrival_gap_s", 0.5))) - actor_to
    return min(max(d, 5.0), ARM_LENGTH_M - 5.0)


#: Background vehicles per traffic density.
DENSITY_COUNT = {"none": 0, "light": 2, "moderate": 5, "heavy": 9}
BACKGROUND_SPACING_M = 25.0


def background(rng: random.Random, layers: dict) -> list[dict]:
    """Background vehicles that keep out of the ego's and the adversaries' lanes: the lanes of the
    ego's road driving the other way (away from any junction), and same-direction lanes nobody uses."""
    count = DENSITY_COUNT[layers["environment"]["traffic_density"]]
    if count == 0:
        return []
    env = layers["environment"]["map"]
    lanes = env.get("lanes_per_direction", 2)
    length = (
        ARM_LENGTH_M if env["kind"] in ("crossroad", "roundabout") else (400.0 if env["kind"] == "straight" else 480.0)
    )
    ego_lane = lane_id(lanes, layers["ego"]["lane"])
    used = {ego_lane}
    for adv in layers["adversaries"]:
        rel = adv["spawn"]["relation"]
        if rel == "left":
            used.add(ego_lane + 1)
        elif rel == "right":
            used.add(ego_lane - 1)
        elif rel == "oncoming":
            used.add(1)
        if any(node["behaviour"] == "overtake" for _, node in behaviour_nodes(adv["behaviour"])):
            used.add(ego_lane + 1 if ego_lane != -1 else 1)
    free = [k for k in range(1, lanes + 1) if k not in used]
    if env["kind"] not in ("crossroad", "roundabout"):  # (towards a junction, players may choose other turns)
        free += [-k for k in range(1, lanes + 1) if -k not in used]
    out: list[dict] = []
    taken: dict[int, list[float]] = {}
    junction = env["kind"] in ("crossroad", "roundabout")
    # away from a junction they drive towards the arm's open end: start far enough from it
    low_s, v_max = (length - 110.0, 12.0) if junction else (10.0, 15.0)
    speeds = {k: _u(rng, 9.0, v_max) for k in free}
    for _ in range(count * 10):
        if len(out) == count or not free:
            break
        lane = rng.choice(free)
        s = _u(rng, low_s, length - 10.0)
        if any(abs(s - o) < BACKGROUND_SPACING_M for o in taken.get(lane, [])):
            continue
        taken.setdefault(lane, []).append(s)
        out.append(
            {"road": "1", "lane": lane, "s_m": s, "speed_mps": speeds[lane], "type": rng.choice(["car", "car", "van"])}
        )
    return out


def layers_from_text(text: str, seed: int) -> dict:
    """Parse and sample: the layers of scenario ``seed`` of ``text``."""
    return sample_layers(read(text), text, seed)
