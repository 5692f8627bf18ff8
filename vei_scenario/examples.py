"""``vei examples DIR``: copy the bundled example clips (and their map) out of the installed package.

Why: a user who installed the wheel has no checkout; the README's commands and the tutorials start from
``examples/case_study/clip.json``. The layout is kept (each clip names its map relative to itself,
``../maps/...``), so the copies compile as they are.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from vei_scenario.errors import VeiInputError

#: The folders copied: the example clips, their shared map, the CI suite, the example controller and the
#: OSMP traffic participants (FMUs and their sources, in ``osmp/src``).
FOLDERS = ("case_study", "multi_scooter", "no_map", "stop_and_go", "maps", "ci", "controllers", "osmp")
#: Scripts beside them: the dataset generator (which builds on the examples' generator).
SCRIPTS = ("generate_dataset.py", "generate_examples.py")


def _files(d, rel: str) -> list[tuple[str, bytes]]:
    """(relative path, bytes) of the files under ``d``, its subfolders' too, in name order."""
    out = []
    for f in sorted(d.iterdir(), key=lambda p: p.name):
        if f.name.startswith(".") or f.name == "__pycache__":
            continue
        if f.is_dir():
            out.extend(_files(f, f"{rel}/{f.name}"))
        elif f.is_file() and f.suffix != ".pyc":
            out.append((f"{rel}/{f.name}", f.read_bytes()))
    return out


def bundled_examples() -> list[tuple[str, bytes]]:
    """(relative path, bytes) of every bundled example file."""
    root = resources.files("vei_scenario").joinpath("data/examples")
    out = []
    for folder in FOLDERS:
        d = root.joinpath(folder)
        if not d.is_dir():
            continue
        out.extend(_files(d, folder))
    for name in SCRIPTS:
        f = root.joinpath(name)
        if f.is_file():
            out.append((name, f.read_bytes()))
    if not out:
        raise VeiInputError(None, "examples", "this installation carries no examples (reinstall vei-scenario)")
    return out


def copy_examples(target: str | Path, force: bool = False) -> list[Path]:
    """Copy the bundled examples into ``target`` (all or nothing); existing files are kept unless
    ``force``."""
    from vei_scenario.atomic_io import OutputSet

    target = Path(target)
    files = bundled_examples()
    clash = [rel for rel, _ in files if (target / rel).exists()]
    if clash and not force:
        raise VeiInputError(target / clash[0], "", "already exists (use --force to overwrite the examples)")
    out = OutputSet()
    for rel, data in files:
        out.add(target / rel, data)
    out.commit()
    return out.paths
