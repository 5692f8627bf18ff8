"""report.html: what a reviewer looks at first. Self-contained (plots embedded as PNG)."""

from __future__ import annotations

import base64
import html
import io

import numpy as np


def _figure(figsize: tuple[float, float]):
    """A figure drawn by Agg without pyplot (whose import and global state a report does not need)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize)
    FigureCanvasAgg(fig)
    return fig


def _png(fig) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100, metadata={"Software": None})
    return base64.b64encode(buf.getvalue()).decode()


def _runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) index of each run of consecutive True values."""
    edges = np.diff(np.concatenate(([0], flags.astype(np.int8), [0])))
    return list(zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1))


def _series_plot(rows: list[dict], x_param: str, groups: list[str], metric: str, label: str) -> str:
    fig = _figure((8, 3.6))
    ax = fig.add_subplot()
    by_key: dict[tuple, list[dict]] = {}
    for r in rows:
        if r["status"] == "ok":
            by_key.setdefault(tuple(r["parameters"][g] for g in groups), []).append(r)
    for key in sorted(by_key):  # a group whose every variant failed is listed under "Failed variants"
        sel = by_key[key]
        sel.sort(key=lambda r: float(r["parameters"][x_param]))
        x = np.array([float(r["parameters"][x_param]) for r in sel])
        y = np.array([np.nan if r["metrics"].get(metric) is None else float(r["metrics"][metric]) for r in sel])
        coll = np.array([bool(r["metrics"].get("collision")) for r in sel], dtype=bool)
        name = ", ".join(f"{g}={k}" for g, k in zip(groups, key)) or "all"
        line = ax.plot(x, y, lw=1.3, marker=".", ms=3, label=name)
        ax.plot(x[coll], y[coll], "x", color=line[0].get_color(), ms=6)
        if coll.any():  # shade this group's collision region: one band per run of colliding variants
            step = np.median(np.diff(x)) if x.size > 1 else 0.1
            for i, j in _runs(coll):
                ax.axvspan(x[i] - step / 2, x[j] + step / 2, color="red", alpha=0.04, lw=0)
    ax.set_xlabel(x_param)
    ax.set_ylabel(label)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title(f"{label} over {x_param} (× collision, red band: collision region)")
    return _png(fig)


def report_html(rows: list[dict], parameter_names: list[str], varied: list[str], meta: dict, top: int = 20) -> str:
    ok = [r for r in rows if r["status"] == "ok"]
    failed = [r for r in rows if r["status"] != "ok"]
    n_coll = sum(1 for r in ok if r["metrics"].get("collision"))
    parts = [
        "<!doctype html><html><head><meta charset='utf-8'><title>vei sweep report</title>",
        "<style>body{font-family:sans-serif;margin:2em;max-width:1100px}table{border-collapse:collapse}"
        "td,th{border:1px solid #ccc;padding:3px 8px;font-size:13px}th{background:#f3f3f3}"
        ".coll{color:#b00;font-weight:bold}</style></head><body>",
        f"<h1>Sweep of {html.escape(meta['scenario'])}</h1>",
        f"<p>{len(rows)} variants: {len(ok) - n_coll} without collision, {n_coll} with collision, "
        f"{len(failed)} failed. dt {meta['dt_s']} s. Varied: {html.escape(', '.join(varied) or 'nothing')}.</p>",
    ]
    numeric_x = (
        "TimeShift"
        if "TimeShift" in varied
        else next((p for p in varied if all(_is_number(r["parameters"][p]) for r in rows)), None)
    )
    if numeric_x and ok:
        groups = [p for p in varied if p != numeric_x]
        for metric, label in (
            ("safety_index", "safety index"),
            ("min_ttc_s", "minimum TTC (s)"),
            ("min_gap_m", "minimum gap (m)"),
        ):
            parts.append(
                f"<img alt='{label}' src='data:image/png;base64,"
                f"{_series_plot(rows, numeric_x, groups, metric, label)}'>"
            )
    crit = sorted(
        ok,
        key=lambda r: (
            not r["metrics"].get("collision"),
            r["metrics"].get("safety_index", 1.0),
            r["metrics"].get("min_ttc_s") if r["metrics"].get("min_ttc_s") is not None else 1e9,
        ),
    )
    parts.append(f"<h2>Most critical variants (top {min(top, len(crit))})</h2><table><tr><th>#</th>")
    parts += [f"<th>{html.escape(p)}</th>" for p in varied]
    parts.append(
        "<th>collision</th><th>t coll (s)</th><th>min gap (m)</th><th>min TTC (s)</th><th>S</th><th>scenario</th></tr>"
    )
    for r in crit[:top]:
        m = r["metrics"]
        link = f"<a href='{html.escape(r['xosc'])}'>{html.escape(r['xosc'])}</a>" if r.get("xosc") else ""
        cells = "".join(f"<td>{html.escape(str(r['parameters'][p]))}</td>" for p in varied)
        coll = "<span class='coll'>yes</span>" if m.get("collision") else "no"
        parts.append(
            f"<tr><td>{r['variant']}</td>{cells}<td>{coll}</td><td>{m.get('collision_time_s')}</td>"
            f"<td>{m.get('min_gap_m')}</td><td>{m.get('min_ttc_s')}</td><td>{m.get('safety_index')}</td>"
            f"<td>{link}</td></tr>"
        )
    parts.append("</table>")
    if failed:
        parts.append("<h2>Failed variants</h2><ul>")
        parts += [f"<li>#{r['variant']}: {html.escape(r['error'])}</li>" for r in failed[:50]]
        parts.append("</ul>")
    parts.append("</body></html>\n")
    return "".join(parts)


def _is_number(s: str) -> bool:
    try:
        float(s)
        return True
    except ValueError:
        return False
