"""Pages made from the code when the site is built (mkdocs-gen-files), so they cannot go stale:

- ``reference/cli.md``: every command's ``--help``, from the argparse parser the ``vei`` command uses;
- ``reference/metrics.md``: every metric of the registry with its docstring (formula and source);
- ``assets/case_study/*.png``: the plots a run of the bundled case study writes, for Getting started.

The help text is formatted at a fixed width (:data:`HELP_COLUMNS`), the width the docs test compares
``vei COMMAND --help`` at.
"""

from __future__ import annotations

import argparse
import inspect
import os
import re
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path

HELP_COLUMNS = 100
ROOT = Path(__file__).resolve().parents[1]


def commands(parser: argparse.ArgumentParser, prefix: tuple[str, ...] = ()) -> Iterator[tuple[tuple[str, ...], str]]:
    """Each command path (``()``, ``("run",)``, ``("fmu", "build")`` ...) with its help text."""
    yield prefix, parser.format_help()
    for action in parser._actions:  # argparse keeps its sub-commands here; there is no public accessor
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from commands(sub, (*prefix, name))


def cli_page() -> str:
    from vei_scenario.cli import build_parser

    os.environ["COLUMNS"] = str(HELP_COLUMNS)
    lines = [
        "# Command line",
        "",
        "Every command and option of `vei`, as `vei COMMAND --help` prints it (generated from the parser",
        "when this site is built). Exit codes everywhere: 0 done, 1 done with failures (failing variants,",
        "failed expectations, invalid files), 2 refused (bad input or usage; one line on stderr, nothing",
        "written).",
        "",
    ]
    for path, text in commands(build_parser()):
        title = "vei " + " ".join(path) if path else "vei"
        lines += [f"## `{title}`", "", "```text", text.rstrip(), "```", ""]
    return "\n".join(lines)


def plain(doc: str) -> str:
    """A docstring as Markdown: Sphinx roles (``:func:`~a.b```) become code (`b`), double backticks single."""
    doc = re.sub(r":\w+:`~?([\w.]+)`", lambda m: f"`{m.group(1).rsplit('.', 1)[-1]}`", doc)
    return doc.replace("``", "`")


def metrics_page() -> str:
    from vei_scenario.metrics.definitions import METRICS

    lines = [
        "# Metrics",
        "",
        "The metrics `vei run`, `vei sweep`, `vei check` and the targets of `vei risk`, `vei falsify` and",
        "`vei probability` use, one function each (`vei_scenario/metrics/definitions.py`), listed from",
        "the registry when this site is built. Units are in the names (`_s` seconds, `_m` metres, `_mps`",
        "m/s, `_mps2` m/s², `_mps3` m/s³); an undefined value (no collision, no crossing) is `null` in JSON",
        "and empty in CSV. Each is computed between the ego and one other road user (the threat unless",
        "the command says otherwise).",
        "",
    ]
    for name, function in METRICS.items():
        doc = plain(inspect.getdoc(function) or "")
        lines += [f"## `{name}`", "", doc, ""]
    return "\n".join(lines)


def case_study_plots() -> dict[str, bytes]:
    """The PNGs of one run of the compiled case study (aggressive rider, planner on, at its conflict shift)."""
    with tempfile.TemporaryDirectory() as tmp:
        scenario = Path(tmp) / "case_study" / "scenario.xosc"
        vei = [sys.executable, "-m", "vei_scenario"]
        subprocess.run(
            [*vei, "compile", str(ROOT / "examples/case_study/clip.json"), "-o", str(scenario)],
            check=True,
            capture_output=True,
        )
        run = Path(tmp) / "run"
        subprocess.run(
            [
                *vei,
                "run",
                str(scenario),
                "--param",
                "RiderType=aggressive",
                "--param",
                "CapEnabled=true",
                "--param",
                "TimeShift=2.197",
                "-o",
                str(run),
            ],
            check=True,
            capture_output=True,
        )
        return {p.name: p.read_bytes() for p in sorted(run.glob("*.png"))}


def main() -> None:
    import mkdocs_gen_files

    with mkdocs_gen_files.open("reference/cli.md", "w") as page:
        page.write(cli_page())
    with mkdocs_gen_files.open("reference/metrics.md", "w") as page:
        page.write(metrics_page())
    for name, data in case_study_plots().items():
        with mkdocs_gen_files.open(f"assets/case_study/{name}", "wb") as image:
            image.write(data)


# mkdocs-gen-files runs this file with runpy.run_path (module name "<run_path>"); the docs test imports
# it for its functions without generating anything.
if __name__ in {"__main__", "<run_path>"}:
    main()
