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
#: Lines Gherkin allows between "Examples:" and its table: blank ones, comments, tags, a description.
_BEFORE_TABLE = re.compile(r"[ \t]*(?:#[^\n]*|@[^\n]*|[^|\n][^\n]*)?\n")
#: A Markdown table's rule under its header ("|---|:--:|"): no row of values.
_RULE = re.compile(r"[\s:|-]*")


def _cells(row: str) -> list[str]:
    return [c.strip() for c in row.split("|")]


def _table(text: str, at: int) -> tuple[list[list[str]], int]:
    """The rows of the table that starts at ``at`` or after the lines allowed before it, and where it ends."""
    rows: list[list[str]] = []
    end = at
    for _ in range(5):  # (a few lines of comment, tag or description before the table)
        if _ROW.match(text, end):
            break
        skipped = _BEFORE_TABLE.match(text, end)
        if skipped is None or skipped.end() == end:
            break
        end = skipped.end()
    while (row := _ROW.match(text, end)) is not None:
        if not _RULE.fullmatch(row.group(1)):
            rows.append(_cells(row.group(1)))
        end = row.end()
    return rows, end


def filled_outline(text: str) -> str:
    """``text`` with each ``<name>`` the first row of its Examples table gives a value replaced by that
    value, and the Examples blocks taken out; unchanged where it has no placeholder or no such table.
    Each outline is filled from the first Examples block after it; a block's other rows are other
    scenarios, and later blocks other sets of them."""
    if not _PLACEHOLDER.search(text):
        return text
    text = text.replace("\r\n", "\n")
    out: list[str] = []
    cursor = 0
    values: dict[str, str] | None = None
    for examples in _EXAMPLES.finditer(text):
        if examples.start() < cursor:
            continue
        rows, end = _table(text, examples.end())
        if len(rows) < 2 or any(len(r) != len(rows[0]) for r in rows[1:2]):
            continue
        segment = text[cursor : examples.start()]
        if _PLACEHOLDER.search(segment) or values is None:
            values = {name.lower(): value for name, value in zip(rows[0], rows[1], strict=True) if name}
        out.append(_PLACEHOLDER.sub(lambda m, v=values: v.get(m.group(1).lower(), m.group(0)), segment))
        cursor = end
    if values is None:
        return text
    out.append(text[cursor:])
    return "\n".join(part.strip("\n") for part in out if part.strip())
