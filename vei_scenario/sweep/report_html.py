"""report.html: what a reviewer looks at first. Self-contained (plots embedded as PNG)."""

from __future__ import annotations

import heapq
import html
from operator import itemgetter

import numpy as np

from vei_scenario.metrics.series import MetricConfig
from vei_scenario.reports.sweep_plots import SERIES, UNITS, param_label, render_plots
from vei_scenario.sut.spec import reproduce_options

#: The metrics the plots show, read from the rows.
PLOTTED = tuple(metric for metric, _ in SERIES)


def _groups(rows: list[dict], x_param: str, groups: list[str]) -> list[tuple[str, np.ndarray, dict, np.ndarray]]:
    """Per group of the other varied parameters (sorted): (name, x sorted, metric arrays, collided)."""
    by_key: dict[tuple, list[dict]] = {}
    key_of = itemgetter(*groups) if groups else (lambda p: ())
    for r in rows:
        if r["status"] == "ok":
            k = key_of(r["parameters"])
            by_key.setdefault(k if isinstance(k, tuple) else (k,), []).append(r)
    out = []
    for key in sorted(by_key):  # a group whose every variant failed is listed under "Failed variants"
        sel = by_key[key]
        x = np.array([float(r["parameters"][x_param]) for r in sel])
        order = np.argsort(x, kind="stable")
        # one pass over the rows; None (no value, or no metrics: a run without a pair) becomes NaN
        table = np.array([[r["metrics"].get(m) for m in PLOTTED] for r in sel], dtype=float)[order]
        values = {m: table[:, k] for k, m in enumerate(PLOTTED)}
        values["variant"] = np.array([r["variant"] for r in sel], dtype=np.int64)[order]  # (for hovering)
        coll = np.array([bool(r["metrics"].get("collision")) for r in sel], dtype=bool)[order]
        name = ", ".join(f"{g}={k}" for g, k in zip(groups, key)) or "all"
        out.append((name, x[order], values, coll))
    return out


#: A near miss closer than this still scores a perfect safety index when its TTC stays out of the
#: alert zone: the report counts those (MetricConfig.close_pass_m).
CLOSE_PASS_M = MetricConfig().close_pass_m
#: The thresholds the report reads near misses by (the metrics' defaults).
DEFAULT_METRICS = MetricConfig()


def is_near_miss(m: dict, cfg: MetricConfig = DEFAULT_METRICS) -> bool:
    """A pass without contact that came close: the minimum box gap under ``cfg.close_pass_m`` (0.5 m),
    or the minimum 2-D TTC at most the upper edge of the near-miss band (1.5 s). It takes in the
    ``near_miss`` metric (TTC inside the band) and what lies below the band or beside it: a pass whose
    TTC drops under 0.5 s without contact, and a crossing at 0.2 m whose TTC stays long."""
    if not m or m.get("collision"):
        return False
    gap, ttc = m.get("min_gap_m"), m.get("min_ttc_s")
    return (gap is not None and gap < cfg.close_pass_m) or (ttc is not None and ttc <= cfg.near_miss_ttc_s[1])


def _cell(v) -> str:
    return "–" if v is None else html.escape(str(v))


def _table(
    rows: list[dict],
    varied: list[str],
    columns: list[tuple[str, str]],
    scenario: str = "",
    dt: float = 0.01,
    options: str = "",
) -> list[str]:
    out = ["<table><tr><th>#</th>", *(f"<th>{html.escape(param_label(p))}</th>" for p in varied)]
    out += [f"<th>{html.escape(h)}</th>" for _, h in columns] + ["<th>reproduce</th><th>scenario</th></tr>"]
    for r in rows:
        m = r["metrics"]
        link = f"<a href='{html.escape(r['xosc'])}'>{html.escape(r['xosc'])}</a>" if r.get("xosc") else ""
        cells = "".join(f"<td>{html.escape(str(r['parameters'][p]))}</td>" for p in varied)
        values = "".join(
            f"<td>{'<span class=coll>yes</span>' if k == 'collision' and m.get(k) else _cell(m.get(k))}</td>"
            for k, _ in columns
        )
        command = html.escape(reproduce(scenario, r, varied, dt, options)) if scenario else ""
        out.append(f"<tr><td>{r['variant']}</td>{cells}{values}<td><code>{command}</code></td><td>{link}</td></tr>")
    out.append("</table>")
    return out


def _severity(r: dict) -> tuple:
    """Collisions first, the most violent first (impact speed: the pair's Δv at first contact); then
    the rest by how close they came (minimum gap, then minimum TTC)."""
    m = r["metrics"]
    big = float("inf")
    if m.get("collision"):
        return (0, -(m.get("impact_speed_mps") or 0.0), r["variant"], 0)
    ttc = m.get("min_ttc_s")
    return (1, m.get("min_gap_m") if m.get("min_gap_m") is not None else big, big if ttc is None else ttc, r["variant"])


def plot_inputs(rows: list[dict], varied: list[str]) -> tuple | None:
    """What the plots are drawn from, (x parameter, groups, x limits), or None when no varied parameter is
    numeric or no variant ran: small (arrays, no rows), so it can be sent to another process."""
    numeric_x = (
        "TimeShift"
        if "TimeShift" in varied
        else next((p for p in varied if all(_is_number(r["parameters"][p]) for r in rows)), None)
    )
    if not numeric_x or not any(r["status"] == "ok" for r in rows):
        return None
    grouped = _groups(rows, numeric_x, [p for p in varied if p != numeric_x])
    lo, hi = min(float(g[1][0]) for g in grouped), max(float(g[1][-1]) for g in grouped)
    pad = 0.02 * (hi - lo or 1.0)
    return numeric_x, grouped, (lo - pad, hi + pad)  # one x-axis for every plot


def report_html(
    rows: list[dict],
    parameter_names: list[str],
    varied: list[str],
    meta: dict,
    top: int = 20,
    plots: list[tuple[str, int]] | None = None,
    inputs: tuple | None = None,
) -> str:
    """The report; ``plots`` are :func:`render_plots`' output when they were drawn elsewhere (the sweep
    draws them in another process while it writes the catalog)."""
    ok = [r for r in rows if r["status"] == "ok"]
    failed = [r for r in rows if r["status"] != "ok"]
    n_coll = sum(1 for r in ok if r["metrics"].get("collision"))
    parts = [
        "<!doctype html><html><head><meta charset='utf-8'><title>vei sweep report</title>",
        "<style>body{font-family:sans-serif;margin:2em;max-width:1400px}img{max-width:100%}"
        "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 8px;font-size:13px}"
        "th{background:#f3f3f3}.coll{color:#b00;font-weight:bold}.note{color:#555;max-width:60em}</style>"
        "</head><body>",
        f"<h1>Sweep of {html.escape(meta['scenario'])}</h1>",
        f"<p>{len(rows)} variants: {len(ok) - n_coll} without collision, {n_coll} with collision, "
        f"{len(failed)} failed. dt {meta['dt_s']} s. Varied: "
        f"{html.escape(', '.join(param_label(v) for v in varied) or 'nothing')}.</p>",
    ]
    parts += _grid(rows, varied)
    unpaired = sum(1 for r in ok if not r["metrics"])
    if unpaired:  # (vei run's metrics are of the ego and one other road user: none when it is alone)
        parts.append(
            f"<p class='note'>{unpaired} variants have no metrics: their scenario has one road user, no "
            "pair to measure.</p>"
        )
    parts += _configurations(ok, varied, meta)
    parts += _regions(inputs if inputs is not None else plot_inputs(rows, varied))
    if plots is None:
        plots = render_plots(plot_inputs(rows, varied))
    for (metric, label), (png, missing) in zip(SERIES, plots):
        parts.append(f"<img alt='{label}' src='data:image/png;base64,{png}'>")
        if missing and metric == "min_ttc_s":
            parts.append(
                f"<p class='note'>{missing} variants have no TTC: the two never head for a collision at "
                "constant velocity. They are marked along the top edge, not left out.</p>"
            )
    from vei_scenario.reports.interactive import interactive_html

    parts.append(interactive_html(inputs if inputs is not None else plot_inputs(rows, varied)))
    hits = [r for r in ok if r["metrics"].get("collision")]
    shown = heapq.nsmallest(top, hits, key=_severity)  # (linear in the variants, as sorting is not)
    columns = [
        ("collision", "collision"),
        ("collision_time_s", "t coll (s)"),
        ("impact_speed_mps", "impact speed (m/s)"),
        ("ei_max_mps", "EI max (m/s)"),
        ("drac_max_mps2", "DRAC max (m/s²)"),
        ("min_gap_m", "min gap (m)"),
        ("min_ttc_s", "min TTC (s)"),
        ("pet_s", "PET (s)"),
        ("safety_index", "S"),
    ]
    parts.append(f"<h2>Most severe collisions (top {len(shown)} of {n_coll})</h2>")
    parts.append(
        "<p class='note'>Ranked by the impact speed: how fast the two met, relative to each other, at "
        "first contact. Every collision has gap, TTC and safety index 0: they cannot rank them.</p>"
    )
    options = reproduce_options(meta.get("system_under_test") or [])
    parts += _table(shown, varied, columns, meta["scenario"], meta["dt_s"], options) if shown else ["<p>None.</p>"]
    near = heapq.nsmallest(top, (r for r in ok if not r["metrics"].get("collision")), key=_severity)
    n_near = sum(1 for r in ok if r["metrics"].get("near_miss"))
    parts.append(f"<h2>Closest passes without collision (top {len(near)}; {n_near} near misses by TTC)</h2>")
    parts.append("<p class='note'>Ranked by the minimum gap, then the minimum TTC.</p>")
    parts += (
        _table(near, varied, [("near_miss", "near miss"), *columns[5:]], meta["scenario"], meta["dt_s"], options)
        if near
        else ["<p>None.</p>"]
    )
    hidden = [
        r
        for r in ok
        if not r["metrics"].get("collision")
        and (r["metrics"].get("safety_index") or 0.0) >= 0.99
        and (r["metrics"].get("min_gap_m") if r["metrics"].get("min_gap_m") is not None else 1e9) < CLOSE_PASS_M
    ]
    parts.append(
        "<h2>What the safety index hides</h2><p class='note'>S is the share of time outside the alert and "
        "collision zones of the TTC. A pass at a small gap whose TTC never drops into the alert zone (a "
        f"crossing, side by side) scores S = 1.0: {len(hidden)} variants score S ≥ 0.99 while passing "
        f"within {CLOSE_PASS_M} m. Read S with the minimum gap and PET.</p>"
    )
    if failed:
        parts.append("<h2>Failed variants</h2><ul>")
        parts += [f"<li>#{r['variant']}: {html.escape(r['error'])}</li>" for r in failed[:50]]
        parts.append("</ul>")
    parts.append("</body></html>\n")
    return "".join(parts)


def planner_on(r: dict) -> bool:
    """The variant ran with the collision-avoidance planner on (CapEnabled=true)."""
    return str(r["parameters"].get("CapEnabled", "")).lower() == "true"


def reproduce(scenario: str, r: dict, varied: list[str], dt: float = 0.01, options: str = "") -> str:
    """The one-line command that replays a variant (its varied parameters; the rest are the file's;
    ``options``: those that plug the system under test in again)."""
    step = f" --dt {dt:g}" if dt != 0.01 else ""
    return f"vei run {scenario} " + " ".join(f"--param {p}={r['parameters'][p]}" for p in varied) + step + options


def _configurations(ok: list[dict], varied: list[str], meta: dict) -> list[str]:
    """A table per configuration (the varied parameters but the plotted x), the configurations with
    collisions under the planner first: those are failures of the system under test, the rows a
    safety engineer reads first; then every such failure with the command that reproduces it."""
    x = "TimeShift" if "TimeShift" in varied else None
    keys = [p for p in varied if p != x]
    groups: dict[tuple, list[dict]] = {}
    for r in ok:
        groups.setdefault(tuple(r["parameters"][p] for p in keys), []).append(r)
    sut = meta.get("system_under_test") or []
    options = reproduce_options(sut)
    has_planner = bool(sut) or any("CapEnabled" in r["parameters"] for r in ok)

    def in_charge(r: dict) -> bool:  # (a user's system drives throughout; vei's planner when switched on)
        return bool(sut) or planner_on(r)

    def summary(key, sel):
        m = [r["metrics"] for r in sel]
        coll = [r for r in sel if r["metrics"].get("collision")]
        on = has_planner and all(in_charge(r) for r in sel)
        s = [v["safety_index"] for v in m if v.get("safety_index") is not None]
        alert = [v["ttc_zones_s"]["alert"] for v in m if v.get("ttc_zones_s")]
        ttc = [v["min_ttc_s"] for v in m if v.get("min_ttc_s") is not None]
        return (0 if (on and coll) else 1 if coll else 2, -len(coll), key), key, sel, coll, on, s, alert, ttc

    rows = sorted((summary(k, v) for k, v in groups.items()), key=lambda t: t[0])
    if sut:  # (the user's system drives in every variant, whatever CapEnabled says)
        note = ("Your system under test drives the ego in every variant: configurations with collisions come "
                "first, each a failure of the system where the ego was moving.")  # fmt: skip
    else:
        note = ("Configurations whose variants collide with the collision-avoidance planner on (CapEnabled=true) "
                "come first: those collisions are failures of the system under test. Without the planner a "
                "collision is the scenario's own risk.")  # fmt: skip
    out = ["<h2>Per configuration</h2>", f"<p class='note'>{note}</p>",
           "<table><tr>", *(f"<th>{html.escape(param_label(p))}</th>" for p in keys),
           f"<th>variants</th><th>collisions</th><th>{'system' if sut else 'planner'}</th><th>min S</th>"
           "<th>max alert (s)</th><th>min TTC (s)</th></tr>"]  # fmt: skip
    for _, key, sel, coll, on, s, alert, ttc in rows:
        cls = " class=coll" if on and coll else ""
        who = "plugged" if sut else "on" if on else "off" if has_planner else "–"
        out.append(
            "<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in key)
            + f"<td>{len(sel)}</td><td{cls}>{len(coll)}</td><td>{who}</td>"
            f"<td>{_cell(min(s) if s else None)}</td><td>{_cell(max(alert) if alert else None)}</td>"
            f"<td>{_cell(min(ttc) if ttc else None)}</td></tr>"
        )  # fmt: skip
    out.append("</table>")
    # a collision with the ego standing (<= 0.1 m/s at the first contact) is no failure of what drives it
    failures = sorted((r for r in ok if r["metrics"].get("collision_ego_moving") and in_charge(r)), key=_severity)
    if sut:
        names = ", ".join(f"{s['entity']}={s['controller']} (sha256 {(s['sha256'] or '-')[:12]})" for s in sut)
        out.insert(0, f"<p>System under test: <code>{html.escape(names)}</code>.</p>")
    if has_planner:
        what = "collisions" if sut else "collisions with the planner on"
        out.append(f"<h2>Failures of the system under test ({len(failures)} {what}, the ego moving)</h2>")
        out.append("<p class='note'>A failure is a collision with the ego moving (faster than 0.1 m/s at the first "
                   "contact); a road user running into the standing ego is not one.</p>")  # fmt: skip
        if failures:
            out.append("<table><tr><th>#</th><th>impact speed (m/s)</th><th>ego speed (m/s)</th><th>t coll (s)</th>"
                       "<th>reproduce</th><th>scenario</th></tr>")  # fmt: skip
            for r in failures[:200]:
                m = r["metrics"]
                link = f"<a href='{html.escape(r['xosc'])}'>{html.escape(r['xosc'])}</a>" if r.get("xosc") else ""
                command = html.escape(reproduce(meta["scenario"], r, varied, meta.get("dt_s", 0.01), options))
                out.append(
                    f"<tr><td>{r['variant']}</td><td>{_cell(m.get('impact_speed_mps'))}</td>"
                    f"<td>{_cell(m.get('ego_speed_at_contact_mps'))}</td>"
                    f"<td>{_cell(m.get('collision_time_s'))}</td><td><code>{command}</code></td><td>{link}</td></tr>"
                )
            out.append("</table>")
            if len(failures) > 200:
                out.append(f"<p class='note'>{len(failures) - 200} more in catalog.csv.</p>")
        else:
            out += _no_failures_seen(ok, varied, meta)
        if any(planner_on(r) for r in ok):
            out += _near_misses(ok, varied, meta)
    return out


def grid_values(rows: list[dict], name: str) -> list[str]:
    """The values a sweep gave ``name``, in the order they first appear."""
    return list(dict.fromkeys(str(r["parameters"][name]) for r in rows))


def grid_step(values: list[str]) -> tuple[float, float] | None:
    """The smallest and largest step between the sorted numeric ``values`` (None when they are not all
    numbers, or fewer than two): what a grid can miss between its points."""
    if len(values) < 2 or not all(_is_number(v) for v in values):
        return None
    x = np.unique(np.array([float(v) for v in values]))
    d = np.diff(x)
    return (float(np.round(d.min(), 9)), float(np.round(d.max(), 9))) if d.size else None


def _even(step: tuple[float, float]) -> bool:
    return step[1] - step[0] <= 1e-9 * max(1.0, step[1])


def _spacing(step: tuple[float, float]) -> str:
    """A grid's spacing as a reader needs it: its step, or for uneven values (a stochastic sample) the
    largest gap, which is what a failure window could hide in."""
    return f"step {step[0]:g}" if _even(step) else f"unevenly spaced, largest gap {step[1]:.3g}"


def _grid(rows: list[dict], varied: list[str]) -> list[str]:
    """Each swept parameter's grid: its values, or for a number its range and step."""
    if not varied:
        return []
    items = []
    for p in varied:
        values = grid_values(rows, p)
        step = grid_step(values)
        if step is None:
            shown = ", ".join(values[:12]) + (f" and {len(values) - 12} more" if len(values) > 12 else "")
            items.append(f"{param_label(p)}: {shown}")
            continue
        x = [float(v) for v in values]
        items.append(f"{param_label(p)}: {len(set(x))} values from {min(x):g} to {max(x):g}, {_spacing(step)}")
    return [
        "<p class='note'>Grid: ",
        "; ".join(html.escape(i) for i in items),
        ". A sweep shows its grid points only: what happens between them is not run.</p>",
    ]


def _search_commands(ok: list[dict], varied: list[str], meta: dict) -> list[str]:
    """The commands that search between the grid points with the planner on: `vei risk` along
    TimeShift (every window as wide as --tol) and `vei falsify` over the swept box."""
    scenario, dt = meta["scenario"], meta.get("dt_s", 0.01)
    step = f" --dt {dt:g}" if dt != 0.01 else ""
    numeric = {p: [float(v) for v in grid_values(ok, p)] for p in varied if grid_step(grid_values(ok, p))}
    discrete = {p: grid_values(ok, p) for p in varied if p not in numeric and p != "CapEnabled"}
    out = []
    if "TimeShift" in numeric:
        x = numeric["TimeShift"]
        others = [p for p in numeric if p != "TimeShift"]
        if not others:  # (vei risk searches TimeShift alone; other numbers go to falsify)
            vary = "".join(f" --vary {p}={','.join(v)}" for p, v in discrete.items())
            planner = " --vary CapEnabled=true" if "CapEnabled" in varied else ""
            out.append(f"vei risk {scenario} --target collision --window={min(x):g}:{max(x):g}{vary}{planner}{step}")
    if numeric:
        bounds = "".join(f" --bounds {p}={min(v):g}:{max(v):g}" for p, v in numeric.items())
        values = "".join(f" --values {p}={','.join(v)}" for p, v in discrete.items())
        planner = " --param CapEnabled=true" if "CapEnabled" in varied else ""
        out.append(f"vei falsify {scenario}{bounds}{values}{planner}{step}")
    return out


def _no_failures_seen(ok: list[dict], varied: list[str], meta: dict) -> list[str]:
    """No collision with the planner on at the grid points: say so, and no more. The planner's failure
    windows can be far narrower than a sweep's step (0.03-0.08 s against 0.1 s in the case study):
    where the grid shows signs of them (collisions nearby with the planner off, near misses with it
    on), the report says the grid cannot rule them out and gives the commands that search between."""
    on = [r for r in ok if planner_on(r)]
    if not on:
        return ["<p>No variant ran with the planner on (CapEnabled=true): this sweep does not test it.</p>"]
    steps = [
        f"{p} {_spacing(s)}{' ' + UNITS[p] if p in UNITS else ''}"
        for p in varied
        if p != "CapEnabled" and (s := grid_step(grid_values(on, p)))
    ]
    where = f" ({', '.join(steps)})" if steps else ""
    out = [f"<p>No collision with the planner on at any of the {len(on)} grid points{html.escape(where)}.</p>"]
    off = [r for r in ok if not planner_on(r) and r["metrics"].get("collision")]
    close = [r for r in on if is_near_miss(r["metrics"])]
    signs = []
    if off:
        signs.append(f"{len(off)} variants collide with the planner off")
    if close:
        worst = min(close, key=_severity)
        at = ", ".join(f"{p}={worst['parameters'][p]}" for p in varied if p != "CapEnabled")
        signs.append(f"{len(close)} near misses with the planner on (closest {worst['metrics']['min_gap_m']} m, {at})")
    if not signs or not steps:
        return out
    commands = _search_commands(ok, varied, meta)
    out.append(
        "<p class='coll'>This does not show that the planner avoids every collision: failure windows "
        f"narrower than the grid step can lie between the grid points, and this grid has signs of them: "
        f"{html.escape('; '.join(signs))}. Search between the points"
        + (
            ":</p><ul>" + "".join(f"<li><code>{html.escape(c)}</code></li>" for c in commands) + "</ul>"
            if commands
            else ".</p>"
        )
    )
    return out


def _near_misses(ok: list[dict], varied: list[str], meta: dict, top: int = 20) -> list[str]:
    """The planner-on variants that passed close (:func:`is_near_miss`), the closest first."""
    close = sorted((r for r in ok if planner_on(r) and is_near_miss(r["metrics"])), key=_severity)
    cfg = MetricConfig()
    out = [
        f"<h2>Near misses with the planner on ({len(close)})</h2>",
        f"<p class='note'>Passes without contact whose minimum gap is under {cfg.close_pass_m:g} m or whose "
        f"minimum TTC is at most {cfg.near_miss_ttc_s[1]:g} s (the upper edge of the near-miss band), the "
        "closest first: the system under test avoided these by little.</p>",
    ]
    if not close:
        return out + ["<p>None.</p>"]
    columns = [("min_gap_m", "min gap (m)"), ("min_ttc_s", "min TTC (s)"), ("near_miss", "TTC in band"),
               ("pet_s", "PET (s)"), ("safety_index", "S")]  # fmt: skip
    out += _table(close[:top], varied, columns, meta["scenario"], meta.get("dt_s", 0.01))
    if len(close) > top:
        out.append(f"<p class='note'>{len(close) - top} more in catalog.csv.</p>")
    return out


def _regions(inputs: tuple | None) -> list[str]:
    """Failure regions along the plotted parameter: the runs of consecutive colliding variants of each
    configuration (their first and last value), the planner's first."""
    if inputs is None:
        return []
    from vei_scenario.reports.sweep_plots import collision_runs

    x_param, grouped, _ = inputs
    found = []
    for name, x, _values, coll in grouped:
        on = "CapEnabled=true" in name
        found += [(not on, name, float(x[a]), float(x[b]), b - a + 1) for a, b in collision_runs(coll)]
    if not found:
        return []
    out = [f"<h2>Collision regions along {html.escape(param_label(x_param))} ({len(found)})</h2>",
           "<p class='note'>Runs of consecutive colliding variants; with the planner on (first) they are failure "
           "regions of the system under test. `vei falsify` searches between the variants and refines the edges."
           "</p><table><tr><th>configuration</th><th>from</th><th>to</th><th>variants</th></tr>"]  # fmt: skip
    for off, name, a, b, n in sorted(found):
        cls = "" if off else " class=coll"
        out.append(f"<tr><td{cls}>{html.escape(name)}</td><td>{a:g}</td><td>{b:g}</td><td>{n}</td></tr>")
    out.append("</table>")
    return out


def _is_number(s: str) -> bool:
    try:
        float(s)
        return True
    except ValueError:
        return False
