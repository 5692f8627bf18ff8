"""The systems ``vei bench`` tests: vei's collision-avoidance planner, or the user's own controller on
the ego (``--controller ENTITY=file.py:Class`` or ``ENTITY=planner.fmu``), one or two at a time.

Why a module of its own: which system a benchmark is of must be named in every output (file and
SHA-256), must be carried by every reproduce command, and two systems on one library need labels to
tell their results apart. The options:

* ``--controller ENTITY=TARGET``: the user's system, labelled by its class (or the FMU's file name);
* ``--controller LABEL=ENTITY=TARGET``: the same with a label of one's own choosing;
* ``--controller planner`` (or ``LABEL=planner``): vei's planner, the default when nothing is given;
* ``--controller-param NAME=VALUE`` goes to every plugged system, ``LABEL:NAME=VALUE`` to one.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from vei_scenario.errors import VeiInputError

#: What a planner-only benchmark calls its system.
PLANNER = "planner"
PLANNER_NAME = "vei's collision-avoidance planner (CapEnabled=true)"
_LABEL = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]{0,63}")


@dataclass(frozen=True)
class System:
    """One system under test: ``controllers`` empty for vei's planner (the compiled kernel runs it),
    else the user's controller specs (:class:`~vei_scenario.sut.ControllerSpec`), run in the interpreter."""

    label: str
    controllers: tuple = ()

    @property
    def is_planner(self) -> bool:
        return not self.controllers

    def name(self) -> str:
        """How report titles name it."""
        if self.is_planner:
            return PLANNER_NAME
        return ", ".join(f"{s.entity}={s.target}" for s in self.controllers)

    def describe(self) -> dict:
        """The system as bench.json names it: its label and, for the user's, file and SHA-256."""
        from vei_scenario.sut import sut_document

        return {"label": self.label, "name": self.name(), "controllers": sut_document(self.controllers)}


def _split(item: str) -> tuple[str | None, str]:
    """(label or None, ``ENTITY=TARGET`` or ``planner``) of one ``--controller`` value."""
    if item.strip() == PLANNER:
        return None, PLANNER
    first, sep, rest = item.partition("=")
    second, sep2, target = rest.partition("=")
    if sep and rest.strip() == PLANNER:
        return first.strip(), PLANNER
    if sep and sep2 and target.strip() and _LABEL.fullmatch(first.strip()) and not re.search(r"[/\\:]", second):
        return first.strip(), f"{second.strip()}={target.strip()}"
    return None, item.strip()


def _default_label(target: str) -> str:
    """The class name of ``ENTITY=file.py:Class``, the file name of ``ENTITY=planner.fmu``."""
    spec = target.partition("=")[2]
    name = Path(spec).stem if spec.lower().endswith(".fmu") else spec.rpartition(":")[2] or spec
    return re.sub(r"[^A-Za-z0-9_.-]", "_", name)[:64] or "system"


def parse_systems(
    controllers: list[str], parameters: list[str] | None = None, step_timeout_s: float | None = None
) -> tuple[System, ...]:
    """The systems of ``vei bench``'s options, each loaded and checked before anything runs: vei's
    planner alone without any ``--controller``, at most two otherwise, with distinct labels."""
    from vei_scenario.sut import parse_controller_options

    items = [_split(c) for c in controllers] or [(None, PLANNER)]
    if len(items) > 2:
        raise VeiInputError(None, "--controller", f"{len(items)} systems: vei bench compares at most two")
    labels = [lab or (PLANNER if t == PLANNER else _default_label(t)) for lab, t in items]
    for lab in labels:
        if not _LABEL.fullmatch(lab):
            raise VeiInputError(None, "--controller", f"label {lab!r}: letters, digits, _ . - only (at most 64)")
    if len(set(labels)) < len(labels):
        raise VeiInputError(None, "--controller", f"two systems labelled {labels[0]!r}: name them LABEL=ENTITY=TARGET")
    scoped: dict[str, list[str]] = {lab: [] for lab in labels}
    for p in parameters or []:
        head, sep, value = p.partition("=")
        owner, colon, name = head.partition(":")
        if sep and colon:
            if owner.strip() not in scoped:
                raise VeiInputError(None, "--controller-param", f"{p!r}: no system labelled {owner.strip()!r}")
            scoped[owner.strip()].append(f"{name}={value}")
        else:
            for lab in labels:
                scoped[lab].append(p)
    out = []
    for lab, (_, target) in zip(labels, items):
        if target == PLANNER:
            if scoped[lab]:
                raise VeiInputError(None, "--controller-param", f"{scoped[lab][0]!r}: vei's planner takes none")
            out.append(System(lab))
        else:
            out.append(System(lab, parse_controller_options([target], scoped[lab], step_timeout_s)))
    if step_timeout_s is not None and all(s.is_planner for s in out):
        raise VeiInputError(None, "--controller-timeout", "given without --controller")
    return tuple(out)
