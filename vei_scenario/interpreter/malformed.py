"""Why a scenario the interpreter could not read is malformed: the ASAM schema's first complaint.

The interpreter reads the elements it plays and refuses, with their line, the values it cannot take.
A file that breaks the schema's structure (a ``SpeedAction`` without its target, a ``BoundingBox``
without ``Dimensions``) can still trip it somewhere it took the structure for granted. Rather than
guard every child it reads, :func:`run_scenario` asks the schema when reading fails: a file the ASAM
XSD finds fault with is refused with that fault, its file and line, in one line. A file the schema
accepts is not blamed: the error is the interpreter's, and it is raised as it is. (vei validate's own
rules are not asked: a missing SceneGraphFile, which many playable files have, is not why reading
failed.)
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter.document import SOURCE_FILE

#: What reading a malformed element raises where the interpreter assumed the structure.
READING_ERRORS = (AttributeError, TypeError, ValueError, KeyError, IndexError)


def files_read(path: Path, root) -> list[Path]:
    """The scenario file and, in order of first use, the catalog files its entries came from."""
    files = [Path(path)]
    if root is not None:
        for el in root.iter():
            src = el.get(SOURCE_FILE) if isinstance(el.tag, str) else None
            if src and Path(src) not in files:
                files.append(Path(src))
    return files


def schema_refusal(path: Path, root, error: BaseException) -> VeiInputError | None:
    """The refusal of a scenario whose reading raised ``error``: the first complaint of the ASAM XSD about
    the files it was read from; None when it has none (then the fault is the interpreter's). Without
    the XSDs installed it cannot tell: the refusal says what failed and how to find out."""
    from vei_scenario.openscenario.validation import validate_file

    for file in files_read(path, root):
        try:
            problems = validate_file(file)
        except VeiInputError as exc:
            if exc.where == "ASAM XSD":  # (no schema on this machine to tell whether the file is at fault)
                return VeiInputError(
                    Path(path),
                    "",
                    f"cannot be played: reading it failed ({type(error).__name__}: {error}); the ASAM XSD that "
                    f"would name the fault is not installed ({exc.reason.split('; ', 1)[-1]}); a file it "
                    "finds valid is a vei bug to report",
                )
            continue
        problems = [p for p in problems if p.rule == "xsd"]
        if problems:
            first = problems[0]
            where = f"line {first.line}" if first.line else ""
            return VeiInputError(Path(first.file), where, f"cannot be played: {first.message} [{first.rule}]")
    return None


@contextmanager
def refused_when_malformed(path: str | Path, root: Callable[[], object]) -> Iterator[None]:
    """Reading (and playing) ``path`` inside: a reading error in a file the schema faults is refused
    with :func:`schema_refusal`; ``root()``: the resolved document so far (None before it is loaded)."""
    try:
        yield
    except READING_ERRORS as exc:
        refusal = schema_refusal(Path(path), root(), exc)
        if refusal is None:
            raise
        raise refusal from exc
