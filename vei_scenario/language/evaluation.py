"""Closed-loop evaluation of a language scenario: run the written OpenSCENARIO with ``vei run``'s
interpreter and score the ego against every adversary.

Per scenario: the collision record (every pair that touched, who with whom, when), whether the ego
collided, the minimum ACT and the maximum EI over the adversaries, the minimum 2-D TTC and the time
in the TTC alert zone, and the ego's comfort. Per batch: the crash rate, the share of scenarios in
which the ego collided with anything (LinguaSim's CR).

Comfort (LinguaSim's equation is not given in the text): the share of the run in which the ego
stays within comfortable limits, |a| <= 2 m/s² and |jerk| <= 2 m/s³ (``comfort_score`` of
:mod:`vei_scenario.metrics`); 1 is a run without a single uncomfortable moment.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from vei_scenario.interpreter import run_scenario
from vei_scenario.language.scenario_writer import DEFAULT_RATE_HZ
from vei_scenario.metrics import MetricConfig, PairSeries, compute_metrics

METRIC_NAMES = ["collision", "act_min_s", "ei_max_mps", "min_ttc_s", "ttc_zones_s", "comfort_score", "min_gap_m"]
#: ACT below this (s) without a collision is a near miss ("almost hits").
NEAR_MISS_ACT_S = 1.0


def evaluate(xosc: Path, rate_hz: float = DEFAULT_RATE_HZ) -> dict:
    """Run ``xosc`` at ``rate_hz`` and score it (JSON-ready)."""
    result = run_scenario(xosc, None, round(1.0 / rate_hz, 6))
    cfg = MetricConfig()
    ego = result.ego
    adversaries = [n for n in result.traces if n.startswith("Adversary")]
    per: dict[str, dict] = {}
    for name in adversaries:
        per[name] = compute_metrics(PairSeries.from_run(result, name), cfg, METRIC_NAMES)
    acts = [m["act_min_s"] for m in per.values() if m["act_min_s"] is not None]
    eis = [m["ei_max_mps"] for m in per.values() if m["ei_max_mps"] is not None]
    ttcs = [m["min_ttc_s"] for m in per.values() if m["min_ttc_s"] is not None]
    collisions = [{"time_s": round(t, 3), "entities": [a, b]} for t, a, b in result.collisions]
    ego_hit = [c for c in collisions if ego in c["entities"]]
    # comfort is the ego's alone: any pair gives it; without an adversary, the ego with anyone
    comfort = per[adversaries[0]]["comfort_score"] if adversaries else _comfort_only(result, cfg)
    alert = sum(m["ttc_zones_s"]["alert"] + m["ttc_zones_s"]["collision"] for m in per.values())
    hit = {n for c in ego_hit for n in c["entities"] if n != ego}
    return {
        "passed_first": {n: passed_first(result, n, n in hit) for n in per},
        "ego_collided": bool(ego_hit),
        "collided_with": sorted(hit),
        "collisions": collisions,
        "act_min_s": min(acts) if acts else None,
        "ei_max_mps": max(eis) if eis else 0.0,
        "min_ttc_s": min(ttcs) if ttcs else None,
        "alert_time_s": round(alert, 3),
        "comfort": comfort,
        "duration_s": round(float(result.t[-1]), 3),
        "end_reason": result.end_reason,
        "per_adversary": per,
    }


def passed_first(result, name: str, touched: bool) -> str:
    """Who of the ego and road user ``name`` came first where their paths meet: ``contact`` when they
    touched; ``adversary`` when, at their closest approach, it is already across the ego's path or in
    it ahead; ``ego`` when it is still on the side it started from, or in the ego's path behind it.

    Refinement brackets a timing with this: between a timing at which the road user went first and one
    at which the ego did lies one at which they meet, wherever the ego's braking moved it."""
    if touched:
        return "contact"
    ego, other = result.traces[result.ego], result.traces[name]
    dx, dy = other.x - ego.x, other.y - ego.y
    k = int(np.argmin(np.hypot(dx, dy)))
    c, s = math.cos(ego.yaw[k]), math.sin(ego.yaw[k])
    lat_now = c * dy[k] - s * dx[k]
    lat_start = c * (other.y[0] - ego.y[k]) - s * (other.x[0] - ego.x[k])
    if abs(lat_now) <= (ego.width + other.width) / 2:  # in the ego's path: ahead went first
        return "adversary" if c * dx[k] + s * dy[k] > 0 else "ego"
    return "adversary" if lat_now * lat_start < 0 else "ego"


def _comfort_only(result, cfg: MetricConfig) -> float:
    names = list(result.traces)
    other = names[1] if len(names) > 1 else names[0]
    return compute_metrics(PairSeries.from_run(result, other), cfg, ["comfort_score"])["comfort_score"]


def intent_met(intent: str, outcome: dict) -> tuple[bool, str]:
    """Whether the outcome is what the description wanted, and which way to adjust when not:
    ``soften`` (less critical) or ``sharpen`` (more critical)."""
    act = outcome["act_min_s"]
    act = math.inf if act is None else act
    if intent == "near_miss":
        if outcome["ego_collided"]:
            return False, "soften"
        if act >= NEAR_MISS_ACT_S:
            return False, "sharpen"
        return True, ""
    if intent == "collision":
        return (True, "") if outcome["ego_collided"] else (False, "sharpen")
    if intent == "safe":
        ok = not outcome["ego_collided"] and outcome["alert_time_s"] == 0
        return (True, "") if ok else (False, "soften")
    return True, ""
