"""The refinement loop: compare a scenario's outcome with the description's intent and adjust the
behaviours' configuration, up to ``MAX_EPISODES`` runs per scenario, recording every episode.

Adjusting moves every configurable value of an adversary's behaviours a fraction of the way towards
the middle of the behaviour's ``safe`` profile (soften) or its ``dangerous`` profile (sharpen), and
re-places the adversary from the new configuration (a cut-in's spawn follows its gap). The fraction
grows with the episode, so a scenario far from its intent still gets there within the budget.

A value that started inside the target profile has nowhere to go towards its middle, and the run
would only repeat itself: with the ego's planner braking, a crossing timed in the middle of the
``dangerous`` profile is often avoided although a collision was asked for. Such a value is probed
on both sides of the profile instead, one and then two profile widths from its middle, first on the
side the profiles order towards (past ``dangerous`` when sharpening), then on the other: where the
outcome turns depends on how the ego brakes, which no closed form here knows (a crossing meets a
braking ego when timed early, a red-light runner when timed late).
"""

from __future__ import annotations

import copy

from vei_scenario.language.behaviours import BEHAVIOURS
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import place_adversary

MAX_EPISODES = 5
#: Share of the way to the target profile's middle moved per episode (episode 1, 2, ...).
STEP_FRACTIONS = (0.3, 0.4, 0.5, 0.6, 0.7)
#: Where a value that started inside the target profile is tried per episode: profile widths from its
#: middle, towards the side the profiles order to (+) and the other (-).
PROBES = (1.0, -1.0, 2.0, -2.0)


def adjust(layers: dict, direction: str, episode: int, start: dict | None = None) -> dict:
    """A copy of ``layers`` moved one episode's step in ``direction`` (``soften``/``sharpen``).
    ``start``: the layers of the first episode (default ``layers``), which say whether a value began
    inside the target profile and is probed around it instead."""
    out = copy.deepcopy(layers)
    frac = STEP_FRACTIONS[min(episode, len(STEP_FRACTIONS) - 1)]
    target = "safe" if direction == "soften" else "dangerous"
    began = [
        [node.get("config", {}) for _, node in behaviour_nodes(adv["behaviour"])]
        for adv in (start or layers)["adversaries"]
    ]
    for a, adv in enumerate(out["adversaries"]):
        first = None
        for b, (_, node) in enumerate(behaviour_nodes(adv["behaviour"])):
            mod = BEHAVIOURS[node["behaviour"]]
            ranges = mod.PROFILES.get(target, {})
            cfg = node.setdefault("config", {})
            for name, (lo, hi) in ranges.items():
                p = mod.PARAMETERS[name]
                now = float(cfg.get(name, p.default))
                was = float(began[a][b].get(name, p.default)) if a < len(began) and b < len(began[a]) else now
                side = _side(mod.PROFILES, name, target)
                if lo <= was <= hi and side:
                    probe = (lo + hi) / 2 + side * PROBES[min(episode, len(PROBES) - 1)] * (hi - lo)
                    cfg[name] = round(min(max(probe, p.low), p.high), 3)
                else:
                    cfg[name] = round(now + frac * ((lo + hi) / 2 - now), 3)
            first = first or (mod, cfg)
        if first is not None and "longitudinal_m" in adv["spawn"]:
            rel = adv["spawn"]["relation"]
            keep_speed = adv.get("speed_mps") if rel.startswith("junction") else None
            lanes = int(out["environment"]["map"].get("lanes_per_direction", 2))
            adv["spawn"], adv["speed_mps"] = place_adversary(
                adv["type"], rel, first[0].NAME, first[1], out["ego"], lanes, keep_speed
            )
    return out


def _side(profiles: dict, name: str, target: str) -> int:
    """+1 when the ``target`` profile of ``name`` lies above the opposite one (a deceleration when
    sharpening), -1 below it (a gap), 0 when the opposite profile does not say."""
    other = profiles.get("safe" if target == "dangerous" else "dangerous", {}).get(name)
    if other is None:
        return 0
    mid, other_mid = sum(profiles[target][name]) / 2, sum(other) / 2
    return (mid > other_mid) - (mid < other_mid)
