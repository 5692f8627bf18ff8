"""``describe``: a description (or layers JSON) → a batch of scenarios, run, scored and refined.

The library behind ``vei describe``. Per scenario ``i`` of a batch: layers from the backend (the
rules backend with seed ``seed·1000 + i``), validated against ``schemas/layers.schema.json``,
written as OpenSCENARIO + OpenDRIVE, run closed loop at the layers' rate and scored
(:mod:`~vei_scenario.language.evaluation`); with ``refine``, adjusted towards the description's
intent and run again, up to five episodes (:mod:`~vei_scenario.language.refinement`). Scenarios
run in parallel worker processes; everything is rendered first and written together.
"""

from __future__ import annotations

import csv
import io
import multiprocessing
import os
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from vei_scenario.atomic_io import OutputSet, json_text
from vei_scenario.errors import VeiInputError
from vei_scenario.language.evaluation import evaluate, intent_met
from vei_scenario.language.layers import behaviour_nodes, validate_layers
from vei_scenario.language.refinement import MAX_EPISODES, adjust
from vei_scenario.language.scenario_writer import DEFAULT_RATE_HZ, write_scenario

SCENARIO_STEM = "scenario"


@dataclass
class ScenarioRecord:
    index: int
    layers: dict
    files: dict[str, bytes]
    outcome: dict
    episodes: list[dict]
    #: Why the scenario could not be written (its layers ask for what the map cannot hold); a row of
    #: the batch with this reason, not the end of the batch.
    error: str | None = None

    @property
    def ok(self) -> bool:
        return self.error is None


def run_one(layers: dict, index: int, refine: bool) -> ScenarioRecord:
    """Write, run and score one scenario; with ``refine``, adjust and rerun until its intent is met
    or the episodes are spent."""
    episodes: list[dict] = []
    intent = layers.get("intent", "unspecified")
    kept = (layers, None)  # (the layers and files of the last episode played, which a failed step falls back to)
    with tempfile.TemporaryDirectory(prefix="vei-describe-") as tmp:
        for episode in range(MAX_EPISODES if refine else 1):
            try:
                written = write_scenario(layers, SCENARIO_STEM)
            except ValueError as exc:  # (PlacementError too): this scenario fails, the batch goes on
                if episode == 0:
                    return ScenarioRecord(index, layers, _files(None, layers), {}, [], f"{type(exc).__name__}: {exc}")
                layers, written = kept  # (a refinement step that cannot be placed: the last that could stands)
                break
            xosc = Path(tmp) / f"{SCENARIO_STEM}.xosc"
            (Path(tmp) / f"{SCENARIO_STEM}.xodr").write_bytes(written.xodr)
            xosc.write_bytes(written.xosc)
            try:
                outcome = evaluate(xosc, float(layers.get("rate_hz", DEFAULT_RATE_HZ)))
            except VeiInputError as exc:  # (one the player cannot play fails with its files kept; the batch goes on)
                if episode == 0:
                    where = f"{exc.where}: " if exc.where else ""
                    named = Path(exc.file).name if exc.file else f"{SCENARIO_STEM}.xosc"  # (its road file, maybe)
                    reason = f"could not be played: {named}: {where}{exc.reason}"
                    return ScenarioRecord(index, layers, _files(written, layers), {}, [], reason)
                layers, written = kept  # (a refinement step that cannot be played: the last that could stands)
                break
            kept = (layers, written)
            met, direction = intent_met(intent, outcome)
            episodes.append(
                {
                    "episode": episode + 1,
                    "configuration": [
                        {
                            "adversary": a["name"],
                            "spawn": a["spawn"],
                            "speed_mps": a.get("speed_mps"),
                            "behaviour": a["behaviour"],
                        }
                        for a in layers["adversaries"]
                    ],
                    "passed_first": outcome["passed_first"],
                    "ego_collided": outcome["ego_collided"],
                    "act_min_s": outcome["act_min_s"],
                    "intent_met": met,
                    "adjustment": direction or None,
                }
            )
            if met or not refine or episode == MAX_EPISODES - 1:
                break
            layers = adjust(layers, direction, episode, episodes)
    return ScenarioRecord(index, layers, _files(written, layers), outcome, episodes)


def _files(written, layers: dict) -> dict[str, bytes]:
    """A scenario's files by name: its OpenSCENARIO and OpenDRIVE (none where it could not be written:
    ``written`` None), and the layers they were written from."""
    files = {} if written is None else {f"{SCENARIO_STEM}.xosc": written.xosc, f"{SCENARIO_STEM}.xodr": written.xodr}
    files["layers.json"] = (json_text(layers, indent=2, sort_keys=False) + "\n").encode()
    return files


def _work(args) -> ScenarioRecord:
    layers, index, refine = args
    return run_one(layers, index, refine)


#: The longest one scenario may take in a worker (s) before the batch stops with one line.
WATCHDOG_S = 600.0


def _guarded_work(args) -> tuple[str, object]:
    """``_work`` in a worker process: its outcome or its error as plain values, so that whatever
    goes wrong reaches the parent as one message and never stalls the pool."""
    try:
        return "ok", _work(args)
    except VeiInputError as exc:
        return "input", (str(exc.file) if exc.file else None, exc.where, exc.reason)
    except Exception as exc:  # noqa: BLE001 - reported in the parent, with the scenario's index
        return "bug", f"{type(exc).__name__}: {exc}"


def batch_summary(records: list[ScenarioRecord]) -> dict:
    failed = [r for r in records if not r.ok]
    records = [r for r in records if r.ok]
    n = len(records)
    acts = [r.outcome["act_min_s"] for r in records if r.outcome["act_min_s"] is not None]
    comforts = [r.outcome["comfort"] for r in records if r.outcome["comfort"] is not None]
    eis = [r.outcome["ei_max_mps"] for r in records]
    crashes = sum(r.outcome["ego_collided"] for r in records)
    stated = [r for r in records if r.layers.get("intent", "unspecified") != "unspecified"]
    return {
        "scenarios": n,
        "crash_rate": round(crashes / n, 4) if n else None,
        "crashes": crashes,
        "mean_min_act_s": round(sum(acts) / len(acts), 4) if acts else None,
        "mean_comfort": round(sum(comforts) / len(comforts), 4) if comforts else None,
        "mean_max_ei_mps": round(sum(eis) / len(eis), 4) if eis else None,
        # (only where an intent was stated: with none, nothing can be met)
        "intent_met": sum(r.episodes[-1]["intent_met"] for r in stated) if stated else None,
        "intent_stated": len(stated),
        "episodes_run": sum(len(r.episodes) for r in records),
        "failed": len(failed),
    }


COLUMNS = [
    "scenario",
    "seed",
    "map",
    "weather",
    "ego_speed_mps",
    "behaviours",
    "ego_collided",
    "collided_with",
    "act_min_s",
    "ei_max_mps",
    "min_ttc_s",
    "alert_time_s",
    "comfort",
    "episodes",
    "intent_met",
    "error",
]


def _row(r: ScenarioRecord) -> dict:
    o, lay = r.outcome, r.layers
    if not r.ok:
        o = {"collided_with": [], "ego_collided": None}

    def names(topology: dict) -> list[str]:
        return [node["behaviour"] for _, node in behaviour_nodes(topology)]

    return {
        "scenario": f"scenario_{r.index:03d}",
        "seed": lay.get("seed"),
        "map": lay["environment"]["map"]["kind"],
        "weather": lay["environment"]["weather"]["condition"],
        "ego_speed_mps": lay["ego"]["speed_mps"],
        "behaviours": " ".join(f"{a['name']}:{'+'.join(names(a['behaviour']))}" for a in lay["adversaries"]),
        "ego_collided": o["ego_collided"],
        "collided_with": " ".join(o["collided_with"]),
        "act_min_s": o.get("act_min_s"),
        "ei_max_mps": o.get("ei_max_mps"),
        "min_ttc_s": o.get("min_ttc_s"),
        "alert_time_s": o.get("alert_time_s"),
        "comfort": o.get("comfort"),
        "episodes": len(r.episodes),
        "intent_met": r.episodes[-1]["intent_met"]
        if r.episodes and lay.get("intent", "unspecified") != "unspecified"
        else None,
        "error": r.error,
    }


def batch_csv(records: list[ScenarioRecord]) -> str:
    buf = io.StringIO()
    w = csv.DictWriter(buf, COLUMNS, lineterminator="\n")
    w.writeheader()
    for r in records:
        w.writerow({k: ("" if v is None else v) for k, v in _row(r).items()})
    return buf.getvalue()


def batch_document(
    description: str, backend: str, seed: int, refine: bool, records: list[ScenarioRecord], reading: dict | None = None
) -> dict:
    """The batch as batch.json holds it; ``reading`` (:func:`~vei_scenario.language.reading.reading_document`)
    is what the reader understood of the description, when a reader read it."""
    return {
        "description": description,
        "backend": backend,
        **({"reading": reading} if reading is not None else {}),
        "seed": seed,
        "refine": refine,
        # the step the scenarios were run and scored at: vei run's default, so it gives the same run
        "rate_hz": sorted({float(r.layers.get("rate_hz", DEFAULT_RATE_HZ)) for r in records}),
        "summary": batch_summary(records),
        "scenarios": [
            {**_row(r), "collisions": r.outcome.get("collisions", []), "episodes": r.episodes} for r in records
        ],
    }


def describe_batch(
    make_layers: Callable[[int], dict],
    count: int,
    out_dir: Path | None,
    description: str,
    backend: str,
    seed: int,
    refine: bool = False,
    jobs: int | None = None,
    progress: Callable[[int, int], None] | None = None,
    reading: dict | None = None,
) -> tuple[list[ScenarioRecord], dict]:
    """Generate, run and score ``count`` scenarios (layers of scenario i: ``make_layers(i)``), and write
    them to ``out_dir`` (where given) when at least one could be written: a batch of which none could
    is a failure, which leaves no output behind."""
    all_layers = []
    for i in range(count):
        layers = make_layers(i)
        validate_layers(layers, f"scenario {i}")
        all_layers.append(layers)
    tasks = [(layers, i, refine) for i, layers in enumerate(all_layers)]
    jobs = jobs or min(len(tasks), os.cpu_count() or 1)
    records: list[ScenarioRecord] = []
    if jobs > 1 and len(tasks) > 1:
        with multiprocessing.get_context("fork").Pool(jobs) as pool:
            results = pool.imap(_guarded_work, tasks)
            for task in tasks:
                try:  # the watchdog: a worker that never answers (killed, stuck) stops the batch with one line
                    kind, value = results.next(timeout=WATCHDOG_S)
                except multiprocessing.TimeoutError:
                    raise VeiInputError(
                        None, f"scenario {task[1]}", f"no result from its worker within {WATCHDOG_S:g} s"
                    ) from None
                if kind == "input":
                    raise VeiInputError(*value)
                if kind == "bug":
                    raise VeiInputError(None, f"scenario {task[1]}", f"could not be generated ({value})")
                rec = value
                records.append(rec)
                if progress:
                    progress(len(records), len(tasks))
    else:
        for t in tasks:
            records.append(_work(t))
            if progress:
                progress(len(records), len(tasks))
    doc = batch_document(description, backend, seed, refine, records, reading)
    if out_dir is not None and any(r.ok for r in records):  # (a batch of which none was written failed: no output)
        from vei_scenario.language.report_html import summary_html

        files = OutputSet()
        for r in records:
            for name, data in r.files.items():
                files.add(out_dir / f"scenario_{r.index:03d}" / name, data)
            if refine:
                files.add(out_dir / f"scenario_{r.index:03d}" / "episodes.json", json_text(r.episodes, indent=2) + "\n")
        files.add(out_dir / "batch.csv", batch_csv(records))
        files.add(out_dir / "batch.json", json_text(doc, indent=2) + "\n")
        files.add(out_dir / "summary.html", summary_html(doc))
        files.commit()
    return records, doc
