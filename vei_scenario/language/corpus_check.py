"""Descriptions with expectations: does a backend understand them, and are the layers it writes faithful?

A corpus file (``vei-language-corpus/1``) lists cases: a description and what a reader of it expects —
the map, weather, time of day, traffic, lanes, the ego's speed and route, the intent, and each
adversary (its type, the behaviours it may show, where it starts, its stated speed and gap, the
criticality its wording gives). A case is *understood* when the backend reads it without refusing,
and *faithful* when every stated expectation holds in the layers of each seed checked. The
expectations are deliberately about meaning, not about vei's wording, so a corpus written by someone
who never read the parser measures the parser.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from pathlib import Path
from types import SimpleNamespace

from vei_scenario.language.behaviours.run_red_light import passes_by
from vei_scenario.language.layers import behaviour_nodes

FORMAT = "vei-language-corpus/1"
#: Hours a time-of-day word covers (start, end), for the ``time`` expectation.
TIME_WINDOWS = {"night": (21, 5), "morning": (6, 11), "afternoon": (12, 17), "evening": (18, 22), "dusk": (18, 21)}


@dataclass
class CaseResult:
    text: str
    understood: bool
    faithful: bool
    problems: list[str] = field(default_factory=list)


def load_corpus(path: Path) -> list[dict]:
    from vei_scenario.clip.loader import read_json
    from vei_scenario.errors import VeiInputError

    doc = read_json(path)
    if not isinstance(doc, dict) or doc.get("format") != FORMAT or not isinstance(doc.get("cases"), list):
        raise VeiInputError(path, "format", f"not a {FORMAT} document")
    return doc["cases"]


def _near(value: float, expected: float, tol: float) -> bool:
    return abs(value - expected) <= tol


#: Moves out of going along the road: along_road before one is judged only until it starts.
_OUT_OF_ALONG = frozenset(("cut_in", "cross_in_front", "change_lane"))
#: Sideways drift (m) from where it started that marks a road user going along as moving out.
_MOVED_OUT_M = 0.3
#: How far (m) a road user going along before it moves out must go along first.
_ALONG_FIRST_M = 1.0


def _before_moving_out(lat, turned):
    """The samples before a road user going along the road moves out: before its lateral offset
    ``lat`` first strays :data:`_MOVED_OUT_M` from its start or it first turns off the road's way
    (``turned``, per sample)."""
    import numpy as np

    out = (np.abs(lat - lat[0]) > _MOVED_OUT_M) | turned
    first = int(np.argmax(out)) if out.any() else len(lat)
    return np.arange(len(lat)) < first


def _actor_problems(adv: dict, want: dict) -> list[str]:
    """Why adversary ``adv`` (layers) does not fit expectation ``want`` (empty: it fits)."""
    out = []
    if adv["type"] != want["type"]:  # (its other keys are still worth saying: a wrong type is one miss of several)
        out.append(f"type {adv['type']} (expected {want['type']})")
    nodes = [node for _, node in behaviour_nodes(adv["behaviour"])]
    names = [n["behaviour"] for n in nodes]
    allowed = want.get("behaviours")  # left out where the text does not settle what it does
    if allowed is None:
        pass
    elif want.get("all"):
        it = iter(names)  # every expected behaviour, in the order given
        if not all(any(b == x for x in it) for b in allowed):
            out.append(f"behaviours {names} (expected all of {allowed} in order)")
    elif not names or not set(names) <= set(allowed):
        out.append(f"behaviours {names} (expected among {allowed})")
    relation = adv["spawn"].get("relation")
    said = {relation}
    lateral = float(adv["spawn"].get("lateral_m", 0.0))
    if names[:1] == ["along_road"] and relation == "ahead" and lateral:
        # a walker or rider going along the road starts ahead at the edge of the ego's lane (lateral_m
        # left of its centre): on the kerb side the format calls roadside_left / roadside_right
        said.add("roadside_left" if lateral > 0 else "roadside_right")
    if relation == "ahead" and adv["spawn"].get("facing") == "against":
        said.add("oncoming")  # (ahead in the ego's lane, facing it: it comes from the opposite direction)
    accepted = set(want.get("relation", ()))
    if "oncoming" in accepted:  # at a junction what comes towards the ego starts on the opposite arm
        accepted.add("junction_opposite")
    if "relation" in want and not said & accepted:
        out.append(f"relation {relation} (expected {' or '.join(want['relation'])})")
    if "speed_kph" in want:  # its speed, or the speed it crosses at
        speeds = [float(adv["speed_mps"])] + [
            float(n["config"]["crossing_speed_mps"]) for n in nodes if "crossing_speed_mps" in n.get("config", {})
        ]
        if not any(_near(v * 3.6, want["speed_kph"], 1.0) for v in speeds):
            out.append(f"speed {[round(v * 3.6, 1) for v in speeds]} km/h (expected {want['speed_kph']})")
    if "gap_m" in want:
        gaps = [abs(float(adv["spawn"].get("longitudinal_m", float("nan"))))]
        gaps += [float(n["config"][k]) for n in nodes for k in ("gap_m", "distance_m") if k in n.get("config", {})]
        if not any(_near(g, want["gap_m"], 1.0) for g in gaps):
            out.append(f"gap {gaps} (expected {want['gap_m']} m)")
    if "criticality" in want:
        # (behaviours without criticality profiles, e.g. stop, carry none)
        classes = {n["config"]["criticality"] for n in nodes if "criticality" in n.get("config", {})}
        if classes != {want["criticality"]}:
            out.append(f"criticality {sorted(map(str, classes))} (expected {want['criticality']})")
    return out


def _scenery(adv: dict) -> bool:
    """Whether adversary ``adv`` is scenery that does not act: standing still and doing nothing,
    wherever it stands (a car parked at the kerb, a broken-down lorry in the lane that a cut-out
    reveals). The format lists road users "not parked scenery unless it acts"; a standing vehicle
    does not act, in a lane or beyond the kerb."""
    names = {node["behaviour"] for _, node in behaviour_nodes(adv["behaviour"])}
    return float(adv.get("speed_mps", 0.0)) == 0.0 and names <= {"keep_going", "stop", "keep_lane"}


def layers_problems(layers: dict, case: dict) -> list[str]:
    """Every expectation of ``case`` that ``layers`` does not meet."""
    env = layers["environment"]
    out = []
    if "map" in case and env["map"]["kind"] != case["map"]:
        out.append(f"map {env['map']['kind']} (expected {case['map']})")
    if "lanes" in case and env["map"].get("lanes_per_direction") != case["lanes"]:
        out.append(f"lanes {env['map'].get('lanes_per_direction')} (expected {case['lanes']})")
    if "weather" in case and env["weather"]["condition"] != case["weather"]:
        out.append(f"weather {env['weather']['condition']} (expected {case['weather']})")
    if "density" in case and env["traffic_density"] != case["density"]:
        out.append(f"traffic {env['traffic_density']} (expected {case['density']})")
    if "time" in case:
        hour = int(str(env["time_of_day"]).split(":")[0])
        lo, hi = TIME_WINDOWS[case["time"]]
        if not (lo <= hour <= hi if lo <= hi else hour >= lo or hour <= hi):
            out.append(f"time {env['time_of_day']} (expected {case['time']})")
    ego = layers["ego"]
    if "ego_speed_kph" in case and not _near(float(ego["speed_mps"]) * 3.6, case["ego_speed_kph"], 1.0):
        out.append(f"ego speed {float(ego['speed_mps']) * 3.6:.1f} km/h (expected {case['ego_speed_kph']})")
    if "ego_route" in case and ego.get("route") != case["ego_route"]:
        out.append(f"ego route {ego.get('route')} (expected {case['ego_route']})")
    if "intent" in case and layers.get("intent") != case["intent"]:
        out.append(f"intent {layers.get('intent')} (expected {case['intent']})")
    advs, wants = layers["adversaries"], case["actors"]
    if len(advs) > len(wants) and not any(w.get("speed_kph") == 0 for w in wants):
        # parked scenery (standing at the kerb, doing nothing) is not among the road users a case lists
        # ("not parked scenery unless it acts"); a scenario may still hold it, as the occluder it is
        acting = [a for a in advs if not _scenery(a)]
        advs = acting if len(acting) >= len(wants) else advs
    if len(advs) != len(wants):
        kinds = [a["type"] for a in advs]
        out.append(f"{len(advs)} adversaries {kinds} (expected {len(wants)}: {[w['type'] for w in wants]})")
    return out + _best_pairing(advs, wants)


def _best_pairing(advs: list[dict], wants: list[dict]) -> list[str]:
    """The problems of the pairing of adversaries with expected actors that has the fewest; where the
    counts differ, the unpaired ones are the count's miss, said already, and the paired ones are still
    checked, so that a miss lists all it gets wrong."""
    if not advs or not wants:
        return []
    best: list[str] | None = None
    if len(advs) >= len(wants):  # (a corpus case names a few actors at most; a reading rarely invents many)
        pairings = (
            (zip(wants, (advs[k] for k in order))) for order in itertools.permutations(range(len(advs)), len(wants))
        )
    else:
        pairings = (
            (zip((wants[k] for k in order), advs)) for order in itertools.permutations(range(len(wants)), len(advs))
        )
    for pairs in itertools.islice(pairings, 50_000):
        found = [p for w, a in pairs for p in _actor_problems(a, w)]
        if best is None or len(found) < len(best):
            best = found
        if not found:
            break
    return best or []


def check_case(case: dict, make_layers, seeds=(0, 1, 2)) -> CaseResult:
    """Understood and faithful? ``make_layers(text, seed)`` returns layers or raises ValueError (the
    backend's refusal, e.g. :class:`~vei_scenario.language.reading.NotUnderstood`)."""
    text = case["text"]
    problems: list[str] = []
    for seed in seeds:
        try:
            layers = make_layers(text, seed)
        except ValueError as exc:
            return CaseResult(text, False, False, [str(exc)])
        problems += [p for p in layers_problems(layers, case) if p not in problems]
    return CaseResult(text, True, not problems, problems)


def check_corpus(cases: list[dict], make_layers, seeds=(0, 1, 2)) -> list[CaseResult]:
    return [check_case(c, make_layers, seeds) for c in cases]


def _ego_frame(result, name: str):
    """(longitudinal, lateral) of ``name`` in the ego's frame at every step (m)."""
    import numpy as np

    ego, tr = result.traces[result.ego], result.traces[name]
    dx, dy = tr.x - ego.x, tr.y - ego.y
    c, s = np.cos(ego.yaw), np.sin(ego.yaw)
    return dx * c + dy * s, -dx * s + dy * c


#: How far a red-light runner goes at the least, in a run's span (m): through a junction.
_RUNS_AT_LEAST_M = 10.0


def played_problems(result, layers: dict) -> list[str]:
    """Did each adversary do what its layers say, in the played run? Checked from the trajectories:
    a stop ends standing, an overtake ends ahead of the ego, a cut-in ends ahead in the ego's lane,
    a crossing passes the ego's path (or is hit in it), a red-light run or a turn across comes within
    3 m of the ego's path (for an ego that stands, the way it stands to go; not a run the text sends
    straight on past the ego from the opposite arm), a road user giving way
    stands and is not hit, one going along the road keeps to the ego's lane in its direction (while
    both are on the ego's road), a wrong-way driver is head-on on the ego's path, an oncoming one faces
    the ego when they meet; and no background vehicle collides."""
    import numpy as np

    out = []
    ego = result.traces[result.ego]
    way = _ego_way(ego, layers)
    on_own_road = np.ones(len(ego.x), dtype=bool)
    if "route" in layers["ego"] and "distance_m" in layers["ego"]:
        # through a junction or roundabout: the ego is on its own road until it has driven the
        # distance_m it started before the junction (from there on its frame is other roads')
        travelled = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(ego.x), np.diff(ego.y)))])
        on_own_road = travelled < float(layers["ego"]["distance_m"])
    for t, a, b in result.collisions:  # background traffic keeps to its lanes and out of the way
        if a.startswith("Background") or b.startswith("Background"):
            out.append(f"background collision of {a} and {b} at {t:.1f} s")
    for adv in layers["adversaries"]:
        name = adv["name"]
        if name not in result.traces:
            out.append(f"{name}: not in the run")
            continue
        tr = result.traces[name]
        lon, lat = _ego_frame(result, name)
        names = [n["behaviour"] for _, n in behaviour_nodes(adv["behaviour"])]
        last = names[-1]
        if last in ("sudden_stop", "stop") and abs(float(tr.speed[-1])) > 0.5:
            out.append(f"{name}: {last} but still at {float(tr.speed[-1]):.1f} m/s at the end")
        if "overtake" in names and not (lon > 0).any():
            out.append(f"{name}: overtake but never ahead of the ego")
        if "cut_in" in names and not ((lon > 0) & (np.abs(lat) < 1.2)).any():
            out.append(f"{name}: cut_in but never ahead in the ego's lane")
        behind_ok = "give_way" in names  # after giving way it crosses behind the ego
        where = lat if behind_ok else lat[lon > -2.0]
        hit_ego = any({name, result.ego} == {a, b} for _, a, b in result.collisions)
        # (one the ego hits has come into its path: that is the crossing, cut short)
        if "cross_in_front" in names and not hit_ego and not (np.sign(where) != np.sign(lat[0])).any():
            out.append(f"{name}: cross_in_front but never across the ego's path")
        to_path = (
            _nearest_on_path(tr, way)
            if {"run_red_light", "turn_across", "turn_into", "wrong_way"} & set(names)
            else None
        )
        runs = [n.get("config", {}) for _, n in behaviour_nodes(adv["behaviour"]) if n["behaviour"] == "run_red_light"]
        route = str(layers["ego"].get("route", "straight"))
        for crossing in ("run_red_light", "turn_across", "turn_into"):
            if crossing == "run_red_light" and runs and passes_by(adv["spawn"]["relation"], runs[0].get("turn"), route):
                continue  # (sent straight on past the ego by the text: side by side, not across its path)
            if crossing in names:
                d = float(to_path[0].min())
                if d > 3.0:
                    out.append(f"{name}: {crossing} but never within 3 m of the ego's path ({d:.1f} m)")
        if "run_red_light" in names and float(np.hypot(np.ptp(tr.x), np.ptp(tr.y))) < _RUNS_AT_LEAST_M:
            out.append(f"{name}: run_red_light but never set off")
        if "turn_into" in names and not ((lon > 0) & (np.abs(lat) < 1.2)).any():
            out.append(f"{name}: turn_into but never ahead in the ego's lane")
        heading = np.abs((tr.yaw - ego.yaw + np.pi) % (2 * np.pi) - np.pi)  # 0: same way, pi: head-on
        if "give_way" in names:
            hit = any({name, result.ego} == {a, b} for _, a, b in result.collisions)
            if hit or not (np.abs(tr.speed) < 0.3).any():
                out.append(f"{name}: give_way but {'hit the ego' if hit else 'never stood to let the ego pass'}")
        if names[0] == "along_road":
            facing = adv["spawn"].get("facing", "with")
            want = np.pi if facing == "against" else 0.0
            # along the ego's road: judged while both are on it, i.e. before a route through a
            # junction or roundabout takes either off it (after that the ego's frame is another road's)
            on_road = on_own_road.copy()
            if "route" in layers["ego"] and "distance_m" in layers["ego"] and facing == "with":
                travelled = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(tr.x), np.diff(tr.y)))])
                on_road &= travelled < float(layers["ego"]["distance_m"]) - float(lon[0])
            moves_out = names[1:2] and names[1] in _OUT_OF_ALONG
            if moves_out:  # (judged as it goes along, before it moves out)
                on_road &= _before_moving_out(lat, np.abs(heading - want) > 0.35)
            moving = (np.abs(tr.speed) > 0.3) & on_road
            if moves_out:  # (and it goes along some way before it does)
                steps = np.hypot(np.diff(tr.x), np.diff(tr.y))[moving[1:]]
                moving &= bool(steps.sum() >= _ALONG_FIRST_M)
            ahead = (lon > 0) & on_road
            if (
                not moving.any()
                or np.abs(heading[moving] - want).max() > 0.35
                or np.ptp(lat[ahead] if ahead.any() else lat[on_road]) > 1.5
            ):
                out.append(f"{name}: along_road but not moving along the ego's lane ({facing} the traffic)")
        if "wrong_way" in names:
            # on the ego's path (within 1.5 m of where the ego drives, at any time) and facing against it
            d, k = to_path
            against = np.abs((tr.yaw - way.yaw[k] + np.pi) % (2 * np.pi) - np.pi) > 2.6
            if not ((d < 1.5) & against & (np.abs(tr.speed) > 0.5)).any():
                out.append(f"{name}: wrong_way but never head-on in the ego's lane")
        if "cut_out" in names and not (np.abs(lat) > 2.5).any():
            out.append(f"{name}: cut_out but never out of the ego's lane")
        closest = int(np.argmin(np.hypot(tr.x - ego.x, tr.y - ego.y)))
        if adv["spawn"].get("relation") == "oncoming" and float(adv["speed_mps"]) > 0.5 and heading[closest] < 2.6:
            out.append(f"{name}: oncoming but driving the ego's way")
    return out


#: An ego that moves less than this (m) in the run is standing: its path is then the way it stands to go.
_STANDING_M = 1.0
#: How far ahead (m) the way of a standing ego is taken, beyond the distance to its junction.
_STANDING_WAY_M = 30.0


def _ego_way(ego, layers: dict):
    """The ego's path for the checks of who comes onto it: the points it passes through, or, for an
    ego that stands (waiting at the lights), the way it stands to go, straight on from where it stands
    through its junction. Why: a road user running the red in front of a standing ego crosses where
    the ego would drive, never the one point the ego stood on."""
    import numpy as np

    if float(np.hypot(ego.x[-1] - ego.x[0], ego.y[-1] - ego.y[0])) >= _STANDING_M:
        return ego
    reach = float(layers["ego"].get("distance_m", 0.0)) + _STANDING_WAY_M
    ahead = np.arange(0.0, reach, 0.25)
    yaw = float(ego.yaw[0])
    return SimpleNamespace(
        x=ego.x[0] + ahead * np.cos(yaw), y=ego.y[0] + ahead * np.sin(yaw), yaw=np.full(len(ahead), yaw)
    )


def _nearest_on_path(tr, ego, rows: int = 512):
    """For every sample of trace ``tr``: the distance to the nearest point the ego passes through
    during the run, and that point's index (computed a block of rows at a time, so a long run does
    not ask for a samples² matrix at once)."""
    import numpy as np

    dist = np.empty(len(tr.x))
    idx = np.empty(len(tr.x), dtype=int)
    for lo in range(0, len(tr.x), rows):
        d = np.hypot(tr.x[lo : lo + rows, None] - ego.x[None, :], tr.y[lo : lo + rows, None] - ego.y[None, :])
        k = np.argmin(d, axis=1)
        idx[lo : lo + rows] = k
        dist[lo : lo + rows] = d[np.arange(len(k)), k]
    return dist, idx


def play_case(case: dict, make_layers, workdir: Path, seed: int = 0) -> list[str]:
    """Write the scenario of ``case`` (seed ``seed``), play it with ``vei run``'s interpreter, and
    return what its adversaries did not do (:func:`played_problems`); a scenario that cannot be
    written returns that reason as its one problem."""
    from vei_scenario.interpreter import run_scenario
    from vei_scenario.language.scenario_writer import write_scenario

    layers = make_layers(case["text"], seed)
    try:
        written = write_scenario(layers, "scenario")
    except ValueError as exc:  # (a PlacementError too): nothing to play, and that is what it did not do
        return [f"could not be written: {exc}"]
    (workdir / "scenario.xosc").write_bytes(written.xosc)
    (workdir / "scenario.xodr").write_bytes(written.xodr)
    from vei_scenario.errors import VeiInputError

    try:
        result = run_scenario(workdir / "scenario.xosc", None, round(1.0 / float(layers["rate_hz"]), 6))
    except VeiInputError as exc:  # the player refuses what was written: that is what it did not do
        return [f"could not be played: {exc.reason}"]
    return played_problems(result, layers)
