"""Write a generator's layers as a scenario and play it with the interpreter, as `vei describe` does,
for the tests that check a scenario does what its layers say."""

from __future__ import annotations

from pathlib import Path

from vei_scenario.interpreter import run_scenario
from vei_scenario.language.scenario_writer import write_scenario


def play_layers(layers: dict, tmp_path: Path):
    """The run of ``layers`` written to ``tmp_path``, stepped at the layers' own rate."""
    written = write_scenario(layers, "scenario")
    (tmp_path / "scenario.xosc").write_bytes(written.xosc)
    (tmp_path / "scenario.xodr").write_bytes(written.xodr)
    return run_scenario(tmp_path / "scenario.xosc", None, round(1.0 / float(layers["rate_hz"]), 6))
