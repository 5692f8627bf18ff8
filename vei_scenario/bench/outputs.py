"""What ``vei bench`` writes besides bench.json: report.html (the share of failing scenarios, the
distribution of their worst impact speeds, the worst cases with the commands that reproduce them, a
table of every scenario) and junit.xml (one test case per scenario, failed where the system
fails) so that CI can gate on a benchmark. Both name the system under test (its file and SHA-256)."""

from __future__ import annotations

import html
from xml.sax.saxutils import quoteattr

STYLE = """
body{font-family:sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse;font-size:13px}
td,th{border:1px solid #ccc;padding:3px 6px;text-align:left;vertical-align:top}
th{background:#eee}
.fail{color:#b00;font-weight:bold}
code{font-size:12px}
"""


def _histogram_svg(values: list[float], label: str, bins: int = 10) -> str:
    """Bars of ``values`` in ``bins`` equal bins (an inline SVG; no plotting library)."""
    if not values:
        return "<p>(none)</p>"
    lo, hi = min(values), max(values)
    width = (hi - lo) / bins or 1.0
    counts = [0] * bins
    for v in values:
        counts[min(int((v - lo) / width), bins - 1)] += 1
    top = max(counts)
    w, h, bar = 360, 140, 360 / bins
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h + 30}">']
    for k, c in enumerate(counts):
        bh = h * c / top
        out.append(
            f'<rect x="{k * bar + 1:.1f}" y="{h - bh:.1f}" width="{bar - 2:.1f}" height="{bh:.1f}" fill="#d62728"/>'
        )
    out.append(f'<text x="0" y="{h + 14}" font-size="11">{lo:.2f}</text>')
    out.append(f'<text x="{w}" y="{h + 14}" font-size="11" text-anchor="end">{hi:.2f}</text>')
    out.append(f'<text x="{w / 2}" y="{h + 28}" font-size="11" text-anchor="middle">{html.escape(label)}</text>')
    return "".join(out) + "</svg>"


def _with_system(w: dict) -> str:
    ttc = "–" if w["min_ttc_s"] is None else f"{w['min_ttc_s']:.2f} s"
    alert = "–" if w["max_alert_s"] is None else f"{w['max_alert_s']:.2f} s"
    return f"{_mps(w['worst_ego_speed_at_contact_mps'])}, {ttc}, {alert}"


def _mps(v: float | None) -> str:
    return "–" if v is None else f"{v:.2f} m/s"


def _intervals(c: dict, key: str = "collision_shifts_s") -> str:
    return ", ".join(f"{a:+.2f}..{b:+.2f}" for a, b in c[key]) or "–"


def _moving(c: dict) -> str:
    return _intervals(c, "ego_moving_collision_shifts_s")


def system_line(doc: dict) -> str:
    """The system under test in one line: what it is, with the file and SHA-256 of the user's code."""
    parts = [doc["system_under_test"]]
    for c in doc.get("system", {}).get("controllers", []):
        params = ", ".join(f"{k}={v}" for k, v in c["parameters"].items())
        parts.append(
            f"{c['file'] or c['controller']} (sha256 {c['sha256'] or '-'})" + (f" with {params}" if params else "")
        )
    return "; ".join(parts)


def _title(doc: dict) -> str:
    label = doc.get("system", {}).get("label")
    return f"{label} ({doc['system_under_test']})" if label and label != "planner" else doc["system_under_test"]


def bench_html(doc: dict) -> str:
    results = doc["results"]
    ok = [r for r in results if r["status"] == "ok"]
    share = "–" if doc["failure_share"] is None else f"{100 * doc['failure_share']:.1f} %"
    impacts = [r["worst_failure"]["ego_speed_at_contact_mps"] for r in ok if r["fails"]]
    search = doc["time_shift_search"]
    out = [
        "<!DOCTYPE html><html><head><meta charset='utf-8'><title>vei bench</title>",
        f"<style>{STYLE}</style></head><body><h1>Benchmark: {html.escape(_title(doc))}</h1>",
        f"<p>System under test: <code>{html.escape(system_line(doc))}</code></p>",
        f"<p>{doc['scenarios']} scenarios, {doc['benched']} benched: configurations "
        f"{', '.join(map(str, doc['configurations']))} at every TimeShift "
        f"within ±{search['half_width_s']:g} s of each conflict shift, every {search['step_s']:g} s (step "
        f"{search['dt_s']:g} s). <b>{doc['failing']} fail ({share})</b>: with the system on (configurations "
        f"{', '.join(map(str, doc['sut_configurations']))}) the ego collides while moving at some shift, or a run "
        "fails.</p>",
        "<h2>Worst ego speed at contact of the failing scenarios (m/s)</h2>",
        _histogram_svg([v for v in impacts if v is not None], "worst ego speed at contact with the system on, m/s"),
    ]
    if doc["worst"]:
        out.append(
            "<h2>Worst cases</h2><table><tr><th>scenario</th><th>configuration</th><th>TimeShift</th>"
            "<th>ego speed at contact</th><th>impact speed</th><th>reproduce</th></tr>"
        )
        for w in doc["worst"]:
            out.append(
                f"<tr><td>{html.escape(str(w['file']))}</td><td>{w['configuration']}</td>"
                f"<td>{w['time_shift_s']:+.2f} s</td><td>{_mps(w['ego_speed_at_contact_mps'])}</td>"
                f"<td>{_mps(w['impact_speed_mps'])}</td>"
                f"<td><code>{html.escape(w['reproduce'])}</code></td></tr>"
            )
        out.append("</table>")
    names = {n: c["description"] for n, c in ok[0]["configurations"].items()} if ok else {}
    out.append(
        "<h2>Scenarios</h2><table><tr><th>scenario</th><th>conflict TimeShift</th><th>verdict</th>"
        "<th>with the system on: worst ego speed at contact, lowest TTC, longest alert</th>"
    )
    out += [f"<th>{html.escape(n)}: {html.escape(d)}<br>colliding shifts</th>" for n, d in names.items()]
    out.append("</tr>")
    for r in results:
        if r["status"] != "ok":
            out.append(
                f"<tr><td>{html.escape(str(r['file']))}</td><td colspan='{3 + len(names)}'>"
                f"{html.escape(r['status'])}: {html.escape(r['error'])}</td></tr>"
            )
            continue
        verdict = "<span class=fail>fails</span>" if r["fails"] else "passes"
        cells = "".join(
            f"<td>{_intervals(c)}"
            + (
                f"<br>ego moving: {_moving(c)}"
                if int(n) in doc["sut_configurations"] and c["collisions"] != c["collisions_ego_moving"]
                else ""
            )
            + (
                f"<br><span class=fail>{c['failed_runs']} run(s) failed (the first: "
                f"{html.escape(str(c['first_error']['error']))})</span>"
                if c["failed_runs"]
                else ""
            )
            + "</td>"
            for n, c in r["configurations"].items()
        )
        out.append(
            f"<tr><td>{html.escape(str(r['file']))}</td><td>{r['conflict_time_shift_s']:+.2f} s</td>"
            f"<td>{verdict}</td><td>{_with_system(r['with_system'])}</td>{cells}</tr>"
        )
    out.append("</table></body></html>")
    return "\n".join(out) + "\n"


def junit_xml(doc: dict) -> str:
    """One test case per scenario: failed where the system fails, skipped where there is nothing
    to search, an error where the scenario could not be compiled or run; the system is a property."""
    results = doc["results"]
    failures = sum(1 for r in results if r["status"] == "ok" and r["fails"])
    errors = sum(1 for r in results if r["status"] == "error")
    skipped = sum(1 for r in results if r["status"] == "skipped")
    out = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<testsuite name="vei bench" tests="{len(results)}" failures="{failures}" errors="{errors}" '
        f'skipped="{skipped}">',
        "  <properties>",
        f'    <property name="system_under_test" value={quoteattr(system_line(doc))}/>',
        "  </properties>",
    ]
    for r in results:
        out.append(f'  <testcase classname="vei.bench" name={quoteattr(str(r["file"]))}>')
        if r["status"] == "skipped":
            out.append(f"    <skipped message={quoteattr(r['error'])}/>")
        elif r["status"] == "error":
            out.append(f"    <error message={quoteattr(r['error'])}/>")
        elif r["fails"]:
            w = r["worst_failure"]
            lines = [
                f"configuration {n}: the ego collides while moving for TimeShift {_moving(c)} s"
                for n in doc["sut_configurations"]
                if (c := r["configurations"][str(n)])["collisions_ego_moving"]
            ]
            lines += [
                f"configuration {n}: {c['failed_runs']} run(s) failed: {c['first_error']['error']}"
                for n in doc["sut_configurations"]
                if (c := r["configurations"][str(n)])["failed_runs"]
            ]
            if w["ego_speed_at_contact_mps"] is not None:
                msg = (
                    f"{doc['system']['label']} collides with the ego moving (worst: ego at "
                    f"{w['ego_speed_at_contact_mps']:.2f} m/s at TimeShift {w['time_shift_s']:+.2f} s)"
                )
            else:
                msg = f"{doc['system']['label']}: a run failed at TimeShift {w['time_shift_s']:+.2f} s"
            body = "\n".join(lines + [f"reproduce: {w['reproduce']}"])
            out.append(f"    <failure message={quoteattr(msg)}>{html.escape(body)}</failure>")
        out.append("  </testcase>")
    out.append("</testsuite>")
    return "\n".join(out) + "\n"
