"""summary.html of a describe batch: the batch figures and one row per scenario, self-contained."""

from __future__ import annotations

from html import escape


def _cell(v) -> str:
    if v is None:
        return "–"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return f"{v:.3f}"
    return escape(str(v))


def summary_html(doc: dict) -> str:
    s = doc["summary"]
    cr = "–" if s["crash_rate"] is None else f"{100 * s['crash_rate']:.1f} %"
    head = [
        "scenario",
        "map",
        "weather",
        "ego km/h",
        "behaviours",
        "ego collided",
        "with",
        "min ACT s",
        "max EI m/s",
        "min TTC s",
        "comfort",
        "episodes",
        "intent met",
    ]
    rows = []
    for r in doc["scenarios"]:
        cls = ' class="crash"' if r["ego_collided"] else ""
        cells = [
            f'<a href="{r["scenario"]}/scenario.xosc">{r["scenario"]}</a>',
            _cell(r["map"]),
            _cell(r["weather"]),
            f"{3.6 * r['ego_speed_mps']:.0f}",
            _cell(r["behaviours"]),
            _cell(r["ego_collided"]),
            _cell(r["collided_with"]),
            _cell(r["act_min_s"]),
            _cell(r["ei_max_mps"]),
            _cell(r["min_ttc_s"]),
            _cell(r["comfort"]),
            _cell(len(r["episodes"])),
            _cell(r["intent_met"] if not r.get("error") else f"not written: {r['error']}"),
        ]
        rows.append(f"<tr{cls}>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    intent = (
        "no intent stated"
        if s["intent_met"] is None
        else f"{s['intent_met']} of {s.get('intent_stated', s['scenarios'])} ({s['episodes_run']} runs)"
    )
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>vei describe: {escape(doc["description"][:80])}</title>
<style>body{{font-family:sans-serif;margin:2em}}table{{border-collapse:collapse}}
td,th{{border:1px solid #ccc;padding:3px 8px;font-size:13px}}
tr.crash{{background:#fde2e2}}.figures td{{font-size:15px}}</style></head><body>
<h1>vei describe</h1>
<p><b>Description:</b> {escape(doc["description"])}</p>
<p>backend {escape(doc["backend"])}, seed {doc["seed"]}, refinement {"on" if doc["refine"] else "off"}</p>
<table class="figures"><tr><td>scenarios</td><td>{s["scenarios"]}</td></tr>
<tr><td>crash rate (ego collided with anything)</td><td>{cr} ({s["crashes"]})</td></tr>
<tr><td>mean minimum ACT</td><td>{_cell(s["mean_min_act_s"])} s</td></tr>
<tr><td>mean comfort (share of time |a| ≤ 2 m/s², |jerk| ≤ 2 m/s³)</td><td>{_cell(s["mean_comfort"])}</td></tr>
<tr><td>mean maximum EI</td><td>{_cell(s["mean_max_ei_mps"])} m/s</td></tr>
<tr><td>intent met</td><td>{intent}</td></tr></table>
<h2>Scenarios</h2>
<table><tr>{"".join(f"<th>{h}</th>" for h in head)}</tr>
{chr(10).join(rows)}
</table></body></html>
"""
