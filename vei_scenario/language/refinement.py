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

Sharpening a timing (``arrival_gap_s``: when a road user reaches the ego's path against when the ego
does) uses what the episodes so far showed: once one timing let the road user go first and another
let the ego go first, the two meet between them, and the next episode tries the middle of the
closest such pair (bisection), whatever the ego's braking did to the closed form's timing.
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


#: The timing parameter that refinement brackets, and the narrowest bracket it still halves (s).
TIMING = "arrival_gap_s"
NARROWEST_BRACKET_S = 0.05


def adjust(layers: dict, direction: str, episode: int, history: list[dict] | None = None) -> dict:
    """A copy of ``layers`` moved one episode's step in ``direction`` (``soften``/``sharpen``).
    ``history``: the episodes run so far (their configuration and who passed first): the first says
    whether a value began inside the target profile and is probed around it instead (without one,
    ``layers`` does), and together they bracket a timing when sharpening."""
    out = copy.deepcopy(layers)
    frac = STEP_FRACTIONS[min(episode, len(STEP_FRACTIONS) - 1)]
    target = "safe" if direction == "soften" else "dangerous"
    began = [
        [node.get("config", {}) for _, node in behaviour_nodes(adv["behaviour"])]
        for adv in (history[0]["configuration"] if history else layers["adversaries"])
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
                middle = _bracketed(history, adv["name"], b, p.default) if name == TIMING and b == 0 else None
                if direction == "sharpen" and middle is not None:
                    cfg[name] = round(middle, 3)
                    continue
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


def _bracketed(history: list[dict] | None, adversary: str, node: int, default: float) -> float | None:
    """The middle of the closest pair of timings tried for ``adversary`` (its behaviour ``node``) at
    which it once went first and once the ego did; None without such a pair or once it is narrower
    than :data:`NARROWEST_BRACKET_S`."""
    tried: dict[str, list[float]] = {"adversary": [], "ego": []}
    for ep in history or []:
        first = ep.get("passed_first", {}).get(adversary)
        conf = next((c for c in ep["configuration"] if c["adversary"] == adversary), None)
        if first not in tried or conf is None:
            continue
        nodes = [n for _, n in behaviour_nodes(conf["behaviour"])]
        if node < len(nodes):
            tried[first].append(float(nodes[node].get("config", {}).get(TIMING, default)))
    pairs = [(abs(a - e), (a + e) / 2) for a in tried["adversary"] for e in tried["ego"]]
    if not pairs:
        return None
    width, middle = min(pairs)
    return middle if width > NARROWEST_BRACKET_S else None
