"""The refinement loop: compare a scenario's outcome with the description's intent and adjust the
behaviours' configuration, up to ``MAX_EPISODES`` runs per scenario, recording every episode.

Adjusting moves every configurable value of an adversary's behaviours a fraction of the way towards
the middle of the behaviour's ``safe`` profile (soften) or its ``dangerous`` profile (sharpen), and
re-places the adversary from the new configuration (a cut-in's spawn follows its gap). The fraction
grows with the episode, so a scenario far from its intent still gets there within the budget.
"""

from __future__ import annotations

import copy

from vei_scenario.language.behaviours import BEHAVIOURS
from vei_scenario.language.layers import behaviour_nodes
from vei_scenario.language.rules_backend import place_adversary

MAX_EPISODES = 5
#: Share of the way to the target profile's middle moved per episode (episode 1, 2, ...).
STEP_FRACTIONS = (0.3, 0.4, 0.5, 0.6, 0.7)


def adjust(layers: dict, direction: str, episode: int) -> dict:
    """A copy of ``layers`` moved one episode's step in ``direction`` (``soften``/``sharpen``)."""
    out = copy.deepcopy(layers)
    frac = STEP_FRACTIONS[min(episode, len(STEP_FRACTIONS) - 1)]
    target = "safe" if direction == "soften" else "dangerous"
    for adv in out["adversaries"]:
        first = None
        for _, node in behaviour_nodes(adv["behaviour"]):
            mod = BEHAVIOURS[node["behaviour"]]
            ranges = mod.PROFILES.get(target, {})
            cfg = node.setdefault("config", {})
            for name, (lo, hi) in ranges.items():
                p = mod.PARAMETERS[name]
                now = float(cfg.get(name, p.default))
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
