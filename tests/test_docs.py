"""The documentation cannot rot: the site builds with warnings as errors, the command-line reference is
what ``vei COMMAND --help`` prints, every page is reachable from the navigation, no page carries
development history, and every command the docs show runs as written.

How a page's commands are run: in a fresh folder holding a copy of ``examples/`` and the case study
compiled to ``out/case_study/`` (what README's main command leaves), with the test's ``vei`` and
``python`` first on PATH. A ```bash block runs as one script (``bash -e``: every line must succeed),
a ```console block's ``$ `` lines one by one, a ```python block as a script; all of one page in order,
in one folder. A block after ``<!-- skip: reason -->`` is not run (installs); one after ``<!-- needs:
NAME -->`` runs only where ``../shared/NAME`` is beside the checkout (esmini, the Euro NCAP pack),
linked into the folder as ``NAME``. The two commands README.md opens with are what CI itself runs.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

from conftest import NO_SHARED, ROOT, SHARED

DOCS = ROOT / "docs"
PAGES = sorted(p.relative_to(ROOT).as_posix() for p in [ROOT / "README.md", *DOCS.rglob("*.md")])
CI_MARKERS = ("<!-- main-command -->", "<!-- test-command -->")
HISTORY = re.compile(r"\bissue #?\d+|#\d{2}\b|\bwas [0-9.]+ ?(m|s|ms)\b|\bnow \d|→ [0-9.]+ ?(m|s|ms)\b", re.IGNORECASE)


@dataclass(frozen=True)
class Block:
    """One fenced block to run: its language, its commands (or script), where it starts, and what it needs."""

    kind: str
    commands: tuple[str, ...]
    line: int
    skip: str | None = None
    needs: str | None = None


def blocks(text: str) -> list[Block]:
    """The runnable blocks of a Markdown page, in order."""
    found, lines, i = [], text.splitlines(), 0
    while i < len(lines):
        fence = re.match(r"^```(bash|console|python)\s*$", lines[i])
        if not fence:
            i += 1
            continue
        start, body = i, []
        i += 1
        while i < len(lines) and lines[i] != "```":
            body.append(lines[i])
            i += 1
        before = next((lines[k].strip() for k in range(start - 1, -1, -1) if lines[k].strip()), "")
        skip = re.match(r"<!-- skip: (.+) -->", before)
        needs = re.match(r"<!-- needs: (\S+) -->", before)
        if before in CI_MARKERS:
            skip = re.match(r"(.*)", "run by .ci/run itself")
        kind = fence.group(1)
        if kind == "python":
            commands = ("\n".join(body),)
        elif kind == "console":
            commands = _joined([ln[2:] for ln in _continued(body) if ln.startswith("$ ")])
        else:
            commands = ("\n".join(body),) if any(ln.strip() and not ln.lstrip().startswith("#") for ln in body) else ()
        found.append(Block(kind, commands, start + 1, skip and skip.group(1), needs and needs.group(1)))
        i += 1
    return found


def _continued(lines: list[str]) -> list[str]:
    """Lines with backslash continuations joined (a console block's continuation has no ``$``)."""
    out: list[str] = []
    for ln in lines:
        if out and out[-1].endswith("\\"):
            out[-1] = out[-1][:-1] + " " + ln.strip()
        else:
            out.append(ln)
    return out


def _joined(lines: list[str]) -> tuple[str, ...]:
    """Shell lines as commands: continuations joined, a here-document kept whole, comments dropped."""
    commands, lines, i = [], _continued(lines), 0
    while i < len(lines):
        line = lines[i]
        heredoc = re.search(r"<<-?'?(\w+)'?", line)
        if heredoc:
            end = lines.index(heredoc.group(1), i + 1)
            commands.append("\n".join(lines[i : end + 1]))
            i = end + 1
            continue
        if line.strip() and not line.lstrip().startswith("#"):
            commands.append(line)
        i += 1
    return tuple(commands)


@pytest.fixture(scope="module")
def case_study(tmp_path_factory) -> Path:
    """The case study compiled once, as README's main command leaves it in ``out/case_study``."""
    out = tmp_path_factory.mktemp("main") / "out" / "case_study"
    subprocess.run(
        _vei("compile", str(ROOT / "examples/case_study/clip.json"), "-o", str(out / "scenario.xosc")),
        check=True,
        capture_output=True,
    )
    return out


def _vei(*args: str) -> list[str]:
    return [sys.executable, "-m", "vei_scenario", *args]


def _env() -> dict[str, str]:
    env = dict(os.environ, COLUMNS="100", MPLBACKEND="Agg", DISABLE_MKDOCS_2_WARNING="true", NO_MKDOCS_2_WARNING="1")
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}"
    env.pop("CI", None)  # progress bars and their absence are not what a page shows
    return env


def _pages_with_commands() -> list[str]:
    return [p for p in PAGES if any(b.commands and not b.skip for b in blocks((ROOT / p).read_text()))]


@pytest.mark.parametrize("page", _pages_with_commands())
def test_every_command_on_the_page_runs(page, case_study, tmp_path):
    runnable = blocks((ROOT / page).read_text())
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    shutil.copytree(case_study, tmp_path / "out" / "case_study")
    env, missing = _env(), []
    for block in runnable:
        if block.skip:
            continue
        if block.needs:
            if not (SHARED / block.needs).exists():
                missing.append(f"{page}:{block.line} needs {block.needs}/ ({NO_SHARED})")
                continue
            link = tmp_path / block.needs
            if not link.exists():
                link.symlink_to(SHARED / block.needs)
        for command in block.commands:
            shell = ["bash", "-e", "-o", "pipefail", "-c"] if block.kind != "python" else [sys.executable, "-c"]
            run = subprocess.run([*shell, command], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600)
            shown = command if len(command) < 300 else command[:300] + " ..."
            assert run.returncode == 0, f"{page}:{block.line}: {shown}\n{run.stdout[-2000:]}\n{run.stderr[-2000:]}"
            assert "Traceback" not in run.stderr, f"{page}:{block.line}: {shown}\n{run.stderr[-2000:]}"
    if missing:
        pytest.skip("; ".join(missing))


def _gen_pages():
    spec = importlib.util.spec_from_file_location("gen_pages", DOCS / "gen_pages.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_cli_reference_is_what_help_prints():
    from vei_scenario.cli import build_parser

    gen = _gen_pages()
    os.environ["COLUMNS"] = str(gen.HELP_COLUMNS)
    page = gen.cli_page()
    paths = [path for path, _ in gen.commands(build_parser())]
    assert ("run",) in paths and ("fmu", "build") in paths and len(paths) > 15
    for path in paths:
        shown = subprocess.run(_vei(*path, "--help"), capture_output=True, text=True, env=_env(), check=True).stdout
        assert f"```text\n{shown.rstrip()}\n```" in page, f"vei {' '.join(path)} --help differs from the reference"


def test_every_metric_of_the_registry_is_documented():
    from vei_scenario.metrics.definitions import METRICS

    page = _gen_pages().metrics_page()
    for name, function in METRICS.items():
        assert f"## `{name}`" in page and function.__doc__ and len(function.__doc__.strip()) > 20, name


def test_every_page_is_in_the_navigation_and_no_page_is_history():
    yaml = pytest.importorskip("yaml")
    nav = (ROOT / "mkdocs.yml").read_text()
    config = yaml.safe_load(nav.replace("!!python", "#"))
    listed = set()

    def walk(node):
        if isinstance(node, dict):
            for v in node.values():
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)
        elif isinstance(node, str):
            listed.add(node)

    walk(config["nav"])
    written = {p.relative_to(DOCS).as_posix() for p in DOCS.rglob("*.md")}
    generated = {"reference/cli.md", "reference/metrics.md"}
    assert written | generated == listed, (sorted(listed - written - generated), sorted(written - listed))
    for page in PAGES:
        text = (ROOT / page).read_text()
        found = HISTORY.search(text)
        assert found is None, f"{page}: development history in the user docs: {found.group(0)!r}"


def test_readme_is_short_and_opens_with_the_two_commands():
    text = (ROOT / "README.md").read_text()
    assert len(text.splitlines()) <= 150
    first, second = text.index(CI_MARKERS[0]), text.index(CI_MARKERS[1])
    assert first < second < 2500


def test_the_site_builds_with_warnings_as_errors(tmp_path):
    pytest.importorskip("mkdocs", reason="the docs extra is not installed (pip install -e '.[docs]')")
    run = subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--strict", "-q", "-d", str(tmp_path / "site")],
        cwd=ROOT,
        capture_output=True,
        text=True,
        env=_env(),
        timeout=600,
    )
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    assert (tmp_path / "site" / "reference" / "cli" / "index.html").is_file()
    assert (tmp_path / "site" / "assets" / "case_study" / "gap_ttc.png").is_file()
