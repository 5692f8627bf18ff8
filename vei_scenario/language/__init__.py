"""Language → interactive scenario (the LinguaSim method).

Pipeline: description → backend (``rules_backend`` offline and seeded, ``llm_backend`` optional, or
layers JSON edited by hand) → layers (``layers``: environment, ego, adversaries with behaviour
topologies, background; JSON Schema ``schemas/layers.schema.json``) → ``scenario_writer`` (maps,
placement, ``behaviours``) → OpenSCENARIO + OpenDRIVE → ``evaluation`` (closed-loop run, EI, ACT,
comfort, collisions) → ``refinement`` → ``describe`` (batches, CSV/JSON, HTML).
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

from vei_scenario.errors import VeiInputError


def describe_command(args) -> int:
    """``vei describe``: the CLI layer over :func:`vei_scenario.language.describe.describe_batch`."""
    from vei_scenario.language.describe import describe_batch
    from vei_scenario.language.layers import load_layers
    from vei_scenario.language.placement import PlacementError
    from vei_scenario.language.reading import NotUnderstood, reading_document, reading_lines
    from vei_scenario.language.rules_backend import read, sample_layers

    if (args.text is None) == (args.layers is None):
        raise VeiInputError(None, "vei describe", "give either a description or --layers FILE")
    if not 1 <= args.count <= 10000:
        raise VeiInputError(None, "--count", f"{args.count} is outside 1..10000")
    if args.seed < 0:
        raise VeiInputError(None, "--seed", "must be non-negative")
    out = Path(args.output)
    if args.text is not None:
        from vei_scenario.language.description_text import readable_description

        args.text = readable_description(args.text)
    read_doc = None
    notes: list[str] = []  # what the text states that a scenario could not keep, and why (the rules backend's)
    if args.layers is not None:
        fixed = load_layers(Path(args.layers))
        count, text, backend = 1, fixed.get("description", ""), "layers"

        def make(i: int) -> dict:
            return fixed

    elif args.backend == "local":
        from vei_scenario.language.local_llm import layers_from_local_model

        count, text, backend = args.count, args.text, "local"

        def make(i: int) -> dict:
            return layers_from_local_model(text, args.seed * 1000 + i, args.llm_model)

    elif args.backend == "llm":
        from vei_scenario.language.llm_backend import layers_from_llm

        count, text, backend = args.count, args.text, "llm"

        def make(i: int) -> dict:
            return layers_from_llm(text, args.seed * 1000 + i, args.llm_url, args.llm_model)

    else:
        count, text, backend = args.count, args.text, "rules"
        try:
            reading = read(text)
        except NotUnderstood as exc:
            raise VeiInputError(None, "description", str(exc)) from None
        read_doc = reading_document(reading)
        for line in reading_lines(reading):  # what was read, before anything is generated from it
            print(line)

        def make(i: int) -> dict:
            return sample_layers(reading, text, args.seed * 1000 + i, notes)

    if args.layers_only:
        from vei_scenario.atomic_io import OutputSet, json_text
        from vei_scenario.language.layers import validate_layers

        files = OutputSet()
        for i in range(count):
            layers = make(i)
            validate_layers(layers, f"scenario {i}")
            files.add(out / f"scenario_{i:03d}" / "layers.json", json_text(layers, indent=2) + "\n")
        files.commit()
        _say_not_kept(notes, count)
        print(f"wrote {count} layers file(s) under {out}")
        return 0

    def progress(done: int, total: int) -> None:
        if sys.stderr.isatty():
            print(f"\r{done}/{total} scenarios", end="" if done < total else "\n", file=sys.stderr, flush=True)

    try:
        records, doc = describe_batch(
            make, count, out, text, backend, args.seed, args.refine, args.jobs, progress, read_doc
        )
    except (PlacementError, ValueError, KeyError) as exc:
        if isinstance(exc, VeiInputError):
            raise
        raise VeiInputError(args.layers, "layers", str(exc).strip("'\"")) from None
    s = doc["summary"]
    if s["scenarios"] == 0:  # nothing could be written: that is the outcome, with the first reason
        first = next(r for r in records if not r.ok)
        print(
            f"vei: error: no scenario could be written ({s['failed']} of {s['failed']} failed); "
            f"scenario_{first.index:03d}: {first.error}; nothing was written",
            file=sys.stderr,
        )
        return 1
    act = "none" if s["mean_min_act_s"] is None else f"{s['mean_min_act_s']} s"
    rate = "–" if s["crash_rate"] is None else f"{100 * s['crash_rate']:.1f} %"
    print(
        f"{s['scenarios']} scenario(s): crash rate {rate} ({s['crashes']}), mean min ACT {act}, "
        f"mean comfort {s['mean_comfort']}, mean max EI {s['mean_max_ei_mps']} m/s"
        + (f"; intent met {s['intent_met']} of {s['intent_stated']}" if s["intent_met"] is not None else "")
        + (f" after {s['episodes_run']} runs" if args.refine else "")
    )
    if s["failed"]:
        print(f"{s['failed']} scenario(s) could not be written: their reasons are in batch.csv (error)")
    _say_not_kept(notes, count)
    print(f"wrote {out / 'batch.csv'}, {out / 'batch.json'}, {out / 'summary.html'} and {count} scenario folder(s)")
    return 0


def _say_not_kept(notes: list[str], count: int) -> None:
    """One line per thing the text states that some scenarios could not keep, with the reason and in
    how many of the ``count`` scenarios."""
    for note, times in Counter(notes).items():
        print(f"not kept in {times} of {count} scenario(s): {note}")
