"""library.html: the scenarios of a library in one page, closest to a collision first.

One table row per clip: rank, thumbnail (the scenario's ``thumbnail.svg``, loaded lazily), id and
files, road users, duration, threat, conflict TimeShift and margin, the collision interval, how far
the recording was from it, the closest centre distance, warnings; the clips that could not be
compiled, with their reasons, at the end. Static HTML, no script: it opens from the folder.
"""

from __future__ import annotations

import html

STYLE = """
body{font-family:sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse;font-size:13px}
td,th{border:1px solid #ccc;padding:3px 6px;vertical-align:top;text-align:left}
th{background:#eee;position:sticky;top:0}
td.num{text-align:right;white-space:nowrap}
.coll{color:#b00;font-weight:bold}
.warn{color:#8a6d00;font-size:12px}
.err{color:#b00}
img{display:block}
"""


def _num(v, unit: str = "", fmt: str = "{:.2f}") -> str:
    return "–" if v is None else html.escape(fmt.format(v) + unit)


def _users(r: dict) -> str:
    return ", ".join(f"{n} {html.escape(k)}" for k, n in r["road_users"].items())


def library_html(doc: dict) -> str:
    ok = [r for r in doc["scenarios"] if r["status"] == "ok"]
    bad = [r for r in doc["scenarios"] if r["status"] != "ok"]
    out = [
        "<!DOCTYPE html><html><head><meta charset='utf-8'><title>vei scenario library</title>",
        f"<style>{STYLE}</style></head><body>",
        "<h1>Scenario library</h1>",
        f"<p>{doc['clips']} clips: {doc['compiled']} compiled, {doc['failed']} could not be compiled. "
        "Ranked by how close the recorded interaction came to a collision: the smallest change of the "
        "threat's timing (TimeShift) that makes the boxes touch (0: they touched as recorded), then the "
        "conflict margin |conflict TimeShift|, then the closest centre distance as recorded.</p>",
        "<table><tr><th>#</th><th>map</th><th>clip</th><th>road users</th><th>duration</th><th>threat</th>"
        "<th>conflict TimeShift</th><th>conflict margin</th><th>collision for TimeShift</th>"
        "<th>from a collision</th><th>closest (centres)</th><th>warnings</th></tr>",
    ]
    for r in ok:
        o = r["outputs"]
        coll = r["collision_shifts_s"]
        interval = "–" if coll is None else html.escape(f"{coll[0]:+.2f}..{coll[1]:+.2f} s")
        margin = r["collision_margin_s"]
        near = "<span class=coll>collides as recorded</span>" if r["recorded_collision"] else _num(margin, " s")
        warnings = "".join(f"<div class=warn>{html.escape(w)}</div>" for w in r["warnings"])
        out.append(
            f"<tr><td class=num>{r['rank']}</td>"
            f"<td><img loading='lazy' width='120' height='120' src='{html.escape(o['thumbnail'])}' alt=''></td>"
            f"<td><a href='{html.escape(o['scenario'])}'>{html.escape(r['file'])}</a><br>"
            f"<small><a href='{html.escape(o['road'])}'>road</a> · "
            f"<a href='{html.escape(o['variations'])}'>variations</a> · {html.escape(r['road'])}</small></td>"
            f"<td>{_users(r)}</td><td class=num>{_num(r['duration_s'], ' s', '{:.1f}')}</td>"
            f"<td>{html.escape(r['threat'])}</td>"
            f"<td class=num>{_num(r['conflict_time_shift_s'], ' s', '{:+.2f}')}</td>"
            f"<td class=num>{_num(r['conflict_margin_s'], ' s')}</td><td class=num>{interval}</td>"
            f"<td class=num>{near}</td><td class=num>{_num(r['min_centre_distance_m'], ' m')}</td>"
            f"<td>{warnings}</td></tr>"
        )
    out.append("</table>")
    if bad:
        out.append(f"<h2>Could not be compiled ({len(bad)})</h2><table><tr><th>clip</th><th>reason</th></tr>")
        for r in bad:
            out.append(f"<tr><td>{html.escape(r['file'])}</td><td class=err>{html.escape(r['error'])}</td></tr>")
        out.append("</table>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"
