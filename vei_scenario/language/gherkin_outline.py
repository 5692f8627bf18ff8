"""A Gherkin Scenario Outline filled in from its Examples table: "Given the ego drives at <v_ego> km/h"
with ``| v_ego | ... |`` over ``| 70 | ... |`` is "Given the ego drives at 70 km/h".

Why: test engineers write their cases as outlines, one row per variant, and the values of the row are
the scenario's speeds, gaps and outcome; read as they stand, the placeholders carry nothing and the
table's bare numbers are read as whatever they stand beside. A scenario is one row: the first. The
keywords are Gherkin's own ("Examples:" and its synonym "Scenarios:")."""

from __future__ import annotations

import re

_PLACEHOLDER = re.compile(r"<\s*([^<>\n|]{1,40}?)\s*>")
_EXAMPLES = re.compile(r"^[ \t]*(?:Examples|Scenarios)[ \t]*:[^\n]*\n", re.IGNORECASE | re.MULTILINE)
_ROW = re.compile(r"[ \t]*\|([^\n]*)\|[ \t]*(?:\n|$)")


def _cells(row: str) -> list[str]:
    return [c.strip() for c in row.split("|")]


def filled_outline(text: str) -> str:
    """``text`` with each ``<name>`` the first row of its Examples table gives a value replaced by that
    value, and the Examples block taken out; unchanged where it has no placeholder or no such table."""
    if not _PLACEHOLDER.search(text):
        return text
    examples = _EXAMPLES.search(text)
    if examples is None:
        return text
    rows, end = [], examples.end()
    while (row := _ROW.match(text, end)) is not None:
        rows.append(_cells(row.group(1)))
        end = row.end()
    if len(rows) < 2 or len(rows[1]) != len(rows[0]):
        return text
    values = {name.lower(): value for name, value in zip(rows[0], rows[1], strict=True) if name}
    head = text[: examples.start()]
    head = _PLACEHOLDER.sub(lambda m: values.get(m.group(1).lower(), m.group(0)), head)
    return head.rstrip() + ("\n" + text[end:] if text[end:].strip() else "")
