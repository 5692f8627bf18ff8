"""The offline backend: a description → layers. Reading is :mod:`vei_scenario.language.reader`'s
(what the text says: actors, where they start, what they do, how critically, and of the road, the
weather and the ego); what a reading is lives in :mod:`vei_scenario.language.reading`; this module fills in the rest.

Filling: what the text leaves open (speeds, gaps, weather, time of day, background traffic, a
behaviour's configuration within the range of its criticality class) is drawn from
``random.Random(seed)``, so one description gives many scenarios and the same seed the same ones.
Words it cannot place are reported (:class:`~vei_scenario.language.reading.NotUnderstood`), never skipped silently.
"""

from __future__ import annotations

import copy
import math
import random
from functools import lru_cache

from vei_scenario.language import closest_approach, lane_room
from vei_scenario.language.behaviours import BEHAVIOURS
from vei_scenario.language.behaviours.base import value
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.maps import ARM_LENGTH_M, LANE_WIDTH_M, ROUNDABOUT_RADIUS_M, layout
from vei_scenario.language.placement import (
    DEFAULT_FEATURE_DISTANCE_M,
    FILTERING_MARGIN_M,
    edge_offset_m,
    ego_pose,
    junction_conflict_m,
    lane_id,
)
from vei_scenario.language.reader import read as read_text
from vei_scenario.language.reading import Reading, stands_there
from vei_scenario.language.scenario_writer import (
    DEFAULT_RATE_HZ,
    EGO_KIND,
    RIDERS_AT_KERB,
    SWERVES_FROM_KERB,
    TYPES,
    vulnerable,
)

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
    # (a behaviour with no profiles keeps the class its wording says: "rides along ... with plenty of room")
    if crit in profiles or (crit and not profiles):
        cls = crit
    else:
        cls = rng.choice(CRITICALITY_CLASSES) if profiles else None
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


def sample_layers(reading: Reading, text: str, seed: int, notes: list[str] | None = None) -> dict:
    """The layers of one scenario of ``reading``, details drawn from ``seed``. What the text states
    that these layers cannot keep (a gap too short for the road user to cover) is appended to
    ``notes``, one sentence each, for the run to say."""
    rng = random.Random(seed)
    behaviour_names = [b[0] for a in reading.actors for b in a.behaviours]
    kind = reading.map_kind
    if kind is None:
        at_junction = any((a.relation or "").startswith("junction") for a in reading.actors if a.behaviours) or {
            "run_red_light",
            "forced_turn",
            "turn_across",
            "turn_into",
        } & set(behaviour_names)
        kind = "crossroad" if at_junction else "straight"
    # a roundabout's arms link one lane each way into the ring: unless more are said, one lane each way
    # (in the kerb lane of a two-lane arm the ego, or an entering road user, could not enter the ring)
    lanes = reading.lanes or (1 if kind == "roundabout" or _far_side_gap(reading) else 2)
    relations = {
        a.relation or getattr(BEHAVIOURS[a.behaviours[0][0]], "DEFAULT_SPAWN", {}).get("relation")
        for a in reading.actors
        if a.behaviours
    }
    to_right = any(
        b[0] in ("change_lane", "cut_out") and float(b[1].get("direction", 1.0)) < 0
        for a in reading.actors
        for b in a.behaviours
    )
    if (("right" in relations and "left" not in relations) or to_right) and reading.lanes is None:
        lanes = max(lanes, 2)  # (someone on the ego's right, or moving over to the right: a lane there)
    if "left" in relations and reading.lanes is None:
        lanes = max(lanes, 2)  # (someone in the lane on the ego's left: a roundabout's arm with two lanes)
    ego_lane = 1
    if reading.ego_relation == "left" or ("right" in relations and "left" not in relations) or to_right:
        ego_lane = min(2, lanes)
    if "right" in relations and ego_lane == 1:
        # road users in lanes on both sides of the ego (or one on its right on a road said to have one
        # lane each way): the lanes the story needs, the ego between them
        lanes, ego_lane = max(lanes, 3 if "left" in relations else 2), 2
    lane_choice = lane_room.choose([_lane_user(a) for a in reading.actors], lanes, ego_lane)
    lanes, ego_lane = lane_choice.lanes, lane_choice.ego_lane
    placement = {
        "straight": "straight",
        "crossroad": "before_junction",
        "curve": "on_curve",
        "roundabout": "before_roundabout",
    }[kind]
    lo, hi = {"straight": (13.0, 17.0), "curve": (11.0, 15.0)}.get(kind, (10.0, 13.0))
    ego_speed = reading.ego_speed_mps
    if ego_speed is None:  # (drawn only here, as it always was: what is drawn after it stays as it was)
        drawn = _u(rng, lo, hi)
        ego_speed = reading.scene_pace_mps if reading.scene_pace_mps is not None else drawn  # (the scene's one)
    if reading.ego_speed_mps is None:
        ego_speed = min([ego_speed] + [_passable_mps(a, behind) for a, behind in _passers(reading.actors)])
    ego_speed = min(max(ego_speed, 0.0), MAX_SPEED_MPS)
    weather = reading.weather or rng.choice(["clear", "clear", "cloudy"])
    time = reading.time or f"{rng.randint(7, 18):02d}:{rng.choice([0, 15, 30, 45]):02d}"
    density = reading.density or rng.choice(["none", "light"])
    ego_distance = round(DEFAULT_FEATURE_DISTANCE_M + _u(rng, -10.0, 10.0), 3)
    ego = {"placement": placement, "lane": ego_lane, "speed_mps": round(ego_speed, 3), "agent": "cap"}
    if kind in ("crossroad", "roundabout", "curve"):
        ego["distance_m"] = ego_distance
    if kind == "crossroad" and ego_speed == 0.0 and not any(a.relation == "ahead" for a in reading.actors):
        ego["distance_m"] = AT_THE_LINE_M  # (standing at the lights with no one ahead: first at its line)
    if kind in ("crossroad", "roundabout"):
        ego["route"] = reading.ego_route if reading.ego_route in ("straight", "left", "right") else "straight"
    intent = reading.intent or "unspecified"
    adversaries = []
    timed: set[str] = set()  # (red-light runners timed by placement, not at a distance the text states)
    stops_open: set[str] = set()  # (stops whose time the text leaves open)
    for index, spec in enumerate(reading.actors):
        behaviours = spec.behaviours or [("keep_going", {}, None, "sequence")]  # (the reading stays as read)
        if _waits_then_runs_the_red(spec):
            behaviours = behaviours[1:]  # (its standing at the kerb is where it starts: it sets off through the red)
        name = f"Adversary{len(adversaries) + 1}"
        nodes = []
        first_cfg: dict = {}
        for idx, (bname, given, crit, link) in enumerate(behaviours):
            if crit is None and intent in ("near_miss", "collision", "critical"):
                crit = "dangerous"
            elif crit is None and intent == "safe":
                crit = "safe"
            cfg, _ = _config(rng, bname, given, crit)
            cfg = {k: v for k, v in cfg.items() if not k.startswith("_")}  # (the reader's own marks stay its own)
            if bname == "cross_in_front" and spec.kind == "e-scooter":
                cfg.setdefault("agent", "sfm")  # the e-scooter rider is the social force model's
            if idx == 0:
                first_cfg = cfg
                if bname in ("stop", "sudden_stop") and "delay_s" not in given:
                    stops_open.add(name)
            nodes.append((link, {"behaviour": bname, "config": cfg}))
        topology = _topology(nodes)
        first = BEHAVIOURS[behaviours[0][0]]
        relation = (
            lane_choice.relations.get(index)
            or spec.relation
            or getattr(first, "DEFAULT_SPAWN", {}).get("relation", "ahead")
        )
        given_speed = spec.speed_mps
        if given_speed is not None and given_speed < 0 and _comes_up_behind(spec):
            # a speed word of a rider coming up behind ("came up fast behind me"): a factor on the pace it
            # comes up at, within its top speed (on the 4 m/s default, "fast" was slower than no word)
            given_speed = min(_coming_up_pace(spec.kind, None, ego_speed) * -given_speed, TYPES[spec.kind][3])
        elif given_speed is not None and given_speed < 0:  # a speed word: a factor on the default speed
            given_speed = _default_speed(spec.kind, relation, ego_speed) * -given_speed
        if given_speed is None and ego_speed == 0.0 and relation == "behind" and not vulnerable(spec.kind):
            given_speed = _u(rng, lo, hi)  # (coming up behind an ego at rest: at the road's pace, not the ego's)
        if first.NAME in DRIVES and given_speed is not None and given_speed < DRIVES_AT_LEAST_MPS:
            given_speed = None  # (it drives from the start: a standstill read for it is where it ends, or another's)
        if (
            given_speed is None
            and first.NAME in DRIVES
            and ego_speed == 0.0
            and vulnerable(spec.kind)
            and not _comes_up_behind(spec)  # (it rides at its own pace: _coming_up_pace)
            and not (relation.startswith("roadside") and first.NAME == "run_red_light")  # (and one at the kerb)
        ):
            given_speed = min(_u(rng, lo, hi), TYPES[spec.kind][3])  # (not the ego's standstill: a rider's pace)
        if given_speed is None and first.NAME == "wrong_way":
            given_speed = min(_u(rng, 10.0, 20.0), TYPES[spec.kind][3])  # (a rider within its own top speed)
        if given_speed is None and relation in ("junction_left", "junction_right") and first.NAME not in WAITING:
            given_speed = min(_u(rng, 9.0, 13.0), TYPES[spec.kind][3])  # (its timing holds only below its top speed)
        if (
            given_speed
            and given_speed > 0
            and relation.startswith("roadside")
            and "crossing_speed_mps" in first.PARAMETERS
        ):
            first_cfg["crossing_speed_mps"] = round(given_speed, 3)  # a crosser's stated speed is its crossing speed
        if first.NAME == "along_road" and spec.lateral_m is None and spec.facing is None:
            spec_lateral = _u(rng, -0.9, 0.0)  # somewhere in the kerb half of the lane
        else:
            spec_lateral = spec.lateral_m
        if _passes_from_behind(spec, first.NAME, relation, intent):
            # coming up from behind, it passes the ego: on the side said (else the kerb side) just over
            # the lane's edge line, as a rider filtering past does, not into the ego's back or flank
            side = 1.0 if spec_lateral is not None and spec_lateral > 0 else -1.0
            spec_lateral = side * edge_offset_m(TYPES[spec.kind][0][1], FILTERING_MARGIN_M)
        starts_at_m = spec.distance_m
        if (
            first.NAME == "along_road"
            and starts_at_m is not None
            and not spec.beside  # (one beside the ego, "on my left", "in the cycle lane", starts where said)
            and closest_approach.is_closest_approach(starts_at_m, TYPES[EGO_KIND][0][0], TYPES[spec.kind][0][0])
        ):  # ("went round him giving 2 m"): how near the ego came, kept as such; it starts where it would
            first_cfg["gap_m"] = round(abs(starts_at_m), 3)
            starts_at_m = None
        crossing = relation.startswith("roadside") and first.NAME == "cross_in_front"
        why = None
        if crossing and starts_at_m is not None:
            why = _cross_at_distance(spec.kind, relation, first_cfg, ego, lanes, starts_at_m)
        if first.NAME == "turn_into" and relation in ("junction_left", "junction_right") and starts_at_m is not None:
            why = _turn_in_at_distance(spec.kind, relation, first_cfg, ego, lanes, starts_at_m)
        if (
            first.NAME == "run_red_light"
            and relation in ("junction_left", "junction_right")
            and starts_at_m is not None
        ):
            why = _run_at_distance(spec.kind, first_cfg, ego_speed, starts_at_m)
        if why and notes is not None:
            notes.append(f"{name}: {why}")
        if "distance_m" in ego and not adversaries and crossing:
            # the crossing lies on the ego's way to its junction: the ego starts far enough back for the
            # road user to get across in time (a child crossing four lanes at 1.5 m/s needs ~9 s)
            room = _crossing_lon_m(spec.kind, relation, first_cfg, ego, lanes) + CROSSING_CLEAR_OF_JUNCTION_M
            if room > float(ego["distance_m"]):  # (within the road before the map's feature: a curve's is short)
                before = layout({"kind": kind, "lanes_per_direction": lanes}).feature_s_m or ARM_LENGTH_M
                ego["distance_m"] = round(min(room, ARM_LENGTH_M - 20.0, before - 10.0), 3)
        spawn, speed = place_adversary(spec.kind, relation, first.NAME, first_cfg, ego, lanes, given_speed, starts_at_m)
        if first.NAME == "run_red_light" and relation.startswith("junction") and starts_at_m is None:
            timed.add(name)
        if spec_lateral:
            spawn["lateral_m"] = round(spec_lateral, 3)
        facing = spec.facing or getattr(first, "DEFAULT_SPAWN", {}).get("facing")
        if first.NAME == "wrong_way" and relation == "oncoming":
            if _in_lane_at_gap(starts_at_m, ego_speed, speed, first_cfg):
                spawn["relation"] = "ahead"  # (at a gap too short to drift over in: already in the ego's lane)
            else:
                facing = None  # it starts in its own lane and drifts over
        if facing == "against":
            spawn["facing"] = "against"
        if first.NAME == "along_road" and starts_at_m is None and spawn["relation"] == "behind":
            closing = max(speed - ego_speed, 1.0)  # (it comes up on the ego within a few seconds)
            spawn["longitudinal_m"] = -round(min(max(closing * _u(rng, 3.0, 5.0), 8.0), 40.0), 3)
        elif first.NAME == "along_road" and starts_at_m is None:
            closing = ego_speed + speed if facing == "against" else max(ego_speed - speed, 1.0)
            spawn["longitudinal_m"] = round(min(max(closing * _u(rng, 4.0, 6.0), 20.0), 200.0), 3)
        speed = min(max(speed, 0.0), MAX_SPEED_MPS)  # (within what the layers hold)
        adversaries.append(
            {"name": name, "type": spec.kind, "spawn": spawn, "speed_mps": round(speed, 3), "behaviour": topology}
        )
    _place_obstacles(reading, adversaries, ego_speed)
    _place_occluders(reading, adversaries)
    start_m = ego.get("distance_m")
    _room_ahead_before_feature(ego, adversaries, kind)
    _turn_in_before_bend(ego, adversaries, kind, lanes)
    make_room_to_pull_out(ego, adversaries, lanes, kind == "roundabout")
    make_room_to_overtake(ego, adversaries, kind)
    make_room_to_roll_up(ego, adversaries)
    if ego.get("distance_m") != start_m:
        retime_junction_runs(ego, adversaries, lanes, timed)
    if kind == "crossroad":
        stop_beyond_junction(ego, adversaries, stops_open)
    hold_spawns_in_range(adversaries)
    keep_on_the_egos_road(ego, adversaries, kind, lanes)
    layers = {
        "format": "vei-layers/1",
        "description": text,
        "seed": seed,
        "intent": intent,
        "duration_s": max(
            MIN_DURATION_S,
            min(
                120.0,
                round(
                    max(
                        max(
                            (topology_time_s(a["behaviour"], ego_speed) + _ring_s(a, kind) for a in adversaries),
                            default=0,
                        )
                        + _approach_s(ego, adversaries)
                        + 5,
                        _kerb_crossing_s(ego, adversaries),
                    ),
                    1,
                ),
            ),
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


def _lane_user(spec) -> lane_room.LaneUser:
    """What :func:`lane_room.choose` needs of a road user as read: where it starts, its first
    behaviour's usual side where the text leaves it open, whether it swerves from the kerb (the
    writer puts such a rider on the kerb lane's edge), and its lane changes with their stated sides."""
    behaviours = spec.behaviours or [("keep_going", {}, None, "sequence")]
    names = [b[0] for b in behaviours]
    default = getattr(BEHAVIOURS[names[0]], "DEFAULT_SPAWN", {}).get("relation", "ahead")
    relation = spec.relation or default
    swerves = names[0] in SWERVES_FROM_KERB or (
        bool(set(names) & set(SWERVES_FROM_KERB)) and "cross_in_front" not in names
    )
    at_kerb = relation.startswith("roadside") and vulnerable(spec.kind) and swerves
    changes = tuple(
        (b[0], float(b[1]["direction"]) if "direction" in b[1] else None)
        for b in behaviours
        if b[0] in lane_room.LANE_CHANGES
    )
    return lane_room.LaneUser(spec.relation, default, at_kerb, changes)


#: How much slower than a rider's top speed an ego it passes goes, where the text leaves the ego's
#: speed open (m/s): enough to draw ahead and cut in within the run.
PASSING_MARGIN_MPS = 4.0


def _passes_ego(spec) -> bool:
    return any(b[0] == "overtake" for b in spec.behaviours)


def _comes_up_behind(spec) -> bool:
    """Whether ``spec`` is a rider said to come up behind the ego along the road or through the red
    ("came up the inside along the kerb"): of those :func:`_passes_from_behind` places beside the ego,
    the riders (a walker's pace sets no ego's)."""
    first = spec.behaviours[0][0] if spec.behaviours else None
    return (
        spec.relation == "behind"
        and spec.facing is None
        and spec.kind in RIDERS_AT_KERB
        and first in ("along_road", "run_red_light")
    )


def _passers(actors: list) -> list:
    """The road users that must be faster than an ego whose speed the text leaves open: each that
    overtakes it, and a rider coming up behind it where the scene is that rider's (every road user
    there passes the ego or only stands): a rider behind a scene ahead ("a cyclist behind me, and the car
    ahead braked hard") does not set the ego's pace."""
    from_behind = [(a, True) for a in actors if _comes_up_behind(a)]
    if not all(_passes_ego(a) or _comes_up_behind(a) or stands_there(a) for a in actors):
        from_behind = []
    return [(a, False) for a in actors if _passes_ego(a)] + from_behind


def _passable_mps(spec, from_behind: bool) -> float:
    """The fastest the ego may go for road user ``spec`` to pass it: a bicycle or an e-scooter that
    overtakes ("flies past me on the inside") or comes up behind (``from_behind``) tells of an ego
    slower than the rider rides: its stated speed, else its top speed; a speed word ("slowly", "fast")
    of one from behind is a factor on its top speed, as on the pace :func:`sample_layers` gives it; an
    overtaker's "slowly" is one on its default speed (its pass, timed on the ego's speed, sets no bound
    for "fast"); and at most half a low speed."""
    kind, speed = spec.kind, spec.speed_mps
    top = TYPES[kind][3]
    if speed is None or 0.0 <= speed < DRIVES_AT_LEAST_MPS:  # (a standstill read for it is where it ends)
        rides = top
    elif speed < 0 and from_behind:  # (a speed word: a factor on the pace one from behind comes up at)
        rides = min(top * -speed, top)
    elif speed < 0:  # (an overtaker's: "slowly" on its default, "fast" none, its pass running past the ego's speed)
        rides = top if -speed >= 1.0 else _default_speed(kind, "behind", top) * -speed
    else:
        rides = min(speed, top)
    return max(rides - PASSING_MARGIN_MPS, min(2.0, rides / 2.0))


#: Seconds of head-on closing a wrong-way road user needs beyond its swerve, drifting over from its own
#: lane, to be in the ego's lane, facing it, before they meet.
SETTLED_S = 1.0


def _in_lane_at_gap(distance_m: float | None, ego_speed: float, speed: float, cfg: dict) -> bool:
    """Whether a wrong-way road user coming from the oncoming lane at a stated gap is in the ego's lane
    already: "it came at me on my side, 20 m off" gives where it is when seen, and at that gap, drifting
    over from its own lane, it would still be across the line when they meet (not head-on)."""
    if distance_m is None:
        return False
    from vei_scenario.language.behaviours.base import value
    from vei_scenario.language.behaviours.wrong_way import PARAMETERS

    swerve = value(cfg, PARAMETERS, "lane_change_s")
    return distance_m < (ego_speed + speed) * (swerve + SETTLED_S)


def _far_side_gap(reading: Reading) -> bool:
    """Whether someone crosses from the far kerb at a stated gap ("ran into the road from the left
    about 20 m in front of me"): on a road whose lanes the text leaves open, one lane each way, the
    road on which such a gap can be kept (across two lanes each way no one on foot covers 13 m in the
    second or two the gap leaves)."""
    return any(
        a.relation == "roadside_left" and a.distance_m is not None and a.behaviours[:1]
        and a.behaviours[0][0] == "cross_in_front"
        for a in reading.actors
    )  # fmt: skip


#: Behaviours that are a drive from the road user's first moment: a run of the red through the junction,
#: a drive head-on in the ego's lane, a pass from behind. Read at a standstill (its "stopped right in front
#: of me" at the end, or the ego's own stop), such a road user would run no red, never come head-on and
#: never get past: it is given a road pace instead.
DRIVES = ("run_red_light", "wrong_way", "overtake")
#: A road user whose first behaviour is one of :data:`DRIVES` read at less than this (m/s) is standing.
DRIVES_AT_LEAST_MPS = 0.5
#: Behaviours that start standing at a junction's stop line and set off when the ego comes.
WAITING = ("turn_across", "turn_into", "give_way")
#: Behaviours whose timing is the ego's arrival at the junction.
AT_JUNCTION = ("run_red_light", "turn_across", "turn_into", "give_way", "forced_turn")


def _first_node(adv: dict) -> dict:
    """The first atomic behaviour of road user ``adv`` (its behaviour and configuration): the one
    that sets where and when it starts."""
    return next(n for _, n in behaviour_nodes(adv["behaviour"]))


def _something_at_junction(ego: dict, adversaries: list[dict]) -> bool:
    """Whether the ego has a junction ahead (its distance to it is set) where a road user's behaviour
    waits for it or meets it there."""
    return "distance_m" in ego and any(
        n["behaviour"] in AT_JUNCTION for a in adversaries for _, n in behaviour_nodes(a["behaviour"])
    )


def _ring_s(adv: dict, kind: str) -> float:
    """The time a road user entering a roundabout without stopping takes half round its ring (s): its
    run lasts until then (what it does next comes once it is on the ego's way), so the run must too."""
    if kind != "roundabout" or not any(n["behaviour"] == "run_red_light" for _, n in behaviour_nodes(adv["behaviour"])):
        return 0.0
    return math.pi * ROUNDABOUT_RADIUS_M / max(float(adv["speed_mps"]), 1.0)


def _approach_s(ego: dict, adversaries: list[dict]) -> float:
    """The ego's time to reach its junction, when something there waits for it (s): the run must
    last that long on top of the behaviours' own times."""
    if not _something_at_junction(ego, adversaries):
        return 0.0
    return float(ego["distance_m"]) / max(float(ego["speed_mps"]), 1.0)


#: How long (s) a run goes on after the ego has reached where a road user crosses in front of it.
CROSSED_S = 4.0


def _kerb_crossing_s(ego: dict, adversaries: list[dict]) -> float:
    """How long the run must last for the ego to reach every kerb-side crossing ahead of it and the
    crossing to be over (s): a crosser is timed to meet the ego there (it sets off when the ego is as
    far off as its way across takes), so the meeting comes when the ego has driven up to it. Why: a
    walker crossing a wide road slowly stands far ahead, and a slow ego takes longer to get there
    than a crossing's usual few seconds; a run that ends first never shows the crossing."""
    speed = float(ego["speed_mps"])
    if speed < STANDING_MPS:
        return 0.0
    meets = [
        float(a["spawn"]["longitudinal_m"]) / speed + CROSSED_S
        for a in adversaries
        if str(a["spawn"].get("relation", "")).startswith("roadside")
        and "longitudinal_m" in a["spawn"]
        and any(n["behaviour"] == "cross_in_front" for _, n in behaviour_nodes(a["behaviour"]))
    ]
    return max(meets, default=0.0)


def _place_obstacles(reading: Reading, adversaries: list[dict], ego_speed: float) -> None:
    """A lead that swerves round something standing (``cut_out``) names it, and the standing actor
    is put far enough ahead of the lead for the swerve to come when its criticality says."""
    from vei_scenario.language.behaviours import cut_out

    for spec, adv in zip(reading.actors, adversaries):
        if spec.obstacle is None or not 0 <= spec.obstacle < len(adversaries):
            continue
        obstacle = adversaries[spec.obstacle]
        for _, node in behaviour_nodes(adv["behaviour"]):
            if node["behaviour"] != "cut_out":
                continue
            cfg = node["config"]
            cfg["obstacle"] = obstacle["name"]
            lead_lon = float(adv["spawn"].get("longitudinal_m", 30.0))
            lead_len, obs_len = TYPES[adv["type"]][0][0], TYPES[obstacle["type"]][0][0]
            lead_gap = max(lead_lon - (lead_len + TYPES["car"][0][0]) / 2, 0.0)
            reveal = cut_out.reveal_gap(ego_speed, float(adv["speed_mps"]), lead_gap, lead_len, cfg)
            # the lead drives on for about three seconds before it swerves
            lon = lead_lon + (lead_len + obs_len) / 2 + reveal + float(adv["speed_mps"]) * 3.0
            obstacle["spawn"] = {"relation": "ahead", "longitudinal_m": round(min(lon, MAX_SPAWN_M), 3)}
            obstacle["speed_mps"] = 0.0


#: Room left between where the ego meets a road user ahead of it and its junction or roundabout (m).
MEETING_CLEAR_OF_FEATURE_M = 10.0


def _room_ahead_before_feature(ego: dict, adversaries: list[dict], kind: str) -> None:
    """Before a junction or roundabout the ego's road ends at it: a road user placed ahead of the ego
    (a wrong-way rider timed by its speed, oncoming traffic, a cyclist the ego catches up with) must
    stand on that road, and the ego meet it there, not in the junction. Where one would not, the ego
    starts farther back (as far as the arm allows); where all fit, nothing changes."""
    if kind not in ("crossroad", "roundabout") or "distance_m" not in ego:
        return
    ego_speed = float(ego["speed_mps"])
    need = 0.0
    for adv in adversaries:
        spawn = adv["spawn"]
        if spawn["relation"] not in ("ahead", "oncoming", "left", "right", "roadside_left", "roadside_right"):
            continue
        default = 90.0 if spawn["relation"] == "oncoming" else 30.0  # (placement's defaults)
        lon = float(spawn.get("longitudinal_m", default))
        speed = float(adv.get("speed_mps", 0.0))
        meet = lon
        if spawn.get("facing", "with") == "with" and spawn["relation"] != "oncoming" and speed < ego_speed - 1.0:
            meet = lon * ego_speed / (ego_speed - speed)  # (the ego catches up with it there)
        if _turns_in_from_roadside(adv):
            meet = lon + ROADSIDE_TURN_ROOM_M  # (it turns out along the road: in the ego's lane before the junction)
        need = max(need, lon, meet + MEETING_CLEAR_OF_FEATURE_M if meet > lon else lon)
    if need > float(ego["distance_m"]) - 1.0:
        ego["distance_m"] = round(min(need + MEETING_CLEAR_OF_FEATURE_M, ARM_LENGTH_M - 20.0), 3)


#: How much farther back than a side-road road user's own time to pull out needs the ego starts (m).
PULL_OUT_MARGIN_M = 10.0


def make_room_to_pull_out(ego: dict, adversaries: list[dict], lanes: int = 1, ring: bool = False) -> None:
    """The ego starts far enough before its junction for a road user waiting in a side road to pull
    out in front of it: that road user sets off when the ego is as far as its own time to the ego's
    lane (from standing, at what its vehicle can do) takes at the ego's speed. Where the ego starts
    nearer (a fast ego, a slow lorry), it is moved back; where it is far enough, nothing changes."""
    from vei_scenario.language.behaviours import turn_into

    if "distance_m" not in ego:
        return
    ego_speed = float(ego["speed_mps"])
    for adv in adversaries:
        relation = adv["spawn"]["relation"]
        node = _first_node(adv)
        if node["behaviour"] != "turn_into" or relation not in ("junction_left", "junction_right"):
            continue
        cfg = node.get("config", {})
        actor_path, ego_path = turn_into.paths_m(relation == "junction_left", lane_id(lanes, ego["lane"]), ring)
        t_actor = turn_into.time_to_join_s(actor_path, cfg, *_vehicle(adv["type"]))
        gap = max(value(cfg, turn_into.PARAMETERS, "arrival_gap_s"), 0.0)
        need = turn_into.ego_distance_at_set_off_m(ego_speed, t_actor, ego_path, gap) + PULL_OUT_MARGIN_M
        if need > float(ego["distance_m"]):
            ego["distance_m"] = round(min(need, ARM_LENGTH_M - 20.0), 3)


def make_room_to_overtake(ego: dict, adversaries: list[dict], kind: str) -> None:
    """The ego starts far enough before its junction or roundabout for a road user on its road that
    overtakes it to be back in a lane ahead of it before the junction: by then the ego has driven as
    far as the behaviours up to the end of the overtake take (:func:`behaviour_time_s`), and the
    overtaker is its gap ahead of it. Why: a lane change still under way as the two reach the
    junction runs on into the junction's roads, where the lane it goes to is not linked to its own.
    Where the ego starts far enough back, nothing changes."""
    if kind not in ("crossroad", "roundabout") or "distance_m" not in ego:
        return
    ego_speed = float(ego["speed_mps"])
    for adv in adversaries:
        if adv["spawn"]["relation"] not in ("behind", "left", "right", "ahead"):
            continue  # (an oncoming one is placed ahead of the ego's meeting with it: _room_ahead_before_feature)
        nodes = [node for _, node in behaviour_nodes(adv["behaviour"])]
        names = [node["behaviour"] for node in nodes]
        if "overtake" not in names:
            continue
        until = nodes[: names.index("overtake") + 1]
        taken_s = sum(behaviour_time_s(n["behaviour"], n.get("config", {}), ego_speed) for n in until)
        ahead_m = value(nodes[names.index("overtake")].get("config", {}), BEHAVIOURS["overtake"].PARAMETERS, "gap_m")
        lengths = (TYPES["car"][0][0] + TYPES[adv["type"]][0][0]) / 2
        need = ego_speed * taken_s + ahead_m + lengths + MEETING_CLEAR_OF_FEATURE_M
        if need > float(ego["distance_m"]):
            ego["distance_m"] = round(min(need, ARM_LENGTH_M - 20.0), 3)


def make_room_to_roll_up(ego: dict, adversaries: list[dict]) -> None:
    """The ego starts farther back by what it covers while a road user that turns across its path or
    pulls out rolls up to its stop line (at its stated speed, braking at about 2 m/s²). Why: that
    road user's setting off is timed from standing at its line; an ego that had come on meanwhile
    would be past the distance at which it sets off, and their paths would not meet as said."""
    if "distance_m" not in ego:
        return
    ego_speed = float(ego["speed_mps"])
    rolling = [
        float(a["speed_mps"])
        for a in adversaries
        if a["spawn"]["relation"].startswith("junction")
        and float(a["speed_mps"]) > 0.5
        and _first_node(a)["behaviour"] in ("turn_across", "turn_into")
    ]
    if rolling:
        brake_s = max(rolling) / 2.0 + 1.0  # (its braking, and a second to stand)
        ego["distance_m"] = round(min(float(ego["distance_m"]) + ego_speed * brake_s, ARM_LENGTH_M - 20.0), 3)


def stop_beyond_junction(ego: dict, adversaries: list[dict], names: set[str]) -> None:
    """A vehicle ahead of the ego that stops (``names``: when, the text leaves open), where someone
    meets the ego at its junction: it stops once through the junction, not on the ego's approach.
    Why: stopping before it, it would hold the ego short of the junction, and what is to meet the
    ego there (a red-light runner, a road user pulling out) would pass where the ego never comes."""
    from vei_scenario.language.maps import JUNCTION_RADIUS_M

    if not _something_at_junction(ego, adversaries):
        return
    for adv in adversaries:
        speed = float(adv["speed_mps"])
        if adv["name"] not in names or adv["spawn"]["relation"] != "ahead" or speed < 1.0:
            continue
        node = _first_node(adv)
        lon = float(adv["spawn"].get("longitudinal_m", 30.0))
        through = float(ego["distance_m"]) - lon + 2 * JUNCTION_RADIUS_M + TYPES[adv["type"]][0][0]
        if through > 0:
            node["config"]["delay_s"] = round(through / speed, 3)


#: How far along the road (m) a road user turning out of a place beside it goes before it is in the ego's
#: lane and drives it (turn_into.roadside_path_st across two lanes each way, from the far side).
ROADSIDE_TURN_ROOM_M = 20.0


def _before_bend_m(lanes: int) -> float:
    """The farthest (m) the ego starts before the bend of a curve map, less a clearance: a road user
    turning into the ego's lane from beside the road does so on that stretch. Why: once both are on
    the bend, the one ahead in the ego's lane is off the ego's heading, and is no longer seen there."""
    return (layout({"kind": "curve", "lanes_per_direction": lanes}).feature_s_m or 0.0) - 2 * MEETING_CLEAR_OF_FEATURE_M


def _turns_in_from_roadside(adv: dict) -> bool:
    """Whether road user ``adv`` comes into the ego's lane from beside the road along a turn: one turning
    out of a place there (a drive, a gate), or one parked beyond the far kerb that pulls out across the
    oncoming lanes (:func:`~vei_scenario.language.behaviours.cut_in.pulls_out_across`)."""
    from vei_scenario.language.behaviours import cut_in

    relation, first = adv["spawn"]["relation"], _first_node(adv)["behaviour"]
    if first == "cut_in":
        return cut_in.pulls_out_across(adv["type"], relation, float(adv.get("speed_mps", 0.0)))
    return relation.startswith("roadside") and first == "turn_into"


def _turn_in_before_bend(ego: dict, adversaries: list[dict], kind: str, lanes: int) -> None:
    """On a curve map the ego starts far enough before the bend for a road user turning into its lane
    from beside the road to be in it before the bend (:func:`_before_bend_m`); where it is, nothing changes."""
    if kind != "curve" or "distance_m" not in ego:
        return
    for adv in adversaries:
        if _turns_in_from_roadside(adv):
            need = float(adv["spawn"]["longitudinal_m"]) + ROADSIDE_TURN_ROOM_M + MEETING_CLEAR_OF_FEATURE_M
            if need > float(ego["distance_m"]):
                ego["distance_m"] = round(min(need, _before_bend_m(lanes) + MEETING_CLEAR_OF_FEATURE_M), 3)


#: How long (s) the ego closes in on a road user beside the road before it turns into the road.
ROADSIDE_LEAD_S = 2.5


def _turn_in_from_roadside_at(
    distance_m: float, ego_speed: float, lateral_m: float, cfg: dict, vehicle: tuple[float, float, float]
) -> None:
    """A road user turning out of a place beside the road at a stated distance ahead of the ego ("pulls
    out of a driveway 20 m ahead of me"): as one from a side road (:func:`_turn_in_at_distance`), it
    sets off when the ego is that far away, where it can still get in ahead of the ego, else it is in
    the ego's lane that far ahead; the timing (``arrival_gap_s``) says which, and the distance is kept
    in ``cfg``."""
    from vei_scenario.language.behaviours import turn_into

    turn_m, along_m = turn_into.roadside_turn_m(lateral_m)
    gap = (distance_m + along_m) / max(ego_speed, 0.5) - turn_into.time_to_join_s(turn_m, cfg, *vehicle)
    if gap < 0.0:  # (it would join behind the ego: it is in its lane that far ahead)
        gap = distance_m / max(ego_speed, 0.5)
    cfg["arrival_gap_s"] = round(min(gap, turn_into.PARAMETERS["arrival_gap_s"].high), 3)
    cfg["distance_m"] = round(distance_m, 3)


def _roadside_to_ego_lane_m(relation: str, lanes: int, ego_lane: int) -> float:
    """How far (m) a road user standing beside the road on ``relation``'s side is from the centre of
    the ego's lane (``ego_lane``, 1 the kerb lane, of ``lanes``): the writer's roadside start
    (:mod:`~vei_scenario.language.placement`), across the oncoming lanes from the far side."""
    from vei_scenario.language.placement import KERB_OFFSET_M

    edge = lanes * LANE_WIDTH_M + KERB_OFFSET_M
    centre = (lanes - ego_lane + 0.5) * LANE_WIDTH_M  # (right of the centre line)
    return edge - centre if relation == "roadside_right" else edge + centre


def _vehicle(kind: str) -> tuple[float, float, float]:
    """(length m, top speed m/s, acceleration m/s²) of a road user of ``kind`` as the writer gives it."""
    return TYPES[kind][0][0], TYPES[kind][3], TYPES[kind][4]


def retime_junction_runs(ego: dict, adversaries: list[dict], lanes: int, names: set[str]) -> None:
    """Red-light runners ``names`` placed again for where the ego now starts: their spawn was timed
    to meet the ego at the junction from its first start, and it starts farther back when a road
    user ahead of it needs the room (they had crossed long before the ego came)."""
    for adv in adversaries:
        if adv["name"] in names and adv["spawn"]["relation"] in ("junction_left", "junction_right"):
            cfg = _first_node(adv)["config"]
            lon = _junction_spawn(
                ego, lanes, adv["spawn"]["relation"], float(adv["speed_mps"]), float(ego["speed_mps"]), cfg
            )
            adv["spawn"]["longitudinal_m"] = round(lon, 3)


def _place_occluders(reading: Reading, adversaries: list[dict]) -> None:
    """Vehicles parked at the kerb a road user crosses from stand just before and after its
    crossing point (seen from the ego), so that they hide it until it steps out."""
    crossers = [a for a in adversaries if a["spawn"]["relation"].startswith("roadside") and vulnerable(a["type"])]
    for side in ("roadside_right", "roadside_left"):
        at = [float(a["spawn"]["longitudinal_m"]) for a in crossers if a["spawn"]["relation"] == side]
        parked = [
            (spec, a)
            for spec, a in zip(reading.actors, adversaries)
            if a["spawn"]["relation"] == side and not vulnerable(a["type"])
        ]
        if not at:
            continue
        before, after = at[0], at[0]
        for k, (spec, a) in enumerate(parked):
            if spec.distance_m is not None:
                continue  # where the text puts it
            half = TYPES[a["type"]][0][0] / 2 + OCCLUDER_GAP_M
            if k % 2 == 0:
                before -= half
                a["spawn"]["longitudinal_m"] = round(before, 3)
                before -= half
            else:
                after += half
                a["spawn"]["longitudinal_m"] = round(after, 3)
                after += half


#: Free space between a parked occluder and the crossing it hides (m).
OCCLUDER_GAP_M = 0.8
#: The farthest spawns ahead and behind the layers hold (m).
MAX_SPAWN_M = 250.0
MIN_SPAWN_M = 150.0
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
    if name in ("follow_vehicle", "keep_going", "keep_lane", "along_road"):
        return v("hold_s") or 4.0
    if name == "give_way":
        return v("clear_s") + 8.0
    if name == "wrong_way":
        return BEHAVIOURS[name].APPROACH_S + v("return_ttc_s") + 2.0
    if name == "cut_out":
        return 3.0 + v("reveal_ttc_s") + 3.0
    return 8.0  # (crossings and red-light runs are timed to meet the ego within a few seconds)


def topology_time_s(node: dict, ego_speed: float) -> float:
    """Time of a behaviour topology: a sequence adds up, a parallel group takes its longest."""
    if "behaviour" in node:
        return behaviour_time_s(node["behaviour"], node.get("config", {}), ego_speed)
    times = [topology_time_s(child, ego_speed) for child in node.get("sequence", node.get("parallel", []))]
    return (sum(times) if "sequence" in node else max(times, default=0.0)) if times else 0.0


def _default_speed(kind: str, relation: str, ego_speed: float) -> float:
    if not vulnerable(kind):
        return ego_speed
    return 0.0 if relation.startswith("roadside") else 4.0


def _within_range(lon: float) -> float:
    return round(min(max(lon, -MIN_SPAWN_M), MAX_SPAWN_M), 3)


def hold_spawns_in_range(adversaries: list[dict]) -> None:
    """Every spawn within what the layers hold (-150 .. 250 m), once every step that places or moves
    road users has run. Why here: parked cars that hide a crossing are set beside it and red-light
    runners are timed again after :func:`place_adversary`'s own hold, so only a last pass over the
    final spawns keeps all of them within the layers' range (a timing that asks for more starts as
    far as they allow)."""
    for adv in adversaries:
        spawn = adv["spawn"]
        if "longitudinal_m" in spawn:
            spawn["longitudinal_m"] = _within_range(float(spawn["longitudinal_m"]))


#: How far behind an ego waiting at the lights a rider at the kerb who rides on through the red starts (m).
RIDES_UP_BEHIND_M = 8.0
#: Relations whose spawn lies on the ego's own road, at ``longitudinal_m`` along it from the ego.
_ON_THE_EGOS_ROAD = frozenset(("ahead", "behind", "left", "right", "oncoming", "roadside_left", "roadside_right"))
#: How far within either end of the ego's road such a spawn is kept (m).
_ROAD_END_MARGIN_M = 2.0


def keep_on_the_egos_road(ego: dict, adversaries: list[dict], kind: str, lanes: int) -> None:
    """Every spawn on the ego's road within that road: where the ego starts near the road's start (a
    fast ego set far before its junction so that an overtaker has room to pass), a road user said to
    come from behind starts as far behind as the road allows, not before the road's start, where no
    scenario can be written. Why here: the ego's start is settled by the steps before this one."""
    info = layout({"kind": kind, "lanes_per_direction": lanes})
    ego_s = ego_pose(info, ego).s
    low, high = _ROAD_END_MARGIN_M - ego_s, info.ego_road_length_m - _ROAD_END_MARGIN_M - ego_s
    for adv in adversaries:
        spawn = adv["spawn"]
        if spawn["relation"] in _ON_THE_EGOS_ROAD and "longitudinal_m" in spawn:
            spawn["longitudinal_m"] = round(min(max(float(spawn["longitudinal_m"]), low), high), 3)


def place_adversary(*args, **kwargs) -> tuple[dict, float]:
    """:func:`_place_adversary`, its spawn held within what the layers can hold (-150 .. 250 m:
    a timing that asks for more, at a speed near the layers' limit, starts as far as they allow)."""
    spawn, speed = _place_adversary(*args, **kwargs)
    if "longitudinal_m" in spawn:
        spawn["longitudinal_m"] = _within_range(float(spawn["longitudinal_m"]))
    return spawn, speed


def _place_adversary(
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
    if behaviour_name in WAITING and relation.startswith("junction"):
        from vei_scenario.language.behaviours.junction_entry import STOP_LINE_M

        go_key = {"turn_across": "turn_speed_mps", "turn_into": "speed_mps", "give_way": "go_speed_mps"}[behaviour_name]
        length = TYPES[kind][0][0]
        if speed is not None and speed > 0.5 and behaviour_name != "give_way":
            cfg.setdefault(go_key, round(speed, 3))  # its stated speed is the speed it goes at
        if speed is not None and speed > 0.5:
            # its stated speed is its speed: it rolls up to its stop line at it and brakes there at
            # about 2 m/s² (what it does then is timed from standing)
            room = STOP_LINE_M + length / 2 + speed * speed / 4.0
            spawn["longitudinal_m"] = round(min(room, ARM_LENGTH_M - 5), 3)
            return spawn, round(speed, 3)
        spawn["longitudinal_m"] = round(STOP_LINE_M + length / 2, 3)
        return spawn, 0.0
    if behaviour_name == "cut_in" and mod.pulls_out_across(kind, relation, _roadside_speed(kind, speed)):
        # parked beyond the far kerb: it stands there until the ego has closed in for lead_s and is as far
        # as its way across the oncoming lanes into the ego's lane takes
        lateral = _roadside_to_ego_lane_m(relation, lanes, int(ego["lane"]))
        trigger = mod.across_distance_m(ego_speed, lateral, cfg, _vehicle(kind))
        lead = ego_speed * float(cfg.get("lead_s", 2.5))
        spawn["longitudinal_m"] = round(_turn_in_spawn_m(trigger, lengths, lead, ego, lanes), 3)
        return spawn, 0.0
    if relation.startswith("roadside") and not vulnerable(kind) and behaviour_name == "cut_in":
        # pulls out of a place beside the road (a stop, a driveway, a lay-by): it stands there until the
        # ego has closed in for lead_s, as a parked car that pulls out does
        lead = float(cfg.get("lead_s", 2.5))
        spawn["longitudinal_m"] = round(lengths / 2 + mod.pull_out_distance_m(ego_speed, cfg) + ego_speed * lead, 3)
        return spawn, 0.0
    if relation.startswith("roadside") and not vulnerable(kind) and behaviour_name == "turn_into":
        # turns out of a place beside the road (a driveway, a gate): where the text puts it, else far enough
        # ahead for the ego to close in for lead_s before it sets off (turn_into.roadside_trigger_m)
        lateral = _roadside_to_ego_lane_m(relation, lanes, int(ego["lane"]))
        if distance_m is not None:
            _turn_in_from_roadside_at(distance_m, ego_speed, lateral, cfg, _vehicle(kind))
        trigger = mod.roadside_trigger_m(ego_speed, lateral, cfg, _vehicle(kind))
        spawn["longitudinal_m"] = round(_turn_in_spawn_m(trigger, lengths, ego_speed * ROADSIDE_LEAD_S, ego, lanes), 3)
        return spawn, 0.0
    if relation.startswith("roadside") and not vulnerable(kind):
        # parked beyond the kerb (placed by the road user it hides, if any: _place_occluders)
        spawn["longitudinal_m"] = distance_m if distance_m is not None else 40.0
        return spawn, 0.0
    if relation.startswith("roadside") and kind in RIDERS_AT_KERB and behaviour_name in SWERVES_FROM_KERB:
        return _kerb_rider(kind, behaviour_name, cfg, ego_speed, lengths, speed, distance_m, spawn)
    if relation.startswith("roadside") and behaviour_name == "give_way":
        spawn["longitudinal_m"] = round(max(30.0, ego_speed * 3.0), 3) if distance_m is None else distance_m
        return spawn, 0.0
    if behaviour_name == "along_road":
        pace = _pace(kind, speed)
        if relation == "behind":  # coming up from behind ("came up the inside along the kerb"): faster
            spawn["longitudinal_m"] = -(distance_m if distance_m is not None else 20.0)
            return spawn, round(_coming_up_pace(kind, speed, ego_speed), 3)
        spawn["relation"] = "ahead"
        spawn["longitudinal_m"] = distance_m if distance_m is not None else 40.0
        return spawn, round(pace, 3)
    if behaviour_name == "wrong_way":
        v = ego_speed if speed is None else speed
        spawn["relation"] = "oncoming" if relation == "oncoming" else "ahead"
        spawn["longitudinal_m"] = round(
            distance_m if distance_m is not None else mod.place(ego_speed, lengths, cfg, v), 3
        )
        return spawn, round(v, 3)
    if relation in ("junction_left", "junction_right"):
        spawn["longitudinal_m"] = round(_junction_spawn(ego, lanes, relation, out_speed, ego_speed, cfg), 3)
    elif relation.startswith("roadside") and behaviour_name == "run_red_light":
        # a rider at the kerb of the ego's road that rides on through the red ("filtered past me and
        # went through on red"): not a crosser; it rides along the kerb at its speed (as read or drawn,
        # else its kind's pace), from where the text puts it, else just behind an ego waiting at the
        # lights (it passes it) or ahead of one that goes
        out_speed = _pace(kind, speed) if vulnerable(kind) else out_speed
        lon = distance_m if distance_m is not None else (-RIDES_UP_BEHIND_M if ego_speed < 0.5 else ego_speed * 2.0)
        spawn["longitudinal_m"] = round(lon, 3)
    elif relation == "behind" and behaviour_name == "run_red_light" and kind in RIDERS_AT_KERB:
        # a rider coming up behind the ego that runs the red ("came up the inside and went through on
        # red"): it rides up the kerb side (the writer places it there) at its speed, or, not said, at
        # its kind's pace and faster than a moving ego, from as far back as the text says, else just
        # behind an ego waiting at the lights or farther behind one that goes
        out_speed = _coming_up_pace(kind, speed, ego_speed)
        back = distance_m if distance_m is not None else (RIDES_UP_BEHIND_M if ego_speed < 0.5 else 20.0)
        spawn["longitudinal_m"] = round(-back, 3)
    elif relation.startswith("roadside"):
        cfg.setdefault("crossing_speed_mps", _crossing_speed(kind, cfg))
        lon = _crossing_lon_m(kind, relation, cfg, ego, lanes)
        if "distance_m" in ego and ego.get("placement") != "on_curve":
            # before a junction: the crossing lies on the ego's way to it (a curved road goes on: there
            # it may lie on the bend)
            lon = min(lon, float(ego["distance_m"]) - CROSSING_CLEAR_OF_JUNCTION_M)
        spawn["longitudinal_m"] = round(lon, 3)
        out_speed = 0.0
    elif (
        distance_m is not None
        and relation in ("ahead", "behind", "oncoming", "left", "right")  # (in its lane or the next one)
        and behaviour_name != "cut_in"
        and not (behaviour_name == "overtake" and cfg.get("gap_m") == distance_m)  # (its gap where it cuts back in)
    ):
        spawn["longitudinal_m"] = -distance_m if relation == "behind" else distance_m  # as the text says
    elif behaviour_name == "cut_in" and speed is not None and speed > ego_speed + mod.FASTER_MPS:
        spawn["longitudinal_m"] = 0.0  # a faster car starts alongside: it draws ahead, then cuts in
    elif behaviour_name == "cut_in" and speed is not None and speed < mod.STANDING_MPS:
        # a parked car that pulls out: far enough ahead for the ego to close in for lead_s first
        lead = float(cfg.get("lead_s", 2.5))
        spawn["longitudinal_m"] = round(lengths / 2 + mod.pull_out_distance_m(ego_speed, cfg) + ego_speed * lead, 3)
    elif behaviour_name == "overtake" and relation in ("oncoming", "junction_opposite"):
        # coming the other way, it overtakes on the ego's side of the road: ahead, on the ego's road
        spawn["relation"] = "oncoming"
        out_speed = ego_speed if speed is None else speed
        stated = distance_m is not None and cfg.get("gap_m") != distance_m  # (not its gap where it gets back in)
        lon = distance_m if stated else mod.place_oncoming(ego_speed, out_speed, lengths, cfg)
        spawn["longitudinal_m"] = round(lon, 3)
    elif behaviour_name == "overtake":  # (from behind or the next lane: its start speed sets how far back)
        lon, placed_speed = mod.place(ego_speed, lengths, cfg, speed)
        spawn["longitudinal_m"] = round(lon, 3)
        out_speed = placed_speed if speed is None else speed
    elif hasattr(mod, "place"):
        lon, placed_speed = mod.place(ego_speed, lengths, cfg)
        if relation == "behind" and lon > 0:
            lon = -lon
        spawn["longitudinal_m"] = round(lon, 3)
        out_speed = placed_speed if speed is None else speed
    elif distance_m is not None:
        spawn["longitudinal_m"] = distance_m if relation != "behind" else -distance_m
    return spawn, round(out_speed, 3)


def _passes_from_behind(spec, first: str, relation: str, intent: str) -> bool:
    """Whether a walker or rider said to come up behind the ego passes it in its lane: going along the
    road, or (a rider) riding on through the red; not where the text says it hit the ego, nor one the
    text turns to face the ego."""
    if relation != "behind" or intent == "collision" or spec.facing is not None:
        return False
    return (first == "along_road" and vulnerable(spec.kind)) or (
        first == "run_red_light" and spec.kind in RIDERS_AT_KERB
    )


def _waits_then_runs_the_red(spec) -> bool:
    """Whether ``spec`` is a rider at the kerb said to stand there, then ride through the red ("a cyclist
    stopped at the kerb, then ran the red"): its stop is the wait before it sets off, not a standstill
    it holds (as read first, a stop that never ends, it stood at the kerb for the whole run)."""
    names = tuple(b[0] for b in spec.behaviours[:2])
    at_kerb = (spec.relation or "").startswith("roadside") and spec.kind in RIDERS_AT_KERB
    return at_kerb and names == ("stop", "run_red_light")


def _roadside_speed(kind: str, speed: float | None) -> float:
    """The speed (m/s) a road user beside the road starts at: a vehicle there stands (parked, at a stop),
    a rider rides along the kerb unless its stated speed says it stands."""
    if not vulnerable(kind):
        return 0.0
    return _pace(kind, speed)


def _turn_in_spawn_m(trigger_m: float, lengths_m: float, closing_m: float, ego: dict, lanes: int) -> float:
    """How far ahead of the ego (m) a road user stands beside the road that turns into the ego's lane
    when the ego is ``trigger_m`` away: ``closing_m`` farther, for the ego to close in first (on a curve
    map as far as the road before the bend has room, that it is in the lane before the bend)."""
    lon = lengths_m / 2 + trigger_m + closing_m
    if ego.get("placement") == "on_curve":  # (in on the road before the bend, as far as it has room)
        lon = max(lengths_m / 2 + trigger_m, min(lon, _before_bend_m(lanes) - ROADSIDE_TURN_ROOM_M))
    return lon


def _pace(kind: str, speed: float | None) -> float:
    """The pace of a walker or rider going along the road: its stated speed, else its kind's usual one."""
    from vei_scenario.language.behaviours.along_road import PACE_MPS

    return PACE_MPS.get(kind, 4.0) if speed is None else speed


#: How much faster than the ego one going along the road that comes up from behind rides, when its
#: speed is not said (m/s; within its own top speed).
COMES_UP_MPS = 2.0


def _coming_up_pace(kind: str, speed: float | None, ego_speed: float) -> float:
    """The speed (m/s) of a walker or rider said to come up behind the ego: its stated speed, else its
    kind's pace, and faster than the ego by :data:`COMES_UP_MPS` (within its own top speed)."""
    if speed is not None:
        return speed
    return max(_pace(kind, None), min(ego_speed + COMES_UP_MPS, TYPES[kind][3]))


def _kerb_rider(
    kind: str,
    behaviour_name: str,
    cfg: dict,
    ego_speed: float,
    lengths: float,
    speed: float | None,
    distance_m: float | None,
    spawn: dict,
) -> tuple[dict, float]:
    """(spawn, speed) of a rider at the kerb of the ego's road who swerves into it ("a cyclist riding
    along the kerb pulls out into my lane", "an e-scooter in the bike lane cuts in"): it rides along
    the kerb at its own pace (its stated speed, else a rider's usual one) and is placed as far ahead as
    ``lead_s`` seconds of the ego closing in before its gap, or at the distance said. The scenario
    writer puts it on the kerb lane's edge, where a lane change can start."""
    pace = _pace(kind, speed)
    params = BEHAVIOURS[behaviour_name].PARAMETERS
    if distance_m is not None:
        spawn["longitudinal_m"] = distance_m
    else:
        # (along_road's gap_m is how near the ego comes, not a start's gap: see closest_approach)
        gap = value(cfg, params, "gap_m") if "gap_m" in params and behaviour_name != "along_road" else 10.0
        closing = max(ego_speed - pace, 1.0)
        spawn["longitudinal_m"] = round(lengths / 2 + gap + closing * float(cfg.get("lead_s", 2.5)), 3)
    return spawn, round(pace, 3)


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


#: How far before the ego's junction a kerb-side crossing on its way stands at most (m).
CROSSING_CLEAR_OF_JUNCTION_M = 5.0


def _crossing_speed(kind: str, cfg: dict) -> float:
    return max(float(cfg.get("crossing_speed_mps", 1.5 if kind == "pedestrian" else 4.0)), 0.3)


#: The earliest a crosser may reach the ego's lane before the ego and still cross in front of it (s).
EARLIEST_IN_FRONT_S = -0.2


def _cross_at_distance(kind: str, relation: str, cfg: dict, ego: dict, lanes: int, distance_m: float) -> str | None:
    """A crossing whose distance from the ego is stated ("steps out 15 m ahead"): its timing
    (``arrival_gap_s``) is the one that sets it off when the ego is that far away, and the distance is
    kept in its configuration. Where its usual crossing speed cannot meet the ego as its criticality
    says from there, the crossing speed (unless stated) is the one within its type's reach that comes
    nearest, and the timing follows from the stated gap (a child 10 m ahead of a car at 30 km/h runs,
    and reaches the lane just as the car does). Returns None when the gap is kept, else why not (the
    timing is then the nearest the behaviour holds)."""
    from vei_scenario.language.behaviours.cross_in_front import PARAMETERS, START_RAMP_S

    k = int(ego["lane"])
    cross = (k - 0.5) * 3.5 + 1.0 if relation == "roadside_right" else (2 * lanes - k + 0.5) * 3.5 + 1.0
    accel = TYPES[kind][4]
    ego_speed = max(float(ego["speed_mps"]), 0.5)
    low, high = PARAMETERS["arrival_gap_s"].low, PARAMETERS["arrival_gap_s"].high

    def gap_at(speed: float) -> float:
        ramp = max(START_RAMP_S, speed / accel if accel > 0 else 0.0)
        return distance_m / ego_speed - (cross / speed + ramp / 2)

    speed = _crossing_speed(kind, cfg)
    gap = gap_at(speed)
    if not EARLIEST_IN_FRONT_S <= gap <= high and "crossing_speed_mps" not in cfg:
        wanted = min(max(float(cfg.get("arrival_gap_s", 0.5)), EARLIEST_IN_FRONT_S), high)
        top = min(PARAMETERS["crossing_speed_mps"].high, TYPES[kind][3])
        lo = PARAMETERS["crossing_speed_mps"].low
        steps = max(int((top - lo) / CROSSING_SPEED_STEP_MPS), 1)
        candidates = [round(lo + (top - lo) * i / steps, 3) for i in range(steps + 1)]
        speed = min(candidates, key=lambda v: (abs(gap_at(v) - wanted), abs(v - speed)))
        gap = gap_at(speed)
        cfg["crossing_speed_mps"] = speed
    # the latest it may reach the ego's lane and still meet the ego (its side, as the ego goes by):
    # later, it would cross behind the ego, which is no crossing in front of it
    band = (TYPES["car"][0][1] + TYPES[kind][0][1]) / 2
    latest = -((TYPES["car"][0][0] + TYPES[kind][0][0]) / ego_speed + band / speed)
    if max(low, latest) <= gap <= high:
        cfg["arrival_gap_s"] = round(gap, 3)
        cfg["distance_m"] = round(distance_m, 3)
        return None
    if gap < high:
        # too close to set off then and still meet the ego: the gap is where it is in the ego's path
        # ("runs out 10 m in front of me": in the lane when the ego is 10 m away), the reading a
        # crossing in front of the ego can keep
        cfg["arrival_gap_s"] = round(min(max(distance_m / ego_speed, EARLIEST_IN_FRONT_S), high), 3)
        cfg["distance_m"] = round(distance_m, 3)
        return None
    cfg["arrival_gap_s"] = float(cfg.get("arrival_gap_s", 0.5))
    return (
        f"the {kind}'s stated gap of {distance_m:g} m: to set off then and still meet the ego it would "
        f"have to cross the {cross:.1f} m to the ego's lane more slowly than a {kind} can at the ego's speed"
    )


def _run_at_distance(kind: str, cfg: dict, ego_speed: float, distance_m: float) -> str | None:
    """A road user running the red across the ego's road at a stated distance ahead ("a car ran the red
    15 m in front of me"): it is in the ego's path when the ego is that far away, so it reaches the
    conflict that distance's time at the ego's speed before the ego would (``arrival_gap_s`` negative),
    and the distance is kept in its configuration. Returns None when kept, else why not."""
    from vei_scenario.language.behaviours.run_red_light import PARAMETERS

    low = PARAMETERS["arrival_gap_s"].low
    gap = -distance_m / max(ego_speed, 0.5)
    cfg["distance_m"] = round(distance_m, 3)
    cfg["arrival_gap_s"] = round(max(gap, low), 3)
    if gap >= low:
        return None
    return (
        f"the {kind}'s stated gap of {distance_m:g} m: at the ego's speed that is more than "
        f"{-low:g} s before the ego reaches its path, later than the red-light run can be timed"
    )


def _turn_in_at_distance(kind: str, relation: str, cfg: dict, ego: dict, lanes: int, distance_m: float) -> str | None:
    """A road user pulling out of a side road at a stated distance ahead of the ego ("pulls out of a
    side street 20 m ahead of me"): its timing (``arrival_gap_s``) is the one that sets it off when the
    ego is that far from where it joins, and the distance is kept in its configuration. Returns None
    when kept, else why not (the timing is then the nearest the behaviour holds)."""
    from vei_scenario.language.behaviours import turn_into
    from vei_scenario.language.behaviours.turn_into import PARAMETERS

    from_left = relation == "junction_left"
    ego_speed, ego_lane = float(ego["speed_mps"]), lane_id(lanes, int(ego["lane"]))
    ring = ego.get("placement") == "before_roundabout"

    def gap_for_distance(distance_m: float, ego_speed: float, from_left: bool, ego_lane: int, cfg: dict) -> float:
        return turn_into.gap_for_distance(distance_m, ego_speed, from_left, ego_lane, cfg, _vehicle(kind), ring)

    gap = gap_for_distance(distance_m, ego_speed, from_left, ego_lane, cfg)
    low, high = PARAMETERS["arrival_gap_s"].low, PARAMETERS["arrival_gap_s"].high
    wanted = float(cfg.get("arrival_gap_s", PARAMETERS["arrival_gap_s"].default))
    if not 0.0 <= gap <= high and "accel_mps2" not in cfg:  # (how hard it pulls away: the timing around the gap)
        rates = PARAMETERS["accel_mps2"]
        steps = int((rates.high - rates.low) / 0.1)
        candidates = [round(rates.low + (rates.high - rates.low) * i / steps, 3) for i in range(steps + 1)]

        def off(a: float) -> float:
            return abs(gap_for_distance(distance_m, ego_speed, from_left, ego_lane, {**cfg, "accel_mps2": a}) - wanted)

        accel = min(candidates, key=off)
        gap = gap_for_distance(distance_m, ego_speed, from_left, ego_lane, {**cfg, "accel_mps2": accel})
        if low <= gap <= high:
            cfg["accel_mps2"] = accel
    if 0.0 <= gap <= high:
        cfg["arrival_gap_s"] = round(gap, 3)
        cfg["distance_m"] = round(distance_m, 3)
        return None
    if gap < 0.0:
        # it would join behind the ego, no turning in ahead of it: the gap is where it is in the ego's
        # road ("pulls out 15 m ahead of me": there when the ego is 15 m away), which it can keep
        cfg["arrival_gap_s"] = round(min(max(distance_m / max(ego_speed, 0.5), low), high), 3)
        cfg["distance_m"] = round(distance_m, 3)
        return None
    cfg["arrival_gap_s"] = high
    return (
        f"the {kind}'s stated gap of {distance_m:g} m: pulling out of the side road then, it would reach the "
        "ego's road too long before the ego comes"
    )


#: The step of the crossing speeds tried for a stated gap (m/s).
CROSSING_SPEED_STEP_MPS = 0.05


def _crossing_lon_m(kind: str, relation: str, cfg: dict, ego: dict, lanes: int) -> float:
    """Where a kerb-side crosser stands ahead of the ego: the ego's distance when it sets off (timed to
    reach the ego's lane ``arrival_gap_s`` after the ego would), plus room to see it first."""
    from vei_scenario.language.behaviours.cross_in_front import trigger_distance

    k = int(ego["lane"])
    cross = (k - 0.5) * 3.5 + 1.0 if relation == "roadside_right" else (2 * lanes - k + 0.5) * 3.5 + 1.0
    speed = _crossing_speed(kind, cfg)
    gap = float(cfg.get("arrival_gap_s", 0.5))
    trigger = trigger_distance(float(ego["speed_mps"]), cross, speed, TYPES[kind][4], gap)
    return trigger + 15.0 + (TYPES["car"][0][0] + TYPES[kind][0][0]) / 2


#: Where an ego standing at the lights stands: this far (m) before its junction's entry, its front at the line.
AT_THE_LINE_M = 5.0
#: Below this speed (m/s) the ego is standing, and never reaches a conflict point by itself.
STANDING_MPS = 0.5
#: When a red-light runner reaches the path of an ego standing at its line (s after the start).
RUN_PAST_A_STANDING_EGO_S = 4.0


def _junction_spawn(ego: dict, lanes: int, relation: str, speed: float, ego_speed: float, cfg: dict) -> float:
    """Distance before its junction entry that brings the actor to the ego's path ``arrival_gap_s``
    after the ego (both at constant speed)."""
    info = layout({"kind": "crossroad", "lanes_per_direction": lanes})
    ego_to, actor_to = junction_conflict_m(info, lane_id(lanes, ego["lane"]), relation, -lanes)
    if ego_speed < STANDING_MPS:  # (an ego standing never arrives: the runner comes through soon after the start)
        t_ego = RUN_PAST_A_STANDING_EGO_S
    else:
        t_ego = (float(ego.get("distance_m", DEFAULT_FEATURE_DISTANCE_M)) + ego_to) / ego_speed
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
    info = layout(env)  # (where the ego starts and how long its road is, as placement has it)
    length = info.ego_road_length_m
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
        for _, node in behaviour_nodes(adv["behaviour"]):
            name = node["behaviour"]
            if name in ("change_lane", "cut_out"):  # (the lane it moves into)
                step = 1 if float(node.get("config", {}).get("direction", 1.0)) >= 0 else -1
                used.add(ego_lane + step if ego_lane + step != 0 else ego_lane + 2 * step)
            elif name == "wrong_way":
                used.update(range(ego_lane, 2))  # (the lanes it crosses and swerves back to)
            elif name == "overtake":
                used.add(ego_lane + 1 if ego_lane != -1 else 1)
            elif name == "cross_in_front" and not rel.startswith("roadside"):
                # (one crossing from a lane goes over to a lane on the ego's other side: either)
                used.update({ego_lane + 1 if ego_lane != -1 else 1, ego_lane - 1})
    free = [k for k in range(1, lanes + 1) if k not in used]
    if env["kind"] not in ("crossroad", "roundabout"):  # (towards a junction, players may choose other turns)
        free += [-k for k in range(1, lanes + 1) if -k not in used]
    out: list[dict] = []
    taken: dict[int, list[float]] = {}
    junction = env["kind"] in ("crossroad", "roundabout")
    # away from a junction they drive towards the arm's open end: start far enough from it
    low_s, v_max = (length - 110.0, 12.0) if junction else (10.0, 15.0)
    speeds = {k: _u(rng, 9.0, v_max) for k in free}
    duration = float(layers.get("duration_s", MIN_DURATION_S))

    # where road users cross the road (s on the ego's road): background traffic never passes there
    ego_s = ego_pose(info, layers["ego"]).s
    crossings = [
        ego_s + float(a["spawn"].get("longitudinal_m", 0.0))
        for a in layers["adversaries"]
        if a["spawn"]["relation"].startswith("roadside")
        or (a["spawn"]["relation"] in ("ahead", "left", "right") and a["speed_mps"] == 0)
    ]

    def passes_crossing(lane: int, s: float, v: float) -> bool:
        end = s - v * duration if lane > 0 else s + v * duration
        lo, hi = min(s, end) - CROSSING_CLEARANCE_M, max(s, end) + CROSSING_CLEARANCE_M
        return any(lo <= c <= hi for c in crossings)

    def room(lane: int, s: float) -> float:
        """Road left before its end in its driving direction (left lanes drive towards s = 0)."""
        return s if lane > 0 else length - s

    for _ in range(count * 10):
        if len(out) == count or not free:
            break
        lane = rng.choice(free)
        s = _u(rng, low_s, length - 10.0)
        if any(abs(s - o) < BACKGROUND_SPACING_M for o in taken.get(lane, [])):
            continue
        if (room(lane, s) - ROAD_END_MARGIN_M) / duration < MIN_BACKGROUND_SPEED_MPS:
            continue  # it would reach the road's end within the run: the next draw
        if passes_crossing(lane, s, speeds[lane]):
            continue  # it would drive through someone crossing the road
        taken.setdefault(lane, []).append(s)
        out.append({"road": "1", "lane": lane, "s_m": s, "speed_mps": 0.0, "type": rng.choice(["car", "car", "van"])})
    # one speed per lane (nobody catches up with the one ahead), slow enough that nobody reaches the
    # road's end before the run is over (it would stand there, and the next would run into it)
    for lane, ss in taken.items():
        lane_speed = min([speeds[lane]] + [(room(lane, s) - ROAD_END_MARGIN_M) / duration for s in ss])
        for v in out:
            if v["lane"] == lane:
                v["speed_mps"] = round(lane_speed, 3)
    return out


#: Background vehicles keep this far from where someone crosses the road or stands in a lane (m).
CROSSING_CLEARANCE_M = 15.0
#: Background vehicles stop this far short of the road's end at the latest (m), and drive at least this fast (m/s).
ROAD_END_MARGIN_M = 15.0
MIN_BACKGROUND_SPEED_MPS = 5.0


def layers_from_text(text: str, seed: int) -> dict:
    """Parse and sample: the layers of scenario ``seed`` of ``text``. The reading is kept for the next
    seeds of the same text (a checker samples each description several times; reading is the slow
    part and depends on the text alone); each sample gets its own copy of it."""
    return sample_layers(copy.deepcopy(_kept_reading(text)), text, seed)


@lru_cache(maxsize=64)
def _kept_reading(text: str) -> Reading:
    return read(text)
