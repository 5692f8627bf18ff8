"""The optional LLM backend: an OpenAI-compatible chat endpoint asked for the layers as structured
output (``response_format`` with the layers JSON Schema).

Works with hosted endpoints and local servers that speak the same API (llama.cpp's server, Ollama,
vLLM). URL and model come from options or ``VEI_LLM_URL`` / ``VEI_LLM_MODEL`` (and ``VEI_LLM_KEY``
for a bearer token). The answer is parsed, repaired where the repair is unambiguous (the format tag,
an absent background layer, numbers sent as strings) and validated; a still-invalid answer is sent
back once with the validator's findings, then refused with them. Nothing here runs unless asked for.
"""

from __future__ import annotations

import json
import os
import urllib.error
import urllib.request

from vei_scenario.errors import VeiInputError
from vei_scenario.language.behaviours import BEHAVIOURS
from vei_scenario.language.layers import FORMAT, layers_schema, schema_problems

TIMEOUT_S = 120.0
ATTEMPTS = 2


def system_prompt() -> str:
    lines = [
        "You turn a driving-scenario description into the JSON document the schema describes:",
        "environment, ego, adversaries (each with a behaviour topology of atomic behaviours), background.",
        "Atomic behaviours and their configuration (units in the names):",
    ]
    for name, mod in BEHAVIOURS.items():
        params = ", ".join(f"{p} [{v.low}..{v.high}]" for p, v in mod.PARAMETERS.items())
        lines.append(f"- {name}: {mod.SUMMARY} Config: {params}.")
    lines.append("Lanes count from the kerb (1 = rightmost). Answer with the JSON document only.")
    return "\n".join(lines)


def _repair(doc):
    """Unambiguous repairs of a model's answer."""
    if not isinstance(doc, dict):
        return doc
    doc.setdefault("format", FORMAT)
    doc.setdefault("background", {"vehicles": []})
    doc.setdefault("adversaries", [])
    for adv in doc.get("adversaries", []):
        if isinstance(adv, dict) and isinstance(adv.get("speed_mps"), str):
            try:
                adv["speed_mps"] = float(adv["speed_mps"])
            except ValueError:
                pass
    return doc


def _post(url: str, payload: dict, key: str | None) -> dict:
    req = urllib.request.Request(
        url.rstrip("/") + "/chat/completions",
        data=json.dumps(payload).encode(),
        headers={"Content-Type": "application/json", **({"Authorization": f"Bearer {key}"} if key else {})},
    )
    try:
        with urllib.request.urlopen(req, timeout=TIMEOUT_S) as resp:
            return json.loads(resp.read().decode("utf-8"))
    except urllib.error.HTTPError as exc:
        raise VeiInputError(url, "LLM endpoint", f"HTTP {exc.code}: {exc.reason}") from None
    except (urllib.error.URLError, TimeoutError, OSError) as exc:
        raise VeiInputError(url, "LLM endpoint", f"not reachable: {getattr(exc, 'reason', exc)}") from None
    except json.JSONDecodeError:
        raise VeiInputError(url, "LLM endpoint", "the answer is not JSON") from None


def layers_from_llm(text: str, seed: int, url: str | None = None, model: str | None = None) -> dict:
    """Ask the endpoint for the layers of ``text``; validated (or refused with the reasons)."""
    url = url or os.environ.get("VEI_LLM_URL")
    model = model or os.environ.get("VEI_LLM_MODEL")
    if not url or not model:
        raise VeiInputError(None, "--backend llm", "needs --llm-url and --llm-model (or VEI_LLM_URL / VEI_LLM_MODEL)")
    messages = [{"role": "system", "content": system_prompt()}, {"role": "user", "content": text}]
    problems: list[str] = []
    for _ in range(ATTEMPTS):
        payload = {
            "model": model,
            "messages": messages,
            "seed": seed,
            "temperature": 0.7,
            "response_format": {
                "type": "json_schema",
                "json_schema": {"name": "vei_layers", "schema": layers_schema()},
            },
        }
        answer = _post(url, payload, os.environ.get("VEI_LLM_KEY"))
        try:
            content = answer["choices"][0]["message"]["content"]
        except (KeyError, IndexError, TypeError):
            raise VeiInputError(url, "LLM answer", "no choices[0].message.content in the answer") from None
        try:
            doc = _repair(json.loads(content))
        except json.JSONDecodeError as exc:
            problems = [f"(answer): not JSON ({exc.msg})"]
        else:
            doc_problems = schema_problems(doc)
            if not doc_problems:
                doc["description"] = text
                doc["seed"] = seed
                return doc
            problems = doc_problems
        messages = messages + [
            {"role": "assistant", "content": content if isinstance(content, str) else json.dumps(content)},
            {
                "role": "user",
                "content": "The document does not validate:\n" + "\n".join(problems[:20]) + "\nAnswer again.",
            },
        ]
    raise VeiInputError(url, "LLM answer", f"refused after {ATTEMPTS} attempts: " + "; ".join(problems[:3]))
