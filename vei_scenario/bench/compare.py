"""Two systems on one library: which scenarios one fails and the other does not.

Why: a team changing its AEB wants to know where the new version fails that the old did not (a
regression) and where it got better, scenario by scenario, with the commands that reproduce each.
Two bench documents (``bench.json`` of ``vei bench``) are compared when they searched the same way
(configurations, TimeShift half-width and step, time step); scenarios are matched by clip file.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

from vei_scenario.bench.outputs import STYLE, system_line
from vei_scenario.errors import VeiInputError

_SEARCH_KEYS = ("configurations", "time_shift_search")


def read_bench(path: str | Path) -> dict:
    """A bench document, or one line saying why ``path`` is not one."""
    path = Path(path)
    if path.is_dir():
        path = path / "bench.json"
    try:
        doc = json.loads(path.read_text("utf-8"))
        assert isinstance(doc, dict) and doc.get("format") == "vei-bench/1" and isinstance(doc["results"], list)
    except FileNotFoundError:
        raise VeiInputError(path, "", "no such file (a bench.json of vei bench)") from None
    except (OSError, ValueError, KeyError, AssertionError):
        raise VeiInputError(path, "", "not a vei bench document (bench.json of vei bench)") from None
    return doc


def _label(doc: dict, fallback: str) -> str:
    return doc.get("system", {}).get("label") or fallback


def compare_bench(a: dict, b: dict) -> dict:
    """Scenario by scenario, which of two systems fails: ``only_a``/``only_b`` (with the failing one's
    worst failure and its reproduce command), ``both``, ``neither``; scenarios benched by one only are
    listed apart. Refuses two documents searched differently."""
    for key in _SEARCH_KEYS:
        if a.get(key) != b.get(key):
            raise VeiInputError(
                None, key, f"the two benchmarks searched differently ({a.get(key)} and {b.get(key)}): run both alike"
            )
    la, lb = _label(a, "A"), _label(b, "B")
    if la == lb:
        la, lb = f"{la} (A)", f"{lb} (B)"
    rows_a = {r["file"]: r for r in a["results"] if r["status"] == "ok"}
    rows_b = {r["file"]: r for r in b["results"] if r["status"] == "ok"}
    common = sorted(set(rows_a) & set(rows_b), key=str)
    out: dict = {"only_a": [], "only_b": [], "both": [], "neither": []}
    for f in common:
        ra, rb = rows_a[f], rows_b[f]
        key = {(True, False): "only_a", (False, True): "only_b", (True, True): "both"}.get(
            (ra["fails"], rb["fails"]), "neither"
        )
        if key == "neither":
            out[key].append(f)
            continue
        out[key].append(
            {
                "file": f,
                "a": ra.get("worst_failure"),
                "b": rb.get("worst_failure"),
            }
        )
    return {
        "format": "vei-bench-compare/1",
        "a": {"label": la, "system": a.get("system"), "system_under_test": a["system_under_test"]},
        "b": {"label": lb, "system": b.get("system"), "system_under_test": b["system_under_test"]},
        "a_line": system_line(a),
        "b_line": system_line(b),
        "libraries": [a.get("library"), b.get("library")],
        "search": {k: a.get(k) for k in _SEARCH_KEYS},
        "compared": len(common),
        "a_failing": sum(1 for f in common if rows_a[f]["fails"]),
        "b_failing": sum(1 for f in common if rows_b[f]["fails"]),
        "not_in_both": sorted((set(rows_a) ^ set(rows_b)), key=str),
        **out,
    }


def _failure_cell(w: dict | None) -> str:
    if not w:
        return "–"
    speed = w.get("ego_speed_at_contact_mps")
    what = f"ego at {speed:.2f} m/s" if speed is not None else html.escape(w.get("error", "a run failed"))
    return (
        f"configuration {w['configuration']}, TimeShift {w['time_shift_s']:+.2f} s: {what}<br>"
        f"<code>{html.escape(w['reproduce'])}</code>"
    )


def compare_html(c: dict) -> str:
    """The comparison as a page: the two systems, the counts, and the scenarios one fails alone."""
    la, lb = html.escape(c["a"]["label"]), html.escape(c["b"]["label"])
    out = [
        "<!DOCTYPE html><html><head><meta charset='utf-8'><title>vei bench: comparison</title>",
        f"<style>{STYLE}</style></head><body><h1>{la} against {lb}</h1>",
        f"<p>A, <b>{la}</b>: <code>{html.escape(c['a_line'])}</code><br>"
        f"B, <b>{lb}</b>: <code>{html.escape(c['b_line'])}</code></p>",
        f"<p>{c['compared']} scenarios benched by both: <b>{la} fails {c['a_failing']}, {lb} fails "
        f"{c['b_failing']}</b>; {len(c['only_a'])} fail with {la} only, {len(c['only_b'])} with {lb} only, "
        f"{len(c['both'])} with both, {len(c['neither'])} with neither.</p>",
    ]
    for key, title in (("only_b", f"Failing with {lb} only"), ("only_a", f"Failing with {la} only"), ("both", "Both")):
        out.append(f"<h2>{html.escape(title)} ({len(c[key])})</h2>")
        if not c[key]:
            out.append("<p>(none)</p>")
            continue
        out.append(f"<table><tr><th>scenario</th><th>{la}: worst failure</th><th>{lb}: worst failure</th></tr>")
        for r in c[key]:
            out.append(
                f"<tr><td>{html.escape(str(r['file']))}</td><td>{_failure_cell(r['a'])}</td>"
                f"<td>{_failure_cell(r['b'])}</td></tr>"
            )
        out.append("</table>")
    if c["not_in_both"]:
        out.append(f"<p>Benched by one only: {html.escape(', '.join(map(str, c['not_in_both'])))}</p>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"


def write_compare(a: dict, b: dict, out_dir: str | Path) -> dict:
    """compare.json and compare.html into ``out_dir``; returns the comparison."""
    from vei_scenario.atomic_io import OutputSet

    c = compare_bench(a, b)
    outputs = OutputSet()
    outputs.add(Path(out_dir) / "compare.json", json.dumps(c, indent=1, allow_nan=False) + "\n")
    outputs.add(Path(out_dir) / "compare.html", compare_html(c))
    outputs.commit()
    return c
