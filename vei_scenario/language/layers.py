"""The layers document (``vei-layers/1``): its JSON Schema and the checks every backend's output
passes before a scenario is written from it."""

from __future__ import annotations

import json
from functools import lru_cache
from importlib import resources
from pathlib import Path

from vei_scenario.errors import VeiInputError
from vei_scenario.language.behaviours import BEHAVIOURS

FORMAT = "vei-layers/1"


@lru_cache(maxsize=1)
def layers_schema() -> dict:
    return json.loads(resources.files("vei_scenario").joinpath("data/layers.schema.json").read_text("utf-8"))


def _non_finite(node, where: str):
    """(path, value) of every non-finite number in a JSON document, depth-first, iteratively."""
    import math

    stack = [(node, where)]
    while stack:
        n, w = stack.pop()
        if isinstance(n, float) and not math.isfinite(n):
            yield (w or "(document)"), n
        elif isinstance(n, dict):
            stack.extend((v, f"{w}/{k}" if w else str(k)) for k, v in n.items())
        elif isinstance(n, list):
            stack.extend((v, f"{w}/{i}" if w else str(i)) for i, v in enumerate(n))


def schema_problems(doc) -> list[str]:
    """Every schema violation and unknown behaviour or parameter, as ``field: reason`` lines."""
    import jsonschema

    validator = jsonschema.Draft202012Validator(layers_schema())
    problems = [f"{where}: {v!r} is not a finite number" for where, v in _non_finite(doc, "")]
    if problems:  # (an LLM's answer or a file may hold 1e400, which reads as infinity)
        return problems
    for err in sorted(validator.iter_errors(doc), key=lambda e: list(e.absolute_path)):
        where = "/".join(str(p) for p in err.absolute_path) or "(document)"
        problems.append(f"{where}: {err.message[:300]}")
    if problems:
        return problems
    for i, adv in enumerate(doc["adversaries"]):
        for where, node in behaviour_nodes(adv["behaviour"], f"adversaries/{i}/behaviour"):
            mod = BEHAVIOURS.get(node["behaviour"])
            if mod is None:
                problems.append(
                    f"{where}/behaviour: unknown behaviour {node['behaviour']!r} (known: {', '.join(BEHAVIOURS)})"
                )
                continue
            for key, v in node.get("config", {}).items():
                if key in mod.PARAMETERS and not isinstance(v, (int, float)):
                    problems.append(f"{where}/config/{key}: {v!r} is not a number")
    names = [a["name"] for a in doc["adversaries"]]
    for i, adv in enumerate(doc["adversaries"]):
        for where, node in behaviour_nodes(adv["behaviour"], f"adversaries/{i}/behaviour"):
            if node["behaviour"] == "cut_out" and node.get("config", {}).get("obstacle") not in set(names) - {
                adv["name"]
            }:
                problems.append(f"{where}/config/obstacle: must name another adversary (what stands in the lane)")
    if len(set(names)) != len(names):
        problems.append("adversaries: names must be unique")
    if "Ego" in names:
        problems.append("adversaries: 'Ego' is the ego's name")
    return problems


def behaviour_nodes(node: dict, where: str = ""):
    """Every atomic behaviour of a topology, in order, with its JSON path below ``where``."""
    if "behaviour" in node:
        yield where, node
    for key in ("sequence", "parallel"):
        for k, child in enumerate(node.get(key, [])):
            yield from behaviour_nodes(child, f"{where}/{key}/{k}")


def validate_layers(doc, source: str | Path) -> None:
    """Raise :class:`VeiInputError` naming the first problem (and how many there are)."""
    problems = schema_problems(doc)
    if problems:
        more = f" (and {len(problems) - 1} more)" if len(problems) > 1 else ""
        field, _, reason = problems[0].partition(": ")
        raise VeiInputError(source, field, reason + more)


def load_layers(path: Path) -> dict:
    from vei_scenario.clip.loader import read_json  # (the clip loader's strict JSON reading)

    doc = read_json(path)
    validate_layers(doc, path)
    return doc
